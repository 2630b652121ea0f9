"""The finite-length journal bearing and Booker's mobility method.

The film force of a bushing of any length is the solution of the two-dimensional
Reynolds equation (:mod:`jointwear.lubrication.film`). In the dimensionless pressure
``Pi`` with ``p = 6 mu (R/c)^2 m Pi`` and axial coordinate ``zeta = z / R``,

.. math::

    \\frac{\\partial}{\\partial\\theta}\\Big(H^3\\frac{\\partial\\Pi}{\\partial\\theta}\\Big)
    + \\frac{\\partial}{\\partial\\zeta}\\Big(H^3\\frac{\\partial\\Pi}{\\partial\\zeta}\\Big)
    = -\\sin(\\theta - \\beta),
    \\qquad H = 1 + \\varepsilon\\cos\\theta,

where the motion enters only through its size ``m`` and direction ``beta``:
``eps omega_bar = m cos beta`` and ``2 deps/dt = m sin beta``. ``Pi`` is zero at both
ends of the bushing (``zeta = +-L/(2R)``) and periodic in ``theta``. The full-film
solution is ``cos beta Pi_w + sin beta Pi_s`` of two solutions per eccentricity;
half-Sommerfeld cavitation keeps its positive part. The force is then

.. math:: F = 6\\mu R^2 (R/c)^2\\, m\\, G(\\varepsilon, \\beta; L/D),
          \\qquad G = \\iint \\Pi^+ (\\cos\\theta, \\sin\\theta)\\,d\\theta\\,d\\zeta .

:func:`finite_bearing_force` solves the equation by finite differences (conservative
second-order stencil on a grid uniform in Sommerfeld's angle, which crowds the nodes at
the smallest film), tabulates ``G`` over the eccentricity and ``beta`` once per ``L/D``
(cached) and interpolates it with cubic splines: thousands of states per call, any
``L/D``. Up to ``eps = 0.995``; beyond, up to ``1 - 1e-5``, a wall table in the variables
in which the film near the wall is bounded (:func:`to_wall`, :func:`wall_table`); where
the pin leaves the wall, from ``eps = 0.9`` on, a leaving table on a finer grid
(:func:`to_leaving`, :func:`leaving_table`). Its accuracy against closed forms is in
``docs/lubrication.md``.

Booker's mobility method inverts the force law: given the load on the pin, it returns
the velocity of the pin's centre. In a frame turning at the mean surface speed
``(omega_pin + omega_bushing) / 2`` the film is a pure squeeze film, and

.. math::

    \\dot\\varepsilon = \\frac{|F|(c/R)^2}{\\mu L D} M_\\varepsilon, \\qquad
    \\varepsilon\\Big(\\dot\\phi - \\frac{\\omega_{pin}+\\omega_{bushing}}{2}\\Big)
      = \\frac{|F|(c/R)^2}{\\mu L D} M_\\phi,

with the mobility vector ``M(eps, direction of the load)``. Here it is computed from
the same force laws (short, long or finite length), so the mobility and the force
models agree exactly. Goenka (1984) fitted closed forms to this finite-length mobility;
jointwear computes it from the Reynolds equation instead, so its accuracy is measured
rather than inherited from a fit.

Sources: [1]_, [2]_, [3]_.

References
----------
.. [1] J. F. Booker, "Dynamically loaded journal bearings: mobility method of
   solution", ASME J. Basic Eng. 87 (1965) 537-546.
.. [2] J. F. Booker, "Dynamically loaded journal bearings: numerical application of the
   mobility method", ASME J. Lubr. Technol. 93 (1971) 168-176.
.. [3] P. K. Goenka, "Analytical curve fits for solution parameters of dynamically
   loaded journal bearings", ASME J. Tribol. 106 (1984) 421-428.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import cache, partial
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import RegularGridInterpolator
from scipy.optimize import elementwise

from jointwear.geometry.angles import wrap_angle
from jointwear.lubrication.film import (
    FilmForce,
    long_bearing_force,
    short_bearing_force,
)
from jointwear.lubrication.reynolds import Cavitation, reynolds_forces, tabulated_forces

__all__ = [
    "FILM_MODELS",
    "CentreVelocity",
    "Mobility",
    "film_force",
    "finite_bearing_force",
    "journal_centre_velocity",
    "mobility",
]

FloatArray = NDArray[np.float64]

#: tabulated eccentricities eps = 1 - 10^-s, s uniform in [0, LOG_GAP_MAX] (eps <= 0.995);
#: beyond, the wall table (:func:`wall_table`) takes over
LOG_GAP_MAX = 2.3
LOG_GAP_NODES = 40
#: the table's largest eccentricity (its node, bit for bit): beyond it the wall table
TABLE_EDGE = 1.0 - 10.0**-LOG_GAP_MAX
DIRECTION_NODES = 72
#: the wall table: s uniform in [LOG_GAP_MAX, WALL_LOG_GAP_MAX] (eps up to 1 - 1e-5);
#: beyond, its scaled values are held (the wall's own asymptotics, :func:`to_wall`)
WALL_LOG_GAP_MAX = 5.0
WALL_LOG_GAP_NODES = 10
#: inner directions psi of the wall table (:func:`wall_direction`)
WALL_DIRECTION_NODES = 72
#: the wall table's Reynolds grid (angle nodes, axial cells): the film's pressure gathers
#: within ``sqrt(1 - eps)`` of the smallest gap, and its axial fall at the ends as well
WALL_GRID = (480, 64)
#: over this much of s beyond the table's end the wall table passes from the usual grid
#: (force_table's) to WALL_GRID
WALL_BLEND = 0.6
#: the wall's inner direction psi (:func:`wall_direction`) beyond which, within
#: (-pi + LEAVING_WALL, -LEAVING_WALL), the pin leaves the wall: tan(beta) <
#: -3 sqrt(1 - eps^2), where the film's force is of order one and the wall table in psi
#: does not resolve it; the finite bearing's leaving table (:func:`leaving_table`) there
LEAVING_WALL = math.atan(3.0)
#: directions u of the leaving table over [-1, 1] (:func:`leaving_direction`)
LEAVING_DIRECTION_NODES = 41
#: the leaving table: s uniform in [LEAVING_LOG_GAP_MIN, WALL_LOG_GAP_MAX] (eps from 0.9,
#: where force_table's grid is within 4e-3 of |G| of a finer one there, to 1 - 1e-5)
LEAVING_LOG_GAP_MIN = 1.0
LEAVING_LOG_GAP_NODES = 15
#: the eccentricity beyond which the leaving table takes over where the pin leaves the wall
LEAVING_START = 1.0 - 10.0**-LEAVING_LOG_GAP_MIN
#: the leaving table's Reynolds grid with Reynolds' cavitation (its complementarity
#: problem on WALL_GRID would take minutes; this one is within 4e-3 of |G| of a grid
#: four times finer along the angle)
LEAVING_REYNOLDS_GRID = (480, 16)
#: the leaving table's grid crowds its nodes as a film of gap 1000 (1 - eps) would, but
#: no more than one of eps = 0.9 (:func:`leaving_crowding`)
LEAVING_CROWDING = 1000.0
#: eccentricity below which the mobility uses this value (the direction of e is undefined)
SMALLEST_ECCENTRICITY = 1e-6


@cache
def force_table(
    length_to_diameter: float, cavitation: Cavitation = "half-Sommerfeld"
) -> RegularGridInterpolator:
    """Interpolant of ``(1 - eps^2)^2.5 G(eps, beta)`` over ``(s, beta)``, ``eps = 1 - 10^-s``.

    Built once per ``L/D`` and cavitation condition and cached: about 0.3 s with
    half-Sommerfeld's, some 10-30 s with Reynolds' (a complementarity problem per state,
    :func:`~jointwear.lubrication.reynolds.reynolds_forces`).

    Parameters
    ----------
    length_to_diameter : float
        ``L / D`` [-].
    cavitation : {"half-Sommerfeld", "Reynolds"}
        The film's cavitation condition (:mod:`jointwear.lubrication.reynolds`).
    """
    forces = reynolds_forces if cavitation == "Reynolds" else tabulated_forces
    log_gap = np.linspace(0.0, LOG_GAP_MAX, LOG_GAP_NODES)
    directions = np.linspace(-np.pi, np.pi, DIRECTION_NODES, endpoint=False)
    values = np.empty((LOG_GAP_NODES, DIRECTION_NODES, 2))
    for k, s in enumerate(log_gap):
        eps = 1.0 - 10.0**-s
        values[k] = forces(eps, length_to_diameter, directions).T * (1.0 - eps * eps) ** 2.5
    return periodic_interpolant(log_gap, directions, values)


def periodic_interpolant(
    log_gap: FloatArray, directions: FloatArray, values: FloatArray
) -> RegularGridInterpolator:
    """Cubic interpolant of ``values[s, direction, component]``, periodic in the direction.

    Parameters
    ----------
    log_gap : ndarray
        ``s = -log10(1 - eps)`` of the rows [-].
    directions : ndarray
        Directions of the columns, uniform over ``[-pi, pi)`` [rad].
    values : ndarray
        The tabulated values [-].
    """
    # three directions repeated on each side make the spline periodic
    pad = 3
    padded = np.concatenate([values[:, -pad:], values, values[:, :pad]], axis=1)
    axis = np.concatenate(
        [directions[-pad:] - 2.0 * np.pi, directions, directions[:pad] + 2.0 * np.pi]
    )
    return RegularGridInterpolator((log_gap, axis), padded, method="cubic")


def wall_motion(eps: ArrayLike, inner: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """The direction ``beta`` of the wall's inner direction ``psi`` [rad], and ``m'`` [-].

    Close to the wall the film's pressure gathers within ``sqrt(1 - eps)`` of the
    smallest gap, where the wedge's share of the pressure is ``sqrt(1 - eps^2) cos beta``
    to the squeeze's ``sin beta``. The film there depends on the direction through

    .. math:: \\tan\\psi = \\frac{\\tan\\beta}{\\sqrt{1-\\varepsilon^2}}, \\qquad
              m' = \\sqrt{(1-\\varepsilon^2)\\cos^2\\beta + \\sin^2\\beta},

    (``psi`` in the quadrant of ``beta``): the inverse of :func:`wall_direction`.

    Parameters
    ----------
    eps : array_like
        Eccentricity ratio [-].
    inner : array_like
        ``psi`` [rad].
    """
    root = np.sqrt(1.0 - np.asarray(eps, float) ** 2)
    direction = np.arctan2(root * np.sin(inner), np.cos(inner))
    return direction, wall_direction(eps, direction)[1]


def wall_direction(eps: ArrayLike, direction: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """The wall's inner direction ``psi`` of the motion ``beta`` [rad], and ``m'`` [-].

    (:func:`wall_motion`.)

    Parameters
    ----------
    eps : array_like
        Eccentricity ratio [-].
    direction : array_like
        ``beta`` [rad].
    """
    root = np.sqrt(1.0 - np.asarray(eps, float) ** 2)
    wedge, squeeze = root * np.cos(direction), np.sin(direction)
    return np.arctan2(squeeze, wedge), np.hypot(wedge, squeeze)


def to_wall(shape: FloatArray, eps: ArrayLike, size: ArrayLike) -> FloatArray:
    """``G`` scaled to the wall's bounded values ``V``, shape ``(2, ...)`` [-].

    Where the gap is small against the bushing's length the film near the wall is a
    long bearing's (Sommerfeld's): its wedge force grows like ``(1 - eps^2)^-1``
    (radial) and ``(1 - eps^2)^-1/2`` (tangential), its squeeze force like
    ``(1 - eps^2)^-3/2`` (Hamrock, Schmid & Jacobson 2004, ch. 8 and 10). With the inner
    direction of :func:`wall_direction`,

    .. math:: G_r = \\frac{m' V_r(\\varepsilon, \\psi)}{(1-\\varepsilon^2)^{3/2}}, \\qquad
              G_t = \\frac{m' V_t(\\varepsilon, \\psi)}{1-\\varepsilon^2},

    and ``V`` tends to a bounded function of ``psi`` alone as ``eps -> 1`` (within
    2e-4 from ``1 - eps = 1e-4`` for the long bearing), smooth where ``G`` changes
    within ``sqrt(1 - eps)`` of a pure wedge.

    Parameters
    ----------
    shape : ndarray
        ``G_r, G_t`` [-].
    eps : array_like
        Eccentricity ratio [-].
    size : array_like
        ``m'`` [-].
    """
    one_minus = 1.0 - np.asarray(eps, float) ** 2
    return np.stack([shape[0] * one_minus**1.5, shape[1] * one_minus]) / size


def from_wall(values: FloatArray, eps: ArrayLike, size: ArrayLike) -> FloatArray:
    """``G`` of the wall's scaled values ``V`` (:func:`to_wall`), shape ``(2, ...)`` [-]."""
    one_minus = 1.0 - np.asarray(eps, float) ** 2
    return np.stack(
        [size * values[0] / (one_minus * np.sqrt(one_minus)), size * values[1] / one_minus]
    )


@cache
def wall_table(
    length_to_diameter: float, cavitation: Cavitation = "half-Sommerfeld"
) -> RegularGridInterpolator:
    """Interpolant of the wall's ``V(eps, psi)`` (:func:`to_wall`) over ``(s, psi)``.

    ``eps = 1 - 10^-s`` from the end of :func:`force_table` (0.995) to ``1 - 1e-5``;
    half-Sommerfeld's film on the finer grid :data:`WALL_GRID` (about 1.5 s once per
    ``L/D``), Reynolds' on the usual grid (some 5 s).

    Parameters
    ----------
    length_to_diameter : float
        ``L / D`` [-].
    cavitation : {"half-Sommerfeld", "Reynolds"}
        The film's cavitation condition (:mod:`jointwear.lubrication.reynolds`).
    """
    log_gap = np.linspace(LOG_GAP_MAX, WALL_LOG_GAP_MAX, WALL_LOG_GAP_NODES)
    inner = np.linspace(-np.pi, np.pi, WALL_DIRECTION_NODES, endpoint=False)
    values = np.empty((WALL_LOG_GAP_NODES, WALL_DIRECTION_NODES, 2))
    for k, s in enumerate(log_gap):
        eps = 1.0 - 10.0**-s
        direction, size = wall_motion(eps, inner)
        if cavitation == "Reynolds":
            shape = reynolds_forces(eps, length_to_diameter, direction)
        else:
            shape = tabulated_forces(eps, length_to_diameter, direction, WALL_GRID)
            # the usual grid's error (0.4 % at the table's end) fades out over
            # WALL_BLEND, so that the wall table continues force_table at its end
            share = max(0.0, 1.0 - (s - LOG_GAP_MAX) / WALL_BLEND)
            if share > 0.0:
                coarse = tabulated_forces(eps, length_to_diameter, direction)
                shape = shape + share * (coarse - shape)
        values[k] = to_wall(shape, eps, size).T
    return periodic_interpolant(log_gap, inner, values)


def leaving_crowding(eps: float) -> float:
    """The Sommerfeld-angle eccentricity of the leaving table's grid [-].

    A grid uniform in Sommerfeld's angle of ``eps`` itself (:func:`film_system
    <jointwear.lubrication.reynolds.film_system>`) leaves a node or two on the wide side
    of a film close to the wall, where the pressure of a pin leaving the wall lies:
    ``min(eps, max(0.9, 1 - 1000 (1 - eps)))`` keeps some 20 nodes per radian there and
    still crowds them at the smallest film (the forces within 1e-3 of a grid four times
    finer, measured at ``1 - eps`` = 1.2e-5).

    Parameters
    ----------
    eps : float
        Eccentricity ratio [-].
    """
    return min(eps, max(0.9, 1.0 - LEAVING_CROWDING * (1.0 - eps)))


def leaving_edge(eps: ArrayLike) -> FloatArray:
    """``asinh(1 / (3 sqrt(1 - eps^2)))``: ``|asinh(cot beta)|`` at the leaving region's edge [-].

    Parameters
    ----------
    eps : array_like
        Eccentricity ratio [-].
    """
    return np.arcsinh(1.0 / (3.0 * np.sqrt(1.0 - np.asarray(eps, float) ** 2)))


def leaving_direction(eps: ArrayLike, direction: ArrayLike) -> FloatArray:
    """The leaving table's direction ``u = asinh(cot beta) / leaving_edge(eps)`` [-].

    Where the pin leaves the wall (``sin beta < 0``, ``|cot beta| < 1/(3 sqrt(1 -
    eps^2))``: :data:`LEAVING_WALL`) ``u`` runs from -1 (``tan beta = -3 sqrt(1 -
    eps^2)``) to 1 (``beta`` as close to ``-pi``): linear in ``beta`` about ``-pi/2``,
    where the film's force tends to a finite limit at fixed ``beta`` as ``eps -> 1``,
    and logarithmic in ``cot beta`` towards the edges, where it grows like
    ``(1 - eps^2)^-1`` within ``sqrt(1 - eps^2)`` of a pure wedge.

    Parameters
    ----------
    eps : array_like
        Eccentricity ratio [-].
    direction : array_like
        ``beta`` [rad].
    """
    return np.arcsinh(np.cos(direction) / np.sin(direction)) / leaving_edge(eps)


def leaving_motion(eps: ArrayLike, leaving: ArrayLike) -> FloatArray:
    """``beta`` of the leaving table's direction ``u`` (inverse of :func:`leaving_direction`) [rad].

    Parameters
    ----------
    eps : array_like
        Eccentricity ratio [-].
    leaving : array_like
        ``u`` in [-1, 1] [-].
    """
    return np.arctan2(-1.0, -np.sinh(np.asarray(leaving, float) * leaving_edge(eps)))


def to_leaving(shape: FloatArray, direction: ArrayLike) -> FloatArray:
    """The leaving table's bounded values ``(W, T)`` of ``G``, shape ``(2, ...)`` [-, rad].

    .. math:: G_r = \\frac{e^W \\cos T}{\\sin^2\\beta}, \\qquad
              G_t = \\frac{e^W \\sin T}{|\\sin\\beta|} :

    at fixed ``beta`` the force of a pin leaving the wall tends to a finite limit as
    ``eps -> 1``; towards the edges, at a fixed inner direction ``psi``
    (:func:`wall_direction`), it grows like the wall's ``(1 - eps^2)^-1`` (radial) and
    ``(1 - eps^2)^-1/2`` (tangential), as ``1 / sin^2 beta`` and ``1 / |sin beta|`` do
    there. The angle ``T`` is unwrapped by the caller.

    Parameters
    ----------
    shape : ndarray
        ``G_r, G_t`` [-].
    direction : array_like
        ``beta`` [rad].
    """
    across = np.abs(np.sin(direction))
    return np.stack(
        [
            np.log(np.hypot(shape[0], shape[1] / across) * across**2),
            np.arctan2(shape[1] / across, shape[0]),
        ]
    )


def from_leaving(values: FloatArray, direction: ArrayLike) -> FloatArray:
    """``G`` of the leaving table's values ``(W, T)`` (:func:`to_leaving`), ``(2, ...)`` [-].

    Parameters
    ----------
    values : ndarray
        ``W`` and ``T`` [-, rad].
    direction : array_like
        ``beta`` [rad].
    """
    across = np.abs(np.sin(direction))
    size = np.exp(values[0]) / across**2
    return np.stack([size * np.cos(values[1]), size * across * np.sin(values[1])])


@cache
def leaving_values(
    length_to_diameter: float, cavitation: Cavitation = "half-Sommerfeld"
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The leaving table's nodes ``(s, u)`` and values [-].

    Where the pin leaves the wall (:data:`LEAVING_WALL`) beyond ``eps = 0.9``
    (:data:`LEAVING_START`): ``W, T`` of :func:`to_leaving` over ``s = -log10(1 - eps)``
    and ``u`` (:func:`leaving_direction`), both bounded. Half-Sommerfeld's film on
    :data:`WALL_GRID`, Reynolds' on :data:`LEAVING_REYNOLDS_GRID`, both with the grid of
    :func:`leaving_crowding` (some 2.5 s and 7 s once per ``L/D``): the usual grid and
    directions of :func:`force_table` are 1-30 % off there from ``eps = 0.97`` on
    (``docs/lubrication.md``).

    Parameters
    ----------
    length_to_diameter : float
        ``L / D`` [-].
    cavitation : {"half-Sommerfeld", "Reynolds"}
        The film's cavitation condition (:mod:`jointwear.lubrication.reynolds`).

    Returns
    -------
    tuple of ndarray
        ``s`` [-], ``u`` [-] and the values ``[s, u, (W, T)]`` [-, rad].
    """
    log_gap = np.linspace(LEAVING_LOG_GAP_MIN, WALL_LOG_GAP_MAX, LEAVING_LOG_GAP_NODES)
    leaving = np.linspace(-1.0, 1.0, LEAVING_DIRECTION_NODES)
    values = np.empty((LEAVING_LOG_GAP_NODES, LEAVING_DIRECTION_NODES, 2))
    for k, s in enumerate(log_gap):
        eps = 1.0 - 10.0**-s
        direction = leaving_motion(eps, leaving)
        crowding = leaving_crowding(eps)
        if cavitation == "Reynolds":
            shape = reynolds_forces(
                eps, length_to_diameter, direction, False, LEAVING_REYNOLDS_GRID, crowding
            )
        else:
            shape = tabulated_forces(eps, length_to_diameter, direction, WALL_GRID, crowding)
        scaled, angle = to_leaving(shape, direction)
        angle = np.unwrap(angle)
        # one branch of the angle for all rows: the middle direction's in (-pi, pi]
        angle -= 2.0 * np.pi * np.round(angle[LEAVING_DIRECTION_NODES // 2] / (2.0 * np.pi))
        values[k, :, 0], values[k, :, 1] = scaled, angle
    return log_gap, leaving, values


@cache
def leaving_table(
    length_to_diameter: float, cavitation: Cavitation = "half-Sommerfeld"
) -> RegularGridInterpolator:
    """Cubic interpolant of :func:`leaving_values` over ``(s, u)`` [-].

    Parameters
    ----------
    length_to_diameter : float
        ``L / D`` [-].
    cavitation : {"half-Sommerfeld", "Reynolds"}
        The film's cavitation condition.
    """
    log_gap, leaving, values = leaving_values(length_to_diameter, cavitation)
    return RegularGridInterpolator((log_gap, leaving), values, method="cubic")


def leaving_the_wall(inner: ArrayLike) -> NDArray[np.bool_]:
    """Whether the wall's inner direction ``psi`` is one of a pin leaving the wall [-].

    Parameters
    ----------
    inner : array_like
        ``psi`` (:func:`wall_direction`) [rad].
    """
    inner = np.asarray(inner, float)
    return (-np.pi + LEAVING_WALL < inner) & (inner < -LEAVING_WALL)


def leaving_states(eps: FloatArray, direction: FloatArray) -> NDArray[np.bool_]:
    """Which states lie on the leaving table: beyond ``eps = 0.9``
    (:data:`LEAVING_START`) where the pin leaves the wall (:func:`leaving_the_wall`).

    Parameters
    ----------
    eps : ndarray
        Eccentricity ratio [-].
    direction : ndarray
        ``beta`` of the motion [rad].
    """
    leaving = eps > LEAVING_START
    if np.any(leaving):
        leaving[leaving] = leaving_the_wall(wall_direction(eps[leaving], direction[leaving])[0])
    return leaving


def leaving_log_gap(eps: ArrayLike) -> FloatArray:
    """The leaving table's ``s = -log10(1 - eps)``, held at its ends [-].

    Parameters
    ----------
    eps : array_like
        Eccentricity ratio [-].
    """
    unclipped = -np.log10(np.maximum(1.0 - np.asarray(eps, float), 1e-300))
    return np.clip(unclipped, LEAVING_LOG_GAP_MIN, WALL_LOG_GAP_MAX)


def wall_finite(
    eps: FloatArray, direction: FloatArray, ratio: float, cavitation: Cavitation
) -> FloatArray:
    """``G(eps, beta; L/D)`` of the finite bearing beyond ``eps = 0.995``, shape ``(2, ...)`` [-].

    From :func:`wall_table`, its values held beyond ``1 - 1e-5`` (:func:`to_wall`).
    """
    inner, size = wall_direction(eps, direction)
    log_gap = np.clip(-np.log10(np.maximum(1.0 - eps, 1e-300)), LOG_GAP_MAX, WALL_LOG_GAP_MAX)
    values = wall_table(ratio, cavitation)(np.stack([log_gap, inner], axis=-1))
    return from_wall(values.T, eps, size)


def leaving_finite(
    out: FloatArray, eps: FloatArray, direction: FloatArray, ratio: float, cavitation: Cavitation
) -> FloatArray:
    """``out`` with :func:`leaving_table`'s ``G`` where the pin leaves the wall [-].

    Beyond ``eps = 0.9`` (:data:`LEAVING_START`) where :func:`leaving_the_wall`, held
    beyond ``1 - 1e-5`` in ``W, T`` at the same ``u``; elsewhere ``out`` as it is.

    Parameters
    ----------
    out : ndarray
        ``G`` of the other tables, shape ``(2, ...)``, changed in place [-].
    eps, direction : ndarray
        Eccentricity ratio [-] and ``beta`` [rad] of its states.
    ratio : float
        ``L / D`` [-].
    cavitation : {"half-Sommerfeld", "Reynolds"}
        The film's cavitation condition.
    """
    leaving = leaving_states(eps, direction)
    if np.any(leaving):
        motion = leaving_direction(eps[leaving], direction[leaving])
        at = np.stack([leaving_log_gap(eps[leaving]), motion], axis=-1)
        scaled = leaving_table(ratio, cavitation)(at)
        out[:, leaving] = from_leaving(scaled.T, direction[leaving])
    return out


def finite_bearing_force(
    radius: ArrayLike,
    length: ArrayLike,
    clearance: ArrayLike,
    viscosity: ArrayLike,
    eccentricity_ratio: ArrayLike,
    eccentricity_rate: ArrayLike,
    wedge_speed: ArrayLike,
    cavitation: Cavitation = "half-Sommerfeld",
) -> FilmForce:
    """Film force of a bushing of finite length [N].

    .. math:: F = 6\\mu R^2 (R/c)^2\\, m\\, G(\\varepsilon, \\beta; L/D), \\qquad
              m = \\sqrt{(\\varepsilon\\bar\\omega)^2 + (2\\dot\\varepsilon)^2},\\;
              \\beta = \\operatorname{atan2}(2\\dot\\varepsilon, \\varepsilon\\bar\\omega)

    with ``G`` the tabulated numerical solution of the Reynolds equation (module text).
    Tends to :func:`~jointwear.lubrication.film.short_bearing_force` for small ``L/D``
    and to :func:`~jointwear.lubrication.film.long_bearing_force` for large ``L/D``.
    Tabulated in ``(1 - eps^2)^2.5 G`` for ``eps <= 0.995``; beyond, up to ``1 - 1e-5``, in
    the wall's scaled values (:func:`to_wall`: near the wall the film is a long bearing's
    where the gap is small against the length), held beyond that.

    Parameters
    ----------
    radius : array_like
        Pin radius ``R`` [m].
    length : array_like
        Bushing length ``L`` [m].
    clearance : array_like
        Radial clearance ``c`` [m].
    viscosity : array_like
        Dynamic viscosity ``mu`` [Pa s].
    eccentricity_ratio : array_like
        ``eps`` in [0, 1) [-].
    eccentricity_rate : array_like
        ``deps/dt`` [1/s].
    wedge_speed : array_like
        ``omega_bar = omega_pin + omega_bushing - 2 dphi/dt`` [rad/s].
    cavitation : {"half-Sommerfeld", "Reynolds"}
        The film's cavitation condition (:mod:`jointwear.lubrication.reynolds`).

    Returns
    -------
    FilmForce
        Radial and tangential components on the pin [N].
    """
    radius_, length_, clearance_, viscosity_, eps, rate, wedge = np.broadcast_arrays(
        *(
            np.asarray(a, dtype=float)
            for a in (
                radius,
                length,
                clearance,
                viscosity,
                eccentricity_ratio,
                eccentricity_rate,
                wedge_speed,
            )
        )
    )
    size = np.hypot(eps * wedge, 2.0 * rate)
    direction = np.arctan2(2.0 * rate, eps * wedge)
    shape = dimensionless_finite(eps, direction, length_ / (2.0 * radius_), cavitation)
    scale = 6.0 * viscosity_ * radius_**2 * (radius_ / clearance_) ** 2 * size
    return FilmForce(scale * shape[0], scale * shape[1])


def dimensionless_finite(
    eps: FloatArray,
    direction: FloatArray,
    ratio: FloatArray,
    cavitation: Cavitation = "half-Sommerfeld",
) -> FloatArray:
    """``G(eps, beta; L/D)`` of the finite bearing, shape ``(2, ...)`` [-]."""
    out = np.empty((2, *eps.shape))
    unclipped = -np.log10(np.maximum(1.0 - eps, 1e-300))
    log_gap = np.clip(unclipped, 0.0, LOG_GAP_MAX)
    # beyond the table's end the wall table takes over (its own scaling: to_wall)
    near_wall = eps > TABLE_EDGE
    wrapped = wrap_angle(direction)
    for value in np.unique(ratio):
        where = (ratio == value) & ~near_wall
        table = force_table(float(value), cavitation)
        scaled = table(np.stack([log_gap[where], wrapped[where]], axis=-1))
        out[:, where] = (scaled / (1.0 - eps[where, None] ** 2) ** 2.5).T
        wall = (ratio == value) & near_wall
        if np.any(wall):
            out[:, wall] = wall_finite(eps[wall], direction[wall], float(value), cavitation)
        # where the pin leaves the wall, from eps = 0.9 on, the leaving table
        here = ratio == value
        out[:, here] = leaving_finite(
            out[:, here], eps[here], direction[here], float(value), cavitation
        )
    return out


#: film models by name: force functions with the signature of short_bearing_force
#: (``"finite-reynolds"``: the finite bearing with Reynolds' cavitation)
FILM_MODELS: dict[str, Callable[..., FilmForce]] = {
    "short": short_bearing_force,
    "long": long_bearing_force,
    "finite": finite_bearing_force,
    "finite-reynolds": partial(finite_bearing_force, cavitation="Reynolds"),
}
#: the finite bearing's film models and their cavitation condition
FINITE_CAVITATION: dict[str, Cavitation] = {
    "finite": "half-Sommerfeld",
    "finite-reynolds": "Reynolds",
}


def film_force(
    model: str,
    radius: ArrayLike,
    length: ArrayLike,
    clearance: ArrayLike,
    viscosity: ArrayLike,
    eccentricity_ratio: ArrayLike,
    eccentricity_rate: ArrayLike,
    wedge_speed: ArrayLike,
) -> FilmForce:
    """Film force of the model named ``model`` (a key of :data:`FILM_MODELS`) [N].

    Parameters
    ----------
    model : str
        ``"short"``, ``"long"``, ``"finite"`` or ``"finite-reynolds"``.
    radius, length, clearance, viscosity, eccentricity_ratio, eccentricity_rate, wedge_speed
        As for :func:`~jointwear.lubrication.film.short_bearing_force` [SI].
    """
    return FILM_MODELS[model](
        radius, length, clearance, viscosity, eccentricity_ratio, eccentricity_rate, wedge_speed
    )


def dimensionless_force(
    model: str,
    eccentricity_ratio: FloatArray,
    direction: FloatArray,
    length_to_diameter: FloatArray,
) -> FloatArray:
    """``G(eps, beta; L/D)`` of a film model, shape ``(2, ...)`` [-] (module text).

    Parameters
    ----------
    model : str
        A key of :data:`FILM_MODELS`.
    eccentricity_ratio : ndarray
        ``eps`` [-].
    direction : ndarray
        ``beta = atan2(2 deps/dt, eps omega_bar)`` [rad].
    length_to_diameter : ndarray
        ``L / D`` [-].
    """
    eps, direction, ratio = np.broadcast_arrays(
        np.maximum(eccentricity_ratio, SMALLEST_ECCENTRICITY), direction, length_to_diameter
    )
    if model in FINITE_CAVITATION:
        return dimensionless_finite(eps, direction, ratio, FINITE_CAVITATION[model])
    # R = c = 1, mu = 1/6 and m = 1 make F = G
    force = FILM_MODELS[model](
        1.0, 2.0 * ratio, 1.0, 1.0 / 6.0, eps, 0.5 * np.sin(direction), np.cos(direction) / eps
    )
    return np.stack([force.radial, force.tangential])


class Mobility(NamedTuple):
    """Booker's mobility vector [-].

    Attributes
    ----------
    radial : ndarray
        ``M_eps``, along the line of centres [-].
    tangential : ndarray
        ``M_phi``, along ``e_t`` [-].
    """

    radial: FloatArray
    tangential: FloatArray


def mobility(
    eccentricity_ratio: ArrayLike,
    load_angle: ArrayLike,
    length_to_diameter: ArrayLike,
    model: str = "finite",
) -> Mobility:
    """Booker's mobility vector ``M(eps, load direction)`` of a film model [-].

    The squeeze motion whose film force balances the load: the direction ``beta`` of
    the motion is the root of ``angle(G(eps, beta)) = load_angle + pi``
    (:func:`scipy.optimize.elementwise.find_root`, bracketed on the tabulated
    directions), and

    .. math:: M_\\varepsilon = \\frac{L/D}{3|G|}\\sin\\beta, \\qquad
              M_\\phi = -\\frac{L/D}{3|G|}\\cos\\beta .

    For the short bearing at the centre this is Booker's ``1 / (pi (L/D)^2)`` along the
    load.

    Parameters
    ----------
    eccentricity_ratio : array_like
        ``eps`` in [0, 1) [-].
    load_angle : array_like
        Direction of the load on the pin, measured from the line of centres ``e_r``
        towards ``e_t`` [rad].
    length_to_diameter : array_like
        ``L / D`` [-].
    model : str
        ``"short"``, ``"long"``, ``"finite"`` or ``"finite-reynolds"`` (:data:`FILM_MODELS`).

    Returns
    -------
    Mobility
        ``M_eps`` and ``M_phi`` [-].

    References
    ----------
    Booker (1965, 1971).
    """
    eps, target, ratio = np.broadcast_arrays(
        np.asarray(eccentricity_ratio, float),
        np.asarray(load_angle, float) + np.pi,
        np.asarray(length_to_diameter, float),
    )

    def mismatch(
        direction: FloatArray, eps: FloatArray, target: FloatArray, ratio: FloatArray
    ) -> FloatArray:
        shape = dimensionless_force(model, eps, direction, ratio)
        return wrap_angle(np.arctan2(shape[1], shape[0]) - target)

    grid = np.linspace(-np.pi, np.pi, DIRECTION_NODES + 1)
    scan = mismatch(grid, eps[..., None], target[..., None], ratio[..., None])
    rising = (scan[..., :-1] <= 0.0) & (scan[..., 1:] > 0.0) & (np.diff(scan, axis=-1) < np.pi)
    cell = np.argmax(rising, axis=-1)
    found = elementwise.find_root(mismatch, (grid[cell], grid[cell + 1]), args=(eps, target, ratio))
    direction = np.where(np.any(rising, axis=-1), found.x, np.nan)
    shape = dimensionless_force(model, eps, direction, ratio)
    size = ratio / (3.0 * np.hypot(shape[0], shape[1]))
    return Mobility(size * np.sin(direction), -size * np.cos(direction))


class CentreVelocity(NamedTuple):
    """Motion of the pin's centre under a load (Booker's mobility method).

    Attributes
    ----------
    eccentricity_rate : ndarray
        ``deps/dt`` [1/s].
    line_of_centres_speed : ndarray
        ``dphi/dt`` [rad/s].
    velocity_x, velocity_y : ndarray
        Velocity of the pin's centre in the joint's x-y frame [m/s].
    """

    eccentricity_rate: FloatArray
    line_of_centres_speed: FloatArray
    velocity_x: FloatArray
    velocity_y: FloatArray


def journal_centre_velocity(
    load_x: ArrayLike,
    load_y: ArrayLike,
    line_of_centres_angle: ArrayLike,
    eccentricity_ratio: ArrayLike,
    radius: ArrayLike,
    length: ArrayLike,
    clearance: ArrayLike,
    viscosity: ArrayLike,
    pin_speed: ArrayLike,
    bushing_speed: ArrayLike = 0.0,
    model: str = "finite",
) -> CentreVelocity:
    """Velocity of the pin's centre that lets the film carry a load [1/s, rad/s, m/s].

    .. math::

        \\dot\\varepsilon = k M_\\varepsilon, \\qquad
        \\dot\\phi = \\frac{\\omega_{pin} + \\omega_{bushing}}{2}
                   + \\frac{k M_\\phi}{\\varepsilon}, \\qquad
        k = \\frac{|F|(c/R)^2}{\\mu L D},

    with ``M`` of :func:`mobility` at the load's direction relative to the line of
    centres; the centre moves with ``c (deps/dt e_r + eps dphi/dt e_t)``. Integrating
    this over a load cycle gives the orbit of the pin (Booker 1965).

    Parameters
    ----------
    load_x, load_y : array_like
        Load on the pin (the force the mechanism applies to it) [N].
    line_of_centres_angle : array_like
        ``phi``, direction of the eccentricity from the x axis [rad].
    eccentricity_ratio : array_like
        ``eps`` in (0, 1) [-].
    radius : array_like
        Pin radius ``R`` [m].
    length : array_like
        Bushing length ``L`` [m].
    clearance : array_like
        Radial clearance ``c`` [m].
    viscosity : array_like
        Dynamic viscosity ``mu`` [Pa s].
    pin_speed, bushing_speed : array_like
        Angular velocities of pin and bushing [rad/s].
    model : str
        ``"short"``, ``"long"``, ``"finite"`` or ``"finite-reynolds"``.

    Returns
    -------
    CentreVelocity
        Eccentricity rate, turning rate of the line of centres and the centre's
        velocity.
    """
    phi = np.asarray(line_of_centres_angle, float)
    eps = np.maximum(np.asarray(eccentricity_ratio, float), SMALLEST_ECCENTRICITY)
    radius_, length_, clearance_ = (np.asarray(a, float) for a in (radius, length, clearance))
    load = np.hypot(load_x, load_y)
    load_angle = wrap_angle(np.arctan2(load_y, load_x) - phi)
    vector = mobility(eps, load_angle, length_ / (2.0 * radius_), model)
    rate = (
        load
        * (clearance_ / radius_) ** 2
        / (np.asarray(viscosity, float) * length_ * 2.0 * radius_)
    )
    mean_speed = 0.5 * (np.asarray(pin_speed, float) + np.asarray(bushing_speed, float))
    eccentricity_rate = rate * vector.radial
    turning = mean_speed + rate * vector.tangential / eps
    radial_speed = clearance_ * eccentricity_rate
    tangential_speed = clearance_ * eps * turning
    return CentreVelocity(
        eccentricity_rate,
        turning,
        radial_speed * np.cos(phi) - tangential_speed * np.sin(phi),
        radial_speed * np.sin(phi) + tangential_speed * np.cos(phi),
    )
