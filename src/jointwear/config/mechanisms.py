"""The ``[mechanism]`` table: one section per mechanism type, chosen by ``type``.

:data:`MECHANISM_TYPES` is the single source of the type names (the mechanism
registry checks that it has the same); :data:`MechanismConfig` is their union,
discriminated by ``type``.
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import Field, create_model, model_validator

from jointwear.config.choices import FOUR_BAR_GEOMETRY
from jointwear.config.fields import (
    Acceleration,
    AngularVelocity,
    Force,
    Inertia,
    Length,
    Mass,
    NonNegMass,
    Section,
    Stiffness,
    si,
)

__all__ = [
    "DUTY_SHARE_TOLERANCE",
    "DYNAMIC_TYPES",
    "FOUR_BAR_JOINT_BODIES",
    "MECHANISM_TYPES",
    "DutyCycleConfig",
    "FourBarBody",
    "FourBarConfig",
    "FourBarJoint",
    "LoadHistoryConfig",
    "MechanismConfig",
    "OscillatingConfig",
    "SliderCrankConfig",
]


class SliderCrankConfig(Section):
    """Slider-crank data (paper Table 1, read in SI) and operating point.

    The clearance joint is the one between the connecting rod and the slider.
    """

    type: Literal["slider-crank"] = "slider-crank"
    crank_length: Length
    rod_length: Length
    crank_mass: NonNegMass
    rod_mass: NonNegMass
    slider_mass: NonNegMass
    rod_inertia: Inertia = None
    spring_stiffness: Stiffness
    spring_preload: Force
    spring_mode: Literal["pull", "push"] = "pull"
    crank_speed: AngularVelocity
    gravity: Acceleration = 9.81
    bushing_body: Literal["slider", "rod"] = "slider"

    @model_validator(mode="after")
    def _assembles(self) -> SliderCrankConfig:
        if self.crank_length >= self.rod_length:
            raise ValueError(
                f"mechanism.crank_length: the mechanism cannot assemble with crank_length "
                f"({self.crank_length:g} m) >= rod_length ({self.rod_length:g} m)"
            )
        return self

    @property
    def rod_centroidal_inertia(self) -> float:
        """Rod inertia about its centre [kg m^2]; ``m2 l2^2 / 12`` unless given."""
        if self.rod_inertia is not None:
            return self.rod_inertia
        return self.rod_mass * self.rod_length**2 / 12.0

    @property
    def period(self) -> float:
        """Duration of one crank revolution [s]."""
        return 2.0 * math.pi / self.crank_speed

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the clearance joints."""
        return ("rod-slider",)

    def resolved(self) -> dict[str, Any]:
        """Keys whose defaults derive from others, written out."""
        return {"rod_inertia": self.rod_centroidal_inertia}


FourBarJoint = Literal["crank-coupler", "coupler-rocker", "rocker-ground"]
FourBarBody = Literal["crank", "coupler", "rocker", "ground"]
#: the two bodies of each four-bar joint; the bushing is on the second by default
FOUR_BAR_JOINT_BODIES: dict[str, tuple[str, str]] = {
    "crank-coupler": ("crank", "coupler"),
    "coupler-rocker": ("coupler", "rocker"),
    "rocker-ground": ("rocker", "ground"),
}


