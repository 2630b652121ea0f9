"""Parameter sweeps: many runs of one base configuration, in parallel.

A sweep file (TOML) names a base configuration and the values to vary::

    base = "base.toml"                 # relative to the sweep file
    [set]                              # fixed overrides for every case
    "simulation.revolutions" = 1
    [grid]                             # cartesian product
    "joint.clearance" = ["0.05 mm", "0.1 mm", "0.2 mm"]
    "mechanism.crank_speed" = ["120 rpm", "240 rpm"]
    [zip]                              # lists of equal length, taken row by row
    "contact.model" = ["winkler", "nlcp"]
    "contact.exponent" = [1.0, 1.5]
    [sample]                           # random samples (numpy, seeded)
    "materials.bushing.wear_coefficient" = {distribution = "lognormal",
                                            median = "5.05e-13 m^2/N", sigma = 0.5}
    samples = 8
    seed = 1

The cases are the product grid x zip x samples (each present part counts).
:func:`load_sweep` expands and validates everything before anything runs: an
unknown key or a value that cannot be read fails the whole sweep with one
line naming the sweep file and key. A combination that is invalid only
together (e.g. crank longer than rod) and any error during a case's run are
recorded as a *failed case* instead.

:func:`run_sweep` runs the cases on local processes
(:class:`concurrent.futures.ProcessPoolExecutor`) or on a dask.distributed
cluster, writes one record per case atomically as it finishes
(``DIR/cases/case-NNNN.json``) and finally ``DIR/cases.csv`` and
``DIR/sweep.nc``. ``run_sweep(..., resume=True)`` skips finished cases.
"""

from __future__ import annotations

import asyncio
import csv
import itertools
import json
import math
import multiprocessing
import os
import shutil
import threading
import time
import tomllib
import types
import typing
import uuid
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from jointwear.config import (
    Config,
    apply_overrides,
    check_bare_numbers,
    config_from_dict,
    error_key,
    is_section,
    key_field,
    load_config,
    read_toml,
)
from jointwear.errors import ConfigError, DataError, JointwearError
from jointwear.io import atomic_write, check_out, check_tree, read_input, write_json
from jointwear.registry import suggest
from jointwear.resources import check_case_count
from jointwear.tribology.metrics import CHECKS, WEAR_METRICS, engineering_checks
from jointwear.units import DIMENSIONS, to_si

__all__ = [
    "CHECK_COLUMNS",
    "DISTRIBUTIONS",
    "METRICS",
    "Case",
    "SweepPlan",
    "SweepResult",
    "case_checks",
    "expand_sweep",
    "limit_counts",
    "load_plan",
    "load_sweep",
    "run_case",
    "run_sweep",
]

#: top-level keys of a sweep file
SWEEP_KEYS = ("base", "set", "grid", "zip", "sample", "samples", "seed")
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
#: per-case metrics (the ``jointwear run --json`` keys) in ``cases.csv`` and ``sweep.nc``
#: name -> (units, long_name) of each per-case result of the run in ``sweep.nc``
RUN_RESULTS: dict[str, tuple[str, str]] = {
    **{
        m.key: ("degree" if m.key.endswith("_deg") else m.units, m.long_name)
        for m in WEAR_METRICS
        if m.key is not None
    },
    "revolutions": ("1", "revolutions"),
    "contour_updates": ("1", "contour updates"),
    "life_revolutions": ("1", "revolutions to the first life limit"),
    "life_hours": ("h", "hours to the first life limit"),
    "dynamics_updates": ("1", "solves of the dynamics on the worn joint"),
    "runtime_s": ("s", "run time of the case"),
}
#: the material checks of ``run --json``'s ``checks`` that have a limit: check -> the
#: column of its value (SI unit in the name); each also has a ``{check}_ratio`` column
CHECK_COLUMNS: dict[str, str] = {
    "nominal_pressure": "nominal_pressure_pa",
    "peak_pressure": "peak_pressure_pa",
    "sliding_speed": "sliding_speed_m_s",
    "pv": "pv_pa_m_s",
}
#: name -> (units, long_name) of each per-case material check in ``sweep.nc``
CHECK_RESULTS: dict[str, tuple[str, str]] = {
    "period_s": ("s", "period of the load cycle"),
    **{
        column: (CHECKS[check].unit, f"{CHECKS[check].label}: {CHECKS[check].description}")
        for check, column in CHECK_COLUMNS.items()
    },
    **{
        f"{check}_ratio": (
            "1",
            f"{CHECKS[check].label} / materials.bushing.{CHECKS[check].limit_key} "
            "(> 1: limit exceeded; NaN: no limit known)",
        )
        for check in CHECK_COLUMNS
    },
    "worst_limit_ratio": (
        "1",
        "largest ratio of a checked value to its materials.bushing limit (> 1: a limit "
        "exceeded; NaN: no limit known)",
    ),
}
CASE_RESULTS: dict[str, tuple[str, str]] = {**RUN_RESULTS, **CHECK_RESULTS}
#: per-case text results: of the run, and the exceeded checks (space-separated)
RUN_LABELS = ("contact_model", "stopped_by")
CASE_LABELS = (*RUN_LABELS, "exceeded_limits")
METRICS = (*CASE_RESULTS, *CASE_LABELS)
#: the sweep's own files inside its output directory
PLAN_FILE = "sweep-plan.json"
CASES_DIR = "cases"
CASES_CSV = "cases.csv"
DATASET_FILE = "sweep.nc"
#: seconds a dask scheduler has to answer the connection probe [s]
CONNECT_TIMEOUT = 10.0
#: statuses of a case record; "error" (internal error, lost worker) reruns on resume
FINISHED = ("ok", "failed")


