"""Cases on this machine: one after the other here, or on a pool of worker processes."""

from __future__ import annotations

import multiprocessing
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any

from jointwear.resources import available_cpus
from jointwear.workflows.sweep.case import lost_record, run_case, run_cases
from jointwear.workflows.sweep.plan import Case

__all__ = ["CHUNKS_PER_WORKER", "WORKER_START", "case_chunks", "default_workers", "run_local"]


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


def start_method() -> str:
    """fork while this process has one thread (fast, and workers inherit what it loaded)."""
    methods = multiprocessing.get_all_start_methods()
    if "fork" in methods and threading.active_count() == 1:
        return "fork"
    return "forkserver" if "forkserver" in methods else "spawn"


def case_chunks(tasks: Sequence[Any], workers: int) -> list[Sequence[Any]]:
    """``tasks`` in order, cut into about :data:`CHUNKS_PER_WORKER` chunks per worker: a
    hand-over costs the workers' cores a few milliseconds, and a chunk each would leave
    them unbalanced at the end."""
    size = max(1, len(tasks) // (workers * CHUNKS_PER_WORKER))
    return [tasks[i : i + size] for i in range(0, len(tasks), size)]


def run_local(
    tasks: Sequence[tuple[Case, dict[str, Any]]],
    finish: Callable[[Case, dict[str, Any]], None],
    workers: int | None,
) -> tuple[str, int]:
    """Run the cases here, one after the other, or on a pool of local worker processes.

    Parameters
    ----------
    tasks : sequence of (Case, dict)
        Each case and its task (:func:`~jointwear.workflows.sweep.case.run_case`).
    finish : callable
        ``finish(case, record)``, called in this process as each case ends.
    workers : int or None
        Worker processes; ``1``: here; ``None``: the first case runs here, the rest on
        :func:`default_workers` processes.

    Returns
    -------
    mode : str
        ``"serial"`` or ``"processes"``.
    workers : int
        The processes that ran the cases (1: here).
    """
    pending = list(tasks)
    method = start_method()
    if workers == 1 or len(pending) <= 1 or (workers is None and available_cpus() == 1):
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
                time.perf_counter() - began, len(pending), available_cpus(), method
            )
        if workers == 1 or not pending:
            for case, task in pending:
                finish(case, run_case(task))
            return "serial", 1
    workers = min(workers, len(pending))
    chunks = case_chunks(pending, workers)
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
                records = [lost_record(case.name, "its worker process died") for case, _ in chunk]
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
