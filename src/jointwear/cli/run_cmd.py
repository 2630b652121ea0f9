"""``jointwear run`` and ``jointwear plot``."""

from __future__ import annotations

import contextlib
import math
import sys
import time
from pathlib import Path
from typing import Annotated

import typer
from rich.table import Table

from jointwear.cli.common import (
    JsonOpt,
    MaxMemoryOpt,
    SetOpt,
    TimeLimitOpt,
    app,
    console,
    emit_json,
    err_console,
    load,
)
from jointwear.interrupts import raise_pending

OutOpt = Annotated[
    Path | None,
    typer.Option(
        "--out", help="Write result.nc, metrics.csv, config.toml, summary.json and plots here."
    ),
]
QuietOpt = Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")]


class ProgressBar:
    """A rich progress bar on stderr that appears only for runs longer than a second.

    Off when ``quiet`` or when stderr is not a terminal. It is redrawn by the progress
    calls themselves (at most every :attr:`interval` seconds), not by a thread of its own:
    a sweep forks its workers only from a process without threads.
    """

    #: shortest time between two redraws [s]
    interval = 0.1

    def __init__(self, description: str, quiet: bool = False, delay: float = 1.0) -> None:
        self.enabled = not quiet and sys.stderr.isatty()
        self.description = description
        self.delay = delay
        self.start = time.perf_counter()
        self._bar = None
        self._task = None
        self._drawn = -math.inf

    def __call__(self, done: float, total: float) -> None:
        """Show ``done`` of ``total``; ``done == total``: the job is complete (the bar keeps
        the total it began with, so a run a limit ended shows where it ended)."""
        raise_pending()  # the work goes on only if no signal has arrived
        if not self.enabled:
            return
        if self._bar is None:
            if time.perf_counter() - self.start < self.delay or done >= total:
                return
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

            self._bar = Progress(
                "{task.description}",
                BarColumn(),
                MofNCompleteColumn(),
                TimeRemainingColumn(),
                console=err_console,
                transient=True,
                auto_refresh=False,
            )
            self._bar.start()
            self._task = self._bar.add_task(self.description, total=total)
            self._drawn = -math.inf
        now = time.perf_counter()
        due = now - self._drawn >= self.interval or done >= total
        self._bar.update(self._task, completed=done, refresh=due)
        if due:
            self._drawn = now

    def finish(self, done: float, description: str) -> None:
        """Show where the job ended and why; a job that ended before its total (a life
        limit) stays on screen, at the revolution it ended, with ``description``.

        Parameters
        ----------
        done : float
            Where the job ended [-].
        description : str
            Why, e.g. ``"stopped: wall_thickness"``.
        """
        if self._bar is None:
            return
        total = self._bar.tasks[0].total
        if total is not None and done < total:
            from rich.progress import TimeElapsedColumn

            # (no time remaining: the time it took, and the bar stays)
            self._bar.columns = (*self._bar.columns[:-1], TimeElapsedColumn())
            self._bar.live.transient = False
        self._bar.update(self._task, completed=done, description=description, refresh=True)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.stop()
            self._bar = None

    def __enter__(self) -> ProgressBar:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def plot_joints(dataset, directory: Path, **options) -> list[Path]:
    """Figures of a result; with several clearance joints, a folder per joint."""
    from jointwear.plots import plot_result
    from jointwear.results import joint_datasets

    joints = joint_datasets(dataset)
    if len(joints) == 1:
        return plot_result(dataset, directory, **options)
    return [
        path
        for joint, single in joints.items()
        for path in plot_result(single, directory / joint, **options)
    ]


#: what ``jointwear run --out`` writes (files, then the plots folder)
RUN_FILES = ("result.nc", "metrics.csv", "config.toml", "summary.json")


def write_outputs(result, out: Path, summary: dict, plots: bool = True) -> None:
    """Write a run's files into ``out``: all or nothing (staged, then published at once).

    ``summary`` is the run's summary with its checks (:func:`add_checks`), written as
    ``summary.json`` as it is: the object ``run --json`` prints.
    """
    from jointwear.io import staged_output, write_json
    from jointwear.results import write_metrics_csv

    # the result file already holds the config as TOML text: written, not made again
    config_text = result.dataset.attrs.get("config")
    if not isinstance(config_text, str):
        config_text = result.config.to_toml()
    with staged_output(out, files=RUN_FILES, dirs=("plots",)) as staging:
        result.to_netcdf(staging / "result.nc")
        write_metrics_csv(result.dataset, staging / "metrics.csv")
        (staging / "config.toml").write_text(
            "# fully resolved configuration, SI units\n" + config_text, encoding="utf-8"
        )
        write_json(staging / "summary.json", summary)
        if plots:
            plot_joints(result.dataset, staging / "plots")


def add_checks(summary: dict, result) -> None:
    """Add the engineering checks (PV, pressure, speed vs the bushing's limits) to a summary;
    each exceeded limit warns once."""
    from jointwear.tribology.metrics import engineering_checks

    summary["checks"] = engineering_checks(result.joint_data(), result.config)
    for joint, entry in summary.get("joints", {}).items():
        entry["checks"] = engineering_checks(result.joint_data(joint), result.config)


