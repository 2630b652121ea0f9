"""Parameter fit: config parameters fitted to observed wear by least squares.

The unknowns are dotted config keys (``joint.axial_length``,
``materials.bushing.wear_coefficient`` ...), each searched inside bounds on a
normalised (log where the bounds allow) scale by ``scipy.optimize.least_squares``.
Residuals are relative (log-ratios for scalar metrics), so quantities of very
different size weigh alike.

:func:`calibrate_metrics` fits scalar metrics (the paper's wear peak, width and
mass: the reproduction protocol calibrates the undisclosed parameters on one table
row, see :mod:`jointwear.paper.protocol`); :mod:`jointwear.measurement` adds
residuals from measured profiles.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import least_squares

from jointwear.config import Config
from jointwear.errors import ConfigError, ConvergenceError

__all__ = ["CalibrationResult", "Parameter", "calibrate", "calibrate_metrics", "config_value"]


@dataclass(frozen=True)
class Parameter:
    """A config key to fit, with bounds in SI units.

    Parameters
    ----------
    key : str
        Dotted config key.
    lower, upper : float
        Bounds [SI unit of the key].
    """

    key: str
    lower: float
    upper: float

    def __post_init__(self) -> None:
        if not (
            math.isfinite(self.lower) and math.isfinite(self.upper) and self.lower < self.upper
        ):
            raise ConfigError(f"{self.key}: calibration bounds must be finite with lower < upper")

    @property
    def logarithmic(self) -> bool:
        return self.lower > 0 and self.upper / self.lower > 10

    def to_unit(self, value: float) -> float:
        if self.logarithmic:
            return math.log(value / self.lower) / math.log(self.upper / self.lower)
        return (value - self.lower) / (self.upper - self.lower)

    def from_unit(self, u: float) -> float:
        if self.logarithmic:
            return self.lower * (self.upper / self.lower) ** u
        return self.lower + u * (self.upper - self.lower)


@dataclass(frozen=True)
class CalibrationResult:
    """Fitted parameters.

    Attributes
    ----------
    values : dict
        Fitted value per key [SI].
    uncertainty : dict
        One-standard-deviation estimate per key from the Jacobian at the
        optimum [SI]; NaN when there are no more residuals than parameters.
    residuals : ndarray
        Residuals at the optimum (relative).
    labels : list of str
        What each residual compares.
    config : Config
        The config with the fitted values applied.
    evaluations : int
        Model evaluations used.
    """

    values: dict[str, float]
    uncertainty: dict[str, float]
    residuals: NDArray[np.float64]
    labels: list[str]
    config: Config
    evaluations: int
    message: str = ""
    extra: dict = field(default_factory=dict)

    def __repr__(self) -> str:
        values = ", ".join(f"{key}={value:.6g}" for key, value in self.values.items())
        return (
            f"<CalibrationResult {values}; RMS residual {self.rms_residual:.3g}, "
            f"{self.evaluations} evaluations>"
        )

    @property
    def rms_residual(self) -> float:
        """Root mean square of the residuals at the optimum [-]."""
        return float(np.sqrt(np.mean(self.residuals**2)))


def calibrate(
    config: Config,
    parameters: Sequence[Parameter],
    residual: Callable[[Config], NDArray[np.float64]],
    labels: Sequence[str],
    initial: Mapping[str, float] | None = None,
    max_evaluations: int = 200,
) -> CalibrationResult:
    """Least-squares fit of config parameters to any residual function.

    Each parameter is searched on ``[0, 1]`` (:meth:`Parameter.to_unit`,
    logarithmic when the bounds span more than a decade) by
    :func:`scipy.optimize.least_squares` (trust region reflective, finite
    difference Jacobian with a step of ``1e-4`` of the unit interval). Values
    are applied with :meth:`Config.replace`, so derived defaults (the NLCP spring
    area, the rod inertia) follow a fitted axial length or rod mass unless the
    config sets them explicitly.

    Parameters
    ----------
    config : Config
        Base configuration.
    parameters : sequence of Parameter
        Keys to fit and their bounds.
    residual : callable
        ``residual(config) -> ndarray`` of relative residuals.
    labels : sequence of str
        Names of the residual entries.
    initial : mapping, optional
        Starting values [SI]; default the config's values (clipped into bounds).
    max_evaluations : int
        Largest number of residual evaluations of the optimiser (the Jacobian's
        finite differences not counted by scipy's limit).
    """
    if not parameters:
        raise ConfigError("calibrate: name at least one parameter to fit")
    start = []
    for p in parameters:
        value = (initial or {}).get(p.key, config_value(config, p.key))
        start.append(min(max(p.to_unit(value), 0.0), 1.0))
    evaluations = 0

    def config_at(u: NDArray[np.float64]) -> Config:
        return config.replace(
            {p.key: p.from_unit(float(x)) for p, x in zip(parameters, u, strict=True)}
        )

    def objective(u: NDArray[np.float64]) -> NDArray[np.float64]:
        nonlocal evaluations
        evaluations += 1
        return np.asarray(residual(config_at(u)), dtype=float)

    solution = least_squares(
        objective,
        np.array(start),
        bounds=(0.0, 1.0),
        diff_step=1e-4,
        x_scale=1.0,
        xtol=1e-10,
        ftol=1e-10,
        gtol=1e-10,
        max_nfev=max_evaluations,
    )
    if not np.all(np.isfinite(solution.fun)):
        raise ConvergenceError("calibrate: the residual is not finite at the optimum")
    values = {p.key: p.from_unit(float(x)) for p, x in zip(parameters, solution.x, strict=True)}
    uncertainty = _uncertainty(parameters, solution)
    return CalibrationResult(
        values=values,
        uncertainty=uncertainty,
        residuals=solution.fun,
        labels=list(labels),
        config=config_at(solution.x),
        evaluations=evaluations,
        message=solution.message,
    )


def calibrate_metrics(
    config: Config,
    targets: Mapping[str, float],
    parameters: Sequence[Parameter],
    initial: Mapping[str, float] | None = None,
) -> CalibrationResult:
    """Fit parameters so that a run's summary metrics match target values.

    Parameters
    ----------
    config : Config
        Base configuration (the case to match).
    targets : mapping
        ``jointwear run --json`` keys to target values, e.g.
        ``{"peak_wear_depth_m": 1.056e-8, "wear_width_deg": 115, "wear_mass_kg": 3.355e-9}``.
    parameters : sequence of Parameter
        Keys to fit and their bounds.
    initial : mapping, optional
        Starting values [SI].
    """
    from jointwear.simulation import Simulation

    names = list(targets)

    def residual(cfg: Config) -> NDArray[np.float64]:
        summary = Simulation(cfg).run().summary()
        return np.array([math.log(summary[n] / targets[n]) for n in names])

    return calibrate(config, parameters, residual, [f"log({n}/target)" for n in names], initial)


def config_value(config: Config, key: str) -> float:
    """The numeric value of a dotted config key, in SI.

    Parameters
    ----------
    config : Config
        The configuration.
    key : str
        Dotted key (``joint.axial_length``).

    Returns
    -------
    float
        The value [SI unit of the key].

    Raises
    ------
    ConfigError
        Not a config key, or not a number.
    """
    node: object = config.to_dict()
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            raise ConfigError(f"{key}: not a config key that can be calibrated")
        node = node[part]
    if not isinstance(node, int | float) or isinstance(node, bool):
        raise ConfigError(f"{key}: not a numeric config value")
    return float(node)


def _uncertainty(parameters: Sequence[Parameter], solution) -> dict[str, float]:
    m, n = solution.jac.shape
    if m <= n:
        return {p.key: math.nan for p in parameters}
    sigma2 = 2 * solution.cost / (m - n)
    try:
        cov = np.linalg.inv(solution.jac.T @ solution.jac) * sigma2
    except np.linalg.LinAlgError:
        return {p.key: math.nan for p in parameters}
    out = {}
    for i, p in enumerate(parameters):
        u, su = solution.x[i], math.sqrt(max(cov[i, i], 0.0))
        # propagate through the unit mapping (local derivative)
        h = 1e-6
        slope = (p.from_unit(min(u + h, 1.0)) - p.from_unit(max(u - h, 0.0))) / (
            min(u + h, 1.0) - max(u - h, 0.0)
        )
        out[p.key] = abs(slope) * su
    return out
