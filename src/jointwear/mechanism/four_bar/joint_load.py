r"""A four-bar joint's load as a load cycle, in the frame of the body with the bushing.

**Joint force and load cycle.** Each joint joins a *first* and a *second* body
(``crank-coupler``, ``coupler-rocker``, ``rocker-ground``); ``J`` is the force the
first exerts on the second: ``F_B``, ``F_C`` and ``-F_D``. The pin presses on the
bushing with ``J`` if the bushing is on the second body, with ``-J`` if on the
first. The relative rotation of a step is ``Delta theta_pin - Delta theta_bushing``
(``theta`` of the ground is 0; the crank turns ``2 pi`` per revolution).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from jointwear.mechanism.cycle import Diagnostic, LoadCycle, bushing_azimuth, crank_extras
from jointwear.mechanism.four_bar.geometry import JOINT_BODIES
from jointwear.mechanism.four_bar.kinematics import FourBarMotion

if TYPE_CHECKING:
    from jointwear.config import FourBarConfig

__all__ = ["body_angles", "joint_cycle", "periodic_increments"]

FloatArray = NDArray[np.float64]


def body_angles(motion: FourBarMotion) -> dict[str, FloatArray]:
    """Angle of each body at the samples: crank, coupler, rocker, ground (0) [rad].

    Parameters
    ----------
    motion : FourBarMotion
        Motion of the linkage.
    """
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


def periodic_increments(angles: dict[str, FloatArray]) -> dict[str, FloatArray]:
    """Increment of each body angle over each step of a periodic motion [rad].

    Parameters
    ----------
    angles : dict of str to ndarray
        :func:`body_angles` [rad].
    """
    # the crank turns once per revolution, coupler and rocker oscillate, ground is fixed
    turns = {"crank": 1.0, "coupler": 0.0, "rocker": 0.0, "ground": 0.0}
    return {body: _increments(values, turns[body]) for body, values in angles.items()}


def joint_cycle(
    mechanism: FourBarConfig,
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
    mechanism : jointwear.config.FourBarConfig
        The ``[mechanism]`` section (``crank_speed``, ``period``).
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
    mech = mechanism
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
