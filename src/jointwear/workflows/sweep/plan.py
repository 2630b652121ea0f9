"""The plan of a sweep: the sweep file read, expanded into validated cases, stored."""

from __future__ import annotations

import itertools
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from jointwear.config import Config, config_from_dict, is_section, load_config, read_toml
from jointwear.errors import ConfigError, DataError
from jointwear.io import read_input
from jointwear.registry import suggest
from jointwear.resources import check_case_count
from jointwear.workflows.sweep.keys import (
    SweptKey,
    check_address,
    check_value,
    swept_key,
    value_list,
    without_none,
)
from jointwear.workflows.sweep.sampling import draw

__all__ = [
    "PLAN_FILE",
    "SEED_MAX",
    "SWEEP_KEYS",
    "Case",
    "SweepPlan",
    "expand_sweep",
    "load_plan",
    "load_sweep",
    "seed_problem",
]

#: top-level keys of a sweep file
SWEEP_KEYS = ("base", "set", "grid", "zip", "sample", "samples", "seed")
#: the plan, stored in the sweep's output directory (read back by ``--resume``)
PLAN_FILE = "sweep-plan.json"
#: the largest seed: ``sweep.nc`` stores it as a 64-bit integer attribute
SEED_MAX = 2**63 - 1


@dataclass(frozen=True)
class Case:
    """One run of a sweep: the base configuration plus ``overrides``.

    Attributes
    ----------
    index : int
        Position in the sweep (0-based).
    overrides : dict
        Dotted key -> value as written in the sweep file (units allowed), or
        the SI number drawn for a ``[sample]`` key.
    invalid : str or None
        Why the case's configuration is invalid (it is then recorded as failed
        without running).
    """

    index: int
    overrides: dict[str, Any]
    invalid: str | None = None

    @property
    def name(self) -> str:
        return f"case-{self.index:04d}"

    @classmethod
    def checked(cls, base: Config, index: int, overrides: dict[str, Any]) -> Case:
        """The case of ``overrides`` on ``base``, marked invalid if they are together."""
        try:
            base.replace(overrides)
        except ConfigError as exc:
            return cls(index, overrides, str(exc))
        return cls(index, overrides)


@dataclass(frozen=True)
class SweepPlan:
    """An expanded, validated sweep: base configuration and its cases.

    Attributes
    ----------
    base : Config
        Base configuration (with the sweep file's ``[set]`` applied).
    keys : list of str
        Swept dotted keys, in file order (grid, zip, sample).
    cases : list of Case
    source : str
        Where the sweep came from (file name, for messages).
    seed : int or None
        Seed of the random samples.
    study : dict
        What a study built on the sweep needs to finish it on ``--resume`` (a life
        study's ``{"kind": "life", ...}``); empty for a plain sweep.
    """

    base: Config
    keys: list[str]
    cases: list[Case]
    source: str = "sweep"
    seed: int | None = None
    study: dict[str, Any] = field(default_factory=dict)

    def config(self, case: Case) -> Config:
        """The full configuration of ``case`` (raises ConfigError if invalid)."""
        return self.base.replace(case.overrides)

    def columns(self) -> list[SweptKey]:
        return [swept_key(name, self.source) for name in self.keys]

    def to_dict(self) -> dict[str, Any]:
        return {
            "format": "jointwear-sweep-1",
            "source": self.source,
            "seed": self.seed,
            # the raw fields: derived defaults (rod inertia, spring area) follow each case
            "base_config": without_none(self.base.model_dump(mode="json")),
            "keys": self.keys,
            "cases": [
                {"case": c.name, "overrides": c.overrides, "invalid": c.invalid} for c in self.cases
            ],
            **({"study": self.study} if self.study else {}),
        }

    @classmethod
    def from_dict(cls, data: Mapping[str, Any], where: str) -> SweepPlan:
        try:
            if data.get("format") != "jointwear-sweep-1":
                raise KeyError("format")
            base = config_from_dict(data["base_config"], defaults=False)
            cases = [
                Case(i, dict(c["overrides"]), c.get("invalid")) for i, c in enumerate(data["cases"])
            ]
            study = dict(data.get("study") or {})
            plan = cls(
                base, list(data["keys"]), cases, str(data["source"]), data.get("seed"), study
            )
        except ConfigError as exc:  # (a ValueError: first)
            raise DataError(f"{where}: base_config: {exc}") from None
        except (KeyError, TypeError, AttributeError, ValueError) as exc:
            raise DataError(f"{where}: not a jointwear sweep plan (bad {exc})") from None
        plan.check_cases(where)
        return plan

    def check_cases(self, where: str) -> None:
        """Refuse a stored plan whose cases were changed by hand (before anything runs).

        Every case may set only the plan's keys, and a case not marked invalid must
        give a valid configuration, as :func:`expand_sweep` left it.

        Raises
        ------
        DataError
            Naming the plan file, the case and the key or reason.
        """
        problem = None if self.seed is None else seed_problem(self.seed)
        if problem is not None:
            raise DataError(f"{where}: seed: {problem}")
        for key in self.keys:
            try:
                swept_key(key, f"{where}: keys")
            except ConfigError as exc:
                raise DataError(str(exc)) from None
        for case in self.cases:
            extra = sorted(set(case.overrides) - set(self.keys))
            if extra:
                raise DataError(f"{where}: {case.name}: {extra[0]} is not a key of this sweep")
            if case.invalid is not None:
                if not isinstance(case.invalid, str):
                    raise DataError(f"{where}: {case.name}: invalid: expected a message")
                continue
            try:
                self.config(case)
            except ConfigError as exc:
                raise DataError(f"{where}: {case.name}: {exc}") from None


