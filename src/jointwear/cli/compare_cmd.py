"""``jointwear compare``: a simulated wear profile against a measured bushing (paper §3.2)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from jointwear.cli.common import (
    JsonOpt,
    MeasuredArg,
    ThresholdOpt,
    UnitsOpt,
    app,
    console,
    emit_json,
)

if TYPE_CHECKING:
    from rich.table import Table

ResultArg = Annotated[
    Path,
    typer.Argument(help="A result.nc written by `jointwear run --out`.", show_default=False),
]
FitOpt = Annotated[
    str,
    typer.Option(
        "--fit",
        help="Bushing centre: robust (unworn arc, radius fixed) or least-squares "
        "(the paper's; biased towards the wear).",
    ),
]
AlignOpt = Annotated[
    str,
    typer.Option(
        "--align",
        help='Rotation of the measurement: "best" (least RMS difference) or the angle of the '
        "bushing's theta = 0 in the file's frame, e.g. \"12 deg\".",
    ),
]
OutOpt = Annotated[
    Path | None,
    typer.Option(
        "--out",
        help="Write compare_polar and compare_profile plots (PNG+SVG), comparison.json and "
        "profiles.csv here.",
    ),
]
FloorOpt = Annotated[
    str,
    typer.Option(
        "--floor",
        help='Depths at or below this do not count towards either width, e.g. "3 um".',
    ),
]
ProfileOpt = Annotated[
    str,
    typer.Option(
        "--profile",
        help="Points to nodes: auto (bin if >= 3 points per node) | interpolate | bin.",
    ),
]
RevolutionOpt = Annotated[
    int | None,
    typer.Option(
        "--revolution", help="Compare this saved profile of the result (default the last)."
    ),
]


@app.command()
def compare(
    result: ResultArg,
    measured: MeasuredArg,
    units: UnitsOpt = None,
    fit: FitOpt = "robust",
    align: AlignOpt = "best",
    out: OutOpt = None,
    threshold: ThresholdOpt = 0.01,
    floor: FloorOpt = "0 m",
    profile: ProfileOpt = "auto",
    revolution: RevolutionOpt = None,
    joint: Annotated[
        str | None,
        typer.Option(
            "--joint", help="The clearance joint of a result with several (default: the most worn)."
        ),
    ] = None,
    json_: JsonOpt = False,
) -> None:
    """Compare a simulated wear profile with a measured bushing.

    The unworn radius, axial length and density come from the result's stored
    config. Both are compared on the simulation's grid, first as measured (no
    rotation: the measured peak angle against the predicted one), then with the
    measured profile rotated onto the simulated one (--align best, or a given
    offset): RMS error, peak, width, mass. Errors are measured minus simulated.
    """
    from jointwear.workflows.measured import compare_run_to_measurement

    done = compare_run_to_measurement(
        result,
        measured,
        units=units,
        fit=fit,
        align=align,
        out=out,
        threshold=threshold,
        floor=floor,
        profile=profile,
        revolution=revolution,
        joint=joint,
    )
    summary, comparison = done.summary, done.comparison
    if json_:
        emit_json(summary)
        return
    console.print(_table(summary, measured, result))
    noise = comparison.fit.rms_residual if comparison.fit is not None else math.nan
    measured_peak = comparison.measured_metrics.peak_depth
    depth_floor = summary["floor_m"]
    robust = fit.replace("_", "-") == "robust"
    if robust and threshold * measured_peak < 3 * noise and depth_floor < 3 * noise:
        console.print(
            f"note: the width threshold ({threshold:g} of the peak) is below 3x the noise "
            f"({noise * 1e6:.2g} µm rms on the unworn arc); the measured width counts noise. "
            f'Try --floor "{3 * noise * 1e6:.2g} um".'
        )
    if done.out is not None:
        console.print(f"plots and data in {done.out}/")


def _table(summary: dict[str, Any], measured: Path, result: Path) -> Table:
    from rich.table import Table

    table = Table(
        title=f"compare: {measured.name} ({summary['fit']} fit, {summary['points']} points) "
        f"vs {result.name} (revolution {summary['revolution']})"
    )
    table.add_column("quantity")
    table.add_column("simulated", justify="right")
    table.add_column("measured", justify="right")
    table.add_column("meas. - sim.", justify="right")

    def um(value: float) -> str:
        return "-" if value != value else f"{value * 1e6:.4g} µm"

    def rel(value: float) -> str:
        return "-" if value != value else f"{100 * value:+.3g} %"

    table.add_row(
        "wear peak",
        um(summary["peak_wear_depth_simulated_m"]),
        um(summary["peak_wear_depth_measured_m"]),
        f"{um(summary['peak_error_m'])} ({rel(summary['peak_error_rel'])})",
    )
    shift = summary["alignment_offset_deg"]
    how = "best fit" if summary["alignment"] == "best" else "given"
    table.add_row(
        "peak angle as measured",
        f"{summary['peak_angle_simulated_deg']:.4g}°",
        f"{summary['peak_angle_measured_deg']:.4g}°",
        f"{summary['peak_angle_difference_deg']:+.3g}°",
    )
    table.add_row("RMS error as measured", "", "", um(summary["rms_error_measured_frame_m"]))
    table.add_row(f"rotation ({how})", "", "", f"{shift:+.4g}°")
    table.add_row(
        f"peak angle, rotated {shift:+.3g}°",
        f"{summary['peak_angle_simulated_deg']:.4g}°",
        f"{summary['peak_angle_aligned_deg']:.4g}°",
        f"{summary['peak_angle_residual_deg']:+.3g}°",
    )
    table.add_row(
        "wear width",
        f"{summary['wear_width_simulated_deg']:.4g}°",
        f"{summary['wear_width_measured_deg']:.4g}°",
        f"{summary['width_error_deg']:+.3g}°",
    )
    mass_sim, mass_meas = summary["wear_mass_simulated_kg"], summary["wear_mass_measured_kg"]
    table.add_row(
        "wear mass",
        "-" if mass_sim != mass_sim else f"{mass_sim * 1e3:.4g} g",
        "-" if mass_meas != mass_meas else f"{mass_meas * 1e3:.4g} g",
        rel(summary["mass_error_rel"]),
    )
    table.add_row("RMS error, rotated", "", "", um(summary["rms_error_m"]))
    table.add_row("largest error, rotated", "", "", um(summary["max_abs_error_m"]))
    table.add_row("fit rms residual", "", um(summary["fit_rms_residual_m"]), "")
    return table
