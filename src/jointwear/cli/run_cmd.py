"""``jointwear run`` and ``jointwear plot``."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from jointwear.cli.common import (
    JsonOpt,
    MaxMemoryOpt,
    QuietOpt,
    SetOpt,
    TimeLimitOpt,
    app,
    console,
    emit_json,
)
from jointwear.cli.progress import ProgressBar, run_ends

if TYPE_CHECKING:
    from rich.table import Table

OutOpt = Annotated[
    Path | None,
    typer.Option(
        "--out", help="Write result.nc, metrics.csv, config.toml, summary.json and plots here."
    ),
]


def end_lines(summary: dict) -> list[str]:
    """Why and when the run (each joint's, of several) ended, one line each."""
    from jointwear.display import end_of_run

    joints = summary.get("joints")
    if not joints:
        return [end_of_run(summary)]
    return [f"{joint}: {end_of_run(entry)}" for joint, entry in joints.items()]


def summary_table(summary: dict, title: str) -> Table:
    from rich.table import Table

    from jointwear.display import revolutions_text

    table = Table(title=title)
    table.add_column("metric")
    table.add_column("value", justify="right")
    table.add_row("wear peak", f"{summary['peak_wear_depth_m'] * 1e3:.6g} mm")
    table.add_row("wear width", f"{summary['wear_width_deg']:.4g}°")
    table.add_row("wear mass", f"{summary['wear_mass_kg'] * 1e3:.6g} g")
    table.add_row("wear volume", f"{summary['wear_volume_m3'] * 1e9:.6g} mm³")
    table.add_row("min. wall left", f"{summary['min_wall_thickness_m'] * 1e3:.6g} mm")
    table.add_row("revolutions", revolutions_text(summary["revolutions"]))
    table.add_row("contour updates", f"{summary['contour_updates']}")
    table.add_row("run time", f"{summary['runtime_s']:.3g} s")
    compiling = summary.get("compile_time_s", 0.0)
    if compiling > 0.0:
        # numba's first compile on this machine (jointwear warm-up pays it once, apart)
        table.add_row("numba compiling (once)", f"{compiling:.3g} s")
        table.add_row("run time without it", f"{summary['runtime_without_compile_s']:.3g} s")
    pv = summary.get("checks", {}).get("pv")
    if pv is not None:
        limit = "no limit known" if pv["limit"] is None else f"limit {pv['limit'] / 1e6:.3g}"
        table.add_row("PV (nominal, cycle mean)", f"{pv['value'] / 1e6:.3g} MPa m/s ({limit})")
    return table


OptConfigArg = Annotated[
    Path | None,
    typer.Argument(help="Config file (TOML); omit with --resume.", show_default=False),
]
CheckpointOpt = Annotated[
    int | None,
    typer.Option(
        "--checkpoint-every",
        help="Save the state into --out every K revolutions (0 = off; sets the config's "
        "checkpoint_every); continue a killed run with --resume OUT.",
        show_default=False,
    ),
]
ResumeOpt = Annotated[
    Path | None,
    typer.Option(
        "--resume",
        help="Continue the checkpointed run in this directory (its config is read from there; "
        "results are written there).",
        show_default=False,
    ),
]


@app.command()
def run(
    config: OptConfigArg = None,
    set_: SetOpt = None,
    out: OutOpt = None,
    json_: JsonOpt = False,
    quiet: QuietOpt = False,
    plots: Annotated[
        bool, typer.Option("--plots/--no-plots", help="Draw figures into OUT/plots.")
    ] = True,
    checkpoint_every: CheckpointOpt = None,
    resume: ResumeOpt = None,
    max_memory: MaxMemoryOpt = None,
    time_limit: TimeLimitOpt = None,
) -> None:
    """Simulate wear over revolutions (dynamics -> pressure -> Archard -> contour update)."""
    from jointwear.resources import parse_time_limit
    from jointwear.workflows.run import run_to_folder

    seconds = parse_time_limit(time_limit)
    with ProgressBar("revolutions", quiet=quiet) as bar:

        def ended(summary: dict) -> None:
            bar.finish(*run_ends(summary))
            bar.close()

        done = run_to_folder(
            config,
            out,
            overrides=set_ or [],
            checkpoint_every=checkpoint_every,
            resume=resume,
            plots=plots,
            max_memory=max_memory,
            time_limit=seconds,
            progress=bar,
            on_end=ended,
        )
    summary = done.summary
    if json_:
        emit_json(summary)
        return
    console.print(summary_table(summary, f"{done.name}: {summary['contact_model']}"))
    for line in end_lines(summary):
        console.print(line, highlight=False)
    if done.out is not None:
        console.print(f"results in {done.out}/")


@app.command()
def plot(
    result: Annotated[Path, typer.Argument(help="A result.nc written by `jointwear run --out`.")],
    out: Annotated[
        Path | None,
        typer.Option("--out", help="Folder for the figures (default: next to the result, plots/)."),
    ] = None,
    magnification: Annotated[
        str, typer.Option(help='Polar wear magnification, a number or "auto".')
    ] = "auto",
) -> None:
    """Redraw the figures of a saved result."""
    from jointwear.errors import ConfigError
    from jointwear.workflows.run import redraw_plots

    if magnification != "auto":
        try:
            value = float(magnification)
        except ValueError:
            raise ConfigError(
                f"--magnification: expected a number or 'auto', got {magnification!r}"
            ) from None
        if not (math.isfinite(value) and value > 0):
            raise ConfigError("--magnification: must be a positive number")
    else:
        value = "auto"
    target, count = redraw_plots(result, out, value)
    console.print(f"{count} files written to {target}/")
