r"""Inverse dynamics of the slider-crank: joint force and crank torque for a motion.

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

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import MechanismError
from jointwear.mechanism.slider_crank.kinematics import SliderCrankMotion

if TYPE_CHECKING:
    from jointwear.config import SliderCrankConfig

__all__ = ["JointReaction", "SliderCrank", "SpringMode", "inverse_dynamics", "spring_force"]

FloatArray = NDArray[np.float64]
SpringMode = Literal["pull", "push"]


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
    ab_x, ab_y = -(omega**2) * b_x, -(omega**2) * b_y
    # rod vector r = C - B and the rod's centre-of-mass acceleration a_G = a_B + r''/2
    r_x, r_y = m.rod_length * cos_t, m.rod_length * sin_t
    rdd_x = -r_y * theta_ddot - r_x * theta_dot**2
    rdd_y = r_x * theta_ddot - r_y * theta_dot**2
    ag_x, ag_y = ab_x + 0.5 * rdd_x, ab_y + 0.5 * rdd_y

    f_spring = spring_force(
        motion.slider_position,
        m.crank_length,
        m.rod_length,
        m.spring_stiffness,
        m.spring_preload,
        m.spring_mode,
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
