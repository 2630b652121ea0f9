"""Life with uncertainty: Monte Carlo over uncertain inputs, run on the sweep machinery.

A joint's life — revolutions until the first ``[life]`` limit — depends on inputs
that scatter: wear coefficients differ by +-40-60 % between nominally equal tests
(Pödra & Andersson 1999 [1]_), clearances by their tolerance, loads by the duty. A life
is therefore a distribution. :func:`run_life` draws ``cases`` samples of the inputs
(the sweep's ``[sample]`` distributions), runs each case to its first limit (local
processes or a Dask cluster, as :func:`~jointwear.workflows.sweep.run_sweep`), and
:func:`life_statistics` reports the median and the 5 % / 95 % lives, with the
sensitivity of the life to each input (Spearman rank correlation), and the joint's
reliability (:mod:`jointwear.workflows.reliability`): B10 and B50 lives with confidence
bounds, a Weibull fit of the censored lives, the reliability curve ``R(N)`` and the
probability of reaching each limit by a given number of revolutions.

A case that reaches no limit within ``simulation.revolutions`` is *censored*: its
life is only known to exceed the revolutions it ran. The quantiles are those of the
Kaplan-Meier estimate [2]_ of the life distribution, which counts a censored case as
running up to where it stopped and no further; a quantile the estimate does not reach
is reported as a lower bound (``"lower_bound": true``).

References
----------
.. [1] Pödra, P., Andersson, S. (1999). Simulating sliding wear with finite element
   method. Tribology International 32, 71-81.
.. [2] Kaplan, E. L., Meier, P. (1958). Nonparametric estimation from incomplete
   observations. Journal of the American Statistical Association 53, 457-481.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.config import Config, parse_override
from jointwear.errors import ConfigError, DataError
from jointwear.workflows.reliability import headline, reliability_summary
from jointwear.workflows.sweep import (
    SweepPlan,
    SweepResult,
    expand_sweep,
    limit_counts,
    resume_command,
    run_sweep,
    seed_problem,
    writing,
)

__all__ = [
    "LifeResult",
    "case_lives",
    "collect_life",
    "life_plan",
    "life_quantiles",
    "life_statistics",
    "life_study",
    "parse_distribution",
    "plot_life",
    "run_life",
    "shown",
]

FloatArray = NDArray[np.float64]

#: the quantiles reported [-]
QUANTILES = (0.05, 0.5, 0.95)
#: Monte Carlo cases of a study unless told [-]
CASES = 100


def parse_distribution(text: str) -> tuple[str, dict[str, Any]]:
    """Read ``KEY=NAME(param=value, ...)`` (or ``KEY={distribution = ..., ...}`` in TOML).

    Parameters
    ----------
    text : str
        E.g. ``"materials.bushing.wear_coefficient=lognormal(median=5e-13 m^2/N, sigma=0.4)"``.

    Returns
    -------
    key : str
        Dotted config key.
    table : dict
        The sweep's ``[sample]`` table of the key (``distribution`` and its parameters).
    """
    key, value = parse_override(text)
    where = f"--sample {key}"
    if isinstance(value, Mapping):
        return key, dict(value)
    if not isinstance(value, str) or "(" not in value or not value.rstrip().endswith(")"):
        raise ConfigError(
            f"{where}: expected NAME(param=value, ...), e.g. lognormal(median=5e-13 m^2/N, "
            f"sigma=0.4), got {value!r}"
        )
    name, _, inside = value.strip()[:-1].partition("(")
    table: dict[str, Any] = {"distribution": name.strip()}
    for item in filter(None, (part.strip() for part in inside.split(","))):
        param, sep, raw = item.partition("=")
        if not sep or not param.strip():
            raise ConfigError(f"{where}: expected param=value, got {item!r}")
        table[param.strip()] = _number_or_text(raw.strip())
    return key, table


def _number_or_text(raw: str) -> Any:
    try:
        return float(raw)
    except ValueError:
        return raw


def life_plan(
    base: Config,
    samples: Mapping[str, Mapping[str, Any]],
    cases: int,
    seed: int | None = None,
    by: float | None = None,
) -> SweepPlan:
    """The sweep plan of a life study: ``cases`` draws of the sampled inputs.

    Parameters
    ----------
    base : Config
        The joint; its ``[life]`` limits end each case.
    samples : mapping
        Dotted key -> sweep ``[sample]`` table (distribution and its parameters).
    cases : int
        Monte Carlo cases [-].
    seed : int, optional
        Seed of the random draws (reproducible plans).
    by : float, optional
        Revolutions by which the probability of reaching each limit is reported
        [revolutions]; default ``simulation.revolutions``. Stored in the plan, so a
        resumed study reports the same.
    """
    if cases < 2:
        raise ConfigError(f"--cases: a distribution needs at least 2 cases, got {cases}")
    if not samples:
        raise ConfigError("--sample: name at least one uncertain input (KEY=DIST)")
    if seed is not None and seed_problem(seed) is not None:
        raise ConfigError(f"--seed: {seed_problem(seed)}")
    if by is not None and not (math.isfinite(by) and by > 0):
        raise ConfigError(f"--by: expected a positive number of revolutions, got {by!r}")
    spec: dict[str, Any] = {"sample": dict(samples), "samples": cases}
    if seed is not None:
        spec["seed"] = seed
    plan = expand_sweep(spec, base, source="life")
    horizon = float(base.simulation.revolutions)
    return replace(plan, study={"kind": "life", "by_revolutions": horizon if by is None else by})


def life_quantiles(
    lives: ArrayLike, censored: ArrayLike, quantiles: Sequence[float] = QUANTILES
) -> list[dict[str, Any]]:
    """Quantiles of a life distribution from right-censored lives (Kaplan-Meier).

    The Kaplan-Meier estimate of the distribution of lives ``F(t) = 1 - prod_{t_i <= t}
    (1 - d_i / n_i)`` (``d_i`` lives ending at ``t_i``, ``n_i`` cases still running
    there) counts a censored case among those at risk up to its censoring point and no
    further. The ``q`` quantile is the smallest life with ``F >= q``. Where ``F`` stays
    below ``q`` up to the last case, the quantile lies beyond the longest censored case:
    it is reported as that case's life, a lower bound. Without censoring the estimate is
    the empirical distribution (``numpy.quantile(..., method="inverted_cdf")``).

    Parameters
    ----------
    lives : array_like, shape (n,)
        Life of each case, or where a censored case stopped [revolutions, or hours].
    censored : array_like of bool, shape (n,)
        Whether each case ended without reaching a limit (its life exceeds ``lives``).
    quantiles : sequence of float
        Probabilities of the quantiles [-], in (0, 1).

    Returns
    -------
    list of dict
        Per quantile ``{"value", "lower_bound"}`` (``value`` ``None`` without lives).

    References
    ----------
    .. [1] Kaplan, E. L., Meier, P. (1958). Nonparametric estimation from incomplete
       observations. Journal of the American Statistical Association 53, 457-481.
    """
    from scipy.stats import CensoredData, ecdf

    lives = np.asarray(lives, dtype=float)
    censored = np.asarray(censored, dtype=bool)
    if not lives.size:
        return [{"value": None, "lower_bound": False} for _ in quantiles]
    if censored.all():
        return [{"value": float(lives.max()), "lower_bound": True} for _ in quantiles]
    cdf = ecdf(CensoredData(uncensored=lives[~censored], right=lives[censored])).cdf
    out = []
    for q in quantiles:
        # (the product of the estimate leaves round-off: 0.5 may be 0.4999999999999999)
        reached = np.flatnonzero(cdf.probabilities >= q - 1e-12)
        if reached.size:
            out.append({"value": float(cdf.quantiles[reached[0]]), "lower_bound": False})
        else:
            out.append({"value": float(lives.max()), "lower_bound": True})
    return out


def case_lives(records: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """Each case's life, or the lower bound of a censored one.

    Parameters
    ----------
    records : sequence of mapping
        The sweep's case records (:func:`~jointwear.workflows.sweep.run_case`).

    Returns
    -------
    list of dict
        Per case ``case``, ``status``, ``life_revolutions`` (a censored case: the
        revolutions it ran, a lower bound), ``life_hours``, ``censored``, ``stopped_by``
        (the limit reached, ``None`` if censored) and its material checks
        ``worst_limit_ratio`` and ``exceeded_limits`` (a failed case: ``error``).
    """
    out = []
    for record in records:
        entry: dict[str, Any] = {"case": record.get("case"), "status": record["status"]}
        metrics = record.get("metrics") or {}
        if record["status"] != "ok":
            out.append({**entry, "error": record.get("error", "")})
            continue
        censored = metrics.get("life_revolutions") is None
        revolutions = metrics["revolutions"] if censored else metrics["life_revolutions"]
        period = metrics.get("period_s")
        if not censored:
            hours = metrics["life_hours"]
        elif period is not None:
            hours = revolutions * period / 3600.0
        else:
            hours = None
        out.append(
            {
                **entry,
                "life_revolutions": revolutions,
                "life_hours": hours,
                "censored": censored,
                "stopped_by": None if censored else metrics.get("stopped_by"),
                "worst_limit_ratio": metrics.get("worst_limit_ratio"),
                "exceeded_limits": (metrics.get("exceeded_limits") or "").split(),
            }
        )
    return out


def life_statistics(
    records: Sequence[Mapping[str, Any]],
    inputs: Mapping[str, Sequence[float]],
    horizon: int,
    by: float | None = None,
) -> dict[str, Any]:
    """Median, 5 % and 95 % life (Kaplan-Meier), and each input's rank correlation with it.

    Parameters
    ----------
    records : sequence of mapping
        The sweep's case records (``metrics`` with ``life_revolutions``, ``life_hours``,
        ``revolutions``, ``period_s`` and the material checks).
    inputs : mapping of str to sequence of float
        Sampled value of each input per case (SI).
    horizon : int
        ``simulation.revolutions``: a case without a limit reached is censored there.
    by : float, optional
        Revolutions of the probability of reaching each limit [revolutions]; default
        ``horizon``.

    Returns
    -------
    dict
        ``cases``, ``failed``, ``censored``, ``horizon_revolutions``, ``b10_revolutions``,
        ``b50_revolutions``, ``weibull_shape``, ``weibull_scale_revolutions`` and
        ``reliability`` (:func:`~jointwear.workflows.reliability.reliability_summary`),
        ``life_revolutions`` and ``life_hours`` (each ``{"p5", "median", "p95"}`` of
        :func:`life_quantiles`: ``{"value", "lower_bound"}``), ``sensitivity`` (key ->
        Spearman rho of life and input, ``None`` where undefined), the material limits
        (:func:`~jointwear.workflows.sweep.limit_counts`) and ``lives`` (:func:`case_lives`).
    """
    lives = case_lives(records)
    ok = [i for i, life in enumerate(lives) if life["status"] == "ok"]
    revolutions = np.array([lives[i]["life_revolutions"] for i in ok], dtype=float)
    censored = np.array([lives[i]["censored"] for i in ok], dtype=bool)
    names = ("p5", "median", "p95")
    stats: dict[str, Any] = {
        "cases": len(records),
        "failed": len(records) - len(ok),
        "censored": int(censored.sum()),
        "horizon_revolutions": int(horizon),
        "life_revolutions": dict(zip(names, life_quantiles(revolutions, censored), strict=True)),
    }
    timed = [i for i in ok if lives[i]["life_hours"] is not None]
    hours = np.array([lives[i]["life_hours"] for i in timed], dtype=float)
    hours_censored = np.array([lives[i]["censored"] for i in timed], dtype=bool)
    stats["life_hours"] = dict(zip(names, life_quantiles(hours, hours_censored), strict=True))
    limits = [lives[i].get("stopped_by") or "" for i in ok]
    reliability = reliability_summary(
        revolutions, censored, limits, float(horizon if by is None else by)
    )
    stats.update(headline(reliability))
    stats["reliability"] = reliability
    sensitivity: dict[str, float | None] = {}
    if revolutions.size > 2:
        from scipy.stats import spearmanr

        # a censored life is longer than every life reached (ties among the censored)
        ranked = np.where(censored, 2.0 * max(revolutions.max(), horizon), revolutions)
        for key, values in inputs.items():
            column = np.asarray([values[i] for i in ok], dtype=float)
            if np.ptp(column) > 0 and np.ptp(ranked) > 0:
                sensitivity[key] = float(spearmanr(column, ranked).statistic)
            else:
                sensitivity[key] = None
    stats["sensitivity"] = sensitivity
    stats.update(limit_counts(records))
    stats["lives"] = lives
    return stats


@dataclass(frozen=True)
class LifeResult:
    """Outcome of :func:`run_life`.

    Attributes
    ----------
    sweep : SweepResult
        The Monte Carlo cases (``cases.csv``, ``sweep.nc`` in ``sweep.out``).
    statistics : dict
        :func:`life_statistics` of the cases.
    lives : ndarray
        Life of each successful case [revolutions]; of a censored case, the revolutions
        it ran (a lower bound).
    censored : ndarray of bool
        Whether each successful case ended without reaching a limit.
    inputs : dict of str to ndarray
        Sampled value of each input per successful case (SI).
    """

    sweep: SweepResult
    statistics: dict[str, Any]
    lives: FloatArray
    censored: NDArray[np.bool_]
    inputs: dict[str, FloatArray]

    def summary(self) -> dict[str, Any]:
        """The ``jointwear life --json`` object: ``life.json`` without the ``lives``, with
        the folder and this invocation's wall-clock time (which ``life.json`` leaves out,
        so that a resumed study writes the same file as an uninterrupted one)."""
        stats = {k: v for k, v in self.statistics.items() if k != "lives"}
        return {**stats, "out": str(self.sweep.out), "runtime_s": self.sweep.runtime}


def run_life(plan: SweepPlan, out: str | Path, **sweep_options: Any) -> LifeResult:
    """Run a life study's cases and collect the life distribution.

    Parameters
    ----------
    plan : SweepPlan
        From :func:`life_plan`.
    out : path-like
        Output directory (the sweep's files and ``life.json``).
    **sweep_options
        Passed to :func:`~jointwear.workflows.sweep.run_sweep` (``workers``, ``scheduler``, ...).
    """
    result = run_sweep(plan, out, **sweep_options)
    return collect_life(plan, result)


def collect_life(plan: SweepPlan, result: SweepResult) -> LifeResult:
    """The life distribution of a life study's finished cases; writes ``life.json``.

    Parameters
    ----------
    plan : SweepPlan
        The study's plan (:func:`life_plan`).
    result : SweepResult
        Its cases, every one finished.
    """
    import json

    from jointwear.io import json_ready, write_json

    # the records as stored: a resumed study reads its earlier cases back from JSON
    result = replace(result, records=json.loads(json.dumps(json_ready(result.records))))
    keys = list(plan.keys)
    columns = {key: [case.overrides.get(key) for case in plan.cases] for key in keys}
    inputs_si = {
        key: [plan.columns()[keys.index(key)].si(v) for v in values]
        for key, values in columns.items()
    }
    statistics = life_statistics(
        result.records,
        inputs_si,
        plan.base.simulation.revolutions,
        plan.study.get("by_revolutions"),
    )
    ok = [i for i, r in enumerate(result.records) if r.get("status") == "ok"]
    finished = [life for life in statistics["lives"] if life["status"] == "ok"]
    lives = np.array([life["life_revolutions"] for life in finished], dtype=float)
    censored = np.array([life["censored"] for life in finished], dtype=bool)
    inputs = {
        key: np.asarray([values[i] for i in ok], dtype=float) for key, values in inputs_si.items()
    }
    with writing(result.out, "life.json", resume_command(plan, result.out)):
        write_json(result.out / "life.json", statistics)
    return LifeResult(result, statistics, lives, censored, inputs)


#: what a life study writes into its folder (files, then folders)
LIFE_FILES = ("life.json", "life.png", "cases.csv", "sweep.nc")
LIFE_DIRS = ("cases",)


def life_study(
    config: Path | None,
    samples: Sequence[str] = (),
    cases: int | None = None,
    *,
    out: Path | None = None,
    resume: Path | None = None,
    seed: int | None = None,
    by: float | None = None,
    overrides: Sequence[str] = (),
    scheduler: str | None = None,
    workers: int | None = None,
    max_memory: str | None = None,
    time_limit: float | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> LifeResult:
    """The life distribution of a joint under uncertain inputs (``jointwear life``).

    Checks the options, the folder and the config, draws the cases
    (:func:`life_plan`), runs them (:func:`run_life`) and writes ``life.json``,
    ``life.png``, ``cases.csv``, ``sweep.nc`` and ``cases/`` into ``out``. With
    ``resume`` it finishes the study in that folder from its stored plan: the finished
    cases are kept, the others run, and every file comes out as an uninterrupted study
    writes it.

    Parameters
    ----------
    config : Path or None
        The joint's config file; its ``[life]`` limits end each case (``None`` with
        ``resume``).
    samples : sequence of str
        The uncertain inputs, ``KEY=NAME(param=value, ...)`` (:func:`parse_distribution`).
    cases : int, optional
        Monte Carlo cases [-]; default :data:`CASES`.
    out : Path
        Output directory (required without ``resume``).
    resume : Path, optional
        The folder of an interrupted life study.
    seed : int, optional
        Seed of the draws.
    by : float, optional
        Revolutions of the probability of reaching each limit [revolutions]; default
        ``simulation.revolutions``.
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.
    scheduler : str, optional
        Address of a dask.distributed scheduler.
    workers : int, optional
        Local worker processes.
    max_memory : str, optional
        The memory budget of the cases running at once, e.g. ``"16 GiB"``.
    time_limit : float, optional
        Stop with :class:`~jointwear.errors.TimeLimitError` after this wall-clock
        time [s], checked between cases.
    progress : callable, optional
        ``progress(cases_done, cases_total)`` [-].

    Returns
    -------
    LifeResult
        The cases and their life distribution.

    Raises
    ------
    ConfigError
        Too many or too few cases, no ``out``, a bad config or distribution, too
        little memory, options given with ``resume`` that the stored plan fixes.
    DataError
        ``resume`` names no life study.
    """
    from jointwear.interrupts import with_resume
    from jointwear.io import atomic_path
    from jointwear.workflows.sweep import checked_progress

    if resume is not None:
        plan, out = _resumed_plan(resume, config, samples, cases, out, seed, by, overrides)
    else:
        plan, out = _new_plan(
            config, samples, CASES if cases is None else cases, out, seed, by, overrides
        )
    command = resume_command(plan, out)
    checked = checked_progress(
        plan,
        progress,
        workers=workers,
        max_memory=max_memory,
        time_limit=time_limit,
        resume=command,
    )
    try:
        result = run_life(
            plan,
            out,
            scheduler=scheduler,
            workers=workers,
            progress=checked,
            resume=resume is not None,
        )
    except KeyboardInterrupt as exc:
        from jointwear.workflows.sweep import PLAN_FILE

        if not (out / PLAN_FILE).is_file():
            raise
        raise with_resume(exc, command) from None  # the finished cases are kept
    with writing(out, "life.png", command), atomic_path(out / "life.png") as tmp:
        plot_life(result).savefig(tmp, format="png", dpi=120, metadata={"Software": None})
    return result


def _new_plan(
    config: Path | None,
    samples: Sequence[str],
    cases: int,
    out: Path | None,
    seed: int | None,
    by: float | None,
    overrides: Sequence[str],
) -> tuple[SweepPlan, Path]:
    """A new study's plan and checked folder (nothing written)."""
    from jointwear.io import check_out, check_tree
    from jointwear.resources import check_case_count
    from jointwear.workflows.inputs import load_config_file

    check_case_count(cases, "--cases")
    if out is None:
        raise ConfigError("--out: missing; the life study needs a directory for its cases")
    if config is None:
        raise ConfigError("CONFIG: missing; give a config file or --resume DIR")
    out = check_out(out, files=LIFE_FILES, dirs=LIFE_DIRS)
    check_tree(out, LIFE_DIRS)
    base = load_config_file(config, overrides)
    tables = dict(parse_distribution(text) for text in samples)
    return life_plan(base, tables, cases, seed, by), out


