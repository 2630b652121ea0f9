"""Crank-rocker four-bar linkage with a clearance in one or more of its moving joints.

==========================  ===========================================================
:mod:`.geometry`            the check that the crank turns, the linkage's data
:mod:`.kinematics`          coupler and rocker angles, rates, accelerations
:mod:`.dynamics`            inverse dynamics with ideal joints
:mod:`.massless_link`       the massless-link model: the ideal-joint reaction
:mod:`.contact_impact`      the contact–impact model: the pin free in a joint
:mod:`.joint_load`          a joint's force as a load cycle in the bushing frame
==========================  ===========================================================

:data:`FOUR_BAR` is its entry in :data:`jointwear.mechanism.MECHANISMS`.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.four_bar.contact_impact import four_bar_contact_impact
from jointwear.mechanism.four_bar.geometry import check_four_bar
from jointwear.mechanism.four_bar.massless_link import massless_link_cycles
from jointwear.mechanism.impact.revolution import ContactImpactSolution
from jointwear.mechanism.inputs import MechanismInputs

__all__ = ["FOUR_BAR", "FourBarMechanism", "check_four_bar", "single_joints"]


class FourBarMechanism:
    """The four-bar as a mechanism type (:class:`jointwear.mechanism.base.Mechanism`)."""

    description = "crank-rocker four-bar linkage, clearance in any of its moving joints"
    models = ("massless-link", "contact-impact")

    def load_cycles(
        self, inputs: MechanismInputs, wear_depth: NDArray[np.float64] | None = None
    ) -> dict[str, LoadCycle]:
        """Load cycle of each clearance joint over one crank revolution.

        ``massless-link``: the ideal-joint reaction at each joint (the clearance's
        ``O(c / l)`` effect on the kinematics is neglected, and so is the wear);
        ``contact-impact``: the pin free in the clearance of each joint in turn, the
        other joints ideal (:func:`single_joints`), on its worn contour.

        Parameters
        ----------
        inputs : MechanismInputs
            The four-bar's section, the joint, the dynamics settings.
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing, in the frame of the body that carries it [m]
            (every joint's: a run re-solves one joint at a time); ``None``: unworn.

        Returns
        -------
        dict of str to LoadCycle
            Joint name -> load cycle (force of the pin on the bushing, its azimuth in
            the bushing body's frame, relative rotation pin - bushing per step), in the
            order of ``mechanism.clearance_joint``.
        """
        if inputs.dynamics.model != "contact-impact":
            return massless_link_cycles(inputs)
        cycles = {}
        for single in single_joints(inputs):
            cycle = self.contact_impact(single, wear_depth).load_cycle()
            cycles[cycle.joint] = cycle
        return cycles

    def contact_impact(
        self,
        inputs: MechanismInputs,
        wear_depth: NDArray[np.float64] | None = None,
        compare: bool = True,
    ) -> ContactImpactSolution:
        """The contact–impact solution of the clearance joint (:func:`.four_bar_contact_impact`).

        Parameters
        ----------
        inputs : MechanismInputs
            A four-bar with one clearance joint, with the joint's elastic law.
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing in its body's frame [m]; ``None``: unworn.
        compare : bool
            Also compute the massless-link load and report the difference.
        """
        return four_bar_contact_impact(inputs, compare, wear_depth)


def single_joints(inputs: MechanismInputs) -> list[MechanismInputs]:
    """One set of inputs per clearance joint, that joint the only one with clearance.

    With several clearance joints each free pin is solved with the other joints
    ideal: the joints do not interact through the loads (as in the massless-link
    model, where each joint's load is the ideal-joint reaction), each meets its own
    bushing.

    Parameters
    ----------
    inputs : MechanismInputs
        A four-bar with one or more clearance joints.
    """
    mech = inputs.mechanism
    if len(mech.joints) == 1:
        return [inputs]
    return [
        replace(
            inputs,
            mechanism=mech.model_copy(update={"clearance_joint": joint, "bushing_body": body}),
        )
        for joint, body in zip(mech.joints, mech.bushing_bodies, strict=True)
    ]


#: the registry entry
FOUR_BAR = FourBarMechanism()
