"""Validated configuration: TOML in, SI floats out.

Every quantity in a config file is a plain number (SI) or a string with units
(``"0.2 mm"``, ``"240 rpm"``); a plain number that can only be a unit slip is
refused (:func:`check_bare_numbers`). :func:`load_config` reads a file, applies
``--set section.key=VALUE`` overrides and returns a :class:`Config` whose
fields are SI floats. Any problem raises :class:`~jointwear.errors.ConfigError`
with a one-line message that starts with the dotted key.

Defaults come from a named parameter set (:mod:`jointwear.parameter_sets`),
``nlcp-paper`` unless the file says ``parameter_set = "..."``.
"""

from __future__ import annotations

import copy
import math
import tomllib
import types
import typing
from collections.abc import Iterable, Iterator, Mapping
from pathlib import Path
from typing import Annotated, Any, Literal

import tomli_w
from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    ValidationInfo,
    field_validator,
    model_validator,
)

from jointwear.errors import ConfigError
from jointwear.parameter_sets import PARAMETER_SETS, get_parameter_set
from jointwear.registry import suggest
from jointwear.units import (
    BARE_LIMITS,
    DIMENSIONS,
    MAX_MAGNITUDE,
    bare_number,
    check_bare,
    shown,
    to_si,
    to_si_unit,
)

#: largest count of revolutions, updates or checkpoints a config can ask for
MAX_COUNT = 10**9
#: most steps the contact-impact integrator may be forced to take by dynamics.max_step
MAX_INTEGRATOR_STEPS = 10**7

__all__ = [
    "MECHANISM_TYPES",
    "Config",
    "ContactConfig",
    "DynamicsConfig",
    "FourBarConfig",
    "JointConfig",
    "LifeConfig",
    "LoadHistoryConfig",
    "MaterialConfig",
    "MechanismConfig",
    "OscillatingConfig",
    "SimulationConfig",
    "SliderCrankConfig",
    "WearConfig",
    "apply_overrides",
    "check_bare_numbers",
    "config_from_dict",
    "error_key",
    "field_kind",
    "is_section",
    "key_field",
    "load_config",
    "normalized_overrides",
    "parse_override",
    "read_toml",
]


#: the converters of :func:`_si` -> their physical kind (read by :func:`field_kind`)
_KIND_OF: dict[Any, str] = {}


def _si(kind: str):
    def convert(value: Any) -> Any:
        if value is None:
            return None
        try:
            return to_si(value, kind, "§")
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ")) from None

    _KIND_OF[convert] = kind
    return BeforeValidator(convert)


def field_kind(info: Any) -> str | None:
    """Physical kind (a key of :data:`~jointwear.units.DIMENSIONS`) of a config field.

    Parameters
    ----------
    info : pydantic.fields.FieldInfo
        A field, e.g. from :func:`key_field`.

    Returns
    -------
    str or None
        ``"length"``, ``"angular_velocity"``, ...; None for a field without units.
    """
    items = [*info.metadata, info.annotation]
    while items:
        item = items.pop()
        if isinstance(item, BeforeValidator) and item.func in _KIND_OF:
            return _KIND_OF[item.func]
        if typing.get_origin(item) in (typing.Annotated, typing.Union, types.UnionType):
            items.extend(typing.get_args(item))
    return None


Length = Annotated[float, _si("length"), Field(gt=0)]
NonNegLength = Annotated[float, _si("length"), Field(ge=0)]
Mass = Annotated[float, _si("mass"), Field(gt=0)]
NonNegMass = Annotated[float, _si("mass"), Field(ge=0)]
Force = Annotated[float, _si("force"), Field(ge=0)]
Stiffness = Annotated[float, _si("stiffness"), Field(ge=0)]
Pressure = Annotated[float, _si("pressure"), Field(gt=0)]
AngularVelocity = Annotated[float, _si("angular_velocity"), Field(gt=0)]
Acceleration = Annotated[float, _si("acceleration"), Field(ge=0)]
Density = Annotated[float, _si("density"), Field(gt=0)]
WearCoefficient = Annotated[float, _si("wear_coefficient"), Field(ge=0)]
PoissonRatio = Annotated[float, _si("dimensionless"), Field(gt=-1.0, lt=0.5)]
OptionalPressure = Annotated[Annotated[float, Field(gt=0)] | None, _si("pressure")]
Inertia = Annotated[Annotated[float, Field(ge=0)] | None, _si("moment_of_inertia")]


def _scalar_types(annotation: Any) -> frozenset[type]:
    """The scalar types a field annotation admits (through Annotated, unions, Literal)."""
    origin = typing.get_origin(annotation)
    if origin is typing.Annotated:
        return _scalar_types(typing.get_args(annotation)[0])
    if origin in (typing.Union, types.UnionType):
        return frozenset().union(*(_scalar_types(a) for a in typing.get_args(annotation)))
    if origin is typing.Literal:
        return frozenset(type(a) for a in typing.get_args(annotation))
    return frozenset({annotation}) if isinstance(annotation, type) else frozenset()


