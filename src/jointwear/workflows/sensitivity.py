"""Global sensitivity of a joint's life (or any case metric) to its uncertain inputs.

Which tolerance or material moves the life most? A rank correlation
(:mod:`jointwear.workflows.life`) sees only monotonic trends one input at a time. This
module decomposes the variance of the output instead:

* **Sobol indices** [1]_: the first-order index ``S1_i = V(E[Y | X_i]) / V(Y)`` is the
  share of the output's variance that input ``i`` causes alone; the total index ``ST_i =
  E[V(Y | X_~i)] / V(Y)`` adds every interaction it takes part in, so ``ST_i ~ 0`` means
  the input can be fixed at any value of its range. Estimated from Saltelli's design
  [2]_ (``N (D + 2)`` cases for ``D`` inputs) with Jansen's and Saltelli's estimators and
  bootstrap confidence intervals (SALib [3]_).
* **Morris screening** [4]_: ``r`` one-at-a-time trajectories (``r (D + 1)`` cases); the
  mean absolute elementary effect ``mu_star`` ranks the inputs, ``sigma`` flags
  non-linear effects and interactions. Cheap for many inputs.

The design is drawn in the unit cube and each column mapped through the inverse CDF of
the input's distribution (the ``--sample`` syntax of ``jointwear life`` and the sweep's
``[sample]`` table), so the indices are those of the inputs as distributed; Morris'
effects are per unit of the inputs' probability scale. The cases run on the sweep
machinery (local processes or a Dask cluster). A case that reaches no limit counts with
the revolutions it ran (its life is at least that).

References
----------
.. [1] Sobol', I. M. (2001). Global sensitivity indices for nonlinear mathematical models
   and their Monte Carlo estimates. Mathematics and Computers in Simulation 55, 271-280.
.. [2] Saltelli, A. et al. (2010). Variance based sensitivity analysis of model output.
   Design and estimator for the total sensitivity index. Computer Physics Communications
   181, 259-270.
.. [3] Herman, J., Usher, W. (2017). SALib: an open-source Python library for sensitivity
   analysis. Journal of Open Source Software 2(9), 97.
.. [4] Morris, M. D. (1991). Factorial sampling plans for preliminary computational
   experiments. Technometrics 33, 161-174; Campolongo, F., Cariboni, J., Saltelli, A.
   (2007). An effective screening design for sensitivity analysis of large models.
   Environmental Modelling & Software 22, 1509-1518.
"""

from __future__ import annotations

import math
import tempfile
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear.config import Config
from jointwear.errors import ConfigError, DataError
from jointwear.workflows.sweep import Case, SweepPlan, SweepResult, run_sweep, seed_problem

__all__ = [
    "METHODS",
    "METRIC",
    "SENSITIVITY_FILES",
    "SensitivityResult",
    "case_outputs",
    "plot_sensitivity",
    "sensitivity_indices",
    "sensitivity_plan",
    "sensitivity_study",
]

#: the methods: variance-based indices, or screening
METHODS = ("sobol", "morris")
#: the output analysed unless told: revolutions to the first life limit
METRIC = "life_revolutions"
#: grid levels of a Morris trajectory [-]
MORRIS_LEVELS = 4
#: what the study writes into its folder (files, then folders)
SENSITIVITY_FILES = ("sensitivity.json", "sensitivity.png", "cases.csv", "sweep.nc")
SENSITIVITY_DIRS = ("cases",)


@dataclass(frozen=True)
class SensitivityResult:
    """Outcome of :func:`sensitivity_study`.

    Attributes
    ----------
    sweep : SweepResult
        The cases (their files in ``sweep.out``, unless the study had no folder).
    method : str
        ``"sobol"`` or ``"morris"``.
    metric : str
        The case metric analysed.
    indices : dict
        Input key -> ``{"S1", "ST", "S1_conf", "ST_conf"}`` (Sobol) or ``{"mu_star",
        "sigma", "mu_star_conf"}`` (Morris).
    outputs : ndarray
        The metric of every case, in case order.
    out : Path or None
        The folder written (``None``: the cases ran in a temporary folder).
    """

    sweep: SweepResult
    method: str
    metric: str
    indices: dict[str, dict[str, float]]
    outputs: NDArray[np.float64]
    out: Path | None

    def summary(self) -> dict[str, Any]:
        """The ``jointwear sensitivity --json`` object (``sensitivity.json`` plus the
        folder and this invocation's wall-clock time)."""
        return {
            **self.report(),
            "out": None if self.out is None else str(self.out),
            "runtime_s": self.sweep.runtime,
        }

    def report(self) -> dict[str, Any]:
        """What ``sensitivity.json`` holds."""
        return {
            "method": self.method,
            "metric": self.metric,
            "cases": len(self.sweep.records),
            "censored": int(
                sum(
                    (r.get("metrics") or {}).get("life_revolutions") is None
                    for r in self.sweep.records
                )
            ),
            "indices": self.indices,
        }


