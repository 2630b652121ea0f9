"""The keys a sweep varies: their config field, physical kind and SI values.

A swept key is a dotted config key (``joint.clearance``). Its field says whether it
has units (the kind of :data:`jointwear.units.DIMENSIONS` its validator converts
to), is a number, a text or a flag; a value is checked on its own before a sweep
runs (:func:`check_value`), while a combination of values is judged per case.
"""

from __future__ import annotations

import math
import types
import typing
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from jointwear.config import (
    Config,
    apply_overrides,
    check_bare_numbers,
    config_from_dict,
    error_key,
    key_field,
)
from jointwear.errors import ConfigError
from jointwear.units import DIMENSIONS, to_si

__all__ = [
    "SweptKey",
    "check_address",
    "check_bare",
    "check_value",
    "swept_key",
    "value_list",
    "without_none",
]


def _field(dotted: str, where: str) -> Any:
    """The pydantic field of a dotted config key; unknown keys raise with a suggestion."""
    from pydantic.fields import FieldInfo

    try:
        info = key_field(dotted)
    except ConfigError as exc:
        raise ConfigError(f"{where} {exc}") from None
    if not isinstance(info, FieldInfo):
        raise ConfigError(f"{where} {dotted}: is a section; name one of its keys")
    return info


def _kind(info: Any) -> str | None:
    """Physical kind (a key of ``units.DIMENSIONS``) of a config field, if it has units.

    The kind is the argument of ``config._si(kind)``, found on the field's
    metadata or inside its annotation (``Annotated[...] | None``).
    """
    return _kind_of([*info.metadata, info.annotation])


def _kind_of(items: Sequence[Any]) -> str | None:
    for item in items:
        origin = typing.get_origin(item)
        if origin is typing.Annotated:
            found = _kind_of(item.__metadata__)
        elif origin in (typing.Union, types.UnionType):
            found = _kind_of(typing.get_args(item))
        else:
            func = getattr(item, "func", None)
            cells = getattr(func, "__closure__", None) or ()
            found = next(
                (
                    c.cell_contents
                    for c in cells
                    if isinstance(c.cell_contents, str) and c.cell_contents in DIMENSIONS
                ),
                None,
            )
        if found is not None:
            return found
    return None


def _base_types(annotation: Any) -> set[type]:
    if typing.get_origin(annotation) is typing.Annotated:
        return _base_types(typing.get_args(annotation)[0])
    if typing.get_origin(annotation) in (typing.Union, types.UnionType):
        return set().union(*(_base_types(a) for a in typing.get_args(annotation)))
    if typing.get_origin(annotation) is typing.Literal:
        return {type(a) for a in typing.get_args(annotation)}
    return {annotation} if isinstance(annotation, type) else set()


@dataclass(frozen=True)
class SweptKey:
    """A swept config key: what its values are and how they become SI numbers.

    Attributes
    ----------
    name : str
        Dotted config key.
    kind : str or None
        Physical kind (a key of :data:`jointwear.units.DIMENSIONS`) of a key with
        units; ``None`` for plain numbers, text and flags.
    types : frozenset of type
        The Python types the key's field accepts.
    """

    name: str
    kind: str | None
    types: frozenset[type]

    @property
    def numeric(self) -> bool:
        """Whether the values are numbers (a quantity, an int or a float)."""
        return self.kind is not None or bool(self.types & {int, float})

    @property
    def integer(self) -> bool:
        """Whether the values are whole numbers (a random draw is rounded)."""
        return self.kind is None and int in self.types and float not in self.types

    @property
    def unit(self) -> str | None:
        """SI unit for the column header; ``None`` for plain numbers, text and flags."""
        if self.kind is None:
            return None
        return DIMENSIONS[self.kind] or "1"

    @property
    def column(self) -> str:
        """Header of the key's column in ``cases.csv``: the key and its SI unit."""
        return self.name if self.unit is None else f"{self.name} [{self.unit}]"

    def si(self, value: Any) -> Any:
        """SI value of a sweep value (quantity strings converted; other values as given)."""
        if self.kind is not None:
            return to_si(value, self.kind, self.name)
        return value


