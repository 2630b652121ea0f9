r"""Crank-rocker four-bar linkage with a clearance in one or more of its moving joints.

Geometry and sign conventions (all angles counter-clockwise from the global x
axis, gravity along -y, 2-D cross product ``a x b = a_x b_y - a_y b_x``):

* ground pivots ``A = (0, 0)`` (crank) and ``D = (l0, 0)`` (rocker);
* crank AB, length ``l1``, angle ``phi = omega t`` (constant ``omega > 0``):
  ``B = l1 e1``, ``e_i = (cos theta_i, sin theta_i)``, ``n_i = (-sin theta_i,
  cos theta_i)``, ``theta_1 = phi``;
* coupler BC, length ``l2``, angle ``theta_2``: ``C = B + l2 e2``;
* rocker DC, length ``l3``, angle ``theta_3`` (of D -> C): ``C = D + l3 e3``;
* centres of mass at the link midpoints, centroidal inertias ``I_i``;
* load on the rocker about D, counter-clockwise positive:
  ``M_r = tau - k_s (theta_3 - theta_s)`` (``rocker_torque``, torsional spring
  ``rocker_spring_stiffness`` towards ``rocker_spring_angle``).

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

**Inverse dynamics with ideal joints** (:func:`inverse_dynamics`). Unknowns:
``F_A`` (ground on crank at A), ``F_B`` (crank on coupler at B), ``F_C``
(coupler on rocker at C), ``F_D`` (ground on rocker at D) and the driving torque
``T`` on the crank (counter-clockwise positive). Newton-Euler per link, with
``g = (0, -g)`` and moments about each centre of mass G_i::

    crank:    F_A - F_B + m1 g = m1 a_G1,   (A-G1) x F_A - (B-G1) x F_B + T = 0
    coupler:  F_B - F_C + m2 g = m2 a_G2,   (B-G2) x F_B - (C-G2) x F_C = I2 theta_2''
    rocker:   F_C + F_D + m3 g = m3 a_G3,   (C-G3) x F_C + (D-G3) x F_D + M_r = I3 theta_3''

nine linear equations per step, solved as one stacked ``(N, 9, 9)`` system.

**Joint force and load cycle.** Each joint joins a *first* and a *second* body
(``crank-coupler``, ``coupler-rocker``, ``rocker-ground``); ``J`` is the force the
first exerts on the second: ``F_B``, ``F_C`` and ``-F_D``. The pin presses on the
bushing with ``J`` if the bushing is on the second body, with ``-J`` if on the
first. The relative rotation of a step is ``Delta theta_pin - Delta theta_bushing``
(``theta`` of the ground is 0; the crank turns ``2 pi`` per revolution).

**Massless-link model.** As for the slider-crank, the clearance joint's load is the
ideal-joint reaction; the clearance changes the geometry by ``O(c / l)`` only,
which is neglected here (the slider-crank iterates it to a fixed point, the
four-bar does not).

**Contact-impact model** (:class:`FourBarContactSystem`). One joint has
clearance; the crank stays kinematically driven, and the coupler and rocker
angles ``q = (theta_2, theta_3)`` become free. Every point of the coupler and the
rocker is ``P = base(t) + L2 e2 + L3 e3`` with ``base`` = B or D; the clearance
vector (pin-centre offset, first body's joint centre minus the second's) is, for
every choice of joint, the loop-closure residual::

    e = B + l2 e2 - D - l3 e3

and the equations of motion follow from virtual power,
``M(q) q'' = sum_b J_b^T m_b (g - a_b^0) + (0, M_r) + Q_contact`` with
``M = sum_b m_b J_b^T J_b + diag(I2, I3)``, ``J_b`` the Jacobian of the centre of
mass of body b with respect to ``q'`` and ``a_b^0`` its acceleration at ``q'' = 0``.
The contact force (:class:`~jointwear.mechanism.force_laws.JointContact`) acts
on the second body with ``J`` and on the first with ``-J``, both at the contact
point ``P = C_1 + rho n``.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError, ContactLossWarning, MechanismError
from jointwear.mechanism.cycle import (
    Diagnostic,
    LoadCycle,
    bushing_azimuth,
    crank_extras,
    wrap_angle,
)
from jointwear.mechanism.impact_integrator import ContactSystemBase

if TYPE_CHECKING:
    from jointwear.config import Config, FourBarConfig
    from jointwear.mechanism.contact_impact import ContactImpactSolution
    from jointwear.mechanism.force_laws import JointContact

__all__ = [
    "FourBar",
    "FourBarContactSystem",
    "FourBarMotion",
    "FourBarReaction",
    "check_four_bar",
    "four_bar_contact_impact",
    "four_bar_cycles",
    "four_bar_motion",
    "inverse_dynamics",
    "joint_force",
    "joint_positions",
    "rocker_load_torque",
]

FloatArray = NDArray[np.float64]

#: the two bodies of each joint (first, second); ``J`` acts on the second
JOINT_BODIES: dict[str, tuple[str, str]] = {
    "crank-coupler": ("crank", "coupler"),
    "coupler-rocker": ("coupler", "rocker"),
    "rocker-ground": ("rocker", "ground"),
}

#: relative tolerance of the change-point test ``s + l == p + q``
_CHANGE_POINT = 1e-12


# ------------------------------------------------------------------ validation


def check_four_bar(ground: float, crank: float, coupler: float, rocker: float) -> None:
    """Check that the crank of the four-bar can turn full revolutions.

    Parameters
    ----------
    ground : float
        Ground length ``l0`` (A to D) [m].
    crank : float
        Crank length ``l1`` (A to B) [m].
    coupler : float
        Coupler length ``l2`` (B to C) [m].
    rocker : float
        Rocker length ``l3`` (D to C) [m].

    Raises
    ------
    ConfigError
        One line naming the key and the failed condition: the crank is not the
        shortest link; Grashof's condition ``s + l <= p + q`` fails; the linkage is
        a change-point one (``s + l == p + q``, it passes through a singular
        flattened position and may switch assembly); or B - D leaves
        ``[|l2 - l3|, l2 + l3]`` at some crank angle (cannot assemble).
    """
    lengths = {"ground": ground, "crank": crank, "coupler": coupler, "rocker": rocker}
    for name, value in lengths.items():
        if not (math.isfinite(value) and value > 0.0):
            raise ConfigError(f"mechanism.{name}_length: must be > 0, got {value!r}")
    shortest = min(lengths.values())
    if crank > shortest:
        other = min((v, k) for k, v in lengths.items() if k != "crank")[1]
        raise ConfigError(
            f"mechanism.crank_length: the crank ({crank:g} m) must be the shortest link to turn "
            f"a full revolution, but {other}_length is {lengths[other]:g} m"
        )
    s, longest = crank, max(lengths.values())
    rest = sum(lengths.values()) - s - longest
    if s + longest > rest * (1.0 + _CHANGE_POINT):
        raise ConfigError(
            f"mechanism.crank_length: Grashof's condition s + l <= p + q fails "
            f"({s:g} + {longest:g} = {s + longest:g} m > {rest:g} m), so the crank cannot turn "
            f"a full revolution"
        )
    if s + longest >= rest * (1.0 - _CHANGE_POINT):
        raise ConfigError(
            f"mechanism.crank_length: change-point linkage, s + l = p + q ({s:g} + {longest:g} "
            f"= {rest:g} m): it passes through a flattened, singular position where the "
            f"assembly can switch; not supported"
        )
    # |B - D| runs over [l0 - l1, l0 + l1] as the crank turns (l0 >= l1 here)
    low, high = ground - crank, ground + crank
    if not abs(coupler - rocker) < low:
        raise ConfigError(
            f"mechanism.coupler_length: the linkage cannot assemble at crank angle 0: "
            f"|B - D| = {low:g} m must exceed |coupler_length - rocker_length| = "
            f"{abs(coupler - rocker):g} m"
        )
    if not high < coupler + rocker:
        raise ConfigError(
            f"mechanism.coupler_length: the linkage cannot assemble at crank angle 180 deg: "
            f"|B - D| = {high:g} m must be below coupler_length + rocker_length = "
            f"{coupler + rocker:g} m"
        )


# ------------------------------------------------------------------ parameters


@dataclass(frozen=True)
class FourBar:
    """Lengths, inertia and load data of the four-bar (SI).

    Parameters
    ----------
    ground_length : float
        Ground length ``l0`` (A to D) [m].
    crank_length : float
        Crank length ``l1`` (A to B) [m].
    coupler_length : float
        Coupler length ``l2`` (B to C) [m].
    rocker_length : float
        Rocker length ``l3`` (D to C) [m].
    crank_mass, coupler_mass, rocker_mass : float
        Link masses, centres of mass at the midpoints [kg].
    crank_inertia, coupler_inertia, rocker_inertia : float
        Centroidal moments of inertia [kg m^2].
    gravity : float
        Gravitational acceleration along -y [m/s^2].
    rocker_torque : float
        Constant torque on the rocker about D, counter-clockwise positive [N m].
    rocker_spring_stiffness : float
        Torsional spring on the rocker [N m/rad].
    rocker_spring_angle : float
        Rocker angle at which the spring is relaxed [rad].
    assembly : {"open", "crossed"}
        Open: C left of the directed line B -> D; crossed: right of it.
    """

    ground_length: float
    crank_length: float
    coupler_length: float
    rocker_length: float
    crank_mass: float = 0.0
    coupler_mass: float = 0.0
    rocker_mass: float = 0.0
    crank_inertia: float = 0.0
    coupler_inertia: float = 0.0
    rocker_inertia: float = 0.0
    gravity: float = 9.81
    rocker_torque: float = 0.0
    rocker_spring_stiffness: float = 0.0
    rocker_spring_angle: float = 0.0
    assembly: str = "open"

    def __post_init__(self) -> None:
        check_four_bar(
            self.ground_length, self.crank_length, self.coupler_length, self.rocker_length
        )
        if self.assembly not in ("open", "crossed"):
            raise ConfigError(f"mechanism.assembly: {self.assembly!r} is not 'open' or 'crossed'")

    @classmethod
    def from_config(cls, mechanism: FourBarConfig) -> FourBar:
        """Build from the validated ``[mechanism]`` section (inertias resolved).

        Parameters
        ----------
        mechanism : jointwear.config.FourBarConfig
            The four-bar section (SI values).
        """
        return cls(
            ground_length=mechanism.ground_length,
            crank_length=mechanism.crank_length,
            coupler_length=mechanism.coupler_length,
            rocker_length=mechanism.rocker_length,
            crank_mass=mechanism.crank_mass,
            coupler_mass=mechanism.coupler_mass,
            rocker_mass=mechanism.rocker_mass,
            crank_inertia=mechanism.inertia("crank"),
            coupler_inertia=mechanism.inertia("coupler"),
            rocker_inertia=mechanism.inertia("rocker"),
            gravity=mechanism.gravity,
            rocker_torque=mechanism.rocker_torque,
            rocker_spring_stiffness=mechanism.rocker_spring_stiffness,
            rocker_spring_angle=mechanism.rocker_spring_angle,
            assembly=mechanism.assembly,
        )

    @property
    def lengths(self) -> tuple[float, float, float, float]:
        """``(l0, l1, l2, l3)`` [m]."""
        return self.ground_length, self.crank_length, self.coupler_length, self.rocker_length


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


# ------------------------------------------------------------------ kinematics


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


# ------------------------------------------------------------------ dynamics


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


def _cross(r: FloatArray, f: FloatArray) -> FloatArray:
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
    w = motion.crank_speed
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
    _, _, l2, l3 = linkage.lengths
    m1, m2, m3 = linkage.crank_mass, linkage.coupler_mass, linkage.rocker_mass
    pos = joint_positions(motion._replace(crank_angle=phi, coupler_angle=t2), linkage)
    a, b, c, d = pos["A"], pos["B"], pos["C"], pos["D"]

    def unit(theta: FloatArray) -> FloatArray:
        return np.stack((np.cos(theta), np.sin(theta)), axis=-1)

    def normal(theta: FloatArray) -> FloatArray:
        return np.stack((-np.sin(theta), np.cos(theta)), axis=-1)

    a_b = -(w * w) * b  # crank pin: centripetal only (constant omega)
    a_g1 = 0.5 * a_b
    a_g2 = a_b + 0.5 * l2 * (t2dd[:, None] * normal(t2) - (t2d**2)[:, None] * unit(t2))
    a_g3 = 0.5 * l3 * (t3dd[:, None] * normal(t3) - (t3d**2)[:, None] * unit(t3))
    g1, g2, g3 = 0.5 * b, 0.5 * (b + c), 0.5 * (c + d)
    gravity = np.array([0.0, -linkage.gravity])

    n = phi.size
    mat = np.zeros((n, 9, 9))
    rhs = np.zeros((n, 9))
    eye = np.eye(2)

    def moment_row(row: int, col: int, arm: FloatArray, sign: float) -> None:
        # (arm x F) = arm_x F_y - arm_y F_x for F the unknown in columns col, col+1
        mat[:, row, col] = -sign * arm[:, 1]
        mat[:, row, col + 1] = sign * arm[:, 0]

    # columns: F_A (0,1), F_B (2,3), F_C (4,5), F_D (6,7), T (8)
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
    x = np.linalg.solve(mat, rhs[..., None])[..., 0]
    return FourBarReaction(
        ground_on_crank=x[:, 0:2],
        crank_on_coupler=x[:, 2:4],
        coupler_on_rocker=x[:, 4:6],
        ground_on_rocker=x[:, 6:8],
        crank_torque=x[:, 8],
    )


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


# ------------------------------------------------------------------ load cycles


def _body_angles(motion: FourBarMotion) -> dict[str, FloatArray]:
    phi = np.asarray(motion.crank_angle, dtype=float)
    return {
        "crank": phi,
        "coupler": np.asarray(motion.coupler_angle, dtype=float),
        "rocker": np.asarray(motion.rocker_angle, dtype=float),
        "ground": np.zeros_like(phi),
    }


def _increments(angles: FloatArray, full_turns: float) -> FloatArray:
    """Exact increments of a periodic angle over each step; the last ends at step 0."""
    return np.append(angles[1:], angles[0] + 2.0 * math.pi * full_turns) - angles


def _periodic_increments(angles: dict[str, FloatArray]) -> dict[str, FloatArray]:
    # the crank turns once per revolution, coupler and rocker oscillate, ground is fixed
    turns = {"crank": 1.0, "coupler": 0.0, "rocker": 0.0, "ground": 0.0}
    return {body: _increments(values, turns[body]) for body, values in angles.items()}


def _joint_cycle(
    config: Config,
    joint: str,
    bushing_body: str,
    force: FloatArray,
    angles: dict[str, FloatArray],
    increments: dict[str, FloatArray],
    crank_torque: FloatArray,
    normal: FloatArray | None = None,
    **fields,
) -> LoadCycle:
    """A four-bar joint's load cycle in the bushing frame.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``mechanism.crank_speed``.
    joint : str
        Joint name.
    bushing_body : str
        Body carrying the bushing.
    force : ndarray, shape (N, 2)
        ``J``, force of the joint's first body on its second (global) [N].
    angles : dict of str to ndarray
        Body angles at the samples [rad].
    increments : dict of str to ndarray
        Increment of each body angle over each step [rad].
    crank_torque : ndarray, shape (N,)
        Crank driving torque [N m].
    normal : ndarray, shape (N, 2), optional
        Contact normal along ``J`` if the load direction is not that of ``J`` [-].
    **fields
        Further :class:`LoadCycle` fields.
    """
    mech = config.mechanism
    first, second = JOINT_BODIES[joint]
    pin_body = first if bushing_body == second else second
    sign = 1.0 if bushing_body == second else -1.0
    on_bushing = sign * force
    direction = on_bushing if normal is None else sign * normal
    steps = force.shape[0]
    load = fields.pop("load", np.hypot(on_bushing[:, 0], on_bushing[:, 1]))
    lost = fields.pop("lost_steps", None)
    if lost is None:
        lost = load < 1e-9 * float(load.max()) if load.max() > 0 else np.ones(steps, bool)
    diagnostics = {
        "crank_torque": Diagnostic(crank_torque, "N m", "crank driving torque"),
        "coupler_angle": Diagnostic(angles["coupler"], "rad", "coupler angle theta_2"),
        "rocker_angle": Diagnostic(angles["rocker"], "rad", "rocker angle theta_3"),
        "global_force_x": Diagnostic(
            on_bushing[:, 0], "N", f"x force of the pin on the bushing at {joint}, global"
        ),
        "global_force_y": Diagnostic(
            on_bushing[:, 1], "N", f"y force of the pin on the bushing at {joint}, global"
        ),
    }
    extras = {
        "bushing_body": bushing_body,
        **crank_extras(mech.crank_speed, crank_torque, lost),
    }
    return LoadCycle(
        time=mech.period * np.arange(steps) / steps,
        load=load,
        azimuth=bushing_azimuth(direction[:, 0], direction[:, 1], angles[bushing_body]),
        relative_rotation=increments[pin_body] - increments[bushing_body],
        period=mech.period,
        mechanism="four-bar",
        joint=joint,
        lost_steps=lost,
        diagnostics=diagnostics,
        extras=extras,
        **fields,
    )


def _motion_of(config: Config, steps: int) -> tuple[FourBar, FourBarMotion]:
    linkage = FourBar.from_config(config.mechanism)
    phi = 2.0 * np.pi * np.arange(steps) / steps
    motion = four_bar_motion(phi, *linkage.lengths, config.mechanism.crank_speed, linkage.assembly)
    return linkage, motion


def _massless_link_cycles(config: Config) -> dict[str, LoadCycle]:
    linkage, motion = _motion_of(config, config.simulation.steps_per_revolution)
    reaction = inverse_dynamics(motion, linkage)
    angles = _body_angles(motion)
    cycles = {}
    for joint, body in zip(config.mechanism.joints, config.mechanism.bushing_bodies, strict=True):
        cycle = _joint_cycle(
            config,
            joint,
            body,
            joint_force(reaction, joint),
            angles,
            _periodic_increments(angles),
            reaction.crank_torque,
            model="massless-link",
        )
        if cycle.contact_lost:
            message = (
                f"dynamics.model: the load on joint {joint!r} nearly vanishes (below 1e-9 of "
                f"its peak) at crank angles {cycle.extras['contact_lost_crank_angles_deg']} "
                f"deg, where the continuous-contact assumption is in doubt"
            )
            if config.dynamics.strict:
                raise MechanismError(message)
            warnings.warn(message, ContactLossWarning, stacklevel=3)
        cycles[joint] = cycle
    return cycles


def four_bar_cycles(config: Config, model: str) -> dict[str, LoadCycle]:
    """Load cycle of each clearance joint of the four-bar over one crank revolution.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[mechanism]`` (a four-bar), ``[dynamics]``, ``[joint]``,
        ``[materials]`` (contact-impact) and ``simulation.steps_per_revolution``.
    model : {"massless-link", "contact-impact"}
        ``"massless-link"``: the ideal-joint reaction at each joint (the clearance's
        ``O(c / l)`` effect on the kinematics is neglected); ``"contact-impact"``:
        the pin free in the clearance of the single configured joint.

    Returns
    -------
    dict of str to LoadCycle
        Joint name -> load cycle (force of the pin on the bushing, its azimuth in the
        bushing body's frame, relative rotation pin - bushing per step), in the order
        of ``mechanism.clearance_joint``.

    Raises
    ------
    ConfigError
        For an unknown model, or several clearance joints with ``contact-impact``.
    """
    if model == "massless-link":
        return _massless_link_cycles(config)
    if model == "contact-impact":
        joints = config.mechanism.joints
        if len(joints) != 1:
            raise ConfigError(
                "mechanism.clearance_joint: contact-impact models one clearance joint"
            )
        solution = four_bar_contact_impact(config)
        cycle = replace(solution.load, extras={**solution.load.extras, **solution.summary()})
        return {joints[0]: cycle}
    raise ConfigError(f"dynamics.model: unknown four-bar dynamics model {model!r}")


# ------------------------------------------------------------------ contact-impact


#: per joint: (base, L2, L3) of the centres of mass of coupler and rocker and of the
#: joint centres on the first and second body; base "B" is the crank pin, "D" the
#: rocker's ground pivot; the chain closes everywhere except at the clearance joint
_CHAINS: dict[str, dict[str, tuple[str, float, float]]] = {
    "crank-coupler": {
        "coupler": ("D", -0.5, 1.0),
        "rocker": ("D", 0.0, 0.5),
        "first": ("B", 0.0, 0.0),
        "second": ("D", -1.0, 1.0),
    },
    "coupler-rocker": {
        "coupler": ("B", 0.5, 0.0),
        "rocker": ("D", 0.0, 0.5),
        "first": ("B", 1.0, 0.0),
        "second": ("D", 0.0, 1.0),
    },
    "rocker-ground": {
        "coupler": ("B", 0.5, 0.0),
        "rocker": ("B", 1.0, -0.5),
        "first": ("B", 1.0, -1.0),
        "second": ("D", 0.0, 0.0),
    },
}
#: index of the free coordinate that is each body's angle (None: driven or fixed)
_ANGLE_INDEX = {"crank": None, "coupler": 0, "rocker": 1, "ground": None}


class FourBarContactSystem(ContactSystemBase):
    """Four-bar with a free pin in one joint (module docstring), a ``ContactSystem``.

    State ``y = (theta_2, theta_3, theta_2', theta_3', W)``: coupler and rocker
    angles [rad], their rates [rad/s] and the work ``W`` of the crank torque and
    the constant rocker torque [J].

    Parameters
    ----------
    linkage : FourBar
        Lengths, masses, gravity and rocker load.
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    contact : JointContact
        Contact force model; its ``friction_arm`` ``rho`` is measured from the first
        body's joint centre (``R_p`` if the pin is on the first body, ``-R_b`` if
        the bushing is).
    joint : {"crank-coupler", "coupler-rocker", "rocker-ground"}
        The clearance joint.
    """

    def __init__(
        self, linkage: FourBar, crank_speed: float, contact: JointContact, joint: str
    ) -> None:
        if joint not in _CHAINS:
            raise ConfigError(f"mechanism.clearance_joint: unknown four-bar joint {joint!r}")
        self.linkage = linkage
        self.omega = float(crank_speed)
        self.contact = contact
        self.joint = joint
        chain = _CHAINS[joint]
        _, _, l2, l3 = linkage.lengths
        self._points = {name: (base, s2 * l2, s3 * l3) for name, (base, s2, s3) in chain.items()}
        first, second = JOINT_BODIES[joint]
        self._first, self._second = _ANGLE_INDEX[first], _ANGLE_INDEX[second]
        inertia = np.diag([linkage.coupler_inertia, linkage.rocker_inertia])
        self._constant_mass = inertia
        if linkage.coupler_inertia + linkage.coupler_mass * l2 * l2 <= 0.0 or (
            linkage.rocker_inertia + linkage.rocker_mass * l3 * l3 <= 0.0
        ):
            raise ConfigError(
                "mechanism.coupler_mass, mechanism.rocker_mass: the contact-impact model "
                "needs a coupler and a rocker with inertia (the pin's degrees of freedom)"
            )

    # -------------------------------------------------------------- kinematics
    def _base(self, base: str, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        if base == "D":
            zero = np.zeros(2)
            return np.array([self.linkage.ground_length, 0.0]), zero, zero
        phi, w, l1 = self.omega * t, self.omega, self.linkage.crank_length
        p = l1 * np.array([math.cos(phi), math.sin(phi)])
        return p, w * np.array([-p[1], p[0]]), -w * w * p

    def _point(
        self, name: str, t: float, q: np.ndarray, qd: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity, Jacobian (2x2) and ``q'' = 0`` acceleration of a point."""
        base, a2, a3 = self._points[name]
        p0, v0, acc0 = self._base(base, t)
        e2 = np.array([math.cos(q[0]), math.sin(q[0])])
        e3 = np.array([math.cos(q[1]), math.sin(q[1])])
        n2, n3 = np.array([-e2[1], e2[0]]), np.array([-e3[1], e3[0]])
        jac = np.column_stack((a2 * n2, a3 * n3))
        pos = p0 + a2 * e2 + a3 * e3
        vel = v0 + jac @ qd
        drift = acc0 - a2 * qd[0] ** 2 * e2 - a3 * qd[1] ** 2 * e3
        return pos, vel, jac, drift

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        q, qd = np.asarray(y[:2], dtype=float), np.asarray(y[2:4], dtype=float)
        p1, v1, _, _ = self._point("first", t, q, qd)
        p2, v2, _, _ = self._point("second", t, q, qd)
        e, v = p1 - p2, v1 - v2
        return float(e[0]), float(e[1]), float(v[0]), float(v[1])

    # -------------------------------------------------------------- dynamics
    def evaluate(self, t: float, y: ArrayLike, impact_velocity: float) -> dict[str, float]:
        """Accelerations, contact force and crank torque at one instant.

        Parameters
        ----------
        t : float
            Time [s] (crank angle ``omega t``).
        y : array_like, shape (5,)
            State.
        impact_velocity : float
            ``delta'^-`` of the current contact [m/s].

        Returns
        -------
        dict
            ``q_ddot`` (2,) [rad/s^2], ``force_x``/``force_y`` (``J`` on the second
            body) [N], ``normal_force``/``friction_force`` [N], ``normal_x``/``normal_y``
            [-], ``penetration`` [m], ``slip`` [m/s], ``crank_torque`` [N m].
        """
        y = np.asarray(y, dtype=float)
        q, qd = y[:2], y[2:4]
        lk = self.linkage
        gravity = np.array([0.0, -lk.gravity])
        p1, v1, jac1, _ = self._point("first", t, q, qd)
        p2, v2, jac2, _ = self._point("second", t, q, qd)
        e, v = p1 - p2, v1 - v2
        # angular velocities of the two bodies (crank: omega; ground: 0)
        first, second = JOINT_BODIES[self.joint]
        omega1 = self.omega if first == "crank" else float(qd[_ANGLE_INDEX[first]])
        omega2 = 0.0 if second == "ground" else float(qd[_ANGLE_INDEX[second]])
        rho = self.contact.friction_arm
        # slip of the first body's surface over the second's at the contact point is
        # e'.t + rho (w1 - w2) - w2 |e|; JointContact adds rho * spin to e'.t
        spin = (omega1 - omega2) - omega2 * math.hypot(e[0], e[1]) / rho if rho else 0.0
        jx, jy, normal, tangential, nx, ny, delta, slip = self.contact.force(
            e[0], e[1], v[0], v[1], spin, impact_velocity
        )
        force = np.array([jx, jy])
        contact_point = p1 + rho * np.array([nx, ny])

        mass = self._constant_mass.copy()
        gen = np.array([0.0, float(rocker_load_torque(q[1], lk))])
        masses = {"coupler": lk.coupler_mass, "rocker": lk.rocker_mass}
        drifts = {}
        for body, m in masses.items():
            _, _, jac, drift = self._point(body, t, q, qd)
            drifts[body] = (jac, drift)
            mass += m * jac.T @ jac
            gen += m * jac.T @ (gravity - drift)
        # contact: -J on the first body, +J on the second, both at the contact point
        for sign, point_jac, centre, index in (
            (-1.0, jac1, p1, self._first),
            (1.0, jac2, p2, self._second),
        ):
            gen += sign * point_jac.T @ force
            if index is not None:
                gen[index] += sign * _cross(contact_point - centre, force)
        q_ddot = np.linalg.solve(mass, gen)

        # crank torque about A (constant omega): T = B x F_B + m1 g (l1 / 2) cos(phi)
        phi = self.omega * t
        b = lk.crank_length * np.array([math.cos(phi), math.sin(phi)])

        def inertial(body: str) -> np.ndarray:
            jac, drift = drifts[body]
            return masses[body] * (jac @ q_ddot + drift - gravity)

        if self.joint == "crank-coupler":
            torque_arm, f_b = contact_point, force
        elif self.joint == "coupler-rocker":
            torque_arm, f_b = b, inertial("coupler") + force
        else:
            torque_arm, f_b = b, inertial("coupler") + inertial("rocker") + force
        torque = _cross(torque_arm, f_b) + 0.5 * lk.crank_mass * lk.gravity * b[0]
        return {
            "q_ddot": q_ddot,
            "force_x": jx,
            "force_y": jy,
            "normal_force": normal,
            "friction_force": tangential,
            "normal_x": nx,
            "normal_y": ny,
            "penetration": delta,
            "slip": slip,
            "crank_torque": float(torque),
            "ex": float(e[0]),
            "ey": float(e[1]),
        }

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """``y' = (theta_2', theta_3', theta_2'', theta_3'', T omega + tau theta_3')``."""
        out = self.evaluate(t, y, impact_velocity)
        q_ddot = out["q_ddot"]
        power = out["crank_torque"] * self.omega + self.linkage.rocker_torque * y[3]
        return np.array([y[2], y[3], q_ddot[0], q_ddot[1], power])

    def energy(self, t: float, y: ArrayLike) -> float:
        """Kinetic + gravity + rocker spring + contact elastic energy [J].

        The crank's kinetic energy is constant and left out; its potential energy
        is included (the crank torque pays for it).
        """
        y = np.asarray(y, dtype=float)
        q, qd = y[:2], y[2:4]
        lk = self.linkage
        phi = self.omega * t
        energy = 0.5 * (lk.coupler_inertia * qd[0] ** 2 + lk.rocker_inertia * qd[1] ** 2)
        energy += lk.gravity * lk.crank_mass * 0.5 * lk.crank_length * math.sin(phi)
        for body, m in (("coupler", lk.coupler_mass), ("rocker", lk.rocker_mass)):
            pos, vel, _, _ = self._point(body, t, q, qd)
            energy += 0.5 * m * float(vel @ vel) + m * lk.gravity * float(pos[1])
        energy += 0.5 * lk.rocker_spring_stiffness * (q[1] - lk.rocker_spring_angle) ** 2
        ex, ey, _, _ = self.clearance_state(t, y)
        return float(energy + self.contact.potential(ex, ey))

    # -------------------------------------------------------------- start
    def initial_state(self, load: ArrayLike, steps: int = 64) -> FloatArray:
        """State at ``phi = 0``: ideal motion, pin pressed into the wall along ``load``.

        Parameters
        ----------
        load : array_like, shape (2,)
            ``J`` of the ideal linkage at ``phi = 0`` [N].
        steps : int
            Newton iterations allowed for the offset geometry [-].
        """
        lk = self.linkage
        motion = four_bar_motion(np.zeros(1), *lk.lengths, self.omega, lk.assembly)
        q = np.array([motion.coupler_angle[0], motion.rocker_angle[0]])
        qd = np.array([motion.coupler_angular_velocity[0], motion.rocker_angular_velocity[0]])
        jx, jy = (float(v) for v in np.asarray(load, dtype=float))
        direction = math.atan2(jy, jx)
        offset = self.contact.static_offset(math.hypot(jx, jy), direction)
        target = offset * np.array([math.cos(direction), math.sin(direction)])
        # Newton on the loop residual e(q) = target (a 2x2 system, well conditioned
        # away from the toggle positions a crank-rocker never reaches)
        for _ in range(steps):
            p1, _, jac1, _ = self._point("first", 0.0, q, qd)
            p2, _, jac2, _ = self._point("second", 0.0, q, qd)
            residual = p1 - p2 - target
            if np.max(np.abs(residual)) <= 1e-15 * lk.coupler_length:
                break
            q = q - np.linalg.solve(jac1 - jac2, residual)
        # velocities: keep e' = 0 (the ideal rates solve it up to O(c))
        _, v1, jac1, _ = self._point("first", 0.0, q, np.zeros(2))
        _, v2, jac2, _ = self._point("second", 0.0, q, np.zeros(2))
        qd = np.linalg.solve(jac1 - jac2, -(v1 - v2))
        return np.array([q[0], q[1], qd[0], qd[1], 0.0])


