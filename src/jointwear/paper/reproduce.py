"""Reproduce the paper: every table row and figure case, calibrated on one row.

Protocol: the parameters the paper does not give (joint axial length
``b``, bushing wall thickness ``L``, spring preload) are calibrated on **one**
row, Table 3, Winkler, 120 rpm, 0.05 mm, one revolution; every other row is
then a prediction with those values, reported next to the paper with its
deviation. No row is tuned on its own.
"""

from __future__ import annotations

import math
import platform
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from jointwear.config import Config
from jointwear.io import json_ready, write_json
from jointwear.paper.cases import PAPER_ROWS, case_config, case_names, deviation, shown
from jointwear.paper.protocol import (
    CALIBRATION_CASE,
    CALIBRATION_PARAMETERS,
    calibrate_paper_row,
)

__all__ = [
    "FEEDBACK_CLEARANCES",
    "SENSITIVITY",
    "TRENDS",
    "Trend",
    "check_trends",
    "compile_kernels",
    "eq2_stiffness_over_pi",
    "feedback_study",
    "reproduce",
    "reproduce_to_folder",
    "run_cases",
    "sensitivity",
    "variant_record",
    "wear_budget",
]


# ---------------------------------------------------------------- trends
@dataclass(frozen=True)
class Trend:
    """A trend the paper states, and how to check it on a set of case summaries.

    ``budget_pairs`` lists (from, to) cases whose wear volumes the report splits
    into Archard's factors (:func:`wear_budget`) to show where a change comes from.
    """

    statement: str
    check: Callable[[dict[str, dict[str, Any]]], tuple[bool, str]]
    budget_pairs: tuple[tuple[str, str], ...] = ()


def _grows(results, low, high, keys=("peak", "width", "mass"), shrink=()):
    ok, parts = True, []
    for key in keys:
        a, b = results[low][key], results[high][key]
        good = b < a if key in shrink else b > a
        ok &= good
        parts.append(f"{key} {shown(key, a)} → {shown(key, b)}")
    return ok, ", ".join(parts)


def _both_models(fn):
    def check(results):
        oks, texts = [], []
        for model in ("nlcp", "winkler"):
            ok, text = fn(results, model)
            oks.append(ok)
            texts.append(f"{model}: {text}")
        return all(oks), "; ".join(texts)

    return check


def _nlcp_beside_winkler(results, key, larger):
    """Is NLCP's ``key`` larger (or smaller) than Winkler's at 120 and 240 rpm, one revolution?"""
    pairs = [
        (speed, results[f"table3_nlcp_{speed}"][key], results[f"table3_winkler_{speed}"][key])
        for speed in ("120rpm", "240rpm")
    ]
    ok = all(nlcp > winkler if larger else nlcp < winkler for _, nlcp, winkler in pairs)
    text = ", ".join(f"{s}: {shown(key, n)} vs {shown(key, w)}" for s, n, w in pairs)
    return ok, text


TRENDS = (
    Trend(
        "faster crank (120 -> 240 rpm) -> larger peak, width and mass",
        _both_models(lambda r, m: _grows(r, f"table3_{m}_120rpm", f"table3_{m}_240rpm")),
    ),
    Trend(
        "larger clearance (0.05 -> 0.2 mm, 240 rpm) -> larger peak, smaller width",
        _both_models(
            lambda r, m: _grows(
                r,
                f"table3_{m}_240rpm",
                f"table4_{m}_clearance_0.2mm",
                keys=("peak", "width"),
                shrink=("width",),
            )
        ),
    ),
    Trend(
        "larger clearance (0.05 -> 0.2 mm, 240 rpm) -> larger mass",
        _both_models(
            lambda r, m: _grows(
                r, f"table3_{m}_240rpm", f"table4_{m}_clearance_0.2mm", keys=("mass",)
            )
        ),
        budget_pairs=tuple(
            (f"table3_{m}_240rpm", f"table4_{m}_clearance_0.2mm") for m in ("nlcp", "winkler")
        ),
    ),
    Trend(
        "more revolutions (10000 -> 15000) -> larger peak, width and mass",
        _both_models(lambda r, m: _grows(r, f"table5_{m}_10000r", f"table5_{m}_15000r")),
    ),
    Trend(
        "contour update -> lower peak and wider zone than without (NLCP, 10000 r)",
        lambda r: _grows(
            r, "fig13_nlcp_no_update", "fig14_nlcp_update", keys=("peak", "width"), shrink=("peak",)
        ),
    ),
    Trend(
        "NLCP -> wider zone than Winkler (one revolution, 120 and 240 rpm)",
        lambda r: _nlcp_beside_winkler(r, "width", larger=True),
    ),
    Trend(
        "NLCP -> lower peak than Winkler (one revolution, 120 and 240 rpm)",
        lambda r: _nlcp_beside_winkler(r, "peak", larger=False),
    ),
    Trend(
        "larger clearance (0.05 -> 0.2 mm, 120 rpm, 10000 r, NLCP) -> larger peak, smaller width",
        lambda r: _grows(
            r,
            "table5_nlcp_10000r",
            "fig15_nlcp_clearance_0.2mm",
            keys=("peak", "width"),
            shrink=("width",),
        ),
    ),
    Trend(
        "larger clearance (0.05 -> 0.2 mm, 120 rpm, 10000 r, NLCP) -> larger mass",
        lambda r: _grows(r, "table5_nlcp_10000r", "fig15_nlcp_clearance_0.2mm", keys=("mass",)),
        budget_pairs=(("table5_nlcp_10000r", "fig15_nlcp_clearance_0.2mm"),),
    ),
)


