r"""Slider-crank mechanism with a clearance joint between rod and slider (paper section 3.1).

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

**Massless-link model** (paper eqs. 10-12). The clearance is a massless link CD of
length ``e`` (the radial clearance). Under the continuous-contact hypothesis the
pin rests on the bushing wall in the direction of the load, so ``C - D = e n``
with ``n = J / |J|`` (this holds whichever body carries the bushing: with the
bushing in the rod, the pin on the slider presses on it with ``-J`` and the
bushing centre C sits at ``e n`` from the pin centre D). Closure of the loop
A-B-C-D, eq. (10), gives the rod angle and slider position for a given load
direction; the inverse dynamics then gives the load for that geometry. Both are
iterated to a fixed point (:func:`solve_massless_link`). The paper's ``gamma``
(direction of the link from C to D in eq. 10) is the direction of ``-J``.

The clearance correction of the geometry is periodic in the crank angle, so its
time derivatives are taken spectrally (:func:`spectral_derivative`) on top of the
closed-form derivatives of the ideal mechanism; no finite differences are used.
The correction is treated as band-limited to the harmonics the ideal load
carries (see :func:`solve_massless_link` for why this matters).

**Inverse dynamics** (:func:`inverse_dynamics`, our form of eq. 11):

* slider, x: ``m3 x3'' = J_x + F_spring``;
* rod, moment about B (B accelerates, so the moment of the rod's inertia
  force ``m2 a_G`` about B enters): with ``r = C - B``, ``G = B + r/2``,
  ``-r x J - (r/2) x (m2 g y) = I2 theta_2'' + (r/2) x (m2 a_G)`` (2-D cross
  product ``a x b = a_x b_y - a_y b_x``), solved for ``J_y``;
* crank, moment about A at constant ``omega``: ``T = B x R_B + m1 g B_x / 2``
  with ``R_B = m2 (a_G + g y) + J`` the force of the crank on the rod.

**Spring** (:func:`spring_force`): stiffness ``K_s``; its reference positions are
the dead centres of the ideal mechanism, ``x_max = l1 + l2`` and
``x_min = l2 - l1``, so ``spring_preload`` is the smallest spring force over
the ideal stroke (see docs/reading-the-paper.md).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ContactLossWarning, ConvergenceError, MechanismError
from jointwear.mechanism.cycle import Diagnostic, LoadCycle, bushing_azimuth, crank_extras

if TYPE_CHECKING:
    from jointwear.config import Config, SliderCrankConfig

__all__ = [
    "JointReaction",
    "MasslessLinkSolution",
    "SliderCrank",
    "SliderCrankMotion",
    "bushing_frame",
    "clearance_motion",
    "contact_loss",
    "crank_angle_grid",
    "ideal_motion",
    "inverse_dynamics",
    "load_bandwidth",
    "massless_link_load",
    "rod_angle",
    "rod_angular_acceleration",
    "rod_angular_velocity",
    "slider_acceleration",
    "slider_crank_cycle",
    "slider_position",
    "slider_velocity",
    "solve_massless_link",
    "spectral_derivative",
    "spring_force",
]

FloatArray = NDArray[np.float64]
SpringMode = Literal["pull", "push"]


# ------------------------------------------------------------------ parameters


@dataclass(frozen=True)
class SliderCrank:
    """Mass, length and spring data of the slider-crank (paper Table 1, SI).

    Parameters
    ----------
    crank_length : float
        Crank length ``l1`` (A to B) [m].
    rod_length : float
        Connecting-rod length ``l2`` (B to C) [m].
    crank_mass : float
        Crank mass ``m1``, centre of mass at the crank's mid-length [kg].
    rod_mass : float
        Rod mass ``m2``, centre of mass at the rod's mid-length [kg].
    slider_mass : float
        Slider mass ``m3`` (with the bushing or pin it carries) [kg].
    rod_inertia : float
        Rod moment of inertia ``I2`` about its centre of mass [kg m^2].
    spring_stiffness : float
        Spring stiffness ``K_s`` [N/m].
    spring_preload : float
        Smallest spring force over the ideal stroke [N]. The paper gives neither
        preload nor sense; the ``nlcp-paper`` parameter set uses 20 N, pull.
    spring_mode : {"pull", "push"}
        ``"pull"`` (default): the spring pulls the slider away from the crank
        (+x) and the rod is in tension, which gives the paper's trend "faster
        crank, more wear"; ``"push"``: it pushes the slider towards the crank and
        the rod is in compression (the opposite trend).
    gravity : float
        Gravitational acceleration, acting along -y [m/s^2].
    """

    crank_length: float
    rod_length: float
    crank_mass: float
    rod_mass: float
    slider_mass: float
    rod_inertia: float
    spring_stiffness: float
    spring_preload: float
    spring_mode: SpringMode = "pull"
    gravity: float = 9.81

    def __post_init__(self) -> None:
        if not 0.0 < self.crank_length < self.rod_length:
            raise MechanismError(
                f"mechanism.crank_length: the slider-crank needs 0 < crank_length "
                f"({self.crank_length:g} m) < rod_length ({self.rod_length:g} m)"
            )
        if self.spring_mode not in ("pull", "push"):
            raise MechanismError(
                f"mechanism.spring_mode: {self.spring_mode!r} is not 'pull' or 'push'"
            )

    @classmethod
    def from_config(cls, mechanism: SliderCrankConfig) -> SliderCrank:
        """Build from the ``[mechanism]`` section of a configuration.

        Parameters
        ----------
        mechanism : jointwear.config.SliderCrankConfig
            Validated ``[mechanism]`` section (SI values); the rod inertia is
            ``rod_centroidal_inertia`` (``m2 l2^2 / 12`` unless given).
        """
        return cls(
            crank_length=mechanism.crank_length,
            rod_length=mechanism.rod_length,
            crank_mass=mechanism.crank_mass,
            rod_mass=mechanism.rod_mass,
            slider_mass=mechanism.slider_mass,
            rod_inertia=mechanism.rod_centroidal_inertia,
            spring_stiffness=mechanism.spring_stiffness,
            spring_preload=mechanism.spring_preload,
            spring_mode=mechanism.spring_mode,
            gravity=mechanism.gravity,
        )


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


class JointReaction(NamedTuple):
    """Joint force and driving torque from :func:`inverse_dynamics`.

    Attributes
    ----------
    force_x, force_y : ndarray
        Components of ``J``, the force of the rod end on the slider [N].
    crank_torque : ndarray
        Driving torque on the crank, counter-clockwise positive [N m].
    """

    force_x: FloatArray
    force_y: FloatArray
    crank_torque: FloatArray


class MasslessLinkSolution(NamedTuple):
    """Self-consistent motion and load of the massless-link model.

    Attributes
    ----------
    motion : SliderCrankMotion
        Motion with the clearance link along the load.
    reaction : JointReaction
        Joint force and crank torque for that motion.
    iterations : int
        Geometry updates used by the fixed point (0 without clearance).
    bandwidth : int
        Highest harmonic of the crank frequency kept in the clearance
        correction's derivatives [-].
    """

    motion: SliderCrankMotion
    reaction: JointReaction
    iterations: int
    bandwidth: int


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
    return (
        ratio * crank_speed**2 * (1.0 - ratio**2) * np.sin(phi) / _rod_cosine(phi, ratio) ** 3
    )


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
        -crank_length * crank_speed * np.sin(phi)
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
        -crank_length * crank_speed**2
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


# ------------------------------------------------------------ dynamics


def spring_force(
    slider_position: ArrayLike,
    crank_length: float,
    rod_length: float,
    stiffness: float,
    preload: float,
    mode: SpringMode = "pull",
) -> FloatArray:
    """Spring force on the slider along +x [N].

    ``"pull"``: ``+(preload + K_s (x_max - x_3))``, ``x_max = l1 + l2`` (the far dead
    centre); ``"push"``: ``-(preload + K_s (x_3 - x_min))``, ``x_min = l2 - l1``.
    Either way the magnitude is ``preload`` at one dead centre of the ideal stroke
    and grows linearly towards the other.

    Parameters
    ----------
    slider_position : array_like
        Slider position ``x_3`` [m].
    crank_length : float
        Crank length ``l1`` [m].
    rod_length : float
        Rod length ``l2`` [m].
    stiffness : float
        Spring stiffness ``K_s`` [N/m].
    preload : float
        Smallest spring force over the ideal stroke [N].
    mode : {"pull", "push"}
        Sense of the spring (see :class:`SliderCrank`).
    """
    x = np.asarray(slider_position, dtype=float)
    if mode == "pull":
        return preload + stiffness * (crank_length + rod_length - x)
    if mode == "push":
        return -(preload + stiffness * (x - (rod_length - crank_length)))
    raise MechanismError(f"mechanism.spring_mode: {mode!r} is not 'pull' or 'push'")


def inverse_dynamics(motion: SliderCrankMotion, mechanism: SliderCrank) -> JointReaction:
    """Joint force and crank torque that produce a given motion.

    Parameters
    ----------
    motion : SliderCrankMotion
        Prescribed motion; the rod end C is at ``B + l2 (cos theta_2, sin theta_2)``
        and the slider at ``x_3`` (they differ by the clearance link, if any).
    mechanism : SliderCrank
        Masses, lengths, spring and gravity.

    Returns
    -------
    JointReaction
        ``J`` (force of the rod on the slider) [N] and the crank torque [N m].

    Notes
    -----
    Slider: ``J_x = m3 x3'' - F_spring``. Rod, moments about B with
    ``r = C - B``::

        r_x J_y = r_y J_x - I2 theta'' - (m2 / 2) [r_x (a_Gy + g) - r_y a_Gx]

    Crank (constant ``omega``, so its own inertia needs no torque)::

        T = B_x R_By - B_y R_Bx + m1 g B_x / 2,   R_B = m2 (a_G + g y) + J

    The paper's eq. (11) is the rod equation with ``F = -J`` and ``phi_2 = -theta_2``;
    see the package documentation for the differences.
    """
    m = mechanism
    phi = np.asarray(motion.crank_angle, dtype=float)
    omega = motion.crank_speed
    theta = np.asarray(motion.rod_angle, dtype=float)
    theta_dot = np.asarray(motion.rod_angular_velocity, dtype=float)
    theta_ddot = np.asarray(motion.rod_angular_acceleration, dtype=float)

    cos_phi, sin_phi = np.cos(phi), np.sin(phi)
    cos_t, sin_t = np.cos(theta), np.sin(theta)
    # crank pin B and its (centripetal only) acceleration
    b_x, b_y = m.crank_length * cos_phi, m.crank_length * sin_phi
    ab_x, ab_y = -omega**2 * b_x, -omega**2 * b_y
    # rod vector r = C - B and the rod's centre-of-mass acceleration a_G = a_B + r''/2
    r_x, r_y = m.rod_length * cos_t, m.rod_length * sin_t
    rdd_x = -r_y * theta_ddot - r_x * theta_dot**2
    rdd_y = r_x * theta_ddot - r_y * theta_dot**2
    ag_x, ag_y = ab_x + 0.5 * rdd_x, ab_y + 0.5 * rdd_y

    f_spring = spring_force(
        motion.slider_position, m.crank_length, m.rod_length,
        m.spring_stiffness, m.spring_preload, m.spring_mode,
    )
    force_x = m.slider_mass * np.asarray(motion.slider_acceleration, dtype=float) - f_spring
    force_y = (
        r_y * force_x
        - m.rod_inertia * theta_ddot
        - 0.5 * m.rod_mass * (r_x * (ag_y + m.gravity) - r_y * ag_x)
    ) / r_x
    # force of the crank on the rod at B (rod's Newton equation)
    rb_x = m.rod_mass * ag_x + force_x
    rb_y = m.rod_mass * (ag_y + m.gravity) + force_y
    torque = b_x * rb_y - b_y * rb_x + 0.5 * m.crank_mass * m.gravity * b_x
    return JointReaction(force_x=force_x, force_y=force_y, crank_torque=torque)


# ------------------------------------------------------------ clearance


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


def solve_massless_link(
    mechanism: SliderCrank,
    crank_speed: float,
    clearance: float,
    steps: int,
    tolerance: float = 1e-12,
    max_iterations: int = 50,
    scheme: Literal["fixed-point", "paper"] = "fixed-point",
) -> MasslessLinkSolution:
    """Load and geometry of the massless-link model, iterated to a fixed point.

    Start from the load of the ideal mechanism, place the clearance link along
    it (eq. 10), recompute the load for that geometry (eq. 11) and repeat until
    the load changes by at most ``tolerance * max|J|`` at every step. The
    paper's scheme is the first pass of this loop.

    Parameters
    ----------
    mechanism : SliderCrank
        Mechanism data.
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    clearance : float
        Radial clearance ``e`` (``0`` gives the ideal mechanism) [m].
    steps : int
        Time steps ``N`` per revolution [-].
    tolerance : float
        Relative tolerance of the fixed point on the load vector [-].
    max_iterations : int
        Largest number of geometry updates [-].
    scheme : {"fixed-point", "paper"}
        ``"fixed-point"`` iterates to self-consistency; ``"paper"`` stops after
        one geometry update (link along the ideal load, paper section 3.1).

    Returns
    -------
    MasslessLinkSolution

    Raises
    ------
    ConvergenceError
        If the fixed point is not reached within ``max_iterations``.

    Notes
    -----
    The link direction is a degree of freedom with its own dynamics: the pin
    can swing along the bushing wall like a pendulum held by the load, with
    ``omega_n^2 ~ |J| / (m_eff e)``. A perturbation of harmonic ``m`` of the
    crank frequency comes back multiplied by about ``(m omega / omega_n)^2``, so
    the plain iteration amplifies round-off in harmonics above ``omega_n /
    omega`` (for the paper's mechanism at 240 rpm and 0.2 mm clearance that is
    harmonic ~50, inside the 180 a 360-step grid resolves) and ends on a
    spurious pin flutter. The load of the ideal mechanism is band-limited (its
    harmonics fall below round-off by about the 20th), so the correction is
    differentiated as a signal band-limited to the ideal load's harmonics
    (:func:`load_bandwidth`), which keeps the physical solution and drops the
    noise. If ``omega_n`` itself falls inside that band, the clearance mode is
    excited, the continuous-contact model breaks down and the iteration
    diverges (``ConvergenceError``).
    """
    if clearance < 0.0:
        raise MechanismError(f"joint.clearance: must be >= 0, got {clearance:g} m")
    phi = crank_angle_grid(steps)
    motion = ideal_motion(phi, mechanism.crank_length, mechanism.rod_length, crank_speed)
    reaction = inverse_dynamics(motion, mechanism)
    bandwidth = load_bandwidth(reaction.force_x, reaction.force_y)
    if clearance == 0.0:
        return MasslessLinkSolution(motion, reaction, 0, bandwidth)
    if scheme not in ("fixed-point", "paper"):
        raise ValueError(f"unknown scheme {scheme!r}; choose 'fixed-point' or 'paper'")
    change = math.inf
    for iteration in range(1, max_iterations + 1):
        motion = clearance_motion(
            np.arctan2(reaction.force_y, reaction.force_x), clearance,
            mechanism.crank_length, mechanism.rod_length, crank_speed, bandwidth,
        )
        updated = inverse_dynamics(motion, mechanism)
        scale = float(np.max(np.hypot(updated.force_x, updated.force_y)))
        change = float(np.max(np.hypot(updated.force_x - reaction.force_x,
                                       updated.force_y - reaction.force_y)))
        reaction = updated
        if scheme == "paper" or change <= tolerance * scale:
            return MasslessLinkSolution(motion, reaction, iteration, bandwidth)
    raise ConvergenceError(
        f"dynamics.max_iterations: the massless-link force/geometry iteration did not "
        f"converge in {max_iterations} iterations (last change {change:.3g} N, "
        f"dynamics.fixed_point_tolerance = {tolerance:g} relative); a large clearance, "
        f"high crank speed or small load lets the pin swing in the clearance at a "
        f"frequency the load excites, outside the continuous-contact model"
    )


def contact_loss(
    motion: SliderCrankMotion, reaction: JointReaction, spring_mode: SpringMode
) -> NDArray[np.bool_]:
    """Steps where the joint force reverses relative to the rod.

    The massless-link model holds only while the axial component of the joint
    force keeps the sense the spring gives it: ``"pull"`` keeps the rod in
    tension (the force on the slider points from C towards B,
    ``J . (B - C) > 0``), ``"push"`` keeps it in compression (``J . (B - C) < 0``).

    Parameters
    ----------
    motion : SliderCrankMotion
        Motion (its rod angle is used).
    reaction : JointReaction
        Joint force of that motion.
    spring_mode : {"pull", "push"}
        Sense of the spring.

    Returns
    -------
    ndarray of bool
        True where the model's continuous-contact assumption fails.
    """
    theta = np.asarray(motion.rod_angle, dtype=float)
    # J . (B - C) / l2: component of J along the rod, towards the crank pin
    towards_crank = -(reaction.force_x * np.cos(theta) + reaction.force_y * np.sin(theta))
    if spring_mode == "pull":
        return towards_crank <= 0.0
    return towards_crank >= 0.0


def _angle_ranges(indices: NDArray[np.int64], steps: int) -> str:
    """``"0-12, 350-359"``: runs of consecutive steps as crank angles in degrees."""
    if indices.size == 0:
        return ""
    breaks = np.flatnonzero(np.diff(indices) != 1)
    starts = np.concatenate(([indices[0]], indices[breaks + 1]))
    ends = np.concatenate((indices[breaks], [indices[-1]]))
    to_deg = 360.0 / steps
    parts = [
        f"{s * to_deg:.4g}" if s == e else f"{s * to_deg:.4g}-{e * to_deg:.4g}"
        for s, e in zip(starts, ends, strict=True)
    ]
    return ", ".join(parts)


def _contact_loss_message(lost: NDArray[np.bool_], spring_mode: SpringMode) -> str:
    indices = np.flatnonzero(lost)
    state = "tension" if spring_mode == "pull" else "compression"
    return (
        f"dynamics.model: the massless-link model assumes continuous contact, but the joint "
        f"force reverses relative to the rod (spring_mode={spring_mode!r} needs the rod in "
        f"{state}) at {indices.size} of {lost.size} steps, crank angles "
        f"{_angle_ranges(indices, lost.size)} deg; raise mechanism.spring_preload or "
        f"lower mechanism.crank_speed"
    )


def bushing_frame(
    force_x: ArrayLike,
    force_y: ArrayLike,
    rod_angle: ArrayLike,
    rod_increment: ArrayLike,
    bushing_body: str,
) -> tuple[FloatArray, FloatArray]:
    """Load azimuth and relative rotation in the frame of the body carrying the bushing.

    Parameters
    ----------
    force_x, force_y : array_like
        Global components of ``J``, the force the rod's pin exerts on the slider [N].
    rod_angle : array_like
        Rod angle at each step [rad].
    rod_increment : array_like
        Rod angle increment over each step [rad].
    bushing_body : {"slider", "rod"}
        Body that carries the bushing.

    Returns
    -------
    azimuth : ndarray
        Direction in which the pin presses on the bushing, unwrapped and shifted by
        whole turns so that its mean lies in (-pi, pi] [rad].
    relative_rotation : ndarray
        Increment of ``phi_pin - phi_bushing`` over each step [rad].
    """
    fx, fy = np.asarray(force_x, dtype=float), np.asarray(force_y, dtype=float)
    increment = np.asarray(rod_increment, dtype=float)
    if bushing_body == "slider":
        # the bushing does not rotate; the pin turns with the rod
        return bushing_azimuth(fx, fy), increment
    # bushing in the rod end, pin on the slider: the pin presses on it with -J,
    # seen in the rod's frame; phi_pin - phi_bushing = 0 - theta_2
    return bushing_azimuth(-fx, -fy, np.asarray(rod_angle, dtype=float)), -increment


def slider_crank_cycle(
    config: Config,
    force_x: FloatArray,
    force_y: FloatArray,
    rod_angle: FloatArray,
    rod_increment: FloatArray,
    slider_position: FloatArray,
    crank_torque: FloatArray,
    normal_x: FloatArray | None = None,
    normal_y: FloatArray | None = None,
    **fields,
) -> LoadCycle:
    """A slider-crank's load cycle in the bushing frame, its own series as diagnostics.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[mechanism]`` (``crank_speed``, ``bushing_body``).
    force_x, force_y : ndarray, shape (N,)
        Global components of ``J``, the force of the rod end on the slider [N].
    rod_angle, rod_increment : ndarray, shape (N,)
        Rod angle and its increment over each step [rad].
    slider_position : ndarray, shape (N,)
        Slider position ``x_3`` [m].
    crank_torque : ndarray, shape (N,)
        Crank driving torque [N m].
    normal_x, normal_y : ndarray, optional
        Direction of the contact normal if not along ``J`` (contact-impact) [-].
    **fields
        Further :class:`~jointwear.mechanism.cycle.LoadCycle` fields.
    """
    mech = config.mechanism
    steps = force_x.size
    nx = force_x if normal_x is None else normal_x
    ny = force_y if normal_y is None else normal_y
    azimuth, relative_rotation = bushing_frame(nx, ny, rod_angle, rod_increment, mech.bushing_body)
    load = fields.pop("load", None)
    diagnostics = {
        "crank_torque": Diagnostic(crank_torque, "N m", "crank driving torque"),
        "slider_position": Diagnostic(slider_position, "m", "slider position x_3"),
        "rod_angle": Diagnostic(rod_angle, "rad", "connecting-rod angle"),
        "global_force_x": Diagnostic(force_x, "N", "x force of the rod end on the slider"),
        "global_force_y": Diagnostic(force_y, "N", "y force of the rod end on the slider"),
    }
    lost = np.zeros(steps, bool) if fields.get("lost_steps") is None else fields["lost_steps"]
    extras = {
        "bushing_body": mech.bushing_body,
        "spring_mode": mech.spring_mode,
        **crank_extras(mech.crank_speed, crank_torque, lost),
    }
    return LoadCycle(
        time=mech.period * np.arange(steps) / steps,
        load=np.hypot(force_x, force_y) if load is None else load,
        azimuth=azimuth,
        relative_rotation=relative_rotation,
        period=mech.period,
        mechanism="slider-crank",
        joint="rod-slider",
        diagnostics=diagnostics,
        extras=extras,
        **fields,
    )


def massless_link_load(config: Config) -> LoadCycle:
    """Joint load over one revolution from the massless-link model (eqs. 10-12).

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[mechanism]``, ``joint.clearance``, ``[dynamics]`` and
        ``simulation.steps_per_revolution``.

    Returns
    -------
    LoadCycle
        Load, its azimuth in the frame of ``mechanism.bushing_body`` and the
        relative rotation of pin and bushing per step.

    Warns
    -----
    ContactLossWarning
        If the joint force reverses relative to the rod somewhere (the result
        is then outside the model's validity).

    Raises
    ------
    MechanismError
        Instead of the warning when ``dynamics.strict`` is true.
    ConvergenceError
        If the force/geometry fixed point does not converge.
    """
    mechanism = SliderCrank.from_config(config.mechanism)
    omega = config.mechanism.crank_speed
    steps = config.simulation.steps_per_revolution
    spring_mode = mechanism.spring_mode
    strict = config.dynamics.strict

    # the ideal mechanism first: if its load reverses, the clearance iteration may
    # not converge (the pin would jump across the clearance), so report that first
    ideal = solve_massless_link(mechanism, omega, 0.0, steps)
    ideal_lost = contact_loss(ideal.motion, ideal.reaction, spring_mode)
    if ideal_lost.any() and strict:
        raise MechanismError(_contact_loss_message(ideal_lost, spring_mode))
    converged = True
    fallback = ""
    try:
        solution = solve_massless_link(
            mechanism, omega, config.joint.clearance, steps,
            tolerance=config.dynamics.fixed_point_tolerance,
            max_iterations=config.dynamics.max_iterations,
            scheme=config.dynamics.scheme,
        )
    except ConvergenceError:
        if not ideal_lost.any():
            raise
        # where the load reverses, the pin would have to jump across the clearance
        # and no continuous-contact fixed point exists; the user asked for a
        # warning, not an error, so give the paper's one-pass answer, flagged
        converged = False
        fallback = (
            "; the force/geometry fixed point does not converge, so the paper's "
            "one-pass scheme (clearance link along the ideal load) is reported"
        )
        solution = solve_massless_link(
            mechanism, omega, config.joint.clearance, steps, scheme="paper"
        )
    lost = contact_loss(solution.motion, solution.reaction, spring_mode)
    if not converged:
        lost |= ideal_lost
    if lost.any():
        message = _contact_loss_message(lost, spring_mode) + fallback
        if strict:
            raise MechanismError(message)
        warnings.warn(message, ContactLossWarning, stacklevel=2)

    motion, reaction = solution.motion, solution.reaction
    theta = motion.rod_angle
    return slider_crank_cycle(
        config,
        reaction.force_x,
        reaction.force_y,
        theta,
        # exact increment of the rod angle over each step (periodic: step N-1 ends at step 0)
        np.roll(theta, -1) - theta,
        motion.slider_position,
        reaction.crank_torque,
        model="massless-link",
        lost_steps=lost,
        iterations=solution.iterations,
        converged=converged,
    )
