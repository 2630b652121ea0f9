"""The pin's orbit over a load cycle: Booker's mobility method with asperity contact.

Under a load that changes in size and direction the pin's centre moves: the film
carries the load by its wedge (rotation) *and* its squeeze (approach) action. Booker's
mobility method (:mod:`jointwear.lubrication.mobility`) gives the centre's velocity for
a load at every eccentricity; integrated over the cycle, the orbit. Where the film
is thin, the asperities (Greenwood--Tripp, :mod:`jointwear.lubrication.asperity`)
carry part of the load and the film only the rest:

.. math::

    \\mathbf F_{film} = -\\big(\\mathbf W + F_a(\\varepsilon)\\,\\mathbf e_r\\big),
    \\qquad
    \\frac{\\dot{\\mathbf e}}{c} = k\\,(M_\\varepsilon\\mathbf e_r + M_\\phi\\mathbf e_t)
        + \\frac{\\omega_{pin}+\\omega_{bushing}}{2}\\,\\varepsilon\\,\\mathbf e_t,
    \\qquad k = \\frac{|\\mathbf W + F_a\\mathbf e_r|\\,(c/R)^2}{\\mu L D},

with ``F_a <= 0`` the radial asperity force and ``M`` the mobility vector of the film
model at the direction of the film's load. Cavitation is the half-Sommerfeld (Guembel)
condition of the film models, or Reynolds' (``"finite-reynolds"``,
:mod:`jointwear.lubrication.reynolds`). The load, the pin's and the bushing's speeds are those
of the cycle, in the frame of the bushing (the film sees only ``omega_pin +
omega_bushing - 2 dphi/dt``, the same in every frame).

The cycle is periodic, and so is the orbit it settles on: the eccentricity ODE is
integrated by the compiled kernel (:mod:`jointwear.lubrication._orbit_kernel`, numba,
Dormand--Prince 5(4); :func:`compiled_kernel`) or, without numba, with
:func:`scipy.integrate.solve_ivp` (LSODA) and the right-hand side in Python, over whole
cycles until the start of one cycle and its end agree within a tolerance (a fixed
point of the cycle map; where plain repetition converges slowly, the fixed point is
found with :func:`scipy.optimize.root`, started with the secant Jacobian of the repeated
cycles, :func:`secant_jacobian`). The eccentricity is integrated in the
stretched coordinate ``e / (1 - eps)`` (:func:`stretched`), in which the wall lies at
infinity: the pin stays inside its clearance and the gap keeps a relative accuracy.

Through a reversal of the sliding speed the wedge vanishes, but the squeeze film
still holds the pin off the wall for a time of order ``mu L D (R/c)^2 / W``: the
quasi-static solution (no squeeze) would put it on the wall.

A pin that the film alone must hold, its asperities too weak, may creep onto the wall
instead; where the film there resists motion in every direction without bound (the
short bearing's), the pin rolls with the mean surface speed and every start closes the
cycle. Such an orbit is posed on the pin's resting angle along the wall, not on a fixed
point of the cycle map (:func:`wall_orbit`). Sommerfeld's film near the wall (long and
finite bearing, :func:`jointwear.lubrication.mobility.to_wall`) lets an oblique load slide
the pin along the wall instead, and the pin finds an orbit off it.

Sources: [1]_, [2]_, [3]_.

References
----------
.. [1] J. F. Booker, "Dynamically loaded journal bearings: mobility method of
   solution", ASME J. Basic Eng. 87 (1965) 537-546.
.. [2] J. A. Greenwood and J. H. Tripp, "The contact of two nominally flat rough
   surfaces", Proc. Instn Mech. Engrs 185 (1970) 625-633.
.. [3] P. Flores, J. Ambrosio, J. C. P. Claro, H. M. Lankarani and C. S. Koshy,
   "A study on dynamics of mechanical systems including joints with clearance and
   lubrication", Mech. Mach. Theory 41 (2006) 247-261.
"""

from __future__ import annotations

import math
import os
from bisect import bisect_right
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import solve_ivp
from scipy.interpolate import CubicSpline, RectBivariateSpline, bisplev
from scipy.optimize import approx_fprime, brentq, root

from jointwear.errors import ConvergenceError
from jointwear.lubrication.asperity import (
    DEFAULT_ETA_BETA_SIGMA,
    DEFAULT_SIGMA_OVER_BETA,
    EXACT_CUTOFF,
    FIT_OMEGA,
    journal_asperity_force,
)
from jointwear.lubrication.film import long_shape_near_wall, short_shape_scalar
from jointwear.lubrication.mobility import (
    DIRECTION_NODES,
    FINITE_CAVITATION,
    LEAVING_LOG_GAP_MIN,
    LEAVING_START,
    LEAVING_WALL,
    LOG_GAP_MAX,
    LOG_GAP_NODES,
    TABLE_EDGE,
    WALL_DIRECTION_NODES,
    WALL_LOG_GAP_MAX,
    WALL_LOG_GAP_NODES,
    dimensionless_force,
    from_leaving,
    from_wall,
    leaving_direction,
    leaving_log_gap,
    leaving_states,
    leaving_the_wall,
    leaving_values,
    to_wall,
    wall_direction,
    wall_motion,
    wall_table,
)
from jointwear.mechanism.impact.film import long_bearing

__all__ = ["Orbit", "OrbitSolver", "periodic_orbit"]

FloatArray = NDArray[np.float64]

#: the largest eccentricity ratio the orbit reaches (h_min = 1e-12 c)
LARGEST_ECCENTRICITY = 1.0 - 1e-12
#: nodes of the tabulated asperity force over the gap h_min / sigma
ASPERITY_NODES = 401
#: tolerances of the integration over a cycle (eccentricity ratio)
INTEGRATION_RTOL = 1e-7
INTEGRATION_ATOL = 1e-10
#: the relative tolerance of the cycles that find the orbit; the cycle that proves it
#: periodic is integrated to ``INTEGRATION_RTOL``
SEARCH_RTOL = 1e-5
#: cycles repeated while each shrinks the mismatch at least this much
PLAIN_CYCLES = 8
FAST_CONTRACTION = 0.2
#: cycle integrations allowed to the root finder per round, and its rounds
ROOT_EVALUATIONS = 40
ROOT_ROUNDS = 3
#: the root finder's forward differences step ``sqrt(JACOBIAN_STEP)`` times the state
#: (MINPACK's ``epsfcn``): well above the integration's error, so that the cycle
#: map's Jacobian is not round-off of the tolerance ``INTEGRATION_RTOL``
JACOBIAN_STEP = 1e-6
#: the two steps of the plain cycles give the secant Jacobian unless the matrix of
#: them is conditioned worse than this (they point nearly the same way)
SECANT_CONDITION = 100.0
#: the root finder stops at a start whose cycle closes within this share of the
#: tolerance: its further steps move the start by the integration's noise
SETTLED = 0.05
#: a mismatch of the film force's direction this small is a root [rad]
ROUND_OFF = 1e-12
#: the periodicity tolerance scales with the smallest gap, but not below this many
#: roughnesses (the asperity pressure varies on the scale of sigma)
GAP_FLOOR = 1.0
#: a search that carries the pin closer to the wall than this many roughnesses has put
#: it on the wall (:func:`wall_orbit`): the film's share of the load is nil there
WALL_FILM_PARAMETER = 0.05
#: the gap of a pin on the wall, over the clearance [-]
WALL_GAP = 1e-9
#: the first steps along the wall that bracket the pin's resting angle [rad]
WALL_STEP = 0.05
#: on the wall a cycle keeps most of a displacement along it: it shrinks by less than
#: this share (a film that holds the pin steers it back much more)
WALL_CONTRACTION = 0.5
#: the compiled kernel (:mod:`jointwear.lubrication._orbit_kernel`), imported on first use
_KERNEL: Any = None


