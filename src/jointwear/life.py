"""Life with uncertainty: Monte Carlo over uncertain inputs, run on the sweep machinery.

A joint's life — revolutions until the first ``[life]`` limit — depends on inputs
that scatter: wear coefficients differ by +-40-60 % between nominally equal tests
(Pödra & Andersson 1999), clearances by their tolerance, loads by the duty. A life
is therefore a distribution. :func:`run_life` draws ``cases`` samples of the inputs
(the sweep's ``[sample]`` distributions), runs each case to its first limit (local
processes or a Dask cluster, as :func:`~jointwear.sweep.run_sweep`), and
:func:`life_statistics` reports the median and the 5 % / 95 % lives, with the
sensitivity of the life to each input (Spearman rank correlation).

A case that reaches no limit within ``simulation.revolutions`` is *censored*: its
life is only known to exceed that; the quantiles that fall among censored cases are
reported as lower bounds.

References
----------
.. [1] Pödra, P., Andersson, S. (1999). Simulating sliding wear with finite element
   method. Tribology International 32, 71-81.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear.config import Config, parse_override
from jointwear.errors import ConfigError
from jointwear.sweep import SweepPlan, SweepResult, expand_sweep, run_sweep

__all__ = ["LifeResult", "life_plan", "life_statistics", "parse_distribution", "run_life"]

FloatArray = NDArray[np.float64]

#: the quantiles reported [-]
QUANTILES = (0.05, 0.5, 0.95)


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
    base: Config, samples: Mapping[str, Mapping[str, Any]], cases: int, seed: int | None = None
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
    """
    if cases < 2:
        raise ConfigError(f"--cases: a distribution needs at least 2 cases, got {cases}")
    if not samples:
        raise ConfigError("--sample: name at least one uncertain input (KEY=DIST)")
    spec: dict[str, Any] = {"sample": dict(samples), "samples": cases}
    if seed is not None:
        spec["seed"] = seed
    return expand_sweep(spec, base, source="life")