class FourBarConfig(Section):
    """Four-bar linkage: ground pivots A = (0, 0) (crank) and D = (ground_length, 0).

    Crank AB turns counter-clockwise at constant speed, coupler BC, rocker DC.
    Centres of mass at the link midpoints; inertias about the centres default to
    the slender rod ``m l^2 / 12``. The rocker carries a torque about D
    (counter-clockwise positive) and a torsional spring towards
    ``rocker_spring_angle``.
    """

    type: Literal["four-bar"] = "four-bar"
    ground_length: Length
    crank_length: Length
    coupler_length: Length
    rocker_length: Length
    crank_mass: NonNegMass
    coupler_mass: NonNegMass
    rocker_mass: NonNegMass
    crank_inertia: Inertia = None
    coupler_inertia: Inertia = None
    rocker_inertia: Inertia = None
    crank_speed: AngularVelocity
    gravity: Acceleration = 9.81
    rocker_torque: Annotated[float, si("torque")] = 0.0
    rocker_spring_stiffness: Annotated[float, si("torsional_stiffness"), Field(ge=0)] = 0.0
    rocker_spring_angle: Annotated[float, si("angle"), Field(ge=-4 * math.pi, le=4 * math.pi)] = 0.0
    assembly: Literal["open", "crossed"] = "open"
    clearance_joint: FourBarJoint | list[FourBarJoint] = "coupler-rocker"
    bushing_body: FourBarBody | list[FourBarBody] | None = None

    @model_validator(mode="after")
    def _consistent(self) -> FourBarConfig:
        joints = self.joints
        if len(set(joints)) != len(joints) or not joints:
            raise ValueError("mechanism.clearance_joint: name each joint once (at least one joint)")
        bodies = self.bushing_bodies
        if len(bodies) != len(joints):
            raise ValueError(
                f"mechanism.bushing_body: give one body per clearance joint ({len(joints)})"
            )
        for joint, body in zip(joints, bodies, strict=True):
            if body not in FOUR_BAR_JOINT_BODIES[joint]:
                first, second = FOUR_BAR_JOINT_BODIES[joint]
                raise ValueError(
                    f"mechanism.bushing_body: {body!r} is not a body of joint {joint!r} "
                    f"(choose {first!r} or {second!r})"
                )
        FOUR_BAR_GEOMETRY(
            self.ground_length, self.crank_length, self.coupler_length, self.rocker_length
        )
        return self

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the clearance joints."""
        joint = self.clearance_joint
        return (joint,) if isinstance(joint, str) else tuple(joint)

    @property
    def bushing_bodies(self) -> tuple[str, ...]:
        """Body that carries the bushing, per clearance joint."""
        body = self.bushing_body
        if body is None:
            return tuple(FOUR_BAR_JOINT_BODIES[j][1] for j in self.joints)
        return (body,) if isinstance(body, str) else tuple(body)

    @property
    def period(self) -> float:
        """Duration of one crank revolution [s]."""
        return 2.0 * math.pi / self.crank_speed

    def inertia(self, link: str) -> float:
        """Centroidal inertia of ``link`` [kg m^2]; ``m l^2 / 12`` unless given."""
        given = getattr(self, f"{link}_inertia")
        if given is not None:
            return given
        return getattr(self, f"{link}_mass") * getattr(self, f"{link}_length") ** 2 / 12.0

    def resolved(self) -> dict[str, Any]:
        """Keys whose defaults derive from others, written out."""
        return {
            **{f"{link}_inertia": self.inertia(link) for link in ("crank", "coupler", "rocker")},
            "bushing_body": list(self.bushing_bodies),
            "clearance_joint": list(self.joints),
        }


class OscillatingConfig(Section):
    """Oscillating bearing test: the pin swings ``amplitude`` either way under a load.

    The pin's rotation relative to the bushing is ``amplitude sin(2 pi f t)``; one
    cycle is one full oscillation (sliding ``4 amplitude R_b``). The load is
    ``load + load_amplitude cos(2 pi load_harmonic f t + load_phase)``, directed at
    ``load_angle`` in the bushing's frame, or in the pin's (turning with it).
    """

    type: Literal["oscillating"] = "oscillating"
    load: Annotated[float, si("force"), Field(gt=0)]
    load_frame: Literal["bushing", "pin"] = "bushing"
    load_angle: Annotated[float, si("angle"), Field(ge=-4 * math.pi, le=4 * math.pi)] = 0.0
    amplitude: Annotated[float, si("angle"), Field(gt=0, le=4 * math.pi)]
    frequency: Annotated[float, si("frequency"), Field(gt=0)]
    load_amplitude: Force = 0.0
    load_harmonic: Annotated[int, Field(ge=1, le=1000)] = 1
    load_phase: Annotated[float, si("angle"), Field(ge=-4 * math.pi, le=4 * math.pi)] = 0.0
    #: mass moving with the pin (pin and loading arm): the contact-impact model's inertia
    pin_mass: Mass = 0.1

    @model_validator(mode="after")
    def _load_positive(self) -> OscillatingConfig:
        if self.load_amplitude > self.load:
            raise ValueError(
                f"mechanism.load_amplitude: {self.load_amplitude:g} N exceeds the mean load "
                f"{self.load:g} N (the load would reverse)"
            )
        return self

    @property
    def period(self) -> float:
        """Duration of one oscillation [s]."""
        return 1.0 / self.frequency

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the clearance joints."""
        return ("bearing",)

    def resolved(self) -> dict[str, Any]:
        """Keys whose defaults derive from others, written out (none)."""
        return {}


