"""Fit config parameters (``K_d``, geometry) to measured wear profiles.

The paper compares its simulation with measured bushings (§3.2); fitting the
wear coefficient ``K_d`` -- and, if the data allow, the joint's undisclosed
geometry -- to such measurements is the natural next step.

Method
------
One or several *cases*: a measured bushing (points of its inner surface) and
the config overrides of its run (speed, revolutions, clearance ...). For given
parameter values ``p`` every case is simulated, and every measured point gets
the residual of :mod:`jointwear.measurement.pointfit`,

.. math::

    r_{ci} = \\frac{|\\mathbf{p}_{ci} - \\mathbf{c}_c| - R_{0c}
        - h^{sim}_c(\\varphi_{ci} - \\alpha_c;\\, p)}{\\sigma_c},

with the bushing centre ``c_c`` and the rotation ``alpha_c`` of each case
fitted to its simulated profile (profiled out: for every ``p`` they take their
best values, so a circle fit's bias towards the scar does not enter), and
``sigma_c`` the case's measurement noise (the RMS residual of the robust
circle fit on the unworn arc, or given). The sum of ``r^2`` over all points is
minimised in two stages:

1. **Global search**: one fitted parameter is scanned on a grid of its bounds
   (log-spaced where they span more than a decade, four values per decade);
   several are sampled with a scrambled Sobol sequence (16 points per
   parameter, rounded up to a power of two). A scan finds the basin of the
   global minimum whatever the starting value; the starting value is one more
   candidate.
2. **Polish**: :func:`scipy.optimize.least_squares` (trust region reflective,
   bounded) from the best candidates (at most three local minima of the scan).
   Its Jacobian is ``dr/dp`` by central differences of the *simulated profile*
   (1 % of the value on a log scale, 0.1 % of the range on a linear one: far
   above the simulation's own tolerances), with the centres and rotations held
   at their optimum and their directions projected out (variable projection,
   Golub & Pereyra 1973), which is the Jacobian of the profiled residual.

Uncertainty: the covariance ``s^2 (J^T J)^-1`` of the profiled Jacobian, with
``s^2`` the residual variance on ``M - P - Q`` degrees of freedom (``M``
points, ``P`` parameters, ``Q`` centre and rotation coordinates); the points'
noise is independent, which node residuals of a binned profile were not. The
reported 95 % interval is Student's on the fitting scale (log for ``K_d``).
Misfit: a case's point residuals averaged per node keep a misfit of the
model's (smooth) profile but only ``sigma sqrt(mean(1/n_j))`` of the noise
(``n_j`` points at node ``j``); when their RMS exceeds that 1.5 times, the case
gets a :class:`~jointwear.errors.FitMisfitWarning`: the model does not explain
that measurement (wrong model, load, speed or revolutions), and the interval,
which assumes it does, is not to be trusted.

The paper's protocol -- scalar metrics (peak, width, mass) of one of its table
rows -- is :func:`jointwear.paper.protocol.calibrate_paper_row`.

References
----------
G. H. Golub, V. Pereyra, "The differentiation of pseudo-inverses and nonlinear
least squares problems whose variables separate", SIAM J. Numer. Anal. 10
(1973) 413-432.
"""

from __future__ import annotations

import math
import typing
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear.config import Config, key_field, parse_override
from jointwear.errors import ConfigError, DataError, FitMisfitWarning, JointwearError
from jointwear.measurement.compare import (
    ALIGN_BEST,
    CIRCLE_FITS,
    Comparison,
    compare_measurement,
    fit_circle,
    resolve_profile_method,
)
from jointwear.measurement.fit import CircleFit
from jointwear.measurement.identifiability import not_identifiable
from jointwear.measurement.pointfit import PointFit, fit_points, interpolation_weights
from jointwear.measurement.profile import align_profiles, measured_wear_profile
from jointwear.registry import suggest
from jointwear.units import DIMENSIONS, to_si
from jointwear.workflows.parameter_fit import CalibrationResult, Parameter, config_value

