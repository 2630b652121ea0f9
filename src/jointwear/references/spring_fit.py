"""Fit Winkler's and NLCP's spring constants to a reference solution.

The paper leaves the calibration of its models to future work. Here the
foundation stiffness of Winkler's model, ``k = E_w / L`` (eq. 4), and the
pressure law of NLCP, ``p = c delta^n`` (eq. 7 with ``c = K / A``), are fitted by
least squares (``scipy.optimize.least_squares``) to a reference (the FE model
of the real bushing by default, or Persson's exact solution) over a load range:

* ``target="pressure"`` (default): the pressure distributions, residual
  ``(p_model - p_ref) / max(p_ref)`` on every node within 100 degrees of the
  load line, for every load;
* ``target="metrics"``: ``log`` ratios of contact half-angle, peak pressure and
  approach, for every load.

Each model is solved by the package's own load balance on the same contour.
NLCP is fitted as ``p = c_ref (delta / delta_ref)^n`` (``delta_ref`` the
reference approach at the middle load), which decorrelates the two constants;
``K = c A`` is then reported for the paper's 1-degree spring area ``A``, with
the ratio to eq. (2)'s ``K = 4/3 E* sqrt(R_p)``. The uncertainty is the usual
least-squares estimate ``sigma^2 (J^T J)^-1`` with ``sigma^2`` from the residual
at the optimum: it measures how well the data pin the constants given the
model's form, not the model-form error itself (the RMS residual does).

Fitted constants map onto config keys: Winkler's ``k`` is a wall thickness
``joint.bushing_thickness = E_w / k`` for the configured foundation modulus;
NLCP's law is ``contact.exponent = n`` with ``contact.spring_area = K_eq2 / c``
and ``contact.nlcp_variant = "mesh-independent"``.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import least_squares

from jointwear.contact import ContactParameters, ContactSolution, PowerLaw, solve, solve_contact
from jointwear.contact import nlcp as nlcp_module
from jointwear.contact import winkler as winkler_module
from jointwear.errors import ConfigError, ConvergenceError, JointwearError
from jointwear.geometry.angles import wrap_angle
from jointwear.geometry.contour import BushingContour, Pin

__all__ = [
    "FITTABLE",
    "LawFit",
    "calibrate_to_reference",
    "fit_nlcp",
    "fit_winkler",
    "reference_solution",
]

FloatArray = NDArray[np.float64]

_WINDOW_DEG = 100.0
#: laws :func:`calibrate_to_reference` can fit
FITTABLE = ("winkler", "nlcp", "nlcp-k")


@dataclass(frozen=True)
class LawFit:
    """A spring law fitted to a reference.

    Attributes
    ----------
    model : str
        ``"winkler"``, ``"nlcp"`` or ``"nlcp-k"`` (exponent fixed).
    values : dict
        Fitted constants (SI; names carry the unit): Winkler
        ``stiffness_pa_per_m``; NLCP ``coefficient_pa_per_m_n`` (``c``),
        ``exponent`` (``n``), ``K_n_per_m_n`` (``K = c A``).
    uncertainty : dict
        One standard deviation of each value (same keys and units).
    equivalent : dict
        The fit expressed as config keys or comparisons (SI).
    rms_residual : float
        RMS of the residuals at the optimum [-].
    reference : str
        Reference model name.
    target : str
        ``"pressure"`` or ``"metrics"``.
    loads_n : ndarray
        Loads of the fit [N].
    evaluations : int
        Model solves used.
    """

    model: str
    values: dict[str, float]
    uncertainty: dict[str, float]
    equivalent: dict[str, float | str]
    rms_residual: float
    reference: str
    target: str
    loads_n: FloatArray
    evaluations: int
    extra: dict = field(default_factory=dict)

    def to_json(self) -> dict:
        """Plain data."""
        return {
            "model": self.model,
            "values": {k: float(v) for k, v in self.values.items()},
            "uncertainty": {k: float(v) for k, v in self.uncertainty.items()},
            "equivalent": {
                k: v if isinstance(v, str) else float(v) for k, v in self.equivalent.items()
            },
            "rms_residual": self.rms_residual,
            "reference": self.reference,
            "target": self.target,
            "loads_n": [float(x) for x in self.loads_n],
        }


def reference_solution(
    parameters: ContactParameters,
    loads: ArrayLike,
    reference: str = "fem",
    nodes: int = 360,
) -> tuple[BushingContour, Pin, ContactSolution]:
    """Reference pressures on the unworn bushing for loads at azimuth 0.

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials.
    loads : array_like
        Loads [N].
    reference : {"fem", "persson"} or any registered model
        The reference model.
    nodes : int
        Contour nodes [-].
    """
    contour = BushingContour.circle(parameters.bushing_radius, nodes, parameters.axial_length)
    pin = Pin(parameters.pin_radius)
    loads = np.asarray(loads, dtype=float).ravel()
    return contour, pin, solve(contour, pin, loads, np.zeros_like(loads), reference, parameters)


def _window(contour: BushingContour) -> NDArray[np.bool_]:
    """The nodes within :data:`_WINDOW_DEG` of the load line (azimuth 0)."""
    return np.abs(np.degrees(wrap_angle(contour.theta))) <= _WINDOW_DEG


def _residuals(
    model: ContactSolution, reference: ContactSolution, window: NDArray[np.bool_], target: str
) -> FloatArray:
    if target == "pressure":
        scale = reference.pressure.max(axis=1, keepdims=True)
        return ((model.pressure - reference.pressure)[:, window] / scale).ravel()
    parts = []
    for solution in (model, reference):
        half = 0.5 * (solution.half_angle_left + solution.half_angle_right)
        parts.append(np.stack([half, solution.pressure.max(axis=1), solution.penetration]))
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.log(parts[0] / parts[1]).ravel()
    return np.where(np.isfinite(out), out, 10.0)


def _covariance(solution) -> FloatArray:
    m, n = solution.jac.shape
    if m <= n:
        return np.full((n, n), np.nan)
    sigma2 = 2.0 * solution.cost / max(m - n, 1)
    try:
        return np.linalg.inv(solution.jac.T @ solution.jac) * sigma2
    except np.linalg.LinAlgError:
        return np.full((n, n), np.nan)


def _check_target(target: str) -> None:
    if target not in ("pressure", "metrics"):
        raise ConfigError(f"calibrate.target: unknown {target!r}; choose 'pressure' or 'metrics'")


def fit_winkler(
    parameters: ContactParameters,
    contour: BushingContour,
    pin: Pin,
    loads: ArrayLike,
    reference: ContactSolution,
    target: str = "pressure",
    reference_name: str = "fem",
) -> LawFit:
    """Fit Winkler's foundation stiffness ``k = E_w / L`` [Pa/m] to a reference.

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials (the starting value is their ``E_w / L``).
    contour : BushingContour
        The contour of the reference solution.
    pin : Pin
        The pin.
    loads : array_like, shape (M,)
        Loads of the reference [N].
    reference : ContactSolution
        Reference pressures for ``loads`` at azimuth 0.
    target : {"pressure", "metrics"}
        What is matched (see the module notes).
    reference_name : str
        Name reported with the fit.
    """
    _check_target(target)
    loads = np.asarray(loads, dtype=float).ravel()
    window = _window(contour)
    modulus = winkler_module.foundation_modulus(
        parameters.bushing_youngs_modulus,
        parameters.bushing_poisson_ratio,
        parameters.foundation_modulus,
    )
    start = modulus / parameters.bushing_thickness
    evaluations = 0

    def objective(x: FloatArray) -> FloatArray:
        nonlocal evaluations
        evaluations += 1
        return _law_residuals(
            lambda: PowerLaw(math.exp(float(x[0])), 1.0, name="winkler", symmetric=True),
            contour,
            pin,
            loads,
            reference,
            window,
            target,
        )

    fit = least_squares(objective, [math.log(start)], x_scale=[1.0], diff_step=1e-6, xtol=1e-12)
    _converged(fit, "winkler")
    k = math.exp(float(fit.x[0]))
    cov = _covariance(fit)
    sigma_k = k * math.sqrt(max(cov[0, 0], 0.0)) if np.isfinite(cov[0, 0]) else math.nan
    constrained = winkler_module.foundation_modulus(
        parameters.bushing_youngs_modulus, parameters.bushing_poisson_ratio, "constrained"
    )
    return LawFit(
        model="winkler",
        values={"stiffness_pa_per_m": k},
        uncertainty={"stiffness_pa_per_m": sigma_k},
        equivalent={
            "joint.bushing_thickness": modulus / k,
            "contact.foundation_modulus": parameters.foundation_modulus,
            "foundation_modulus_at_thickness_pa": k * parameters.bushing_thickness,
            "ratio_to_youngs_over_thickness": k
            / (parameters.bushing_youngs_modulus / parameters.bushing_thickness),
            "ratio_to_constrained_over_thickness": k / (constrained / parameters.bushing_thickness),
        },
        rms_residual=float(np.sqrt(np.mean(fit.fun**2))),
        reference=reference_name,
        target=target,
        loads_n=loads,
        evaluations=evaluations,
    )


def fit_nlcp(
    parameters: ContactParameters,
    contour: BushingContour,
    pin: Pin,
    loads: ArrayLike,
    reference: ContactSolution,
    target: str = "pressure",
    reference_name: str = "fem",
    fix_exponent: bool = False,
) -> LawFit:
    """Fit NLCP's pressure law ``p = c delta^n`` (``c = K / A``) to a reference.

    The law is integrated over the nodes' own areas (the mesh-independent form
    of eq. 7), which at the paper's 1-degree spacing is the paper's form.
    With ``fix_exponent`` only ``K`` is fitted (``n = parameters.exponent``) and
    the result is compared with eq. (2)'s ``K``.

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials (``spring_area`` is the ``A`` of ``K = c A``;
        the exponent is the starting value).
    contour : BushingContour
        The contour of the reference solution.
    pin : Pin
        The pin.
    loads : array_like, shape (M,)
        Loads of the reference [N].
    reference : ContactSolution
        Reference pressures for ``loads`` at azimuth 0.
    target : {"pressure", "metrics"}
        What is matched.
    reference_name : str
        Name reported with the fit.
    fix_exponent : bool
        Keep ``n`` at ``parameters.exponent`` and fit ``K`` only.
    """
    _check_target(target)
    loads = np.asarray(loads, dtype=float).ravel()
    window = _window(contour)
    delta_ref, p_ref = _reference_scale(loads, reference)
    fixed = float(parameters.exponent)
    evaluations = 0

    def objective(x: FloatArray) -> FloatArray:
        nonlocal evaluations
        evaluations += 1
        exponent = fixed if fix_exponent else float(x[1])
        return _law_residuals(
            lambda: _scaled_power_law(float(x[0]), exponent, delta_ref),
            contour,
            pin,
            loads,
            reference,
            window,
            target,
        )

    log_p = math.log(p_ref)
    if fix_exponent:
        start = np.array([log_p])
        bounds = ([log_p - 12.0], [log_p + 12.0])
    else:
        start = np.array([log_p, fixed])
        bounds = ([log_p - 12.0, 0.3], [log_p + 12.0, 4.0])
    fit = least_squares(objective, start, bounds=bounds, diff_step=1e-6, xtol=1e-12)
    _converged(fit, "nlcp")
    log_c_ref = float(fit.x[0])
    n = fixed if fix_exponent else float(fit.x[1])
    c = math.exp(log_c_ref) / delta_ref**n
    k_fit = c * float(parameters.spring_area)
    sigma_log_c, sigma_n = _nlcp_spreads(_covariance(fit), delta_ref, fix_exponent)
    return LawFit(
        model="nlcp-k" if fix_exponent else "nlcp",
        values={"coefficient_pa_per_m_n": c, "exponent": n, "K_n_per_m_n": k_fit},
        uncertainty={
            "coefficient_pa_per_m_n": c * sigma_log_c,
            "exponent": sigma_n,
            "K_n_per_m_n": k_fit * sigma_log_c,
        },
        equivalent=_nlcp_equivalent(parameters, c, n, math.exp(log_c_ref), delta_ref, fix_exponent),
        rms_residual=float(np.sqrt(np.mean(fit.fun**2))),
        reference=reference_name,
        target=target,
        loads_n=loads,
        evaluations=evaluations,
    )


def _reference_scale(loads: FloatArray, reference: ContactSolution) -> tuple[float, float]:
    """Approach [m] and peak pressure [Pa] of the reference at the middle load.

    NLCP is fitted as ``p = c_ref (delta / delta_ref)^n``: scaled by the reference's own
    approach, the two constants hardly correlate.
    """
    middle = int(np.argsort(loads)[loads.size // 2])
    delta_ref = float(reference.penetration[middle])
    if not delta_ref > 0:
        raise ConvergenceError("calibrate: the reference has no approach to scale NLCP with")
    return delta_ref, float(reference.pressure[middle].max())


def _scaled_power_law(log_c_ref: float, exponent: float, delta_ref: float) -> PowerLaw:
    """``p = c_ref (delta / delta_ref)^n`` with ``c_ref = exp(log_c_ref)`` [Pa]."""
    coefficient = math.exp(log_c_ref) / delta_ref**exponent
    return PowerLaw(coefficient, exponent, name="nlcp")


def _law_residuals(
    law: Callable[[], PowerLaw],
    contour: BushingContour,
    pin: Pin,
    loads: FloatArray,
    reference: ContactSolution,
    window: NDArray[np.bool_],
    target: str,
) -> FloatArray:
    """Residuals of the law ``law()`` against the reference [-], 10 each where it fails.

    The law's own balance (:func:`~jointwear.contact.solve_contact`) on the reference's
    contour, for the reference's loads at azimuth 0.
    """
    try:
        solution = solve_contact(contour, pin, loads, np.zeros_like(loads), law())
        return _residuals(solution, reference, window, target)
    except JointwearError:
        return np.full(_residual_size(loads, window, target), 10.0)


def _nlcp_spreads(
    covariance: FloatArray, delta_ref: float, fix_exponent: bool
) -> tuple[float, float]:
    """Standard deviations of ``ln c`` and ``n`` [-] from those of ``(ln c_ref, n)``.

    ``ln c = ln c_ref - n ln delta_ref``, so
    ``var(ln c) = var(ln c_ref) + ln(delta_ref)^2 var(n) - 2 ln(delta_ref) cov``.
    """
    if fix_exponent:
        var_log_c, var_n = covariance[0, 0], 0.0
    else:
        log_d = math.log(delta_ref)
        var_log_c = covariance[0, 0] + log_d**2 * covariance[1, 1] - 2.0 * log_d * covariance[0, 1]
        var_n = covariance[1, 1]
    sigma_log_c = math.sqrt(max(var_log_c, 0.0)) if np.isfinite(var_log_c) else math.nan
    sigma_n = math.sqrt(max(var_n, 0.0)) if np.isfinite(var_n) else math.nan
    return sigma_log_c, sigma_n


def _nlcp_equivalent(
    parameters: ContactParameters,
    c: float,
    n: float,
    c_ref: float,
    delta_ref: float,
    fix_exponent: bool,
) -> dict[str, float | str]:
    """A fitted ``p = c delta^n`` as config keys, and ``K = c A`` against eq. (2)'s ``K``."""
    area = float(parameters.spring_area)
    k_eq2 = float(
        nlcp_module.stiffness(
            parameters.pin_radius,
            parameters.pin_youngs_modulus,
            parameters.pin_poisson_ratio,
            parameters.bushing_youngs_modulus,
            parameters.bushing_poisson_ratio,
        )
    )
    equivalent: dict[str, float | str] = {
        "contact.exponent": n,
        "contact.spring_area": k_eq2 / c,
        "contact.nlcp_variant": "mesh-independent",
        "spring_area_m2": area,
        "pressure_at_reference_approach_pa": c_ref,
        "reference_approach_m": delta_ref,
    }
    if fix_exponent and n == 1.5:
        equivalent["K_eq2_n_per_m_1.5"] = k_eq2
        equivalent["ratio_K_to_eq2"] = c * area / k_eq2
    return equivalent


