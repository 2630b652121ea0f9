"""The fields of config sections: quantities read into SI, and the section base.

A quantity field is annotated with :func:`si` (``Annotated[float, si("length"),
Field(gt=0)]``): a plain number is SI, a string carries its unit (``"0.2 mm"``).
:func:`field_kind` reads the kind back from a field, for messages and for the
bare-number checks (:mod:`jointwear.config.lookup`).
"""

from __future__ import annotations

import types
import typing
from collections.abc import Iterable, Mapping
from typing import Annotated, Any

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, model_validator

from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import MAX_MAGNITUDE, shown, to_si

__all__ = [
    "FIELD",
    "KIND_OF",
    "MAX_COUNT",
    "MAX_INTEGRATOR_STEPS",
    "MAX_SLICES",
    "Acceleration",
    "AngularVelocity",
    "Density",
    "Force",
    "Inertia",
    "Length",
    "Mass",
    "NonNegLength",
    "NonNegMass",
    "OptionalPressure",
    "PoissonRatio",
    "Pressure",
    "Section",
    "Stiffness",
    "WearCoefficient",
    "field_kind",
    "one_of",
    "scalar_types",
    "si",
]

#: largest count of revolutions, updates or checkpoints a config can ask for
MAX_COUNT = 10**9
#: most axial slices of a joint (each slice holds a contour of ``contact.nodes`` nodes)
MAX_SLICES = 1000
#: most steps the contact-impact integrator may be forced to take by dynamics.max_step
MAX_INTEGRATOR_STEPS = 10**7

#: the converters of :func:`si` -> their physical kind (read by :func:`field_kind`)
KIND_OF: dict[Any, str] = {}


def si(kind: str) -> BeforeValidator:
    """A field's converter of a quantity (number or string with units) into SI.

    Parameters
    ----------
    kind : str
        Physical kind, a key of :data:`~jointwear.units.DIMENSIONS` (``"length"``).
    """

    def convert(value: Any) -> Any:
        if value is None:
            return None
        try:
            return to_si(value, kind, "§")
        except ConfigError as exc:
            raise ValueError(str(exc).removeprefix("§: ")) from None

    KIND_OF[convert] = kind
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
        if isinstance(item, BeforeValidator) and item.func in KIND_OF:
            return KIND_OF[item.func]
        if typing.get_origin(item) in (typing.Annotated, typing.Union, types.UnionType):
            items.extend(typing.get_args(item))
    return None


Length = Annotated[float, si("length"), Field(gt=0)]
NonNegLength = Annotated[float, si("length"), Field(ge=0)]
Mass = Annotated[float, si("mass"), Field(gt=0)]
NonNegMass = Annotated[float, si("mass"), Field(ge=0)]
Force = Annotated[float, si("force"), Field(ge=0)]
Stiffness = Annotated[float, si("stiffness"), Field(ge=0)]
Pressure = Annotated[float, si("pressure"), Field(gt=0)]
AngularVelocity = Annotated[float, si("angular_velocity"), Field(gt=0)]
Acceleration = Annotated[float, si("acceleration"), Field(ge=0)]
Density = Annotated[float, si("density"), Field(gt=0)]
WearCoefficient = Annotated[float, si("wear_coefficient"), Field(ge=0)]
PoissonRatio = Annotated[float, si("dimensionless"), Field(gt=-1.0, lt=0.5)]
OptionalPressure = Annotated[Annotated[float, Field(gt=0)] | None, si("pressure")]
Inertia = Annotated[Annotated[float, Field(ge=0)] | None, si("moment_of_inertia")]


def scalar_types(annotation: Any) -> frozenset[type]:
    """The scalar types a field annotation admits (through Annotated, unions, Literal)."""
    origin = typing.get_origin(annotation)
    if origin is typing.Annotated:
        return scalar_types(typing.get_args(annotation)[0])
    if origin in (typing.Union, types.UnionType):
        return frozenset().union(*(scalar_types(a) for a in typing.get_args(annotation)))
    if origin is typing.Literal:
        return frozenset(type(a) for a in typing.get_args(annotation))
    return frozenset({annotation}) if isinstance(annotation, type) else frozenset()


def one_of(value: str, names: Iterable[str], what: str) -> str:
    """``value`` if it is one of ``names``, else a ValueError with the best match.

    A section's validator raises it; pydantic's message is then put after the key.
    """
    if value not in names:
        raise ValueError(f"unknown {what} {value!r}{suggest(value, names)}")
    return value


class Section(BaseModel):
    """A config section: unknown keys refused, values finite, frozen once validated."""

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
            accepted = scalar_types(cls.model_fields[name].annotation)
            if not accepted & {int, float}:
                continue
            if isinstance(value, bool) and bool not in accepted:
                raise ValueError(f"{FIELD}{name}: expected a number, got a boolean")
            if not isinstance(value, bool) and abs(value) > MAX_MAGNITUDE:
                raise ValueError(
                    f"{FIELD}{name}: {shown(value)} is beyond any physical value "
                    f"(|value| <= {MAX_MAGNITUDE:g})"
                )
        return data


#: marks a section validator's message that starts with the field's name
FIELD = "field "
