"""``jointwear compare``: a simulated wear profile against a measured bushing (paper §3.2)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer
from rich.table import Table

from jointwear.cli.common import (
    JsonOpt,
    MeasuredArg,
    ThresholdOpt,
    UnitsOpt,
    app,
    console,
    emit_json,
)
from jointwear.errors import ConfigError, DataError

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


def parse_align(text: str) -> str | float:
    """``"best"`` or an angle with units (``"12 deg"``; a bare number is radians)."""
    from jointwear.units import to_angle

    if text.strip().lower() == "best":
        return "best"
    return to_angle(text, "--align")


def simulated_profile(
    dataset: Any, path: Path, revolution: int | None
) -> tuple[np.ndarray, int | float]:
    """The wear profile of a saved revolution (default the last) [m] and its revolution
    (fractional for the last profile of a run a life limit ended)."""
    from jointwear.state import revolution_number

    revolutions = [revolution_number(r) for r in dataset["revolution"].values]
    if revolution is None:
        index = len(revolutions) - 1
    elif revolution in revolutions:
        index = revolutions.index(revolution)
    else:
        saved = ", ".join(str(r) for r in revolutions)
        raise ConfigError(f"--revolution: {path} holds the profiles of revolutions {saved}")
    depth = np.asarray(dataset["wear_depth"].values[index], dtype=float)
    if depth.ndim != 1 or not np.all(np.isfinite(depth)):
        raise DataError(f"{path}: the stored wear profile is not a finite 1-D array")
    return depth, revolutions[index]


#: what ``jointwear compare --out`` writes
COMPARE_FILES = (
    "comparison.json",
    "profiles.csv",
    "compare_polar.png",
    "compare_polar.svg",
    "compare_profile.png",
    "compare_profile.svg",
)


def write_staged(out: Path, write: Any) -> list[Path]:
    """Call ``write(staging_dir)``, then publish its files into ``out``: all or nothing."""
    from jointwear.io import staged_output

    with staged_output(out, files=COMPARE_FILES) as staging:
        write(staging)
        names = sorted(item.name for item in staging.iterdir())
    return [out / name for name in names]


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
    from jointwear.io import check_out
    from jointwear.measurement.compare import (
        CIRCLE_FITS,
        PROFILE_CHOICES,
        compare_measurement,
        plot_comparison,
    )
    from jointwear.measurement.io import length_unit_factor, read_points
    from jointwear.registry import suggest
    from jointwear.results import config_of, read_result, select_joint
    from jointwear.units import BARE_LIMITS, to_si

    # options first: a typo must not cost a circle fit, and must leave --out untouched
    fit_name = fit.replace("_", "-")
    if fit_name not in CIRCLE_FITS:
        raise ConfigError(f"--fit: unknown circle fit {fit!r}{suggest(fit_name, CIRCLE_FITS)}")
    if profile not in PROFILE_CHOICES:
        raise ConfigError(
            f"--profile: unknown method {profile!r}{suggest(profile, PROFILE_CHOICES)}"
        )
    if not 0 <= threshold < 1:
        raise ConfigError(f"--threshold: must be in [0, 1), got {threshold:g}")
    depth_floor = to_si(floor, "length", "--floor", bare_limit=BARE_LIMITS["length"][0])
    if depth_floor < 0:
        raise ConfigError(f"--floor: must be >= 0, got {floor!r}")
    alignment = parse_align(align)
    if units is not None:
        length_unit_factor(units, "--units")
    if out is not None:
        out = check_out(out, files=COMPARE_FILES)

    dataset = select_joint(read_result(result), joint)
    config = config_of(dataset)
    simulated, shown_revolution = simulated_profile(dataset, result, revolution)
    if simulated.size != config.contact.nodes:
        raise DataError(
            f"{result}: the profile has {simulated.size} nodes, its config says "
            f"{config.contact.nodes}"
        )
    x, y = read_points(measured, units)
    radius = config.bushing_radius
    comparison = compare_measurement(
        simulated,
        x,
        y,
        radius,
        fit=fit_name,
        axial_length=config.joint.axial_length,
        density=config.materials.bushing.density,
        threshold=threshold,
        align=alignment,
        floor=depth_floor,
        profile=profile,
    )
    summary = comparison.summary()
    summary.update(
        {
            "result": str(result),
            "measured": str(measured),
            "revolution": shown_revolution,
            "floor_m": depth_floor,
        }
    )

    if out is not None:
        from jointwear.io import json_ready, write_json

        label = f"{measured.name} vs {result.name}"

        def write(directory: Path) -> None:
            plot_comparison(comparison, directory, x, y, label=label)
            write_json(directory / "comparison.json", json_ready(summary))
            _write_profiles(directory / "profiles.csv", comparison)

        summary["files"] = [str(p) for p in write_staged(out, write)]

    if json_:
        emit_json(summary)
        return
    console.print(_table(summary, measured, result))
    noise = comparison.fit.rms_residual if comparison.fit is not None else math.nan
    measured_peak = comparison.measured_metrics.peak_depth
    if fit_name == "robust" and threshold * measured_peak < 3 * noise and depth_floor < 3 * noise:
        console.print(
            f"note: the width threshold ({threshold:g} of the peak) is below 3x the noise "
            f"({noise * 1e6:.2g} µm rms on the unworn arc); the measured width counts noise. "
            f'Try --floor "{3 * noise * 1e6:.2g} um".'
        )
    if out is not None:
        console.print(f"plots and data in {out}/")


def _write_profiles(path: Path, comparison: Any) -> None:
    from jointwear.io import atomic_write

    with atomic_write(path, encoding="utf-8", newline="") as handle:
        handle.write("theta [deg],simulated [m],measured [m],measured - simulated [m]\n")
        for theta, sim, meas in zip(
            np.degrees(comparison.theta), comparison.simulated, comparison.measured, strict=True
        ):
            handle.write(f"{theta:.6g},{sim:.10g},{meas:.10g},{meas - sim:.10g}\n")


def _table(summary: dict[str, Any], measured: Path, result: Path) -> Table:
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