# ---------------------------------------------------------------- config keys


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
class _Key:
    name: str
    kind: str | None
    types: frozenset[type]

    @property
    def numeric(self) -> bool:
        return self.kind is not None or bool(self.types & {int, float})

    @property
    def integer(self) -> bool:
        return self.kind is None and int in self.types and float not in self.types

    @property
    def unit(self) -> str | None:
        """SI unit for the column header; ``None`` for plain numbers, text and flags."""
        if self.kind is None:
            return None
        return DIMENSIONS[self.kind] or "1"

    @property
    def column(self) -> str:
        return self.name if self.unit is None else f"{self.name} [{self.unit}]"

    def si(self, value: Any) -> Any:
        """SI value of a sweep value (quantity strings converted; other values as given)."""
        if self.kind is not None:
            return to_si(value, self.kind, self.name)
        return value


def _key(dotted: str, where: str) -> _Key:
    if not isinstance(dotted, str) or not dotted:
        raise ConfigError(f"{where}: keys must be dotted config keys, e.g. 'joint.clearance'")
    info = _field(dotted, where)
    return _Key(dotted, _kind(info), frozenset(_base_types(info.annotation)))


# ---------------------------------------------------------------- the plan


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
    """

    base: Config
    keys: list[str]
    cases: list[Case]
    source: str = "sweep"
    seed: int | None = None

    def config(self, case: Case) -> Config:
        """The full configuration of ``case`` (raises ConfigError if invalid)."""
        return self.base.replace(case.overrides)

    def columns(self) -> list[_Key]:
        return [_key(name, self.source) for name in self.keys]

    def to_dict(self) -> dict[str, Any]:
        return {
            "format": "jointwear-sweep-1",
            "source": self.source,
            "seed": self.seed,
            # the raw fields: derived defaults (rod inertia, spring area) follow each case
            "base_config": _without_none(self.base.model_dump(mode="json")),
            "keys": self.keys,
            "cases": [
                {"case": c.name, "overrides": c.overrides, "invalid": c.invalid} for c in self.cases
            ],
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
            return cls(base, list(data["keys"]), cases, str(data["source"]), data.get("seed"))
        except ConfigError as exc:  # (a ValueError: first)
            raise DataError(f"{where}: base_config: {exc}") from None
        except (KeyError, TypeError, AttributeError, ValueError) as exc:
            raise DataError(f"{where}: not a jointwear sweep plan (bad {exc})") from None


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

    Parameters
    ----------
    spec : mapping
        Keys ``set``, ``grid``, ``zip``, ``sample``, ``samples``, ``seed``
        (``base`` is ignored here).
    base : Config
        Base configuration.
    source : str
        Name used at the start of error messages.
    """
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
            _key(dotted, f"{source}: [{name}]")

    if tables["set"]:
        for dotted, value in tables["set"].items():
            _check_value(base, dotted, value, f"{source}: [set] {dotted}")
        try:
            base = base.replace(tables["set"])
        except ConfigError as exc:
            raise ConfigError(f"{source}: [set]: {exc}") from None

    grid_axes = []
    for dotted, values in tables["grid"].items():
        values = _value_list(values, f"{source}: [grid] {dotted}")
        for value in values:
            _check_value(base, dotted, value, f"{source}: [grid] {dotted}")
        grid_axes.append([(dotted, v) for v in values])
    grid_count = math.prod(len(axis) for axis in grid_axes)
    check_case_count(grid_count, f"{source}: [grid]")
    grid_points = [dict(point) for point in itertools.product(*grid_axes)]

    zip_rows: list[dict[str, Any]] = [{}]
    if tables["zip"]:
        lengths = {}
        for dotted, values in tables["zip"].items():
            values = _value_list(values, f"{source}: [zip] {dotted}")
            for value in values:
                _check_value(base, dotted, value, f"{source}: [zip] {dotted}")
            lengths[dotted] = values
        sizes = {len(v) for v in lengths.values()}
        if len(sizes) > 1:
            detail = ", ".join(f"{k} has {len(v)}" for k, v in lengths.items())
            raise ConfigError(f"{source}: [zip] lists must have the same length ({detail})")
        zip_rows = [
            dict(zip(lengths, row, strict=True)) for row in zip(*lengths.values(), strict=True)
        ]

    samples = spec.get("samples")
    seed = spec.get("seed")
    sample_rows: list[dict[str, Any]] = [{}]
    if tables["sample"] or samples is not None:
        if not tables["sample"]:
            raise ConfigError(f"{source}: samples: given without a [sample] table")
        if samples is None:
            raise ConfigError(f"{source}: samples: missing (how many random samples to draw)")
        if isinstance(samples, bool) or not isinstance(samples, int) or samples < 1:
            raise ConfigError(f"{source}: samples: expected a positive integer, got {samples!r}")
        check_case_count(
            grid_count * len(zip_rows) * samples, f"{source}: samples ({samples}) x [grid] x [zip]"
        )
        if seed is None:
            seed = 0
        if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
            raise ConfigError(f"{source}: seed: expected a non-negative integer, got {seed!r}")
        rng = np.random.default_rng(seed)
        columns = {
            dotted: _draw(base, dotted, dist, samples, rng, f"{source}: [sample] {dotted}")
            for dotted, dist in tables["sample"].items()
        }
        sample_rows = [{k: columns[k][i] for k in columns} for i in range(samples)]
    elif seed is not None:
        raise ConfigError(f"{source}: seed: given without a [sample] table")

    check_case_count(grid_count * len(zip_rows), f"{source}: [grid] x [zip]")
    if not (tables["grid"] or tables["zip"] or tables["sample"]):
        raise ConfigError(f"{source}: nothing to sweep; give a [grid], [zip] or [sample] table")

    cases = []
    for index, (g, z, s) in enumerate(itertools.product(grid_points, zip_rows, sample_rows)):
        overrides = {**g, **z, **s}
        invalid = None
        try:
            base.replace(overrides)
        except ConfigError as exc:
            invalid = str(exc)
        cases.append(Case(index, overrides, invalid))
    keys = list(tables["grid"]) + list(tables["zip"]) + list(tables["sample"])
    return SweepPlan(base, keys, cases, source, seed if tables["sample"] else None)


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


