"""Film forces of a journal bearing: a pin (journal) turning and moving in its bushing.

Geometry and signs (used by every module of :mod:`jointwear.lubrication`): the pin of
radius ``R`` sits in a bushing of radial clearance ``c`` and length ``L``; its centre is
displaced by the eccentricity ``e = eps c`` along the unit vector ``e_r`` (the line of
centres, at the angle ``phi`` in the joint's x-y frame); ``e_t`` is ``e_r`` turned by
+90 degrees. The film angle ``theta`` is measured from the point of *largest* film, so
the film thickness is

.. math:: h(\\theta) = c\\,(1 + \\varepsilon \\cos\\theta),

smallest at ``theta = pi``, which faces ``e_r``. Forces are those the film exerts on the
pin, split into the radial component (along ``e_r``; negative pushes the pin back to
the centre) and the tangential one (along ``e_t``).

The Reynolds equation of a pin turning at ``omega_pin`` in a bushing turning at
``omega_bushing``, whose centre moves with the eccentricity rate ``deps/dt`` and whose
line of centres turns at ``dphi/dt``, reads (Pinkus & Sternlicht 1961, ch. 3)

.. math::

    \\frac{1}{R^2}\\frac{\\partial}{\\partial\\theta}
    \\Big(h^3\\frac{\\partial p}{\\partial\\theta}\\Big)
    + \\frac{\\partial}{\\partial z}\\Big(h^3\\frac{\\partial p}{\\partial z}\\Big)
    = -6\\mu c\\,\\big(\\bar\\omega\\,\\varepsilon\\sin\\theta
      - 2\\dot\\varepsilon\\cos\\theta\\big),
    \\qquad \\bar\\omega = \\omega_{pin} + \\omega_{bushing} - 2\\dot\\phi,

the wedge term driven by the effective wedge speed ``omega_bar`` and the squeeze term
by ``deps/dt`` (the form used for lubricated joints of mechanisms by Flores et al.,
Mech. Mach. Theory 41 (2006) 247-261).

Cavitation is the half-Sommerfeld (Guembel) condition throughout: the pressure of the
full-film solution where it is positive, zero where it is negative. The forces are
integrated in closed form over the positive region with Sommerfeld's substitution
(:func:`sommerfeld_angle`), so they are exact for any combination of rotation and
squeeze, not only for the fixed half film ``0 < theta < pi`` of steady rotation.

Sources: [1]_, [2]_, [3]_, [4]_, [5]_.

References
----------
.. [1] F. W. Ocvirk, "Short-bearing approximation for full journal bearings",
   NACA TN 2808 (1952).
.. [2] A. Sommerfeld, "Zur hydrodynamischen Theorie der Schmiermittelreibung",
   Z. Math. Phys. 50 (1904) 97-155.
.. [3] O. Pinkus and B. Sternlicht, *Theory of Hydrodynamic Lubrication*, McGraw-Hill
   (1961).
.. [4] B. J. Hamrock, S. R. Schmid and B. O. Jacobson, *Fundamentals of Fluid Film
   Lubrication*, 2nd ed., Marcel Dekker (2004), ch. 10.
.. [5] P. Flores, J. Ambrosio, J. C. P. Claro, H. M. Lankarani and C. S. Koshy,
   "A study on dynamics of mechanical systems including joints with clearance and
   lubrication", Mech. Mach. Theory 41 (2006) 247-261.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import elementwise

__all__ = [
    "FilmForce",
    "film_thickness",
    "long_bearing_force",
    "long_shape_near_wall",
    "min_film_thickness",
    "short_bearing_force",
    "short_shape_scalar",
    "sommerfeld_angle",
    "to_xy",
    "wedge_speed",
]

FloatArray = NDArray[np.float64]

#: below this eccentricity ratio the squeeze terms of the long bearing use this value:
#: they are a difference of order-one terms divided by eps (finite as eps -> 0)
SMALLEST_ECCENTRICITY = 1e-8
#: cells of the film angle searched for the ends of the long bearing's positive film
LONG_BEARING_CELLS = 96
#: the long bearing's closed form down to this gap over the clearance; closer, its value
#: there in the wall's scaling (:func:`long_shape_near_wall`)
LONG_CLOSED_FORM_GAP = 1e-6


class FilmForce(NamedTuple):
    """The force of the film on the pin [N], in the line-of-centres frame.

    Attributes
    ----------
    radial : ndarray
        Component along the line of centres ``e_r`` [N]; negative pushes the pin
        back towards the bushing's centre.
    tangential : ndarray
        Component along ``e_t`` (``e_r`` turned by +90 degrees) [N].
    """

    radial: FloatArray
    tangential: FloatArray


def min_film_thickness(clearance: ArrayLike, eccentricity_ratio: ArrayLike) -> FloatArray:
    """Smallest film thickness ``h_min = c (1 - eps)`` [m].

    Parameters
    ----------
    clearance : array_like
        Radial clearance ``c`` [m].
    eccentricity_ratio : array_like
        ``eps = e / c`` [-].
    """
    return np.asarray(clearance, dtype=float) * (1.0 - np.asarray(eccentricity_ratio, float))


def film_thickness(
    clearance: ArrayLike, eccentricity_ratio: ArrayLike, film_angle: ArrayLike
) -> FloatArray:
    """Film thickness ``h = c (1 + eps cos theta)`` of a round pin in a round bushing [m].

    Parameters
    ----------
    clearance : array_like
        Radial clearance ``c`` [m].
    eccentricity_ratio : array_like
        ``eps = e / c`` [-].
    film_angle : array_like
        ``theta``, measured from the largest film [rad].
    """
    eps = np.asarray(eccentricity_ratio, dtype=float)
    return np.asarray(clearance, dtype=float) * (1.0 + eps * np.cos(film_angle))


def wedge_speed(
    pin_speed: ArrayLike, bushing_speed: ArrayLike = 0.0, line_of_centres_speed: ArrayLike = 0.0
) -> FloatArray:
    """Effective wedge speed ``omega_bar = omega_pin + omega_bushing - 2 dphi/dt`` [rad/s].

    Parameters
    ----------
    pin_speed : array_like
        Angular velocity of the pin [rad/s].
    bushing_speed : array_like
        Angular velocity of the bushing [rad/s].
    line_of_centres_speed : array_like
        ``dphi/dt``, the rate at which the line of centres (the eccentricity vector)
        turns [rad/s]; under a load turning steadily at ``omega_load`` the pin's centre
        follows it and this is ``omega_load``.

    Notes
    -----
    A pin whirling at half the sum of the two surface speeds carries no load: the
    wedge vanishes (half-frequency whirl; Pinkus & Sternlicht 1961).
    """
    pin = np.asarray(pin_speed, dtype=float)
    return pin + np.asarray(bushing_speed, float) - 2.0 * np.asarray(line_of_centres_speed, float)


def sommerfeld_angle(film_angle: ArrayLike, eccentricity_ratio: ArrayLike) -> FloatArray:
    """Sommerfeld's substitution angle ``gamma(theta)``, continuous over any number of turns.

    ``cos gamma = (eps + cos theta) / (1 + eps cos theta)``; with it
    ``d theta / (1 + eps cos theta) = d gamma / sqrt(1 - eps^2)``, which turns the film
    integrals of the journal bearing into trigonometric polynomials of ``gamma``.

    .. math:: \\gamma = \\theta - 2\\arctan\\frac{b\\sin\\theta}{1 + b\\cos\\theta},
              \\qquad b = \\frac{\\varepsilon}{1 + \\sqrt{1-\\varepsilon^2}}

    (the relation of true and eccentric anomaly of a Kepler orbit), which increases with
    ``theta`` and equals it at every multiple of ``pi``.

    Parameters
    ----------
    film_angle : array_like
        ``theta`` [rad].
    eccentricity_ratio : array_like
        ``eps`` in [0, 1) [-].
    """
    theta = np.asarray(film_angle, dtype=float)
    eps = np.asarray(eccentricity_ratio, dtype=float)
    b = eps / (1.0 + np.sqrt(1.0 - eps * eps))
    return theta - 2.0 * np.arctan(b * np.sin(theta) / (1.0 + b * np.cos(theta)))


def to_xy(force: FilmForce, line_of_centres_angle: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Rotate a force from the line-of-centres frame to the joint's x-y frame [N].

    Parameters
    ----------
    force : FilmForce
        Radial and tangential components [N].
    line_of_centres_angle : array_like
        ``phi``, the angle of ``e_r`` from the x axis [rad].

    Returns
    -------
    tuple of ndarray
        ``(F_x, F_y)`` [N].
    """
    cos_phi = np.cos(line_of_centres_angle)
    sin_phi = np.sin(line_of_centres_angle)
    radial, tangential = np.asarray(force.radial), np.asarray(force.tangential)
    return radial * cos_phi - tangential * sin_phi, radial * sin_phi + tangential * cos_phi


