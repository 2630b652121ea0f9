"""Calibrate model parameters to measured wear profiles (and to the paper's tables).

The paper compares its simulation with measured bushings (§3.2); fitting the
wear coefficient ``K_d`` -- and, if the data allow, the joint's undisclosed
geometry -- to such measurements is the natural next step.

Method
------
One or several *cases*: a measured bushing (points of its inner surface) and
the config overrides of its run (speed, revolutions, clearance ...). For given
parameter values every case is simulated, the measured profile (robust circle
fit by default, see :mod:`jointwear.measurement.fit`) is put on the
simulation's node grid, rotated onto the simulated profile, and the residual
per node is

.. math::

    r_{ij} = \\frac{h^{sim}_i(\\theta_j) - h^{meas}_i(\\theta_j)}{\\max_j h^{meas}_i}

(each case normalised by its own measured peak, so that shallow and deep
bushings weigh alike). All residuals are stacked and minimised by
:func:`jointwear.calibration.calibrate` (``scipy.optimize.least_squares``,
bounded, logarithmic scale for bounds spanning more than a decade). The 1σ
uncertainty comes from the Jacobian at the optimum,
``sigma^2 (J^T J)^-1`` with ``sigma^2`` the residual variance; it assumes
independent node residuals, which neighbouring nodes sharing the same points
are not quite, so read it as a lower bound.

Conditioning: without contour update the simulated profile is exactly
proportional to ``K_d`` (one revolution is computed and scaled), so fitting
``K_d`` alone is a well-conditioned, essentially linear problem with a single
minimum. With contour update wear is nonlinear in ``K_d`` (the widening contact
spreads the pressure), still smooth and monotone in practice; use a fixed
``simulation.update_every`` when calibrating -- the adaptive interval changes
discretely with the parameters and makes the finite-difference Jacobian noisy.
Geometry parameters (axial length, wall thickness, preload) change the shape
of the profile only weakly and correlate with ``K_d``: fit them together only
with several cases that differ (e.g. in speed), and check the uncertainties.

Alignment: the measured profile's rotation is found by best fit at the
starting values and kept fixed during a least-squares pass; after the pass it
is found again at the fitted values, and the pass is repeated (at most three
times) while it moves by more than a tenth of a node.

The paper's protocol -- scalar metrics (peak, width, mass) of one of its table
rows -- is :func:`jointwear.paper.calibration.calibrate_paper_row`.
"""

from __future__ import annotations

import math
import typing
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear.calibration import CalibrationResult, Parameter, calibrate, config_value
from jointwear.config import Config, key_field, parse_override
from jointwear.errors import ConfigError, DataError, JointwearError
from jointwear.measurement.compare import (
    ALIGN_BEST,
    CIRCLE_FITS,
    Comparison,
    compare_measurement,
    fit_circle,
    resolve_profile_method,
)
from jointwear.measurement.fit import CircleFit
from jointwear.measurement.profile import measured_wear_profile
from jointwear.registry import suggest
from jointwear.units import DIMENSIONS, to_si

__all__ = [
    "DEFAULT_BOUNDS",
    "PARAMETER_ALIASES",
    "MeasuredCase",
    "ProfileCalibration",
    "calibrate_profiles",
    "key_kind",
    "key_unit",
    "parse_case",
    "parse_fit",
    "resolve_key",
    "resolve_parameter",
]

FloatArray = NDArray[np.float64]

#: Short names of the parameters users calibrate most.
PARAMETER_ALIASES: dict[str, str] = {
    "wear_coefficient": "materials.bushing.wear_coefficient",
    "axial_length": "joint.axial_length",
    "bushing_thickness": "joint.bushing_thickness",
    "spring_preload": "mechanism.spring_preload",
}

