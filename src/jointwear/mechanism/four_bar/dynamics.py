r"""Inverse dynamics of the ideal four-bar: the joint reactions and the crank torque.

**Inverse dynamics with ideal joints** (:func:`inverse_dynamics`). Unknowns:
``F_A`` (ground on crank at A), ``F_B`` (crank on coupler at B), ``F_C``
(coupler on rocker at C), ``F_D`` (ground on rocker at D) and the driving torque
``T`` on the crank (counter-clockwise positive). Newton-Euler per link, with
``g = (0, -g)`` and moments about each centre of mass G_i::

    crank:    F_A - F_B + m1 g = m1 a_G1,   (A-G1) x F_A - (B-G1) x F_B + T = 0
    coupler:  F_B - F_C + m2 g = m2 a_G2,   (B-G2) x F_B - (C-G2) x F_C = I2 theta_2''
    rocker:   F_C + F_D + m3 g = m3 a_G3,   (C-G3) x F_C + (D-G3) x F_D + M_r = I3 theta_3''

nine linear equations per step, solved as one stacked ``(N, 9, 9)`` system.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError
from jointwear.mechanism.four_bar.geometry import FourBar
from jointwear.mechanism.four_bar.kinematics import FourBarMotion, joint_positions

__all__ = ["FourBarReaction", "cross", "inverse_dynamics", "joint_force", "rocker_load_torque"]

FloatArray = NDArray[np.float64]


class FourBarReaction(NamedTuple):
    """Ideal-joint reactions and driving torque from :func:`inverse_dynamics`.

    Each force has shape ``(N, 2)`` (global x, y) [N].

    Attributes
    ----------
    ground_on_crank : ndarray
        ``F_A``, force of the ground on the crank at A [N].
    crank_on_coupler : ndarray
        ``F_B``, force of the crank on the coupler at B [N].
    coupler_on_rocker : ndarray
        ``F_C``, force of the coupler on the rocker at C [N].
    ground_on_rocker : ndarray
        ``F_D``, force of the ground on the rocker at D [N].
    crank_torque : ndarray
        Driving torque on the crank, counter-clockwise positive [N m].
    """

    ground_on_crank: FloatArray
    crank_on_coupler: FloatArray
    coupler_on_rocker: FloatArray
    ground_on_rocker: FloatArray
    crank_torque: FloatArray


def rocker_load_torque(rocker_angle: ArrayLike, linkage: FourBar) -> FloatArray:
    """Load torque on the rocker about D, ``tau - k_s (theta_3 - theta_s)`` [N m].

    Parameters
    ----------
    rocker_angle : array_like
        ``theta_3`` on its continuous branch (not wrapped) [rad].
    linkage : FourBar
        Torque and spring data.
    """
    theta3 = np.asarray(rocker_angle, dtype=float)
    return linkage.rocker_torque - linkage.rocker_spring_stiffness * (
        theta3 - linkage.rocker_spring_angle
    )


def cross(r: ArrayLike, f: ArrayLike) -> FloatArray:
    """2-D cross product ``r x f = r_x f_y - r_y f_x`` over the last axis [unit r * unit f].

    Parameters
    ----------
    r, f : array_like, shape (..., 2)
        Vectors, e.g. an arm [m] and a force [N].
    """
    r, f = np.asarray(r), np.asarray(f)
    return r[..., 0] * f[..., 1] - r[..., 1] * f[..., 0]


def inverse_dynamics(motion: FourBarMotion, linkage: FourBar) -> FourBarReaction:
    """Ideal-joint reactions and crank torque that produce a motion (module docstring).

    Parameters
    ----------
    motion : FourBarMotion
        Motion of the ideal linkage.
    linkage : FourBar
        Masses, inertias, gravity and rocker load.

    Returns
    -------
    FourBarReaction
        ``F_A``, ``F_B``, ``F_C``, ``F_D`` [N] and ``T`` [N m].
    """
    phi = np.atleast_1d(np.asarray(motion.crank_angle, dtype=float))
    t2, t2d, t2dd = (
        np.atleast_1d(np.asarray(v, dtype=float))
        for v in (
            motion.coupler_angle,
            motion.coupler_angular_velocity,
            motion.coupler_angular_acceleration,
        )
    )
    t3, t3d, t3dd = (
        np.atleast_1d(np.asarray(v, dtype=float))
        for v in (
            motion.rocker_angle,
            motion.rocker_angular_velocity,
            motion.rocker_angular_acceleration,
        )
    )
    pos = joint_positions(motion._replace(crank_angle=phi, coupler_angle=t2), linkage)
    accelerations = _centre_accelerations(
        motion.crank_speed, linkage, pos["B"], (t2, t2d, t2dd), (t3, t3d, t3dd)
    )
    mat, rhs = _newton_euler(linkage, pos, accelerations, t2dd, t3, t3dd)
    x = np.linalg.solve(mat, rhs[..., None])[..., 0]
    return FourBarReaction(
        ground_on_crank=x[:, 0:2],
        crank_on_coupler=x[:, 2:4],
        coupler_on_rocker=x[:, 4:6],
        ground_on_rocker=x[:, 6:8],
        crank_torque=x[:, 8],
    )


def _centre_accelerations(
    crank_speed: float,
    linkage: FourBar,
    b: FloatArray,
    coupler: tuple[FloatArray, FloatArray, FloatArray],
    rocker: tuple[FloatArray, FloatArray, FloatArray],
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Accelerations of the centres of mass of crank, coupler and rocker, (N, 2) [m/s^2].

    ``coupler`` and ``rocker`` are each link's angle [rad], rate [rad/s] and
    acceleration [rad/s^2]; ``b`` is the crank pin B [m].
    """
    w = crank_speed
    (t2, t2d, t2dd), (t3, t3d, t3dd) = coupler, rocker
    _, _, l2, l3 = linkage.lengths

    def unit(theta: FloatArray) -> FloatArray:
        return np.stack((np.cos(theta), np.sin(theta)), axis=-1)

    def normal(theta: FloatArray) -> FloatArray:
        return np.stack((-np.sin(theta), np.cos(theta)), axis=-1)

    a_b = -(w * w) * b  # crank pin: centripetal only (constant omega)
    a_g1 = 0.5 * a_b
    a_g2 = a_b + 0.5 * l2 * (t2dd[:, None] * normal(t2) - (t2d**2)[:, None] * unit(t2))
    a_g3 = 0.5 * l3 * (t3dd[:, None] * normal(t3) - (t3d**2)[:, None] * unit(t3))
    return a_g1, a_g2, a_g3


