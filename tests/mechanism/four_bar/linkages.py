"""Four-bar linkages the tests share: two crank-rockers with masses, a load and a spring."""

from __future__ import annotations

import math

import numpy as np

from jointwear.mechanism.four_bar.geometry import FourBar
from jointwear.mechanism.four_bar.kinematics import FourBarMotion, four_bar_motion

RPM = 2.0 * math.pi / 60.0
#: (l0, l1, l2, l3) [m]: the example and a stubbier crank-rocker with a long rocker
LINKAGES = [(0.2, 0.05, 0.18, 0.12), (0.1, 0.04, 0.12, 0.09)]


def linkage(lengths=LINKAGES[0], **changes: object) -> FourBar:
    """A four-bar of ``lengths`` [m] with slender-bar inertias; ``changes`` override fields."""
    data = dict(
        crank_mass=0.1,
        coupler_mass=0.3,
        rocker_mass=0.2,
        gravity=9.81,
        rocker_torque=2.0,
        rocker_spring_stiffness=1.0,
        rocker_spring_angle=math.pi / 2,
    )
    data.update(changes)
    l0, l1, l2, l3 = lengths
    for name, length in (("crank", l1), ("coupler", l2), ("rocker", l3)):
        data.setdefault(f"{name}_inertia", data[f"{name}_mass"] * length**2 / 12)
    return FourBar(l0, l1, l2, l3, **data)


def motion_of(link: FourBar, phi: np.ndarray, omega: float) -> FourBarMotion:
    """The linkage's motion at crank angles ``phi`` [rad] and crank speed ``omega`` [rad/s]."""
    return four_bar_motion(phi, *link.lengths, omega, link.assembly)


def unit(theta: np.ndarray) -> np.ndarray:
    """Unit vectors at angles ``theta`` [rad]."""
    return np.stack((np.cos(theta), np.sin(theta)), axis=-1)


def normal(theta: np.ndarray) -> np.ndarray:
    """Unit normals (``unit`` turned by +90 deg) at angles ``theta`` [rad]."""
    return np.stack((-np.sin(theta), np.cos(theta)), axis=-1)