def _resumed_plan(
    resume: Path,
    config: Path | None,
    samples: Sequence[str],
    cases: int | None,
    out: Path | None,
    seed: int | None,
    by: float | None,
    overrides: Sequence[str],
) -> tuple[SweepPlan, Path]:
    """The stored plan of an interrupted study; options the plan fixes are refused."""
    from jointwear.io import check_out, check_tree
    from jointwear.workflows.sweep import PLAN_FILE, load_plan

    given = [
        name
        for name, value in (
            ("CONFIG", config),
            ("--sample", list(samples)),
            ("--cases", cases),
            ("--seed", seed),
            ("--by", by),
            ("--set", list(overrides)),
        )
        if value not in (None, [])
    ]
    if given:
        raise ConfigError(
            f"--resume: {given[0]} is fixed by the study in {resume}; drop it (the stored "
            "plan is resumed)"
        )
    if out is not None and out.resolve() != resume.resolve():
        raise ConfigError("--out: a resumed life study writes into its --resume directory")
    out = check_out(resume, "--resume", files=(*LIFE_FILES, PLAN_FILE), dirs=LIFE_DIRS)
    check_tree(out, LIFE_DIRS, "--resume")
    plan = load_plan(out)
    if plan.study.get("kind") != "life":
        raise ConfigError(
            f"--resume: {resume} holds a sweep, not a life study; continue it with "
            f"`jointwear sweep --resume {resume}`"
        )
    by = plan.study.get("by_revolutions")
    if isinstance(by, bool) or not isinstance(by, int | float) or not 0 < by < math.inf:
        raise DataError(f"{out / PLAN_FILE}: study.by_revolutions: expected a positive number")
    return plan, out