def _value_list(values: Any, where: str) -> list[Any]:
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


def _check_bare(base: Config, dotted: str, value: Any, where: str) -> None:
    """A bare number that is a unit slip fails the sweep, as in a config file."""
    try:
        check_bare_numbers({dotted: value}, base.mechanism.type)
    except ConfigError as exc:
        raise ConfigError(f"{where}: {str(exc).removeprefix(f'{dotted}: ')}") from None


def _check_value(base: Config, dotted: str, value: Any, where: str) -> None:
    """A value must be valid on its own; combinations are judged per case.

    Errors of the field itself (wrong unit, out of range, unknown model ...)
    fail the sweep. An error that only arises together with other values
    (a section's cross-check, e.g. crank longer than rod) does not: the
    case that combines them is recorded as failed.
    """
    from pydantic import ValidationError

    _check_bare(base, dotted, value, where)
    data = _without_none(base.model_dump(mode="json"))
    apply_overrides(data, {dotted: value})
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


def _without_none(data: Mapping[str, Any]) -> dict[str, Any]:
    return {
        key: _without_none(value) if isinstance(value, Mapping) else value
        for key, value in data.items()
        if value is not None
    }


def _draw(
    base: Config, dotted: str, dist: Any, n: int, rng: np.random.Generator, where: str
) -> list[Any]:
    key = _key(dotted, where)
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
        choices = _value_list(dist["values"], f"{where}.values")
        for value in choices:
            _check_value(base, dotted, value, f"{where}.values")
        return [choices[i] for i in rng.integers(0, len(choices), size=n)]
    if not key.numeric:
        raise ConfigError(f"{where}: a {name} distribution needs a numeric key; use 'choice'")

    def number(param: str) -> float:
        value = dist[param]
        kind = "dimensionless" if param in _SHAPE_PARAMETERS or key.kind is None else key.kind
        if kind == key.kind:
            _check_bare(base, dotted, value, f"{where}.{param}")
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


# ---------------------------------------------------------------- one case


