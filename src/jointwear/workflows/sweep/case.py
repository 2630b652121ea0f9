"""One case of a sweep: its run, its record and its material checks."""

from __future__ import annotations

import math
import tomllib
import warnings
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from jointwear.config import config_from_dict
from jointwear.errors import JointwearError
from jointwear.tribology.metrics import CHECKS, WEAR_METRICS, engineering_checks

__all__ = [
    "CASE_LABELS",
    "CASE_RESULTS",
    "CHECK_COLUMNS",
    "FINISHED",
    "METRICS",
    "RUN_RESULTS",
    "case_checks",
    "limit_counts",
    "lost_record",
    "run_case",
    "run_cases",
]

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
#: statuses of a case record; "error" (internal error, lost worker) reruns on resume
FINISHED = ("ok", "failed")


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
        record.update(status="failed", error=one_line(str(exc)))
    except Exception as exc:
        record.update(
            status="error", error=one_line(f"internal error: {type(exc).__name__}: {exc}")
        )
    else:
        record["warnings"] = sorted({one_line(str(w.message)) for w in caught})
    return record


def one_line(text: str) -> str:
    """``text`` on one line (any run of white space, newlines included, one space)."""
    return " ".join(text.split())


def case_checks(result: Any) -> dict[str, Any]:
    """The material checks of a case (``run --json``'s ``checks``) as its sweep columns.

    Each joint is checked by
    :func:`~jointwear.tribology.metrics.engineering_checks` (an exceeded limit warns);
    with several joints each column holds the largest value over them.

    Parameters
    ----------
    result : jointwear.results.WearResult
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
    attrs = result.joint_data().attrs  # (a duty cycle's: the mean duration of a cycle)
    out: dict[str, Any] = {"period_s": float(attrs.get("mean_cycle_duration_s", attrs["period_s"]))}
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


def run_cases(tasks: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """:func:`run_case` of each task, in order (a chunk of a sweep,
    :func:`~jointwear.workflows.sweep.local.case_chunks`)."""
    return [run_case(task) for task in tasks]


def lost_record(name: str, why: str) -> dict[str, Any]:
    """The record of a case that ran but whose result was lost (its worker died).

    Parameters
    ----------
    name : str
        The case's name (``case-NNNN``).
    why : str
        What happened, one line.

    Returns
    -------
    dict
        A record with status ``"error"``: ``--resume`` runs the case again.
    """
    return {"case": name, "status": "error", "error": f"internal error: {why}", "warnings": []}
