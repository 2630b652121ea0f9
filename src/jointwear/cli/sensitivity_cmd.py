"""``jointwear sensitivity``: which uncertain input moves the life most (Sobol, Morris)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from jointwear.cli.common import (
    ConfigArg,
    JsonOpt,
    MaxMemoryOpt,
    QuietOpt,
    SetOpt,
    TimeLimitOpt,
    app,
    console,
    emit_json,
)
from jointwear.cli.life_cmd import SampleOpt
from jointwear.cli.progress import ProgressBar
from jointwear.cli.sweep_cmd import SchedulerOpt, WorkersOpt

CasesOpt = Annotated[
    int,
    typer.Option(
        "--cases",
        help="The most cases to run: Sobol uses N (D + 2) of them (N a power of two, "
        "D inputs), Morris r (D + 1).",
    ),
]
MethodOpt = Annotated[
    str,
    typer.Option(
        "--method",
        help="sobol: first-order and total indices; morris: screening of many inputs.",
    ),
]
MetricOpt = Annotated[
    str,
    typer.Option(
        "--metric",
        help="The case metric analysed (a cases.csv column); a life not reached counts "
        "as the revolutions run.",
    ),
]


@app.command()
def sensitivity(
    config: ConfigArg,
    sample: SampleOpt = None,
    cases: CasesOpt = 256,
    method: MethodOpt = "sobol",
    metric: MetricOpt = "life_revolutions",
    seed: Annotated[
        int | None, typer.Option("--seed", help="Seed of the design and the bootstrap.")
    ] = None,
    out: Annotated[
        Path | None,
        typer.Option(
            "--out",
            help="Output directory: sensitivity.json, sensitivity.png, cases.csv, sweep.nc "
            "(default: none kept).",
        ),
    ] = None,
    set_: SetOpt = None,
    scheduler: SchedulerOpt = None,
    workers: WorkersOpt = None,
    json_: JsonOpt = False,
    quiet: QuietOpt = False,
    max_memory: MaxMemoryOpt = None,
    time_limit: TimeLimitOpt = None,
) -> None:
    """Global sensitivity of the life to uncertain inputs: Sobol indices (S1, ST) with
    confidence intervals, or a Morris screening (mu*, sigma), and a bar chart."""
    from jointwear.resources import parse_time_limit
    from jointwear.workflows.sensitivity import sensitivity_study

    seconds = parse_time_limit(time_limit)
    with ProgressBar("cases", quiet=quiet, delay=0.0) as bar:
        result = sensitivity_study(
            config,
            sample or [],
            cases,
            method=method,
            metric=metric,
            out=out,
            seed=seed,
            overrides=set_ or [],
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
    print_indices(summary, out)


def print_indices(summary: dict, out: Path | None) -> None:
    """The indices of each input as a table, and where the files are."""
    from rich.table import Table

    columns = ("S1", "S1_conf", "ST", "ST_conf")
    if summary["method"] == "morris":
        columns = ("mu_star", "mu_star_conf", "sigma")
    table = Table(
        title=f"{summary['method']} sensitivity of {summary['metric']} "
        f"({summary['cases']} cases, {summary['censored']} without a limit reached)"
    )
    table.add_column("input")
    for column in columns:
        table.add_column(column, justify="right")
    for key, values in summary["indices"].items():
        table.add_row(key, *(f"{values[c]:.3g}" for c in columns))
    console.print(table)
    if out is not None:
        console.print(f"results in {out}/ (sensitivity.json, sensitivity.png, cases.csv, sweep.nc)")