#: Default search bounds [SI]. ``K_d`` 1e-16 ... 1e-10 1/Pa (log scale: PTFE-like
#: polymers lie around 1e-13 ... 1e-12); axial length, wall thickness and preload
#: wide around the paper's joint (the reproduction calibrates them on one row of its
#: tables within these bounds). Any other real-valued key defaults to a tenth ... ten
#: times its current value.
DEFAULT_BOUNDS: dict[str, tuple[float, float]] = {
    "materials.bushing.wear_coefficient": (1e-16, 1e-10),
    "joint.axial_length": (5e-3, 80e-3),
    "joint.bushing_thickness": (0.3e-3, 10e-3),
    "mechanism.spring_preload": (0.0, 400.0),
}

#: Residual of a case whose simulation fails (e.g. wears through the wall) [-]:
#: large, so that the optimiser steps back.
_FAILED_RESIDUAL = 10.0
#: Re-align and repeat while the offset moves by more than this share of a node.
_REALIGN_TOLERANCE = 0.1
_MAX_PASSES = 3


# ---------------------------------------------------------------- parameter names
def _numeric_keys(data: Mapping[str, Any], prefix: str = "") -> list[str]:
    keys = []
    for name, value in data.items():
        dotted = f"{prefix}{name}"
        if isinstance(value, Mapping):
            keys += _numeric_keys(value, dotted + ".")
        elif isinstance(value, float):
            keys.append(dotted)
    return keys


def _field(key: str) -> Any:
    from pydantic.fields import FieldInfo

    try:
        info = key_field(key)
    except ConfigError:
        return None
    return info if isinstance(info, FieldInfo) else None


def key_kind(key: str) -> str | None:
    """Physical kind of a dotted config key (a key of :data:`jointwear.units.DIMENSIONS`).

    ``None`` for keys without units (plain numbers such as ``contact.exponent``)
    or unknown keys.
    """
    info = _field(key)
    if info is None:
        return None

    def search(objects: Sequence[Any]) -> str | None:
        for item in objects:
            func = getattr(item, "func", None)
            for cell in getattr(func, "__closure__", None) or ():
                if isinstance(cell.cell_contents, str) and cell.cell_contents in DIMENSIONS:
                    return cell.cell_contents
            found = search(typing.get_args(item))
            if found:
                return found
        return None

    return search([*info.metadata, info.annotation])


def key_unit(key: str) -> str:
    """SI unit of a dotted config key as text (``"1/Pa"``, ``"m"``, ``"N"``; ``""`` if none)."""
    kind = key_kind(key)
    unit = DIMENSIONS.get(kind, "") if kind else ""
    return unit.replace("**", "^")


def resolve_key(name: str, config: Config) -> str:
    """Dotted config key of a parameter name (short name or dotted key).

    Parameters
    ----------
    name : str
        A short name of :data:`PARAMETER_ALIASES` or a dotted key of a
        real-valued config entry (``joint.clearance``).
    config : Config
        The configuration the key must exist in.

    Raises
    ------
    ConfigError
        Unknown name (with a did-you-mean suggestion) or not a real number.
    """
    name = name.strip()
    if name in PARAMETER_ALIASES:
        return PARAMETER_ALIASES[name]
    data = config.to_dict()
    numeric = _numeric_keys(data)
    if name in numeric:
        return name
    try:
        config_value(config, name)
    except ConfigError:
        options = [*PARAMETER_ALIASES, *numeric]
        raise ConfigError(f"--fit: unknown parameter {name!r}{suggest(name, options)}") from None
    raise ConfigError(f"--fit: {name} is not a real-valued config entry and cannot be fitted")


def resolve_parameter(
    name: str, config: Config, bounds: tuple[float, float] | None = None
) -> Parameter:
    """A :class:`~jointwear.calibration.Parameter` for a name, with default bounds.

    Parameters
    ----------
    name : str
        Short name or dotted key (see :func:`resolve_key`).
    config : Config
        Base configuration (for the key's current value).
    bounds : tuple of float, optional
        ``(lower, upper)`` [SI]; default :data:`DEFAULT_BOUNDS`, else a tenth to
        ten times the current value.

    Raises
    ------
    ConfigError
        Unknown name, bad bounds, or no default bounds for a zero value.
    """
    key = resolve_key(name, config)
    if bounds is None:
        if key in DEFAULT_BOUNDS:
            bounds = DEFAULT_BOUNDS[key]
        else:
            value = config_value(config, key)
            if not value > 0:
                raise ConfigError(
                    f"--fit: {key} is {value:g}; give bounds, e.g. --fit '{key}=LOWER..UPPER'"
                )
            bounds = (value / 10, value * 10)
    lower, upper = bounds
    if not (math.isfinite(lower) and math.isfinite(upper) and lower < upper):
        raise ConfigError(f"--fit: {key}: bounds must be finite with lower < upper")
    return Parameter(key, float(lower), float(upper))


