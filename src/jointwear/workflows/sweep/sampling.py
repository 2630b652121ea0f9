"""Random samples of a sweep's ``[sample]`` table (numpy, seeded)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import to_si
from jointwear.workflows.sweep.keys import check_bare, check_value, swept_key, value_list

__all__ = ["DISTRIBUTIONS", "draw"]

#: distributions of ``[sample]`` and their parameters
DISTRIBUTIONS: dict[str, tuple[str, ...]] = {
    "uniform": ("low", "high"),
    "loguniform": ("low", "high"),
    "normal": ("mean", "std"),
    "lognormal": ("median", "sigma"),
    "choice": ("values",),
}
#: parameters of a distribution that are plain numbers (not quantities of the key)
_SHAPE_PARAMETERS = {"sigma"}


def draw(
    base: Config, dotted: str, dist: Any, n: int, rng: np.random.Generator, where: str
) -> list[Any]:
    """``n`` random values of a key from its ``[sample]`` distribution.

    ``uniform(low, high)``, ``loguniform(low, high)``, ``normal(mean, std)``,
    ``lognormal(median, sigma)`` (``sigma`` of the underlying normal, a plain number)
    and ``choice(values)``; the parameters are quantities of the key (units allowed).

    Parameters
    ----------
    base : Config
        The sweep's base configuration (a choice's values are checked on it).
    dotted : str
        Dotted config key.
    dist : mapping
        The key's table: ``distribution`` and its parameters.
    n : int
        Values to draw [-].
    rng : numpy.random.Generator
        The sweep's seeded generator.
    where : str
        Start of error messages.

    Returns
    -------
    list
        SI numbers (rounded for an integer key), or the chosen values as written.
    """
    key = swept_key(dotted, where)
    if not isinstance(dist, Mapping) or "distribution" not in dist:
        raise ConfigError(
            f'{where}: expected a table like {{distribution = "uniform", low = ..., high = ...}}'
        )
    name = dist["distribution"]
    if name not in DISTRIBUTIONS:
        raise ConfigError(
            f"{where}: unknown distribution {name!r}{suggest(str(name), DISTRIBUTIONS)}"
        )
    wanted = DISTRIBUTIONS[name]
    for param in dist:
        if param != "distribution" and param not in wanted:
            raise ConfigError(f"{where}: {name} has no parameter {param!r}{suggest(param, wanted)}")
    for param in wanted:
        if param not in dist:
            raise ConfigError(f"{where}: {name} needs {' and '.join(wanted)} ({param} missing)")
    if name == "choice":
        choices = value_list(dist["values"], f"{where}.values")
        for value in choices:
            check_value(base, dotted, value, f"{where}.values")
        return [choices[i] for i in rng.integers(0, len(choices), size=n)]
    if not key.numeric:
        raise ConfigError(f"{where}: a {name} distribution needs a numeric key; use 'choice'")

    def number(param: str) -> float:
        value = dist[param]
        kind = "dimensionless" if param in _SHAPE_PARAMETERS or key.kind is None else key.kind
        if kind == key.kind:
            check_bare(base, dotted, value, f"{where}.{param}")
        return to_si(value, kind, f"{where}.{param}")

    if name in ("uniform", "loguniform"):
        low, high = number("low"), number("high")
        if not low < high:
            raise ConfigError(f"{where}: needs low < high, got {dist['low']!r}, {dist['high']!r}")
        if name == "uniform":
            values = rng.uniform(low, high, size=n)
        else:
            if low <= 0:
                raise ConfigError(f"{where}: loguniform needs low > 0, got {dist['low']!r}")
            values = np.exp(rng.uniform(math.log(low), math.log(high), size=n))
    elif name == "normal":
        mean, std = number("mean"), number("std")
        if std < 0:
            raise ConfigError(f"{where}.std: must be >= 0, got {dist['std']!r}")
        values = rng.normal(mean, std, size=n)
    else:  # lognormal: median and sigma of the underlying normal
        median, sigma = number("median"), number("sigma")
        if median <= 0:
            raise ConfigError(f"{where}.median: must be > 0, got {dist['median']!r}")
        if sigma < 0:
            raise ConfigError(f"{where}.sigma: must be >= 0, got {dist['sigma']!r}")
        values = rng.lognormal(math.log(median), sigma, size=n)
    if key.integer:
        return [round(float(v)) for v in values]
    return [float(v) for v in values]