def run_case(task: Mapping[str, Any]) -> dict[str, Any]:
    """Run one case; never raises for a case's own failure.

    Parameters
    ----------
    task : mapping
        ``case`` (name), ``config`` (the resolved configuration as TOML text,
        :meth:`Config.to_toml`) and ``checkpoint`` (directory for the case's
        checkpoints or ``None``).

    Returns
    -------
    dict
        ``case``, ``status`` ("ok", "failed" for a :class:`JointwearError`,
        "error" for anything else), ``error`` (one line), ``metrics`` and
        ``wear_depth_m`` (final profile, list of floats).
    """
    from jointwear.simulation import Simulation

    record: dict[str, Any] = {"case": task["case"], "status": "ok", "error": "", "warnings": []}
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            config = config_from_dict(tomllib.loads(task["config"]), defaults=False)
            checkpointer = state = None
            if task.get("checkpoint") and config.simulation.checkpoint_every > 0:
                from jointwear.checkpoint import Checkpointer

                checkpointer = Checkpointer(task["checkpoint"], config)
                state = checkpointer.load()
                if state is None:
                    checkpointer.begin()
            # a case keeps scalars and the final profile: no Dataset, and the pressure
            # snapshots only where a limit compares their peak
            pressures = config.materials.bushing.max_static_pressure is not None
            result = Simulation(config).run(state=state, on_step=checkpointer, pressures=pressures)
            summary = result.summary()
            record["metrics"] = {name: summary[name] for name in (*RUN_RESULTS, *RUN_LABELS)}
            record["metrics"].update(case_checks(result))
        record["wear_depth_m"] = np.asarray(result.wear_depth, dtype=np.float64).tolist()
        for name in ("peak_wear_depth_m", "wear_width_deg", "wear_mass_kg", "wear_volume_m3"):
            if not math.isfinite(record["metrics"][name]):
                raise ArithmeticError(f"{name} is {record['metrics'][name]}")
    except JointwearError as exc:
        record.update(status="failed", error=_one_line(str(exc)))
    except Exception as exc:
        record.update(
            status="error", error=_one_line(f"internal error: {type(exc).__name__}: {exc}")
        )
    else:
        record["warnings"] = sorted({_one_line(str(w.message)) for w in caught})
    return record


def _one_line(text: str) -> str:
    return " ".join(text.split())


def case_checks(result: Any) -> dict[str, Any]:
    """The material checks of a case (``run --json``'s ``checks``) as its sweep columns.

    Each joint is checked by
    :func:`~jointwear.tribology.metrics.engineering_checks` (an exceeded limit warns);
    with several joints each column holds the largest value over them.

    Parameters
    ----------
    result : jointwear.simulation.WearResult
        The case's result.

    Returns
    -------
    dict
        ``period_s`` [s], the value of each check of :data:`CHECK_COLUMNS` (SI), its
        ratio to its limit ``{check}_ratio`` [-] (``None`` where no limit is known or
        the value was not computed), ``worst_limit_ratio`` [-] and ``exceeded_limits``
        (the exceeded checks, space-separated).
    """
    joints = result.joints
    checked = [
        engineering_checks(result.joint_data(joint if len(joints) > 1 else None), result.config)
        for joint in joints
    ]
    out: dict[str, Any] = {"period_s": float(result.joint_data().attrs["period_s"])}
    ratios = []
    for check, column in CHECK_COLUMNS.items():
        values = [c[check]["value"] for c in checked if math.isfinite(c[check]["value"])]
        out[column] = max(values) if values else None
        ratio = [
            c[check]["value"] / c[check]["limit"]
            for c in checked
            if c[check]["ok"] is not None and c[check]["limit"] > 0
        ]
        out[f"{check}_ratio"] = max(ratio) if ratio else None
        ratios += ratio
    out["worst_limit_ratio"] = max(ratios) if ratios else None
    out["exceeded_limits"] = " ".join(
        check for check in CHECK_COLUMNS if any(c[check]["ok"] is False for c in checked)
    )
    return out


def limit_counts(records: Sequence[Mapping[str, Any]]) -> dict[str, Any]:
    """How many finished cases were checked against a material limit, and exceeded one.

    Parameters
    ----------
    records : sequence of mapping
        Case records (:func:`run_case`).

    Returns
    -------
    dict
        ``limits_checked`` (cases with at least one limit known), ``limits_exceeded``
        (cases exceeding at least one) and ``limits_exceeded_by`` (check -> cases).
    """
    metrics = [r.get("metrics") or {} for r in records if r.get("status") == "ok"]
    exceeded = [set((m.get("exceeded_limits") or "").split()) for m in metrics]
    return {
        "limits_checked": sum(m.get("worst_limit_ratio") is not None for m in metrics),
        "limits_exceeded": sum(bool(e) for e in exceeded),
        "limits_exceeded_by": {c: sum(c in e for e in exceeded) for c in CHECK_COLUMNS},
    }


# ---------------------------------------------------------------- running


@dataclass
class SweepResult:
    """Outcome of :func:`run_sweep`.

    Attributes
    ----------
    out : Path
        Output directory.
    records : list of dict
        One per case, in case order (see :func:`run_case`).
    runtime : float
        Wall time of this invocation [s].
    skipped : int
        Cases already finished before (``resume=True``).
    scheduler : str
        ``"serial"``, ``"processes"`` or the dask scheduler address.
    workers : int or None
        Local processes that ran the cases (1: one after the other in this process;
        ``None`` on a dask cluster).
    counts : dict
        Cases by status (``"ok"``, ``"failed"``, ``"error"``).
    """

    out: Path
    records: list[dict[str, Any]]
    runtime: float
    skipped: int = 0
    scheduler: str = "processes"
    workers: int | None = None
    counts: dict[str, int] = field(default_factory=dict)

    def summary(self) -> dict[str, Any]:
        """The ``jointwear sweep --json`` object."""
        return {
            "cases": len(self.records),
            "ok": self.counts.get("ok", 0),
            "failed": self.counts.get("failed", 0),
            "errors": self.counts.get("error", 0),
            "skipped": self.skipped,
            "out": str(self.out),
            "cases_csv": str(self.out / CASES_CSV),
            "dataset": str(self.out / DATASET_FILE),
            "scheduler": self.scheduler,
            "workers": self.workers,
            **limit_counts(self.records),
            "runtime_s": self.runtime,
        }


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


