"""``jointwear measure``: wear profile of a measured bushing (paper §3.2)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Annotated

import typer

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
from jointwear.measurement.profile import PROFILE_METHODS

if TYPE_CHECKING:
    from rich.table import Table

if TYPE_CHECKING:
    from jointwear.workflows.measured import MeasuredBushing

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
    from jointwear.workflows.measured import measure_bushing

    done = measure_bushing(
        measured,
        radius,
        units=units,
        nodes=nodes,
        threshold=threshold,
        floor=floor,
        angle_offset=angle_offset,
        profile=profile,
        axial_length=axial_length,
        density=density,
        max_memory=max_memory,
    )
    if json_:
        emit_json({"fits": done.fits})
        return
    console.print(_table(done, measured.name))
    noise = done.noise
    peak = done.fits["robust"]["peak_wear_depth_m"]
    if threshold * peak < 3 * noise and done.floor < 3 * noise:
        console.print(
            f"note: the width threshold ({threshold:g} of the peak) is below 3x the noise "
            f"({noise * 1e6:.2g} µm rms on the unworn arc); the width counts noise. "
            f'Try --floor "{3 * noise * 1e6:.2g} um".'
        )


def _table(done: MeasuredBushing, name: str) -> Table:
    from rich.table import Table

    results = done.fits
    title = f"measure: {name}, {done.points} points, R0 = {done.radius * 1e3:g} mm"
    table = Table(title=title)
    table.add_column("quantity")
    for fit in results:
        table.add_column(fit.replace("_", " "), justify="right")
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
    if done.axial_length is not None:
        volumes = (_cell(results[n]["wear_volume_m3"], 1e9, " mm³") for n in results)
        table.add_row("wear volume", *volumes)
    if done.density is not None and done.axial_length is not None:
        masses = (_cell(results[n]["wear_mass_kg"], 1e3, " g") for n in results)
        table.add_row("wear mass", *masses)
    return table


def _cell(value: float, scale: float, unit: str) -> str:
    if value != value:  # NaN: not computed
        return "-"
    if unit == "":
        return f"{value:.6g}"
    return f"{value * scale:.6g}{unit}"