def short_bearing_force(
    radius: ArrayLike,
    length: ArrayLike,
    clearance: ArrayLike,
    viscosity: ArrayLike,
    eccentricity_ratio: ArrayLike,
    eccentricity_rate: ArrayLike,
    wedge_speed: ArrayLike,
) -> FilmForce:
    """Film force of the short bearing (Ocvirk), half-Sommerfeld cavitation [N].

    Dropping the circumferential flow (``L << D``) gives the pressure

    .. math::

        p = \\frac{3\\mu}{c^2}\\Big(\\frac{L^2}{4} - z^2\\Big)
            \\frac{\\bar\\omega\\varepsilon\\sin\\theta - 2\\dot\\varepsilon\\cos\\theta}
                 {(1 + \\varepsilon\\cos\\theta)^3},

    positive for ``theta`` in ``(theta_1, theta_1 + pi)`` with
    ``theta_1 = atan2(2 deps/dt, eps omega_bar)``; integrating it there,

    .. math::

        F_r = \\frac{\\mu R L^3}{2c^2}\\int_{\\theta_1}^{\\theta_1+\\pi}
              \\frac{(\\bar\\omega\\varepsilon\\sin\\theta
              - 2\\dot\\varepsilon\\cos\\theta)\\cos\\theta}
              {(1+\\varepsilon\\cos\\theta)^3}\\,d\\theta,

    and ``F_t`` the same with ``sin theta``. For steady rotation (``deps/dt = 0``) this
    is Ocvirk's ``F_r = -mu U L^3 eps^2 / (c^2 (1 - eps^2)^2)``,
    ``F_t = pi mu U L^3 eps / (4 c^2 (1 - eps^2)^1.5)`` with ``U = R omega_bar``.

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
        ``deps/dt`` [1/s]; positive moves the pin towards the wall.
    wedge_speed : array_like
        ``omega_bar = omega_pin + omega_bushing - 2 dphi/dt`` [rad/s]
        (:func:`wedge_speed`).

    Returns
    -------
    FilmForce
        Radial and tangential components on the pin [N].

    References
    ----------
    Ocvirk (1952); Hamrock, Schmid & Jacobson (2004), ch. 10; Flores et al. (2006).
    """
    eps = np.asarray(eccentricity_ratio, dtype=float)
    wedge = np.asarray(wedge_speed, dtype=float) * eps
    squeeze = 2.0 * np.asarray(eccentricity_rate, dtype=float)
    start = np.arctan2(squeeze, wedge)
    end = start + np.pi
    one_minus = 1.0 - eps * eps
    g0, g1 = sommerfeld_angle(start, eps), sommerfeld_angle(end, eps)

    def sin_sin(g: FloatArray) -> FloatArray:
        return (0.5 * g - 0.25 * np.sin(2.0 * g)) / one_minus**1.5

    def cos_cos(g: FloatArray) -> FloatArray:
        return ((0.5 + eps * eps) * g + 0.25 * np.sin(2.0 * g) - 2.0 * eps * np.sin(g)) / (
            one_minus**2.5
        )

    def sin_cos(g: FloatArray) -> FloatArray:
        return (0.5 * np.sin(g) ** 2 + eps * np.cos(g)) / one_minus**2

    scale = (
        np.asarray(viscosity, float)
        * np.asarray(radius, float)
        * np.asarray(length, float) ** 3
        / (2.0 * np.asarray(clearance, float) ** 2)
    )
    s_ss, s_cc, s_sc = (
        sin_sin(g1) - sin_sin(g0),
        cos_cos(g1) - cos_cos(g0),
        sin_cos(g1) - sin_cos(g0),
    )
    return FilmForce(
        scale * (wedge * s_sc - squeeze * s_cc), scale * (wedge * s_ss - squeeze * s_sc)
    )