def _read_record(path: Path) -> dict[str, Any] | None:
    try:
        record = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return None
    return record if isinstance(record, dict) and record.get("status") in FINISHED else None


def run_sweep(
    plan: SweepPlan,
    out: str | Path,
    *,
    scheduler: str | None = None,
    client: Any = None,
    workers: int | None = None,
    resume: bool = False,
    progress: Callable[[int, int], None] | None = None,
    connect_timeout: float | None = None,
) -> SweepResult:
    """Run every case of ``plan``, writing results into ``out``.

    Parameters
    ----------
    plan : SweepPlan
        From :func:`load_sweep` (or :func:`load_plan` to resume).
    out : path-like
        Output directory.
    scheduler : str, optional
        Address of a dask.distributed scheduler (``tcp://host:port``).
    client : dask.distributed.Client, optional
        An existing client (instead of ``scheduler``).
    workers : int, optional
        Local worker processes; ``1`` runs the cases one after the other in this
        process. Default: the first case runs here, and the rest on the CPUs available
        when that pays for starting the workers (:func:`default_workers`), else here.
    resume : bool
        Keep the finished cases already in ``out``; run the others.
    progress : callable, optional
        ``progress(cases_done, cases_total)``.
    connect_timeout : float, optional
        Seconds to wait for the dask scheduler to answer [s]; default
        :data:`CONNECT_TIMEOUT`.
    """
    start = time.perf_counter()
    # a link or special file planted inside must never redirect a write or a cleanup
    out = check_out(out, files=(PLAN_FILE, CASES_CSV, DATASET_FILE), dirs=(CASES_DIR,))
    check_tree(out, (CASES_DIR,))
    if workers is not None and workers < 1:
        raise ConfigError(f"--workers: must be >= 1, got {workers}")
    if (scheduler is not None or client is not None) and workers is not None:
        raise ConfigError("--workers: a dask cluster has its own workers; drop --workers")
    if not resume and (out / PLAN_FILE).exists():
        raise ConfigError(
            f"--out: {out} already holds a sweep; continue it with --resume {out} "
            "or choose another directory"
        )
    own_client = client is None and scheduler is not None
    if own_client:  # connect before anything is written
        client = _connect(
            scheduler, CONNECT_TIMEOUT if connect_timeout is None else connect_timeout
        )
    try:
        return _run(plan, out, client, workers, resume, progress, start)
    finally:
        if own_client:
            client.close()


def _run(
    plan: SweepPlan,
    out: Path,
    client: Any,
    workers: int | None,
    resume: bool,
    progress: Callable[[int, int], None] | None,
    start: float,
) -> SweepResult:
    cases_dir = out / CASES_DIR
    cases_dir.mkdir(parents=True, exist_ok=True)
    if not resume:
        write_json(out / PLAN_FILE, plan.to_dict())

    records: dict[int, dict[str, Any]] = {}
    for case in plan.cases:
        record = _read_record(cases_dir / f"{case.name}.json") if resume else None
        if record is not None:
            records[case.index] = record
    skipped = len(records)
    total = len(plan.cases)

    def finish(case: Case, record: dict[str, Any]) -> None:
        record["case"] = case.name
        record["parameters"] = case.overrides
        write_json(cases_dir / f"{case.name}.json", record)
        shutil.rmtree(cases_dir / case.name, ignore_errors=True)  # its checkpoints
        records[case.index] = record
        if progress is not None:
            progress(len(records), total)

    tasks = []
    for case in plan.cases:
        if case.index in records:
            continue
        if case.invalid is not None:
            finish(case, {"status": "failed", "error": case.invalid, "warnings": []})
            continue
        tasks.append((case, _task(plan, case, cases_dir)))
    if progress is not None:
        progress(len(records), total)

    if client is not None:
        mode = _run_dask(tasks, finish, client)
        used = None
    else:
        mode, used = _run_local(tasks, finish, workers)

    ordered = [records[case.index] for case in plan.cases]
    write_cases_csv(plan, ordered, out / CASES_CSV)
    write_sweep_dataset(plan, ordered, out / DATASET_FILE)
    counts = {s: sum(r["status"] == s for r in ordered) for s in ("ok", "failed", "error")}
    return SweepResult(
        out, ordered, time.perf_counter() - start, skipped, mode, used, counts=counts
    )


