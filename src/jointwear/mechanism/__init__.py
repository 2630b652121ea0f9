"""Mechanism dynamics (stage 1 of the pipeline: the joint's motion -> its load cycle).

A mechanism type (``mechanism.type``) and, for the types with inertia, a dynamics
model (``dynamics.model``) turn the mechanism's :class:`MechanismInputs` (its config
section and the joint's numbers) into one :class:`LoadCycle` per clearance joint:
load magnitude and azimuth on the bushing and the relative rotation of pin and
bushing, per time step of one period. Every type is a :class:`Mechanism` in the
registry :data:`MECHANISMS`:

================  =================================================================
``slider-crank``  :mod:`jointwear.mechanism.slider_crank` (the paper's mechanism)
``four-bar``      :mod:`jointwear.mechanism.four_bar`
``oscillating``   :mod:`jointwear.mechanism.oscillating`
``load-history``  :mod:`jointwear.mechanism.history`
================  =================================================================

The contact–impact machinery they share (force laws, integrator) is
:mod:`jointwear.mechanism.impact`. A run computes its load cycles with
:func:`jointwear.mechanism.stage.load_cycles` (from a configuration); the models'
own functions are imported from their modules.
"""

from __future__ import annotations

from jointwear.mechanism.base import (
    DYNAMICS_MODELS,
    MECHANISMS,
    ContactImpactMechanism,
    Mechanism,
)
from jointwear.mechanism.cycle import Diagnostic, LoadCycle
from jointwear.mechanism.impact.revolution import ContactImpactSolution
from jointwear.mechanism.inputs import ElasticLaw, JointGeometry, MechanismInputs

__all__ = [
    "DYNAMICS_MODELS",
    "MECHANISMS",
    "ContactImpactMechanism",
    "ContactImpactSolution",
    "Diagnostic",
    "ElasticLaw",
    "JointGeometry",
    "LoadCycle",
    "Mechanism",
    "MechanismInputs",
]