def compiled_kernel() -> Any:
    """The compiled orbit kernel, imported on first use (None without numba).

    ``JOINTWEAR_NO_NUMBA=1`` switches it off: the orbit is then integrated with
    :func:`scipy.integrate.solve_ivp` and the Python right-hand side.
    """
    global _KERNEL
    if os.environ.get("JOINTWEAR_NO_NUMBA", "") not in ("", "0"):
        return None
    if _KERNEL is None:
        try:
            from jointwear.compile_time import watch_compiles

            watch_compiles()  # (before the kernel compiles: its time is counted)
            from jointwear.lubrication import _orbit_kernel as module
        except ImportError:
            module = False
        _KERNEL = module
    return _KERNEL or None


@dataclass(frozen=True)
class Orbit:
    """The periodic orbit of a pin over a load cycle, at the cycle's steps.

    Attributes
    ----------
    eccentricity_x, eccentricity_y : ndarray
        Eccentricity ratio components ``e / c`` in the frame of the load's components [-].
    eccentricity_ratio : ndarray
        ``eps = |e| / c`` [-].
    asperity_force : ndarray
        Radial asperity force on the pin, ``<= 0`` (towards the centre) [N].
    cycles : int
        Cycles integrated until the orbit repeated.
    periodicity_error : float
        ``|e(T) - e(0)| / c`` of the last cycle [-].
    """

    eccentricity_x: FloatArray
    eccentricity_y: FloatArray
    eccentricity_ratio: FloatArray
    asperity_force: FloatArray
    cycles: int
    periodicity_error: float


def scalar_spline(
    breaks: FloatArray, coefficients: FloatArray
) -> Callable[[float], NDArray[np.float64]]:
    """A cubic spline evaluated at one point without scipy's call overhead.

    Horner's rule on the spline's coefficients (``c[power, interval, ...]`` of a
    :class:`scipy.interpolate.CubicSpline` with ``breaks``), the interval found with
    :func:`bisect.bisect_right`; outside the breakpoints the end polynomials extend, as
    :class:`scipy.interpolate.CubicSpline` does.
    """
    last = breaks.size - 2

    def value(x: float) -> NDArray[np.float64]:
        k = min(max(bisect_right(breaks, x) - 1, 0), last)
        dx = x - breaks[k]
        c = coefficients[:, k]
        return ((c[0] * dx + c[1]) * dx + c[2]) * dx + c[3]

    return value


def short_shape(eccentricity_ratio: ArrayLike, direction: ArrayLike, ratio: float) -> FloatArray:
    """``G(eps, beta; L/D)`` of the short bearing in closed form, shape ``(2, ...)`` [-].

    :func:`jointwear.lubrication.film.short_bearing_force` at ``R = c = 1``,
    ``mu = 1/6`` and unit motion ``m = 1`` in the direction ``beta``, written for few
    states at a time (the film starts at ``theta_1 = beta``).

    Parameters
    ----------
    eccentricity_ratio : array_like
        ``eps`` [-].
    direction : array_like
        ``beta`` [rad].
    ratio : float
        ``L / D`` [-].
    """
    eps = np.asarray(eccentricity_ratio, float)
    beta = np.asarray(direction, float)
    one_minus = 1.0 - eps * eps
    b = eps / (1.0 + np.sqrt(one_minus))
    sin_b, cos_b = np.sin(beta), np.cos(beta)
    g0 = beta - 2.0 * np.arctan(b * sin_b / (1.0 + b * cos_b))
    g1 = beta + np.pi + 2.0 * np.arctan(b * sin_b / (1.0 - b * cos_b))
    s0, s1 = np.sin(g0), np.sin(g1)
    c0, c1 = np.cos(g0), np.cos(g1)
    d_sin2 = np.sin(2.0 * g1) - np.sin(2.0 * g0)
    sin_sin = (0.5 * (g1 - g0) - 0.25 * d_sin2) / one_minus**1.5
    cos_cos = ((0.5 + eps * eps) * (g1 - g0) + 0.25 * d_sin2 - 2.0 * eps * (s1 - s0)) / (
        one_minus**2.5
    )
    sin_cos = (0.5 * (s1 * s1 - s0 * s0) + eps * (c1 - c0)) / one_minus**2
    scale = 2.0 * ratio**3 / 3.0
    return np.stack(
        [scale * (cos_b * sin_cos - sin_b * cos_cos), scale * (cos_b * sin_sin - sin_b * sin_cos)]
    )


@cache
def shape_table(model: str, ratio: float) -> RectBivariateSpline:
    """Spline of ``(1 - eps^2)^2.5 G`` of a film model over ``(s, beta)``, ``eps = 1 - 10^-s``.

    The long and the finite bearing's force factor, tabulated once per ``L/D`` on the
    grid of :func:`jointwear.lubrication.mobility.force_table` up to its largest
    eccentricity (0.995; beyond, the long bearing in closed form,
    :func:`long_shape_scalar`, and the finite one from :func:`wall_shape_table`); a bicubic spline
    (:class:`scipy.interpolate.RectBivariateSpline`) evaluates it in microseconds.
    Returns one spline per component, stacked along the first axis of the values.

    Parameters
    ----------
    model : str
        ``"long"`` or ``"finite"``.
    ratio : float
        ``L / D`` [-].
    """
    log_gap = np.linspace(0.0, LOG_GAP_MAX, LOG_GAP_NODES)
    pad = 3
    step = 2.0 * np.pi / DIRECTION_NODES
    directions = -np.pi + step * np.arange(-pad, DIRECTION_NODES + pad)
    eps = 1.0 - 10.0**-log_gap
    values = dimensionless_force(model, eps[:, None], directions[None, :], np.array(ratio))
    scaled = values * (1.0 - eps[:, None] ** 2) ** 2.5
    return (
        RectBivariateSpline(log_gap, directions, scaled[0]),
        RectBivariateSpline(log_gap, directions, scaled[1]),
    )


@cache
def wall_shape_table(model: str, ratio: float) -> RectBivariateSpline:
    """Spline of the wall's scaled values ``V`` of a film model over ``(s, psi)`` [-].

    Beyond :func:`shape_table` (``eps`` from 0.995 to ``1 - 1e-5``, held beyond): the
    values ``V`` and the inner direction ``psi`` of
    :func:`jointwear.lubrication.mobility.to_wall`, in which the film close to the wall
    is bounded and smooth; the long bearing's from its closed form
    (:func:`long_shape_scalar`), the finite one's from
    :func:`jointwear.lubrication.mobility.wall_table` at its nodes. One spline per
    component, as :func:`shape_table`.

    Parameters
    ----------
    model : str
        ``"long"``, ``"finite"`` or ``"finite-reynolds"``.
    ratio : float
        ``L / D`` [-].
    """
    log_gap = np.linspace(LOG_GAP_MAX, WALL_LOG_GAP_MAX, WALL_LOG_GAP_NODES)
    pad = 3
    step = 2.0 * np.pi / WALL_DIRECTION_NODES
    inner = -np.pi + step * np.arange(-pad, WALL_DIRECTION_NODES + pad)
    if model in FINITE_CAVITATION:
        table = wall_table(ratio, FINITE_CAVITATION[model])
        nodes = np.stack(np.broadcast_arrays(log_gap[:, None], wrap_to_pi(inner)[None, :]), -1)
        scaled = np.moveaxis(table(nodes), -1, 0)
    else:
        eps = 1.0 - 10.0 ** -log_gap[:, None]
        direction, size = wall_motion(eps, inner[None, :])
        shape = np.vectorize(long_shape_scalar)(eps, direction, ratio)
        scaled = to_wall(np.stack(shape), eps, size)
    return (
        RectBivariateSpline(log_gap, inner, scaled[0]),
        RectBivariateSpline(log_gap, inner, scaled[1]),
    )