def check_trends(summaries: dict[str, dict[str, Any]]) -> list[dict[str, Any]]:
    """Check every stated trend on our results and on the paper's own table values.

    A trend the paper states in its text can disagree with its own tables (the
    wear mass in Table 4 falls with clearance while the text says it grows);
    both verdicts are reported.
    """
    paper = {
        name: {"peak": row.peak, "width": row.width, "mass": row.mass}
        for name, row in PAPER_ROWS.items()
    }
    out = []
    for number, trend in enumerate(TRENDS, start=1):
        try:
            ok, detail = trend.check(summaries)
        except KeyError:
            continue
        try:
            paper_ok, paper_detail = trend.check(paper)
        except KeyError:
            paper_ok, paper_detail = None, "figure only, no table values"
        out.append(
            {
                "id": f"T{number}",
                "statement": trend.statement,
                "holds": bool(ok),
                "detail": detail,
                "paper_tables_hold": paper_ok,
                "paper_detail": paper_detail,
                "budget": _budget_ratios(summaries, trend.budget_pairs),
            }
        )
    return out


def _budget_ratios(
    summaries: dict[str, dict[str, Any]], pairs: tuple[tuple[str, str], ...]
) -> list[dict[str, Any]]:
    """Ratios (to / from) of the factors of Archard's global balance, per case pair."""
    out = []
    for low, high in pairs:
        try:
            a, b = summaries[low]["budget"], summaries[high]["budget"]
            volume = summaries[high]["wear_volume_m3"] / summaries[low]["wear_volume_m3"]
        except KeyError:
            continue
        out.append(
            {
                "from": low,
                "to": high,
                "radius": b["radius_m"] / a["radius_m"],
                "load_rotation": b["load_rotation_n_rad"] / a["load_rotation_n_rad"],
                "kappa": b["kappa"] / a["kappa"],
                "kappa_from": a["kappa"],
                "kappa_to": b["kappa"],
                "volume": volume,
            }
        )
    return out


# ---------------------------------------------------------------- driver
def eq2_stiffness_over_pi(config: Config) -> float:
    """NLCP ``K`` of eq. (2) read with ``sigma = (1 - nu^2) / E`` (no pi) [N/m^1.5].

    Eq. (3) defines ``sigma = (1 - nu^2) / (pi E)``, which cancels the ``pi`` of
    eq. (2); Lankarani-Nikravesh and Flores write the same stiffness with
    ``sigma = (1 - nu^2) / E`` and no ``pi`` in ``K``. Mixing the two conventions
    gives ``K / pi``: a slip an implementation can make, and one that reproduces the
    paper's NLCP wear widths (docs/reproduction.md).

    Parameters
    ----------
    config : Config
        A case's configuration (its own ``contact.stiffness`` is ignored).
    """
    return config.replace({"contact.stiffness": None}).nlcp_stiffness / math.pi


