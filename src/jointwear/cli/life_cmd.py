"""``jointwear life``: the life distribution of a joint under uncertain inputs."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.table import Table

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
from jointwear.cli.progress import ProgressBar
from jointwear.cli.sweep_cmd import SchedulerOpt, WorkersOpt

SampleOpt = Annotated[
    list[str] | None,
    typer.Option(
        "--sample",
        help="An uncertain input KEY=NAME(param=value, ...): uniform(low, high), "
        "loguniform(low, high), normal(mean, std), lognormal(median, sigma), "
        "choice(values); e.g. --sample 'joint.clearance=uniform(low=0.04 mm, "
        "high=0.06 mm)'. Repeat.",
        show_default=False,
    ),
]


@app.command()
def life(
    config: ConfigArg,
    sample: SampleOpt = None,
    cases: Annotated[int, typer.Option("--cases", help="Monte Carlo cases.")] = 100,
    seed: Annotated[int | None, typer.Option("--seed", help="Seed of the draws.")] = None,
    out: Annotated[
        Path | None,
        typer.Option("--out", help="Output directory: life.json, life.png, cases.csv, sweep.nc."),
    ] = None,
    set_: SetOpt = None,
    scheduler: SchedulerOpt = None,
    workers: WorkersOpt = None,
    json_: JsonOpt = False,
    quiet: QuietOpt = False,
    max_memory: MaxMemoryOpt = None,
    time_limit: TimeLimitOpt = None,
) -> None:
    """Life to the first [life] limit as a distribution: median, 5 % and 95 % life.

    Each case draws the sampled inputs and runs to its first limit; the sensitivity is
    the rank correlation of the life with each input.
    """
    from jointwear.resources import parse_time_limit
    from jointwear.workflows.life import life_study

    seconds = parse_time_limit(time_limit)
    with ProgressBar("cases", quiet=quiet, delay=0.0) as bar:
        result = life_study(
            config,
            sample or [],
            cases,
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
    print_summary(summary, config.name, result.sweep.out)


def print_summary(summary: dict, name: str, out: Path) -> None:
    """The life quantiles, the censored cases, the material limits and the sensitivity."""
    from jointwear.workflows.life import shown

    table = Table(
        title=f"life of {name}: {summary['cases']} cases, "
        f"{summary['censored']} without a limit reached, {summary['failed']} failed"
    )
    table.add_column("")
    for column in ("p5", "median", "p95"):
        table.add_column(column, justify="right")
    for label, key in (("revolutions", "life_revolutions"), ("hours", "life_hours")):
        table.add_row(label, *(shown(summary[key][n]) for n in ("p5", "median", "p95")))
    console.print(table)
    if summary["censored"]:
        console.print(
            f"{summary['censored']} cases reached no limit within "
            f"{summary['horizon_revolutions']} revolutions: their lives are lower bounds "
            "(Kaplan-Meier; >= marks a quantile beyond them)"
        )
    if summary["limits_exceeded"]:
        which = ", ".join(f"{k} {n}" for k, n in summary["limits_exceeded_by"].items() if n)
        console.print(
            f"{summary['limits_exceeded']} of {summary['cases'] - summary['failed']} cases "
            f"exceed a material limit ({which}): the wear coefficient does not hold there"
        )
    elif summary["limits_checked"]:
        console.print(f"material limits: {summary['limits_checked']} cases checked, none exceeded")
    else:
        console.print("material limits: none known for materials.bushing (not checked)")
    if summary["sensitivity"]:
        sens = Table(title="sensitivity (Spearman rank correlation of life and input)")
        sens.add_column("input")
        sens.add_column("rho", justify="right")
        for key, rho in summary["sensitivity"].items():
            sens.add_row(key, "n/a" if rho is None else f"{rho:+.3f}")
        console.print(sens)
    console.print(f"results in {out}/ (life.json, life.png, cases.csv, sweep.nc)")