@cache
def leaving_shape_table(model: str, ratio: float) -> RectBivariateSpline:
    """Spline of the finite bearing's leaving table over ``(s, u)`` [-].

    Where the pin leaves the wall beyond ``eps = 0.9``
    (:data:`~jointwear.lubrication.mobility.LEAVING_WALL`,
    :data:`~jointwear.lubrication.mobility.LEAVING_START`): ``W, T``
    (:func:`jointwear.lubrication.mobility.to_leaving`) of
    :func:`jointwear.lubrication.mobility.leaving_values` at its nodes. One spline per
    value, as :func:`shape_table`.

    Parameters
    ----------
    model : str
        ``"finite"`` or ``"finite-reynolds"``.
    ratio : float
        ``L / D`` [-].
    """
    log_gap, leaving, values = leaving_values(ratio, FINITE_CAVITATION[model])
    return (
        RectBivariateSpline(log_gap, leaving, values[..., 0]),
        RectBivariateSpline(log_gap, leaving, values[..., 1]),
    )


@cache
def kernel_tables(model: str, ratio: float) -> tuple[FloatArray, ...]:
    """The compiled kernel's ``tables`` of a film model at one ``L/D``, once per process.

    Knots and coefficients of :func:`shape_table` and of :func:`wall_shape_table`
    (``tx, ty, radial, tangential`` each), and the finite bearing's
    :func:`leaving_shape_table` (``tx, ty, W, angle``); placeholders where the model has
    none (the short bearing in closed form).

    Parameters
    ----------
    model : str
        ``"short"``, ``"long"``, ``"finite"`` or ``"finite-reynolds"``.
    ratio : float
        ``L / D`` [-].
    """
    unused = np.zeros(8)
    if model == "short":
        return (unused,) * 12
    radial, tangential = shape_table(model, ratio)
    tables = (*radial.tck, tangential.tck[2])
    radial, tangential = wall_shape_table(model, ratio)
    tables += (*radial.tck, tangential.tck[2])
    if model in FINITE_CAVITATION:  # the leaving table, with its own s knots
        scaled, angle = leaving_shape_table(model, ratio)
        tables += (*scaled.tck[:3], angle.tck[2])
    else:
        tables += (unused,) * 4
    return tuple(np.ascontiguousarray(a, dtype=float) for a in tables)


def wrap_to_pi(angle: ArrayLike) -> FloatArray:
    """``angle`` wrapped to ``[-pi, pi)`` [rad]."""
    return np.remainder(np.asarray(angle, float) + np.pi, 2.0 * np.pi) - np.pi


def long_shape_scalar(eps: float, beta: float, ratio: float) -> tuple[float, float]:
    """``G(eps, beta; L/D)`` of the long bearing in closed form, for one state [-].

    :func:`jointwear.lubrication.film.long_shape_near_wall` with
    :func:`jointwear.mechanism.impact.film.long_bearing` (the scalar form of
    :func:`jointwear.lubrication.film.long_bearing_force` that the compiled kernel runs
    too).

    Parameters
    ----------
    eps : float
        Eccentricity ratio [-].
    beta : float
        Direction of the motion [rad].
    ratio : float
        ``L / D`` [-].
    """
    return long_shape_near_wall(eps, beta, ratio, long_bearing)


def wall_shape_scalar(model: str, ratio: float) -> Callable[[float, float], tuple[float, float]]:
    """``G(eps, beta)`` beyond ``eps = 0.995`` for one state, from :func:`wall_shape_table` [-].

    The operations of the compiled kernel's ``shape_along`` for the wall's table; where
    the pin leaves the wall (:data:`~jointwear.lubrication.mobility.LEAVING_WALL`) the
    long bearing in closed form (the finite one's leaving table:
    :func:`leaving_shape_scalar`).
    """
    knots = [(*spline.tck, *spline.degrees) for spline in wall_shape_table(model, ratio)]
    long = model == "long"

    def shape(eps: float, beta: float) -> tuple[float, float]:
        log_gap = min(max(-math.log10(max(1.0 - eps, 1e-300)), LOG_GAP_MAX), WALL_LOG_GAP_MAX)
        one_minus = 1.0 - eps * eps
        root = math.sqrt(one_minus)
        wedge, squeeze = root * math.cos(beta), math.sin(beta)
        inner = math.atan2(squeeze, wedge)
        if long and -math.pi + LEAVING_WALL < inner < -LEAVING_WALL:
            return long_shape_scalar(eps, beta, ratio)
        size = math.hypot(wedge, squeeze)
        radial, tangential = (float(bisplev(log_gap, inner, tck)) for tck in knots)
        return size * radial / (one_minus * root), size * tangential / one_minus

    return shape


def leaving_shape_scalar(
    model: str, ratio: float
) -> Callable[[float, float], tuple[float, float] | None]:
    """``G(eps, beta)`` of :func:`leaving_shape_table` for one state, None off its region [-].

    The finite bearing's where the pin leaves the wall beyond ``eps = 0.9`` (the
    operations of the compiled kernel's ``_leaving_shape``); None everywhere for the
    long bearing.
    """
    leaving = (
        [(*spline.tck, *spline.degrees) for spline in leaving_shape_table(model, ratio)]
        if model in FINITE_CAVITATION
        else None
    )

    def shape(eps: float, beta: float) -> tuple[float, float] | None:
        if leaving is None or not eps > LEAVING_START:
            return None
        root = math.sqrt(1.0 - eps * eps)
        squeeze = math.sin(beta)
        inner = math.atan2(squeeze, root * math.cos(beta))
        if not -math.pi + LEAVING_WALL < inner < -LEAVING_WALL:
            return None
        log_gap = -math.log10(max(1.0 - eps, 1e-300))
        log_gap = min(max(log_gap, LEAVING_LOG_GAP_MIN), WALL_LOG_GAP_MAX)
        motion = math.asinh(math.cos(beta) / squeeze) / math.asinh(1.0 / (3.0 * root))
        scaled, angle = (float(bisplev(log_gap, motion, tck)) for tck in leaving)
        size = math.exp(scaled) / (squeeze * squeeze)
        return size * math.cos(angle), -size * squeeze * math.sin(angle)

    return shape