def _problem(keys: Sequence[str]) -> dict[str, Any]:
    """SALib's problem: the inputs on the unit cube (mapped to their distributions after)."""
    return {"num_vars": len(keys), "names": list(keys), "bounds": [[0.0, 1.0]] * len(keys)}


def _salib(module: str) -> Any:
    import importlib

    try:
        return importlib.import_module(f"SALib.{module}")
    except ImportError:
        raise ConfigError(
            "--method: SALib is not installed; install it with "
            "`pip install 'jointwear[sensitivity]'`"
        ) from None


def _design(method: str, keys: Sequence[str], cases: int, seed: int) -> NDArray[np.float64]:
    """The design in the unit cube: Saltelli's (``N (D + 2)`` rows, ``N`` a power of two)
    or Morris' trajectories (``r (D + 1)`` rows), as many rows as ``cases`` allows."""
    dims = len(keys)
    inputs = f"{dims} input{'s' if dims > 1 else ''}"
    if method == "sobol":
        per = dims + 2
        if cases < 2 * per:
            raise ConfigError(
                f"--cases: Sobol indices of {inputs} need at least 2 x {per} = "
                f"{2 * per} cases, got {cases}"
            )
        base = 1 << ((cases // per).bit_length() - 1)  # the largest power of two that fits
        sample = _salib("sample.sobol").sample(
            _problem(keys), base, calc_second_order=False, seed=seed
        )
        return np.clip(sample, 1e-12, 1 - 1e-12)  # (never 0 or 1: an inverse CDF is finite)
    per = dims + 1
    if cases < 2 * per:
        raise ConfigError(
            f"--cases: a Morris screening of {inputs} needs at least 2 x {per} = "
            f"{2 * per} cases, got {cases}"
        )
    return _salib("sample.morris").sample(
        _problem(keys), cases // per, num_levels=MORRIS_LEVELS, seed=seed
    )


def _quantiles(method: str, design: NDArray[np.float64]) -> NDArray[np.float64]:
    """The probabilities each design point stands for: Morris' grid levels ``0 .. 1`` are
    the centres of ``MORRIS_LEVELS`` equal-probability bins (its ends would be infinite
    for a normal input)."""
    if method == "morris":
        return (design * (MORRIS_LEVELS - 1) + 0.5) / MORRIS_LEVELS
    return design


def sensitivity_plan(
    base: Config,
    samples: Mapping[str, Mapping[str, Any]],
    cases: int,
    method: str = "sobol",
    seed: int = 0,
) -> tuple[SweepPlan, NDArray[np.float64]]:
    """The cases of a sensitivity study and their design in the unit cube.

    Parameters
    ----------
    base : Config
        The joint.
    samples : mapping
        Dotted key -> ``[sample]`` table (distribution and its parameters).
    cases : int
        The most cases to run [-] (the design uses as many as its structure allows).
    method : str
        ``"sobol"`` or ``"morris"``.
    seed : int
        Seed of the design and of the bootstrap [-].

    Returns
    -------
    plan : SweepPlan
        One case per design row, the inputs at their distributions' quantiles.
    design : ndarray, shape (cases, inputs)
        The design in the unit cube (what SALib analyses).
    """
    from jointwear.registry import suggest
    from jointwear.workflows.sweep.sampling import quantile_values

    if method not in METHODS:
        raise ConfigError(f"--method: unknown method {method!r}{suggest(method, METHODS)}")
    if not samples:
        raise ConfigError("--sample: name at least one uncertain input (KEY=DIST)")
    if seed_problem(seed) is not None:
        raise ConfigError(f"--seed: {seed_problem(seed)}")
    keys = list(samples)
    design = _design(method, keys, cases, seed)
    quantiles = _quantiles(method, design)
    columns = {
        key: quantile_values(base, key, samples[key], quantiles[:, j], f"--sample {key}")
        for j, key in enumerate(keys)
    }
    plan_cases = [
        Case.checked(base, index, {key: columns[key][index] for key in keys})
        for index in range(design.shape[0])
    ]
    study = {"kind": "sensitivity", "method": method}
    return SweepPlan(base, keys, plan_cases, "sensitivity", seed, study), design


def case_outputs(records: Sequence[Mapping[str, Any]], metric: str) -> NDArray[np.float64]:
    """The metric of every case; a life not reached is the revolutions the case ran.

    Parameters
    ----------
    records : sequence of mapping
        The sweep's case records, in case order.
    metric : str
        A case metric (``cases.csv`` column), e.g. ``life_revolutions``.

    Raises
    ------
    DataError
        A case failed, or has no such number: the indices need every case.
    """
    values = []
    for record in records:
        if record.get("status") != "ok":
            raise DataError(
                f"{record.get('case')}: {record.get('error', 'failed')}; the sensitivity "
                "indices need every case (see cases.csv; narrow the --sample ranges)"
            )
        metrics = record.get("metrics") or {}
        value = metrics.get(metric)
        if value is None and metric == METRIC:
            value = metrics.get("revolutions")  # censored: at least this long
        if value is None or not math.isfinite(float(value)):
            raise DataError(f"{record.get('case')}: --metric {metric}: no number for this case")
        values.append(float(value))
    return np.asarray(values)


def sensitivity_indices(
    method: str,
    keys: Sequence[str],
    design: NDArray[np.float64],
    outputs: NDArray[np.float64],
    seed: int = 0,
) -> dict[str, dict[str, float]]:
    """Sobol indices or Morris measures of ``outputs`` over ``design`` (SALib).

    Parameters
    ----------
    method : str
        ``"sobol"`` or ``"morris"``.
    keys : sequence of str
        The inputs, in design column order.
    design : ndarray, shape (cases, inputs)
        The design in the unit cube.
    outputs : ndarray, shape (cases,)
        The metric of every case.
    seed : int
        Seed of the bootstrap of the confidence intervals [-].

    Returns
    -------
    dict
        Key -> ``{"S1", "ST", "S1_conf", "ST_conf"}`` (95 % confidence half-widths) or
        ``{"mu_star", "sigma", "mu_star_conf"}``. A constant output has no variance to
        share: its Sobol indices are 0.
    """
    problem = _problem(keys)
    if method == "sobol":
        if np.ptp(outputs) == 0:
            zero = {"S1": 0.0, "ST": 0.0, "S1_conf": 0.0, "ST_conf": 0.0}
            return {key: dict(zero) for key in keys}
        found = _salib("analyze.sobol").analyze(
            problem, outputs, calc_second_order=False, conf_level=0.95, seed=seed
        )
        names = ("S1", "ST", "S1_conf", "ST_conf")
    else:
        found = _salib("analyze.morris").analyze(
            problem, design, outputs, conf_level=0.95, num_levels=MORRIS_LEVELS, seed=seed
        )
        names = ("mu_star", "sigma", "mu_star_conf")
    return {
        key: {name: float(np.asarray(found[name], dtype=float)[j]) for name in names}
        for j, key in enumerate(keys)
    }


def sensitivity_study(
    config: Path,
    samples: Sequence[str],
    cases: int = 256,
    *,
    method: str = "sobol",
    metric: str = METRIC,
    out: Path | None = None,
    seed: int | None = None,
    overrides: Sequence[str] = (),
    scheduler: str | None = None,
    workers: int | None = None,
    max_memory: str | None = None,
    time_limit: float | None = None,
    progress: Callable[[int, int], None] | None = None,
) -> SensitivityResult:
    """Sobol indices or a Morris screening of a joint's life (``jointwear sensitivity``).

    Checks the options, the folder and the config, builds the design
    (:func:`sensitivity_plan`), runs the cases on the sweep machinery and analyses the
    metric (:func:`sensitivity_indices`); with ``out``, writes ``sensitivity.json``,
    ``sensitivity.png``, ``cases.csv``, ``sweep.nc`` and ``cases/`` there.

    Parameters
    ----------
    config : Path
        The joint's config file.
    samples : sequence of str
        The uncertain inputs, ``KEY=NAME(param=value, ...)`` as for ``jointwear life``.
    cases : int
        The most cases to run [-].
    method : str
        ``"sobol"`` or ``"morris"``.
    metric : str
        The case metric analysed (a ``cases.csv`` column) [its own unit].
    out : Path, optional
        Output directory; without it the cases run in a temporary folder.
    seed : int, optional
        Seed of the design and the bootstrap (default 0).
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.
    scheduler : str, optional
        Address of a dask.distributed scheduler.
    workers : int, optional
        Local worker processes.
    max_memory : str, optional
        The memory budget of the cases running at once, e.g. ``"16 GiB"``.
    time_limit : float, optional
        Stop after this wall-clock time [s], checked between cases.
    progress : callable, optional
        ``progress(cases_done, cases_total)`` [-].

    Raises
    ------
    ConfigError
        A bad option, config, input or distribution; too few cases; SALib missing.
    DataError
        A case failed (the indices need every case).
    """
    from jointwear.io import check_out, check_tree
    from jointwear.resources import check_case_count
    from jointwear.workflows.inputs import load_config_file
    from jointwear.workflows.life import parse_distribution
    from jointwear.workflows.sweep import METRICS, checked_progress

    check_case_count(cases, "--cases")
    if metric not in METRICS:
        from jointwear.registry import suggest

        raise ConfigError(f"--metric: unknown case metric {metric!r}{suggest(metric, METRICS)}")
    if out is not None:
        out = check_out(out, files=SENSITIVITY_FILES, dirs=SENSITIVITY_DIRS)
        check_tree(out, SENSITIVITY_DIRS)
    base = load_config_file(config, overrides)
    tables = dict(parse_distribution(text) for text in samples)
    seed = 0 if seed is None else seed
    plan, design = sensitivity_plan(base, tables, cases, method, seed)
    checked = checked_progress(
        plan, progress, workers=workers, max_memory=max_memory, time_limit=time_limit
    )
    options = {"scheduler": scheduler, "workers": workers, "progress": checked}
    if out is None:
        with tempfile.TemporaryDirectory(prefix="jointwear-sensitivity-") as folder:
            sweep = run_sweep(plan, Path(folder) / "study", **options)
    else:
        sweep = run_sweep(plan, out, **options)
    outputs = case_outputs(sweep.records, metric)
    indices = sensitivity_indices(method, plan.keys, design, outputs, seed)
    result = SensitivityResult(sweep, method, metric, indices, outputs, out)
    if out is not None:
        _write(result, out)
    return result


def _write(result: SensitivityResult, out: Path) -> None:
    """``sensitivity.json`` and ``sensitivity.png``, each whole or not at all."""
    from jointwear.io import atomic_path, write_json
    from jointwear.workflows.sweep import writing

    with writing(out, "sensitivity.json"):
        write_json(out / "sensitivity.json", result.report())
    with writing(out, "sensitivity.png"), atomic_path(out / "sensitivity.png") as tmp:
        plot_sensitivity(result).savefig(tmp, format="png", dpi=120, metadata={"Software": None})


def plot_sensitivity(result: SensitivityResult) -> Any:
    """Bar chart of the indices with their 95 % confidence intervals: ``S1`` and ``ST``
    per input (Sobol), or ``mu_star`` and ``sigma`` (Morris).

    Returns
    -------
    matplotlib.figure.Figure
    """
    from matplotlib.figure import Figure

    keys = list(result.indices)
    fig = Figure(figsize=(max(5.0, 1.6 * len(keys) + 2.0), 3.8), layout="constrained")
    ax = fig.subplots()
    x = np.arange(len(keys))
    if result.method == "sobol":
        bars = (("S1", "S1_conf", "first order S1"), ("ST", "ST_conf", "total ST"))
        ax.set_ylabel(f"Sobol index of {result.metric}")
    else:
        bars = (("mu_star", "mu_star_conf", "mu*"), ("sigma", None, "sigma"))
        ax.set_ylabel(f"elementary effect on {result.metric}")
    width = 0.38
    for i, (name, conf, label) in enumerate(bars):
        values = [result.indices[k][name] for k in keys]
        errors = None if conf is None else [result.indices[k][conf] for k in keys]
        ax.bar(x + (i - 0.5) * width, values, width, yerr=errors, capsize=3, label=label)
    if result.method == "sobol":  # estimates scatter beyond [0, 1]: show them whole
        ax.axhline(1.0, color="k", linewidth=0.8, linestyle=":")
        ax.set_ylim(bottom=min(0.0, ax.get_ylim()[0]))
    ax.set_xticks(x, keys, rotation=15, ha="right", fontsize="small")
    ax.grid(axis="y", alpha=0.3)
    ax.legend(fontsize="small")
    ax.set_title(
        f"{result.method}: {len(result.sweep.records)} cases, sensitivity of {result.metric}"
    )
    return fig
