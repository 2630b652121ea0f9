"""Mechanism dynamics (stage 1 of the pipeline: crank motion -> joint load).

A dynamics model turns a :class:`~jointwear.config.Config` into a
:class:`JointLoad` (load magnitude and azimuth on the bushing, relative rotation
of pin and bushing, per time step of one crank revolution). Models are selected
by ``dynamics.model`` through :data:`DYNAMICS_MODELS`:

=================  ==========================================================
``massless-link``  slider-crank, clearance as a massless link along the
                   load (continuous contact), paper eqs. (10)-(12)
``contact-impact`` slider-crank with the pin free in the clearance: contact
                   force law with hysteresis damping, Coulomb friction,
                   event-driven integration (:mod:`.contact_impact`)
=================  ==========================================================
"""

from __future__ import annotations

from collections.abc import Callable

from jointwear.config import Config
from jointwear.mechanism import force_laws
from jointwear.mechanism.contact_impact import (
    ContactImpactSettings,
    ContactImpactSolution,
    JointContact,
    contact_impact_load,
    solve_contact_impact,
)
from jointwear.mechanism.loads import JointLoad, wrap_angle
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
from jointwear.registry import Registry

__all__ = [
    "DYNAMICS_MODELS",
    "DYNAMICS_MODEL_DESCRIPTIONS",
    "ContactImpactSettings",
    "ContactImpactSolution",
    "JointContact",
    "JointLoad",
    "JointReaction",
    "MasslessLinkSolution",
    "SliderCrank",
    "SliderCrankMotion",
    "clearance_motion",
    "contact_impact_load",
    "contact_loss",
    "crank_angle_grid",
    "force_laws",
    "ideal_motion",
    "inverse_dynamics",
    "joint_load",
    "load_bandwidth",
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

#: name -> ``(Config) -> JointLoad``
DYNAMICS_MODELS: Registry[Callable[[Config], JointLoad]] = Registry(
    "dynamics model", "dynamics.model"
)
DYNAMICS_MODELS.add("massless-link", massless_link_load)
DYNAMICS_MODELS.add("contact-impact", contact_impact_load)

DYNAMICS_MODEL_DESCRIPTIONS = {
    "massless-link": "clearance as a massless link along the load, continuous contact "
    "(eqs. 10-12)",
    "contact-impact": "pin free in the clearance: contact force law with hysteresis damping "
    "and friction, event-driven integration (no continuous-contact assumption)",
}


def joint_load(config: Config) -> JointLoad:
    """Joint load over one crank revolution from the model named by ``dynamics.model``.

    Parameters
    ----------
    config : jointwear.config.Config
        Validated configuration (SI values).

    Returns
    -------
    JointLoad

    Raises
    ------
    ConfigError
        If ``dynamics.model`` names no registered model.
    """
    return DYNAMICS_MODELS.get(config.dynamics.model)(config)