def long_bearing_pressure_sign(
    film_angle: ArrayLike,
    eccentricity_ratio: ArrayLike,
    eccentricity_rate: ArrayLike,
    wedge: ArrayLike,
) -> FloatArray:
    """``(1 + eps cos theta)^2`` times the long bearing's full-film pressure over ``6 mu (R/c)^2``.

    Its sign is the sign of the pressure (:func:`long_bearing_force`).

    Parameters
    ----------
    film_angle : array_like
        ``theta`` [rad].
    eccentricity_ratio : array_like
        ``eps`` [-].
    eccentricity_rate : array_like
        ``deps/dt`` [1/s].
    wedge : array_like
        ``omega_bar`` [rad/s].
    """
    theta = np.asarray(film_angle, dtype=float)
    eps = np.asarray(eccentricity_ratio, dtype=float)
    cos_t = np.cos(theta)
    rotation = wedge * eps * np.sin(theta) * (2.0 + eps * cos_t) / (2.0 + eps * eps)
    squeeze = eccentricity_rate * (3.0 * eps - 4.0 * cos_t - 2.0 * eps * cos_t**2)
    return rotation + squeeze / (2.0 + 3.0 * eps * eps)


def long_bearing_antiderivatives(
    film_angle: FloatArray, eccentricity_ratio: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """Antiderivatives in ``theta`` of the long bearing's four force integrands.

    With ``H = 1 + eps cos theta``, ``S = sin theta (2 + eps cos theta) / H^2`` (rotation)
    and ``Q = 1 / H^2 - 2 / (2 + 3 eps^2)`` (squeeze), the four are those of
    ``S cos theta``, ``S sin theta``, ``Q cos theta`` and ``Q sin theta`` (constants
    dropped):

    .. math::

        -\\frac{\\cos^2\\theta}{H}, \\quad
        \\frac{\\gamma}{\\sqrt{1-\\varepsilon^2}} - \\frac{\\sin\\theta\\cos\\theta}{H}, \\quad
        \\frac{\\sin\\gamma - \\varepsilon\\gamma}{(1-\\varepsilon^2)^{3/2}}
          - K\\sin\\theta, \\quad
        -\\frac{\\cos\\theta}{H} + K\\cos\\theta

    with ``gamma`` of :func:`sommerfeld_angle` and ``K = 2 / (2 + 3 eps^2)``.

    Parameters
    ----------
    film_angle : ndarray
        ``theta`` [rad].
    eccentricity_ratio : ndarray
        ``eps`` [-].
    """
    eps = eccentricity_ratio
    cos_t, sin_t = np.cos(film_angle), np.sin(film_angle)
    film = 1.0 + eps * cos_t
    gamma = sommerfeld_angle(film_angle, eps)
    root = np.sqrt(1.0 - eps * eps)
    k = 2.0 / (2.0 + 3.0 * eps * eps)
    return (
        -(cos_t**2) / film,
        gamma / root - sin_t * cos_t / film,
        (np.sin(gamma) - eps * gamma) / root**3 - k * sin_t,
        -cos_t / film + k * cos_t,
    )


def positive_cells(
    eccentricity_ratio: FloatArray, eccentricity_rate: FloatArray, wedge: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Where the long bearing's full-film pressure is positive, cell by cell [rad].

    The turn is cut into :data:`LONG_BEARING_CELLS` cells; in each the positive part is
    the whole cell, none of it, or the part on one side of the one root of the pressure
    in the cell (found with :func:`scipy.optimize.elementwise.find_root`). A positive
    sliver narrower than a cell between two roots in one cell is missed; its force is
    of the order of the cell width cubed.

    Returns
    -------
    tuple of ndarray
        Start and end ``theta`` of the positive part of every cell, shape
        ``(..., LONG_BEARING_CELLS)`` [rad]; equal where the cell has none.
    """
    edges = np.linspace(0.0, 2.0 * np.pi, LONG_BEARING_CELLS + 1)
    args = (eccentricity_ratio[..., None], eccentricity_rate[..., None], wedge[..., None])
    sign = long_bearing_pressure_sign(edges, *args)
    left, right = edges[:-1] + 0.0 * sign[..., :-1], edges[1:] + 0.0 * sign[..., 1:]
    q_left, q_right = sign[..., :-1], sign[..., 1:]
    crossing = (q_left > 0.0) != (q_right > 0.0)
    root = left.copy()
    if np.any(crossing):
        index = np.nonzero(crossing)
        found = elementwise.find_root(
            long_bearing_pressure_sign,
            (left[index], right[index]),
            args=tuple(np.broadcast_to(a, crossing.shape)[index] for a in args),
        )
        root[index] = found.x
    start = np.where(q_left > 0.0, left, np.where(crossing, root, right))
    end = np.where(q_left > 0.0, np.where(crossing, root, right), right)
    return start, end


def long_bearing_force(
    radius: ArrayLike,
    length: ArrayLike,
    clearance: ArrayLike,
    viscosity: ArrayLike,
    eccentricity_ratio: ArrayLike,
    eccentricity_rate: ArrayLike,
    wedge_speed: ArrayLike,
) -> FilmForce:
    """Film force of the long bearing (Sommerfeld), half-Sommerfeld cavitation [N].

    Dropping the axial flow (``L >> D``), the full-film pressure is

    .. math::

        p = \\frac{6\\mu R^2}{c^2}\\Big[
            \\frac{\\bar\\omega\\varepsilon\\sin\\theta(2+\\varepsilon\\cos\\theta)}
                 {(2+\\varepsilon^2)(1+\\varepsilon\\cos\\theta)^2}
            + \\frac{\\dot\\varepsilon}{\\varepsilon}\\Big(
              \\frac{1}{(1+\\varepsilon\\cos\\theta)^2} - \\frac{2}{2+3\\varepsilon^2}\\Big)
            \\Big],

    Sommerfeld's solution with a squeeze term. Its constant makes
    ``oint h^3 p dtheta = 0``: the limit of a finite bearing with ambient pressure at
    both ends as ``L/D -> infinity`` (for pure rotation this is Sommerfeld's
    ``p(0) = 0``). The positive part is integrated in closed form
    (:func:`long_bearing_antiderivatives`) between the roots of ``p``
    (:func:`positive_cells`). For steady rotation this is the classical half-Sommerfeld
    result ``F_r = -12 mu U R^2 L eps^2 / (c^2 (2 + eps^2)(1 - eps^2))``,
    ``F_t = 6 pi mu U R^2 L eps / (c^2 (2 + eps^2) sqrt(1 - eps^2))``, ``U = R omega_bar``
    (Hamrock, Schmid & Jacobson 2004, ch. 8).

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
        ``deps/dt`` [1/s]; positive moves the pin towards the wall.
    wedge_speed : array_like
        ``omega_bar = omega_pin + omega_bushing - 2 dphi/dt`` [rad/s].

    Returns
    -------
    FilmForce
        Radial and tangential components on the pin [N].

    References
    ----------
    Sommerfeld (1904); Pinkus & Sternlicht (1961), ch. 3; Hamrock, Schmid & Jacobson
    (2004).
    """
    eps, rate, wedge = np.broadcast_arrays(
        np.maximum(np.asarray(eccentricity_ratio, float), SMALLEST_ECCENTRICITY),
        np.asarray(eccentricity_rate, float),
        np.asarray(wedge_speed, float),
    )
    start, end = positive_cells(eps, rate, wedge)
    at_end = long_bearing_antiderivatives(end, eps[..., None])
    at_start = long_bearing_antiderivatives(start, eps[..., None])
    rot_cos, rot_sin, sq_cos, sq_sin = (
        np.sum(a - b, axis=-1) for a, b in zip(at_end, at_start, strict=True)
    )
    rotation = wedge * eps / (2.0 + eps * eps)
    squeeze = rate / eps
    radius = np.asarray(radius, dtype=float)
    scale = 6.0 * np.asarray(viscosity, float) * radius**3 * np.asarray(length, float)
    scale = scale / np.asarray(clearance, float) ** 2
    return FilmForce(
        scale * (rotation * rot_cos + squeeze * sq_cos),
        scale * (rotation * rot_sin + squeeze * sq_sin),
    )


def short_shape_scalar(eps: float, beta: float, ratio: float) -> tuple[float, float]:
    """``G(eps, beta; L/D)`` of the short bearing for one state, with :mod:`math` [-].

    :func:`short_bearing_force` at ``R = c = 1``, ``mu = 1/6`` and unit motion in the
    direction ``beta`` (the film starts at ``theta_1 = beta``): the closed form of
    :func:`jointwear.lubrication.orbit.short_shape` without array overhead, plain
    enough for numba to compile (:mod:`jointwear.lubrication._orbit_kernel`).

    Parameters
    ----------
    eps : float
        Eccentricity ratio [-].
    beta : float
        Direction of the motion [rad].
    ratio : float
        ``L / D`` [-].
    """
    one_minus = 1.0 - eps * eps
    b = eps / (1.0 + math.sqrt(one_minus))
    sin_b, cos_b = math.sin(beta), math.cos(beta)
    g0 = beta - 2.0 * math.atan(b * sin_b / (1.0 + b * cos_b))
    g1 = beta + math.pi + 2.0 * math.atan(b * sin_b / (1.0 - b * cos_b))
    s0, s1 = math.sin(g0), math.sin(g1)
    d_sin2 = math.sin(2.0 * g1) - math.sin(2.0 * g0)
    sin_sin = (0.5 * (g1 - g0) - 0.25 * d_sin2) / one_minus**1.5
    cos_cos = ((0.5 + eps * eps) * (g1 - g0) + 0.25 * d_sin2 - 2.0 * eps * (s1 - s0)) / (
        one_minus**2.5
    )
    sin_cos = (0.5 * (s1 * s1 - s0 * s0) + eps * (math.cos(g1) - math.cos(g0))) / one_minus**2
    scale = 2.0 * ratio**3 / 3.0
    return (
        scale * (cos_b * sin_cos - sin_b * cos_cos),
        scale * (cos_b * sin_sin - sin_b * sin_cos),
    )


def long_shape_near_wall(
    eps: float, beta: float, ratio: float, force: Callable[..., tuple[float, float]]
) -> tuple[float, float]:
    """``G(eps, beta; L/D)`` of the long bearing from its scalar closed form ``force`` [-].

    ``force(R, L, c, mu, eps, deps/dt, omega_bar)`` at ``R = c = 1``, ``mu = 1/6`` and
    unit motion in the direction ``beta`` (``force`` is
    :func:`jointwear.mechanism.impact.film.long_bearing` in the orbit's Python path; its
    compiled kernel repeats these operations with the compiled force). Closer to the wall than
    :data:`LONG_CLOSED_FORM_GAP` of the clearance, where the closed form's
    antiderivatives cancel to round-off times ``(1 - eps^2)^-1.5``, the value there in
    the wall's scaling (:func:`jointwear.lubrication.mobility.to_wall`): at the same
    inner direction ``tan psi = tan beta / sqrt(1 - eps^2)``,

    .. math::

        G_r = \\frac{m'}{m'_w}\\Big(\\frac{1-\\varepsilon_w^2}{1-\\varepsilon^2}\\Big)^{3/2}
              G_{r,w}, \\qquad
        G_t = \\frac{m'}{m'_w}\\,\\frac{1-\\varepsilon_w^2}{1-\\varepsilon^2}\\, G_{t,w},

    the growth of Sommerfeld's film near the wall (squeeze ``(1 - eps^2)^-3/2``, wedge
    ``(1 - eps^2)^-1`` and ``^-1/2``; Hamrock, Schmid & Jacobson 2004, ch. 8 and 10).

    Parameters
    ----------
    eps : float
        Eccentricity ratio [-].
    beta : float
        Direction of the motion [rad].
    ratio : float
        ``L / D`` [-].
    force : callable
        The long bearing's scalar force [N] (module text).
    """
    if 1.0 - eps >= LONG_CLOSED_FORM_GAP:
        return force(
            1.0, 2.0 * ratio, 1.0, 1.0 / 6.0, eps, 0.5 * math.sin(beta), math.cos(beta) / eps
        )
    held = 1.0 - LONG_CLOSED_FORM_GAP
    one_minus, held_minus = 1.0 - eps * eps, 1.0 - held * held
    root, held_root = math.sqrt(one_minus), math.sqrt(held_minus)
    direction = math.atan2(held_root * math.sin(beta), root * math.cos(beta))
    size = math.hypot(root * math.cos(beta), math.sin(beta))
    held_size = math.hypot(held_root * math.cos(direction), math.sin(direction))
    radial, tangential = force(
        1.0,
        2.0 * ratio,
        1.0,
        1.0 / 6.0,
        held,
        0.5 * math.sin(direction),
        math.cos(direction) / held,
    )
    scale = size / held_size
    return (
        scale * radial * (held_minus / one_minus) ** 1.5,
        scale * tangential * (held_minus / one_minus),
    )
