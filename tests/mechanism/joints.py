"""Helpers of the mechanism tests: a configuration's mechanism inputs and joint contact."""

from __future__ import annotations

from dataclasses import replace

from jointwear.config import Config
from jointwear.geometry import BushingContour
from jointwear.mechanism.impact.joint_contact import JointContact
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.inputs import MechanismInputs
from jointwear.mechanism.slider_crank.contact_impact import (
    SliderCrankContactSystem,
    slider_crank_contact,
)
from jointwear.mechanism.slider_crank.dynamics import SliderCrank
from jointwear.mechanism.stage import elastic_law, mechanism_inputs


def inputs_of(config: Config) -> MechanismInputs:
    """The mechanism inputs of ``config``, with the joint's elastic law whatever the model."""
    return replace(mechanism_inputs(config), elastic=elastic_law(config))


def joint_contact(config: Config, contour: BushingContour | None = None) -> JointContact:
    """The contact model of the slider-crank joint of ``config`` (its ``[dynamics]``)."""
    settings = ContactImpactSettings.from_config(config.dynamics)
    return slider_crank_contact(inputs_of(config), settings, contour)


def slider_crank_system(
    config: Config, contour: BushingContour | None = None, compiled: bool | None = None
) -> SliderCrankContactSystem:
    """The slider-crank of ``config`` with a free pin (its contact-impact system)."""
    return SliderCrankContactSystem(
        SliderCrank.from_config(config.mechanism),
        config.mechanism.crank_speed,
        joint_contact(config, contour),
        compiled,
    )