def run_ends(summary: dict) -> tuple[float, str]:
    """Where a run ended (revolutions; the farthest joint's of several) and a short reason
    for the progress bar."""
    joints = list(summary.get("joints", {}).values()) or [summary]
    done = max(float(joint["revolutions"]) for joint in joints)
    limits = sorted({str(joint["stopped_by"]) for joint in joints if joint["stopped_by"]})
    if limits and all(joint["stopped_by"] for joint in joints):
        return done, f"stopped: {', '.join(limits)}"
    return done, "revolutions"


def end_lines(summary: dict) -> list[str]:
    """Why and when the run (each joint's, of several) ended, one line each."""
    from jointwear.display import end_of_run

    joints = summary.get("joints")
    if not joints:
        return [end_of_run(summary)]
    return [f"{joint}: {end_of_run(entry)}" for joint, entry in joints.items()]


def summary_table(summary: dict, title: str) -> Table:
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
    pv = summary.get("checks", {}).get("pv")
    if pv is not None:
        limit = "no limit known" if pv["limit"] is None else f"limit {pv['limit'] / 1e6:.3g}"
        table.add_row("PV (nominal, cycle mean)", f"{pv['value'] / 1e6:.3g} MPa m/s ({limit})")
    return table


#: entries of a run's --out directory a run may replace (checkpoints included)
OUT_FILES = (*RUN_FILES, "checkpoint.toml", "checkpoint.npz")

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
    from jointwear.checkpoint import (
        Checkpointer,
        CheckpointWriteError,
        has_checkpoint,
        load_checkpoint,
    )
    from jointwear.errors import ConfigError, JointwearError, TimeLimitError
    from jointwear.interrupts import with_resume
    from jointwear.io import check_out
    from jointwear.resources import Deadline, check_run, parse_time_limit
    from jointwear.simulation import Simulation

    seconds = parse_time_limit(time_limit)
    state = None
    if resume is not None:
        if config is not None:
            raise ConfigError(f"--resume: give either CONFIG ({config}) or --resume DIR, not both")
        if set_:
            raise ConfigError(
                "--set: a resumed run keeps its configuration (from --resume DIR/checkpoint.toml)"
            )
        if checkpoint_every is not None:
            raise ConfigError("--checkpoint-every: a resumed run keeps its checkpoint interval")
        if out is not None and out.resolve() != resume.resolve():
            raise ConfigError("--out: a resumed run writes its results into the --resume directory")
        out = check_out(resume, "--resume", files=OUT_FILES, dirs=("plots",))
        cfg, state, checkpointer = load_checkpoint(out)
        name = out.name
    else:
        if config is None:
            raise ConfigError("CONFIG: missing; give a config file or --resume DIR")
        overrides = list(set_ or [])
        if checkpoint_every is not None:
            if checkpoint_every < 0:
                raise ConfigError(f"--checkpoint-every: must be >= 0, got {checkpoint_every}")
            if checkpoint_every > 0 and out is None:
                raise ConfigError("--checkpoint-every: needs --out DIR (checkpoints go there)")
            overrides.append(f"simulation.checkpoint_every={checkpoint_every}")
        if out is not None:  # before anything is computed
            out = check_out(out, files=OUT_FILES, dirs=("plots",))
        cfg = load(config, overrides)
        if out is not None and has_checkpoint(out):
            raise ConfigError(
                f"--out: {out} holds the checkpoint of an unfinished run; continue it with "
                f"`jointwear run --resume {out}` or delete {out}/checkpoint.*"
            )
        every = cfg.simulation.checkpoint_every
        checkpointer = Checkpointer(out, cfg) if out is not None and every > 0 else None
        name = config.name
    check_run(cfg, max_memory)
    resume_command = f"jointwear run --resume {out}" if checkpointer is not None else None
    deadline = Deadline(seconds, "revolutions", resume_command)
    simulation = Simulation(cfg)
    created = out is not None and not out.exists()
    if checkpointer is not None and state is None and resume is None:
        checkpointer.begin()
    try:
        with ProgressBar("revolutions", quiet=quiet) as bar:
            progress = deadline.watching(bar)
            result = simulation.run(progress=progress, state=state, on_step=checkpointer)
            summary = result.summary()
            bar.finish(*run_ends(summary))
    except TimeLimitError:
        raise  # a checkpoint stays for --resume
    except JointwearError as exc:
        # the run cannot finish from this state: leave no checkpoint (or empty folder) behind;
        # a checkpoint that could not be written (full disk) keeps the previous one
        if checkpointer is not None and not isinstance(exc, CheckpointWriteError):
            checkpointer.clear()
            if created:
                with contextlib.suppress(OSError):
                    out.rmdir()
        raise
    except KeyboardInterrupt as exc:
        if checkpointer is None or not checkpointer.config_path.exists():
            raise
        raise with_resume(exc, f"jointwear run --resume {out}") from None
    # one summary, made once: the object `--json` prints is the one summary.json holds
    add_checks(summary, result)
    if out is not None:
        write_outputs(result, out, summary, plots=plots)
    if checkpointer is not None:
        checkpointer.clear()
    if json_:
        emit_json(summary)
    else:
        console.print(summary_table(summary, f"{name}: {summary['contact_model']}"))
        for line in end_lines(summary):
            console.print(line, highlight=False)
        if out is not None:
            console.print(f"results in {out}/")


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
    from jointwear.io import check_out, staged_output
    from jointwear.results import read_result

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
    target = check_out(out if out is not None else result.parent / "plots")
    dataset = read_result(result)
    with staged_output(target) as staging:
        count = len(plot_joints(dataset, staging, magnification=value))
    console.print(f"{count} files written to {target}/")
