"""Validated configuration: TOML in, SI floats out.

Every quantity in a config file is a plain number (SI) or a string with units
(``"0.2 mm"``, ``"240 rpm"``). :func:`load_config` reads a file, applies
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
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Annotated, Any, Literal

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
from jointwear.parameter_sets import get_parameter_set
from jointwear.registry import suggest
from jointwear.units import to_si, to_si_unit

__all__ = [
    "Config",
    "ContactConfig",
    "DynamicsConfig",
    "JointConfig",
    "MaterialConfig",
    "MechanismConfig",
    "SimulationConfig",
    "apply_overrides",
    "config_from_dict",
    "load_config",
    "parse_override",
    "read_toml",
]


def _si(kind: str):
    def convert(value: Any) -> Any:
        if value is None:
            return None
        try:
            return to_si(value, kind, "§")
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ")) from None

    return BeforeValidator(convert)


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


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=True)


class MechanismConfig(_Section):
    """Slider-crank data (paper Table 1, read in SI) and operating point."""

    crank_length: Length
    rod_length: Length
    crank_mass: NonNegMass
    rod_mass: NonNegMass
    slider_mass: NonNegMass
    rod_inertia: Annotated[float | None, _si("moment_of_inertia"), Field(ge=0)] = None
    spring_stiffness: Stiffness
    spring_preload: Force
    spring_mode: Literal["pull", "push"] = "pull"
    crank_speed: AngularVelocity
    gravity: Acceleration = 9.81
    bushing_body: Literal["slider", "rod"] = "slider"

    @model_validator(mode="after")
    def _assembles(self) -> MechanismConfig:
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
    """Elastic (and, for the bushing, wear) properties of one body."""

    youngs_modulus: Pressure
    poisson_ratio: PoissonRatio
    density: Density | None = None
    wear_coefficient: WearCoefficient | None = None


class MaterialsConfig(_Section):
    pin: MaterialConfig
    bushing: MaterialConfig

    @model_validator(mode="after")
    def _bushing_complete(self) -> MaterialsConfig:
        for key in ("density", "wear_coefficient"):
            if getattr(self.bushing, key) is None:
                raise ValueError(f"materials.bushing.{key}: missing (needed for wear)")
        return self


class ContactConfig(_Section):
    """Contact pressure model and the load-balance solver."""

    model: str = "winkler"
    exponent: Annotated[float, Field(gt=0, le=10)] = 1.5
    nodes: Annotated[int, Field(ge=16, le=200_000)] = 360
    tolerance: Annotated[float, _si("force"), Field(gt=0)] = 1e-12
    max_iterations: Annotated[int, Field(ge=1, le=10_000)] = 100
    foundation_modulus: Literal["youngs", "constrained"] = "youngs"
    spring_area: Annotated[float | None, _si("area"), Field(gt=0)] = None
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

        if value not in CONTACT_MODELS:
            raise ValueError(f"unknown contact model {value!r}{suggest(value, CONTACT_MODELS)}")
        return value


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
    friction_velocity_full: Annotated[float | None, _si("velocity"), Field(gt=0)] = None
    impact_velocity_floor: Annotated[float, _si("velocity"), Field(gt=0)] = 1e-3
    integrator: Literal["LSODA", "Radau", "BDF", "RK45", "DOP853"] = "LSODA"
    rtol: Annotated[float, Field(gt=0, lt=1)] = 1e-8
    atol: Annotated[float, Field(gt=0)] = 1e-10
    revolutions_settle: Annotated[int, Field(ge=0, le=10_000)] = 2
    max_step: Annotated[float | None, _si("time"), Field(gt=0)] = None

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

        if value not in DYNAMICS_MODELS:
            raise ValueError(f"unknown dynamics model {value!r}{suggest(value, DYNAMICS_MODELS)}")
        return value


class SimulationConfig(_Section):
    """Time discretisation, number of revolutions and contour updates."""

    steps_per_revolution: Annotated[int, Field(ge=8, le=1_000_000)] = 360
    revolutions: Annotated[int, Field(ge=1, le=10**9)] = 1
    update_contour: bool = False
    update_every: Annotated[int, Field(ge=1)] | Literal["adaptive"] = 1
    adaptive_tolerance: Annotated[float, Field(gt=0, lt=1)] = 2e-3
    sliding: Literal["relative-rotation", "contact-azimuth"] = "relative-rotation"
    width_threshold: Annotated[float, Field(gt=0, lt=1)] = 0.01
    saved_profiles: Annotated[int, Field(ge=1, le=100_000)] = 11
    checkpoint_every: Annotated[int, Field(ge=0)] = 0


class Config(_Section):
    """A whole jointwear configuration (all values SI)."""

    parameter_set: str = "nlcp-paper"
    mechanism: MechanismConfig
    joint: JointConfig
    materials: MaterialsConfig
    contact: ContactConfig = ContactConfig()
    dynamics: DynamicsConfig = DynamicsConfig()
    simulation: SimulationConfig = SimulationConfig()

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
        data["mechanism"]["rod_inertia"] = self.mechanism.rod_centroidal_inertia
        data["contact"]["spring_area"] = self.spring_area
        data["contact"]["stiffness"] = self.nlcp_stiffness
        return data

    def to_toml(self) -> str:
        """The resolved config as TOML text (SI units, noted in comments)."""
        return _dump_toml(self.to_dict())

    def replace(self, overrides: Mapping[str, Any]) -> Config:
        """Return a new config with dotted-key overrides applied and validated."""
        # the raw fields, not to_dict(): derived defaults (rod inertia from the rod
        # mass, spring area from the axial length) must follow the overrides
        data = _without_none(self.model_dump(mode="json"))
        apply_overrides(data, overrides)
        return config_from_dict(data, defaults=False)


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
    return key, value


def apply_overrides(data: dict[str, Any], overrides: Mapping[str, Any] | Iterable[str]) -> None:
    """Apply dotted-key overrides in place (a mapping, or ``key=value`` strings)."""
    items = (
        overrides.items()
        if isinstance(overrides, Mapping)
        else (parse_override(o) for o in overrides)
    )
    for dotted, value in items:
        parts = dotted.split(".")
        node = data
        for part in parts[:-1]:
            child = node.setdefault(part, {})
            if not isinstance(child, dict):
                raise ConfigError(f"{dotted}: {part!r} is a value, not a section")
            node = child
        node[parts[-1]] = value


def _field_names(loc: tuple[Any, ...]) -> list[str]:
    model: Any = Config
    for part in loc[:-1]:
        field = model.model_fields.get(part) if hasattr(model, "model_fields") else None
        if field is None:
            return []
        model = field.annotation
    return list(getattr(model, "model_fields", {}))


def _key_loc(loc: tuple[Any, ...]) -> tuple[Any, ...]:
    """The config key of an error location (without pydantic's union-branch tags)."""
    out: list[Any] = []
    model: Any = Config
    for part in loc:
        if isinstance(part, int):
            continue
        if model is None:  # past a value: e.g. 'constrained-int' of an int | Literal field
            break
        out.append(part)
        field = getattr(model, "model_fields", {}).get(part)
        annotation = getattr(field, "annotation", None)
        is_model = isinstance(annotation, type) and hasattr(annotation, "model_fields")
        model = annotation if is_model else None
    return tuple(out)


def _first_error(errors: list[Any]) -> Mapping[str, Any]:
    """The error to report; for text given to an ``int | Literal`` key, the Literal one."""
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
        return f"{key}: unknown key{suggest(str(loc[-1]), _field_names(loc))}"
    if kind == "missing":
        return f"{key}: missing"
    msg = error["msg"].removeprefix("Value error, ")
    if kind == "literal_error":
        expected = error.get("ctx", {}).get("expected", "")
        options = [o.strip().strip("'") for o in expected.replace(" or ", ",").split(",")]
        return f"{key}: {error['input']!r} is not allowed{suggest(str(error['input']), options)}"
    if kind in {"finite_number"}:
        return f"{key}: must be finite, got {error['input']!r}"
    if msg.startswith(key + ":") or (msg.split(":")[0].count(".") and ":" in msg):
        return msg
    return f"{key}: {msg}"


def config_from_dict(data: Mapping[str, Any], defaults: bool = True) -> Config:
    """Validate a (nested) config mapping into a :class:`Config`.

    Parameters
    ----------
    data : mapping
        Nested sections; quantities as SI numbers or strings with units.
    defaults : bool
        Merge the named parameter set's values underneath ``data``.
    """
    data = dict(data)
    if defaults:
        name = data.get("parameter_set", "nlcp-paper")
        if not isinstance(name, str):
            raise ConfigError(f"parameter_set: expected a name, got {name!r}")
        data = _deep_merge(get_parameter_set(name), data)
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
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise error(f"{path}: file not found") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise error(f"{path}: cannot read ({exc})") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path}: not valid TOML ({exc})") from None