def swept_key(dotted: str, where: str) -> SweptKey:
    """The :class:`SweptKey` of a dotted config key.

    Parameters
    ----------
    dotted : str
        Dotted config key, e.g. ``joint.clearance``.
    where : str
        Start of error messages (the sweep file and table).

    Raises
    ------
    ConfigError
        Not a config key (with a suggestion), or a section.
    """
    if not isinstance(dotted, str) or not dotted:
        raise ConfigError(f"{where}: keys must be dotted config keys, e.g. 'joint.clearance'")
    info = _field(dotted, where)
    return SweptKey(dotted, _kind(info), frozenset(_base_types(info.annotation)))


def value_list(values: Any, where: str) -> list[Any]:
    """The values of a ``[grid]`` or ``[zip]`` key: a non-empty list of finite numbers,
    strings or booleans.

    Parameters
    ----------
    values : object
        What the sweep file gives.
    where : str
        Start of error messages.

    Returns
    -------
    list
        ``values`` (units allowed in strings).
    """
    if not isinstance(values, list):
        raise ConfigError(f"{where}: expected a list of values, got {values!r}")
    if not values:
        raise ConfigError(f"{where}: the list of values is empty")
    for value in values:
        if isinstance(value, float) and not math.isfinite(value):
            raise ConfigError(f"{where}: must be finite, got {value!r}")
        if not isinstance(value, str | int | float | bool):
            raise ConfigError(f"{where}: values must be numbers, strings or booleans")
    return values


def check_bare(base: Config, dotted: str, value: Any, where: str) -> None:
    """A bare number that is a unit slip fails the sweep, as in a config file.

    Parameters
    ----------
    base : Config
        The sweep's base configuration (its mechanism type).
    dotted : str
        Dotted config key.
    value : object
        The value the sweep gives the key (SI when a bare number).
    where : str
        Start of error messages.
    """
    try:
        check_bare_numbers({dotted: value}, base.mechanism.type)
    except ConfigError as exc:
        raise ConfigError(f"{where}: {str(exc).removeprefix(f'{dotted}: ')}") from None


def check_value(base: Config, dotted: str, value: Any, where: str) -> None:
    """A value must be valid on its own; combinations are judged per case.

    Errors of the field itself (wrong unit, out of range, unknown model ...)
    fail the sweep. An error that only arises together with other values
    (a section's cross-check, e.g. crank longer than rod) does not: the
    case that combines them is recorded as failed.

    Parameters
    ----------
    base : Config
        The sweep's base configuration.
    dotted : str
        Dotted config key.
    value : object
        The value the sweep gives the key (units allowed).
    where : str
        Start of error messages.

    Raises
    ------
    ConfigError
        The value is invalid on its own.
    """
    from pydantic import ValidationError

    check_bare(base, dotted, value, where)
    data = without_none(base.model_dump(mode="json"))
    try:
        apply_overrides(data, {dotted: value})
    except ConfigError as exc:  # e.g. a duty cycle's mode the base does not have
        raise ConfigError(f"{where}: {str(exc).removeprefix(f'{dotted}: ')}") from None
    try:
        Config.model_validate(data)
    except ValidationError as exc:
        parts = tuple(dotted.split("."))
        own = any(error_key(error)[: len(parts)] == parts for error in exc.errors())
        if not own:
            return
        try:
            config_from_dict(data, defaults=False)
        except ConfigError as error:
            message = str(error).removeprefix(f"{dotted}: ")
            raise ConfigError(f"{where} = {value!r}: {message}") from None


def check_address(base: Config, dotted: str, where: str) -> None:
    """A key must name a place of the base configuration: ``mechanism.modes.N.*`` a mode
    it has (``N`` below its number of modes).

    Parameters
    ----------
    base : Config
        The sweep's base configuration.
    dotted : str
        Dotted config key.
    where : str
        Start of error messages (the sweep file and table).
    """
    if not dotted.startswith("mechanism.modes."):
        return  # (the other keys are the schema's, checked by swept_key)
    try:
        apply_overrides(without_none(base.model_dump(mode="json")), {dotted: 0})
    except ConfigError as exc:
        raise ConfigError(f"{where} {exc}") from None


def without_none(data: Mapping[str, Any]) -> dict[str, Any]:
    """A nested mapping without its ``None`` values (a config's unset, derived fields)."""
    return {
        key: without_none(value) if isinstance(value, Mapping) else value
        for key, value in data.items()
        if value is not None
    }
