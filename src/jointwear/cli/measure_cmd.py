"""``jointwear measure``: wear profile of a measured bushing (paper §3.2)."""

from __future__ import annotations

from typing import Annotated, Any

import numpy as np
import typer
from rich.table import Table

from jointwear.cli.common import (
    JsonOpt,
    MaxMemoryOpt,
    MeasuredArg,
    ThresholdOpt,
    UnitsOpt,
    app,
    console,
    emit_json,
)
from jointwear.errors import ConfigError
from jointwear.measurement.fit import CircleFit, fit_circle_least_squares, fit_circle_robust
from jointwear.measurement.io import length_unit_factor, read_points
from jointwear.measurement.profile import (
    PROFILE_METHODS,
    measured_wear_profile,
    wear_metrics,
)
from jointwear.resources import check_nodes
from jointwear.units import BARE_LIMITS, to_angle, to_si

RadiusOpt = Annotated[
    str,
    typer.Option("--radius", help='Unworn bushing radius R0, e.g. "7.5 mm".', show_default=False),
]
NodesOpt = Annotated[int, typer.Option("--nodes", help="Nodes of the profile grid.")]
FloorOpt = Annotated[
    str,
    typer.Option(
        "--floor", help='Depths at or below this do not count towards the width, e.g. "3 um".'
    ),
]
AngleOffsetOpt = Annotated[
    str,
    typer.Option(
        "--angle-offset",
        help="Angle of the bushing's theta = 0 in the file's frame, e.g. \"90 deg\".",
    ),
]
ProfileOpt = Annotated[
    str, typer.Option("--profile", help=f"Points to nodes: {' | '.join(PROFILE_METHODS)}.")
]
AxialLengthOpt = Annotated[
    str | None,
    typer.Option("--axial-length", help='Bushing length for volume and mass, e.g. "20 mm".'),
]
DensityOpt = Annotated[
    str | None,
    typer.Option("--density", help='Bushing density for the mass, e.g. "2200 kg/m^3".'),
]