def _task(plan: SweepPlan, case: Case, cases_dir: Path) -> dict[str, Any]:
    config = plan.config(case)
    checkpoint = None
    if config.simulation.checkpoint_every > 0:
        checkpoint = str((cases_dir / case.name).resolve())
    return {"case": case.name, "config": config.to_toml(), "checkpoint": checkpoint}


def _cpus() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


#: seconds until a pool of local workers runs its first case, by start method [s]:
#: a forked worker inherits this process (numba's machine code loaded by the first
#: case); a spawned one imports jointwear and loads the compiled kernel again
WORKER_START = {"fork": 0.15, "forkserver": 2.0, "spawn": 2.0}
#: chunks of cases handed to each local worker (fewer hand-overs, still balanced)
CHUNKS_PER_WORKER = 8


def default_workers(case_seconds: float, remaining: int, cpus: int, method: str) -> int:
    """Local workers for the rest of a sweep, after one case took ``case_seconds``.

    ``w`` workers finish the remaining cases in about ``start + serial / w`` instead of
    ``serial = remaining * case_seconds``; they pay off when ``serial (1 - 1/w) >
    start``, ``start`` the time a pool needs to run its first case
    (:data:`WORKER_START`). Otherwise the cases run one after the other here, so a small
    sweep is never slower than serial.

    Parameters
    ----------
    case_seconds : float
        Wall time of the case that ran first [s].
    remaining : int
        Cases still to run.
    cpus : int
        Processors available to this process.
    method : str
        Start method of the worker processes (``"fork"``, ``"forkserver"``, ``"spawn"``).
    """
    workers = min(cpus, remaining)
    if workers < 2:
        return 1
    serial = case_seconds * remaining
    start = WORKER_START.get(method, WORKER_START["spawn"])
    return workers if serial * (1.0 - 1.0 / workers) > start else 1


def _start_method() -> str:
    """fork while this process has one thread (fast, and workers inherit what it loaded)."""
    methods = multiprocessing.get_all_start_methods()
    if "fork" in methods and threading.active_count() == 1:
        return "fork"
    return "forkserver" if "forkserver" in methods else "spawn"