def parse_fit(text: str, config: Config) -> Parameter:
    """Parse a ``--fit`` option: ``NAME`` or ``NAME=LOWER..UPPER`` (units allowed).

    Examples: ``wear_coefficient``, ``joint.clearance=0.02 mm..0.2 mm``,
    ``wear_coefficient=1e-14..1e-11``.

    Raises
    ------
    ConfigError
        Bad syntax, unknown name, bad bounds.
    """
    name, sep, rest = text.partition("=")
    if not sep:
        return resolve_parameter(name, config)
    key = resolve_key(name, config)
    lower_text, dots, upper_text = rest.partition("..")
    if not dots or not lower_text.strip() or not upper_text.strip():
        raise ConfigError(f"--fit {text!r}: expected NAME or NAME=LOWER..UPPER")
    kind = key_kind(key) or "dimensionless"
    lower = to_si(lower_text.strip(), kind, f"--fit {key} lower bound")
    upper = to_si(upper_text.strip(), kind, f"--fit {key} upper bound")
    return resolve_parameter(key, config, (lower, upper))


# ---------------------------------------------------------------- cases
@dataclass(frozen=True)
class MeasuredCase:
    """A measured bushing and how it was run.

    Parameters
    ----------
    name : str
        Label (the file name).
    x, y : ndarray, shape (M,)
        Measured points of the inner surface [m].
    overrides : dict
        Dotted config keys of this run, applied on top of the base config
        (values SI numbers or strings with units).
    align : "best" or float
        Best-fit rotation, or the offset of the bushing's ``theta = 0`` in the
        measured frame [rad].
    """

    name: str
    x: FloatArray
    y: FloatArray
    overrides: dict[str, Any] = field(default_factory=dict)
    align: str | float = ALIGN_BEST

    @classmethod
    def from_file(
        cls,
        path: str | Path,
        overrides: Mapping[str, Any] | None = None,
        units: str | None = None,
        align: str | float = ALIGN_BEST,
    ) -> MeasuredCase:
        """Read a case from a measurement file (:func:`~jointwear.measurement.io.read_points`)."""
        from jointwear.measurement.io import read_points

        x, y = read_points(path, units)
        return cls(Path(path).name, x, y, dict(overrides or {}), align)


def parse_case(text: str) -> tuple[Path, dict[str, Any]]:
    """Parse a ``--case`` option: ``FILE:KEY=VALUE[,KEY=VALUE...]``.

    The file name ends at the last ``:`` before the first ``=`` (so Windows
    drive letters work); overrides are comma separated ``--set``-style
    ``section.key=VALUE`` pairs (values may carry units; a value cannot
    contain a comma). A bare ``FILE`` has no overrides.

    Examples: ``worn_240.csv:mechanism.crank_speed=240 rpm``,
    ``b.csv:mechanism.crank_speed=240 rpm,simulation.revolutions=5000``.

    Raises
    ------
    ConfigError
        Empty file name or a pair without ``=``.
    """
    equals = text.find("=")
    if equals < 0:
        path, spec = text, ""
    else:
        colon = text.rfind(":", 0, equals)
        if colon <= 0:
            raise ConfigError(f"--case {text!r}: expected FILE:section.key=VALUE[,...]")
        path, spec = text[:colon], text[colon + 1 :]
    if not path.strip():
        raise ConfigError(f"--case {text!r}: no file name")
    overrides: dict[str, Any] = {}
    for pair in filter(str.strip, spec.split(",")):
        try:
            key, value = parse_override(pair)
        except ConfigError:
            raise ConfigError(
                f"--case {text!r}: {pair.strip()!r} is not section.key=VALUE"
            ) from None
        overrides[key] = value
    return Path(path.strip()), overrides