def _four_bar_contact(config: Config, joint: str, bushing_body: str) -> JointContact:
    from jointwear.mechanism.force_laws import JointContact

    contact = JointContact.from_config(config)
    # rho is measured from the first body's joint centre: R_p with the pin there,
    # -R_b with the bushing there (the slider-crank's rule keys on its own bodies)
    first = JOINT_BODIES[joint][0]
    contact.friction_arm = (
        -config.joint.bushing_radius if bushing_body == first else config.joint.pin_radius
    )
    return contact


def four_bar_contact_impact(config: Config, compare: bool = True) -> ContactImpactSolution:
    """Integrate the four-bar with a free pin in its clearance joint; one settled revolution.

    Parameters
    ----------
    config : jointwear.config.Config
        A four-bar with one clearance joint; uses ``[joint]``, ``[materials]``,
        ``[dynamics]`` and ``simulation.steps_per_revolution``.
    compare : bool
        Also compute the massless-link load and report the difference.

    Returns
    -------
    ContactImpactSolution
        ``load`` is the normal contact force (zero in free flight) with the contact
        normal's azimuth in the bushing body's frame.

    Raises
    ------
    ConfigError
        If more than one clearance joint is configured.
    ConvergenceError
        If the integrator fails.
    """
    from jointwear.mechanism.contact_impact import sampled_solution
    from jointwear.mechanism.impact_integrator import ContactImpactSettings, integrate_revolution

    mech = config.mechanism
    if len(mech.joints) != 1:
        raise ConfigError("mechanism.clearance_joint: contact-impact models one clearance joint")
    joint, bushing = mech.joints[0], mech.bushing_bodies[0]
    settings = ContactImpactSettings.from_config(config.dynamics)
    steps = config.simulation.steps_per_revolution
    linkage, motion = _motion_of(config, steps)
    ideal = joint_force(inverse_dynamics(motion, linkage), joint)
    system = FourBarContactSystem(
        linkage, mech.crank_speed, _four_bar_contact(config, joint, bushing), joint
    )
    run = integrate_revolution(system, system.initial_state(ideal[0]), settings, steps)

    states = run.states
    angles = {
        "crank": motion.crank_angle,
        "coupler": states[:-1, 0],
        "rocker": states[:-1, 1],
        "ground": np.zeros(steps),
    }
    # increments up to the sampled end of the revolution: the settled motion is
    # periodic only to the integration tolerance, so step N-1 does not end at step 0
    increments = {
        "crank": np.full(steps, 2.0 * math.pi / steps),
        "coupler": np.diff(states[:, 0]),
        "rocker": np.diff(states[:, 1]),
        "ground": np.zeros(steps),
    }
    load = _joint_cycle(
        config,
        joint,
        bushing,
        np.column_stack((run.column("force_x"), run.column("force_y"))),
        angles,
        increments,
        run.column("crank_torque"),
        normal=np.column_stack((run.column("normal_x"), run.column("normal_y"))),
        load=run.column("normal_force"),
        model="contact-impact",
        lost_steps=run.step_lost,
    )
    return sampled_solution(
        load,
        run,
        system,
        settings,
        (lambda: _massless_link_cycles(config)[joint]) if compare else None,
    )