class LoadHistoryConfig(Section):
    """One period of a joint's load read from a file (CSV or netCDF).

    ``file`` is relative to the config file. CSV columns ``time``, ``force_x``,
    ``force_y`` (the force of the pin on the bushing) and ``rotation`` (cumulative
    rotation of the pin relative to the bushing), each with its unit in brackets;
    with ``frame = "global"`` the forces are global and a ``bushing_angle`` column
    gives the bushing's orientation.
    """

    type: Literal["load-history"] = "load-history"
    file: Annotated[str, Field(min_length=1)]
    frame: Literal["bushing", "global"] = "bushing"
    period: Annotated[Annotated[float, Field(gt=0)] | None, si("time")] = None
    load_scale: Annotated[float, Field(gt=0, le=1e6)] = 1.0

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the clearance joints."""
        return ("joint",)

    def resolved(self) -> dict[str, Any]:
        """Keys whose defaults derive from others, written out (none)."""
        return {}


#: the single mechanism types, each a mode of a duty cycle
SINGLE_TYPES: tuple[type[Section], ...] = (
    SliderCrankConfig,
    FourBarConfig,
    OscillatingConfig,
    LoadHistoryConfig,
)

#: mechanism types whose load comes from dynamics (the others prescribe it)
DYNAMIC_TYPES: tuple[str, ...] = ("slider-crank", "four-bar", "oscillating")

#: how far the shares of a duty cycle's modes may sum from one [-]
DUTY_SHARE_TOLERANCE = 1e-9

Share = Annotated[float, Field(gt=0, le=1)]


def _mode(cls: type[Section]) -> type[Section]:
    """The section of ``cls`` with the mode's ``share`` of the cycles [-]."""
    return create_model(f"{cls.__name__.removesuffix('Config')}Mode", __base__=cls, share=Share)


#: ``type`` -> the section of a duty cycle's mode of that type
MODE_TYPES: dict[str, type[Section]] = {
    cls.model_fields["type"].default: _mode(cls) for cls in SINGLE_TYPES
}

SliderCrankMode, FourBarMode, OscillatingMode, LoadHistoryMode = MODE_TYPES.values()
DutyMode = Annotated[
    SliderCrankMode | FourBarMode | OscillatingMode | LoadHistoryMode,
    Field(discriminator="type"),
]


class DutyCycleConfig(Section):
    """A duty cycle: several operating modes, each run in a share of the cycles.

    ``[[mechanism.modes]]`` tables, each a full ``[mechanism]`` table of a single type
    plus ``share``, the fraction of the cycles it runs [-]; the shares sum to one. The
    ``i``-th clearance joint of every mode is the same joint (named as in the first
    mode), so every mode has as many clearance joints. The wear of a cycle is the
    share-weighted sum of the modes' wear on the current contour.
    """

    type: Literal["duty-cycle"] = "duty-cycle"
    modes: Annotated[list[DutyMode], Field(min_length=1, max_length=64)]

    @model_validator(mode="before")
    @classmethod
    def _not_nested(cls, data: Any) -> Any:
        modes = data.get("modes") if isinstance(data, dict) else None
        for index, mode in enumerate(modes if isinstance(modes, list) else []):
            if isinstance(mode, dict) and mode.get("type") == "duty-cycle":
                raise ValueError(
                    f"mechanism.modes[{index}].type: a duty cycle's mode is one mechanism, "
                    f"not another duty cycle (list its modes here instead)"
                )
        return data

    @model_validator(mode="after")
    def _shares_and_joints(self) -> DutyCycleConfig:
        total = math.fsum(mode.share for mode in self.modes)
        if abs(total - 1.0) > DUTY_SHARE_TOLERANCE:
            raise ValueError(
                f"mechanism.modes.share: the shares of the modes sum to {total:.12g}, not 1 "
                f"(within {DUTY_SHARE_TOLERANCE:g}): "
                f"{' + '.join(f'{mode.share:.12g}' for mode in self.modes)}; "
                "each is the fraction of cycles in that mode"
            )
        counts = {len(mode.joints) for mode in self.modes}
        if len(counts) > 1:
            raise ValueError(
                "mechanism.modes: every mode needs as many clearance joints (the i-th joint "
                f"of each mode is the same joint); the modes have {sorted(counts)}"
            )
        return self

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the clearance joints (those of the first mode)."""
        return self.modes[0].joints

    @property
    def mode_types(self) -> tuple[str, ...]:
        """The ``type`` of each mode."""
        return tuple(mode.type for mode in self.modes)

    @property
    def period(self) -> float:
        """The longest period of a mode [s] (what bounds one integration of its dynamics)."""
        return max(getattr(mode, "period", None) or 0.0 for mode in self.modes)

    def resolved(self) -> dict[str, Any]:
        """Every mode with the keys whose defaults derive from others written out."""
        return {
            "modes": [{**mode.model_dump(mode="json"), **mode.resolved()} for mode in self.modes]
        }


#: ``mechanism.type`` -> its config section; the single source of the type names
MECHANISM_TYPES: dict[str, type[Section]] = {
    cls.model_fields["type"].default: cls for cls in (*SINGLE_TYPES, DutyCycleConfig)
}

MechanismConfig = Annotated[
    SliderCrankConfig | FourBarConfig | OscillatingConfig | LoadHistoryConfig | DutyCycleConfig,
    Field(discriminator="type"),
]