# ---------------------------------------------------------------- profile calibration
@dataclass(frozen=True)
class ProfileCalibration:
    """Parameters fitted to measured profiles.

    Attributes
    ----------
    result : CalibrationResult
        Fitted values [SI], 1σ uncertainties [SI], residuals (fractions of each
        case's measured peak), fitted config, evaluations.
    parameters : list of Parameter
        What was fitted, with bounds [SI].
    initial : dict
        Starting values [SI].
    cases : list of MeasuredCase
        The measured cases.
    comparisons : list of Comparison
        Each case at the fitted values (aligned profiles, errors, metrics).
    passes : int
        Least-squares passes (alignment updates between them).
    evaluations : int
        Residual evaluations of the optimiser in all passes.
    simulations : int
        Simulations run in all (one per case per evaluation, plus alignment
        and the final comparison).
    """

    result: CalibrationResult
    parameters: list[Parameter]
    initial: dict[str, float]
    cases: list[MeasuredCase]
    comparisons: list[Comparison]
    passes: int
    evaluations: int
    simulations: int

    @property
    def values(self) -> dict[str, float]:
        """Fitted values [SI] by dotted key."""
        return self.result.values

    @property
    def uncertainty(self) -> dict[str, float]:
        """1σ uncertainties [SI] by dotted key (NaN if not estimable)."""
        return self.result.uncertainty

    @property
    def rms_residual(self) -> float:
        """RMS of the normalised residuals at the optimum [-] (fraction of the peak)."""
        return self.result.rms_residual

    def summary(self) -> dict[str, Any]:
        """The ``jointwear calibrate --json`` object."""
        return {
            "parameters": {
                p.key: {
                    "value": self.values[p.key],
                    "uncertainty": self.uncertainty[p.key],
                    "unit": key_unit(p.key),
                    "initial": self.initial[p.key],
                    "lower": p.lower,
                    "upper": p.upper,
                    "at_bound": _at_bound(p, self.values[p.key]),
                }
                for p in self.parameters
            },
            "rms_residual": self.rms_residual,
            "residual_unit": "fraction of each case's measured peak",
            "evaluations": self.evaluations,
            "simulations": self.simulations,
            "passes": self.passes,
            "cases": [
                {
                    "name": case.name,
                    "overrides": {k: _plain(v) for k, v in case.overrides.items()},
                    "points": int(case.x.size),
                    "rms_error_m": comparison.rms_error,
                    "peak_wear_depth_simulated_m": comparison.simulated_metrics.peak_depth,
                    "peak_wear_depth_measured_m": comparison.measured_metrics.peak_depth,
                    "peak_error_rel": comparison.peak_error_rel,
                    "alignment_offset_deg": math.degrees(comparison.alignment_offset),
                }
                for case, comparison in zip(self.cases, self.comparisons, strict=True)
            ],
        }


def _plain(value: Any) -> Any:
    return value if isinstance(value, str | int | float | bool) else str(value)


def _at_bound(parameter: Parameter, value: float) -> bool:
    u = parameter.to_unit(value)
    return bool(u < 1e-6 or u > 1 - 1e-6)


def _reworded(exc: JointwearError, message: str) -> JointwearError:
    """The same kind of error with a new message (a DataError if it cannot be built)."""
    try:
        return type(exc)(message)
    except TypeError:
        return DataError(message)


def _describe(values: Mapping[str, float]) -> str:
    return ", ".join(f"{key}={value:.4g}" for key, value in values.items())