def _newton_euler(
    linkage: FourBar,
    pos: dict[str, FloatArray],
    accelerations: tuple[FloatArray, FloatArray, FloatArray],
    t2dd: FloatArray,
    t3: FloatArray,
    t3dd: FloatArray,
) -> tuple[FloatArray, FloatArray]:
    """The nine Newton-Euler equations per step (module docstring), ``(N, 9, 9)``, ``(N, 9)``.

    Unknowns in the columns: ``F_A`` (0, 1), ``F_B`` (2, 3), ``F_C`` (4, 5), ``F_D``
    (6, 7), ``T`` (8).
    """
    m1, m2, m3 = linkage.crank_mass, linkage.coupler_mass, linkage.rocker_mass
    a, b, c, d = pos["A"], pos["B"], pos["C"], pos["D"]
    a_g1, a_g2, a_g3 = accelerations
    g1, g2, g3 = 0.5 * b, 0.5 * (b + c), 0.5 * (c + d)
    gravity = np.array([0.0, -linkage.gravity])

    n = b.shape[0]
    mat = np.zeros((n, 9, 9))
    rhs = np.zeros((n, 9))
    eye = np.eye(2)

    def moment_row(row: int, col: int, arm: FloatArray, sign: float) -> None:
        # (arm x F) = arm_x F_y - arm_y F_x for F the unknown in columns col, col+1
        mat[:, row, col] = -sign * arm[:, 1]
        mat[:, row, col + 1] = sign * arm[:, 0]

    mat[:, 0:2, 0:2] = eye
    mat[:, 0:2, 2:4] = -eye
    rhs[:, 0:2] = m1 * (a_g1 - gravity)
    moment_row(2, 0, a - g1, 1.0)
    moment_row(2, 2, b - g1, -1.0)
    mat[:, 2, 8] = 1.0
    mat[:, 3:5, 2:4] = eye
    mat[:, 3:5, 4:6] = -eye
    rhs[:, 3:5] = m2 * (a_g2 - gravity)
    moment_row(5, 2, b - g2, 1.0)
    moment_row(5, 4, c - g2, -1.0)
    rhs[:, 5] = linkage.coupler_inertia * t2dd
    mat[:, 6:8, 4:6] = eye
    mat[:, 6:8, 6:8] = eye
    rhs[:, 6:8] = m3 * (a_g3 - gravity)
    moment_row(8, 4, c - g3, 1.0)
    moment_row(8, 6, d - g3, 1.0)
    rhs[:, 8] = linkage.rocker_inertia * t3dd - rocker_load_torque(t3, linkage)
    return mat, rhs


def joint_force(reaction: FourBarReaction, joint: str) -> FloatArray:
    """``J``: force of the joint's first body on its second, shape (N, 2) [N].

    Parameters
    ----------
    reaction : FourBarReaction
        Ideal-joint reactions.
    joint : {"crank-coupler", "coupler-rocker", "rocker-ground"}
        The joint.
    """
    if joint == "crank-coupler":
        return reaction.crank_on_coupler
    if joint == "coupler-rocker":
        return reaction.coupler_on_rocker
    if joint == "rocker-ground":
        return -reaction.ground_on_rocker
    raise ConfigError(f"mechanism.clearance_joint: unknown four-bar joint {joint!r}")
