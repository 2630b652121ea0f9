"""The slider-crank of the paper (section 3.1): clearance between connecting rod and slider.

==========================  ===========================================================
:mod:`.kinematics`          the ideal mechanism and the clearance link (eq. 10)
:mod:`.dynamics`            mechanism data, spring, inverse dynamics (eq. 11)
:mod:`.massless_link`       the massless-link model (eqs. 10-12), iterated to a fixed point
:mod:`.contact_impact`      the contact–impact model: the pin free in the clearance
:mod:`.joint_load`          the joint force as a load cycle in the bushing frame
==========================  ===========================================================

:data:`SLIDER_CRANK` is its entry in :data:`jointwear.mechanism.MECHANISMS`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.impact.revolution import ContactImpactSolution
from jointwear.mechanism.inputs import MechanismInputs
from jointwear.mechanism.slider_crank.contact_impact import (
    contact_impact_load,
    solve_contact_impact,
    worn_contour,
)
from jointwear.mechanism.slider_crank.massless_link import massless_link_load

__all__ = ["SLIDER_CRANK", "SliderCrankMechanism"]


class SliderCrankMechanism:
    """The slider-crank as a mechanism type (:class:`jointwear.mechanism.base.Mechanism`)."""

    description = "the paper's slider-crank, clearance between connecting rod and slider"
    models = ("massless-link", "contact-impact")

    def load_cycles(
        self, inputs: MechanismInputs, wear_depth: NDArray[np.float64] | None = None
    ) -> dict[str, LoadCycle]:
        """The rod-slider joint's load cycle from the model ``inputs.dynamics.model``.

        Parameters
        ----------
        inputs : MechanismInputs
            The slider-crank's section, the joint, the dynamics settings.
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing [m]; ``None``: the unworn joint.
        """
        if inputs.dynamics.model == "contact-impact":
            cycle = contact_impact_load(inputs, wear_depth)
        else:
            cycle = massless_link_load(inputs, wear_depth)
        return {cycle.joint: cycle}

    def contact_impact(
        self,
        inputs: MechanismInputs,
        wear_depth: NDArray[np.float64] | None = None,
        compare: bool = True,
    ) -> ContactImpactSolution:
        """The contact–impact solution of the joint (:func:`.solve_contact_impact`).

        Parameters
        ----------
        inputs : MechanismInputs
            With the joint's elastic law.
        wear_depth : ndarray, shape (N,), optional
            Wear depth of the bushing [m]; ``None``: the unworn joint.
        compare : bool
            Also run the massless-link model and report the load difference.
        """
        return solve_contact_impact(inputs, worn_contour(inputs, wear_depth), compare)


#: the registry entry
SLIDER_CRANK = SliderCrankMechanism()