#: alternative readings of what the paper leaves open, each re-calibrated on the
#: calibration row and re-predicting every case (no per-row tuning). A value may be a
#: callable of the calibration case's config.
SENSITIVITY: dict[str, dict[str, Any]] = {
    "paper's sliding reading (contact azimuth)": {"simulation.sliding": "contact-azimuth"},
    "constrained Winkler modulus": {"contact.foundation_modulus": "constrained"},
    "spring pushing the slider towards the crank": {"mechanism.spring_mode": "push"},
    # the shipped defaults b = 20 mm, L = 2.5 mm fixed, the preload alone fitted to the
    # row's mass; the row's peak and width become predictions too
    "b = 20 mm, L = 2.5 mm (the defaults), preload fitted to the mass only": {
        "joint.axial_length": 0.020,
        "joint.bushing_thickness": 0.0025,
    },
    # NLCP's K does not enter the (Winkler) calibration row: the calibrated values are
    # the default's, and only the NLCP predictions change
    "NLCP stiffness K / pi (eq. 2 with sigma = (1 - nu^2) / E)": {
        "contact.stiffness": eq2_stiffness_over_pi,
    },
}


def run_cases(
    names: list[str],
    overrides: dict[str, Any],
    progress: Callable[[str, int, int], None] | None = None,
) -> tuple[dict[str, dict[str, Any]], dict[str, Any]]:
    """Run paper cases with dotted-key overrides.

    Returns
    -------
    summaries : dict
        Per case, the ``run --json`` summary plus ``peak`` [m], ``width`` [deg],
        ``mass`` [kg], ``contour_update`` (whether the contour was updated; without,
        ``contour_updates`` counts the saved profiles of the scaled revolution) and
        ``budget`` (:func:`wear_budget`).
    results : dict
        Per case, the :class:`~jointwear.results.WearResult`.
    """
    from jointwear.simulation import Simulation

    summaries: dict[str, dict[str, Any]] = {}
    results: dict[str, Any] = {}
    for i, name in enumerate(names):
        if progress is not None:
            progress(name, i, len(names))
        result = Simulation(case_config(name, overrides)).run()
        summary = result.summary()
        summary["peak"] = summary["peak_wear_depth_m"]
        summary["width"] = summary["wear_width_deg"]
        summary["mass"] = summary["wear_mass_kg"]
        summary["contour_update"] = bool(result.config.simulation.update_contour)
        summary["budget"] = wear_budget(result)
        summaries[name] = summary
        results[name] = result
    return summaries, results


def material_checks(result: Any) -> dict[str, dict[str, Any]]:
    """The engineering checks of a paper case against its bushing's limits.

    The paper's bushing is PTFE but its configs name no limits: without limits of its
    own the bushing is checked against the materials library's ``ptfe`` (an exceeded
    limit warns).

    Parameters
    ----------
    result : jointwear.results.WearResult
        A single-joint run.
    """
    from jointwear.materials import LIMIT_KEYS, get_material
    from jointwear.tribology.metrics import engineering_checks

    bushing = result.config.materials.bushing
    if any(getattr(bushing, key) is not None for key in LIMIT_KEYS):
        return engineering_checks(result.joint_data(), result.config)
    ptfe = get_material("ptfe")
    return engineering_checks(
        result.joint_data(), result.config, limits=ptfe.limits(), name=ptfe.name
    )


def wear_budget(result: Any) -> dict[str, float]:
    """What a run's wear volume is made of, by Archard's law summed over the bushing.

    Summing ``dh_j = K_d p_j ds`` over the bushing surface gives the volume per step
    ``K_d ds sum_j F_j``: the sliding distance times the sum of the spring forces,
    which exceeds the joint load ``N`` by the spread factor
    ``kappa = sum_j F_j / sum_j F_j cos(beta_j) >= 1`` (a wide contact arc carries
    the load at a slant). With ``ds = R_b |d phi|``,

    .. math:: V = K_d \\, R_b \\, \\bar\\kappa \\sum_k N_k |\\Delta\\varphi_k| \\times
              \\text{revolutions}.

    Parameters
    ----------
    result : WearResult
        A finished run.

    Returns
    -------
    dict
        ``radius_m`` (sliding radius ``R_b``), ``load_rotation_n_rad`` (``sum_k N_k
        |dphi_k|`` over one revolution [N rad]), ``kappa`` (the run's mean spread
        factor [-], from its wear volume).
    """
    ds = result.dataset
    config = result.config
    radius = config.joint.bushing_radius
    load_sliding = float(np.sum(ds["joint_load"].values * ds["sliding_distance"].values))
    revolutions = int(ds["update_revolution"].values[-1])
    volume = float(ds["wear_volume"].values[-1])
    wear_coefficient = config.materials.bushing.wear_coefficient
    return {
        "radius_m": radius,
        "load_rotation_n_rad": load_sliding / radius,
        "kappa": volume / (wear_coefficient * load_sliding * revolutions),
    }


