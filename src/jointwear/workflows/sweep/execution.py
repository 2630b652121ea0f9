"""Running a sweep: every case once (the finished ones kept on resume), then its outputs."""

from __future__ import annotations

import json
import shutil
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from jointwear.errors import ConfigError
from jointwear.io import check_out, check_tree, write_json
from jointwear.workflows.sweep.case import FINISHED, limit_counts
from jointwear.workflows.sweep.cluster import connect, run_dask
from jointwear.workflows.sweep.local import run_local
from jointwear.workflows.sweep.outputs import (
    CASES_CSV,
    DATASET_FILE,
    write_cases_csv,
    write_sweep_dataset,
)
from jointwear.workflows.sweep.plan import PLAN_FILE, Case, SweepPlan

__all__ = ["CASES_DIR", "SweepResult", "run_sweep"]

#: one record per case (``case-NNNN.json``) and each running case's checkpoints
CASES_DIR = "cases"


@dataclass
class SweepResult:
    """Outcome of :func:`run_sweep`.

    Attributes
    ----------
    out : Path
        Output directory.
    records : list of dict
        One per case, in case order (see :func:`~jointwear.workflows.sweep.case.run_case`).
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
        From :func:`~jointwear.workflows.sweep.plan.load_sweep` (or
        :func:`~jointwear.workflows.sweep.plan.load_plan` to resume).
    out : path-like
        Output directory.
    scheduler : str, optional
        Address of a dask.distributed scheduler (``tcp://host:port``).
    client : dask.distributed.Client, optional
        An existing client (instead of ``scheduler``).
    workers : int, optional
        Local worker processes; ``1`` runs the cases one after the other in this
        process. Default: the first case runs here, and the rest on the CPUs available
        when that pays for starting the workers
        (:func:`~jointwear.workflows.sweep.local.default_workers`), else here.
    resume : bool
        Keep the finished cases already in ``out``; run the others.
    progress : callable, optional
        ``progress(cases_done, cases_total)``.
    connect_timeout : float, optional
        Seconds to wait for the dask scheduler to answer [s]; default
        :data:`~jointwear.workflows.sweep.cluster.CONNECT_TIMEOUT`.
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
        client = connect(scheduler, connect_timeout)
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
        mode = run_dask(tasks, finish, client)
        used = None
    else:
        mode, used = run_local(tasks, finish, workers)

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