def table_shape_scalar(model: str, ratio: float) -> Callable[[float, float], tuple[float, float]]:
    """:func:`film_shape` of a tabulated model for one state (:func:`scipy.interpolate.bisplev`)."""
    splines = shape_table(model, ratio)
    knots = [(*spline.tck, *spline.degrees) for spline in splines]
    near_wall = wall_shape_scalar(model, ratio)
    leaving = leaving_shape_scalar(model, ratio)

    def shape(eps: float, beta: float) -> tuple[float, float]:
        left = leaving(eps, beta)
        if left is not None:
            return left
        if eps > TABLE_EDGE:
            return near_wall(eps, beta)
        log_gap = min(max(-math.log10(max(1.0 - eps, 1e-300)), 0.0), LOG_GAP_MAX)
        wrapped = math.remainder(beta, 2.0 * math.pi)
        scale = (1.0 - eps * eps) ** 2.5
        radial, tangential = (float(bisplev(log_gap, wrapped, tck)) / scale for tck in knots)
        return radial, tangential

    return shape


def film_shape(model: str, ratio: float) -> Callable[[ArrayLike, ArrayLike], FloatArray]:
    """``G(eps, beta)`` of a film model at one ``L/D``, fast for few states [-].

    The short bearing in closed form (:func:`short_shape`), the long and finite ones
    from :func:`shape_table`.

    Parameters
    ----------
    model : str
        ``"short"``, ``"long"`` or ``"finite"``.
    ratio : float
        ``L / D`` [-].
    """
    if model == "short":
        return lambda eps, beta: short_shape(eps, beta, ratio)
    radial, tangential = shape_table(model, ratio)

    def tabulated(eps: ArrayLike, beta: ArrayLike) -> FloatArray:
        eps_, beta_ = np.broadcast_arrays(np.asarray(eps, float), np.asarray(beta, float))
        log_gap = np.clip(-np.log10(np.maximum(1.0 - eps_, 1e-300)), 0.0, LOG_GAP_MAX)
        wrapped = np.remainder(beta_ + np.pi, 2.0 * np.pi) - np.pi
        scale = (1.0 - eps_ * eps_) ** 2.5
        out = np.stack(
            [radial.ev(log_gap, wrapped) / scale, tangential.ev(log_gap, wrapped) / scale]
        )
        near_wall = eps_ > TABLE_EDGE
        if np.any(near_wall):
            out[:, near_wall] = wall_shape(model, ratio, eps_[near_wall], beta_[near_wall])
        if model in FINITE_CAVITATION:
            out = leaving_shape(model, ratio, eps_, beta_, out)
        return out

    return tabulated


def wall_shape(model: str, ratio: float, eps: FloatArray, beta: FloatArray) -> FloatArray:
    """``G(eps, beta)`` beyond ``eps = 0.995``, shape ``(2, n)`` [-].

    From :func:`wall_shape_table` (the scaling of
    :func:`jointwear.lubrication.mobility.to_wall`); where the pin leaves the wall
    (:data:`~jointwear.lubrication.mobility.LEAVING_WALL`) the long bearing in closed
    form (the finite one's leaving table: :func:`leaving_shape`).
    """
    wall_radial, wall_tangential = wall_shape_table(model, ratio)
    inner, size = wall_direction(eps, beta)
    log_gap = np.clip(-np.log10(np.maximum(1.0 - eps, 1e-300)), LOG_GAP_MAX, WALL_LOG_GAP_MAX)
    values = np.stack([wall_radial.ev(log_gap, inner), wall_tangential.ev(log_gap, inner)])
    out = from_wall(values, eps, size)
    leaving = leaving_the_wall(inner)
    if model == "long":
        for k in np.flatnonzero(leaving):
            out[:, k] = long_shape_scalar(float(eps[k]), float(beta[k]), ratio)
    return out


def leaving_shape(
    model: str, ratio: float, eps: FloatArray, beta: FloatArray, out: FloatArray
) -> FloatArray:
    """``out`` with the finite bearing's :func:`leaving_shape_table` where the pin leaves
    the wall beyond ``eps = 0.9``, shape ``(2, ...)`` [-] (:func:`leaving_shape_scalar`).
    """
    leaving = leaving_states(eps, beta)
    if np.any(leaving):
        scaled, angle = leaving_shape_table(model, ratio)
        at = (leaving_log_gap(eps[leaving]), leaving_direction(eps[leaving], beta[leaving]))
        out[:, leaving] = from_leaving(np.stack([scaled.ev(*at), angle.ev(*at)]), beta[leaving])
    return out


