"""The sections of a configuration besides the mechanism: one pydantic model each.

``[joint]``, ``[materials]`` (``pin``, ``bushing``), ``[contact]``, ``[dynamics]``,
``[simulation]``, ``[wear]`` and ``[life]``; every quantity SI once validated. A
stage takes the section it needs (``wear_law(config.wear, config.materials.bushing)``).
"""

from __future__ import annotations

import math
from typing import Annotated, Any, Literal

from pydantic import BeforeValidator, Field, ValidationInfo, field_validator, model_validator

from jointwear import materials
from jointwear.config.choices import (
    CONTACT_MODEL,
    DYNAMICS_MODEL,
    LUBRICANT,
    WEAR_LAW,
    SlidingModel,
)
from jointwear.config.fields import (
    FIELD,
    MAX_COUNT,
    MAX_SLICES,
    Density,
    Length,
    NonNegLength,
    OptionalPressure,
    PoissonRatio,
    Pressure,
    Section,
    WearCoefficient,
    si,
)
from jointwear.config.wear_table import TableCoefficients, TablePoints, WearTable, check_table
from jointwear.errors import ConfigError
from jointwear.units import registry, to_si_unit

__all__ = [
    "NAMED",
    "ContactConfig",
    "DynamicsConfig",
    "JointConfig",
    "LifeConfig",
    "LubricationConfig",
    "MaterialConfig",
    "MaterialsConfig",
    "SimulationConfig",
    "WearConfig",
]


class JointConfig(Section):
    """Clearance joint geometry (paper Table 2, read in SI)."""

    pin_radius: Length
    clearance: Length
    axial_length: Length
    bushing_thickness: Length
    #: along the pin (docs/along-the-pin.md): slices, an imposed tilt and its plane, and
    #: the axial position of the load's line of action (0: the mid-plane)
    axial_slices: Annotated[int, Field(ge=1, le=MAX_SLICES)] = 1
    misalignment: Annotated[float, si("angle"), Field(ge=0, lt=0.1)] = 0.0
    misalignment_angle: Annotated[
        Annotated[float, Field(ge=-4 * math.pi, le=4 * math.pi)] | None, si("angle")
    ] = None
    load_offset: Annotated[float, si("length")] = 0.0

    @property
    def bushing_radius(self) -> float:
        """Unworn bushing inner radius [m] = pin radius + radial clearance."""
        return self.pin_radius + self.clearance


def _table_in_si(value: Any) -> Any:
    """A material's ``wear_table`` with units (a library entry's) read into SI numbers."""
    if value is None or isinstance(value, WearTable):
        return value
    try:
        return materials.wear_table(value, "§")
    except ConfigError as exc:
        raise ValueError(str(exc).removeprefix("§: ").removeprefix("§.")) from None


class MaterialConfig(Section):
    """Elastic (and, for the bushing, wear) properties of one body, and its datasheet limits.

    ``name`` is a material of the library (:mod:`jointwear.materials`) whose values the
    other keys override. Wear comes as ``wear_coefficient`` (``K_d`` [m^2/N]),
    ``specific_wear_rate`` ([mm^3/(N m)], the same dimension) or ``wear_factor_k`` with
    ``hardness`` (``K_d = k / H``), one of them; the last three are read into
    ``wear_coefficient`` and not written back out. ``boundary_wear_coefficient`` [m^2/N]
    is the pair's coefficient with a grease (boundary lubrication: a library grease as
    ``lubrication.lubricant`` without a film model wears with it).
    """

    name: str | None = None
    youngs_modulus: Pressure
    poisson_ratio: PoissonRatio
    density: Density | None = None
    wear_coefficient: WearCoefficient | None = None
    specific_wear_rate: Annotated[
        Annotated[float, Field(ge=0)] | None, si("wear_coefficient"), Field(exclude=True)
    ] = None
    wear_factor_k: Annotated[
        Annotated[float, Field(ge=0)] | None, si("dimensionless"), Field(exclude=True)
    ] = None
    hardness: Annotated[
        Annotated[float, Field(gt=0)] | None, si("pressure"), Field(exclude=True)
    ] = None
    boundary_wear_coefficient: WearCoefficient | None = None
    #: K_d [1/Pa] tabulated against speed, PV or temperature (wear.law = "tabulated")
    wear_table: Annotated[WearTable | None, BeforeValidator(_table_in_si)] = None
    max_static_pressure: OptionalPressure = None
    max_dynamic_pressure: OptionalPressure = None
    max_pv: Annotated[Annotated[float, Field(gt=0)] | None, si("pressure_velocity")] = None
    max_sliding_speed: Annotated[Annotated[float, Field(gt=0)] | None, si("velocity")] = None

    @model_validator(mode="after")
    def _one_wear_form(self) -> MaterialConfig:
        values = {
            k: getattr(self, k)
            for k in ("wear_coefficient", "specific_wear_rate", "wear_factor_k", "hardness")
        }
        try:
            coefficient = materials.wear_coefficient(values, "§")
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ").removeprefix("§.")) from None
        # the other forms are read into K_d and not kept, so that a config equals the one
        # read back from its TOML (the model is frozen once validated)
        object.__setattr__(self, "wear_coefficient", coefficient)
        for key in ("specific_wear_rate", "wear_factor_k", "hardness"):
            object.__setattr__(self, key, None)
        return self


