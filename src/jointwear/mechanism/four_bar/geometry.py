r"""Crank-rocker four-bar linkage: its geometry, the check that the crank turns, its data.

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

:func:`check_four_bar` refuses a linkage whose crank cannot turn full revolutions (the
configuration validates a four-bar with it); :class:`FourBar` holds the lengths,
masses and rocker load of one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from jointwear.errors import ConfigError

if TYPE_CHECKING:
    from jointwear.config import FourBarConfig

__all__ = ["JOINT_BODIES", "FourBar", "check_four_bar"]

#: the two bodies of each joint (first, second); ``J`` acts on the second
JOINT_BODIES: dict[str, tuple[str, str]] = {
    "crank-coupler": ("crank", "coupler"),
    "coupler-rocker": ("coupler", "rocker"),
    "rocker-ground": ("rocker", "ground"),
}

#: relative tolerance of the change-point test ``s + l == p + q``
_CHANGE_POINT = 1e-12


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