def load_sweep(path: str | Path) -> SweepPlan:
    """Read a sweep file and expand it into validated cases.

    Raises
    ------
    ConfigError
        The file is missing, not TOML, or has an unknown key, a bad value, an
        unknown distribution ... (one line naming the file and the key).
    """
    path = Path(path)
    spec = read_toml(path)
    base_ref = spec.get("base")
    if base_ref is None:
        base = load_config()
    elif not isinstance(base_ref, str):
        raise ConfigError(f"{path}: base: expected a path to a config file, got {base_ref!r}")
    else:
        base_path = path.parent / base_ref
        try:
            base = load_config(base_path)
        except ConfigError as exc:
            raise ConfigError(f"{path}: base = {base_ref!r}: {exc}") from None
    return expand_sweep(spec, base, source=str(path))


def expand_sweep(spec: Mapping[str, Any], base: Config, source: str = "sweep") -> SweepPlan:
    """Expand a sweep specification (the parsed sweep file) on ``base``.

    The cases are the product grid x zip x samples (each present part counts); every
    key and value is checked before a case exists, and a case whose combination of
    values is invalid is kept, marked :attr:`Case.invalid`.

    Parameters
    ----------
    spec : mapping
        Keys ``set``, ``grid``, ``zip``, ``sample``, ``samples``, ``seed``
        (``base`` is ignored here).
    base : Config
        Base configuration.
    source : str
        Name used at the start of error messages.

    Raises
    ------
    ConfigError
        An unknown key, a bad value or distribution, too many cases, nothing to sweep.
    """
    tables, samples, seed = _tables(spec, source)
    if tables["set"]:
        base = _with_set(base, tables["set"], source)
    for name in ("grid", "zip", "sample"):
        for dotted in tables[name]:
            check_address(base, dotted, f"{source}: [{name}]")
    grid_points = _grid_points(base, tables["grid"], source)
    zip_rows = _zip_rows(base, tables["zip"], source)
    sample_rows: list[dict[str, Any]] = [{}]
    if tables["sample"] or samples is not None:
        before = len(grid_points) * len(zip_rows)
        sample_rows, seed = _sample_rows(base, tables["sample"], samples, seed, before, source)
    elif seed is not None:
        raise ConfigError(f"{source}: seed: given without a [sample] table")
    check_case_count(len(grid_points) * len(zip_rows), f"{source}: [grid] x [zip]")
    if not (tables["grid"] or tables["zip"] or tables["sample"]):
        raise ConfigError(f"{source}: nothing to sweep; give a [grid], [zip] or [sample] table")
    cases = [
        Case.checked(base, index, {**g, **z, **s})
        for index, (g, z, s) in enumerate(itertools.product(grid_points, zip_rows, sample_rows))
    ]
    keys = list(tables["grid"]) + list(tables["zip"]) + list(tables["sample"])
    return SweepPlan(base, keys, cases, source, seed if tables["sample"] else None)


def _tables(spec: Mapping[str, Any], source: str) -> tuple[dict[str, dict[str, Any]], Any, Any]:
    """The ``set``, ``grid``, ``zip`` and ``sample`` tables with dotted keys, each key in
    one of them and a config key; and the ``samples`` and ``seed`` settings."""
    for key in spec:
        if key not in SWEEP_KEYS:
            raise ConfigError(f"{source}: unknown key {key!r}{suggest(key, SWEEP_KEYS)}")
    tables = {}
    for name in ("set", "grid", "zip", "sample"):
        table = spec.get(name, {})
        if not isinstance(table, Mapping):
            raise ConfigError(f"{source}: [{name}] must be a table of dotted keys")
        tables[name] = table
    spec = dict(spec)
    sample_table = dict(tables["sample"])
    for setting in ("samples", "seed"):  # TOML puts them inside [sample] if written after it
        if setting in sample_table:
            if setting in spec:
                raise ConfigError(f"{source}: {setting}: given twice (top level and in [sample])")
            spec[setting] = sample_table.pop(setting)
    tables["sample"] = sample_table
    tables = {name: _flatten(table) for name, table in tables.items()}
    seen: dict[str, str] = {}
    for name, table in tables.items():
        for dotted in table:
            if dotted in seen:
                raise ConfigError(
                    f"{source}: {dotted}: appears in both [{seen[dotted]}] and [{name}]"
                )
            seen[dotted] = name
            swept_key(dotted, f"{source}: [{name}]")
    return tables, spec.get("samples"), spec.get("seed")