@app.command()
def measure(
    measured: MeasuredArg,
    radius: RadiusOpt,
    units: UnitsOpt = None,
    nodes: NodesOpt = 360,
    threshold: ThresholdOpt = 0.01,
    floor: FloorOpt = "0 m",
    angle_offset: AngleOffsetOpt = "0 deg",
    profile: ProfileOpt = "interpolate",
    axial_length: AxialLengthOpt = None,
    density: DensityOpt = None,
    json_: JsonOpt = False,
    max_memory: MaxMemoryOpt = None,
) -> None:
    """Fit the centre of a measured worn bushing and report its wear.

    Two fits: the paper's plain least-squares circle (biased: the worn zone pulls
    the centre towards it, so the wear looks shallower) and a robust fit of the
    unworn arc with the radius fixed to --radius.
    """
    # a bare number is metres: "--radius 7.5" is refused as a unit slip, not a 7.5 m bushing
    part = BARE_LIMITS["length"][0]
    original_radius = to_si(radius, "length", "--radius", bare_limit=part)
    if not original_radius > 0:
        raise ConfigError(f"--radius: must be > 0, got {radius!r}")
    if nodes < 16:
        raise ConfigError(f"--nodes: must be >= 16, got {nodes}")
    check_nodes(nodes, 0, "--nodes", max_memory)
    if not 0 <= threshold < 1:
        raise ConfigError(f"--threshold: must be in [0, 1), got {threshold:g}")
    if profile not in PROFILE_METHODS:
        choices = ", ".join(PROFILE_METHODS)
        raise ConfigError(f"--profile: must be one of {choices}, got {profile!r}")
    depth_floor = to_si(floor, "length", "--floor", bare_limit=part)
    if depth_floor < 0:
        raise ConfigError(f"--floor: must be >= 0, got {floor!r}")
    offset = to_angle(angle_offset, "--angle-offset")
    length = (
        None
        if axial_length is None
        else to_si(axial_length, "length", "--axial-length", bare_limit=part)
    )
    rho = None if density is None else to_si(density, "density", "--density")
    for key, value in (("--axial-length", length), ("--density", rho)):
        if value is not None and not value > 0:
            raise ConfigError(f"{key}: must be > 0")

    if units is not None:
        length_unit_factor(units, "--units")  # name the option, not the library argument
    x, y = read_points(measured, units)
    fits = {
        "least_squares": fit_circle_least_squares(x, y),
        "robust": fit_circle_robust(x, y, original_radius),
    }
    results = {
        name: _summary(
            fit, x, y, original_radius, nodes, offset, profile, threshold, depth_floor, length, rho
        )
        for name, fit in fits.items()
    }
    if json_:
        emit_json({"fits": results})
        return

    title = f"measure: {measured.name}, {x.size} points, R0 = {original_radius * 1e3:g} mm"
    table = Table(title=title)
    table.add_column("quantity")
    for name in results:
        table.add_column(name.replace("_", " "), justify="right")
    rows: list[tuple[str, str, float]] = [
        ("centre x", "center_x_m", 1e3),
        ("centre y", "center_y_m", 1e3),
        ("radius", "radius_m", 1e3),
        ("peak wear depth", "peak_wear_depth_m", 1e6),
        ("peak angle", "peak_angle_deg", 1.0),
        ("deepest negative depth", "min_wear_depth_m", 1e6),
        ("wear width", "wear_width_deg", 1.0),
        ("wear area", "wear_area_m2", 1e6),
        ("rms residual", "rms_residual_m", 1e6),
        ("points used", "points_used", 1.0),
    ]
    units_shown = {1e3: " mm", 1e6: " µm", 1.0: ""}
    for label, key, scale in rows:
        unit = units_shown[scale]
        if key == "wear_area_m2":
            unit = " mm²"
        elif key.endswith("_deg"):
            unit = "°"
        table.add_row(label, *(_cell(results[n][key], scale, unit) for n in results))
    if length is not None:
        volumes = (_cell(results[n]["wear_volume_m3"], 1e9, " mm³") for n in results)
        table.add_row("wear volume", *volumes)
    if rho is not None and length is not None:
        masses = (_cell(results[n]["wear_mass_kg"], 1e3, " g") for n in results)
        table.add_row("wear mass", *masses)
    console.print(table)
    noise = fits["robust"].rms_residual
    if threshold * results["robust"]["peak_wear_depth_m"] < 3 * noise and depth_floor < 3 * noise:
        console.print(
            f"note: the width threshold ({threshold:g} of the peak) is below 3x the noise "
            f"({noise * 1e6:.2g} µm rms on the unworn arc); the width counts noise. "
            f'Try --floor "{3 * noise * 1e6:.2g} um".'
        )


def _summary(
    fit: CircleFit,
    x: np.ndarray,
    y: np.ndarray,
    original_radius: float,
    nodes: int,
    offset: float,
    method: str,
    threshold: float,
    floor: float,
    axial_length: float | None,
    density: float | None,
) -> dict[str, Any]:
    depth = measured_wear_profile(x, y, fit, original_radius, nodes, offset, method)
    metrics = wear_metrics(depth, original_radius, threshold, axial_length, density, floor)
    return {
        "method": fit.method,
        "center_x_m": fit.center_x,
        "center_y_m": fit.center_y,
        "radius_m": fit.radius,
        "radius_fixed": fit.radius_fixed,
        "peak_wear_depth_m": metrics.peak_depth,
        "peak_angle_deg": metrics.peak_angle_deg,
        "min_wear_depth_m": metrics.min_depth,
        "wear_width_deg": metrics.width_deg,
        "wear_area_m2": metrics.area,
        "wear_volume_m3": metrics.volume,
        "wear_mass_kg": metrics.mass,
        "rms_residual_m": fit.rms_residual,
        "points": int(x.size),
        "points_used": fit.points_used,
        "nodes": nodes,
        "threshold": threshold,
    }


def _cell(value: float, scale: float, unit: str) -> str:
    if value != value:  # NaN: not computed
        return "-"
    if unit == "":
        return f"{value:.6g}"
    return f"{value * scale:.6g}{unit}"