#: marks a section that is also set as a whole: a library name, or a table
#: (:func:`jointwear.config.lookup.takes_a_name`)
NAMED = {"material": "a library name or a table"}


def _material(part: str) -> BeforeValidator:
    """Resolve a library name (``"bronze"``, or a table with ``name``) into the table."""

    def resolve(value: Any) -> Any:
        try:
            return materials.resolve_material(value, f"materials.{part}", wear=part == "bushing")
        except ConfigError as exc:
            raise ValueError(str(exc)) from None

    return BeforeValidator(resolve)


class MaterialsConfig(Section):
    """The pin's and the bushing's material (a library name or a table each)."""

    pin: Annotated[MaterialConfig, _material("pin"), Field(json_schema_extra=NAMED)]
    bushing: Annotated[MaterialConfig, _material("bushing"), Field(json_schema_extra=NAMED)]

    @model_validator(mode="after")
    def _bushing_complete(self) -> MaterialsConfig:
        for key in ("density", "wear_coefficient"):
            if getattr(self.bushing, key) is None:
                raise ValueError(f"materials.bushing.{key}: missing (needed for wear)")
        return self


class ContactConfig(Section):
    """Contact pressure model and the load-balance solver."""

    #: Winkler's springs on the real contour: the load balances on a worn contour too
    model: str = "asymmetric-winkler"
    exponent: Annotated[float, Field(gt=0, le=10)] = 1.5
    nodes: Annotated[int, Field(ge=16, le=200_000)] = 360
    tolerance: Annotated[float, si("force"), Field(gt=0)] = 1e-12
    max_iterations: Annotated[int, Field(ge=1, le=10_000)] = 100
    #: the thin-layer modulus of a wall bonded in its housing (docs/models.md)
    foundation_modulus: Literal["youngs", "constrained"] = "constrained"
    spring_area: Annotated[Annotated[float, Field(gt=0)] | None, si("area")] = None
    balance: Literal["paper", "equilibrium"] = "paper"
    nlcp_variant: Literal["paper", "mesh-independent"] = "paper"
    #: NLCP spring stiffness K [N/m^n]; None: eq. (2), 4/3 E* sqrt(R_p)
    stiffness: float | None = None

    @field_validator("stiffness", mode="before")
    @classmethod
    def _stiffness_insi(cls, value: Any, info: ValidationInfo) -> Any:
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
        return CONTACT_MODEL.check(value)


