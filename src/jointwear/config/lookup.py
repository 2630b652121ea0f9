"""Dotted config keys: the field a key names, and bare numbers that are unit slips.

:func:`key_field` walks :class:`~jointwear.config.schema.ConfigSchema` along a dotted
key (``"mechanism.crank_length"``; the mechanism table by its type) and fails with the
closest known key; :func:`check_bare_numbers` refuses a plain number beyond the
plausible magnitude of its key.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import Any

from pydantic import BaseModel
from pydantic.fields import FieldInfo

from jointwear.config.fields import field_kind
from jointwear.config.mechanisms import MECHANISM_TYPES, MODE_TYPES, DutyCycleConfig
from jointwear.config.schema import ConfigSchema
from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import BARE_LIMITS, check_bare, shown

__all__ = [
    "BARE_LINK_LENGTH",
    "MECHANISM_UNION",
    "MODE_LIST",
    "MODE_UNION",
    "bare_limited",
    "check_bare_numbers",
    "is_section",
    "key_field",
    "mode_index",
    "takes_a_name",
]

#: marks the mechanism union while walking keys (its table depends on ``type``)
MECHANISM_UNION = object()

#: marks a duty cycle's list of modes while walking keys (the next part is a mode's index)
MODE_LIST = object()

#: marks a duty cycle's mode while walking keys (its table depends on the mode's ``type``)
MODE_UNION = object()


def _union_member(
    marker: object, part: str, mechanism: str | None, mode: str | None
) -> tuple[type[BaseModel], list[str]]:
    """The section of a mechanism (or mode) table that has the key ``part``, and the
    keys of every table it may be (the type given, else all types)."""
    types, given = (MECHANISM_TYPES, mechanism) if marker is MECHANISM_UNION else (MODE_TYPES, mode)
    candidates = [types[given]] if given in types else list(types.values())
    owner = next((c for c in candidates if part in c.model_fields), candidates[0])
    return owner, sorted({key for c in candidates for key in c.model_fields})


def mode_index(part: str, dotted: str) -> int:
    """The index of a duty cycle's mode in a dotted key (``mechanism.modes.1.share``).

    Raises
    ------
    ConfigError
        If ``part`` is not a whole number ``>= 0``.
    """
    if not (part.isascii() and part.isdigit()):
        raise ConfigError(
            f"{dotted}: {shown(part)} is not a mode's number; a duty cycle's modes are "
            "mechanism.modes.0, mechanism.modes.1, ... in the order of the file"
        )
    return int(part)


def key_field(dotted: str, mechanism: str | None = None, mode: str | None = None) -> Any:
    """The pydantic field of a dotted config key, e.g. ``"joint.clearance"``.

    A duty cycle's mode is addressed by its index from 0 in the order of the
    ``[[mechanism.modes]]`` tables: ``mechanism.modes.1.crank_speed``.

    Parameters
    ----------
    dotted : str
        Dotted key; sections are separated by dots.
    mechanism : str, optional
        Mechanism type whose ``mechanism.*`` keys are meant; default any type that
        has the key (the first in :data:`MECHANISM_TYPES` order).
    mode : str, optional
        Mechanism type of the duty cycle's mode a ``mechanism.modes.N.*`` key is of;
        default any type that has the key.

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
    model: Any = ConfigSchema
    parts = dotted.split(".")
    for i, part in enumerate(parts):
        known: list[str] | None = None
        if model is MODE_LIST:
            mode_index(part, dotted)
            model = MODE_UNION
            continue
        if model is MECHANISM_UNION or model is MODE_UNION:
            model, known = _union_member(model, part, mechanism, mode)
        fields = getattr(model, "model_fields", None)
        if fields is None:
            raise ConfigError(f"{dotted}: {parts[i - 1]!r} is a value, not a section")
        if part not in fields:
            prefix = ".".join(parts[:i])
            what = f"unknown key {part!r}" + (f" in [{prefix}]" if prefix else "")
            raise ConfigError(f"{dotted}: {what}{suggest(part, known or list(fields))}")
        info = fields[part]
        annotation = info.annotation
        last = i == len(parts) - 1
        if last and (takes_a_name(info) or model is DutyCycleConfig):
            return info  # set as a whole: materials.bushing = "bronze", mechanism.modes = [...]
        if model is ConfigSchema and part == "mechanism":
            model = MECHANISM_UNION
        elif model is DutyCycleConfig and part == "modes":
            model = MODE_LIST
        elif isinstance(annotation, type) and issubclass(annotation, BaseModel):
            model = annotation
        else:
            if not last:
                raise ConfigError(f"{dotted}: {part!r} is a value, not a section")
            return info
    return model


def is_section(dotted: str) -> bool:
    """True if ``dotted`` names a config section (``"joint"``, ``"materials.pin"``)."""
    try:
        found = key_field(dotted)
    except ConfigError:
        return False
    return not isinstance(found, FieldInfo) or takes_a_name(found)


def takes_a_name(info: Any) -> bool:
    """True for a section field that also takes a value as a whole (a material name).

    Such a field carries :data:`jointwear.config.sections.NAMED` as its JSON schema extra.
    """
    return isinstance(info.json_schema_extra, dict) and "material" in info.json_schema_extra


#: a bare length of a mechanism's link above this [m] is taken for a unit slip (the
#: joint's parts and the life limits: the much smaller ``BARE_LIMITS["length"]``)
BARE_LINK_LENGTH = 10.0


def bare_limited(
    data: Mapping[str, Any], mechanism: str | None, prefix: str = "", mode: str | None = None
) -> Iterator[tuple[Mapping[str, Any], str, str, str, float]]:
    """(section, name, dotted key, kind, limit) of each value of ``data`` whose key has
    a plausible largest bare number (:data:`jointwear.units.BARE_LIMITS`); a duty
    cycle's modes (``mechanism.modes.N.*``) included."""
    for name, value in data.items():
        dotted = f"{prefix}{name}"
        if isinstance(value, Mapping):
            yield from bare_limited(value, mechanism, f"{dotted}.", mode)
            continue
        if dotted == "mechanism.modes" and isinstance(value, list):
            for index, table in enumerate(value):
                if isinstance(table, Mapping):
                    kind = table.get("type")
                    yield from bare_limited(
                        table,
                        mechanism,
                        f"{dotted}.{index}.",
                        kind if isinstance(kind, str) else None,
                    )
            continue
        try:
            info = key_field(dotted, mechanism, mode)
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
    for values, name, dotted, kind, limit in bare_limited(data, mechanism):
        check_bare(values[name], kind, dotted, limit)
