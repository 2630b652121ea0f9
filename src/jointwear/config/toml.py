"""TOML in and out: reading a config file, writing a resolved config (``tomli-w``)."""

from __future__ import annotations

import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import tomli_w

from jointwear.config.lookup import bare_limited
from jointwear.errors import ConfigError
from jointwear.io import read_input
from jointwear.units import DIMENSIONS, shown

__all__ = ["MAX_TOML_DEPTH", "depth", "read_toml", "toml_ready", "toml_text"]


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
    text = read_input(path, "TOML file", error=error)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise error(f"{path}: not valid TOML ({exc})") from None
    except ValueError as exc:  # an integer of thousands of digits
        raise error(f"{path}: not readable TOML ({' '.join(str(exc).split()[:6])})") from None
    except RecursionError:
        data = None
    if data is None or depth(data) > MAX_TOML_DEPTH:
        raise error(f"{path}: nested more than {MAX_TOML_DEPTH} levels deep")
    return data


#: deepest nesting of tables and arrays accepted in a TOML file [-]
MAX_TOML_DEPTH = 32


def depth(value: Any) -> int:
    """Nesting depth of tables and arrays (a scalar is 0) [-]."""
    if isinstance(value, dict):
        return 1 + max((depth(v) for v in value.values()), default=0)
    if isinstance(value, list):
        return 1 + max((depth(v) for v in value), default=0)
    return 0


def toml_text(data: Mapping[str, Any], mechanism: str) -> str:
    """A resolved config's data as TOML text (SI units).

    A value a bare number would not be taken for
    (:func:`~jointwear.config.check_bare_numbers`, e.g. an angle of more than a turn)
    is written with its SI unit, so that the text reads back as the same config.

    Parameters
    ----------
    data : mapping
        Nested sections of SI values (:meth:`jointwear.config.Config.to_dict`); the
        values of such keys are replaced in it.
    mechanism : str
        The mechanism type whose ``mechanism.*`` keys ``data`` holds.
    """
    for values, name, _, kind, limit in list(bare_limited(data, mechanism)):
        value = values[name]
        if isinstance(value, float) and abs(value) > limit:
            values[name] = f"{value!r} {DIMENSIONS[kind]}"  # reads back exactly
    return tomli_w.dumps(toml_ready(data))


def toml_ready(data: Mapping[str, Any]) -> dict[str, Any]:
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
            value = toml_ready(value)
        for text in [key, *(value if isinstance(value, list) else [value])]:
            if isinstance(text, str) and any(0xD800 <= ord(c) <= 0xDFFF for c in text):
                raise ConfigError(f"{shown(text)}: not a valid Unicode string")
        out[key] = value
    return out
