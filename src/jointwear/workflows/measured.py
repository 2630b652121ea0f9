"""Measured bushings: the wear of one (``jointwear measure``), a run against one (``compare``).

:func:`measure_bushing` fits the centre of a measured worn bushing twice (the paper's
plain least-squares circle, biased towards the wear, and a robust fit of the unworn
arc with the radius fixed) and reports the wear profile's metrics for each.
:func:`compare_run_to_measurement` compares a saved run's wear profile with a
measured bushing and writes the plots and tables of the comparison.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from jointwear.errors import ConfigError, DataError

__all__ = [
    "COMPARE_FILES",
    "MeasuredBushing",
    "RunComparison",
    "compare_run_to_measurement",
    "measure_bushing",
    "simulated_profile",
]

#: what ``jointwear compare --out`` writes
COMPARE_FILES = (
    "comparison.json",
    "profiles.csv",
    "compare_polar.png",
    "compare_polar.svg",
    "compare_profile.png",
    "compare_profile.svg",
)


@dataclass(frozen=True)
class MeasuredBushing:
    """Outcome of :func:`measure_bushing`.

    Attributes
    ----------
    fits : dict
        ``{"least_squares": {...}, "robust": {...}}``: per circle fit its centre,
        radius and the wear metrics (the ``jointwear measure --json`` entries).
    points : int
        Measured points [-].
    radius : float
        Unworn bushing radius [m].
    noise : float
        RMS residual of the robust fit on the unworn arc [m].
    floor : float
        Depths at or below this do not count towards the width [m].
    axial_length : float or None
        Bushing length for volume and mass [m].
    density : float or None
        Bushing density for the mass [kg/m^3].
    """

    fits: dict[str, dict[str, Any]]
    points: int
    radius: float
    noise: float
    floor: float
    axial_length: float | None
    density: float | None


@dataclass(frozen=True)
class RunComparison:
    """Outcome of :func:`compare_run_to_measurement`.

    Attributes
    ----------
    summary : dict
        The ``jointwear compare --json`` object (with ``files`` when written).
    comparison : Comparison
        The comparison (:func:`~jointwear.measurement.compare.compare_measurement`).
    out : Path or None
        The folder the plots and tables were written into.
    """

    summary: dict[str, Any]
    comparison: Any
    out: Path | None


def measure_bushing(
    measured: Path,
    radius: str,
    *,
    units: str | None = None,
    nodes: int = 360,
    threshold: float = 0.01,
    floor: str = "0 m",
    angle_offset: str = "0 deg",
    profile: str = "interpolate",
    axial_length: str | None = None,
    density: str | None = None,
    max_memory: str | None = None,
) -> MeasuredBushing:
    """Fit the centre of a measured worn bushing and measure its wear, two ways.

    Parameters
    ----------
    measured : Path
        Measured inner-surface points (CSV with an ``x,y`` header or two columns).
    radius : str
        Unworn bushing radius with its unit, e.g. ``"7.5 mm"`` (a bare number is m).
    units : str, optional
        Length unit of columns without one (default m).
    nodes : int
        Nodes of the profile grid [-].
    threshold : float
        Wear width threshold, a fraction of the peak [-].
    floor : str
        Depths at or below this do not count towards the width, e.g. ``"3 um"``.
    angle_offset : str
        Angle of the bushing's theta = 0 in the file's frame, e.g. ``"90 deg"``.
    profile : str
        Points to nodes: one of :data:`~jointwear.measurement.profile.PROFILE_METHODS`.
    axial_length : str, optional
        Bushing length for volume and mass, e.g. ``"20 mm"``.
    density : str, optional
        Bushing density for the mass, e.g. ``"2200 kg/m^3"``.
    max_memory : str, optional
        Refuse a profile grid that would need more memory than this.

    Returns
    -------
    MeasuredBushing
        Both fits' metrics and the values they were measured with (SI).

    Raises
    ------
    ConfigError
        An option out of range or with a wrong unit.
    DataError
        The measured file cannot be read.
    """
    from jointwear.measurement.fit import fit_circle_least_squares, fit_circle_robust
    from jointwear.measurement.io import length_unit_factor, read_points
    from jointwear.measurement.profile import PROFILE_METHODS
    from jointwear.resources import check_nodes
    from jointwear.units import BARE_LIMITS, to_angle, to_si

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
    grid = (original_radius, nodes, offset, profile, threshold, depth_floor, length, rho)
    results = {name: fit_summary(fit, x, y, *grid) for name, fit in fits.items()}
    noise = fits["robust"].rms_residual
    return MeasuredBushing(results, int(x.size), original_radius, noise, depth_floor, length, rho)


def fit_summary(
    fit: Any,
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
    """A circle fit's centre and radius and the wear metrics of the profile it gives.

    Parameters
    ----------
    fit : CircleFit
        The bushing's fitted centre (and radius).
    x, y : ndarray
        Measured points [m].
    original_radius : float
        Unworn bushing radius [m].
    nodes : int
        Nodes of the profile grid [-].
    offset : float
        Angle of the bushing's theta = 0 in the points' frame [rad].
    method : str
        Points to nodes (:data:`~jointwear.measurement.profile.PROFILE_METHODS`).
    threshold : float
        Wear width threshold, a fraction of the peak [-].
    floor : float
        Depths at or below this do not count towards the width [m].
    axial_length : float or None
        Bushing length [m].
    density : float or None
        Bushing density [kg/m^3].

    Returns
    -------
    dict
        The ``jointwear measure --json`` entry of the fit.
    """
    from jointwear.measurement.profile import measured_wear_profile, wear_metrics

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


def simulated_profile(
    dataset: Any, path: Path, revolution: int | None
) -> tuple[np.ndarray, int | float]:
    """The wear profile of a saved revolution (default the last) and its revolution.

    Parameters
    ----------
    dataset : xarray.Dataset
        A run's result (one joint).
    path : Path
        Its file, for messages.
    revolution : int, optional
        A saved revolution [-]; default the last.

    Returns
    -------
    depth : ndarray
        The wear profile [m].
    revolution : int or float
        Its revolution (fractional for the last profile of a run a life limit ended).
    """
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


def compare_run_to_measurement(
    result: Path,
    measured: Path,
    *,
    units: str | None = None,
    fit: str = "robust",
    align: str = "best",
    out: Path | None = None,
    threshold: float = 0.01,
    floor: str = "0 m",
    profile: str = "auto",
    revolution: int | None = None,
    joint: str | None = None,
) -> RunComparison:
    """Compare a saved run's wear profile with a measured bushing (paper section 3.2).

    The unworn radius, axial length and density come from the result's stored config.
    Both profiles are compared on the simulation's grid, as measured and rotated onto
    each other (``align``): RMS error, peak, width, mass; errors are measured minus
    simulated. The options are checked before the result is read and before ``out``
    is touched.

    Parameters
    ----------
    result : Path
        A ``result.nc`` of a run.
    measured : Path
        Measured inner-surface points.
    units : str, optional
        Length unit of columns without one (default m).
    fit : str
        Bushing centre: ``robust`` or ``least-squares``.
    align : str
        ``"best"`` or the angle of the bushing's theta = 0 in the file's frame.
    out : Path, optional
        Folder for the plots, ``comparison.json`` and ``profiles.csv``.
    threshold : float
        Wear width threshold, a fraction of the peak [-].
    floor : str
        Depths at or below this do not count towards either width, e.g. ``"3 um"``.
    profile : str
        Points to nodes: ``auto``, ``interpolate`` or ``bin``.
    revolution : int, optional
        Compare this saved profile [-] (default the last).
    joint : str, optional
        The clearance joint of a result with several (default the most worn).

    Returns
    -------
    RunComparison
        The summary, the comparison and the folder written.
    """
    from jointwear.io import check_out, json_ready, write_json
    from jointwear.measurement.compare import compare_measurement, plot_comparison
    from jointwear.measurement.io import read_points
    from jointwear.results import config_of, read_result, select_joint

    # options first: a typo must not cost a circle fit, and must leave --out untouched
    fit_name, depth_floor, alignment = _comparison_options(
        fit, profile, threshold, floor, align, units
    )
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
    comparison = compare_measurement(
        simulated,
        x,
        y,
        config.bushing_radius,
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
        label = f"{measured.name} vs {result.name}"

        def write(directory: Path) -> None:
            plot_comparison(comparison, directory, x, y, label=label)
            write_json(directory / "comparison.json", json_ready(summary))
            write_profiles(directory / "profiles.csv", comparison)

        summary["files"] = [str(p) for p in write_staged(out, write)]
    return RunComparison(summary, comparison, out)


def _comparison_options(
    fit: str, profile: str, threshold: float, floor: str, align: str, units: str | None
) -> tuple[str, float, str | float]:
    """The circle fit's name, the depth floor [m] and the alignment [rad] or ``"best"``."""
    from jointwear.measurement.compare import CIRCLE_FITS, PROFILE_CHOICES
    from jointwear.measurement.io import length_unit_factor
    from jointwear.registry import suggest
    from jointwear.units import BARE_LIMITS, to_si
    from jointwear.workflows.inputs import parse_align

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
    return fit_name, depth_floor, alignment