def variant_record(
    label: str,
    settings: dict[str, Any],
    calibrated: dict[str, float],
    summaries: dict[str, dict[str, Any]],
) -> dict[str, Any]:
    """Deviations, the ratios the paper's trends rest on, and the trend verdicts of one reading."""
    deviations = {
        name: {
            key: deviation(summaries[name][key], getattr(row, key))
            for key in ("peak", "width", "mass")
        }
        for name, row in PAPER_ROWS.items()
        if name in summaries
    }

    def ratio(key: str, high: str, low: str) -> float:
        try:
            return summaries[high][key] / summaries[low][key]
        except KeyError:
            return math.nan

    trends = check_trends(summaries)
    return {
        "variant": label,
        "settings": settings,
        "calibrated": calibrated,
        "deviations": deviations,
        "mass_ratio_240_120": ratio("mass", "table3_winkler_240rpm", "table3_winkler_120rpm"),
        "nlcp_winkler_peak_ratio": ratio("peak", "table3_nlcp_120rpm", "table3_winkler_120rpm"),
        "nlcp_winkler_width_ratio": ratio("width", "table3_nlcp_120rpm", "table3_winkler_120rpm"),
        "trends_holding": [t["id"] for t in trends if t["holds"]],
        "trends_failing": [t["id"] for t in trends if not t["holds"]],
    }


def sensitivity(
    overrides: dict[str, Any] | None = None, names: list[str] | None = None
) -> list[dict[str, Any]]:
    """Re-run the calibration protocol under each alternative reading in ``SENSITIVITY``.

    Each variant is calibrated on the calibration row (the unknowns it leaves free) and
    predicts every case in ``names`` (default all); see :func:`variant_record`.
    """
    names = names or case_names()
    base_config = case_config(CALIBRATION_CASE, overrides)
    out = []
    for label, variant in SENSITIVITY.items():
        resolved = {k: v(base_config) if callable(v) else v for k, v in variant.items()}
        base = {**(overrides or {}), **resolved}
        free = [p for p in CALIBRATION_PARAMETERS if p.key not in resolved]
        calibration = calibrate_paper_row(parameters=free, overrides=base, metrics=len(free))
        summaries, _ = run_cases(names, {**base, **calibration.values})
        out.append(variant_record(label, resolved, calibration.values, summaries))
    return out


#: clearances of the clearance -> wear-mass study with impacts [m]
FEEDBACK_CLEARANCES = (0.05e-3, 0.1e-3, 0.2e-3, 0.3e-3)
#: a spring that lets the pin separate (the pulling spring of the paper keeps contact)
PUSHING_SPRING = {"mechanism.spring_mode": "push", "mechanism.spring_preload": 1.0}