class DynamicsConfig(Section):
    """Which dynamics model produces the joint load, and its settings.

    The keys from ``force_law`` on belong to ``model = "contact-impact"``
    (:mod:`jointwear.mechanism.slider_crank.contact_impact`); velocities are m/s or strings
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
    friction_velocity_tolerance: Annotated[float, si("velocity"), Field(gt=0)] = 1e-4
    friction_velocity_full: Annotated[Annotated[float, Field(gt=0)] | None, si("velocity")] = None
    impact_velocity_floor: Annotated[float, si("velocity"), Field(gt=0)] = 1e-3
    # auto: RK45-compiled where it runs (the slider-crank's point laws; Radau-compiled with
    # an oil film), LSODA elsewhere
    integrator: Literal[
        "auto", "LSODA", "Radau", "BDF", "RK45", "DOP853", "RK45-compiled", "Rodas4-compiled",
        "Radau-compiled",
    ] = "auto"  # fmt: skip
    rtol: Annotated[float, Field(gt=0, lt=1)] = 1e-8
    atol: Annotated[float, Field(gt=0)] = 1e-10
    # a flying, impacting pin is tolerance-sensitive: rtol 1e-8 is off by percents there;
    # None: 1e-10 for one solve, the run's rtol for the solves of a coupled run
    separation_rtol: Annotated[float, Field(gt=0, lt=1)] | None = None
    revolutions_settle: Annotated[int, Field(ge=0, le=10_000)] = 2
    max_step: Annotated[Annotated[float, Field(gt=0)] | None, si("time")] = None

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
        return DYNAMICS_MODEL.check(value)


class SimulationConfig(Section):
    """Time discretisation, number of revolutions and contour updates."""

    steps_per_revolution: Annotated[int, Field(ge=8, le=1_000_000)] = 360
    revolutions: Annotated[int, Field(ge=1, le=MAX_COUNT)] = 1
    update_contour: bool = False
    update_every: Annotated[int, Field(ge=1, le=MAX_COUNT)] | Literal["adaptive"] = 1
    adaptive_tolerance: Annotated[float, Field(gt=0, lt=1)] = 2e-3
    sliding: SlidingModel = "relative-rotation"
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


#: a table's points (SI of wear.table_against) and coefficients [1/Pa], 2 to 1000 each


#: lowest temperature read [K]: a bare number is kelvin, and oil is liquid well above this
LOWEST_TEMPERATURE = 173.15
#: temperature of a lubricant given without one: the reference of the ISO VG grades [K]
DEFAULT_TEMPERATURE = 313.15


def read_temperature(value: Any) -> float:
    """A temperature [K] from a number (kelvin) or a string with units (``"60 degC"``).

    pint refuses ``"60 degC"`` as a product of a number and an offset unit; the
    number and the unit are read apart and the quantity built from them.
    """
    if isinstance(value, str):
        number, _, unit = value.strip().partition(" ")
        try:
            kelvin = float(
                registry().Quantity(float(number), unit.strip() or "K").to("K").magnitude
            )
        except Exception as exc:  # pint's and float's errors alike: one message
            raise ValueError(f"cannot read {value!r} as a temperature ({exc})") from None
    elif isinstance(value, int | float) and not isinstance(value, bool):
        kelvin = float(value)
    else:
        raise ValueError(f"expected a temperature such as '60 degC', got {value!r}")
    if not math.isfinite(kelvin) or kelvin < LOWEST_TEMPERATURE:
        raise ValueError(
            f"{value!r} is below {LOWEST_TEMPERATURE:g} K (a bare number is kelvin: "
            "write '60 degC')"
        )
    return kelvin


def optional_temperature(value: Any) -> float | None:
    """:func:`read_temperature`, with ``None`` (not given) passed through [K]."""
    return None if value is None else read_temperature(value)


class WearConfig(Section):
    """The wear law and its coefficients (``archard`` uses the bushing's wear coefficient)."""

    law: str = "archard"
    energy_coefficient: Annotated[Annotated[float, Field(gt=0)] | None, si("wear_coefficient")] = (
        None
    )
    friction_coefficient: Annotated[float | None, Field(gt=0, le=10)] = None
    # power-law: K_d (p / reference_pressure)^a (v / reference_speed)^b
    reference_pressure: Pressure = 1e6
    reference_speed: Annotated[float, si("velocity"), Field(gt=0)] = 0.01
    pressure_exponent: Annotated[float, Field(ge=-1, le=5)] = 0.0
    speed_exponent: Annotated[float, Field(ge=-1, le=5)] = 0.0
    # running-in: K from initial_wear_coefficient to the bushing's over running_in_distance
    initial_wear_coefficient: Annotated[
        Annotated[float, Field(gt=0)] | None, si("wear_coefficient")
    ] = None
    running_in_distance: Annotated[Annotated[float, Field(gt=0)] | None, si("length")] = None
    # tabulated: K at table_points (SI: m/s, Pa m/s or K) of table_against
    table_against: Literal["speed", "pv", "temperature"] | None = None
    table_points: TablePoints | None = None
    table_coefficients: TableCoefficients | None = None
    temperature: Annotated[float | None, BeforeValidator(optional_temperature)] = None  # [K]

    @field_validator("law")
    @classmethod
    def _known_law(cls, value: str) -> str:
        return WEAR_LAW.check(value)

    @model_validator(mode="after")
    def _energy_complete(self) -> WearConfig:
        if self.law == "energy":
            for key in ("energy_coefficient", "friction_coefficient"):
                if getattr(self, key) is None:
                    raise ValueError(f"wear.{key}: missing (needed by wear.law = 'energy')")
        if self.law == "running-in":
            for key in ("initial_wear_coefficient", "running_in_distance"):
                if getattr(self, key) is None:
                    raise ValueError(f"wear.{key}: missing (needed by wear.law = 'running-in')")
        check_table(self)
        return self


class LifeConfig(Section):
    """Wear limits: the run stops where the first one is reached (inside a revolution).

    ``wall_thickness`` is the least remaining wall; its default 0 stops the run where
    wear goes through the wall.
    """

    peak_wear_depth: Annotated[Annotated[float, Field(gt=0)] | None, si("length")] = None
    wear_mass: Annotated[Annotated[float, Field(gt=0)] | None, si("mass")] = None
    wear_volume: Annotated[Annotated[float, Field(gt=0)] | None, si("volume")] = None
    clearance: Annotated[Annotated[float, Field(gt=0)] | None, si("length")] = None
    wall_thickness: NonNegLength = 0.0


#: ``lubrication.model``: dry contact, or a film model sharing the load with the asperities
LubricationModel = Literal["dry", "short-bearing", "long-bearing", "finite-length"]
#: ``lubrication.cavitation``: where the film ends (``jointwear.lubrication.reynolds``)
LubricationCavitation = Literal["half-Sommerfeld", "Reynolds"]


class LubricationConfig(Section):
    """A lubricated joint: the film model, the oil and the surfaces' roughness.

    ``model = "dry"`` (the default) runs the dry contact models; a film model
    (short, long or finite-length bearing) shares each step's load between the oil
    film and the asperities (:mod:`jointwear.contact.lubricated`). The oil is a
    ``viscosity`` [Pa s] or a library ``lubricant`` at a ``temperature`` [K, 40 degC
    if not given], one of the two. ``roughness`` is the composite Rq
    ``sqrt(Rq_pin^2 + Rq_bushing^2)`` [m]; ``eta_beta_sigma`` and ``sigma_over_beta``
    are Greenwood--Tripp's asperity parameters, their defaults those of
    :mod:`jointwear.lubrication.asperity` (mid-range of engineering surfaces).
    ``cavitation`` is the film's end: the positive part of the full film
    (``"half-Sommerfeld"``) or Reynolds' condition (``"Reynolds"``, finite length only).
    """

    model: LubricationModel = "dry"
    cavitation: LubricationCavitation = "half-Sommerfeld"
    viscosity: Annotated[float | None, Field(gt=0)] = None
    lubricant: str | None = None
    temperature: Annotated[float | None, BeforeValidator(optional_temperature)] = None
    roughness: Annotated[float, si("length"), Field(gt=0)] = 0.4e-6
    eta_beta_sigma: Annotated[float, Field(gt=0, le=1)] = 0.04
    sigma_over_beta: Annotated[float, Field(gt=0, le=1)] = 1e-3

    @field_validator("viscosity", mode="before")
    @classmethod
    def _viscosity_in_si(cls, value: Any) -> Any:
        if value is None or isinstance(value, bool):
            return value
        try:
            return to_si_unit(value, "Pa*s", "§")
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ")) from None

    @field_validator("lubricant")
    @classmethod
    def _known_lubricant(cls, value: str | None) -> str | None:
        if value is None:
            return None
        try:
            return LUBRICANT(value, "§").name
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ")) from None

    @model_validator(mode="after")
    def _one_oil(self) -> LubricationConfig:
        if self.viscosity is not None and self.lubricant is not None:
            raise ValueError(
                f"{FIELD}viscosity: give viscosity or lubricant, not both "
                f"(lubricant {self.lubricant!r} has its own)"
            )
        if self.temperature is not None and self.lubricant is None:
            raise ValueError(f"{FIELD}temperature: sets a lubricant's viscosity; give lubricant")
        if self.cavitation == "Reynolds" and self.model != "finite-length":
            raise ValueError(
                f"{FIELD}cavitation: 'Reynolds' needs model = 'finite-length' (got "
                f"{self.model!r}; the short and long bearings are half-Sommerfeld closed forms)"
            )
        if self.model != "dry" and self.viscosity is None and self.lubricant is None:
            raise ValueError(
                f"{FIELD}viscosity: missing (lubrication.model = {self.model!r} needs "
                "viscosity or lubricant)"
            )
        return self

    @property
    def lubricated(self) -> bool:
        """A film model is chosen (not ``"dry"``)."""
        return self.model != "dry"

    @property
    def oil_temperature(self) -> float:
        """The lubricant's temperature [K]: ``temperature`` or 40 degC."""
        return DEFAULT_TEMPERATURE if self.temperature is None else self.temperature
