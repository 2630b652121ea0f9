"""Running a sweep: every case once (the finished ones kept on resume), then its outputs."""

from __future__ import annotations

import contextlib
import json
import shutil
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from jointwear.errors import ConfigError, DataError
from jointwear.io import check_out, check_tree, os_reason, write_json
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

__all__ = [
    "CASES_DIR",
    "SIZING_KEYS",
    "SweepResult",
    "checked_progress",
    "resume_command",
    "run_sweep",
    "sweep_to_folder",
    "writing",
]

#: one record per case (``case-NNNN.json``) and each running case's checkpoints
CASES_DIR = "cases"
#: config keys that set the memory of a case
SIZING_KEYS = {
    "contact.nodes",
    "simulation.steps_per_revolution",
    "simulation.saved_profiles",
    "mechanism.clearance_joint",
}


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
    if not resume:
        _start(plan, out)
    command = resume_command(plan, out)
    with writing(out, CASES_DIR, command):
        cases_dir.mkdir(parents=True, exist_ok=True)

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
        with writing(out, f"{CASES_DIR}/{case.name}.json", command):
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
    with writing(out, CASES_CSV, command):
        write_cases_csv(plan, ordered, out / CASES_CSV)
    with writing(out, DATASET_FILE, command):
        write_sweep_dataset(plan, ordered, out / DATASET_FILE)
    counts = {s: sum(r["status"] == s for r in ordered) for s in ("ok", "failed", "error")}
    return SweepResult(
        out, ordered, time.perf_counter() - start, skipped, mode, used, counts=counts
    )


def _start(plan: SweepPlan, out: Path) -> None:
    """Create ``out`` with the plan; if that fails, leave nothing behind."""
    created = [p for p in (*reversed(out.parents), out) if not p.exists()]
    try:
        with writing(out, PLAN_FILE):
            out.mkdir(parents=True, exist_ok=True)
            write_json(out / PLAN_FILE, plan.to_dict())
    except DataError:
        for folder in reversed(created):
            with contextlib.suppress(OSError):
                folder.rmdir()
        raise


@contextlib.contextmanager
def writing(out: Path, name: str, resume: str | None = None) -> Iterator[None]:
    """A write into a sweep's folder that fails (a full disk) as one line naming the file.

    Parameters
    ----------
    out : Path
        The sweep's folder.
    name : str
        The file written, relative to ``out``.
    resume : str, optional
        The command that continues the sweep, named in the message.


    The writers are atomic, so the file is either whole or absent; once the plan is
    written, the finished cases are kept and the message says how to continue.
    """
    try:
        yield
    except OSError as exc:
        message = f"--out: {out / name}: {os_reason(exc)}"
        if resume is not None:
            message += f"; the finished cases are kept, continue with `{resume}`"
        raise DataError(message) from None


def resume_command(plan: SweepPlan, out: Path) -> str:
    """The command that continues the sweep (or life study) in ``out``."""
    command = "life" if plan.study.get("kind") == "life" else "sweep"
    return f"jointwear {command} --resume {out}"


def _task(plan: SweepPlan, case: Case, cases_dir: Path) -> dict[str, Any]:
    config = plan.config(case)
    checkpoint = None
    if config.simulation.checkpoint_every > 0:
        checkpoint = str((cases_dir / case.name).resolve())
    return {"case": case.name, "config": config.to_toml(), "checkpoint": checkpoint}


