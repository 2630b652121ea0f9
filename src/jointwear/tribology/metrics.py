"""Wear metrics as the paper reports them: peak, width, area, volume, mass.

All functions take a wear-depth profile on the equally spaced node grid
``theta_j = 2 pi j / N`` (radial growth of the bushing radius, [m]).

:data:`CHECKS` are the engineering checks of a run against the bushing material's
datasheet limits (:mod:`jointwear.materials`): nominal pressure, local peak pressure,
sliding speed and PV; :func:`operating_values` computes them from a load cycle,
:func:`engineering_checks` from a result dataset, warning
(:class:`~jointwear.errors.MaterialLimitWarning`) where a limit is exceeded.

:data:`WEAR_METRICS` is the one metric schema: the per-update record of a run,
the result dataset, ``WearResult.summary()`` (``run --json``), the metrics CSV,
sweeps and the life limits all take their names, units and descriptions from it,
and :func:`evaluate_metrics` computes every metric of a profile.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from jointwear.materials import LIMIT_KEYS
from jointwear.tribology.sliding import sliding_speed

if TYPE_CHECKING:
    from jointwear.config import JointConfig

__all__ = [
    "CHECKS",
    "PIN_METRICS",
    "WEAR_METRICS",
    "Check",
    "JointGeometry",
    "Metric",
    "compare_with_limits",
    "engineering_checks",
    "evaluate_metrics",
    "operating_values",
    "pin_metrics",
    "profile_metrics",
    "removed_area",
    "wear_mass",
    "wear_peak",
    "wear_volume",
    "wear_width",
    "worn_area",
]


@dataclass(frozen=True)
class Metric:
    """One scalar wear metric of a profile.

    Attributes
    ----------
    name : str
        Variable name in the result dataset and the per-update record.
    units : str
        SI unit of the dataset variable (UDUNITS spelling).
    long_name : str
        What it is.
    key : str or None
        Key in ``WearResult.summary()`` / ``run --json`` / sweeps (unit in the name),
        ``None`` if not reported there.
    display_units : str
        Unit in the metrics CSV header.
    scale : float
        Factor from ``units`` to the ``key`` / CSV value.
    """

    name: str
    units: str
    long_name: str
    key: str | None
    display_units: str
    scale: float = 1.0

    @property
    def header(self) -> str:
        """Column header of the metrics CSV, unit in brackets."""
        return f"{self.name} [{self.display_units}]"


#: the wear metrics, in report order
WEAR_METRICS: tuple[Metric, ...] = (
    Metric("peak_wear_depth", "m", "largest wear depth of the bushing", "peak_wear_depth_m", "m"),
    Metric(
        "wear_width",
        "rad",
        "angular width of the worn zone",
        "wear_width_deg",
        "deg",
        180.0 / math.pi,
    ),
    Metric("wear_area", "m2", "cross-section area removed by wear", None, "m^2"),
    Metric("wear_volume", "m3", "worn volume", "wear_volume_m3", "m^3"),
    Metric("wear_mass", "kg", "worn mass", "wear_mass_kg", "kg"),
    Metric(
        "min_wall_thickness",
        "m",
        "smallest remaining bushing wall thickness",
        "min_wall_thickness_m",
        "m",
    ),
    Metric(
        "max_clearance",
        "m",
        "largest radial play of the pin (clearance plus wear)",
        "max_clearance_m",
        "m",
    ),
)


#: the pin's metrics, when the pin wears (``materials.pin.wear_coefficient``)
PIN_METRICS: tuple[Metric, ...] = (
    Metric(
        "pin_peak_wear_depth", "m", "largest wear depth of the pin", "pin_peak_wear_depth_m", "m"
    ),
    Metric("pin_wear_volume", "m3", "worn volume of the pin", "pin_wear_volume_m3", "m^3"),
)


def pin_metrics(pin_wear_depth: ArrayLike, joint: JointConfig) -> dict[str, float]:
    """The :data:`PIN_METRICS` of a pin wear profile (pin frame) [SI].

    The removed area of a pin of radius ``R_p`` worn inwards by ``h`` is
    ``sum h_j (R_p - h_j / 2) dtheta``. Of a map over ``S`` slices along the pin: the
    peak is its deepest point, the area the mean of the slices' (so the volume is the sum
    of the slices' areas times their width ``b / S``), as the bushing's.

    Parameters
    ----------
    pin_wear_depth : array_like, shape (N,) or (S, N)
        Wear depth of the pin [m].
    joint : jointwear.config.JointConfig
        The ``[joint]`` section: ``pin_radius`` ``R_p`` [m] and ``axial_length`` ``b`` [m].
    """
    depth = np.asarray(pin_wear_depth, dtype=float)
    area = float(np.sum(depth * (joint.pin_radius - 0.5 * depth)) * 2 * np.pi / depth.size)
    return {
        "pin_peak_wear_depth": float(depth.max()),
        "pin_wear_volume": area * joint.axial_length,
    }


@dataclass(frozen=True)
class JointGeometry:
    """What the metrics need of the joint besides the profile.

    Attributes
    ----------
    bushing_radius : float
        Unworn inner radius of the bushing [m].
    clearance : float
        Radial clearance of the unworn joint [m].
    axial_length : float
        Axial length of the joint ``b`` [m].
    bushing_thickness : float
        Wall thickness of the unworn bushing ``L`` [m].
    density : float
        Density of the bushing material [kg/m^3].
    width_threshold : float
        Fraction of the peak that counts as worn [-].
    """

    bushing_radius: float
    clearance: float
    axial_length: float
    bushing_thickness: float
    density: float
    width_threshold: float = 0.01


def evaluate_metrics(wear_depth: ArrayLike, joint: JointGeometry) -> dict[str, float]:
    """Every metric of :data:`WEAR_METRICS` for one wear-depth profile (SI units).

    Parameters
    ----------
    wear_depth : array_like, shape (N,) or (slices, N)
        Radial wear depth at the nodes [m] (a map along the pin: every slice's row).
    joint : JointGeometry
        Radius, clearance, axial length, wall thickness, density, width threshold.
    """
    depth = np.asarray(wear_depth, dtype=float)
    peak = float(depth.max())
    # a map along the pin (slices, nodes): the width of the slice with the deepest wear,
    # the area the mean of the slices' (so that the volume is the area times the length)
    deepest = depth if depth.ndim == 1 else depth[np.unravel_index(depth.argmax(), depth.shape)[0]]
    return _metrics(
        peak, _width(deepest, peak, joint.width_threshold),
        worn_area(joint.bushing_radius, depth), joint,
    )  # fmt: skip


def _metrics(peak: Any, width: Any, area: Any, joint: JointGeometry) -> dict[str, Any]:
    """:data:`WEAR_METRICS` from the peak [m], width [rad] and removed area [m^2]."""
    return {
        "peak_wear_depth": peak,
        "wear_width": width,
        "wear_area": area,
        "wear_volume": wear_volume(area, joint.axial_length),
        "wear_mass": wear_mass(area, joint.axial_length, joint.density),
        "min_wall_thickness": joint.bushing_thickness - peak,
        "max_clearance": joint.clearance + peak,
    }


def profile_metrics(wear_depth: ArrayLike, joint: JointGeometry) -> dict[str, np.ndarray]:
    """:func:`evaluate_metrics` of each row of a stack of profiles, one array per metric.

    Each row's values are those of the row alone, to the bit (the reductions run along
    the rows as on a single profile), so the per-update record of a run does not depend
    on how its rows were grouped.

    Parameters
    ----------
    wear_depth : array_like, shape (K, N)
        ``K`` radial wear-depth profiles at the nodes [m].
    joint : JointGeometry
        Radius, clearance, axial length, wall thickness, density, width threshold.
    """
    depth = np.asarray(wear_depth, dtype=float)
    nodes = depth.shape[1]
    peak = depth.max(axis=1)
    radius = np.asarray(joint.bushing_radius, dtype=float)
    area = 0.5 * (depth * (2 * radius + depth)).sum(axis=1) * 2 * np.pi / nodes
    return _metrics(peak, _widths(depth, peak, joint.width_threshold), area, joint)


def _widths(depth: np.ndarray, peak: np.ndarray, threshold: float) -> np.ndarray:
    """:func:`wear_width` of each row of ``depth`` (largest values ``peak``) [rad]."""
    out = np.zeros(depth.shape[0])
    worn = peak > 0
    if not worn.any():
        return out
    rows, nodes = depth[worn], depth.shape[1]
    above = rows - (threshold * peak[worn])[:, None]
    inside = above > 0
    # the intervals that cross the threshold, in node order, the periodic one last
    row, crossing = (inside != np.roll(inside, -1, axis=1)).nonzero()
    count = np.bincount(row, minlength=rows.shape[0])
    both = np.count_nonzero(inside, axis=1) - count // 2
    here = above[row, crossing]
    there = above[row, (crossing + 1) % nodes]
    fraction = np.maximum(here, there) / np.abs(here - there)
    # each row's fractions summed as a row of their own (a segmented sum would add them
    # in another order)
    total = np.zeros(rows.shape[0])
    start = np.concatenate(([0], np.cumsum(count)[:-1]))
    # (sorted(set()) of a few counts: np.unique would import numpy.ma at a run's start)
    for size in sorted(set(count[count > 0].tolist())):
        members = np.flatnonzero(count == size)
        total[members] = fraction[start[members, None] + np.arange(size)].sum(axis=1)
    width = (both + total) * 2 * np.pi / nodes
    out[worn] = np.minimum(width, 2 * np.pi)  # all worn: exactly 2 pi, not one ulp more
    return out


def wear_peak(wear_depth: ArrayLike) -> float:
    """Largest wear depth [m].

    Parameters
    ----------
    wear_depth : array_like, shape (N,)
        Radial wear depth at the nodes [m].
    """
    return float(np.asarray(wear_depth).max())


def wear_width(wear_depth: ArrayLike, threshold: float = 0.01) -> float:
    """Angular extent of the worn zone [rad].

    The measure of the angles where the profile, linearly interpolated between
    nodes (periodically), exceeds ``threshold * peak``: whole node intervals
    above the threshold count fully, intervals that cross it count up to the
    interpolated crossing. Unlike a node count this is continuous in the
    model's parameters (so calibration can use it) and exact for the
    interpolated profile. For the single scar a revolute joint wears it is the
    scar's width; for several scars, their summed width.

    Parameters
    ----------
    wear_depth : array_like, shape (N,)
        Radial wear depth at the nodes [m].
    threshold : float
        Fraction of the peak that counts as worn [-], default 1 %.
    """
    depth = np.asarray(wear_depth, dtype=float)
    return _width(depth, depth.max(), threshold)


def _width(depth: np.ndarray, peak: float, threshold: float) -> float:
    """:func:`wear_width` of a float profile whose largest value is ``peak`` [rad]."""
    if not peak > 0:
        return 0.0
    above = depth - threshold * peak
    inside = above > 0
    # the few intervals that cross the threshold (one end in, one out, so |a - b| > 0),
    # the last one periodic
    crossing = (inside[:-1] != inside[1:]).nonzero()[0]
    if inside[-1] != inside[0]:
        crossing = np.append(crossing, depth.size - 1)
    # crossings alternate in and out: half of them leave an interval that started inside
    both = np.count_nonzero(inside) - crossing.size // 2
    here = above[crossing]
    there = above.take(crossing + 1, mode="wrap")
    fraction = np.maximum(here, there) / np.abs(here - there)
    width = (both + fraction.sum()) * 2 * np.pi / depth.size
    return float(min(width, 2 * np.pi))  # all worn: exactly 2 pi, not one ulp more


def removed_area(original_radius: float | ArrayLike, radius: ArrayLike) -> float:
    """Area of bushing removed by wear, exact for a polar contour [m^2].

    .. math:: A = \\tfrac12 \\sum_j (r_j^2 - r_{0,j}^2) \\, \\Delta\\theta

    the area between two star-shaped contours sampled at the same angles (the
    trapezoid rule on a periodic grid, spectrally accurate for smooth contours).

    Parameters
    ----------
    original_radius : float or array_like, shape (N,)
        Radius before wear [m].
    radius : array_like, shape (N,)
        Radius after wear [m].
    """
    radius = np.asarray(radius, dtype=float)
    return worn_area(original_radius, radius - original_radius)


def worn_area(original_radius: float | ArrayLike, wear_depth: ArrayLike) -> float:
    """Area removed by a wear-depth profile, exact for a polar contour [m^2].

    :func:`removed_area` in terms of ``h = r - r_0``: ``1/2 sum h_j (2 r_0 + h_j) dtheta``,
    so that micrometre depths on a millimetre radius keep full precision.

    Parameters
    ----------
    original_radius : float or array_like, shape (N,)
        Radius before wear [m].
    wear_depth : array_like, shape (N,)
        Radial wear depth [m].
    """
    depth = np.asarray(wear_depth, dtype=float)
    original = np.asarray(original_radius, dtype=float)
    if original.ndim:  # (a scalar radius broadcasts by itself)
        original = np.broadcast_to(original, depth.shape)
    return float(0.5 * (depth * (2 * original + depth)).sum() * 2 * np.pi / depth.size)


def wear_volume(removed_area: float, axial_length: float) -> float:
    """Worn volume ``b * A`` [m^3].

    Parameters
    ----------
    removed_area : float
        Removed cross-section area [m^2].
    axial_length : float
        Axial length of the joint ``b`` [m].
    """
    return removed_area * axial_length


def wear_mass(removed_area: float, axial_length: float, density: float) -> float:
    """Worn mass ``rho * b * A`` [kg].

    Parameters
    ----------
    removed_area : float
        Removed cross-section area [m^2].
    axial_length : float
        Axial length of the joint ``b`` [m].
    density : float
        Density of the bushing material [kg/m^3].
    """
    return density * axial_length * removed_area


# ---------------------------------------------------------------- engineering checks


@dataclass(frozen=True)
class Check:
    """One engineering check of a run against a datasheet limit.

    Attributes
    ----------
    label : str
        Short name for tables and warnings.
    limit_key : str or None
        The material key (``materials.bushing.<key>``) it is compared with; ``None``
        for a value reported but not compared.
    unit : str
        SI unit of the value.
    display_unit : str
        Unit for tables and warnings.
    description : str
        What the value is.
    """

    label: str
    limit_key: str | None
    unit: str
    display_unit: str
    description: str


#: the engineering checks, in report order; the datasheet limits are nominal, so the
#: nominal pressure and the nominal PV are compared, the local values only reported
CHECKS: dict[str, Check] = {
    "nominal_pressure": Check(
        "nominal pressure",
        "max_dynamic_pressure",
        "Pa",
        "MPa",
        "largest nominal pressure F / (2 R_p b) over the cycle",
    ),
    "peak_pressure": Check(
        "peak pressure",
        "max_static_pressure",
        "Pa",
        "MPa",
        "largest local contact pressure (stored pressure snapshots of the unworn and the "
        "final contour)",
    ),
    "sliding_speed": Check(
        "sliding speed",
        "max_sliding_speed",
        "m/s",
        "m/s",
        "largest sliding speed R_p |d(phi_pin - phi_bushing)/dt| over the cycle",
    ),
    "pv": Check(
        "nominal PV (cycle mean)",
        "max_pv",
        "Pa*m/s",
        "MPa*m/s",
        "cycle mean of nominal pressure F / (2 R_p b) times sliding speed (the datasheet "
        "PV, compared with the limit)",
    ),
    "pv_max": Check(
        "PV (largest)",
        None,
        "Pa*m/s",
        "MPa*m/s",
        "largest nominal pressure times sliding speed over the cycle (not compared)",
    ),
    "pv_peak_local": Check(
        "PV (local peak)",
        None,
        "Pa*m/s",
        "MPa*m/s",
        "largest local contact pressure times sliding speed at a node (stored pressure "
        "snapshots; not compared)",
    ),
}


def operating_values(
    load: ArrayLike,
    relative_rotation: ArrayLike,
    step_duration: ArrayLike,
    pin_radius: float,
    axial_length: float,
    pressure: ArrayLike | None = None,
    pressure_steps: ArrayLike | None = None,
) -> dict[str, float]:
    """The values of :data:`CHECKS` over one load cycle (SI).

    Step ``k`` carries the load ``F_k`` (at its start) for ``dt_k`` while the pin turns
    by ``dphi_k`` relative to the bushing: nominal pressure ``p_k = F_k / (2 R_p b)``,
    sliding speed ``v_k = R_p |dphi_k| / dt_k``. The datasheet PV is the cycle mean
    ``sum p_k v_k dt_k / T`` (the mean frictional heat flux over the friction
    coefficient); its largest value over the cycle is ``pv_max``.

    Parameters
    ----------
    load : array_like, shape (M,)
        Joint load at each step [N].
    relative_rotation : array_like, shape (M,)
        Rotation of the pin relative to the bushing over each step [rad].
    step_duration : array_like, shape (M,)
        Duration of each step [s].
    pin_radius : float
        Pin radius ``R_p`` [m].
    axial_length : float
        Axial length of the joint ``b`` [m].
    pressure : array_like, shape (S, N), optional
        Local contact pressure at ``S`` steps and ``N`` nodes [Pa]; without it the
        local values are NaN.
    pressure_steps : array_like of int, shape (S,), optional
        The step of each row of ``pressure``.

    Returns
    -------
    dict
        ``nominal_pressure`` [Pa], ``peak_pressure`` [Pa], ``sliding_speed`` [m/s],
        ``pv``, ``pv_max``, ``pv_peak_local`` [Pa m/s].
    """
    load = np.asarray(load, dtype=float)
    duration = np.asarray(step_duration, dtype=float)
    nominal = load / (2.0 * pin_radius * axial_length)
    speed = sliding_speed(relative_rotation, duration, pin_radius)
    out = {
        "nominal_pressure": float(nominal.max()),
        "peak_pressure": math.nan,
        "sliding_speed": float(speed.max()),
        "pv": float(np.sum(nominal * speed * duration) / np.sum(duration)),
        "pv_max": float(np.max(nominal * speed)),
        "pv_peak_local": math.nan,
    }
    if pressure is not None:
        local = np.asarray(pressure, dtype=float).max(axis=1)
        out["peak_pressure"] = float(local.max())
        steps = np.asarray(pressure_steps, dtype=int)
        out["pv_peak_local"] = float(np.max(local * speed[steps]))
    return out


def _display(value: float, unit: str) -> str:
    from jointwear.units import format_quantity

    return format_quantity(value, unit, digits=3).replace("*", " ")


def compare_with_limits(
    values: dict[str, float],
    limits: Any,
    name: str | None = None,
    where: str = "",
    warn: bool = True,
) -> dict[str, dict[str, Any]]:
    """The ``checks`` object: each value with its limit, unit and verdict.

    Parameters
    ----------
    values : dict
        :func:`operating_values` (SI).
    limits : mapping or jointwear.config.MaterialConfig
        The bushing material's ``max_*`` values [SI] (missing or ``None``: none known).
    name : str, optional
        The material's library name, for warnings.
    where : str
        Names the joint in warnings (e.g. ``"joint 'rod-slider': "``).
    warn : bool
        Warn (:class:`~jointwear.errors.MaterialLimitWarning`) for each exceeded limit.

    Returns
    -------
    dict
        name -> ``{"value", "limit", "unit", "ok", "limit_key", "description"}``; ``ok``
        is ``None`` where no limit is known or the value is not compared.
    """
    from jointwear.errors import MaterialLimitWarning

    if not isinstance(limits, Mapping):
        limits = {key: getattr(limits, key, None) for key in LIMIT_KEYS}
    out: dict[str, dict[str, Any]] = {}
    for key, check in CHECKS.items():
        value = values[key]
        limit = limits.get(check.limit_key) if check.limit_key else None
        ok = None if limit is None or not math.isfinite(value) else bool(value <= limit)
        out[key] = {
            "value": value,
            "limit": limit,
            "unit": check.unit,
            "ok": ok,
            "limit_key": f"materials.bushing.{check.limit_key}" if check.limit_key else None,
            "description": check.description,
        }
        if ok is False and warn:
            of = f" of {name!r}" if name else ""
            warnings.warn(
                MaterialLimitWarning(
                    f"materials.bushing.{check.limit_key}: {where}{check.label} "
                    f"{_display(value, check.display_unit)} exceeds the limit "
                    f"{_display(limit, check.display_unit)}{of}; the wear coefficient "
                    "does not hold beyond it"
                ),
                stacklevel=3,
            )
    return out


def engineering_checks(
    dataset: Any,
    config: Any,
    warn: bool = True,
    limits: Mapping[str, float | None] | None = None,
    name: str | None = None,
) -> dict[str, dict[str, Any]]:
    """The :data:`CHECKS` of a single-joint result dataset against the bushing's limits.

    Parameters
    ----------
    dataset : xarray.Dataset or ResultContents
        A result without a ``joint`` dimension (``WearResult.joint_data()``, or
        ``WearResult.joint_dataset()``). Without its pressure snapshots (a run with
        ``pressures=False``) the local values are NaN and the peak pressure is not
        compared.
    config : jointwear.config.Config
        Uses ``joint.pin_radius``, ``joint.axial_length`` and ``materials.bushing``.
    warn : bool
        Warn for each exceeded limit.
    limits : mapping, optional
        ``max_*`` values [SI] to compare with instead of ``materials.bushing``'s.
    name : str, optional
        The material named in warnings (default ``materials.bushing.name``).
    """
    time = np.asarray(dataset["time"].values, dtype=float)
    period = float(dataset.attrs["period_s"])
    pressure = steps = None
    # a result run without pressure snapshots (a sweep case) has no local values
    if "pressure_initial" in dataset:
        phase = np.asarray(dataset["phase"].values, dtype=float)
        snapshot = np.searchsorted(phase, np.asarray(dataset["snapshot"].values, dtype=float))
        pressure = np.concatenate(
            [dataset["pressure_initial"].values, dataset["pressure_final"].values]
        )
        steps = np.concatenate([snapshot, snapshot])
    values = operating_values(
        dataset["joint_load"].values,
        dataset["relative_rotation"].values,
        np.diff(np.append(time, period)),
        config.joint.pin_radius,
        config.joint.axial_length,
        pressure,
        steps,
    )
    joint = dataset.attrs.get("joint")
    where = f"joint {joint!r}: " if joint and len(config.joints) > 1 else ""
    bushing = config.materials.bushing
    return compare_with_limits(
        values, bushing if limits is None else limits, name or bushing.name, where, warn
    )