def shown(quantile: Mapping[str, Any]) -> str:
    """A quantile of :func:`life_quantiles` as text: ``"812"``, ``">= 2000"`` or ``"n/a"``."""
    if quantile.get("value") is None:
        return "n/a"
    return f"{'>= ' if quantile.get('lower_bound') else ''}{quantile['value']:.4g}"


def plot_life(result: LifeResult) -> Any:
    """Histogram of the lives reached, the Kaplan-Meier distribution of the life with the
    5/50/95 % lives marked (a lower bound dashed), and the reliability curve ``R(N)``:
    Kaplan-Meier with its confidence band, the Weibull fit, B10 and B50.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    reached = result.lives[~result.censored]
    fig = Figure(figsize=(12, 3.8), layout="constrained")
    hist, cdf, curve = fig.subplots(1, 3)
    if reached.size:
        hist.hist(reached, bins=max(5, int(np.sqrt(reached.size))), color="tab:blue", alpha=0.8)
    _plot_distribution(cdf, result)
    _plot_reliability(curve, result)
    hist.set_xlabel("life reached [revolutions]")
    hist.set_ylabel("cases")
    stats = result.statistics
    quantiles = stats["life_revolutions"]
    fig.suptitle(
        f"life: median {shown(quantiles['median'])} rev, 5-95 % {shown(quantiles['p5'])} to "
        f"{shown(quantiles['p95'])} rev, B10 {shown(_b_life(stats, 'b10'))} rev "
        f"({stats['cases']} cases, {stats['censored']} censored)"
    )
    return fig


def _b_life(stats: Mapping[str, Any], name: str) -> dict[str, Any]:
    entry = stats["reliability"][name]
    return {"value": entry["value"], "lower_bound": entry["lower_bound"]}


def _plot_distribution(ax: Any, result: LifeResult) -> None:
    """The Kaplan-Meier distribution of the life, the 5/50/95 % lives marked."""
    from scipy.stats import CensoredData, ecdf

    reached = result.lives[~result.censored]
    if reached.size:
        estimate = ecdf(CensoredData(uncensored=reached, right=result.lives[result.censored])).cdf
        ax.step(estimate.quantiles, estimate.probabilities, where="post")
    quantiles = result.statistics["life_revolutions"]
    for name, style in (("p5", ":"), ("median", "-"), ("p95", ":")):
        value = quantiles[name]["value"]
        if value is not None:
            dashed = quantiles[name]["lower_bound"]
            ax.axvline(value, color="k", linestyle="--" if dashed else style, linewidth=1)
    ax.set_xlabel("life [revolutions]")
    ax.set_ylabel("fraction of joints worn out (Kaplan-Meier)")
    ax.grid(alpha=0.3)


def _plot_reliability(ax: Any, result: LifeResult) -> None:
    """``R(N)``: Kaplan-Meier with its confidence band, the Weibull fit, B10 and B50."""
    from scipy.stats import CensoredData, ecdf

    from jointwear.workflows.reliability import weibull_cdf

    stats = result.statistics["reliability"]
    reached = result.lives[~result.censored]
    if reached.size:
        survival = ecdf(CensoredData(uncensored=reached, right=result.lives[result.censored])).sf
        with warnings.catch_warnings():  # undefined where the estimate is 0 or 1: a gap
            warnings.simplefilter("ignore", RuntimeWarning)
            band = survival.confidence_interval(stats["confidence"], method="log-log")
        ax.step(survival.quantiles, survival.probabilities, where="post", label="Kaplan-Meier")
        ax.fill_between(
            survival.quantiles,
            band.low.evaluate(survival.quantiles),
            band.high.evaluate(survival.quantiles),
            step="post",
            alpha=0.2,
            label=f"{stats['confidence']:.0%} band",
        )
    if stats["weibull"] is not None and result.lives.size:
        grid = np.linspace(0.0, 1.2 * float(result.lives.max()), 200)
        shape = stats["weibull"]["shape"]["value"]
        fitted = 1.0 - weibull_cdf(grid, stats["weibull"])
        ax.plot(grid, fitted, "k-", linewidth=1, label=f"Weibull, shape {shape:.3g}")
    for name, color in (("b10", "tab:red"), ("b50", "tab:green")):
        entry = stats[name]
        if entry["value"] is not None:
            style = "--" if entry["lower_bound"] else "-"
            label = f"{name.upper()} {shown(_b_life(result.statistics, name))}"
            ax.axvline(entry["value"], color=color, linestyle=style, linewidth=1, label=label)
    ax.set_ylim(0.0, 1.02)
    ax.set_xlabel("revolutions N")
    ax.set_ylabel("reliability R(N): no limit reached")
    ax.grid(alpha=0.3)
    ax.legend(fontsize="small")