def write_staged(out: Path, write: Any) -> list[Path]:
    """Call ``write(staging_dir)``, then publish its files into ``out``: all or nothing.

    Parameters
    ----------
    out : Path
        The folder.
    write : callable
        ``write(directory)`` writes some of :data:`COMPARE_FILES` into ``directory``.

    Returns
    -------
    list of Path
        The files published, in ``out``.
    """
    from jointwear.io import staged_output

    with staged_output(out, files=COMPARE_FILES) as staging:
        write(staging)
        names = sorted(item.name for item in staging.iterdir())
    return [out / name for name in names]


def write_profiles(path: Path, comparison: Any) -> None:
    """``profiles.csv``: the simulated and measured profiles and their difference.

    Parameters
    ----------
    path : Path
        The file.
    comparison : Comparison
        The comparison (its grid and both profiles) [rad, m].
    """
    from jointwear.io import atomic_write

    with atomic_write(path, encoding="utf-8", newline="") as handle:
        handle.write("theta [deg],simulated [m],measured [m],measured - simulated [m]\n")
        for theta, sim, meas in zip(
            np.degrees(comparison.theta), comparison.simulated, comparison.measured, strict=True
        ):
            handle.write(f"{theta:.6g},{sim:.10g},{meas:.10g},{meas - sim:.10g}\n")
