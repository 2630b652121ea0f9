"""Crank-rocker four-bar linkage with a clearance in one or more of its moving joints.

==========================  ===========================================================
:mod:`.geometry`            the check that the crank turns, the linkage's data
:mod:`.kinematics`          coupler and rocker angles, rates, accelerations
:mod:`.dynamics`            inverse dynamics with ideal joints
:mod:`.massless_link`       the massless-link model: the ideal-joint reaction
:mod:`.contact_impact`      the contact–impact model: the pin free in one joint
:mod:`.joint_load`          a joint's force as a load cycle in the bushing frame
==========================  ===========================================================

:data:`FOUR_BAR` is its entry in :data:`jointwear.mechanism.MECHANISMS`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.four_bar.contact_impact import four_bar_contact_impact
from jointwear.mechanism.four_bar.geometry import check_four_bar
from jointwear.mechanism.four_bar.massless_link import massless_link_cycles
from jointwear.mechanism.impact.revolution import ContactImpactSolution
from jointwear.mechanism.inputs import MechanismInputs

__all__ = ["FOUR_BAR", "FourBarMechanism", "check_four_bar"]


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
        ``contact-impact``: the pin free in the clearance of the single configured joint.

        Parameters
        ----------
        inputs : MechanismInputs
            The four-bar's section, the joint, the dynamics settings.
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing [m]; ``None``: the unworn joint.

        Returns
        -------
        dict of str to LoadCycle
            Joint name -> load cycle (force of the pin on the bushing, its azimuth in
            the bushing body's frame, relative rotation pin - bushing per step), in the
            order of ``mechanism.clearance_joint``.

        Raises
        ------
        ConfigError
            Several clearance joints with ``contact-impact``, or contact-impact on a
            worn joint.
        """
        if inputs.dynamics.model != "contact-impact":
            return massless_link_cycles(inputs)
        cycle = self.contact_impact(inputs, wear_depth).load_cycle()
        return {cycle.joint: cycle}

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
            Must be unworn (``None`` or zeros) [m]: the free pin meeting a worn
            four-bar bushing is not modelled.
        compare : bool
            Also compute the massless-link load and report the difference.
        """
        # the ideal-joint reactions do not depend on the clearance; the free pin would
        if wear_depth is not None and np.any(wear_depth):
            raise ConfigError(
                "simulation.dynamics_update: contact-impact on a worn four-bar joint is not "
                "modelled; use 'once' (or the slider-crank)"
            )
        return four_bar_contact_impact(inputs, compare)


#: the registry entry
FOUR_BAR = FourBarMechanism()
