"""``jointwear sweep``: many runs of one base configuration, locally or on a dask cluster."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

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
    from jointwear.workflows.sweep import sweep_to_folder

    seconds = parse_time_limit(time_limit)
    with ProgressBar("cases", quiet=quiet, delay=0.0) as bar:
        result = sweep_to_folder(
            sweep_file,
            out,
            resume=resume,
            scheduler=scheduler,
            workers=workers,
            max_memory=max_memory,
            time_limit=seconds,
            progress=bar,
        )
    summary = result.summary()
    if json_:
        emit_json(summary)
        return
    print_summary(summary, result.records, resume if resume is not None else out)


def print_summary(summary: dict, records: list[dict], out: Path) -> None:
    """The sweep's counts, the cases beyond a material limit and the failed cases."""
    from rich.table import Table

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
    failures = [r for r in records if r["status"] != "ok"]
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
