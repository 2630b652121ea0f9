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
from jointwear.config.mechanisms import MECHANISM_TYPES
from jointwear.config.schema import ConfigSchema
from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import BARE_LIMITS, check_bare

__all__ = [
    "BARE_LINK_LENGTH",
    "MECHANISM_UNION",
    "bare_limited",
    "check_bare_numbers",
    "is_section",
    "key_field",
    "takes_a_name",
]

#: marks the mechanism union while walking keys (its table depends on ``type``)
MECHANISM_UNION = object()


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
    model: Any = ConfigSchema
    parts = dotted.split(".")
    for i, part in enumerate(parts):
        if model is MECHANISM_UNION:
            candidates = (
                [MECHANISM_TYPES[mechanism]]
                if mechanism in MECHANISM_TYPES
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
        if i == len(parts) - 1 and takes_a_name(info):
            return info  # a section that is also set as a whole: materials.bushing = "bronze"
        if model is ConfigSchema and part == "mechanism":
            model = MECHANISM_UNION
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
    data: Mapping[str, Any], mechanism: str | None, prefix: str = ""
) -> Iterator[tuple[Mapping[str, Any], str, str, str, float]]:
    """(section, name, dotted key, kind, limit) of each value of ``data`` whose key has
    a plausible largest bare number (:data:`jointwear.units.BARE_LIMITS`)."""
    for name, value in data.items():
        dotted = f"{prefix}{name}"
        if isinstance(value, Mapping):
            yield from bare_limited(value, mechanism, f"{dotted}.")
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
    for values, name, dotted, kind, limit in bare_limited(data, mechanism):
        check_bare(values[name], kind, dotted, limit)
