"""Mechanism dynamics (stage 1 of the pipeline: the joint's motion -> its load cycle).

A mechanism type (``mechanism.type``) and, for the types with inertia, a dynamics
model (``dynamics.model``) turn a :class:`~jointwear.config.Config` into one
:class:`LoadCycle` per clearance joint: load magnitude and azimuth on the bushing
and the relative rotation of pin and bushing, per time step of one period. The
registry :data:`MECHANISMS` holds, per type, its dynamics models:

================  =================================================================
``slider-crank``  the paper's mechanism, clearance between rod and slider
                  (:mod:`.slider_crank`); ``massless-link`` (paper eqs. 10-12) or
                  ``contact-impact`` (:mod:`.contact_impact`)
``four-bar``      crank-rocker four-bar, any of its three moving joints with
                  clearance (:mod:`.four_bar`); ``massless-link`` or
                  ``contact-impact``
``oscillating``   oscillating-bearing test, prescribed load (:mod:`.oscillating`)
``load-history``  one period of load read from a file (:mod:`.history`)
================  =================================================================
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from jointwear.config import MECHANISM_TYPES, Config
from jointwear.errors import ConfigError
from jointwear.mechanism import force_laws
from jointwear.mechanism.contact_impact import (
    ContactImpactSolution,
    contact_impact_load,
    solve_contact_impact,
)
from jointwear.mechanism.cycle import Diagnostic, LoadCycle, bushing_azimuth, wrap_angle
from jointwear.mechanism.force_laws import JointContact
from jointwear.mechanism.impact_integrator import ContactImpactSettings
from jointwear.mechanism.oscillating import oscillating_cycle
from jointwear.mechanism.slider_crank import (
    JointReaction,
    MasslessLinkSolution,
    SliderCrank,
    SliderCrankMotion,
    clearance_motion,
    contact_loss,
    crank_angle_grid,
    ideal_motion,
    inverse_dynamics,
    load_bandwidth,
    massless_link_load,
    rod_angle,
    rod_angular_acceleration,
    rod_angular_velocity,
    slider_acceleration,
    slider_position,
    slider_velocity,
    solve_massless_link,
    spectral_derivative,
    spring_force,
)
from jointwear.registry import Registry, suggest

__all__ = [
    "DYNAMICS_MODELS",
    "DYNAMICS_MODEL_DESCRIPTIONS",
    "MECHANISMS",
    "ContactImpactSettings",
    "ContactImpactSolution",
    "Diagnostic",
    "JointContact",
    "JointReaction",
    "LoadCycle",
    "MasslessLinkSolution",
    "Mechanism",
    "SliderCrank",
    "SliderCrankMotion",
    "bushing_azimuth",
    "clearance_motion",
    "contact_impact_load",
    "contact_loss",
    "crank_angle_grid",
    "force_laws",
    "ideal_motion",
    "inverse_dynamics",
    "load_bandwidth",
    "load_cycle",
    "load_cycles",
    "massless_link_load",
    "rod_angle",
    "rod_angular_acceleration",
    "rod_angular_velocity",
    "slider_acceleration",
    "slider_position",
    "slider_velocity",
    "solve_contact_impact",
    "solve_massless_link",
    "spectral_derivative",
    "spring_force",
    "wrap_angle",
]

FloatArray = NDArray[np.float64]

#: a dynamics model: (config, wear depth of the bushing or None) -> one load cycle per joint
CycleModel = Callable[[Config, FloatArray | None], Mapping[str, LoadCycle]]


@dataclass(frozen=True)
class Mechanism:
    """A mechanism type: what it is and how its load cycles are computed.

    Attributes
    ----------
    description : str
        One line for ``jointwear mechanisms``.
    models : mapping of str to callable
        Dynamics model name -> ``(Config) -> {joint: LoadCycle}``. A type whose load
        is prescribed has the single model ``"prescribed"``, used whatever
        ``dynamics.model`` says.
    """

    description: str
    models: Mapping[str, CycleModel]


def _massless_link(config: Config, wear_depth: FloatArray | None) -> dict[str, LoadCycle]:
    # the worn joint's massless link: the pin rests in the scar, so the link is the
    # clearance plus the deepest wear
    if wear_depth is not None and np.any(wear_depth):
        worn = config.joint.clearance + float(wear_depth.max())
        config = config.replace({"joint.clearance": worn})
    cycle = massless_link_load(config)
    return {cycle.joint: cycle}


def _contact_impact(config: Config, wear_depth: FloatArray | None) -> dict[str, LoadCycle]:
    cycle = contact_impact_load(config, wear_depth)
    return {cycle.joint: cycle}


def _four_bar(model: str) -> CycleModel:
    def cycles(config: Config, wear_depth: FloatArray | None) -> dict[str, LoadCycle]:
        from jointwear.mechanism import four_bar

        # the ideal-joint reactions do not depend on the clearance; the free pin would
        if model == "contact-impact" and wear_depth is not None and np.any(wear_depth):
            raise ConfigError(
                "simulation.dynamics_update: contact-impact on a worn four-bar joint is not "
                "modelled; use 'once' (or the slider-crank)"
            )
        return four_bar.four_bar_cycles(config, model)

    return cycles


def _prescribed(function: Callable[[Config], Mapping[str, LoadCycle]]) -> CycleModel:
    # a prescribed load does not depend on the wear
    def cycles(config: Config, wear_depth: FloatArray | None) -> dict[str, LoadCycle]:
        return dict(function(config))

    return cycles


def _history(config: Config) -> dict[str, LoadCycle]:
    from jointwear.mechanism.history import history_cycle

    cycle = history_cycle(config)
    return {cycle.joint: cycle}


#: ``mechanism.type`` -> :class:`Mechanism`; its names are those of the config schema
MECHANISMS: Registry[Mechanism] = Registry("mechanism type", "mechanism.type")
MECHANISMS.add(
    "slider-crank",
    Mechanism(
        "the paper's slider-crank, clearance between connecting rod and slider",
        {
            "massless-link": _massless_link,
            "contact-impact": _contact_impact,
        },
    ),
)
MECHANISMS.add(
    "four-bar",
    Mechanism(
        "crank-rocker four-bar linkage, clearance in any of its moving joints",
        {
            "massless-link": _four_bar("massless-link"),
            "contact-impact": _four_bar("contact-impact"),
        },
    ),
)
MECHANISMS.add(
    "oscillating",
    Mechanism(
        "oscillating-bearing test: pin swinging +-amplitude under a radial load",
        {"prescribed": _prescribed(oscillating_cycle)},
    ),
)
MECHANISMS.add(
    "load-history",
    Mechanism(
        "one period of joint load from a file (CSV or netCDF), e.g. another multibody code",
        {"prescribed": _prescribed(_history)},
    ),
)
if set(MECHANISMS) != set(MECHANISM_TYPES):  # pragma: no cover - a programming error
    raise RuntimeError("mechanism registry and config schema disagree on the type names")

#: dynamics model names (``dynamics.model``)
DYNAMICS_MODELS: Registry[str] = Registry("dynamics model", "dynamics.model")
DYNAMICS_MODELS.add("massless-link", "massless-link")
DYNAMICS_MODELS.add("contact-impact", "contact-impact")

DYNAMICS_MODEL_DESCRIPTIONS = {
    "massless-link": "clearance as a massless link along the load, continuous contact "
    "(eqs. 10-12); for the four-bar the ideal-joint reaction",
    "contact-impact": "pin free in the clearance: contact force law with hysteresis damping "
    "and friction, event-driven integration (no continuous-contact assumption)",
}


def load_cycles(config: Config, wear_depth: FloatArray | None = None) -> dict[str, LoadCycle]:
    """Load cycle of every clearance joint of the configured mechanism.

    Parameters
    ----------
    config : jointwear.config.Config
        Validated configuration (SI values).
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing on the ``contact.nodes`` grid, bushing frame [m]:
        the dynamics of the worn joint (the massless link grows by the deepest wear,
        contact-impact meets the worn contour). ``None``: the unworn joint.

    Returns
    -------
    dict of str to LoadCycle
        Joint name -> its load cycle, in the order of ``config.joints``.

    Raises
    ------
    ConfigError
        If ``dynamics.model`` names no model of the mechanism type.
    """
    mechanism = MECHANISMS.get(config.mechanism.type)
    models = mechanism.models
    if "prescribed" in models:
        return dict(models["prescribed"](config, wear_depth))
    if config.dynamics.model not in models:
        DYNAMICS_MODELS.get(config.dynamics.model)
    return dict(models[config.dynamics.model](config, wear_depth))


def load_cycle(config: Config, joint: str | None = None) -> LoadCycle:
    """Load cycle of one clearance joint (default: the first of ``config.joints``).

    Parameters
    ----------
    config : jointwear.config.Config
        Validated configuration (SI values).
    joint : str, optional
        Name of the joint.
    """
    cycles = load_cycles(config)
    if joint is None:
        return next(iter(cycles.values()))
    if joint not in cycles:
        raise ConfigError(
            f"mechanism.clearance_joint: no clearance joint {joint!r}{suggest(joint, cycles)}"
        )
    return cycles[joint]