def _residual_size(loads: FloatArray, window: NDArray[np.bool_], target: str) -> int:
    return loads.size * (int(window.sum()) if target == "pressure" else 3)


def _converged(fit, name: str) -> None:
    if not np.all(np.isfinite(fit.x)) or fit.status <= 0:
        raise ConvergenceError(f"calibrate: the {name} fit did not converge ({fit.message})")


def calibrate_to_reference(
    parameters: ContactParameters,
    loads: ArrayLike,
    reference: str = "fem",
    models: Sequence[str] = FITTABLE,
    target: str = "pressure",
    nodes: int = 360,
) -> dict[str, LawFit]:
    """Fit Winkler's stiffness and/or NLCP's ``K``, ``n`` to a reference over loads.

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials of the joint.
    loads : array_like
        Loads [N] (e.g. 50-400 N).
    reference : str
        ``"fem"`` (default) or ``"persson"``.
    models : sequence of {"winkler", "nlcp", "nlcp-k"}
        Laws to fit (``nlcp-k``: NLCP with the configured exponent, ``K`` only).
    target : {"pressure", "metrics"}
        Match the pressure distributions or the half-angle, peak and approach.
    nodes : int
        Contour nodes [-].

    Returns
    -------
    dict
        ``{model: LawFit}``.
    """
    unknown = [m for m in models if m not in FITTABLE]
    if unknown:
        raise ConfigError(f"calibrate: can fit {', '.join(FITTABLE)}, not {unknown}")
    loads = np.asarray(loads, dtype=float).ravel()
    if loads.size == 0 or np.any(loads <= 0):
        raise ConfigError("calibrate: need loads > 0")
    contour, pin, ref = reference_solution(parameters, loads, reference, nodes)
    fits: dict[str, LawFit] = {}
    for name in models:
        if name == "winkler":
            fits[name] = fit_winkler(parameters, contour, pin, loads, ref, target, reference)
        else:
            fits[name] = fit_nlcp(
                parameters, contour, pin, loads, ref, target, reference, name == "nlcp-k"
            )
    return fits