def _one_of(value: str, names: Iterable[str], what: str) -> str:
    """``value`` if it is one of ``names``, else a ValueError with the best match."""
    if value not in names:
        raise ValueError(f"unknown {what} {value!r}{suggest(value, names)}")
    return value


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=True)

    @model_validator(mode="before")
    @classmethod
    def _plain_numbers(cls, data: Any) -> Any:
        # pydantic reads true as 1 for a number field; and float() of an integer of
        # hundreds of digits overflows: both are refused here, for every section
        if not isinstance(data, Mapping):
            return data
        for name, value in data.items():
            if not isinstance(value, int) or name not in cls.model_fields:
                continue
            accepted = _scalar_types(cls.model_fields[name].annotation)
            if not accepted & {int, float}:
                continue
            if isinstance(value, bool) and bool not in accepted:
                raise ValueError(f"{_FIELD}{name}: expected a number, got a boolean")
            if not isinstance(value, bool) and abs(value) > MAX_MAGNITUDE:
                raise ValueError(
                    f"{_FIELD}{name}: {shown(value)} is beyond any physical value "
                    f"(|value| <= {MAX_MAGNITUDE:g})"
                )
        return data


#: marks a section validator's message that starts with the field's name
_FIELD = "field "


class SliderCrankConfig(_Section):
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


