r"""Kinematics of the ideal four-bar: coupler and rocker angles, rates and accelerations.

**Position** (closed form). With ``d = D - B``, ``r = |d|``, ``beta =
atan2(d_y, d_x)`` and the angle ``alpha`` at B of the triangle B-D-C,
``tan(alpha) = 4 Area / (l2^2 + r^2 - l3^2)`` (Heron's area, no ``arccos``)::

    theta_2 = beta + alpha    (open: C left of the directed line B -> D)
    theta_2 = beta - alpha    (crossed)
    theta_3 = theta_2 + mu,   mu = angle from e2 to (C - D)   (transmission angle)

For a crank-rocker ``d_x >= l0 - l1 > 0``, ``alpha`` stays in ``(0, pi)`` and
``mu`` never reaches ``0`` or ``pi``, so both angles are continuous functions of
``phi`` (no unwrapping); each is shifted by the whole turns that put its value at
``phi = 0`` in ``(-pi, pi]``. ``theta_3 - theta_s`` in the spring is taken on this
continuous branch, never wrapped.

**Velocity and acceleration**, from ``l1 e1 + l2 e2 - l3 e3 = D`` projected on
``e3`` and ``e2`` (``n_i . e_j = sin(theta_j - theta_i)``)::

    theta_2'  = -l1 omega sin(theta_3 - phi) / (l2 sin(theta_3 - theta_2))
    theta_3'  = -l1 omega sin(theta_2 - phi) / (l3 sin(theta_3 - theta_2))
    R         = l1 omega^2 e1 + l2 theta_2'^2 e2 - l3 theta_3'^2 e3
    theta_2'' = R . e3 / (l2 sin(theta_3 - theta_2))
    theta_3'' = R . e2 / (l3 sin(theta_3 - theta_2))
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError
from jointwear.geometry.angles import wrap_angle
from jointwear.mechanism.four_bar.geometry import FourBar, check_four_bar

__all__ = ["FourBarMotion", "four_bar_motion", "ideal_motion", "joint_positions"]

FloatArray = NDArray[np.float64]


class FourBarMotion(NamedTuple):
    """Motion of the ideal four-bar at a set of crank angles (constant crank speed).

    Attributes
    ----------
    crank_angle : ndarray
        ``phi`` [rad].
    crank_speed : float
        ``omega`` [rad/s].
    coupler_angle, coupler_angular_velocity, coupler_angular_acceleration : ndarray
        ``theta_2`` [rad], ``theta_2'`` [rad/s], ``theta_2''`` [rad/s^2].
    rocker_angle, rocker_angular_velocity, rocker_angular_acceleration : ndarray
        ``theta_3`` [rad], ``theta_3'`` [rad/s], ``theta_3''`` [rad/s^2].
    """

    crank_angle: FloatArray
    crank_speed: float
    coupler_angle: FloatArray
    coupler_angular_velocity: FloatArray
    coupler_angular_acceleration: FloatArray
    rocker_angle: FloatArray
    rocker_angular_velocity: FloatArray
    rocker_angular_acceleration: FloatArray


def _branch_shift(angle_at_zero: float) -> float:
    """Whole turns that move an angle into (-pi, pi] [rad]."""
    return 2.0 * math.pi * round(float(wrap_angle(angle_at_zero) - angle_at_zero) / (2 * math.pi))


def _raw_angles(
    phi: FloatArray, lengths: tuple[float, float, float, float], assembly: str
) -> tuple[FloatArray, FloatArray]:
    l0, l1, l2, l3 = lengths
    dx, dy = l0 - l1 * np.cos(phi), -l1 * np.sin(phi)
    r2 = dx * dx + dy * dy
    r = np.sqrt(r2)
    # 16 Area^2 of the triangle (l2, r, l3), Heron's formula in a factored form
    area4 = np.sqrt(np.maximum((l2 + r + l3) * (-l2 + r + l3) * (l2 - r + l3) * (l2 + r - l3), 0.0))
    alpha = np.arctan2(area4, l2 * l2 + r2 - l3 * l3)
    beta = np.arctan2(dy, dx)
    theta2 = beta + alpha if assembly == "open" else beta - alpha
    cx = l1 * np.cos(phi) + l2 * np.cos(theta2) - l0
    cy = l1 * np.sin(phi) + l2 * np.sin(theta2)
    theta3 = theta2 + wrap_angle(np.arctan2(cy, cx) - theta2)
    return theta2, theta3


def four_bar_motion(
    crank_angle: ArrayLike,
    ground_length: float,
    crank_length: float,
    coupler_length: float,
    rocker_length: float,
    crank_speed: float,
    assembly: str = "open",
) -> FourBarMotion:
    """Closed-form motion of the ideal four-bar (module docstring).

    Parameters
    ----------
    crank_angle : array_like
        Crank angle ``phi`` [rad].
    ground_length : float
        ``l0`` [m].
    crank_length : float
        ``l1`` [m].
    coupler_length : float
        ``l2`` [m].
    rocker_length : float
        ``l3`` [m].
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    assembly : {"open", "crossed"}
        Assembly branch.

    Returns
    -------
    FourBarMotion
    """
    check_four_bar(ground_length, crank_length, coupler_length, rocker_length)
    if assembly not in ("open", "crossed"):
        raise ConfigError(f"mechanism.assembly: {assembly!r} is not 'open' or 'crossed'")
    lengths = (ground_length, crank_length, coupler_length, rocker_length)
    phi = np.asarray(crank_angle, dtype=float)
    theta2, theta3 = _raw_angles(phi, lengths, assembly)
    zero2, zero3 = _raw_angles(np.zeros(1), lengths, assembly)
    theta2 = theta2 + _branch_shift(float(zero2[0]))
    theta3 = theta3 + _branch_shift(float(zero3[0]))

    l1, l2, l3, w = crank_length, coupler_length, rocker_length, float(crank_speed)
    sin_mu = np.sin(theta3 - theta2)
    theta2_dot = -l1 * w * np.sin(theta3 - phi) / (l2 * sin_mu)
    theta3_dot = -l1 * w * np.sin(theta2 - phi) / (l3 * sin_mu)
    # R . e3 and R . e2 with R = l1 w^2 e1 + l2 theta2'^2 e2 - l3 theta3'^2 e3
    cos_mu = np.cos(theta3 - theta2)
    r_e3 = l1 * w * w * np.cos(phi - theta3) + l2 * theta2_dot**2 * cos_mu - l3 * theta3_dot**2
    r_e2 = l1 * w * w * np.cos(phi - theta2) + l2 * theta2_dot**2 - l3 * theta3_dot**2 * cos_mu
    return FourBarMotion(
        crank_angle=phi,
        crank_speed=w,
        coupler_angle=theta2,
        coupler_angular_velocity=theta2_dot,
        coupler_angular_acceleration=r_e3 / (l2 * sin_mu),
        rocker_angle=theta3,
        rocker_angular_velocity=theta3_dot,
        rocker_angular_acceleration=r_e2 / (l3 * sin_mu),
    )


def joint_positions(motion: FourBarMotion, linkage: FourBar) -> dict[str, FloatArray]:
    """Positions of the joint centres ``A``, ``B``, ``C`` (via B) and ``D``, shape (N, 2) [m].

    Parameters
    ----------
    motion : FourBarMotion
        Motion (angles are used).
    linkage : FourBar
        Lengths.
    """
    phi = np.asarray(motion.crank_angle, dtype=float)
    theta2 = np.asarray(motion.coupler_angle, dtype=float)
    b = linkage.crank_length * np.stack((np.cos(phi), np.sin(phi)), axis=-1)
    c = b + linkage.coupler_length * np.stack((np.cos(theta2), np.sin(theta2)), axis=-1)
    return {
        "A": np.zeros_like(b),
        "B": b,
        "C": c,
        "D": np.broadcast_to(np.array([linkage.ground_length, 0.0]), b.shape).copy(),
    }


def ideal_motion(linkage: FourBar, crank_speed: float, steps: int) -> FourBarMotion:
    """Motion of the ideal linkage at the crank angles ``2 pi k / N`` of one revolution.

    Parameters
    ----------
    linkage : FourBar
        Lengths and assembly.
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    steps : int
        Steps ``N`` per revolution [-].
    """
    phi = 2.0 * np.pi * np.arange(steps) / steps
    return four_bar_motion(phi, *linkage.lengths, crank_speed, linkage.assembly)