class OrbitSolver:
    """The centre's velocity of a pin in its film and on its asperities.

    Parameters
    ----------
    radius : float
        Pin radius ``R`` [m].
    length : float
        Bushing length ``L`` [m].
    clearance : float
        Radial clearance ``c`` [m].
    viscosity : float
        Dynamic viscosity ``mu`` [Pa s].
    roughness : float
        Composite roughness ``sigma`` [m].
    composite_modulus : float
        ``E*`` of pin and bushing [Pa].
    model : str
        Film model: ``"short"``, ``"long"``, ``"finite"`` or ``"finite-reynolds"``.
    eta_beta_sigma, sigma_over_beta : float
        Greenwood--Tripp asperity parameters [-].
    exact : bool
        Exact ``F_{5/2}`` instead of the usual fit.
    """

    def __init__(
        self,
        radius: float,
        length: float,
        clearance: float,
        viscosity: float,
        roughness: float,
        composite_modulus: float,
        model: str = "short",
        eta_beta_sigma: float = DEFAULT_ETA_BETA_SIGMA,
        sigma_over_beta: float = DEFAULT_SIGMA_OVER_BETA,
        exact: bool = False,
    ) -> None:
        self.model = model
        self.clearance = clearance
        self.ratio = length / (2.0 * radius)
        self.shape = film_shape(model, self.ratio)
        self.scalar_shape: Callable[[float, float], tuple[float, float]] = (
            (lambda eps, beta: short_shape_scalar(eps, beta, self.ratio))
            if model == "short"
            else table_shape_scalar(model, self.ratio)
        )
        #: the direction of motion found last: the next search starts there
        self.last_direction: float | None = None
        self.mobility_scale = (clearance / radius) ** 2 / (viscosity * length * 2.0 * radius)
        self.directions = np.linspace(-np.pi, np.pi, DIRECTION_NODES + 1)
        # the asperity force over the gap h_min / sigma, tabulated once: it is zero
        # beyond the fit's (or the exact integral's) cut-off
        cutoff = EXACT_CUTOFF if exact else FIT_OMEGA
        self.gaps = np.linspace(0.0, cutoff, ASPERITY_NODES)
        eps = 1.0 - self.gaps * roughness / clearance
        forces = journal_asperity_force(
            radius,
            length,
            clearance,
            eps,
            roughness,
            composite_modulus,
            eta_beta_sigma,
            sigma_over_beta,
            exact,
        )
        # a cubic spline: a stiff integrator needs a smooth force (linear pieces stall it)
        self.asperity_spline = CubicSpline(self.gaps, forces)
        self.asperity_at = scalar_spline(self.asperity_spline.x, self.asperity_spline.c)
        self.cutoff = cutoff
        self.roughness = roughness
        #: the compiled kernel's last direction of motion and the target direction of
        #: the film's force it was found for (NaN: none yet) [rad]
        self.memory = np.array([math.nan, math.nan])
        #: the asperity spline's breaks and coefficients for the compiled kernel
        self.kernel_asperity: tuple[FloatArray, FloatArray] | None = None

    def kernel_arguments(self) -> tuple[Any, ...]:
        """``(joint, asperity, memory, tables, nodes)`` of the compiled kernel's velocity.

        ``tables``: knots and coefficients of :func:`shape_table` and of
        :func:`wall_shape_table` (``tx, ty, radial, tangential`` each), and the
        finite bearing's :func:`leaving_shape_table` (``tx, ty, W, angle``).
        """
        codes = {"short": 0.0, "long": 3.0, "finite": 4.0, "finite-reynolds": 4.0}
        joint = (
            self.clearance,
            self.roughness,
            float(self.cutoff),
            self.mobility_scale,
            self.ratio,
            codes[self.model],
            float(LOG_GAP_MAX),
        )
        if self.kernel_asperity is None:
            spline = self.asperity_spline
            self.kernel_asperity = (
                np.ascontiguousarray(spline.x),
                np.ascontiguousarray(spline.c[:, :, None]),
            )
        tables = kernel_tables(self.model, self.ratio)
        return joint, self.kernel_asperity, self.memory, tables, DIRECTION_NODES

    def steady_shape(self) -> Callable[[float, float], tuple[float, float]]:
        """:attr:`scalar_shape`, by the compiled kernel where it runs [-].

        The same force factor to round-off (``tests/lubrication/test_orbit_kernel.py``),
        some ten times faster for the tabulated models: for the few dozen states of a
        steady solution such as the orbit's first guess.
        """
        kernel = compiled_kernel()
        if kernel is None or self.model == "short":
            return self.scalar_shape
        joint, _, _, tables, _ = self.kernel_arguments()
        model, ratio, log_gap_max = joint[-2], joint[-3], joint[-1]

        def shape(eps: float, beta: float) -> tuple[float, float]:
            return kernel.shape(eps, beta, model, ratio, log_gap_max, *tables)

        return shape

    def asperity_force(self, eccentricity_ratio: ArrayLike) -> FloatArray:
        """Radial asperity force at ``eps`` (tabulated, linear between nodes) [N]."""
        gap = (1.0 - np.asarray(eccentricity_ratio, float)) * self.clearance / self.roughness
        return np.where(
            gap < self.cutoff, self.asperity_spline(np.clip(gap, 0.0, self.cutoff)), 0.0
        )

    def direction_of_motion(self, eps: float, target: float) -> float:
        """``beta`` whose film force points at ``target`` [rad] (module text).

        The mismatch ``angle(G(eps, beta)) - target`` rises through zero once per turn
        of ``beta``. Its root is bracketed next to the last one found (the orbit moves
        little between calls), or else by a scan over
        :data:`~jointwear.lubrication.mobility.DIRECTION_NODES` directions, and refined
        with :func:`scipy.optimize.brentq`.
        """

        def mismatch(direction: float) -> float:
            shape = self.scalar_shape(eps, direction)
            return math.remainder(math.atan2(shape[1], shape[0]) - target, 2.0 * math.pi)

        found = None
        searches = (
            lambda: self.local_bracket(mismatch),
            lambda: self.scanned_bracket(eps, target),
        )
        for search in searches:
            bracket = search()
            if bracket is None:
                continue
            low, high = bracket
            below, above = mismatch(low), mismatch(high)
            # a root on a node: the scan and the scalar form differ by round-off
            if min(abs(below), abs(above)) <= ROUND_OFF:
                found = low if abs(below) <= abs(above) else high
            elif (below < 0.0 < above) and above - below < math.pi:
                found = brentq(mismatch, low, high, xtol=1e-13, rtol=1e-15)
            if found is not None:
                break
        if found is None:
            raise ConvergenceError(f"mobility: no film force direction at eps = {eps:.12g}")
        self.last_direction = found
        return found

    def local_bracket(self, mismatch: Callable[[float], float]) -> tuple[float, float] | None:
        """A bracket ``(low, high)`` of the rising root next to the last root, or None."""
        centre = self.last_direction
        if centre is None:
            return None
        width = 0.05
        low, high = centre - width, centre + width
        below, above = mismatch(low), mismatch(high)
        while width < 1.0:
            if below <= 0.0 < above and above - below < math.pi:
                return low, high
            width *= 3.0
            if below > 0.0:
                low = centre - width
                below = mismatch(low)
            else:
                high = centre + width
                above = mismatch(high)
        return None

    def scanned_bracket(self, eps: float, target: float) -> tuple[float, float]:
        """A bracket of the rising root from a scan over all directions [rad]."""
        shape = self.shape(eps, self.directions)
        scan = np.remainder(np.arctan2(shape[1], shape[0]) - target + np.pi, 2.0 * np.pi) - np.pi
        rising = (scan[:-1] <= 0.0) & (scan[1:] > 0.0) & (np.diff(scan) < np.pi)
        cell = int(np.argmax(rising))
        return float(self.directions[cell]), float(self.directions[cell + 1])

    def velocity(
        self, state: FloatArray, load_x: float, load_y: float, mean_speed: float
    ) -> FloatArray:
        """``de/dt / c`` of the pin's centre at ``state = e / c`` [1/s] (module text).

        Parameters
        ----------
        state : ndarray, shape (2,)
            Eccentricity ratio components ``e / c`` [-].
        load_x, load_y : float
            Load on the pin (the force the mechanism applies to it) [N].
        mean_speed : float
            ``(omega_pin + omega_bushing) / 2`` [rad/s].
        """
        x, y = float(state[0]), float(state[1])
        eps, phi = math.hypot(x, y), math.atan2(y, x)
        eps = min(max(eps, 1e-6), LARGEST_ECCENTRICITY)
        cos_phi, sin_phi = math.cos(phi), math.sin(phi)
        gap = (1.0 - eps) * self.clearance / self.roughness
        asperity = float(self.asperity_at(gap)) if gap < self.cutoff else 0.0
        film_x, film_y = load_x + asperity * cos_phi, load_y + asperity * sin_phi
        carried = math.hypot(film_x, film_y)
        radial = tangential = 0.0
        if carried > 0.0:
            target = math.atan2(film_y, film_x) - phi + math.pi
            beta = self.direction_of_motion(eps, target)
            shape = self.scalar_shape(eps, beta)
            size = self.ratio / (3.0 * math.hypot(shape[0], shape[1]))
            rate = carried * self.mobility_scale * size
            radial, tangential = rate * math.sin(beta), -rate * math.cos(beta)
        tangential += mean_speed * eps
        return np.array(
            [
                radial * cos_phi - tangential * sin_phi,
                radial * sin_phi + tangential * cos_phi,
            ]
        )


def stretched(state: ArrayLike) -> FloatArray:
    """``q = e / (1 - eps)``: the clearance circle stretched over the plane [-].

    The orbit is integrated in ``q``: the wall (``eps = 1``) is at infinity, out of the
    integrator's reach, and its relative tolerance holds the gap ``1 - eps`` to a
    relative accuracy however thin it is.

    Parameters
    ----------
    state : array_like, shape (2, ...)
        ``e / c`` [-].
    """
    state = np.asarray(state, float)
    return state / (1.0 - np.hypot(state[0], state[1]))


def unstretched(stretched_state: ArrayLike) -> FloatArray:
    """``e / c = q / (1 + |q|)``, the inverse of :func:`stretched` [-]."""
    q = np.asarray(stretched_state, float)
    return q / (1.0 + np.hypot(q[0], q[1]))


class Settled(Exception):
    """A start of the root finder whose cycle closes within ``SETTLED`` of the tolerance.

    Parameters
    ----------
    start : ndarray, shape (2,)
        That start in the stretched coordinate [-].
    """

    def __init__(self, start: FloatArray) -> None:
        super().__init__("the cycle closes")
        self.start = np.array(start, float)