class _Measured:
    """The measured profile of a case on a grid, cached by unworn radius and grid."""

    def __init__(self, case: MeasuredCase, fit: str, profile: str) -> None:
        self.case = case
        self.fit = fit
        self.profile = profile
        self._circles: dict[float, CircleFit] = {}

    def circle(self, radius: float) -> CircleFit:
        if radius not in self._circles:
            try:
                self._circles[radius] = fit_circle(self.case.x, self.case.y, radius, self.fit)
            except DataError as exc:
                raise DataError(f"{self.case.name}: {exc}") from None
        return self._circles[radius]

    def profile_at(self, radius: float, nodes: int, offset: float) -> FloatArray:
        method = resolve_profile_method(self.profile, self.case.x.size, nodes)
        return measured_wear_profile(
            self.case.x, self.case.y, self.circle(radius), radius, nodes, offset, method
        )


def _simulate(config: Config) -> FloatArray:
    import warnings

    from jointwear.errors import WearFeedbackWarning, WearThroughError
    from jointwear.simulation import Simulation

    # the trial values of a fit are no run of the user's: what they would warn about
    # (e.g. a trial K_d wearing past the clearance) says nothing about the result
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", WearFeedbackWarning)
        result = Simulation(config).run()
    summary = result.summary()
    if summary["stopped_by"] is not None:
        # a profile cut short by a limit is not the measured run's: these values fail
        raise WearThroughError(
            f"life.{summary['stopped_by']}: reached at revolution {summary['revolutions']} "
            f"of {config.simulation.revolutions}"
        )
    return np.asarray(result.wear_depth, dtype=float)


def _case_config(base: Config, case: MeasuredCase) -> Config:
    try:
        return base.replace(case.overrides)
    except ConfigError as exc:
        raise ConfigError(f"{case.name}: {exc}") from None