__all__ = [
    "CONFIDENCE",
    "DEFAULT_BOUNDS",
    "MISFIT_RATIO",
    "PARAMETER_ALIASES",
    "CaseFit",
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

#: Confidence of the reported intervals [-].
CONFIDENCE = 0.95
#: A case warns when its point residuals averaged per node exceed what its noise leaves of
#: them by this factor [-] (:attr:`CaseFit.misfit_ratio`). With a right model the ratio is
#: about 1 (0.85-1.1 on the synthetic tests: the unworn arc's RMS, the noise estimate,
#: includes the scar's shallow flanks), scattering by about 1/sqrt(2 N) for N nodes.
MISFIT_RATIO = 1.5
#: Misfits below this share of a case's measured peak never warn [-]: the model and the
#: interpolation between nodes are not better than that, so a noise-free measurement
#: (a synthetic one) would warn about them.
_MISFIT_FLOOR = 1e-3
#: Values per decade of the global scan of one log-scaled parameter, and its size limits.
_SCAN_PER_DECADE = 4
_SCAN_MIN, _SCAN_MAX = 9, 41
#: Values of the global scan of one linear parameter.
_SCAN_LINEAR = 17
#: Sobol points per parameter of the global sample of several parameters.
_SAMPLE_PER_PARAMETER = 16
#: Local minima of the global stage polished by least squares, and how much worse than the
#: best one (sum of squared residuals) a minimum may be to be polished [-].
_POLISH_STARTS = 3
_CANDIDATE_COST_RATIO = 2.0
#: Finite-difference steps of the Jacobian: a share of the value on a log scale, of the
#: range on a linear one [-]. Far larger than the simulation's tolerances (contact balance,
#: adaptive contour update), far smaller than the scale on which dh/dp changes.
_LOG_STEP = 1e-2
_LINEAR_STEP = 1e-3


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
    """A :class:`~jointwear.workflows.parameter_fit.Parameter` for a name, with default bounds.

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
class CaseFit:
    """One measured case at the fitted parameters.

    Attributes
    ----------
    points : PointFit
        Centre, rotation and point residuals against the simulated profile
        (:func:`~jointwear.measurement.pointfit.fit_points`).
    noise : float
        Measurement noise the residuals are divided by [m].
    noise_source : str
        ``"unworn arc"`` (the robust circle fit's RMS residual) or ``"given"``.
    peak : float
        Largest depth of the measured profile [m].
    nodes : int
        Nodes of the simulation's grid.
    """

    points: PointFit
    noise: float
    noise_source: str
    peak: float
    nodes: int

    @property
    def rms_residual(self) -> float:
        """RMS residual of the points [m]."""
        return self.points.rms_residual

    def _node_means(self) -> tuple[FloatArray, FloatArray]:
        """Mean point residual per node (points at their nearest node) and points per node."""
        nearest = np.rint(self.points.angles / (2 * np.pi / self.nodes)).astype(int) % self.nodes
        count = np.bincount(nearest, minlength=self.nodes).astype(float)
        total = np.bincount(nearest, weights=self.points.residuals, minlength=self.nodes)
        filled = count > 0
        return total[filled] / count[filled], count[filled]

    @property
    def misfit(self) -> float:
        """RMS of the point residuals averaged per node [m].

        Averaging shrinks the noise (by the square root of the points per node) but
        not a misfit of the model's profile, which is smooth in angle.
        """
        means, _ = self._node_means()
        return float(np.sqrt(np.mean(means**2)))

    @property
    def expected_misfit(self) -> float:
        """What the noise alone leaves of :attr:`misfit` [m]: ``noise sqrt(mean(1/n_j))``."""
        _, count = self._node_means()
        return self.noise * float(np.sqrt(np.mean(1.0 / count)))

    @property
    def misfit_ratio(self) -> float:
        """:attr:`misfit` over :attr:`expected_misfit` [-]; about 1 if the model is right."""
        expected = self.expected_misfit
        return self.misfit / expected if expected > 0 else math.inf

    @property
    def explained(self) -> bool:
        """False if the model misses the profile by more than the noise allows."""
        floor = max(self.expected_misfit, _MISFIT_FLOOR * self.peak)
        return self.misfit <= MISFIT_RATIO * floor


@dataclass(frozen=True)
class ProfileCalibration:
    """Parameters fitted to measured profiles.

    Attributes
    ----------
    result : CalibrationResult
        Fitted values [SI], 1σ uncertainties [SI], point residuals (in units of
        each case's noise), fitted config, evaluations.
    parameters : list of Parameter
        What was fitted, with bounds [SI].
    initial : dict
        Starting values [SI].
    cases : list of MeasuredCase
        The measured cases.
    comparisons : list of Comparison
        Each case at the fitted values, seen from its fitted centre and rotation
        (aligned profiles, errors, metrics).
    fits : list of CaseFit
        Each case's centre, rotation, noise and point residuals at the fitted values.
    intervals : dict
        ``(lower, upper)`` confidence interval per key [SI] (NaN if not estimable).
    correlation : ndarray, shape (P, P)
        Correlation of the fitted parameters (on their fitting scale).
    scan : list of tuple
        The global stage: ``(values, cost)`` per trial, ``values`` a dict [SI],
        ``cost`` the sum of squared residuals (``inf`` where the simulation fails).
    starts : int
        Least-squares polishes run from the global stage's best candidates.
    evaluations : int
        Residual evaluations (global stage and polish; the Jacobian's not counted).
    simulations : int
        Simulations run in all (one per case per evaluation, two per case and
        parameter for each Jacobian).
    """

    result: CalibrationResult
    parameters: list[Parameter]
    initial: dict[str, float]
    cases: list[MeasuredCase]
    comparisons: list[Comparison]
    fits: list[CaseFit]
    intervals: dict[str, tuple[float, float]]
    correlation: FloatArray
    scan: list[tuple[dict[str, float], float]]
    starts: int
    evaluations: int
    simulations: int
    not_identifiable: dict[str, str] = field(default_factory=dict)

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
        """RMS of the profile differences at the fitted values [-] (fraction of each peak).

        Simulated minus measured profile on the node grid (points averaged or
        interpolated per node, seen from the fitted centre and rotation), each
        case divided by its measured peak.
        """
        parts = [
            comparison.difference / comparison.measured_metrics.peak_depth
            for comparison in self.comparisons
        ]
        return float(np.sqrt(np.mean(np.concatenate(parts) ** 2)))

    @property
    def warnings(self) -> list[str]:
        """One line per case the fitted model does not explain, and per parameter the
        cases do not determine (:mod:`jointwear.measurement.identifiability`)."""
        return [
            _misfit_message(case, fit)
            for case, fit in zip(self.cases, self.fits, strict=True)
            if not fit.explained
        ] + [
            f"calibrate: {key} is not identifiable from these cases: {reason}"
            for key, reason in self.not_identifiable.items()
        ]

    def summary(self) -> dict[str, Any]:
        """The ``jointwear calibrate --json`` object."""
        n = len(self.parameters)
        return {
            "parameters": {
                p.key: {
                    "value": self.values[p.key],
                    "uncertainty": _finite(self.uncertainty[p.key]),
                    "interval": [_finite(v) for v in self.intervals[p.key]],
                    "confidence": CONFIDENCE,
                    "scale": "log" if p.logarithmic else "linear",
                    "unit": key_unit(p.key),
                    "initial": self.initial[p.key],
                    "lower": p.lower,
                    "upper": p.upper,
                    "at_bound": _at_bound(p, self.values[p.key]),
                }
                for p in self.parameters
            },
            "correlation": [[_finite(float(c)) for c in row] for row in self.correlation]
            if n > 1
            else None,
            "method": {
                "residual": "points: distance from the fitted centre - R0 - simulated "
                "profile, divided by the case's noise",
                "global": "grid" if n == 1 else "sobol",
                "global_trials": len(self.scan),
                "polish": "least_squares",
                "starts": self.starts,
                "uncertainty": "s^2 (J^T J)^-1, centre and rotation profiled out",
                "interval": "student-t on the fitting scale",
            },
            "not_identifiable": dict(self.not_identifiable),
            "rms_residual": self.rms_residual,
            "residual_unit": "fraction of each case's measured peak",
            "evaluations": self.evaluations,
            "simulations": self.simulations,
            "warnings": self.warnings,
            "cases": [
                {
                    "name": case.name,
                    "overrides": {k: _plain(v) for k, v in case.overrides.items()},
                    "points": int(case.x.size),
                    "rms_error_m": comparison.rms_error,
                    "rms_point_residual_m": fit.rms_residual,
                    "noise_m": fit.noise,
                    "noise_source": fit.noise_source,
                    "misfit_m": fit.misfit,
                    "expected_misfit_m": fit.expected_misfit,
                    "misfit_ratio": _finite(fit.misfit_ratio),
                    "center_x_m": fit.points.center_x,
                    "center_y_m": fit.points.center_y,
                    "peak_wear_depth_simulated_m": comparison.simulated_metrics.peak_depth,
                    "peak_wear_depth_measured_m": comparison.measured_metrics.peak_depth,
                    "peak_error_rel": comparison.peak_error_rel,
                    "alignment_offset_deg": math.degrees(comparison.alignment_offset),
                }
                for case, comparison, fit in zip(
                    self.cases, self.comparisons, self.fits, strict=True
                )
            ],
        }


def _finite(value: float) -> float | None:
    return value if math.isfinite(value) else None


def _misfit_message(case: MeasuredCase, fit: CaseFit) -> str:
    return (
        f"{case.name}: the fitted model misses the measured profile by "
        f"{fit.misfit * 1e6:.3g} µm rms (points averaged per node), {fit.misfit_ratio:.3g} "
        f"times what the measurement noise ({fit.noise * 1e6:.3g} µm per point, "
        f"{fit.noise_source}) explains; the model does not explain this measurement (check "
        "the contact model, load, speed and revolutions of this case), and the interval "
        "assumes it does"
    )


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
    """A case's points: circle fit, noise, profile and point fits, cached by radius and grid."""

    def __init__(self, case: MeasuredCase, fit: str, profile: str, noise: float | None) -> None:
        self.case = case
        self.fit = str(fit).replace("_", "-")
        self.profile = profile
        self.given_noise = noise
        self._circles: dict[float, CircleFit] = {}
        self._noise: dict[float, float] = {}
        self._first: dict[tuple[float, int], FloatArray] = {}

    def circle(self, radius: float) -> CircleFit:
        """The circle fit of the points: the starting centre (the centre, least squares)."""
        if radius not in self._circles:
            try:
                self._circles[radius] = fit_circle(self.case.x, self.case.y, radius, self.fit)
            except DataError as exc:
                raise DataError(f"{self.case.name}: {exc}") from None
        return self._circles[radius]

    def noise(self, radius: float) -> tuple[float, str]:
        """Measurement noise [m] and where it comes from."""
        if self.given_noise is not None:
            return self.given_noise, "given"
        if radius not in self._noise:
            circle = self.circle(radius)
            if circle.method != "robust":
                try:
                    circle = fit_circle(self.case.x, self.case.y, radius, "robust")
                except DataError as exc:
                    raise DataError(
                        f"{self.case.name}: no unworn arc to estimate the noise from ({exc}); "
                        "give it (--noise)"
                    ) from None
            # coordinates rounded in the file are a floor of what the points resolve
            self._noise[radius] = max(circle.rms_residual, circle.resolution, 1e-12 * radius)
        return self._noise[radius], "unworn arc"

    def first_profile(self, radius: float, nodes: int) -> FloatArray:
        """The measured profile seen from the circle's centre, offset 0 (for alignment)."""
        key = (radius, nodes)
        if key not in self._first:
            method = resolve_profile_method(self.profile, self.case.x.size, nodes)
            self._first[key] = measured_wear_profile(
                self.case.x, self.case.y, self.circle(radius), radius, nodes, 0.0, method
            )
        return self._first[key]

    def peak(self, radius: float, nodes: int) -> float:
        return float(np.max(self.first_profile(radius, nodes)))

    def fit_points(self, simulated: FloatArray, radius: float) -> PointFit:
        """Centre and rotation of the points against a simulated profile."""
        circle = self.circle(radius)
        if self.case.align == ALIGN_BEST:
            offset, _ = align_profiles(simulated, self.first_profile(radius, simulated.size))
        else:
            offset = float(self.case.align)
        return fit_points(
            self.case.x,
            self.case.y,
            simulated,
            radius,
            circle.center,
            offset,
            fit_center=self.fit == "robust",
            fit_offset=self.case.align == ALIGN_BEST,
        )


def _simulate(config: Config) -> FloatArray:
    from jointwear.errors import ContactModelWarning, WearFeedbackWarning, WearThroughError
    from jointwear.simulation import Simulation

    # the trial values of a fit are no run of the user's: what they would warn about
    # (e.g. a trial K_d wearing past the clearance, or deeper than the models' range)
    # says nothing about the result
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", WearFeedbackWarning)
        warnings.simplefilter("ignore", ContactModelWarning)
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


@dataclass
class _Trial:
    """The cases simulated and fitted at one point ``u`` of the unit cube."""

    u: FloatArray
    values: dict[str, float]
    configs: list[Config]
    profiles: list[FloatArray] = field(default_factory=list)
    fits: list[PointFit] = field(default_factory=list)
    failure: JointwearError | None = None
    failed_case: str = ""

    @property
    def failed(self) -> bool:
        return self.failure is not None


def _global_trials(parameters: Sequence[Parameter], start: FloatArray) -> FloatArray:
    """Points of the unit cube the global stage evaluates (the start included)."""
    if len(parameters) == 1:
        (p,) = parameters
        if p.logarithmic:
            decades = math.log10(p.upper / p.lower)
            count = int(np.clip(round(_SCAN_PER_DECADE * decades) + 1, _SCAN_MIN, _SCAN_MAX))
        else:
            count = _SCAN_LINEAR
        grid = np.linspace(0.0, 1.0, count)[:, None]
    else:
        from scipy.stats import qmc

        exponent = math.ceil(math.log2(_SAMPLE_PER_PARAMETER * len(parameters)))
        grid = qmc.Sobol(len(parameters), scramble=True, seed=0).random_base2(exponent)
    return np.vstack([grid, start[None, :]])


def _candidates(trials: FloatArray, costs: FloatArray, count: int) -> list[int]:
    """Indices of the global stage's best distinct local minima, worth a polish.

    A local minimum whose cost is more than :data:`_CANDIDATE_COST_RATIO` times the best
    one's is not polished: on a flat stretch (a trial ``K_d`` decades too small, whose
    profile is nearly zero everywhere) noise makes spurious minima, far above the real one.
    """
    finite = np.isfinite(costs)
    if not finite.any():
        return []
    limit = _CANDIDATE_COST_RATIO * float(np.min(costs[finite]))
    worth = finite & (costs <= limit)
    if trials.shape[1] == 1:
        grid = np.argsort(trials[:-1, 0])  # the scan proper (the start is the last trial)
        minima = []
        for position, i in enumerate(grid):
            left = costs[grid[position - 1]] if position > 0 else math.inf
            right = costs[grid[position + 1]] if position + 1 < grid.size else math.inf
            if worth[i] and costs[i] <= left and costs[i] <= right:
                minima.append(int(i))
        chosen = sorted(minima, key=lambda i: costs[i])[:count]
        start = trials.shape[0] - 1
        if worth[start] and costs[start] < min((costs[i] for i in chosen), default=math.inf):
            chosen.insert(0, start)
        return chosen[:count]
    chosen: list[int] = []
    for i in np.argsort(costs):
        if worth[i] and all(np.max(np.abs(trials[i] - trials[j])) > 0.1 for j in chosen):
            chosen.append(int(i))
        if len(chosen) == count:
            break
    return chosen


def _steps(parameters: Sequence[Parameter]) -> FloatArray:
    """Finite-difference steps on the unit scale [-]."""
    return np.array(
        [
            _LOG_STEP / math.log(p.upper / p.lower) if p.logarithmic else _LINEAR_STEP
            for p in parameters
        ]
    )


def calibrate_profiles(
    config: Config,
    cases: Sequence[MeasuredCase],
    parameters: Sequence[Parameter],
    *,
    fit: str = "robust",
    profile: str = "auto",
    initial: Mapping[str, float] | None = None,
    noise: float | None = None,
    max_evaluations: int = 200,
) -> ProfileCalibration:
    """Fit config parameters so that simulated wear profiles match measured points.

    See the module docstring for the residual, the global stage, the polish and
    the uncertainty.

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
        Bushing centre: ``"robust"`` (default: started from the robust circle
        fit of the unworn arc, then fitted with each simulated profile) or
        ``"least-squares"`` (the paper's plain circle fit, kept fixed; biased
        towards the scar, see :mod:`jointwear.measurement.fit`).
    profile : str
        Points onto the grid for the reported comparisons: ``"auto"``,
        ``"interpolate"`` or ``"bin"``.
    initial : mapping, optional
        Starting values [SI]; default the config's (clipped into the bounds).
        The global stage makes the result independent of them; they are one
        more candidate.
    noise : float, optional
        Measurement noise (standard deviation of the radial error) of every
        case [m]; default: estimated per case from the unworn arc.
    max_evaluations : int
        Largest number of residual evaluations of each polish.

    Returns
    -------
    ProfileCalibration

    Raises
    ------
    ConfigError
        No cases or parameters, a parameter a case overrides, bad overrides or noise.
    DataError
        A circle fit fails, or a measured profile shows no wear.
    JointwearError
        The simulation fails at every trial value (the start's error, reworded).
    """
    _check_calibration(cases, parameters, fit, profile, noise)
    measured = [_Measured(case, fit, profile, noise) for case in cases]
    start = _starting_values(config, parameters, initial)
    _check_measured_wear(config, start, cases, measured)
    objective = _ProfileObjective(config, cases, measured, parameters)
    points, costs = _global_stage(objective, start)
    best, starts = _polish(objective, points, costs, max_evaluations)
    u_best = np.clip(best.x, 0.0, 1.0)
    final = objective.trial(u_best)
    if final.failure is not None:
        raise _reworded(
            final.failure,
            f"calibrate: the simulation fails at {_describe(final.values)} (e.g. the bushing "
            "wears through); narrow the bounds",
        )
    r = objective.scaled(final)
    spread = _Spread.of(final, r, objective.jacobian(u_best), parameters)
    result = CalibrationResult(
        values=final.values,
        uncertainty=spread.uncertainty,
        residuals=r,
        labels=[f"{case.name}:point {i}" for case in cases for i in range(case.x.size)],
        config=config.replace(final.values),
        evaluations=objective.evaluations,
        message=str(best.message),
    )
    comparisons, fits = _cases_at(measured, final)
    outcome = ProfileCalibration(
        result=result,
        parameters=list(parameters),
        initial=start,
        cases=list(cases),
        comparisons=comparisons,
        fits=fits,
        intervals=spread.intervals,
        correlation=spread.correlation,
        scan=[(objective.values_at(u), float(c)) for u, c in zip(points, costs, strict=True)],
        starts=starts,
        evaluations=objective.evaluations,
        simulations=objective.simulations,
        not_identifiable=spread.not_identifiable,
    )
    for message in outcome.warnings:
        warnings.warn(message, FitMisfitWarning, stacklevel=2)
    return outcome


def _check_calibration(
    cases: Sequence[MeasuredCase],
    parameters: Sequence[Parameter],
    fit: str,
    profile: str,
    noise: float | None,
) -> None:
    """Refuse a calibration without cases or parameters, or with clashing or bad options."""
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
    if noise is not None and not (math.isfinite(noise) and noise > 0):
        raise ConfigError(f"--noise: must be a length > 0, got {noise!r}")
    resolve_profile_method(profile, 1, 1)  # check the names early
    if str(fit).replace("_", "-") not in CIRCLE_FITS:
        raise ConfigError(f"fit: unknown circle fit {fit!r}{suggest(str(fit), CIRCLE_FITS)}")


def _starting_values(
    config: Config, parameters: Sequence[Parameter], initial: Mapping[str, float] | None
) -> dict[str, float]:
    """The given starting values, else the config's, clipped into the bounds [SI]."""
    start = {
        p.key: float((initial or {}).get(p.key, config_value(config, p.key))) for p in parameters
    }
    return {p.key: min(max(start[p.key], p.lower), p.upper) for p in parameters}


def _check_measured_wear(
    config: Config,
    start: Mapping[str, float],
    cases: Sequence[MeasuredCase],
    measured: Sequence[_Measured],
) -> None:
    """Every case's config, measured profile and noise, checked once at the start values.

    Raises
    ------
    DataError
        A measured profile whose peak is within its noise: no wear to fit.
    """
    for case, meas in zip(cases, measured, strict=True):
        cfg = _case_config(config.replace(start), case)
        radius, nodes = cfg.bushing_radius, cfg.contact.nodes
        peak, (sigma, _) = meas.peak(radius, nodes), meas.noise(radius)
        if not peak > max(3 * sigma, 1e-6 * radius):
            raise DataError(
                f"{case.name}: the measured profile shows no wear to fit (peak "
                f"{peak * 1e6:.3g} µm, noise {sigma * 1e6:.3g} µm rms)"
            )


class _ProfileObjective:
    """The point residuals of every case at a point ``u`` of the unit cube of the parameters.

    Simulated profiles and trials are cached by ``u``; ``simulations`` counts the runs,
    ``evaluations`` the residual and cost evaluations (not the Jacobian's).
    """

    def __init__(
        self,
        config: Config,
        cases: Sequence[MeasuredCase],
        measured: Sequence[_Measured],
        parameters: Sequence[Parameter],
    ) -> None:
        self.config = config
        self.cases = cases
        self.measured = measured
        self.parameters = parameters
        self.steps = _steps(parameters)
        self.simulations = 0
        self.evaluations = 0
        self._profiles: dict[tuple[tuple[float, ...], int], FloatArray | JointwearError] = {}
        self._trials: dict[tuple[float, ...], _Trial] = {}

    def values_at(self, u: FloatArray) -> dict[str, float]:
        """Parameter values [SI] at ``u``."""
        return {p.key: p.from_unit(float(v)) for p, v in zip(self.parameters, u, strict=True)}

    def simulated(self, u: FloatArray, index: int) -> FloatArray | JointwearError:
        """A case's simulated profile at ``u`` [m] (or the error it fails with)."""
        key = (tuple(float(v) for v in u), index)
        if key not in self._profiles:
            self.simulations += 1
            cfg = _case_config(self.config.replace(self.values_at(u)), self.cases[index])
            try:
                self._profiles[key] = _simulate(cfg)
            except JointwearError as exc:
                self._profiles[key] = exc
        return self._profiles[key]

    def trial(self, u: FloatArray) -> _Trial:
        """The cases simulated at ``u`` and their points fitted (up to the first failure)."""
        key = tuple(float(v) for v in u)
        if key not in self._trials:
            values = self.values_at(u)
            configs = [_case_config(self.config.replace(values), case) for case in self.cases]
            item = _Trial(np.array(u, dtype=float), values, configs)
            for index, (case, meas, cfg) in enumerate(
                zip(self.cases, self.measured, configs, strict=True)
            ):
                depth = self.simulated(u, index)
                if isinstance(depth, JointwearError):
                    item.failure, item.failed_case = depth, case.name
                    break
                item.profiles.append(depth)
                item.fits.append(meas.fit_points(depth, cfg.bushing_radius))
            self._trials[key] = item
        return self._trials[key]

    def noises(self, item: _Trial) -> list[float]:
        """Each case's measurement noise [m] (its residuals are divided by it)."""
        return [
            meas.noise(cfg.bushing_radius)[0]
            for meas, cfg in zip(self.measured, item.configs, strict=True)
        ]

    def scaled(self, item: _Trial) -> FloatArray:
        """The residual vector of a trial [-] (point residuals over each case's noise)."""
        if item.failed:
            # larger than any residual of a simulation that runs (wear within the wall)
            return np.concatenate(
                [
                    np.full(case.x.size, 10 * cfg.bushing_radius / sigma)
                    for case, cfg, sigma in zip(
                        self.cases, item.configs, self.noises(item), strict=True
                    )
                ]
            )
        return np.concatenate(
            [f.residuals / sigma for f, sigma in zip(item.fits, self.noises(item), strict=True)]
        )

    def residual(self, u: FloatArray) -> FloatArray:
        """The residual vector at ``u`` [-] (an evaluation)."""
        self.evaluations += 1
        return self.scaled(self.trial(u))

    def cost(self, u: FloatArray) -> float:
        """Sum of squared residuals at ``u`` [-], ``inf`` where a simulation fails."""
        self.evaluations += 1
        item = self.trial(u)
        return math.inf if item.failed else float(np.sum(self.scaled(item) ** 2))

    def jacobian(self, u: FloatArray) -> FloatArray:
        """Jacobian of the profiled residual: d(profile)/du, centre and rotation projected out."""
        item = self.trial(u)
        if item.failed:  # no slope where the simulation fails: the cost there is a wall
            return np.zeros((sum(case.x.size for case in self.cases), len(self.parameters)))
        blocks = []
        for index, (fitted, sigma) in enumerate(zip(item.fits, self.noises(item), strict=True)):
            columns = []
            for i, step in enumerate(self.steps):
                slope = self._profile_slope(u, item, index, i, step)
                k, w = interpolation_weights(fitted.angles, slope.size)
                columns.append(-((1 - w) * slope[k] + w * slope[(k + 1) % slope.size]) / sigma)
            block = np.column_stack(columns)
            nuisance = fitted.jacobian / sigma
            if nuisance.shape[1]:
                basis, _ = np.linalg.qr(nuisance)
                block = block - basis @ (basis.T @ block)
            blocks.append(block)
        return np.vstack(blocks)

    def _profile_slope(
        self, u: FloatArray, item: _Trial, index: int, i: int, step: float
    ) -> FloatArray:
        """``d(profile)/du_i`` of case ``index`` [m] by central differences within the cube.

        A side where the simulation fails is replaced by ``u`` itself (one-sided).
        """
        up, down = np.array(u, dtype=float), np.array(u, dtype=float)
        up[i], down[i] = min(u[i] + step, 1.0), max(u[i] - step, 0.0)
        high, low = self.simulated(up, index), self.simulated(down, index)
        if isinstance(high, JointwearError):
            high, up = item.profiles[index], np.array(u, dtype=float)
        if isinstance(low, JointwearError):
            low, down = item.profiles[index], np.array(u, dtype=float)
        span = up[i] - down[i]
        return (high - low) / span if span > 0 else np.zeros_like(high)


def _global_stage(
    objective: _ProfileObjective, start: Mapping[str, float]
) -> tuple[FloatArray, FloatArray]:
    """Stage 1: the cost at the scan (or Sobol sample) of the unit cube and at the start.

    Raises the start's error, reworded, if the simulation fails at every trial.
    """
    start_u = np.array([p.to_unit(start[p.key]) for p in objective.parameters])
    points = _global_trials(objective.parameters, start_u)
    costs = np.array([objective.cost(u) for u in points])
    if not np.any(np.isfinite(costs)):
        failed = objective.trial(start_u)
        raise _reworded(
            failed.failure or DataError("the simulation fails"),
            f"{failed.failed_case}: the simulation fails at {_describe(start)} "
            f"({failed.failure}), and at every value of the global search; narrow the bounds",
        )
    return points, costs


def _polish(
    objective: _ProfileObjective, points: FloatArray, costs: FloatArray, max_evaluations: int
) -> tuple[Any, int]:
    """Stage 2: least squares from the global stage's best candidates; the best and how many."""
    from scipy.optimize import least_squares

    best: Any = None
    starts = 0
    for index in _candidates(points, costs, _POLISH_STARTS):
        starts += 1
        solution = least_squares(
            objective.residual,
            points[index],
            jac=objective.jacobian,
            bounds=(0.0, 1.0),
            method="trf",
            x_scale="jac",
            xtol=1e-10,
            ftol=1e-12,
            gtol=1e-12,
            max_nfev=max_evaluations,
        )
        if best is None or solution.cost < best.cost:
            best = solution
    return best, starts


@dataclass(frozen=True)
class _Spread:
    """Stage 3: 1σ uncertainties and intervals [SI] and correlation, NaN if not estimable."""

    uncertainty: dict[str, float]
    intervals: dict[str, tuple[float, float]]
    correlation: FloatArray
    not_identifiable: dict[str, str] = field(default_factory=dict)

    @classmethod
    def of(
        cls, final: _Trial, r: FloatArray, jac: FloatArray, parameters: Sequence[Parameter]
    ) -> _Spread:
        """From the profiled Jacobian ``jac`` and residuals ``r`` at the fitted trial.

        ``s^2 (J^T J)^-1`` on ``M - P - Q`` degrees of freedom; Student's interval on the
        fitting scale (log or linear).
        """
        from scipy.special import stdtrit

        keys = [p.key for p in parameters]
        nuisance = sum(len(f.free) for f in final.fits)
        dof = r.size - len(parameters) - nuisance
        uncertainty = {key: math.nan for key in keys}
        intervals = {key: (math.nan, math.nan) for key in keys}
        correlation = np.full((len(keys), len(keys)), math.nan)
        covariance = None
        if dof > 0:
            try:
                covariance = np.linalg.inv(jac.T @ jac) * float(r @ r) / dof
            except np.linalg.LinAlgError:
                covariance = None
        scales = {p.key: p.logarithmic for p in parameters}
        if covariance is None or not np.all(np.isfinite(covariance)):
            widths = {key: math.nan for key in keys}
            flagged = not_identifiable(keys, jac, correlation, widths, scales)
            return cls(uncertainty, intervals, correlation, flagged)
        quantile = float(stdtrit(dof, 0.5 + CONFIDENCE / 2))  # Student's t
        sigma_u = np.sqrt(np.maximum(np.diag(covariance), 0.0))
        with np.errstate(invalid="ignore", divide="ignore"):
            correlation = covariance / np.outer(sigma_u, sigma_u)
        for p, s in zip(parameters, sigma_u, strict=True):
            value = final.values[p.key]
            if p.logarithmic:
                spread = s * math.log(p.upper / p.lower)  # of ln(value)
                uncertainty[p.key] = value * spread
                # (a parameter the data do not fix can have a spread beyond any float)
                factor = float(np.exp(min(quantile * spread, 700.0)))
                intervals[p.key] = (value / factor, value * factor)
            else:
                spread = s * (p.upper - p.lower)
                uncertainty[p.key] = spread
                intervals[p.key] = (value - quantile * spread, value + quantile * spread)
        # the half-widths on the fitting scale: of ln(value), or a fraction of the bounds
        widths = {
            p.key: quantile * s * (math.log(p.upper / p.lower) if p.logarithmic else 1.0)
            for p, s in zip(parameters, sigma_u, strict=True)
        }
        flagged = not_identifiable(keys, jac, correlation, widths, scales)
        return cls(uncertainty, intervals, correlation, flagged)


def _cases_at(
    measured: Sequence[_Measured], final: _Trial
) -> tuple[list[Comparison], list[CaseFit]]:
    """Each case at the fitted values, seen from its fitted centre and rotation."""
    fits = []
    comparisons = []
    for meas, cfg, depth, points_fit in zip(
        measured, final.configs, final.profiles, final.fits, strict=True
    ):
        radius = cfg.bushing_radius
        sigma, source = meas.noise(radius)
        circle = meas.circle(radius)
        centre = CircleFit(
            points_fit.center_x,
            points_fit.center_y,
            radius,
            points_fit.rms_residual,
            "profile" if meas.fit == "robust" else circle.method,
            int(meas.case.x.size),
            True,
            None,
            circle.resolution,
        )
        comparison = compare_measurement(
            depth,
            meas.case.x,
            meas.case.y,
            radius,
            fit=centre,
            profile=meas.profile,
            align=points_fit.offset,
            axial_length=cfg.joint.axial_length,
            density=cfg.materials.bushing.density,
        )
        comparisons.append(comparison)
        fits.append(
            CaseFit(points_fit, sigma, source, comparison.measured_metrics.peak_depth, depth.size)
        )
    return comparisons, fits
