"""Messages: a pydantic validation error of a config as one line that names its key.

``mechanism.crank_length: must be greater than 0 m, got '-1 mm' = -0.001 m``;
unknown keys and values with the closest known one.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from jointwear.config.fields import FIELD, field_kind
from jointwear.config.mechanisms import MECHANISM_TYPES, MODE_TYPES
from jointwear.config.schema import ConfigSchema
from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import BARE_LIMITS, DIMENSIONS, bare_number, shown, to_si

__all__ = ["error_key", "error_message", "first_error"]


def _walk(loc: tuple[Any, ...]) -> tuple[tuple[Any, ...], Any]:
    """The config key of an error location and the section model holding its last part.

    Pydantic's union-branch tags (the mechanism type of ``mechanism``, the branch of
    an ``int | Literal`` field) are not part of the key.
    """
    out: list[Any] = []
    model: Any = ConfigSchema
    parent: Any = ConfigSchema
    tagged = False
    for part in loc:
        if isinstance(part, int):
            if out[-2:] == ["mechanism", "modes"]:  # a duty cycle's mode, then its type's tag
                out.append(part)
                tagged = True
            continue
        if tagged:  # the discriminator value of the mechanism union
            tagged = False
            model = MODE_TYPES.get(part) if out[-1:] != ["mechanism"] else None
            model = model or MECHANISM_TYPES.get(part)
            parent = model
            continue
        if model is None:  # past a value: e.g. 'constrained-int' of an int | Literal field
            break
        out.append(part)
        parent = model
        field = getattr(model, "model_fields", {}).get(part)
        annotation = getattr(field, "annotation", None)
        is_model = isinstance(annotation, type) and hasattr(annotation, "model_fields")
        tagged = model is ConfigSchema and part == "mechanism"
        model = annotation if is_model else None
    return tuple(out), parent


def _field_names(loc: tuple[Any, ...]) -> list[str]:
    _, parent = _walk(loc)
    return list(getattr(parent, "model_fields", {}))


def _key_loc(loc: tuple[Any, ...]) -> tuple[Any, ...]:
    """The config key of an error location (without pydantic's union-branch tags)."""
    return _walk(loc)[0]


def error_key(error: Mapping[str, Any]) -> tuple[str, ...]:
    """The config key a pydantic error of a config is about, as its parts.

    Without pydantic's union-branch tags, and with the field a section's own check
    names in its message (booleans, hundred-digit integers).
    """
    loc = tuple(str(p) for p in _key_loc(tuple(error["loc"])))
    msg = str(error.get("msg", "")).removeprefix("Value error, ")
    if msg.startswith(FIELD):
        loc = (*loc, msg.removeprefix(FIELD).partition(": ")[0])
    return loc


def first_error(errors: list[Any]) -> Mapping[str, Any]:
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


def error_message(error: Mapping[str, Any]) -> str:
    """The one-line message of a pydantic error of a config: the dotted key, then why.

    Unknown keys and values get the best match (:func:`~jointwear.registry.suggest`),
    a bound of a quantity its SI unit and how the value was read.
    """
    loc = _key_loc(tuple(error["loc"]))
    key = ".".join(str(p) for p in loc) or "config"
    kind = error["type"]
    if kind == "extra_forbidden":
        return f"{key}: unknown key{suggest(str(loc[-1]), _field_names(tuple(error['loc'])))}"
    if kind == "missing":
        return f"{key}: missing"
    msg = error["msg"].removeprefix("Value error, ")
    if msg.startswith(FIELD):  # a section's check of one of its fields
        field, _, reason = msg.removeprefix(FIELD).partition(": ")
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