def feedback_study(overrides: dict[str, Any]) -> dict[str, Any]:
    """What the wear feedback changes for the paper's joint, and clearance -> wear with impacts.

    * The Table 5 NLCP case run to 10^5 revolutions, with the load of the unworn joint
      throughout and with the dynamics solved again on the worn joint (adaptive).
    * The paper's claim that a larger clearance wears more mass (its Tables 3-4,
      240 rpm, one revolution), with the contact-impact dynamics, for the paper's
      pulling spring and for a pushing spring with 1 N preload that lets the pin
      separate.

    Parameters
    ----------
    overrides : dict
        Dotted-key overrides of every case (the calibration).

    Returns
    -------
    dict
        ``coupling`` (uncoupled and coupled summaries) and ``clearance`` (per spring,
        the wear mass [kg] and impacts per revolution at each clearance).
    """
    import warnings

    from jointwear.errors import ContactLossWarning, WearFeedbackWarning
    from jointwear.simulation import Simulation

    def summary(name: str, extra: dict[str, Any]) -> dict[str, Any]:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", WearFeedbackWarning)
            warnings.simplefilter("ignore", ContactLossWarning)
            result = Simulation(case_config(name, {**overrides, **extra})).run()
        out = result.summary()
        out["impacts"] = int(result.dataset["dynamics_impacts"].values[0])
        return out

    long = {"simulation.revolutions": 100000, "simulation.update_every": "adaptive"}
    coupling = {
        "uncoupled": summary("table5_nlcp_15000r", long),
        "coupled": summary(
            "table5_nlcp_15000r", {**long, "simulation.dynamics_update": "adaptive"}
        ),
    }
    clearance: dict[str, dict[str, list[float]]] = {}
    for spring, extra in (("pulling (paper)", {}), ("pushing, 1 N preload", PUSHING_SPRING)):
        rows: dict[str, list[float]] = {"clearance_m": list(FEEDBACK_CLEARANCES)}
        for model in ("massless-link", "contact-impact"):
            runs = [
                summary(
                    "table3_winkler_240rpm",
                    {**extra, "joint.clearance": c, "dynamics.model": model},
                )
                for c in FEEDBACK_CLEARANCES
            ]
            rows[f"{model}_mass_kg"] = [r["wear_mass_kg"] for r in runs]
            rows[f"{model}_impacts"] = [r["impacts"] for r in runs]
        clearance[spring] = rows
    return {"coupling": coupling, "clearance": clearance}


def compile_kernels(config: Config) -> float:
    """Compile the numba kernel the cases run, or load it from numba's cache [s].

    numba compiles a kernel at its first call on a new installation (tens of seconds)
    and loads it from its cache afterwards (a few tenths of a second); either is paid
    once per process, by whatever calls the kernel first. Called before the cases, it
    keeps that one-time cost out of every case's run time. A cold and a warm-started
    revolution of the contact kernel take the argument types of a run: the one
    compiled variant of each function that every case uses (the cases read no dense
    pressure from it and integrate no contact-impact dynamics long enough to compile
    theirs).

    Parameters
    ----------
    config : Config
        A paper case (its joint, load cycle and contact law).

    Returns
    -------
    float
        Wall time taken [s].
    """
    from jointwear.contact.kernel import revolution_wear
    from jointwear.simulation import Simulation

    start = time.perf_counter()
    simulation = Simulation(config)
    cycle = simulation.load_cycle
    arguments = (
        simulation.initial_contour(),
        simulation.pin,
        cycle.load,
        cycle.azimuth,
        simulation.sliding_distance,
        simulation.law,
        config.materials.bushing.wear_coefficient,
    )
    reach = config.joint.bushing_thickness
    cold = revolution_wear(*arguments, max_penetration=reach)
    revolution_wear(
        *arguments, max_penetration=reach, initial_offset=cold.offset, window=cold.window
    )
    return time.perf_counter() - start


