"""What a sweep writes: ``cases.csv`` (one row per case) and ``sweep.nc``."""

from __future__ import annotations

import csv
import json
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from jointwear.errors import ConfigError
from jointwear.io import atomic_write
from jointwear.workflows.sweep.case import CASE_RESULTS, METRICS
from jointwear.workflows.sweep.plan import SweepPlan

__all__ = ["CASES_CSV", "DATASET_FILE", "write_cases_csv", "write_sweep_dataset"]

#: the sweep's tables inside its output directory
CASES_CSV = "cases.csv"
DATASET_FILE = "sweep.nc"


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

    from jointwear.results import ResultVariable, write_netcdf
    from jointwear.version import package_version

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
            "jointwear_version": package_version(),
        },
    )
    write_netcdf(dataset, path)
