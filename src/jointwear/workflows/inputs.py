"""What a workflow reads before it runs: a config file with its overrides, option texts."""

from __future__ import annotations

import math
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from jointwear.errors import ConfigError

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = ["load_config_file", "parse_align", "parse_loads", "split_list"]


def load_config_file(path: Path, overrides: Iterable[str] | None = None) -> Config:
    """Read a config file and apply ``--set`` overrides (errors name the file or key).

    Parameters
    ----------
    path : Path
        The TOML config file.
    overrides : iterable of str, optional
        ``section.key=VALUE`` strings (units allowed).

    Returns
    -------
    Config
        The validated configuration.

    Raises
    ------
    ConfigError
        The file does not exist, is not a valid config, or an override is not valid.
    """
    from jointwear.config import load_config

    if not path.exists():
        raise ConfigError(f"{path}: file not found")
    return load_config(path, list(overrides or []))


def split_list(values: Iterable[str] | None) -> list[str]:
    """Repeated and comma-separated option values as one list (``["a,b", "c"]`` -> a, b, c).

    Parameters
    ----------
    values : iterable of str, optional
        The option's values.

    Returns
    -------
    list of str
        Each item, stripped; empty items dropped.
    """
    out: list[str] = []
    for value in values or []:
        out.extend(part.strip() for part in value.split(",") if part.strip())
    return out


def parse_loads(text: str) -> list[float]:
    """Parse a ``--loads`` option: comma-separated forces with units (``"50 N,100 N"``).

    Parameters
    ----------
    text : str
        The option's text; each load a positive force with its unit.

    Returns
    -------
    list of float
        The loads [N].

    Raises
    ------
    ConfigError
        No load, a bad unit, or a load that is not positive and finite.
    """
    from jointwear.units import to_si

    loads = [to_si(part, "force", "--loads") for part in split_list([text])]
    if not loads or any(not (math.isfinite(f) and f > 0) for f in loads):
        raise ConfigError('--loads: give loads > 0, e.g. "50 N,100 N,200 N"')
    return loads


def parse_align(text: str) -> str | float:
    """Parse an ``--align`` option: ``"best"`` or an angle with units.

    Parameters
    ----------
    text : str
        ``"best"``, or the angle of the bushing's theta = 0 in the measurement's frame,
        e.g. ``"12 deg"`` (a bare number is radians).

    Returns
    -------
    str or float
        ``"best"``, or the angle [rad].
    """
    from jointwear.units import to_angle

    if text.strip().lower() == "best":
        return "best"
    return to_angle(text, "--align")