def load_config(
    path: str | Path | None = None, overrides: Iterable[str] | Mapping[str, Any] = ()
) -> Config:
    """Read a TOML config, apply overrides, validate.

    Parameters
    ----------
    path : path-like, optional
        TOML file; ``None`` uses the parameter set's defaults only.
    overrides : iterable of str or mapping
        ``"section.key=VALUE"`` strings (CLI ``--set``) or a dotted-key mapping.
    """
    data: dict[str, Any] = {} if path is None else read_toml(path)
    apply_overrides(data, overrides)
    return config_from_dict(data)


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    return str(value)


def _dump_toml(data: Mapping[str, Any], prefix: str = "") -> str:
    lines: list[str] = []
    tables: list[tuple[str, Mapping[str, Any]]] = []
    for key, value in data.items():
        if isinstance(value, Mapping):
            tables.append((f"{prefix}{key}", value))
        elif value is not None:
            lines.append(f"{key} = {_toml_value(value)}")
    out = "\n".join(lines)
    for name, table in tables:
        body = _dump_toml(table, prefix=f"{name}.")
        header = (
            f"\n\n[{name}]\n" if any(not isinstance(v, Mapping) for v in table.values()) else "\n"
        )
        out += header + body if body else ""
    return out.strip() + "\n" if not prefix else out