def sweep_to_folder(
    sweep_file: Path | None = None,
    out: Path | None = None,
    *,
    resume: Path | None = None,
    scheduler: str | None = None,
    workers: int | None = None,
    max_memory: str | None = None,
    time_limit: float | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> SweepResult:
    """Run a sweep file into a folder, or continue the sweep in a folder (``jointwear sweep``).

    The options, the sweep file (every case expanded and checked) and the memory of
    the largest case are checked before a case runs.

    Parameters
    ----------
    sweep_file : Path, optional
        The sweep file (TOML); omitted with ``resume``.
    out : Path, optional
        Output directory (needed without ``resume``).
    resume : Path, optional
        The folder of an unfinished sweep: its finished cases are kept, the rest run.
    scheduler : str, optional
        Address of a dask.distributed scheduler (``tcp://host:port``).
    workers : int, optional
        Local worker processes (see :func:`run_sweep`).
    max_memory : str, optional
        Refuse a sweep whose running cases would need more memory than this, e.g.
        ``"16 GiB"``.
    time_limit : float, optional
        Stop with :class:`~jointwear.errors.TimeLimitError` after this wall-clock
        time [s], checked between cases.
    progress : callable, optional
        ``progress(cases_done, cases_total)`` [-].

    Returns
    -------
    SweepResult
        The records of every case, in case order.

    Raises
    ------
    ConfigError
        Conflicting options, a bad sweep file, too little memory.
    DataError
        ``resume`` names no sweep folder.
    """
    from jointwear.interrupts import with_resume
    from jointwear.workflows.sweep.plan import load_plan, load_sweep

    if workers is not None and workers < 1:
        raise ConfigError(f"--workers: must be >= 1, got {workers}")
    if scheduler is not None and workers is not None:
        raise ConfigError("--workers: a dask cluster has its own workers; drop --workers")
    if resume is not None:
        if sweep_file is not None:
            raise ConfigError(
                f"--resume: give either SWEEP_FILE ({sweep_file}) or --resume DIR, not both"
            )
        if out is not None and out.resolve() != resume.resolve():
            raise ConfigError("--out: a resumed sweep writes into its --resume directory")
        plan = load_plan(resume)
        if plan.study.get("kind") == "life":  # its life.json and life.png need `life`
            raise ConfigError(
                f"--resume: {resume} holds a life study; continue it with "
                f"`jointwear life --resume {resume}`"
            )
        out = resume
    else:
        if sweep_file is None:
            raise ConfigError("SWEEP_FILE: missing; give a sweep file or --resume DIR")
        if out is None:
            raise ConfigError("--out: missing; the sweep needs a directory for its results")
        if out.exists() and not out.is_dir():
            raise ConfigError(f"--out: {out} exists and is not a directory")
        plan = load_sweep(sweep_file)
    try:
        return run_sweep(
            plan,
            out,
            scheduler=scheduler,
            workers=workers,
            resume=resume is not None,
            progress=checked_progress(
                plan,
                progress,
                workers=workers,
                max_memory=max_memory,
                time_limit=time_limit,
                resume=f"jointwear sweep --resume {out}",
            ),
        )
    except KeyboardInterrupt as exc:
        if not (out / PLAN_FILE).is_file():
            raise
        raise with_resume(exc, f"jointwear sweep --resume {out}") from None  # cases are kept


def checked_progress(
    plan: SweepPlan,
    progress: Callable[[int, int], None] | None = None,
    *,
    workers: int | None = None,
    max_memory: str | None = None,
    time_limit: float | None = None,
    resume: str | None = None,
) -> Callable[[int, int], None]:
    """Check that the plan's cases fit in memory, then a progress callback that stops
    at the time limit.

    Parameters
    ----------
    plan : SweepPlan
        The sweep (or life study) about to run.
    progress : callable, optional
        ``progress(cases_done, cases_total)`` [-], called before the limit is checked.
    workers : int, optional
        Cases running at once [-]; default the CPUs available (at most one per case).
    max_memory : str, optional
        The memory budget, e.g. ``"16 GiB"`` (default: :mod:`jointwear.resources`'s).
    time_limit : float, optional
        Wall-clock limit [s].
    resume : str, optional
        The command that continues the job, named when the limit stops it.

    Raises
    ------
    ConfigError
        The largest case times the cases running at once exceed the memory budget.
    """
    from jointwear.resources import Deadline, available_cpus, check_sweep, run_memory

    parallel = workers or min(available_cpus(), max(1, len(plan.cases)))
    largest = plan.base
    if SIZING_KEYS & set(plan.keys):  # the cases differ in size: the largest counts
        configs = [plan.config(case) for case in plan.cases if case.invalid is None]
        largest = max(
            configs, key=lambda c: sum(size for *_, size in run_memory(c)), default=plan.base
        )
    check_sweep(len(plan.cases), largest, f"{plan.source}: cases", max_memory, parallel)
    return Deadline(time_limit, "cases", resume).watching(progress or _no_progress)


def _no_progress(done: int, total: int) -> None:
    """No progress report."""
