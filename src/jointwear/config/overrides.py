"""Overrides: dotted keys (``joint.clearance``) and ``--set section.key=VALUE``.

:func:`apply_overrides` writes them into the nested data of a config before it is
validated (:meth:`jointwear.config.Config.replace`, :func:`jointwear.config.load_config`);
a material given by name or key is merged with the library's table
(:func:`jointwear.materials.merge_material`).
"""

from __future__ import annotations

import copy
import tomllib
from collections.abc import Iterable, Mapping
from typing import Any

from jointwear.config.lookup import mode_index
from jointwear.errors import ConfigError
from jointwear.materials import merge_material
from jointwear.units import shown

__all__ = [
    "MAX_KEY_PARTS",
    "apply_overrides",
    "check_key_depth",
    "deep_merge",
    "material_defaults",
    "normalized_overrides",
    "parse_override",
    "without_none",
]


def without_none(data: Mapping[str, Any]) -> dict[str, Any]:
    """``data`` (nested) without its ``None`` values: the keys a config left unset."""
    return {
        key: without_none(value) if isinstance(value, Mapping) else value
        for key, value in data.items()
        if value is not None
    }


def deep_merge(base: dict[str, Any], update: Mapping[str, Any]) -> dict[str, Any]:
    """A copy of ``base`` with ``update`` merged in, table by table (``update`` wins)."""
    out = copy.deepcopy(base)
    for key, value in update.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), dict):
            out[key] = deep_merge(out[key], value)
        else:
            out[key] = copy.deepcopy(value)
    return out


#: parts of the deepest dotted key read (the config's deepest has three:
#: ``materials.bushing.wear_coefficient``); a deeper one is refused before it is nested
MAX_KEY_PARTS = 16


def check_key_depth(dotted: str) -> None:
    """Refuse a dotted key of more than :data:`MAX_KEY_PARTS` parts, naming its start.

    Parameters
    ----------
    dotted : str
        The key as given, e.g. ``joint.clearance``.
    """
    parts = dotted.count(".") + 1
    if parts > MAX_KEY_PARTS:
        raise ConfigError(
            f"{dotted[:40]}...: a dotted key of {parts} parts; config keys have at most "
            f"{MAX_KEY_PARTS} (e.g. 'materials.bushing.wear_coefficient')"
        )


def parse_override(text: str) -> tuple[str, Any]:
    """Split ``section.key=VALUE``; VALUE is read as a TOML literal, else kept as text."""
    key, sep, raw = text.partition("=")
    key = key.strip()
    if not sep or not key:
        raise ConfigError(f"--set {text[:80]!r}: expected section.key=VALUE")
    check_key_depth(key)
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
        check_key_depth(dotted)
        parts = dotted.split(".")
        if _material_override(data, parts, value):
            continue
        node: Any = data
        for i, part in enumerate(parts[:-1]):
            child = _entry(node, parts[: i + 1], dotted)
            if child is None:
                child = node.setdefault(part, {})
            if isinstance(child, list) and parts[: i + 1] == ["mechanism", "modes"]:
                node = child
                continue
            if not isinstance(child, dict):
                raise ConfigError(f"{dotted}: {part!r} is a value, not a section")
            node = child
        if isinstance(node, list):
            node[_index(node, parts[-1], dotted)] = value
        else:
            _entry(node, parts, dotted)  # refuses a mode's number where there are no modes
            node[parts[-1]] = value


def _entry(node: Any, parts: list[str], dotted: str) -> Any:
    """The entry ``parts[-1]`` of ``node``: a duty cycle's mode by its index in the list
    of modes, else the key of a table (``None`` if the table lacks it)."""
    if isinstance(node, list):
        return node[_index(node, parts[-1], dotted)]
    if parts[-1].isdigit() and parts[:-1] == ["mechanism", "modes"]:
        raise ConfigError(
            f"{dotted}: the config has no [[mechanism.modes]] to number (only a "
            'mechanism of type = "duty-cycle" has modes)'
        )
    return node.get(parts[-1])


def _index(modes: list[Any], part: str, dotted: str) -> int:
    """The index ``part`` of a duty cycle's mode, checked against the modes there are."""
    index = mode_index(part, dotted)
    if index >= len(modes):
        raise ConfigError(
            f"{dotted}: no mode {index}; the duty cycle has {len(modes)} "
            f"mode{'s' if len(modes) != 1 else ''} (mechanism.modes.0 to "
            f"mechanism.modes.{len(modes) - 1})"
        )
    return index


def _material_override(data: dict[str, Any], parts: list[str], value: Any) -> bool:
    """Apply an override of ``materials.pin|bushing[.key]`` (True if it was one).

    A name replaces the material's table; a key updates it (a named material becomes a
    table naming it), and a wear form drops the others (:func:`materials.merge_material`).
    """
    if not (2 <= len(parts) <= 3 and parts[0] == "materials" and parts[1] in ("pin", "bushing")):
        return False
    materials = data.setdefault("materials", {})
    if not isinstance(materials, dict):
        raise ConfigError(f"{'.'.join(parts)}: 'materials' is a value, not a section")
    update = value if len(parts) == 2 else {parts[2]: value}
    materials[parts[1]] = merge_material(materials.get(parts[1], {}), update)
    return True


def material_defaults(defaults: dict[str, Any], data: Mapping[str, Any]) -> dict[str, Any]:
    """The parameter set's defaults under a config's materials: a named material drops
    them, a wear form drops the defaults' other forms."""
    given = data.get("materials")
    if not isinstance(given, Mapping) or not isinstance(defaults.get("materials"), dict):
        return defaults
    out = copy.deepcopy(defaults)
    for part in ("pin", "bushing"):
        if part in given and part in out["materials"]:
            out["materials"][part] = merge_material(out["materials"][part], given[part])
    return out
