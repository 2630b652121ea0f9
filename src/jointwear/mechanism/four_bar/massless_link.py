r"""The massless-link model of the four-bar: the ideal-joint reaction at each joint.

**Massless-link model.** As for the slider-crank, the clearance joint's load is the
ideal-joint reaction; the clearance changes the geometry by ``O(c / l)`` only,
which is neglected here (the slider-crank iterates it to a fixed point, the
four-bar does not).
"""

from __future__ import annotations

import warnings

from jointwear.errors import ContactLossWarning, MechanismError
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.four_bar.dynamics import inverse_dynamics, joint_force
from jointwear.mechanism.four_bar.geometry import FourBar
from jointwear.mechanism.four_bar.joint_load import body_angles, joint_cycle, periodic_increments
from jointwear.mechanism.four_bar.kinematics import ideal_motion
from jointwear.mechanism.inputs import MechanismInputs

__all__ = ["massless_link_cycles"]


def massless_link_cycles(inputs: MechanismInputs) -> dict[str, LoadCycle]:
    """The ideal-joint reaction at each clearance joint over one crank revolution.

    Parameters
    ----------
    inputs : MechanismInputs
        The four-bar's ``[mechanism]`` section, ``dynamics.strict`` and the steps per
        revolution.

    Returns
    -------
    dict of str to LoadCycle
        Joint name -> load cycle, in the order of ``mechanism.clearance_joint``.

    Warns
    -----
    ContactLossWarning
        Where a joint's load nearly vanishes (below 1e-9 of its peak).

    Raises
    ------
    MechanismError
        Instead of the warning when ``dynamics.strict`` is true.
    """
    mechanism = inputs.mechanism
    linkage = FourBar.from_config(mechanism)
    motion = ideal_motion(linkage, mechanism.crank_speed, inputs.steps)
    reaction = inverse_dynamics(motion, linkage)
    angles = body_angles(motion)
    cycles = {}
    for joint, body in zip(mechanism.joints, mechanism.bushing_bodies, strict=True):
        cycle = joint_cycle(
            mechanism,
            joint,
            body,
            joint_force(reaction, joint),
            angles,
            periodic_increments(angles),
            reaction.crank_torque,
            model="massless-link",
        )
        if cycle.contact_lost:
            message = (
                f"dynamics.model: the load on joint {joint!r} nearly vanishes (below 1e-9 of "
                f"its peak) at crank angles {cycle.extras['contact_lost_crank_angles_deg']} "
                f"deg, where the continuous-contact assumption is in doubt"
            )
            if inputs.dynamics.strict:
                raise MechanismError(message)
            warnings.warn(message, ContactLossWarning, stacklevel=3)
        cycles[joint] = cycle
    return cycles
