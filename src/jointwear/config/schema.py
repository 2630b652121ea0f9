"""The schema of a whole configuration: its sections, cross-checks and derived values.

The checks between sections (life limits against the joint, the contact model
against contour updating, the dynamics model against the mechanism type) and the
derived defaults (NLCP's spring area and stiffness) live here; the stages' own
checks and closed forms are reached through :mod:`jointwear.config.choices`.
"""

from __future__ import annotations

import math
from typing import Any

from pydantic import field_validator, model_validator

from jointwear.config.choices import IMPACT_FILM, MODEL_CHOICE, NLCP_STIFFNESS, PAPER_SPRING_AREA
from jointwear.config.fields import MAX_INTEGRATOR_STEPS, Section, one_of
from jointwear.config.greases import check_grease, wearing_bushing
from jointwear.config.mechanisms import DYNAMIC_TYPES, MechanismConfig
from jointwear.config.parameter_sets import PARAMETER_SETS
from jointwear.config.pin import PinConfig, check_along_the_pin
from jointwear.config.sections import (
    ContactConfig,
    DynamicsConfig,
    JointConfig,
    LifeConfig,
    LubricationConfig,
    MaterialConfig,
    MaterialsConfig,
    SimulationConfig,
    WearConfig,
)
from jointwear.config.wear_table import check_table

__all__ = ["ConfigSchema"]


