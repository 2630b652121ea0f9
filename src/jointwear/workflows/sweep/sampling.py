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
from jointwear.workflows.sweep.keys import (
    SweptKey,
    check_bare,
    check_value,
    swept_key,
    value_list,
)

__all__ = ["DISTRIBUTIONS", "distribution_parameters", "draw", "quantile_values"]

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
    name, key, params = distribution_parameters(base, dotted, dist, where)
    if name == "choice":
        choices = params["values"]
        return [choices[i] for i in rng.integers(0, len(choices), size=n)]
    values = _draw_numbers(name, params, n, rng)
    if key.integer:
        return [round(float(v)) for v in values]
    return [float(v) for v in values]


def _draw_numbers(name: str, params: Mapping[str, Any], n: int, rng: np.random.Generator) -> Any:
    """``n`` draws of a numeric distribution from its SI parameters."""
    if name == "uniform":
        return rng.uniform(params["low"], params["high"], size=n)
    if name == "loguniform":
        return np.exp(rng.uniform(math.log(params["low"]), math.log(params["high"]), size=n))
    if name == "normal":
        return rng.normal(params["mean"], params["std"], size=n)
    return rng.lognormal(math.log(params["median"]), params["sigma"], size=n)


def distribution_parameters(
    base: Config, dotted: str, dist: Any, where: str
) -> tuple[str, SweptKey, dict[str, Any]]:
    """A ``[sample]`` table checked: its distribution's name, the key and its parameters.

    Parameters
    ----------
    base : Config
        The sweep's base configuration (a choice's values are checked on it).
    dotted : str
        Dotted config key.
    dist : mapping
        The key's table: ``distribution`` and its parameters.
    where : str
        Start of error messages.

    Returns
    -------
    name : str
        One of :data:`DISTRIBUTIONS`.
    key : SweptKey
        The key.
    params : dict
        The parameters in SI (``sigma`` a plain number; a choice's ``values`` as written).

    Raises
    ------
    ConfigError
        Unknown distribution or parameter, a missing one, a value out of range.
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
        return name, key, {"values": choices}
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
        if name == "loguniform" and low <= 0:
            raise ConfigError(f"{where}: loguniform needs low > 0, got {dist['low']!r}")
        return name, key, {"low": low, "high": high}
    if name == "normal":
        mean, std = number("mean"), number("std")
        if std < 0:
            raise ConfigError(f"{where}.std: must be >= 0, got {dist['std']!r}")
        return name, key, {"mean": mean, "std": std}
    median, sigma = number("median"), number("sigma")  # lognormal: of the underlying normal
    if median <= 0:
        raise ConfigError(f"{where}.median: must be > 0, got {dist['median']!r}")
    if sigma < 0:
        raise ConfigError(f"{where}.sigma: must be >= 0, got {dist['sigma']!r}")
    return name, key, {"median": median, "sigma": sigma}


def quantile_values(base: Config, dotted: str, dist: Any, quantiles: Any, where: str) -> list[Any]:
    """The values of a key at given quantiles of its ``[sample]`` distribution.

    The inverse of each distribution's CDF (scipy.stats): a design of points in the unit
    cube (Saltelli, Morris) becomes values with the key's distribution. A choice takes
    the value at ``floor(q * len(values))``.

    Parameters
    ----------
    base : Config
        The sweep's base configuration.
    dotted : str
        Dotted config key.
    dist : mapping
        The key's table: ``distribution`` and its parameters.
    quantiles : array_like
        Probabilities in (0, 1) [-].
    where : str
        Start of error messages.

    Returns
    -------
    list
        SI numbers (rounded for an integer key), or the chosen values as written.
    """
    from scipy import stats

    name, key, params = distribution_parameters(base, dotted, dist, where)
    q = np.asarray(quantiles, dtype=float)
    if name == "choice":
        choices = params["values"]
        index = np.minimum((q * len(choices)).astype(int), len(choices) - 1)
        return [choices[i] for i in index]
    if name == "uniform":
        values = stats.uniform(params["low"], params["high"] - params["low"]).ppf(q)
    elif name == "loguniform":
        values = stats.loguniform(params["low"], params["high"]).ppf(q)
    elif name == "normal":
        values = stats.norm(params["mean"], params["std"]).ppf(q)
    else:
        values = stats.lognorm(params["sigma"], scale=params["median"]).ppf(q)
    if key.integer:
        return [round(float(v)) for v in values]
    return [float(v) for v in values]