def reproduce(
    out: str | Path,
    progress: Callable[[str, int, int], None] | None = None,
    calibrate: bool = True,
    cases: list[str] | None = None,
    overrides: dict[str, Any] | None = None,
    with_sensitivity: bool | None = None,
) -> dict[str, Any]:
    """Run every paper case and write ``out/report.md`` and figures.

    Parameters
    ----------
    out : path-like
        Output folder.
    progress : callable, optional
        ``progress(case, done, total)``.
    calibrate : bool
        Calibrate on the calibration row first (else use the configs' values).
    cases : list of str, optional
        Subset of cases (default all).
    overrides : dict, optional
        Dotted-key overrides applied to every case before calibration.
    with_sensitivity : bool, optional
        Also re-run the protocol under the alternative readings of
        ``SENSITIVITY`` (default: when all cases are run with calibration).

    Returns
    -------
    dict
        ``{"calibration": {...}, "cases": {name: summary}, "trends": [...],
        "compile_s": ...}``; ``compile_s`` is the one-time compile of the kernels
        (:func:`compile_kernels`, ``None`` if no case needed them), timed apart from
        every case.
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    overrides = dict(overrides or {})
    overrides_in = dict(overrides)
    names = cases or case_names()
    if with_sensitivity is None:
        with_sensitivity = calibrate and cases is None
    compile_s = _compile_first(names, overrides, with_sensitivity)
    calibration = None
    if calibrate:
        calibration = calibrate_paper_row(overrides=overrides)
        overrides.update(calibration.values)
    summaries, results = run_cases(names, overrides, progress)
    for name, result in results.items():
        summaries[name]["checks"] = material_checks(result)
    for name, result in results.items():
        result.to_netcdf(out / "results" / f"{name}.nc")
    if progress is not None:
        progress("done", len(names), len(names))
    variants, feedback = [], None
    if with_sensitivity:
        fitted = {} if calibration is None else calibration.values
        default = variant_record(DEFAULT_READING, {}, fitted, summaries)
        variants = [default, *sensitivity(overrides_in, names)]
        feedback = feedback_study(overrides)
    from jointwear.paper.report import figures, write_report

    datasets = {name: result.dataset for name, result in results.items()}
    figure_paths = figures(datasets, out / "figures")
    report = {
        "calibration": None if calibration is None else _calibration_record(calibration),
        "cases": summaries,
        "trends": check_trends(summaries),
        "sensitivity": variants,
        "feedback": feedback,
        "compile_s": compile_s,
        "total_runtime_s": time.perf_counter() - started,
        "machine": f"{platform.processor() or platform.machine()}, {platform.system()}, "
        f"Python {platform.python_version()}",
    }
    write_report(report, out / "report.md", figure_paths)
    write_json(out / "report.json", json_ready(report))
    return report


#: the label of the default reading in the sensitivity table
DEFAULT_READING = "**default** (relative rotation, E, pulling spring, K of eq. 2)"


def _compile_first(
    names: list[str], overrides: dict[str, Any], with_sensitivity: bool
) -> float | None:
    """The one-time compile of the kernels before anything is timed [s], if a case will use
    them (a run of one-revolution cases never loads numba); ``None`` otherwise."""
    from jointwear.contact.kernel import compiled_available
    from jointwear.contact.solver import compiled_kernel

    compiled = [compiled_kernel(case_config(name, overrides)) is not False for name in names]
    if (with_sensitivity or any(compiled)) and compiled_available():
        return compile_kernels(case_config(CALIBRATION_CASE, overrides))
    return None


def _calibration_record(calibration: Any) -> dict[str, Any]:
    """The report's record of the calibration on :data:`CALIBRATION_CASE`."""
    return {
        "case": CALIBRATION_CASE,
        "values": calibration.values,
        "residuals": calibration.residuals.tolist(),
        "labels": calibration.labels,
        "evaluations": calibration.evaluations,
    }


#: what ``jointwear reproduce`` writes into its folder (files, then folders)
REPORT_FILES = ("report.md", "report.json")
REPORT_DIRS = ("figures", "results")


def reproduce_to_folder(
    out: Path,
    *,
    cases: Sequence[str] | None = None,
    calibrate: bool = True,
    overrides: Sequence[str] = (),
    progress: Callable[[str, int, int], None] | None = None,
) -> tuple[dict[str, Any], Path]:
    """``jointwear reproduce``: :func:`reproduce` into a folder that appears when complete.

    Parameters
    ----------
    out : Path
        Folder for ``report.md``, ``report.json``, ``figures/`` and ``results/``.
    cases : sequence of str, optional
        Run only these paper cases (default all, with the sensitivity study).
    calibrate : bool
        Calibrate the undisclosed parameters on the calibration row first.
    overrides : sequence of str
        ``section.key=VALUE`` overrides of every case.
    progress : callable, optional
        ``progress(case, done, total)``.

    Returns
    -------
    report : dict
        What :func:`reproduce` returns.
    folder : Path
        Where the report is.

    Raises
    ------
    ConfigError
        An unknown case (with a suggestion), a bad override or folder.
    """
    from jointwear.config import parse_override
    from jointwear.errors import ConfigError
    from jointwear.io import check_out, check_tree, staged_output
    from jointwear.registry import suggest

    out = check_out(out, files=REPORT_FILES, dirs=REPORT_DIRS)
    check_tree(out, REPORT_DIRS)
    if cases:
        known = case_names()
        for name in cases:
            if name not in known:
                raise ConfigError(f"--case: unknown paper case {name!r}{suggest(name, known)}")
    changes = dict(parse_override(text) for text in overrides)
    # the folder appears when complete
    with staged_output(out, files=REPORT_FILES, dirs=REPORT_DIRS) as staging:
        report = reproduce(
            staging,
            progress=progress,
            calibrate=calibrate,
            cases=None if cases is None else list(cases),
            overrides=changes,
        )
    return report, out
