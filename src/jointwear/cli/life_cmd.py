"""``jointwear life``: the life distribution of a joint under uncertain inputs."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from jointwear.cli.common import (
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
from jointwear.cli.run_cmd import OptConfigArg
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


ByOpt = Annotated[
    float | None,
    typer.Option(
        "--by",
        help="Revolutions by which to report the probability of reaching each life limit "
        "(default: simulation.revolutions).",
        show_default=False,
    ),
]
LifeResumeOpt = Annotated[
    Path | None,
    typer.Option(
        "--resume",
        help="Finish the interrupted life study in this directory: finished cases are kept, "
        "the rest run, and every output is written as by an uninterrupted study.",
        show_default=False,
    ),
]


@app.command()
def life(
    config: OptConfigArg = None,
    sample: SampleOpt = None,
    cases: Annotated[
        int | None, typer.Option("--cases", help="Monte Carlo cases [default: 100].")
    ] = None,
    seed: Annotated[int | None, typer.Option("--seed", help="Seed of the draws.")] = None,
    by: ByOpt = None,
    out: Annotated[
        Path | None,
        typer.Option("--out", help="Output directory: life.json, life.png, cases.csv, sweep.nc."),
    ] = None,
    resume: LifeResumeOpt = None,
    set_: SetOpt = None,
    scheduler: SchedulerOpt = None,
    workers: WorkersOpt = None,
    json_: JsonOpt = False,
    quiet: QuietOpt = False,
    max_memory: MaxMemoryOpt = None,
    time_limit: TimeLimitOpt = None,
) -> None:
    """Life to the first [life] limit as a distribution: median, 5 % and 95 % life, B10 and
    B50 with confidence bounds, a Weibull fit and the reliability curve R(N).

    Each case draws the sampled inputs and runs to its first limit (a case that reaches
    none is censored: its life is a lower bound); the sensitivity is the rank correlation
    of the life with each input.
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
            resume=resume,
            seed=seed,
            by=by,
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
    print_summary(summary, config.name if config is not None else str(resume), result.sweep.out)


def print_summary(summary: dict, name: str, out: Path) -> None:
    """The life quantiles, the censored cases, the material limits and the sensitivity."""
    from rich.table import Table

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
    print_reliability(summary["reliability"])
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


def print_reliability(reliability: dict) -> None:
    """B10 and B50 with their bounds, the Weibull fit and the probability of each limit."""
    from rich.table import Table

    from jointwear.workflows.life import shown

    level = f"{reliability['confidence']:.0%}"
    table = Table(title=f"reliability ({level} confidence bounds)")
    for column in ("", "Kaplan-Meier", "bounds", "Weibull", "bounds"):
        table.add_column(column, justify="right")

    def bounds(entry: dict | None) -> str:
        if entry is None or entry.get("lower") is None:  # (no life reached: no bound)
            return "n/a"
        upper = "open" if entry.get("upper") is None else f"{entry['upper']:.4g}"
        return f"{entry['lower']:.4g} to {upper}"

    for name in ("b10", "b50"):
        entry, fit = reliability[name], reliability[name]["weibull"]
        table.add_row(
            f"{name.upper()} [rev]",
            shown(entry),
            bounds(entry),
            "n/a" if fit is None else f"{fit['value']:.4g}",
            bounds(fit),
        )
    console.print(table)
    fit = reliability["weibull"]
    if fit is not None:
        console.print(
            f"Weibull fit: shape {fit['shape']['value']:.3g}, scale "
            f"{fit['scale_revolutions']['value']:.4g} rev ({fit['reached']} lives reached, "
            f"{fit['censored']} censored)"
        )
    reach = reliability["reach_probability"]
    by_limit = ", ".join(f"{k} {v:.3g}" for k, v in reach["limits"].items() if k != "any")
    console.print(
        f"probability of reaching a limit by {reach['by_revolutions']:.4g} revolutions: "
        f"{reach['limits']['any']:.3g}" + (f" ({by_limit})" if by_limit else "")
    )