class FourBarConfig(_Section):
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
    rocker_torque: Annotated[float, _si("torque")] = 0.0
    rocker_spring_stiffness: Annotated[float, _si("torsional_stiffness"), Field(ge=0)] = 0.0
    rocker_spring_angle: Annotated[float, _si("angle"), Field(ge=-4 * math.pi, le=4 * math.pi)] = (
        0.0
    )
    assembly: Literal["open", "crossed"] = "open"
    clearance_joint: FourBarJoint | list[FourBarJoint] = "coupler-rocker"
    bushing_body: FourBarBody | list[FourBarBody] | None = None

    @model_validator(mode="after")
    def _consistent(self) -> FourBarConfig:
        joints = self.joints
        if len(set(joints)) != len(joints) or not joints:
            raise ValueError(
                "mechanism.clearance_joint: name each joint once (at least one joint)"
            )
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
        from jointwear.mechanism.four_bar import check_four_bar

        check_four_bar(
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


class OscillatingConfig(_Section):
    """Oscillating bearing test: the pin swings ``amplitude`` either way under a load.

    The pin's rotation relative to the bushing is ``amplitude sin(2 pi f t)``; one
    cycle is one full oscillation (sliding ``4 amplitude R_b``). The load is
    ``load + load_amplitude cos(2 pi load_harmonic f t + load_phase)``, directed at
    ``load_angle`` in the bushing's frame, or in the pin's (turning with it).
    """

    type: Literal["oscillating"] = "oscillating"
    load: Annotated[float, _si("force"), Field(gt=0)]
    load_frame: Literal["bushing", "pin"] = "bushing"
    load_angle: Annotated[float, _si("angle"), Field(ge=-4 * math.pi, le=4 * math.pi)] = 0.0
    amplitude: Annotated[float, _si("angle"), Field(gt=0, le=4 * math.pi)]
    frequency: Annotated[float, _si("frequency"), Field(gt=0)]
    load_amplitude: Force = 0.0
    load_harmonic: Annotated[int, Field(ge=1, le=1000)] = 1
    load_phase: Annotated[float, _si("angle"), Field(ge=-4 * math.pi, le=4 * math.pi)] = 0.0

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


class LoadHistoryConfig(_Section):
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
    period: Annotated[Annotated[float, Field(gt=0)] | None, _si("time")] = None
    load_scale: Annotated[float, Field(gt=0, le=1e6)] = 1.0

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the clearance joints."""
        return ("joint",)

    def resolved(self) -> dict[str, Any]:
        """Keys whose defaults derive from others, written out (none)."""
        return {}


#: ``mechanism.type`` -> its config section; the single source of the type names
MECHANISM_TYPES: dict[str, type[_Section]] = {
    cls.model_fields["type"].default: cls
    for cls in (SliderCrankConfig, FourBarConfig, OscillatingConfig, LoadHistoryConfig)
}

#: mechanism types whose load comes from dynamics (the others prescribe it)
DYNAMIC_TYPES: tuple[str, ...] = ("slider-crank", "four-bar")

_MECHANISM_UNION = object()  # marks the union while walking keys (see key_field)

MechanismConfig = Annotated[
    SliderCrankConfig | FourBarConfig | OscillatingConfig | LoadHistoryConfig,
    Field(discriminator="type"),
]


class JointConfig(_Section):
    """Clearance joint geometry (paper Table 2, read in SI)."""

    pin_radius: Length
    clearance: Length
    axial_length: Length
    bushing_thickness: Length

    @property
    def bushing_radius(self) -> float:
        """Unworn bushing inner radius [m] = pin radius + radial clearance."""
        return self.pin_radius + self.clearance


class MaterialConfig(_Section):
    """Elastic (and, for the bushing, wear) properties of one body, and its datasheet limits.

    ``name`` is a material of the library (:mod:`jointwear.materials`) whose values the
    other keys override. Wear comes as ``wear_coefficient`` (``K_d`` [m^2/N]),
    ``specific_wear_rate`` ([mm^3/(N m)], the same dimension) or ``wear_factor_k`` with
    ``hardness`` (``K_d = k / H``), one of them; the last three are read into
    ``wear_coefficient`` and not written back out.
    """

    name: str | None = None
    youngs_modulus: Pressure
    poisson_ratio: PoissonRatio
    density: Density | None = None
    wear_coefficient: WearCoefficient | None = None
    specific_wear_rate: Annotated[
        Annotated[float, Field(ge=0)] | None, _si("wear_coefficient"), Field(exclude=True)
    ] = None
    wear_factor_k: Annotated[
        Annotated[float, Field(ge=0)] | None, _si("dimensionless"), Field(exclude=True)
    ] = None
    hardness: Annotated[
        Annotated[float, Field(gt=0)] | None, _si("pressure"), Field(exclude=True)
    ] = None
    max_static_pressure: OptionalPressure = None
    max_dynamic_pressure: OptionalPressure = None
    max_pv: Annotated[Annotated[float, Field(gt=0)] | None, _si("pressure_velocity")] = None
    max_sliding_speed: Annotated[Annotated[float, Field(gt=0)] | None, _si("velocity")] = None

    @model_validator(mode="after")
    def _one_wear_form(self) -> MaterialConfig:
        from jointwear.materials import wear_coefficient

        values = {
            k: getattr(self, k)
            for k in ("wear_coefficient", "specific_wear_rate", "wear_factor_k", "hardness")
        }
        try:
            coefficient = wear_coefficient(values, "§")
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ").removeprefix("§.")) from None
        # the other forms are read into K_d and not kept, so that a config equals the one
        # read back from its TOML (the model is frozen once validated)
        object.__setattr__(self, "wear_coefficient", coefficient)
        for key in ("specific_wear_rate", "wear_factor_k", "hardness"):
            object.__setattr__(self, key, None)
        return self


#: marks a section that is also set as a whole: a library name, or a table
_NAMED = {"material": "a library name or a table"}


def _material(part: str) -> BeforeValidator:
    """Resolve a library name (``"bronze"``, or a table with ``name``) into the table."""

    def resolve(value: Any) -> Any:
        from jointwear.materials import resolve_material

        try:
            return resolve_material(value, f"materials.{part}", wear=part == "bushing")
        except ConfigError as exc:
            raise ValueError(str(exc)) from None

    return BeforeValidator(resolve)


class MaterialsConfig(_Section):
    """The pin's and the bushing's material (a library name or a table each)."""

    pin: Annotated[MaterialConfig, _material("pin"), Field(json_schema_extra=_NAMED)]
    bushing: Annotated[MaterialConfig, _material("bushing"), Field(json_schema_extra=_NAMED)]

    @model_validator(mode="after")
    def _bushing_complete(self) -> MaterialsConfig:
        for key in ("density", "wear_coefficient"):
            if getattr(self.bushing, key) is None:
                raise ValueError(f"materials.bushing.{key}: missing (needed for wear)")
        return self


class ContactConfig(_Section):
    """Contact pressure model and the load-balance solver."""

    #: Winkler's springs on the real contour: the load balances on a worn contour too
    model: str = "asymmetric-winkler"
    exponent: Annotated[float, Field(gt=0, le=10)] = 1.5
    nodes: Annotated[int, Field(ge=16, le=200_000)] = 360
    tolerance: Annotated[float, _si("force"), Field(gt=0)] = 1e-12
    max_iterations: Annotated[int, Field(ge=1, le=10_000)] = 100
    #: the thin-layer modulus of a wall bonded in its housing (docs/models.md)
    foundation_modulus: Literal["youngs", "constrained"] = "constrained"
    spring_area: Annotated[Annotated[float, Field(gt=0)] | None, _si("area")] = None
    balance: Literal["paper", "equilibrium"] = "paper"
    nlcp_variant: Literal["paper", "mesh-independent"] = "paper"
    #: NLCP spring stiffness K [N/m^n]; None: eq. (2), 4/3 E* sqrt(R_p)
    stiffness: float | None = None

    @field_validator("stiffness", mode="before")
    @classmethod
    def _stiffness_in_si(cls, value: Any, info: ValidationInfo) -> Any:
        # the unit of K depends on the exponent (N/m**n): converted here, where the
        # (already validated) exponent is known
        if value is None:
            return None
        exponent = info.data.get("exponent")
        if exponent is None:
            raise ValueError("needs a valid contact.exponent")
        try:
            stiffness = to_si_unit(value, f"N/m**{exponent:g}", "§")
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ")) from None
        if not stiffness > 0:
            raise ValueError(f"must be > 0, got {value!r}")
        return stiffness

    @field_validator("model")
    @classmethod
    def _known_model(cls, value: str) -> str:
        from jointwear.contact import CONTACT_MODELS

        return _one_of(value, CONTACT_MODELS, "contact model")


class DynamicsConfig(_Section):
    """Which dynamics model produces the joint load, and its settings.

    The keys from ``force_law`` on belong to ``model = "contact-impact"``
    (:mod:`jointwear.mechanism.contact_impact`); velocities are m/s or strings
    with units (``"0.1 mm/s"``).
    """

    model: str = "massless-link"
    strict: bool = False
    scheme: Literal["fixed-point", "paper"] = "fixed-point"
    fixed_point_tolerance: Annotated[float, Field(gt=0, lt=1)] = 1e-12
    max_iterations: Annotated[int, Field(ge=1, le=1000)] = 50
    # contact-impact model
    force_law: Literal["lankarani-nikravesh", "hunt-crossley", "flores", "nlcp", "winkler"] = (
        "lankarani-nikravesh"
    )
    restitution: Annotated[float, Field(gt=0, le=1)] = 0.9
    friction_coefficient: Annotated[float, Field(ge=0, le=10)] = 0.0
    friction_velocity_tolerance: Annotated[float, _si("velocity"), Field(gt=0)] = 1e-4
    friction_velocity_full: Annotated[Annotated[float, Field(gt=0)] | None, _si("velocity")] = None
    impact_velocity_floor: Annotated[float, _si("velocity"), Field(gt=0)] = 1e-3
    integrator: Literal["LSODA", "Radau", "BDF", "RK45", "DOP853"] = "LSODA"
    rtol: Annotated[float, Field(gt=0, lt=1)] = 1e-8
    atol: Annotated[float, Field(gt=0)] = 1e-10
    revolutions_settle: Annotated[int, Field(ge=0, le=10_000)] = 2
    max_step: Annotated[Annotated[float, Field(gt=0)] | None, _si("time")] = None

    @model_validator(mode="after")
    def _friction_ramp(self) -> DynamicsConfig:
        full = self.friction_velocity_full
        if full is not None and full <= self.friction_velocity_tolerance:
            raise ValueError(
                f"dynamics.friction_velocity_full: must be > friction_velocity_tolerance "
                f"({self.friction_velocity_tolerance:g} m/s), got {full:g} m/s"
            )
        return self

    @field_validator("model")
    @classmethod
    def _known_model(cls, value: str) -> str:
        from jointwear.mechanism import DYNAMICS_MODELS

        return _one_of(value, DYNAMICS_MODELS, "dynamics model")


class SimulationConfig(_Section):
    """Time discretisation, number of revolutions and contour updates."""

    steps_per_revolution: Annotated[int, Field(ge=8, le=1_000_000)] = 360
    revolutions: Annotated[int, Field(ge=1, le=MAX_COUNT)] = 1
    update_contour: bool = False
    update_every: Annotated[int, Field(ge=1, le=MAX_COUNT)] | Literal["adaptive"] = 1
    adaptive_tolerance: Annotated[float, Field(gt=0, lt=1)] = 2e-3
    sliding: Literal["relative-rotation", "contact-azimuth"] = "relative-rotation"
    width_threshold: Annotated[float, Field(gt=0, lt=1)] = 0.01
    saved_profiles: Annotated[int, Field(ge=1, le=100_000)] = 11
    checkpoint_every: Annotated[int, Field(ge=0, le=MAX_COUNT)] = 0
    #: re-solve the dynamics on the worn joint: never, every K contour updates, or
    #: whenever the load cycle would move by more than dynamics_tolerance
    dynamics_update: Annotated[int, Field(ge=1, le=MAX_COUNT)] | Literal["once", "adaptive"] = (
        "once"
    )
    dynamics_tolerance: Annotated[float, Field(gt=0, lt=1)] = 0.02

    @property
    def contact_solves(self) -> int:
        """Most contact solves (revolutions of the load balance) the run can need.

        ``revolutions / update_every`` for a fixed interval, ``revolutions`` for adaptive
        updating (every jump covers at least one revolution), one without contour update.
        Read from the configuration alone, so that a choice made from it (which kernel,
        which right-hand side) is the same in a run resumed from its checkpoint.
        """
        if not self.update_contour:
            return 1
        if self.update_every == "adaptive":
            return self.revolutions
        return math.ceil(self.revolutions / self.update_every)


class WearConfig(_Section):
    """The wear law and its coefficients (``archard`` uses the bushing's wear coefficient)."""

    law: str = "archard"
    energy_coefficient: Annotated[
        Annotated[float, Field(gt=0)] | None, _si("wear_coefficient")
    ] = None
    friction_coefficient: Annotated[float | None, Field(gt=0, le=10)] = None

    @field_validator("law")
    @classmethod
    def _known_law(cls, value: str) -> str:
        from jointwear.tribology.wear_laws import WEAR_LAWS

        return _one_of(value, WEAR_LAWS, "wear law")

    @model_validator(mode="after")
    def _energy_complete(self) -> WearConfig:
        if self.law == "energy":
            for key in ("energy_coefficient", "friction_coefficient"):
                if getattr(self, key) is None:
                    raise ValueError(f"wear.{key}: missing (needed by wear.law = 'energy')")
        return self


class LifeConfig(_Section):
    """Wear limits: the run stops where the first one is reached (inside a revolution).

    ``wall_thickness`` is the least remaining wall; its default 0 stops the run where
    wear goes through the wall.
    """

    peak_wear_depth: Annotated[Annotated[float, Field(gt=0)] | None, _si("length")] = None
    wear_mass: Annotated[Annotated[float, Field(gt=0)] | None, _si("mass")] = None
    wear_volume: Annotated[Annotated[float, Field(gt=0)] | None, _si("volume")] = None
    clearance: Annotated[Annotated[float, Field(gt=0)] | None, _si("length")] = None
    wall_thickness: NonNegLength = 0.0



class Config(_Section):
    """A whole jointwear configuration (all values SI)."""

    parameter_set: str = "nlcp-paper"
    mechanism: MechanismConfig
    joint: JointConfig
    materials: MaterialsConfig
    contact: ContactConfig = ContactConfig()
    dynamics: DynamicsConfig = DynamicsConfig()
    simulation: SimulationConfig = SimulationConfig()
    wear: WearConfig = WearConfig()
    life: LifeConfig = LifeConfig()

    @field_validator("parameter_set")
    @classmethod
    def _known_parameter_set(cls, value: str) -> str:
        # also where the defaults are not merged (Config.replace, a sweep's cases): the
        # name is recorded with the results and must be one that exists
        return _one_of(value, PARAMETER_SETS, "parameter set")

    @model_validator(mode="after")
    def _life_limits_fit(self) -> Config:
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
    def _contact_model_fits(self) -> Config:
        # a model that cannot follow a worn contour, or NLCP's paper form off its mesh,
        # would wear the wrong volume: refused before anything runs
        from jointwear.contact import check_model_choice, check_paper_spring_area

        contact = self.contact
        check_model_choice(contact.model, self.simulation.update_contour)
        if contact.model == "nlcp" and contact.nlcp_variant == "paper":
            node = self.joint.bushing_radius * 2.0 * math.pi / contact.nodes
            check_paper_spring_area(self.spring_area, node * self.joint.axial_length, contact.nodes)
        return self

    @model_validator(mode="after")
    def _dynamics_fits_mechanism(self) -> Config:
        if self.dynamics.model == "contact-impact" and self.mechanism.type not in DYNAMIC_TYPES:
            raise ValueError(
                f"dynamics.model: 'contact-impact' needs a mechanism with inertia "
                f"({', '.join(repr(t) for t in DYNAMIC_TYPES)}); mechanism.type "
                f"{self.mechanism.type!r} prescribes its load"
            )
        return self

    @model_validator(mode="after")
    def _integration_bounded(self) -> Config:
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
        from jointwear.contact.nlcp import stiffness

        pin, bushing = self.materials.pin, self.materials.bushing
        return float(
            stiffness(
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

    def to_toml(self) -> str:
        """The resolved config as TOML text (SI units, noted in comments).

        A value a bare number would not be taken for (:func:`check_bare_numbers`, e.g.
        an angle of more than a turn) is written with its SI unit, so that the text
        reads back as the same config.
        """
        data = self.to_dict()
        for values, name, _, kind, limit in list(_bare_limited(data, self.mechanism.type)):
            value = values[name]
            if isinstance(value, float) and abs(value) > limit:
                values[name] = f"{value!r} {DIMENSIONS[kind]}"  # reads back exactly
        return tomli_w.dumps(_toml_ready(data))

    def replace(self, overrides: Mapping[str, Any] | Iterable[str] | str) -> Config:
        """Return a new config with dotted-key overrides applied and validated.

        Parameters
        ----------
        overrides : mapping, iterable of str, or str
            ``{"joint.clearance": "0.2 mm"}``, ``["joint.clearance=0.2 mm"]`` or
            ``"joint.clearance=0.2 mm"``; quantities as SI numbers or strings with units.

        Raises
        ------
        ConfigError
            For overrides of another form, an unknown key or an invalid value.
        """
        # the raw fields, not to_dict(): derived defaults (rod inertia from the rod
        # mass, spring area from the axial length) must follow the overrides
        data = _without_none(self.model_dump(mode="json"))
        apply_overrides(data, overrides)
        return config_from_dict(data, defaults=False)


# ---------------------------------------------------------------- keys


def key_field(dotted: str, mechanism: str | None = None) -> Any:
    """The pydantic field of a dotted config key, e.g. ``"joint.clearance"``.

    Parameters
    ----------
    dotted : str
        Dotted key; sections are separated by dots.
    mechanism : str, optional
        Mechanism type whose ``mechanism.*`` keys are meant; default any type that
        has the key (the first in :data:`MECHANISM_TYPES` order).

    Returns
    -------
    pydantic.fields.FieldInfo or type
        The field of a key; the section model of a section (the field of a section
        that can also be set as a whole, ``materials.bushing``).

    Raises
    ------
    ConfigError
        For an unknown key (with the closest known key) or a key inside a value.
    """
    model: Any = Config
    parts = dotted.split(".")
    for i, part in enumerate(parts):
        if model is _MECHANISM_UNION:
            candidates = (
                [MECHANISM_TYPES[mechanism]] if mechanism in MECHANISM_TYPES
                else list(MECHANISM_TYPES.values())
            )
            owner = next((c for c in candidates if part in c.model_fields), candidates[0])
            model = owner
        fields = getattr(model, "model_fields", None)
        if fields is None:
            raise ConfigError(f"{dotted}: {parts[i - 1]!r} is a value, not a section")
        if part not in fields:
            if model is MECHANISM_TYPES.get(mechanism or "") or model in MECHANISM_TYPES.values():
                known = sorted({k for c in candidates for k in c.model_fields})
            else:
                known = list(fields)
            prefix = ".".join(parts[:i])
            what = f"unknown key {part!r}" + (f" in [{prefix}]" if prefix else "")
            raise ConfigError(f"{dotted}: {what}{suggest(part, known)}")
        info = fields[part]
        annotation = info.annotation
        if i == len(parts) - 1 and _takes_a_name(info):
            return info  # a section that is also set as a whole: materials.bushing = "bronze"
        if model is Config and part == "mechanism":
            model = _MECHANISM_UNION
        elif isinstance(annotation, type) and issubclass(annotation, BaseModel):
            model = annotation
        else:
            model = None
            if i < len(parts) - 1:
                raise ConfigError(f"{dotted}: {part!r} is a value, not a section")
            return info
    return model


def is_section(dotted: str) -> bool:
    """True if ``dotted`` names a config section (``"joint"``, ``"materials.pin"``)."""
    from pydantic.fields import FieldInfo

    try:
        found = key_field(dotted)
    except ConfigError:
        return False
    return not isinstance(found, FieldInfo) or _takes_a_name(found)


def _takes_a_name(info: Any) -> bool:
    """True for a section field that also takes a value as a whole (a material name)."""
    return isinstance(info.json_schema_extra, dict) and "material" in info.json_schema_extra


#: a bare length of a mechanism's link above this [m] is taken for a unit slip (the
#: joint's parts and the life limits: the much smaller ``BARE_LIMITS["length"]``)
BARE_LINK_LENGTH = 10.0


def _bare_limited(
    data: Mapping[str, Any], mechanism: str | None, prefix: str = ""
) -> Iterator[tuple[Mapping[str, Any], str, str, str, float]]:
    """(section, name, dotted key, kind, limit) of each value of ``data`` whose key has
    a plausible largest bare number (:data:`jointwear.units.BARE_LIMITS`)."""
    from pydantic.fields import FieldInfo

    for name, value in data.items():
        dotted = f"{prefix}{name}"
        if isinstance(value, Mapping):
            yield from _bare_limited(value, mechanism, f"{dotted}.")
            continue
        try:
            info = key_field(dotted, mechanism)
        except ConfigError:
            continue
        kind = field_kind(info) if isinstance(info, FieldInfo) else None
        if kind == "length" and dotted.startswith("mechanism."):
            yield data, name, dotted, kind, BARE_LINK_LENGTH
        elif kind in BARE_LIMITS:
            yield data, name, dotted, kind, BARE_LIMITS[kind][0]


def check_bare_numbers(data: Mapping[str, Any], mechanism: str | None = None) -> None:
    """Refuse the bare numbers of a config as written that are almost surely unit slips.

    A bare number is SI; one beyond the plausible magnitude of its key (an angle of
    more than a turn, a joint's part of more than a metre, ...; see
    :func:`jointwear.units.check_bare`) is refused with a message that says how it
    was read and how to give a unit. :func:`load_config` applies it to files and
    ``--set``; :meth:`Config.to_toml` writes such values with their unit.

    Parameters
    ----------
    data : mapping
        Nested sections as written (or dotted keys: ``{"joint.clearance": 0.1}``).
    mechanism : str, optional
        Mechanism type whose keys ``mechanism.*`` are; default ``data``'s.

    Raises
    ------
    ConfigError
        ``mechanism.amplitude: 35 is read as 35 rad (a bare number is SI), more than
        6.283 rad; give a unit, e.g. "35 deg"``.
    """
    if mechanism is None:
        section = data.get("mechanism")
        given = section.get("type", "slider-crank") if isinstance(section, Mapping) else None
        mechanism = given if isinstance(given, str) else None
    for values, name, dotted, kind, limit in _bare_limited(data, mechanism):
        check_bare(values[name], kind, dotted, limit)


# ---------------------------------------------------------------- loading


def _without_none(data: Mapping[str, Any]) -> dict[str, Any]:
    return {
        key: _without_none(value) if isinstance(value, Mapping) else value
        for key, value in data.items()
        if value is not None
    }


def _deep_merge(base: dict[str, Any], update: Mapping[str, Any]) -> dict[str, Any]:
    out = copy.deepcopy(base)
    for key, value in update.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), dict):
            out[key] = _deep_merge(out[key], value)
        else:
            out[key] = copy.deepcopy(value)
    return out


def parse_override(text: str) -> tuple[str, Any]:
    """Split ``section.key=VALUE``; VALUE is read as a TOML literal, else kept as text."""
    key, sep, raw = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise ConfigError(f"--set {text!r}: expected section.key=VALUE")
    raw = raw.strip()
    try:
        value = tomllib.loads(f"v = {raw}")["v"]
    except tomllib.TOMLDecodeError:
        value = raw
    except ValueError:  # an integer of thousands of digits (Python's conversion limit)
        raise ConfigError(f"{key}: {shown(raw)} is beyond any physical value") from None
    return key, value


def normalized_overrides(
    overrides: Mapping[str, Any] | Iterable[str] | str,
) -> list[tuple[str, Any]]:
    """The ``(dotted key, value)`` pairs of overrides given in any of their forms.

    Parameters
    ----------
    overrides : mapping, iterable of str, or str
        A dotted-key mapping, ``"section.key=VALUE"`` strings (``--set``), or one such string.

    Raises
    ------
    ConfigError
        For anything else, or a string that is not ``section.key=VALUE``.
    """
    if isinstance(overrides, Mapping):
        return list(overrides.items())
    if isinstance(overrides, str):
        return [parse_override(overrides)]
    if isinstance(overrides, Iterable) and not isinstance(overrides, bytes | bytearray):
        items = list(overrides)
        for item in items:
            if not isinstance(item, str):
                raise ConfigError(
                    f"overrides: expected 'section.key=VALUE' strings, got {shown(item)}"
                )
        return [parse_override(item) for item in items]
    raise ConfigError(
        "overrides: expected a mapping of dotted keys or 'section.key=VALUE' strings, "
        f"got {type(overrides).__name__}"
    )


def apply_overrides(
    data: dict[str, Any], overrides: Mapping[str, Any] | Iterable[str] | str
) -> None:
    """Apply dotted-key overrides in place (a mapping, ``key=value`` strings or one such
    string, :func:`normalized_overrides`)."""
    for dotted, value in normalized_overrides(overrides):
        if not isinstance(dotted, str) or not dotted:
            raise ConfigError(f"{dotted!r}: a config key is a dotted name, e.g. 'joint.clearance'")
        parts = dotted.split(".")
        if _material_override(data, parts, value):
            continue
        node = data
        for part in parts[:-1]:
            child = node.setdefault(part, {})
            if not isinstance(child, dict):
                raise ConfigError(f"{dotted}: {part!r} is a value, not a section")
            node = child
        node[parts[-1]] = value


def _material_override(data: dict[str, Any], parts: list[str], value: Any) -> bool:
    """Apply an override of ``materials.pin|bushing[.key]`` (True if it was one).

    A name replaces the material's table; a key updates it (a named material becomes a
    table naming it), and a wear form drops the others (:func:`materials.merge_material`).
    """
    if not (2 <= len(parts) <= 3 and parts[0] == "materials" and parts[1] in ("pin", "bushing")):
        return False
    from jointwear.materials import merge_material

    materials = data.setdefault("materials", {})
    if not isinstance(materials, dict):
        raise ConfigError(f"{'.'.join(parts)}: 'materials' is a value, not a section")
    update = value if len(parts) == 2 else {parts[2]: value}
    materials[parts[1]] = merge_material(materials.get(parts[1], {}), update)
    return True


def _material_defaults(defaults: dict[str, Any], data: Mapping[str, Any]) -> dict[str, Any]:
    """The parameter set's defaults under a config's materials: a named material drops
    them, a wear form drops the defaults' other forms."""
    given = data.get("materials")
    if not isinstance(given, Mapping) or not isinstance(defaults.get("materials"), dict):
        return defaults
    from jointwear.materials import merge_material

    out = copy.deepcopy(defaults)
    for part in ("pin", "bushing"):
        if part in given and part in out["materials"]:
            out["materials"][part] = merge_material(out["materials"][part], given[part])
    return out


def _walk(loc: tuple[Any, ...]) -> tuple[tuple[Any, ...], Any]:
    """The config key of an error location and the section model holding its last part.

    Pydantic's union-branch tags (the mechanism type of ``mechanism``, the branch of
    an ``int | Literal`` field) are not part of the key.
    """
    out: list[Any] = []
    model: Any = Config
    parent: Any = Config
    tagged = False
    for part in loc:
        if isinstance(part, int):
            continue
        if tagged:  # the discriminator value of the mechanism union
            tagged = False
            model = MECHANISM_TYPES.get(part)
            parent = model
            continue
        if model is None:  # past a value: e.g. 'constrained-int' of an int | Literal field
            break
        out.append(part)
        parent = model
        field = getattr(model, "model_fields", {}).get(part)
        annotation = getattr(field, "annotation", None)
        is_model = isinstance(annotation, type) and hasattr(annotation, "model_fields")
        tagged = model is Config and part == "mechanism"
        model = annotation if is_model else None
    return tuple(out), parent


def _field_names(loc: tuple[Any, ...]) -> list[str]:
    _, parent = _walk(loc)
    return list(getattr(parent, "model_fields", {}))


def _key_loc(loc: tuple[Any, ...]) -> tuple[Any, ...]:
    """The config key of an error location (without pydantic's union-branch tags)."""
    return _walk(loc)[0]


def error_key(error: Mapping[str, Any]) -> tuple[str, ...]:
    """The config key a pydantic error of :class:`Config` is about, as its parts.

    Without pydantic's union-branch tags, and with the field a section's own check
    names in its message (booleans, hundred-digit integers).
    """
    loc = tuple(str(p) for p in _key_loc(tuple(error["loc"])))
    msg = str(error.get("msg", "")).removeprefix("Value error, ")
    if msg.startswith(_FIELD):
        loc = (*loc, msg.removeprefix(_FIELD).partition(": ")[0])
    return loc


def _first_error(errors: list[Any]) -> Mapping[str, Any]:
    """The error to report; for text given to an ``int | Literal`` key, the Literal one.

    An unknown key is reported before a missing one: keys of another mechanism type
    (or a misspelt key) explain the missing ones.
    """
    unknown = [e for e in errors if e["type"] == "extra_forbidden"]
    if unknown and any(e["type"] == "missing" for e in errors):
        return unknown[0]
    first = errors[0]
    if isinstance(first.get("input"), str):
        key = _key_loc(tuple(first["loc"]))
        for error in errors:
            if error["type"] == "literal_error" and _key_loc(tuple(error["loc"])) == key:
                return error
    return first


def _message(error: Mapping[str, Any]) -> str:
    loc = _key_loc(tuple(error["loc"]))
    key = ".".join(str(p) for p in loc) or "config"
    kind = error["type"]
    if kind == "extra_forbidden":
        return f"{key}: unknown key{suggest(str(loc[-1]), _field_names(tuple(error['loc'])))}"
    if kind == "missing":
        return f"{key}: missing"
    msg = error["msg"].removeprefix("Value error, ")
    if msg.startswith(_FIELD):  # a section's check of one of its fields
        field, _, reason = msg.removeprefix(_FIELD).partition(": ")
        return f"{field if key == 'config' else f'{key}.{field}'}: {reason}"
    if kind == "literal_error":
        expected = error.get("ctx", {}).get("expected", "")
        options = [o.strip().strip("'") for o in expected.replace(" or ", ",").split(",")]
        given = shown(error["input"])
        return f"{key}: {given} is not allowed{suggest(given.strip(chr(39)), options)}"
    if kind in {"finite_number"}:
        return f"{key}: must be finite, got {shown(error['input'])}"
    kind_of_key = _range_kind(error)
    if kind_of_key is not None:
        return f"{key}: {msg} {_as_read(error, kind_of_key)}"
    if msg.startswith(key + ":") or (msg.split(":")[0].count(".") and ":" in msg):
        return msg
    return f"{key}: {msg}"


#: pydantic's error types of a violated bound
_RANGE_ERRORS = frozenset({"greater_than", "greater_than_equal", "less_than", "less_than_equal"})


def _range_kind(error: Mapping[str, Any]) -> str | None:
    """The physical kind of a key whose bound ``error`` reports (None: no units or no bound)."""
    if error["type"] not in _RANGE_ERRORS:
        return None
    loc, parent = _walk(tuple(error["loc"]))
    info = getattr(parent, "model_fields", {}).get(loc[-1]) if loc else None
    kind = None if info is None else field_kind(info)
    return kind if kind is not None and DIMENSIONS[kind] else None


def _as_read(error: Mapping[str, Any], kind: str) -> str:
    """The end of a bound's message: its SI unit and how the value was read.

    ``rad; 35 is read as 35 rad (a bare number is SI), give a unit, e.g. "35 deg"``
    for a bare number of too large a magnitude (a unit slip; not for one below 0,
    which no unit mends); ``rad, got '1000 deg' = 17.4533 rad`` for a value with a
    unit.
    """
    unit, given = DIMENSIONS[kind], error["input"]
    number = bare_number(given)
    if number is None:
        try:
            return f"{unit}, got {shown(given)} = {to_si(given, kind):.6g} {unit}"
        except ConfigError:
            return unit
    text = given.strip() if isinstance(given, str) else repr(given)
    read = f"{unit}; {text} is read as {text} {unit} (a bare number is SI)"
    bound = next(iter(error.get("ctx", {}).values()), 0)
    too_large = error["type"].startswith("less_than") or bound < 0  # (-35 < -4π: too large)
    if too_large and kind in BARE_LIMITS:
        return f'{read}, give a unit, e.g. "{text} {BARE_LIMITS[kind][1]}"'
    return read


def config_from_dict(data: Mapping[str, Any], defaults: bool = True) -> Config:
    """Validate a (nested) config mapping into a :class:`Config`.

    Parameters
    ----------
    data : mapping
        Nested sections; quantities as SI numbers or strings with units.
    defaults : bool
        Merge the named parameter set's values underneath ``data``.
    """
    if not isinstance(data, Mapping):
        raise ConfigError(f"config: expected a mapping of sections, got {shown(data)}")
    data = dict(data)
    mechanism = data.get("mechanism", {})
    if not isinstance(mechanism, Mapping):
        raise ConfigError("mechanism: expected a section")
    kind = mechanism.get("type", "slider-crank")
    if not isinstance(kind, str) or kind not in MECHANISM_TYPES:
        raise ConfigError(
            f"mechanism.type: {shown(kind)} is not a mechanism type"
            f"{suggest(shown(kind).strip(chr(39)), MECHANISM_TYPES)}"
        )
    data["mechanism"] = {**mechanism, "type": kind}
    if defaults:
        name = data.get("parameter_set", "nlcp-paper")
        if not isinstance(name, str):
            raise ConfigError(f"parameter_set: expected a name, got {name!r}")
        data = _deep_merge(_material_defaults(get_parameter_set(name, kind), data), data)
    try:
        return Config.model_validate(data)
    except ValidationError as exc:
        raise ConfigError(_message(_first_error(exc.errors()))) from None


def read_toml(path: str | Path, error: type[Exception] = ConfigError) -> dict[str, Any]:
    """Read a TOML file; any problem raises ``error`` with a one-line message naming it.

    Parameters
    ----------
    path : path-like
        The file.
    error : exception type
        Raised for a missing, unreadable or invalid file (a ``JointwearError``).
    """
    from jointwear.io import read_input

    path = Path(path)
    text = read_input(path, "TOML file", error=error)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path}: not valid TOML ({exc})") from None
    except ValueError as exc:  # an integer of thousands of digits
        raise error(f"{path}: not readable TOML ({' '.join(str(exc).split()[:6])})") from None
    except RecursionError:
        data = None
    if data is None or _depth(data) > MAX_TOML_DEPTH:
        raise error(f"{path}: nested more than {MAX_TOML_DEPTH} levels deep")
    return data


#: deepest nesting of tables and arrays accepted in a TOML file [-]
MAX_TOML_DEPTH = 32


def _depth(value: Any) -> int:
    """Nesting depth of tables and arrays (a scalar is 0)."""
    if isinstance(value, dict):
        return 1 + max((_depth(v) for v in value.values()), default=0)
    if isinstance(value, list):
        return 1 + max((_depth(v) for v in value), default=0)
    return 0


def load_config(
    path: str | Path | None = None, overrides: Iterable[str] | Mapping[str, Any] | str = ()
) -> Config:
    """Read a TOML config, apply overrides, validate.

    Parameters
    ----------
    path : path-like, optional
        TOML file; ``None`` uses the parameter set's defaults only.
    overrides : iterable of str, str or mapping
        ``"section.key=VALUE"`` strings (CLI ``--set``), one such string, or a
        dotted-key mapping.
    """
    data: dict[str, Any] = {} if path is None else read_toml(path)
    apply_overrides(data, overrides)
    check_bare_numbers(data)
    mechanism = data.get("mechanism")
    if isinstance(mechanism, dict) and isinstance(mechanism.get("file"), str):
        # a data file named in a config is found next to the config, wherever it is run
        base = Path.cwd() if path is None else Path(path).parent
        # absolute, but a link keeps its name (messages name the file the user wrote)
        try:
            if "\x00" in mechanism["file"]:
                raise ValueError("embedded null byte")
            mechanism["file"] = str(Path.absolute(base / mechanism["file"]))
        except (OSError, ValueError) as exc:  # e.g. a NUL or a lone surrogate in the name
            raise ConfigError(f"mechanism.file: {shown(mechanism['file'])}: {exc}") from None
    return config_from_dict(data)


def _toml_ready(data: Mapping[str, Any]) -> dict[str, Any]:
    """``data`` without its ``None`` values (TOML has no null), every string writable.

    Raises
    ------
    ConfigError
        If a string holds a lone surrogate: it has no UTF-8 form, so no file can hold it.
    """
    out: dict[str, Any] = {}
    for key, value in data.items():
        if value is None:
            continue
        if isinstance(value, Mapping):
            value = _toml_ready(value)
        for text in [key, *(value if isinstance(value, list) else [value])]:
            if isinstance(text, str) and any(0xD800 <= ord(c) <= 0xDFFF for c in text):
                raise ConfigError(f"{shown(text)}: not a valid Unicode string")
        out[key] = value
    return out
