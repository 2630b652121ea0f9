r"""Kinematics of the slider-crank: the ideal mechanism and the clearance link (eq. 10).

Geometry and sign conventions (paper Fig. 6, all angles counter-clockwise from
the global x axis, gravity along -y):

* crank AB, length ``l1``, pivot A at the origin, crank angle ``phi_1 = omega t``
  (constant ``omega``): ``B = l1 (cos phi_1, sin phi_1)``;
* connecting rod BC, length ``l2``, angle ``theta_2`` (:func:`rod_angle`); the
  paper's ``phi_2`` in eqs. (10)-(11) is measured the other way,
  ``phi_2 = -theta_2``;
* slider on the x axis; the bushing-side joint centre D moves with it at
  ``(x_3, 0)``; C is the joint centre on the rod end;
* ``J`` is the force the rod end exerts on the slider through the joint; the
  rod feels ``-J``. The slider guide takes all y forces on the slider.

Without clearance C = D and ``x_3 = l1 cos phi_1 + sqrt(l2^2 - l1^2 sin^2 phi_1)``.

With the clearance as a massless link CD of length ``e`` along the load direction
(:func:`clearance_motion`, eq. 10), closure of the loop A-B-C-D gives the rod angle
and slider position. The clearance correction of the geometry is periodic in the crank angle, so its
time derivatives are taken spectrally (:func:`spectral_derivative`) on top of the
closed-form derivatives of the ideal mechanism; no finite differences are used.
The correction is treated as band-limited to the harmonics the ideal load
carries (see
:func:`~jointwear.mechanism.slider_crank.massless_link.solve_massless_link` for why this
matters).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import MechanismError

__all__ = [
    "SliderCrankMotion",
    "clearance_motion",
    "crank_angle_grid",
    "ideal_motion",
    "load_bandwidth",
    "rod_angle",
    "rod_angular_acceleration",
    "rod_angular_velocity",
    "slider_acceleration",
    "slider_position",
    "slider_velocity",
    "spectral_derivative",
]

FloatArray = NDArray[np.float64]


class SliderCrankMotion(NamedTuple):
    """Motion of the mechanism at a set of crank angles (constant crank speed).

    Attributes
    ----------
    crank_angle : ndarray
        Crank angle ``phi_1`` [rad].
    crank_speed : float
        Crank angular velocity ``omega`` [rad/s].
    rod_angle, rod_angular_velocity, rod_angular_acceleration : ndarray
        ``theta_2`` [rad], its first [rad/s] and second [rad/s^2] time derivatives.
    slider_position, slider_velocity, slider_acceleration : ndarray
        ``x_3`` [m], its first [m/s] and second [m/s^2] time derivatives.
    """

    crank_angle: FloatArray
    crank_speed: float
    rod_angle: FloatArray
    rod_angular_velocity: FloatArray
    rod_angular_acceleration: FloatArray
    slider_position: FloatArray
    slider_velocity: FloatArray
    slider_acceleration: FloatArray


# ------------------------------------------------------- ideal kinematics


def crank_angle_grid(steps: int) -> FloatArray:
    """Crank angles ``2 pi k / N``, ``k = 0, 1, ..., N-1``, of one revolution [rad].

    Parameters
    ----------
    steps : int
        Number of time steps ``N`` per revolution [-].
    """
    if steps < 2:
        raise ValueError(f"steps must be >= 2, got {steps}")
    return 2.0 * np.pi * np.arange(steps) / steps


def _rod_cosine(crank_angle: FloatArray, ratio: float) -> FloatArray:
    # cos(theta_2) = sqrt(1 - lambda^2 sin^2 phi_1) > 0: the rod points from B towards
    # the slider side (+x) because l1 < l2
    return np.sqrt(1.0 - (ratio * np.sin(crank_angle)) ** 2)


def rod_angle(crank_angle: ArrayLike, crank_length: float, rod_length: float) -> FloatArray:
    """Rod angle of the ideal mechanism, ``theta_2 = -arcsin(l1 sin(phi_1) / l2)`` [rad].

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi_1`` [rad].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].

    Returns
    -------
    ndarray
        Angle of B->C, counter-clockwise from +x, in (-pi/2, pi/2) [rad].
    """
    phi = np.asarray(crank_angle, dtype=float)
    return np.arcsin(-crank_length / rod_length * np.sin(phi))


def rod_angular_velocity(
    crank_angle: ArrayLike, crank_length: float, rod_length: float, crank_speed: float
) -> FloatArray:
    """Rod angular velocity of the ideal mechanism [rad/s].

    ``theta_2' = -lambda omega cos(phi_1) / cos(theta_2)``, ``lambda = l1 / l2``.

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi_1`` [rad].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    """
    phi = np.asarray(crank_angle, dtype=float)
    ratio = crank_length / rod_length
    return -ratio * crank_speed * np.cos(phi) / _rod_cosine(phi, ratio)


def rod_angular_acceleration(
    crank_angle: ArrayLike, crank_length: float, rod_length: float, crank_speed: float
) -> FloatArray:
    """Rod angular acceleration of the ideal mechanism [rad/s^2].

    ``theta_2'' = lambda omega^2 (1 - lambda^2) sin(phi_1) / cos^3(theta_2)``.

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi_1`` [rad].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    """
    phi = np.asarray(crank_angle, dtype=float)
    ratio = crank_length / rod_length
    return ratio * crank_speed**2 * (1.0 - ratio**2) * np.sin(phi) / _rod_cosine(phi, ratio) ** 3


def slider_position(crank_angle: ArrayLike, crank_length: float, rod_length: float) -> FloatArray:
    """Slider position of the ideal mechanism [m].

    ``x_3 = l1 cos(phi_1) + sqrt(l2^2 - l1^2 sin^2(phi_1))``.

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi_1`` [rad].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    """
    phi = np.asarray(crank_angle, dtype=float)
    return crank_length * np.cos(phi) + rod_length * _rod_cosine(phi, crank_length / rod_length)


def slider_velocity(
    crank_angle: ArrayLike, crank_length: float, rod_length: float, crank_speed: float
) -> FloatArray:
    """Slider velocity of the ideal mechanism [m/s].

    ``x_3' = -l1 omega sin(phi_1) (1 + lambda cos(phi_1) / cos(theta_2))``.

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi_1`` [rad].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    """
    phi = np.asarray(crank_angle, dtype=float)
    ratio = crank_length / rod_length
    return (
        -crank_length
        * crank_speed
        * np.sin(phi)
        * (1.0 + ratio * np.cos(phi) / _rod_cosine(phi, ratio))
    )


def slider_acceleration(
    crank_angle: ArrayLike, crank_length: float, rod_length: float, crank_speed: float
) -> FloatArray:
    """Slider acceleration of the ideal mechanism [m/s^2].

    ``x_3'' = -l1 omega^2 [cos(phi_1) + lambda (cos(2 phi_1) + lambda^2 sin^4(phi_1))
    / cos^3(theta_2)]``; at the dead centres ``-l1 omega^2 (1 + lambda)`` (``phi_1 = 0``)
    and ``l1 omega^2 (1 - lambda)`` (``phi_1 = pi``).

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi_1`` [rad].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    """
    phi = np.asarray(crank_angle, dtype=float)
    ratio = crank_length / rod_length
    bracket = np.cos(2.0 * phi) + ratio**2 * np.sin(phi) ** 4
    return (
        -crank_length
        * crank_speed**2
        * (np.cos(phi) + ratio * bracket / _rod_cosine(phi, ratio) ** 3)
    )


def ideal_motion(
    crank_angle: ArrayLike, crank_length: float, rod_length: float, crank_speed: float
) -> SliderCrankMotion:
    """Closed-form motion of the slider-crank without clearance.

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi_1`` [rad].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    """
    phi = np.asarray(crank_angle, dtype=float)
    args = (phi, crank_length, rod_length, crank_speed)
    return SliderCrankMotion(
        crank_angle=phi,
        crank_speed=float(crank_speed),
        rod_angle=rod_angle(phi, crank_length, rod_length),
        rod_angular_velocity=rod_angular_velocity(*args),
        rod_angular_acceleration=rod_angular_acceleration(*args),
        slider_position=slider_position(phi, crank_length, rod_length),
        slider_velocity=slider_velocity(*args),
        slider_acceleration=slider_acceleration(*args),
    )


# ------------------------------------------------------- the clearance link


def spectral_derivative(
    samples: ArrayLike,
    angular_frequency: float,
    order: int = 1,
    max_harmonic: int | None = None,
) -> FloatArray:
    """Time derivative of a periodic signal sampled uniformly over one period.

    Exact (to round-off) for a signal band-limited to the retained harmonics.

    Parameters
    ----------
    samples : array_like, shape (..., N)
        Signal values at ``t_k = k T / N``, ``k = 0, 1, ..., N-1``, along the last axis.
    angular_frequency : float
        ``2 pi / T`` of the period ``T`` [rad/s].
    order : int
        Order of the derivative (>= 0) [-].
    max_harmonic : int, optional
        Treat the signal as band-limited to harmonics ``0 .. max_harmonic`` and
        drop the rest; default: all harmonics up to ``N // 2`` [-].

    Returns
    -------
    ndarray, shape (..., N)
        ``d^order / dt^order`` of the samples [unit of samples / s^order].
    """
    values = np.asarray(samples, dtype=float)
    if order < 0:
        raise ValueError(f"order must be >= 0, got {order}")
    if order == 0 and max_harmonic is None:
        return values.copy()
    n = values.shape[-1]
    harmonics = np.arange(n // 2 + 1)
    factor = (1j * angular_frequency * harmonics) ** order
    if n % 2 == 0 and order % 2 == 1:
        # the Nyquist harmonic of a real signal has no defined phase: its odd
        # derivatives are set to zero (the usual choice, keeps the result real)
        factor[-1] = 0.0
    if max_harmonic is not None:
        factor[harmonics > max_harmonic] = 0.0
    return np.fft.irfft(np.fft.rfft(values, axis=-1) * factor, n=n, axis=-1)


def load_bandwidth(force_x: ArrayLike, force_y: ArrayLike, floor: float = 1e-15) -> int:
    """Highest harmonic of the crank frequency that a periodic load carries.

    Parameters
    ----------
    force_x, force_y : array_like, shape (N,)
        Load components over one revolution, uniformly sampled [N].
    floor : float
        Harmonics whose amplitude is at most ``floor`` times the largest one are
        round-off [-].

    Returns
    -------
    int
        The largest harmonic number above the floor [-].
    """
    spectrum = np.abs(np.fft.rfft(np.asarray(force_x, dtype=float))) + np.abs(
        np.fft.rfft(np.asarray(force_y, dtype=float))
    )
    above = np.flatnonzero(spectrum > floor * spectrum.max())
    return int(above.max()) if above.size else 0


def clearance_motion(
    force_angle: ArrayLike,
    clearance: float,
    crank_length: float,
    rod_length: float,
    crank_speed: float,
    max_harmonic: int | None = None,
) -> SliderCrankMotion:
    """Motion with the clearance link along a given load direction (eq. 10).

    The samples are the crank angles ``2 pi k / N`` of one revolution
    (:func:`crank_angle_grid`), ``N = len(force_angle)``. Loop closure with
    ``C - D = e (cos gamma_J, sin gamma_J)``::

        l1 sin(phi_1) + l2 sin(theta_2) = e sin(gamma_J)
        x_3 = l1 cos(phi_1) + l2 cos(theta_2) - e cos(gamma_J)

    Derivatives are the closed-form ideal ones plus the spectral derivatives of
    the periodic correction.

    Parameters
    ----------
    force_angle : array_like, shape (N,)
        Direction ``gamma_J`` of ``J`` (force of the rod on the slider) at each
        step, counter-clockwise from +x [rad]. The paper's ``gamma`` is
        ``gamma_J + pi``.
    clearance : float
        Radial clearance ``e`` (length of the link CD) [m].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    max_harmonic : int, optional
        Band limit of the correction's derivatives (:func:`spectral_derivative`) [-].
    """
    gamma = np.asarray(force_angle, dtype=float)
    phi = crank_angle_grid(gamma.size)
    ideal = ideal_motion(phi, crank_length, rod_length, crank_speed)
    if clearance == 0.0:
        return ideal
    n_x, n_y = np.cos(gamma), np.sin(gamma)
    sin_t = (clearance * n_y - crank_length * np.sin(phi)) / rod_length
    if np.any(np.abs(sin_t) >= 1.0):
        raise MechanismError(
            f"joint.clearance: the mechanism cannot assemble: crank_length ({crank_length:g} m)"
            f" + clearance ({clearance:g} m) must be < rod_length ({rod_length:g} m)"
        )
    theta = np.arctan2(sin_t, np.sqrt(1.0 - sin_t**2))
    # corrections in a cancellation-free form, exact for any e:
    # sin(theta) - sin(theta_i) = 2 cos(mean) sin(delta / 2) = e n_y / l2, and
    # l2 (cos(theta) - cos(theta_i)) = -2 l2 sin(mean) sin(delta / 2)
    mean = 0.5 * (theta + ideal.rod_angle)
    half_sine = clearance * n_y / (2.0 * rod_length * np.cos(mean))
    delta_theta = 2.0 * np.arcsin(half_sine)
    delta_x = -clearance * (n_y * np.tan(mean) + n_x)

    def derivative(samples: FloatArray, order: int) -> FloatArray:
        return spectral_derivative(samples, crank_speed, order, max_harmonic)

    return SliderCrankMotion(
        crank_angle=phi,
        crank_speed=float(crank_speed),
        rod_angle=ideal.rod_angle + delta_theta,
        rod_angular_velocity=ideal.rod_angular_velocity + derivative(delta_theta, 1),
        rod_angular_acceleration=ideal.rod_angular_acceleration + derivative(delta_theta, 2),
        slider_position=ideal.slider_position + delta_x,
        slider_velocity=ideal.slider_velocity + derivative(delta_x, 1),
        slider_acceleration=ideal.slider_acceleration + derivative(delta_x, 2),
    )