class PinOnWall(Exception):
    """The orbit's root finder put the pin closer to the wall than ``CycleMap.wall_gap``.

    Parameters
    ----------
    start : ndarray, shape (2,)
        That start in the stretched coordinate [-].
    """

    def __init__(self, start: FloatArray) -> None:
        super().__init__("the pin reached the wall")
        self.start = start


class CycleMap:
    """One cycle of the orbit, integrated in the stretched coordinate (:func:`stretched`).

    Calling it with ``q(t_0)`` integrates the cycle with LSODA and returns ``q`` at the
    samples and at the cycle's end, shape ``(2, M + 1)``; the last call's start and path
    are kept (``start``, ``path``).

    Parameters
    ----------
    solver : OrbitSolver
        The joint, its film and its asperities.
    time : array_like, shape (M,)
        Times of the samples [s].
    period : float
        The cycle's duration [s].
    load_x, load_y : array_like, shape (M,)
        Load on the pin at ``time`` [N].
    mean_speed : array_like, shape (M,)
        ``(omega_pin + omega_bushing) / 2`` at ``time`` [rad/s].
    compiled : bool
        Integrate with the compiled kernel where numba is installed (else
        :func:`scipy.integrate.solve_ivp`, LSODA, with the Python right-hand side).
    """

    def __init__(
        self,
        solver: OrbitSolver,
        time: ArrayLike,
        period: float,
        load_x: ArrayLike,
        load_y: ArrayLike,
        mean_speed: ArrayLike,
        compiled: bool = True,
    ) -> None:
        times = np.asarray(time, float)
        self.ends = np.append(times, times[0] + period)
        samples = np.empty((3, self.ends.size))
        samples[0, :-1], samples[1, :-1], samples[2, :-1] = load_x, load_y, mean_speed
        samples[:, -1] = samples[:, 0]
        self.solver = solver
        self.kernel = compiled_kernel() if compiled else None
        # a periodic cubic spline: the integrator sees no kink at every sample (the
        # compiled kernel's coefficients are scipy's, without its checks of the input)
        if self.kernel is not None and self.ends.size > 3:
            coefficients = self.kernel.periodic_spline(self.ends, samples)
        else:
            spline = CubicSpline(self.ends, samples, axis=1, bc_type="periodic")
            coefficients = np.ascontiguousarray(spline.c)
        self.inputs_at = scalar_spline(self.ends, coefficients)
        self.inputs = (self.ends, coefficients)
        self.arguments = solver.kernel_arguments() if self.kernel is not None else ()
        #: right-hand side evaluations of the last cycle (compiled path)
        self.evaluations = 0
        #: cycles integrated (a call from the last start again is not integrated again)
        self.integrations = 0
        self.start = np.zeros(2)
        self.path = np.zeros((2, self.ends.size))
        #: the relative tolerance of the integration, and that of the last cycle
        self.rtol = INTEGRATION_RTOL
        self.path_rtol = math.nan
        #: a root finder's start closer to the wall than this (``1 - eps``) raises
        #: :class:`PinOnWall` (:func:`fixed_point`)
        self.wall_gap = 0.0

    def right_hand_side(self, t: float, stretched_state: FloatArray) -> FloatArray:
        """``dq/dt = v / (1 - eps) + eps (e_r . v) e_r / (1 - eps)^2`` [1/s]."""
        load_x, load_y, speed = self.inputs_at(t)
        state = unstretched(stretched_state)
        velocity = self.solver.velocity(state, float(load_x), float(load_y), float(speed))
        gap = 1.0 - math.hypot(state[0], state[1])
        radial = (state @ velocity) / gap**2
        return velocity / gap + radial * state

    def __call__(self, initial: FloatArray) -> FloatArray:
        if self.path_rtol == self.rtol and np.array_equal(initial, self.start):
            return self.path
        self.integrations += 1
        self.path_rtol = self.rtol
        if self.kernel is not None:
            return self.compiled_cycle(initial)
        solution = solve_ivp(
            self.right_hand_side,
            (self.ends[0], self.ends[-1]),
            initial,
            method="LSODA",
            rtol=self.rtol,
            atol=INTEGRATION_ATOL,
            t_eval=self.ends,
        )
        if not solution.success:
            raise ConvergenceError(f"orbit: the integration failed ({solution.message})")
        self.start, self.path = np.array(initial, float), solution.y
        return solution.y

    def compiled_cycle(self, initial: FloatArray) -> FloatArray:
        """The cycle integrated by the compiled kernel (Dormand--Prince 5(4))."""
        kernel = self.kernel
        path = np.empty((2, self.ends.size))
        start = np.array(initial, float)
        status, self.evaluations = kernel.cycle(
            start, self.ends, self.rtol, INTEGRATION_ATOL, self.inputs, *self.arguments, path
        )
        if status != kernel.DONE or not np.all(np.isfinite(path)):
            raise ConvergenceError(
                f"orbit: the integration failed (compiled kernel, status {status})"
            )
        self.start, self.path = start, path
        return path


def residual(cycle: CycleMap, initial: FloatArray) -> FloatArray:
    """``q(T) - q(0)`` of the cycle from ``initial``, stretched coordinate [-].

    Raises
    ------
    PinOnWall
        Where the start's gap ``1 - eps = 1 / (1 + |q|)`` is below ``cycle.wall_gap``.
    """
    if 1.0 / (1.0 + float(np.hypot(initial[0], initial[1]))) < cycle.wall_gap:
        raise PinOnWall(np.array(initial, float))
    return cycle(initial)[:, -1] - initial


def secant_jacobian(starts: list[FloatArray], ends: list[FloatArray]) -> FloatArray | None:
    """The cycle map's residual Jacobian from the last three plain cycles, or None [-].

    Plain repetition ``q_{k+1} = P(q_k)`` gives the residual ``r(q) = P(q) - q`` at
    three starts for nothing; its two differences give the secant (Broyden) estimate

    .. math:: J\\,[\\Delta q_1\\;\\Delta q_2] = [\\Delta r_1\\;\\Delta r_2],

    solved with :func:`numpy.linalg.solve`. None where fewer than three cycles were
    repeated, or where the two steps point nearly the same way (the repetition
    settles along one direction: the other column would be noise).

    Parameters
    ----------
    starts, ends : list of ndarray, shape (2,)
        Starts and ends of the plain cycles, stretched coordinate [-].
    """
    if len(starts) < 3:
        return None
    steps = np.column_stack([starts[-2] - starts[-3], starts[-1] - starts[-2]])
    residuals = [end - start for start, end in zip(starts[-3:], ends[-3:], strict=True)]
    changes = np.column_stack([residuals[1] - residuals[0], residuals[2] - residuals[1]])
    if np.linalg.cond(steps / np.hypot(steps[0], steps[1])) > SECANT_CONDITION:
        return None
    return np.linalg.solve(steps.T, changes.T).T