def life_statistics(
    records: Sequence[Mapping[str, Any]], inputs: Mapping[str, Sequence[float]], horizon: int
) -> dict[str, Any]:
    """Median, 5 % and 95 % life, and each input's rank correlation with the life.

    Parameters
    ----------
    records : sequence of mapping
        The sweep's case records (``metrics`` with ``life_revolutions``, ``life_hours``,
        ``revolutions``).
    inputs : mapping of str to sequence of float
        Sampled value of each input per case (SI).
    horizon : int
        ``simulation.revolutions``: a case without a limit reached is censored there.

    Returns
    -------
    dict
        ``cases``, ``failed``, ``censored``, ``life_revolutions`` and ``life_hours``
        (each ``{"p5", "median", "p95"}``, with ``lower_bound`` flags for quantiles
        among censored cases), ``sensitivity`` (key -> Spearman rho of life and input).
    """
    ok = [i for i, r in enumerate(records) if r.get("status") == "ok"]
    lives = np.array(
        [
            records[i]["metrics"]["life_revolutions"]
            if records[i]["metrics"].get("life_revolutions") is not None
            else math.inf
            for i in ok
        ],
        dtype=float,
    )
    hours_per_revolution = [
        records[i]["metrics"]["life_hours"] / records[i]["metrics"]["life_revolutions"]
        for i in ok
        if records[i]["metrics"].get("life_revolutions")
    ]
    per_revolution = float(np.median(hours_per_revolution)) if hours_per_revolution else math.nan
    censored = ~np.isfinite(lives)
    stats: dict[str, Any] = {
        "cases": len(records),
        "failed": len(records) - len(ok),
        "censored": int(censored.sum()),
        "horizon_revolutions": int(horizon),
    }
    quantiles: dict[str, Any] = {}
    hours: dict[str, Any] = {}
    if lives.size:
        # censored lives sort last: a quantile that falls on them is a lower bound
        values = np.where(censored, horizon, lives)
        order = np.sort(lives)
        for q, name in zip(QUANTILES, ("p5", "median", "p95"), strict=True):
            value = float(np.quantile(values, q, method="inverted_cdf"))
            bound = bool(np.quantile(order, q, method="inverted_cdf") == math.inf)
            quantiles[name] = value
            hours[name] = value * per_revolution
            if bound:
                quantiles[f"{name}_lower_bound"] = True
    stats["life_revolutions"] = quantiles
    stats["life_hours"] = hours
    sensitivity: dict[str, float] = {}
    if lives.size > 2:
        from scipy.stats import spearmanr

        ranked = np.where(censored, horizon * 2.0, lives)  # censored: longer than any other
        for key, values in inputs.items():
            column = np.asarray([values[i] for i in ok], dtype=float)
            if np.ptp(column) > 0 and np.ptp(ranked) > 0:
                sensitivity[key] = float(spearmanr(column, ranked).statistic)
            else:
                sensitivity[key] = math.nan
    stats["sensitivity"] = sensitivity
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
        Life of each successful case [revolutions] (``inf`` if censored).
    inputs : dict of str to ndarray
        Sampled value of each input per successful case (SI).
    """

    sweep: SweepResult
    statistics: dict[str, Any]
    lives: FloatArray
    inputs: dict[str, FloatArray]

    def summary(self) -> dict[str, Any]:
        """The ``jointwear life --json`` object."""
        return {**self.statistics, "out": str(self.sweep.out), "runtime_s": self.sweep.runtime}


def run_life(plan: SweepPlan, out: str | Path, **sweep_options: Any) -> LifeResult:
    """Run a life study's cases and collect the life distribution.

    Parameters
    ----------
    plan : SweepPlan
        From :func:`life_plan`.
    out : path-like
        Output directory (the sweep's files and ``life.json``).
    **sweep_options
        Passed to :func:`~jointwear.sweep.run_sweep` (``workers``, ``scheduler``, ...).
    """
    from jointwear.io import write_json

    result = run_sweep(plan, out, **sweep_options)
    keys = list(plan.keys)
    columns = {key: [case.overrides.get(key) for case in plan.cases] for key in keys}
    inputs_si = {
        key: [plan.columns()[keys.index(key)].si(v) for v in values]
        for key, values in columns.items()
    }
    statistics = life_statistics(result.records, inputs_si, plan.base.simulation.revolutions)
    ok = [i for i, r in enumerate(result.records) if r.get("status") == "ok"]
    lives = np.array(
        [result.records[i]["metrics"].get("life_revolutions") or math.inf for i in ok],
        dtype=float,
    )
    inputs = {
        key: np.asarray([values[i] for i in ok], dtype=float) for key, values in inputs_si.items()
    }
    write_json(Path(out) / "life.json", {**statistics, "runtime_s": result.runtime})
    return LifeResult(result, statistics, lives, inputs)


def plot_life(result: LifeResult) -> Any:
    """Histogram and empirical CDF of the life, with the 5/50/95 % lives marked.

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    lives = result.lives[np.isfinite(result.lives)]
    fig = Figure(figsize=(8, 3.5), layout="constrained")
    hist, cdf = fig.subplots(1, 2)
    if lives.size:
        hist.hist(lives, bins=max(5, int(np.sqrt(lives.size))), color="tab:blue", alpha=0.8)
        ordered = np.sort(result.lives)
        fraction = np.arange(1, ordered.size + 1) / ordered.size
        finite = np.isfinite(ordered)
        cdf.step(ordered[finite], fraction[finite], where="post")
        for name, style in (("p5", ":"), ("median", "-"), ("p95", ":")):
            value = result.statistics["life_revolutions"].get(name)
            if value is not None:
                for ax in (hist, cdf):
                    ax.axvline(value, color="k", linestyle=style, linewidth=1)
    hist.set_xlabel("life [revolutions]")
    hist.set_ylabel("cases")
    cdf.set_xlabel("life [revolutions]")
    cdf.set_ylabel("fraction of joints worn out")
    cdf.grid(alpha=0.3)
    stats = result.statistics
    fig.suptitle(
        f"life: median {stats['life_revolutions'].get('median', math.nan):.4g} rev, "
        f"5-95 % {stats['life_revolutions'].get('p5', math.nan):.4g}-"
        f"{stats['life_revolutions'].get('p95', math.nan):.4g} rev "
        f"({stats['cases']} cases, {stats['censored']} censored)"
    )
    return fig