def _with_set(base: Config, table: Mapping[str, Any], source: str) -> Config:
    """``base`` with the ``[set]`` overrides of every case."""
    for dotted, value in table.items():
        check_value(base, dotted, value, f"{source}: [set] {dotted}")
    try:
        return base.replace(table)
    except ConfigError as exc:
        raise ConfigError(f"{source}: [set]: {exc}") from None


def _grid_points(base: Config, table: Mapping[str, Any], source: str) -> list[dict[str, Any]]:
    """The cartesian product of the ``[grid]`` lists, in file order."""
    grid_axes = []
    for dotted, values in table.items():
        values = value_list(values, f"{source}: [grid] {dotted}")
        for value in values:
            check_value(base, dotted, value, f"{source}: [grid] {dotted}")
        grid_axes.append([(dotted, v) for v in values])
    check_case_count(math.prod(len(axis) for axis in grid_axes), f"{source}: [grid]")
    return [dict(point) for point in itertools.product(*grid_axes)]


def _zip_rows(base: Config, table: Mapping[str, Any], source: str) -> list[dict[str, Any]]:
    """The ``[zip]`` lists taken row by row (one empty row without them)."""
    if not table:
        return [{}]
    lengths = {}
    for dotted, values in table.items():
        values = value_list(values, f"{source}: [zip] {dotted}")
        for value in values:
            check_value(base, dotted, value, f"{source}: [zip] {dotted}")
        lengths[dotted] = values
    sizes = {len(v) for v in lengths.values()}
    if len(sizes) > 1:
        detail = ", ".join(f"{k} has {len(v)}" for k, v in lengths.items())
        raise ConfigError(f"{source}: [zip] lists must have the same length ({detail})")
    return [dict(zip(lengths, row, strict=True)) for row in zip(*lengths.values(), strict=True)]


def _sample_rows(
    base: Config,
    table: Mapping[str, Any],
    samples: Any,
    seed: Any,
    other_cases: int,
    source: str,
) -> tuple[list[dict[str, Any]], int]:
    """``samples`` random draws of the ``[sample]`` keys (seed 0 unless given), and the seed.

    ``other_cases`` is the number of grid x zip cases each draw multiplies.
    """
    if not table:
        raise ConfigError(f"{source}: samples: given without a [sample] table")
    if samples is None:
        raise ConfigError(f"{source}: samples: missing (how many random samples to draw)")
    if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
        raise ConfigError(f"{source}: samples: expected a positive integer, got {samples!r}")
    check_case_count(other_cases * samples, f"{source}: samples ({samples}) x [grid] x [zip]")
    if seed is None:
        seed = 0
    problem = seed_problem(seed)
    if problem is not None:
        raise ConfigError(f"{source}: seed: {problem}")
    rng = np.random.default_rng(seed)
    columns = {
        dotted: draw(base, dotted, dist, samples, rng, f"{source}: [sample] {dotted}")
        for dotted, dist in table.items()
    }
    return [{k: columns[k][i] for k in columns} for i in range(samples)], seed


def seed_problem(seed: Any) -> str | None:
    """Why ``seed`` cannot seed a sweep, or ``None``.

    A seed is a whole number from 0 to 2**63 - 1: ``sweep.nc`` stores it as a 64-bit
    integer attribute (numpy would take a longer one, and the cases would run, only
    for the dataset to fail at the end).

    Parameters
    ----------
    seed : Any
        The seed as read [-].
    """
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        return f"expected a non-negative integer, got {str(seed)[:40]!r}"
    if seed > SEED_MAX:
        return f"at most 2**63 - 1 (the dataset stores it in 64 bits), got {len(str(seed))} digits"
    return None


def _flatten(table: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """``{"joint": {"clearance": [...]}}`` and ``{"joint.clearance": [...]}`` alike.

    Nested tables are followed only while they name a config section, so a
    ``[sample]`` entry (itself a table) stays one value.
    """
    out: dict[str, Any] = {}
    for key, value in table.items():
        dotted = f"{prefix}{key}"
        if isinstance(value, Mapping) and is_section(dotted):
            out.update(_flatten(value, dotted + "."))
        else:
            out[dotted] = value
    return out


def load_plan(out: str | Path) -> SweepPlan:
    """The plan stored in a sweep's output directory (for ``--resume``)."""
    out = Path(out)
    path = out / PLAN_FILE
    if not out.is_dir():
        raise DataError(f"{out}: no such directory to resume")
    if not (path.exists() or path.is_symlink()):
        raise DataError(f"{out}: not a sweep directory (no {PLAN_FILE})")
    try:
        data = json.loads(read_input(path, "sweep plan"))
    except json.JSONDecodeError as exc:
        raise DataError(f"{path}: unreadable sweep plan ({type(exc).__name__})") from None
    if not isinstance(data, dict):
        raise DataError(f"{path}: not a jointwear sweep plan")
    return SweepPlan.from_dict(data, str(path))