def closing_cycle(
    cycle: CycleMap, start: FloatArray, mismatch: Callable[[FloatArray], tuple[float, float]]
) -> FloatArray | None:
    """The cycle from ``start`` at the proof's tolerance, where it closes [-].

    A search whose next cycle will close would integrate it and then the proof's cycle
    from the same start (:func:`searched`): the proof's cycle alone, integrated to
    ``INTEGRATION_RTOL``, is returned where it closes within the tolerance (the
    proof's test). None where the search's tolerance is already the proof's or where
    the cycle does not close; the search then goes on from ``start`` as before, at its
    own tolerance.

    Parameters
    ----------
    cycle : CycleMap
        The cycle map.
    start : ndarray, shape (2,)
        The next cycle's start, stretched coordinate [-].
    mismatch : callable
        ``path -> (|e(T) - e(0)| / c, allowed)`` [-].
    """
    searching = cycle.rtol
    if searching == INTEGRATION_RTOL:
        return None
    cycle.rtol = INTEGRATION_RTOL
    path = cycle(start)
    error, allowed = mismatch(path)
    if error <= allowed:
        return path
    cycle.rtol = searching
    return None


def fixed_point(
    cycle: CycleMap,
    path: FloatArray,
    mismatch: Callable[[FloatArray], tuple[float, float]],
    tolerance: float,
) -> FloatArray:
    """The path of a cycle that ends where it starts, from the cycle ``path`` [-].

    Plain repetition while it contracts fast (a stiff film forgets its start
    quickly), then :func:`scipy.optimize.root` on the cycle map from the last
    repeated start. Its Jacobian there is :func:`secant_jacobian`'s, from the cycles
    repeated (two cycles of forward differences saved); where that is None, or where
    the root finder asks again elsewhere, forward differences
    (:func:`scipy.optimize.approx_fprime`, MINPACK's step). It stops at the first start
    whose cycle closes within ``SETTLED`` of the tolerance (:class:`Settled`): its
    further steps would move the start by the integration's error only. Where plain
    repetition contracts so fast that its next cycle will close, that cycle is
    integrated at the proof's tolerance (:func:`closing_cycle`) and ends the search
    where it closes.
    Returns the path of the last cycle integrated, periodic or not (the caller checks
    ``mismatch``).

    Parameters
    ----------
    cycle : CycleMap
        The cycle map.
    path : ndarray, shape (2, M + 1)
        A cycle's path in the stretched coordinate [-].
    mismatch : callable
        ``path -> (|e(T) - e(0)| / c, allowed)`` [-].
    tolerance : float
        The orbit's tolerance (:func:`periodic_orbit`) [-].
    """
    cycles, previous = 1, math.inf
    starts, ends = [path[:, 0]], [path[:, -1]]
    while cycles < PLAIN_CYCLES:
        error, allowed = mismatch(path)
        if error <= allowed or error > FAST_CONTRACTION * previous:
            break
        # contracting so fast that the next cycle will close within SETTLED of the
        # tolerance (the last mismatch times the last contraction; none measured after
        # the first cycle): that cycle at the proof's tolerance
        if cycles > 1 and error * error / previous <= SETTLED * allowed:
            proved = closing_cycle(cycle, path[:, -1], mismatch)
            if proved is not None:
                return proved
        previous = error
        path = cycle(path[:, -1])
        starts.append(path[:, 0])
        ends.append(path[:, -1])
        cycles += 1
    error, allowed = mismatch(path)
    if error > allowed:
        # the root finder's start, from where plain repetition stopped; the secant
        # Jacobian from this cycle and the two before, not the first guess's if it can
        path = cycle(path[:, -1])
        starts.append(path[:, 0])
        ends.append(path[:, -1])
    secant = secant_jacobian(starts, ends)

    def function(initial: FloatArray) -> FloatArray:
        value = residual(cycle, initial)
        error, allowed = mismatch(cycle.path)
        if error <= SETTLED * allowed:
            raise Settled(initial)
        return value

    def jacobian(initial: FloatArray) -> FloatArray:
        # (scipy calls it once at the start to check its shape, then once more there)
        if np.array_equal(initial, starts[-1]):
            return secant
        step = math.sqrt(JACOBIAN_STEP) * np.where(initial == 0.0, 1.0, np.abs(initial))
        return approx_fprime(initial, function, step)

    for _ in range(ROOT_ROUNDS):
        error, allowed = mismatch(path)
        if error <= allowed:
            break
        # the cycle map's fixed point; the orbit can creep towards the wall over many
        # cycles (a squeeze film thins slowly), which plain repetition follows slowly;
        # from the last start, whose cycle is integrated already
        from_secant = secant is not None and np.array_equal(path[:, 0], starts[-1])
        try:
            found = root(
                function,
                path[:, 0],
                jac=jacobian if from_secant else None,
                method="hybr",
                options={
                    "xtol": 0.1 * tolerance,
                    "maxfev": ROOT_EVALUATIONS,
                    "eps": JACOBIAN_STEP,
                },
            ).x
        except Settled as settled:
            found = settled.start
        # (the cycle map integrates a start it integrated last only once)
        path = cycle(found)
    return path


def wall_orbit(
    cycle: CycleMap, entry: FloatArray, probe_gap: float, angle_tolerance: float
) -> FloatArray | None:
    """The path of a pin resting on the wall, from where the search put it there [-].

    Where the film alone holds the pin (the asperities carry too little), the pin
    creeps towards the wall over the cycles, its gap shrinking ever more slowly, and
    its film's resistance to motion grows without bound in every direction as the gap
    closes: the pin then rolls with the mean surface speed and returns where the cycle
    began, *at any gap and any angle*. The cycle map is the identity there, so a fixed
    point of it is wherever a root finder stops. What is determined is the angle at
    which the creeping pin comes to rest: where the film no longer turns it along the
    wall as it sinks,

    .. math:: \\phi(T) = \\phi(0) \\quad\\text{for a pin started at } (1 - \\varepsilon) = g_p,
        \\qquad \\frac{\\partial(\\phi(T) - \\phi(0))}{\\partial\\phi(0)} < 0,

    the angle that attracts the creep from either side, found with
    :func:`scipy.optimize.brentq` by following the drift from where the pin reached the
    wall. On the wall the pin must sink there, and the cycle must keep most of a
    displacement along the wall (``|d(phi(T) - phi(0)) / d phi(0)| < WALL_CONTRACTION``:
    nearly the identity); else the pin is held off the wall, by a film that steers it
    back, and None is returned. The orbit is the cycle from that angle at the gap
    ``WALL_GAP`` (the film's share of the load is nil: the solids carry it).

    Parameters
    ----------
    cycle : CycleMap
        The cycle map.
    entry : ndarray, shape (2,)
        Where the search put the pin on the wall, stretched coordinate [-].
    probe_gap : float
        ``g_p``: the gap, over the clearance, at which the drift along the wall is
        measured [-].
    angle_tolerance : float
        The resting angle's tolerance [rad].

    Returns
    -------
    ndarray or None
        The orbit's path in the stretched coordinate, or None where the drift has no
        attracting angle, the pin does not sink there or the film steers it back.
    """

    def start_at(angle: float, gap: float) -> FloatArray:
        return stretched((1.0 - gap) * np.array([math.cos(angle), math.sin(angle)]))

    # the turn and the end gap of each angle probed (brentq asks for its bracket again)
    probed: dict[float, tuple[float, float]] = {}

    def drift(angle: float) -> float:
        """The turn of a pin started ``probe_gap`` off the wall at ``angle``, one cycle [rad]."""
        if angle not in probed:
            end = cycle(start_at(angle, probe_gap))[:, -1]
            turn = math.remainder(math.atan2(end[1], end[0]) - angle, 2.0 * math.pi)
            probed[angle] = turn, 1.0 / (1.0 + float(np.hypot(*end)))
        return probed[angle][0]

    cycle.rtol = SEARCH_RTOL
    # follow the drift, in growing steps, until it turns back within half a turn: the
    # attracting angle lies between
    origin = near = float(math.atan2(entry[1], entry[0]))
    near_drift, step = drift(near), WALL_STEP
    if near_drift == 0.0:
        return None
    heading = math.copysign(1.0, near_drift)
    far = near + heading * step
    while math.copysign(1.0, drift(far)) == heading:
        if abs(far - origin) >= math.pi:
            return None
        near, step = far, 2.0 * step
        far = near + heading * step
    low, high = sorted((near, far))
    if abs(drift(high) - drift(low)) >= WALL_CONTRACTION * (high - low):
        return None  # the cycle map contracts along the wall: a film holds the pin
    resting = brentq(drift, low, high, xtol=angle_tolerance)
    drift(resting)
    if probed[resting][1] >= probe_gap:  # the pin does not sink there
        return None
    cycle.rtol = INTEGRATION_RTOL
    return cycle(start_at(resting, WALL_GAP))


