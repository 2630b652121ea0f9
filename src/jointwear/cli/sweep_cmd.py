"""``jointwear sweep``: many runs of one base configuration, locally or on a dask cluster."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.table import Table

from jointwear.cli.common import (
    JsonOpt,
    MaxMemoryOpt,
    QuietOpt,
    TimeLimitOpt,
    app,
    console,
    emit_json,
)
from jointwear.cli.progress import ProgressBar
from jointwear.errors import ConfigError

if TYPE_CHECKING:
    from jointwear.workflows.sweep import SweepPlan

SweepArg = Annotated[
    Path | None,
    typer.Argument(help="Sweep file (TOML); omit with --resume.", show_default=False),
]
SweepOutOpt = Annotated[
    Path | None,
    typer.Option(
        "--out", help="Output directory: cases.csv, sweep.nc, cases/ (one record per case)."
    ),
]
SchedulerOpt = Annotated[
    str | None,
    typer.Option(
        "--scheduler",
        help="Address of a running dask.distributed scheduler, e.g. tcp://host:8786 "
        "(needs the `sweep` extra). Default: local processes.",
        show_default=False,
    ),
]
WorkersOpt = Annotated[
    int | None,
    typer.Option(
        "--workers",
        help="Local worker processes (default: the CPUs available when the first case shows "
        "the sweep is worth it, else 1; 1 = one after another in this process).",
        show_default=False,
    ),
]
SweepResumeOpt = Annotated[
    Path | None,
    typer.Option(
        "--resume",
        help="Continue the sweep in this directory: finished cases are kept, the rest run.",
        show_default=False,
    ),
]


#: config keys that set the memory of a case
SIZING_KEYS = {
    "contact.nodes",
    "simulation.steps_per_revolution",
    "simulation.saved_profiles",
    "mechanism.clearance_joint",
}


def limited(
    bar: ProgressBar,
    plan: SweepPlan,
    out: Path,
    seconds: float | None,
    workers: int | None,
    max_memory: str | None,
    command: str,
) -> Callable[[int, int], None]:
    """Check the plan's memory, then a progress callback that stops at the time limit."""
    from jointwear.resources import Deadline, available_cpus, check_sweep, run_memory

    parallel = workers or min(available_cpus(), max(1, len(plan.cases)))
    largest = plan.base
    if SIZING_KEYS & set(plan.keys):  # the cases differ in size: the largest counts
        configs = [plan.config(case) for case in plan.cases if case.invalid is None]
        largest = max(
            configs, key=lambda c: sum(size for *_, size in run_memory(c)), default=plan.base
        )
    check_sweep(len(plan.cases), largest, f"{plan.source}: cases", max_memory, parallel)
    resume = f"jointwear sweep --resume {out}" if command == "sweep" else None
    return Deadline(seconds, "cases", resume).watching(bar)


#: failed cases listed in the human-readable summary
SHOWN_FAILURES = 10


@app.command()
def sweep(
    sweep_file: SweepArg = None,
    out: SweepOutOpt = None,
    scheduler: SchedulerOpt = None,
    workers: WorkersOpt = None,
    resume: SweepResumeOpt = None,
    json_: JsonOpt = False,
    quiet: QuietOpt = False,
    max_memory: MaxMemoryOpt = None,
    time_limit: TimeLimitOpt = None,
) -> None:
    """Run a parameter sweep (grid, zipped lists, random samples) and collect the metrics."""
    from jointwear.resources import parse_time_limit
    from jointwear.workflows.sweep import load_plan, load_sweep, run_sweep

    seconds = parse_time_limit(time_limit)
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
        with ProgressBar("cases", quiet=quiet, delay=0.0) as bar:
            result = run_sweep(
                plan,
                out,
                scheduler=scheduler,
                workers=workers,
                resume=resume is not None,
                progress=limited(bar, plan, out, seconds, workers, max_memory, "sweep"),
            )
    except KeyboardInterrupt as exc:
        from jointwear.interrupts import with_resume
        from jointwear.workflows.sweep import PLAN_FILE

        if not (out / PLAN_FILE).is_file():
            raise
        raise with_resume(exc, f"jointwear sweep --resume {out}") from None  # cases are kept
    summary = result.summary()
    if json_:
        emit_json(summary)
        return
    counts = f"{summary['ok']} ok, {summary['failed']} failed"
    if summary["errors"]:
        counts += f", {summary['errors']} internal errors"
    if summary["skipped"]:
        counts += f" ({summary['skipped']} finished before)"
    console.print(
        f"{summary['cases']} cases: {counts}; {summary['runtime_s']:.3g} s on "
        f"{summary['scheduler']}"
    )
    if summary["limits_exceeded"]:
        which = ", ".join(f"{k} {n}" for k, n in summary["limits_exceeded_by"].items() if n)
        console.print(
            f"{summary['limits_exceeded']} cases exceed a material limit ({which}); "
            "see exceeded_limits and the *_ratio columns"
        )
    failures = [r for r in result.records if r["status"] != "ok"]
    if failures:
        table = Table(title="failed cases")
        table.add_column("case")
        table.add_column("error")
        for record in failures[:SHOWN_FAILURES]:
            table.add_row(record["case"], record["error"])
        if len(failures) > SHOWN_FAILURES:
            table.add_row("...", f"{len(failures) - SHOWN_FAILURES} more in cases.csv")
        console.print(table)
    console.print(f"results in {out}/cases.csv and {out}/sweep.nc")