def calibrate_profiles(
    config: Config,
    cases: Sequence[MeasuredCase],
    parameters: Sequence[Parameter],
    *,
    fit: str = "robust",
    profile: str = "auto",
    initial: Mapping[str, float] | None = None,
    max_evaluations: int = 200,
) -> ProfileCalibration:
    """Fit config parameters so that simulated wear profiles match measured ones.

    Parameters
    ----------
    config : Config
        Base configuration; each case's overrides are applied on top of it
        (and on top of the values being fitted).
    cases : sequence of MeasuredCase
        Measured bushings with their run overrides.
    parameters : sequence of Parameter
        Keys to fit with bounds [SI] (:func:`resolve_parameter`).
    fit : str
        Circle fit of the measured points: ``"robust"`` (default) or
        ``"least-squares"`` (biased; see :mod:`jointwear.measurement.fit`).
    profile : str
        Points onto the grid: ``"auto"``, ``"interpolate"`` or ``"bin"``.
    initial : mapping, optional
        Starting values [SI]; default the config's (clipped into the bounds).
    max_evaluations : int
        Largest number of optimiser steps per pass.

    Returns
    -------
    ProfileCalibration

    Raises
    ------
    ConfigError
        No cases or parameters, a parameter a case overrides, bad overrides.
    DataError
        A circle fit fails, or a measured profile shows no wear.
    ConvergenceError
        The residual is not finite at the optimum.
    """
    if not cases:
        raise ConfigError("calibrate: give at least one measured profile")
    if not parameters:
        raise ConfigError("calibrate: name at least one parameter to fit (--fit)")
    keys = [p.key for p in parameters]
    if len(set(keys)) != len(keys):
        raise ConfigError("calibrate: a parameter is named twice")
    for case in cases:
        clash = sorted(set(case.overrides) & set(keys))
        if clash:
            raise ConfigError(f"{case.name}: the case sets {clash[0]}, which is being fitted")
    resolve_profile_method(profile, 1, 1)  # check the names early
    if str(fit).replace("_", "-") not in CIRCLE_FITS:
        raise ConfigError(f"fit: unknown circle fit {fit!r}{suggest(str(fit), CIRCLE_FITS)}")
    measured = [_Measured(case, fit, profile) for case in cases]
    start = {
        p.key: float((initial or {}).get(p.key, config_value(config, p.key))) for p in parameters
    }
    start = {p.key: min(max(start[p.key], p.lower), p.upper) for p in parameters}
    # validate every case's config once, with the starting values
    for case in cases:
        _case_config(config.replace(start), case)

    simulations = 0

    def align(values: Mapping[str, float]) -> list[tuple[float, int, float, float]]:
        """Per case: unworn radius, nodes, offset [rad], normalisation [m]."""
        nonlocal simulations
        out = []
        for case, meas in zip(cases, measured, strict=True):
            cfg = _case_config(config.replace(values), case)
            radius, nodes = cfg.bushing_radius, cfg.contact.nodes
            if case.align == ALIGN_BEST:
                simulations += 1
                try:
                    simulated = _simulate(cfg)
                except JointwearError as exc:
                    raise _reworded(
                        exc, f"{case.name}: the simulation fails at {_describe(values)} ({exc})"
                    ) from None
                comparison = compare_measurement(
                    simulated,
                    case.x,
                    case.y,
                    radius,
                    fit=meas.circle(radius),
                    profile=meas.profile,
                )
                offset = comparison.alignment_offset
            else:
                offset = float(case.align)
            peak = float(np.max(meas.profile_at(radius, nodes, offset)))
            noise = meas.circle(radius).rms_residual
            if not peak > max(3 * noise, 1e-6 * radius):
                raise DataError(
                    f"{case.name}: the measured profile shows no wear to fit (peak "
                    f"{peak * 1e6:.3g} µm, noise {noise * 1e6:.3g} µm rms)"
                )
            out.append((radius, nodes, offset, peak))
        return out

    failed: set[tuple[float, ...]] = set()
    values = dict(start)
    passes = 0
    evaluations = 0
    result: CalibrationResult | None = None
    alignment = align(values)
    while True:
        passes += 1
        fixed = list(alignment)
        labels = [
            f"{case.name}:theta={360.0 * j / nodes:g}deg"
            for case, (_, nodes, _, _) in zip(cases, fixed, strict=True)
            for j in range(nodes)
        ]

        def residual(cfg: Config, fixed: list[tuple[float, int, float, float]] = fixed) -> Any:
            nonlocal simulations
            parts = []
            for case, meas, (_, _, offset, peak) in zip(cases, measured, fixed, strict=True):
                case_cfg = _case_config(cfg, case)
                radius, nodes = case_cfg.bushing_radius, case_cfg.contact.nodes
                target = meas.profile_at(radius, nodes, offset)
                simulations += 1
                try:
                    simulated = _simulate(case_cfg)
                except JointwearError:
                    failed.add(tuple(config_value(cfg, key) for key in keys))
                    parts.append(np.full(nodes, _FAILED_RESIDUAL))
                    continue
                parts.append((simulated - target) / peak)
            return np.concatenate(parts)

        result = calibrate(config, parameters, residual, labels, values, max_evaluations)
        evaluations += result.evaluations
        values = dict(result.values)
        if tuple(values[key] for key in keys) in failed:
            raise DataError(
                f"calibrate: the simulation fails at {_describe(values)} (e.g. the bushing "
                "wears through); narrow the bounds"
            )
        alignment = align(values)
        moved = max(
            abs(np.angle(np.exp(1j * (new[2] - old[2])))) / (2 * np.pi / new[1])
            for new, old in zip(alignment, fixed, strict=True)
        )
        if moved <= _REALIGN_TOLERANCE or passes >= _MAX_PASSES:
            break

    comparisons = []
    for case, meas, (radius, _, offset, _) in zip(cases, measured, alignment, strict=True):
        cfg = _case_config(result.config, case)
        simulations += 1
        comparisons.append(
            compare_measurement(
                _simulate(cfg),
                case.x,
                case.y,
                radius,
                fit=meas.circle(radius),
                profile=meas.profile,
                align=offset,
                axial_length=cfg.joint.axial_length,
                density=cfg.materials.bushing.density,
            )
        )
    return ProfileCalibration(
        result=result,
        parameters=list(parameters),
        initial=start,
        cases=list(cases),
        comparisons=comparisons,
        passes=passes,
        evaluations=evaluations,
        simulations=simulations,
    )