def searched(
    cycle: CycleMap,
    start: FloatArray,
    mismatch: Callable[[FloatArray], tuple[float, float]],
    tolerance: float,
) -> FloatArray:
    """The periodic path from ``start`` (``e / c``) by :func:`fixed_point` [-].

    Found with cycles of a coarser tolerance, proved (or else found again) with cycles
    of the full one: the fixed points of the two maps differ by their integration
    errors, well inside the tolerance.
    """
    cycle.rtol = SEARCH_RTOL
    initial = stretched(start)
    if 0.0 < 1.0 - float(np.hypot(start[0], start[1])) < cycle.wall_gap:  # on the wall
        raise PinOnWall(initial)
    path = fixed_point(cycle, cycle(initial), mismatch, tolerance)
    cycle.rtol = INTEGRATION_RTOL
    return fixed_point(cycle, cycle(path[:, 0]), mismatch, tolerance)


#: least film parameter below which the film alone must hold the pin off its asperities
CREEPING_FILM_PARAMETER = 0.5


def creeping_pin(solver: OrbitSolver, path: FloatArray) -> str:
    """What an orbit that does not repeat says about the joint, for its error message.

    A pin whose least film parameter stays low keeps sinking a little every cycle: the
    squeeze film thins slowly and the asperities carry too little to stop it, so there
    is no orbit within the cycles allowed and the film model is out of its range.

    Parameters
    ----------
    solver : OrbitSolver
        The joint, its film and its asperities.
    path : ndarray, shape (2, M + 1)
        The last cycle's ``e / c`` [-].
    """
    gap = solver.clearance * (1.0 - float(np.hypot(*path).max()))
    parameter = gap / solver.roughness
    if parameter >= CREEPING_FILM_PARAMETER:
        return ""
    return (
        f"; the pin keeps sinking towards the wall at a least film parameter of "
        f"{parameter:.2g}: the film alone holds this load and the model is out of its range "
        f"there (a smoother finish, a more viscous oil or model = 'dry' are within it)"
    )


def periodic_orbit(
    solver: OrbitSolver,
    time: ArrayLike,
    period: float,
    load_x: ArrayLike,
    load_y: ArrayLike,
    mean_speed: ArrayLike,
    start: ArrayLike,
    tolerance: float = 1e-3,
    compiled: bool = True,
) -> Orbit:
    """The periodic orbit of a pin over a load cycle (module text).

    Load and mean surface speed are interpolated linearly and periodically between
    their samples.

    Parameters
    ----------
    solver : OrbitSolver
        The joint, its film and its asperities.
    time : array_like, shape (M,)
        Times of the samples, in ``[0, period)`` [s]; the orbit is returned there.
    period : float
        The cycle's duration [s].
    load_x, load_y : array_like, shape (M,)
        Load on the pin at ``time`` [N].
    mean_speed : array_like, shape (M,)
        ``(omega_pin + omega_bushing) / 2`` at ``time`` [rad/s].
    start : array_like, shape (2,)
        First guess of ``e / c`` at ``time[0]`` [-].
    tolerance : float
        The orbit repeats when ``|e(T) - e(0)|`` is below ``tolerance`` times the
        smallest gap ``c (1 - eps)`` of the cycle, or times ``sigma`` if that is
        larger [-].
    compiled : bool
        Integrate with the compiled kernel where numba is installed (:class:`CycleMap`).

    Returns
    -------
    Orbit
        The orbit at ``time``.

    Raises
    ------
    ConvergenceError
        When the orbit does not repeat within the cycles allowed.
    """
    cycle = CycleMap(solver, time, period, load_x, load_y, mean_speed, compiled)

    # the gap matters against the roughness: a pin on its asperities needs no finer
    floor = GAP_FLOOR * solver.roughness / solver.clearance

    last: list[Any] = [None, (math.nan, math.nan)]

    def mismatch(path: FloatArray) -> tuple[float, float]:
        """``|e(T) - e(0)| / c`` and the tolerance it must meet [-]."""
        # asked several times of a cycle: the last cycle's answer kept
        if path is last[0]:
            return last[1]
        # the least gap 1 - eps = 1 / (1 + |q|) at the largest |q| (found by |q|^2: a
        # hypot per sample costs more than the rest): no need to unstretch the whole
        # path; its ends unstretched as scalars
        far = int(np.argmax(path[0] * path[0] + path[1] * path[1]))
        gap = max(1.0 / (1.0 + math.hypot(path[0, far], path[1, far])), floor)
        x0, y0, x1, y1 = path[0, 0], path[1, 0], path[0, -1], path[1, -1]
        norm0, norm1 = 1.0 + math.hypot(x0, y0), 1.0 + math.hypot(x1, y1)
        error = math.hypot(x1 / norm1 - x0 / norm0, y1 / norm1 - y0 / norm0)
        last[:] = path, (float(error), tolerance * gap)
        return last[1]

    start = np.asarray(start, float)
    # where the asperities cannot hold the pin at any step, a pin started on the wall or
    # carried onto it by the root finder is posed again there (wall_orbit); kept if its
    # cycle closes
    wall = WALL_FILM_PARAMETER * solver.roughness / solver.clearance
    capacity = -float(solver.asperity_at(0.0))  # (asperity_force(1.0), the gap nil)
    cycle.wall_gap = wall if capacity < float(np.min(np.hypot(load_x, load_y))) else 0.0
    try:
        path = searched(cycle, start, mismatch, tolerance)
    except PinOnWall as reached:
        cycle.wall_gap = 0.0
        resting = wall_orbit(cycle, reached.start, wall, tolerance * floor)
        if resting is not None and mismatch(resting)[0] <= mismatch(resting)[1]:
            path = resting
        else:
            path = searched(cycle, start, mismatch, tolerance)
    cycles = cycle.integrations
    error, allowed = mismatch(path)
    if error > allowed:
        raise ConvergenceError(
            f"orbit: not periodic after {cycles} cycles (|e(T) - e(0)| / c = {error:.3g})"
            + creeping_pin(solver, unstretched(path))
        )
    path = unstretched(path)
    eps = np.hypot(path[0, :-1], path[1, :-1])
    return Orbit(
        eccentricity_x=path[0, :-1],
        eccentricity_y=path[1, :-1],
        eccentricity_ratio=eps,
        asperity_force=solver.asperity_force(eps),
        cycles=cycles,
        periodicity_error=error,
    )