class ConfigSchema(Section):
    """The sections of a whole configuration, their cross-checks and derived values.

    :class:`~jointwear.config.Config` adds writing and overriding; the key look-up and
    the messages walk this schema.
    """

    parameter_set: str = "nlcp-paper"
    mechanism: MechanismConfig
    joint: JointConfig
    materials: MaterialsConfig
    contact: ContactConfig = ContactConfig()
    dynamics: DynamicsConfig = DynamicsConfig()
    simulation: SimulationConfig = SimulationConfig()
    wear: WearConfig = WearConfig()
    life: LifeConfig = LifeConfig()
    pin: PinConfig = PinConfig()
    lubrication: LubricationConfig = LubricationConfig()

    @field_validator("parameter_set")
    @classmethod
    def _known_parameter_set(cls, value: str) -> str:
        # also where the defaults are not merged (Config.replace, a sweep's cases): the
        # name is recorded with the results and must be one that exists
        return one_of(value, PARAMETER_SETS, "parameter set")

    @model_validator(mode="after")
    def _life_limits_fit(self) -> ConfigSchema:
        life, joint = self.life, self.joint
        if life.clearance is not None and life.clearance <= joint.clearance:
            raise ValueError(
                f"life.clearance: the limit ({life.clearance:g} m) must exceed the initial "
                f"clearance joint.clearance ({joint.clearance:g} m)"
            )
        if life.wall_thickness >= joint.bushing_thickness:
            raise ValueError(
                f"life.wall_thickness: the limit ({life.wall_thickness:g} m) must be below "
                f"joint.bushing_thickness ({joint.bushing_thickness:g} m)"
            )
        return self

    @model_validator(mode="after")
    def _contact_model_fits(self) -> ConfigSchema:
        # a model that cannot follow a worn contour, or NLCP's paper form off its mesh,
        # would wear the wrong volume: refused before anything runs
        contact = self.contact
        MODEL_CHOICE(contact.model, self.simulation.update_contour)
        if contact.model == "nlcp" and contact.nlcp_variant == "paper":
            node = self.joint.bushing_radius * 2.0 * math.pi / contact.nodes
            PAPER_SPRING_AREA(self.spring_area, node * self.joint.axial_length, contact.nodes)
        return self

    @model_validator(mode="after")
    def _along_the_pin_fits(self) -> ConfigSchema:
        check_along_the_pin(self)
        return self

    @model_validator(mode="after")
    def _running_in_updates(self) -> ConfigSchema:
        # one revolution's wear scaled to the run would keep the new joint's coefficient
        if self.wear.law == "running-in" and not self.simulation.update_contour:
            raise ValueError(
                "wear.law: 'running-in' wears less with every cycle, which a run without "
                "contour update (one cycle's wear, scaled) cannot follow; set "
                "simulation.update_contour = true"
            )
        return self

    @model_validator(mode="after")
    def _dynamics_fits_mechanism(self) -> ConfigSchema:
        kinds = getattr(self.mechanism, "mode_types", (self.mechanism.type,))
        if self.dynamics.model == "contact-impact" and set(kinds) - set(DYNAMIC_TYPES):
            raise ValueError(
                f"dynamics.model: 'contact-impact' needs a mechanism with inertia "
                f"({', '.join(repr(t) for t in DYNAMIC_TYPES)}); mechanism.type "
                f"{self.mechanism.type!r} prescribes its load"
            )
        return self

    @model_validator(mode="after")
    def _film_fits_dynamics(self) -> ConfigSchema:
        # the contact-impact dynamics compile the short and the long bearing only
        lubrication = self.lubrication
        if self.dynamics.model != "contact-impact" or not lubrication.lubricated:
            return self
        if lubrication.model == "finite-length":
            ratio = self.joint.axial_length / (2.0 * self.joint.pin_radius)
            nearer = "short-bearing" if ratio < 1.0 else "long-bearing"
            raise ValueError(
                "lubrication.model: 'finite-length' has no film in dynamics.model = "
                f"'contact-impact'; use {nearer!r} (the nearer at the joint's L/D = "
                f"{ratio:.3g}), or dynamics.model = 'massless-link' for the finite-length film "
                "on the load cycle"
            )
        IMPACT_FILM(lubrication.model, lubrication.roughness, self.joint.clearance)
        return self

    @model_validator(mode="after")
    def _grease_has_coefficient(self) -> ConfigSchema:
        check_grease(self)
        return self

    @model_validator(mode="after")
    def _table_complete(self) -> ConfigSchema:
        # a tabulated law without a [wear] table runs the bushing material's
        check_table(self.wear, self.materials.bushing)
        return self

    @model_validator(mode="after")
    def _integration_bounded(self) -> ConfigSchema:
        # the contact-impact integrator takes at least span / max_step steps: refused up
        # front where that would run for hours instead of failing after them
        dynamics = self.dynamics
        if dynamics.model != "contact-impact" or dynamics.max_step is None:
            return self
        revolutions = dynamics.revolutions_settle + 1
        span = revolutions * self.mechanism.period
        steps = span / dynamics.max_step
        if steps > MAX_INTEGRATOR_STEPS:
            raise ValueError(
                f"dynamics.max_step: {dynamics.max_step:g} s makes at least {steps:.3g} "
                f"integrator steps over {revolutions} revolution(s) of {self.mechanism.period:g} s "
                f"(at most {MAX_INTEGRATOR_STEPS:.0e}); give a larger step"
            )
        return self

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the mechanism's clearance joints."""
        return self.mechanism.joints

    @property
    def wearing_bushing(self) -> MaterialConfig:
        """The bushing's material as it wears: with a grease and no film model, its
        ``boundary_wear_coefficient`` is its ``wear_coefficient`` [m^2/N]
        (:mod:`jointwear.config.greases`)."""
        return wearing_bushing(self)

    @property
    def bushing_radius(self) -> float:
        """Unworn bushing inner radius [m]."""
        return self.joint.bushing_radius

    @property
    def default_spring_area(self) -> float:
        """Area of a 1 degree spring at the unworn bushing radius [m^2]."""
        return self.joint.bushing_radius * math.radians(1.0) * self.joint.axial_length

    @property
    def spring_area(self) -> float:
        """NLCP spring area [m^2]: ``contact.spring_area`` or the 1 degree default."""
        if self.contact.spring_area is not None:
            return self.contact.spring_area
        return self.default_spring_area

    @property
    def nlcp_stiffness(self) -> float:
        """NLCP spring stiffness ``K`` [N/m^n]: ``contact.stiffness`` or eq. (2)."""
        if self.contact.stiffness is not None:
            return self.contact.stiffness
        pin, bushing = self.materials.pin, self.materials.bushing
        return float(
            NLCP_STIFFNESS(
                self.joint.pin_radius,
                pin.youngs_modulus,
                pin.poisson_ratio,
                bushing.youngs_modulus,
                bushing.poisson_ratio,
            )
        )

    def to_dict(self) -> dict[str, Any]:
        """Fully resolved config as plain data (SI numbers, every default written)."""
        data = self.model_dump(mode="json")
        data["mechanism"].update(self.mechanism.resolved())
        data["contact"]["spring_area"] = self.spring_area
        data["contact"]["stiffness"] = self.nlcp_stiffness
        return data