def run_cases(tasks: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """:func:`run_case` of each task, in order (a chunk of a sweep, :func:`_chunks`)."""
    return [run_case(task) for task in tasks]


def _chunks(tasks: Sequence[Any], workers: int) -> list[Sequence[Any]]:
    """``tasks`` in order, cut into about :data:`CHUNKS_PER_WORKER` chunks per worker: a
    hand-over costs the workers' cores a few milliseconds, and a chunk each would leave
    them unbalanced at the end."""
    size = max(1, len(tasks) // (workers * CHUNKS_PER_WORKER))
    return [tasks[i : i + size] for i in range(0, len(tasks), size)]


def _run_local(
    tasks: Sequence[tuple[Case, dict[str, Any]]],
    finish: Callable[[Case, dict[str, Any]], None],
    workers: int | None,
) -> tuple[str, int]:
    """Run the cases on local processes; the mode (``"serial"``/``"processes"``), workers."""
    pending = list(tasks)
    method = _start_method()
    if workers == 1 or len(pending) <= 1 or (workers is None and _cpus() == 1):
        for case, task in pending:
            finish(case, run_case(task))
        return "serial", 1
    if workers is None or method == "fork":
        # the first case runs here: it shows what a case costs, and forked workers
        # inherit what it loaded (the compiled kernel) instead of loading it each
        case, task = pending.pop(0)
        began = time.perf_counter()
        finish(case, run_case(task))
        if workers is None:
            workers = default_workers(
                time.perf_counter() - began, len(pending), _cpus(), method
            )
        if workers == 1 or not pending:
            for case, task in pending:
                finish(case, run_case(task))
            return "serial", 1
    workers = min(workers, len(pending))
    chunks = _chunks(pending, workers)
    from concurrent.futures import ProcessPoolExecutor, as_completed
    from concurrent.futures.process import BrokenProcessPool

    executor = ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context(method))
    try:
        futures = {
            executor.submit(run_cases, [task for _, task in chunk]): chunk for chunk in chunks
        }
        # the workers exist now: load what sweep.nc is written with while they run
        # instead of after them (~0.5 s of imports)
        import h5netcdf  # noqa: F401
        import xarray  # noqa: F401

        for future in as_completed(futures):
            chunk = futures[future]
            try:
                records = future.result()
            except BrokenProcessPool:
                records = [_lost(case, "its worker process died") for case, _ in chunk]
            for (case, _), record in zip(chunk, records, strict=True):
                finish(case, record)
    except BaseException:
        # interrupted: stop the running cases now (their checkpoints are whole files)
        # instead of waiting for them at exit
        for process in list((getattr(executor, "_processes", None) or {}).values()):
            process.kill()
        executor.shutdown(wait=False, cancel_futures=True)
        raise
    executor.shutdown()
    return "processes", workers


def _lost(case: Case, why: str) -> dict[str, Any]:
    return {"case": case.name, "status": "error", "error": f"internal error: {why}", "warnings": []}


def _connect(scheduler: str, timeout: float) -> Any:
    """A dask.distributed client for ``scheduler`` (one-line errors if impossible)."""
    try:
        from dask.distributed import Client
    except ImportError:
        raise ConfigError(
            "--scheduler: dask.distributed is not installed; "
            "install it with `pip install 'jointwear[sweep]'`"
        ) from None
    _probe(scheduler, timeout)
    try:
        # not the process-wide default: a Client registers itself as dask's scheduler
        # before it connects, and a failed connection would leave that registration
        # behind for every later dask-aware call (xarray) in this process
        return Client(scheduler, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError, TypeError) as exc:
        why = _one_line(str(exc)) or type(exc).__name__
        raise ConfigError(f"--scheduler: cannot connect to {scheduler} ({why})") from None


def _probe(scheduler: str, timeout: float) -> None:
    """Check that a TCP address is a dask scheduler that answers within ``timeout`` [s].

    A ``Client`` that fails to connect is half built: at interpreter exit its
    destructor waits for a loop that never ran and prints a traceback; and a
    server that accepts the connection but never answers would keep it waiting.
    So first the address is parsed, a TCP connection opened, and the scheduler
    asked for its identity (dask's own handshake), all within ``timeout``.
    """
    import socket

    from distributed.comm.addressing import parse_address, parse_host_port

    try:
        protocol, location = parse_address(scheduler)
        if protocol == "inproc":
            # a scheduler in this very process (a LocalCluster without processes)
            from distributed.comm.inproc import global_manager

            if global_manager.get_listener_for(location) is None:
                raise ValueError("no scheduler at this in-process address")
            return
        if protocol not in ("tcp", "tls"):
            # a Client would wait for a transport that is not there and fail at exit
            # with a traceback
            raise ValueError(f"protocol {protocol!r} is not supported; give tcp://host:port")
        host, port = parse_host_port(location)
        if not 0 < int(port) < 65536:
            raise ValueError(f"port {port} is not in 1..65535")
    except (ValueError, TypeError) as exc:
        raise ConfigError(f"--scheduler: cannot connect to {scheduler} ({exc})") from None
    try:
        with socket.create_connection((host, port), timeout=timeout):
            pass
    except OSError as exc:
        why = _one_line(str(exc)) or type(exc).__name__
        raise ConfigError(f"--scheduler: cannot connect to {scheduler} ({why})") from None
    if protocol != "tcp":
        return  # TLS needs the cluster's certificates: the Client will handshake
    silent = ConfigError(
        f"--scheduler: no dask scheduler answered at {scheduler} within {timeout:g} s"
    )
    from concurrent.futures import ThreadPoolExecutor
    from concurrent.futures import TimeoutError as FutureTimeout

    # in a thread of its own: the caller may be inside an event loop (a notebook)
    executor = ThreadPoolExecutor(1, thread_name_prefix="jointwear-probe")
    try:
        reply = executor.submit(asyncio.run, _identity(scheduler, timeout)).result(timeout + 5)
    except (FutureTimeout, TimeoutError, OSError) as exc:
        raise silent from exc
    except Exception as exc:  # the comm's own errors: closed, bad handshake ...
        raise silent from exc
    finally:
        executor.shutdown(wait=False)
    if not isinstance(reply, Mapping) or reply.get("type") != "Scheduler":
        raise ConfigError(f"--scheduler: {scheduler} answered, but is not a dask scheduler")


async def _identity(address: str, timeout: float) -> Any:
    """The ``identity`` reply of the dask server at ``address`` (within ``timeout`` [s])."""
    from distributed.comm import connect

    async def ask() -> Any:
        comm = await connect(address, timeout=timeout)
        try:
            await comm.write({"op": "identity", "reply": True})
            return await comm.read()
        finally:
            comm.abort()

    return await asyncio.wait_for(ask(), timeout)


def _run_dask(
    tasks: Sequence[tuple[Case, dict[str, Any]]],
    finish: Callable[[Case, dict[str, Any]], None],
    client: Any,
) -> str:
    from dask.distributed import as_completed

    address = str(client.scheduler.address)
    token = uuid.uuid4().hex[:12]
    # chunks of cases, as for local workers: a task costs the scheduler, the client and
    # the worker a few milliseconds of the cores the cases run on
    chunks = _chunks(tasks, max(1, sum(client.nthreads().values())))
    futures: dict[Any, Sequence[tuple[Case, dict[str, Any]]]] = {}
    try:
        for chunk in chunks:
            key = f"jointwear-{chunk[0][0].name}-{len(chunk)}-{token}"
            tasks_of = [task for _, task in chunk]
            futures[client.submit(run_cases, tasks_of, key=key, pure=False)] = chunk
        for future in as_completed(list(futures), loop=client.loop):
            chunk = futures[future]
            if future.status == "finished":
                records = future.result()
            else:
                exc = future.exception()
                why = f"{type(exc).__name__}: {_one_line(str(exc))}"
                records = [_lost(case, why) for case, _ in chunk]
            for (case, _), record in zip(chunk, records, strict=True):
                finish(case, record)
    except BaseException:
        for future in futures:
            future.cancel()
        raise
    return address


# ---------------------------------------------------------------- outputs


def _parameter_values(plan: SweepPlan, records: Sequence[Mapping[str, Any]]) -> dict[str, list]:
    """SI value of every swept key in every case (``None`` if unreadable)."""
    values: dict[str, list] = {}
    for key in plan.columns():
        column = []
        for case in plan.cases:
            raw = case.overrides.get(key.name)
            try:
                column.append(key.si(raw))
            except ConfigError:
                column.append(None)
        values[key.name] = column
    return values


def write_cases_csv(
    plan: SweepPlan, records: Sequence[Mapping[str, Any]], path: str | Path
) -> None:
    """One row per case: parameters (SI, unit in the header), metrics, status, error."""
    keys = plan.columns()
    params = _parameter_values(plan, records)
    with atomic_write(path, newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["case", *(k.column for k in keys), *METRICS, "status", "error"])
        for i, (case, record) in enumerate(zip(plan.cases, records, strict=True)):
            metrics = record.get("metrics") or {}
            writer.writerow(
                [
                    case.name,
                    *(_cell(params[k.name][i]) for k in keys),
                    *(_cell(metrics.get(m)) for m in METRICS),
                    record["status"],
                    record.get("error", ""),
                ]
            )


def _cell(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def write_sweep_dataset(
    plan: SweepPlan, records: Sequence[Mapping[str, Any]], path: str | Path
) -> None:
    """``sweep.nc``: metrics, parameters and final wear profiles along ``case``."""
    import xarray as xr

    from jointwear import __version__
    from jointwear.results import ResultVariable, write_netcdf

    n = len(records)
    profiles = [r.get("wear_depth_m") for r in records]
    sizes = {len(p) for p in profiles if p}
    nodes = max(sizes) if sizes else plan.base.contact.nodes
    theta = 2 * np.pi * np.arange(nodes) / nodes
    depth = np.full((n, nodes), np.nan)
    for i, profile in enumerate(profiles):
        if not profile:
            continue
        values = np.asarray(profile, dtype=np.float64)
        if values.size == nodes:
            depth[i] = values
        else:  # a coarser mesh: periodic linear interpolation onto the finest one
            own = 2 * np.pi * np.arange(values.size) / values.size
            depth[i] = np.interp(theta, own, values, period=2 * np.pi)

    def var(values, units, long_name, dims=("case",)):
        return ResultVariable(dims, values, {"units": units, "long_name": long_name}).to_variable()

    data_vars: dict[str, Any] = {}
    for name, (unit, long_name) in CASE_RESULTS.items():
        column = [(r.get("metrics") or {}).get(name) for r in records]
        data_vars[name] = var(
            np.array([np.nan if v is None else float(v) for v in column]), unit, long_name
        )
    for name, long_name in (
        ("contact_model", "contact model"),
        ("stopped_by", "life limit that ended the case"),
        ("exceeded_limits", "material checks whose limit the case exceeds (space-separated)"),
    ):
        data_vars[name] = var(
            np.array([(r.get("metrics") or {}).get(name) or "" for r in records], dtype=str),
            "",
            long_name,
        )
    data_vars["status"] = var(np.array([r["status"] for r in records], dtype=str), "", "status")
    data_vars["error"] = var(
        np.array([r.get("error", "") for r in records], dtype=str), "", "error message"
    )
    data_vars["wear_depth"] = var(depth, "m", "final radial wear depth", ("case", "theta"))
    params = _parameter_values(plan, records)
    for key in plan.columns():
        column = params[key.name]
        name = key.name
        if key.numeric and all(isinstance(v, int | float) or v is None for v in column):
            values = np.array([np.nan if v is None else float(v) for v in column])
        else:
            values = np.array(["" if v is None else _cell(v) for v in column], dtype=str)
        data_vars[name] = var(values, key.unit or "", f"swept parameter {name}")
    dataset = xr.Dataset(
        data_vars,
        coords={
            "case": var(np.array([c.name for c in plan.cases], dtype=str), "", "case"),
            "theta": var(theta, "rad", "bushing angle", ("theta",)),
        },
        attrs={
            "title": "jointwear sweep",
            "source": plan.source,
            "swept_keys": json.dumps(plan.keys),
            "seed": -1 if plan.seed is None else plan.seed,
            "base_config": plan.base.to_toml(),
            "jointwear_version": __version__,
        },
    )
    write_netcdf(dataset, path)
