"""Life with uncertainty: the Monte Carlo life against a closed form."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.stats import norm

from jointwear.config import Config
from jointwear.errors import ConfigError, DataError
from jointwear.workflows.life import (
    LIFE_FILES,
    life_plan,
    life_quantiles,
    life_study,
    parse_distribution,
    run_life,
)
from tests.conftest import strict_json

KD = "materials.bushing.wear_coefficient"
SIGMA = 0.4
CASES = 200


@pytest.fixture(scope="module")
def study(paper_config: Config, tmp_path_factory: pytest.TempPathFactory):
    """Without contour update the wear is linear, so life = limit / rate is 1 / K_d."""
    base = paper_config.replace(
        {
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 90,
            "simulation.revolutions": 10**7,
            "life.peak_wear_depth": 1e-5,
        }
    )
    _, table = parse_distribution(f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma={SIGMA})")
    plan = life_plan(base, {KD: table}, CASES, seed=7)
    out = tmp_path_factory.mktemp("life")
    return base, run_life(plan, out, workers=1), out


def test_life_is_inversely_proportional_to_the_wear_coefficient(study) -> None:
    _, result, _ = study
    life_times_k = result.lives * result.inputs[KD]
    # each life is the first whole revolution past limit / rate: within one revolution
    spread = np.ptp(life_times_k) / np.median(life_times_k)
    assert spread < 2.0 / result.lives.min()


def test_life_distribution_is_the_lognormal_of_the_closed_form(study) -> None:
    _, result, _ = study
    stats = result.statistics
    assert stats["cases"] == CASES
    assert stats["censored"] == stats["failed"] == 0
    # life = C / K with K lognormal(median m, sigma): lognormal(C / m, sigma)
    constant = float(np.median(result.lives * result.inputs[KD]))
    median = constant / 5.05e-13
    logs = np.log(result.lives)
    assert logs.mean() == pytest.approx(math.log(median), abs=4 * SIGMA / math.sqrt(CASES))
    assert logs.std(ddof=1) == pytest.approx(SIGMA, rel=4 / math.sqrt(2 * CASES))
    quantiles = stats["life_revolutions"]
    assert not any(q["lower_bound"] for q in quantiles.values())
    # without censoring the Kaplan-Meier quantiles are the empirical ones
    for name, q in (("p5", 0.05), ("median", 0.5), ("p95", 0.95)):
        assert quantiles[name]["value"] == np.quantile(result.lives, q, method="inverted_cdf")
    z = norm.ppf(0.95)
    assert quantiles["median"]["value"] == pytest.approx(median, rel=0.1)
    assert quantiles["p5"]["value"] == pytest.approx(median * math.exp(-z * SIGMA), rel=0.15)
    assert quantiles["p95"]["value"] == pytest.approx(median * math.exp(z * SIGMA), rel=0.15)
    # the life falls as the wear coefficient rises (lives are whole revolutions: ties)
    assert stats["sensitivity"][KD] == pytest.approx(-1.0, abs=1e-4)


def test_b10_is_the_lognormal_quantile_of_the_closed_form(study) -> None:
    """life = C / K with K lognormal(m, sigma): B10 = (C / m) exp(-1.2816 sigma). The
    Kaplan-Meier B10 of 200 cases lies within 3 standard errors of the sample quantile
    (sigma sqrt(p (1 - p) / n) / phi(z_p), relative: 4.8 %), inside its 95 % bounds;
    B50 likewise. (That the bounds hold the closed form 95 % of the time is tested over
    many samples in test_reliability.py.)"""
    _, result, out = study
    stats = result.statistics
    constant = float(np.median(result.lives * result.inputs[KD]))
    for name, p in (("b10", 0.1), ("b50", 0.5)):
        z = norm.ppf(p)
        closed = constant / 5.05e-13 * math.exp(z * SIGMA)
        error = SIGMA * math.sqrt(p * (1 - p) / CASES) / norm.pdf(z)
        entry = stats["reliability"][name]
        assert entry["lower_bound"] is False
        assert entry["value"] == pytest.approx(closed, rel=3 * error)
        assert entry["lower"] < entry["value"] < entry["upper"]
        assert stats[f"{name}_revolutions"] == entry["value"]
    # the Weibull fit of lognormal lives: shape about 1.28 / sigma, B10 within 15 %
    assert stats["weibull_shape"] == pytest.approx(1.2816 / SIGMA, rel=0.25)
    b10 = constant / 5.05e-13 * math.exp(norm.ppf(0.1) * SIGMA)
    assert stats["reliability"]["b10"]["weibull"]["value"] == pytest.approx(b10, rel=0.15)
    data = strict_json((out / "life.json").read_text(encoding="utf-8"))
    assert data["b10_revolutions"] == stats["b10_revolutions"]
    reach = data["reliability"]["reach_probability"]  # by the horizon every case wore out
    assert reach["limits"] == {"peak_wear_depth": pytest.approx(1.0), "any": 1.0}


def test_life_hours_follow_the_period(study) -> None:
    _, result, out = study
    stats = result.statistics
    assert stats["life_hours"]["median"]["value"] == pytest.approx(
        stats["life_revolutions"]["median"]["value"] * 0.5 / 3600
    )
    data = strict_json((out / "life.json").read_text(encoding="utf-8"))
    assert data["cases"] == CASES
    assert len(data["lives"]) == CASES


def test_kaplan_meier_quantiles_of_a_published_example() -> None:
    """The 6-MP group of Freireich et al. (1963), weeks in remission, * censored: the
    Kaplan-Meier estimate falls to 0.448 at 23 weeks (the median) and no lower, so the
    95 % quantile lies beyond the longest case, 35 weeks (Kaplan-Meier tables of
    Kleinbaum & Klein, Survival Analysis, 3rd ed., ch. 2)."""
    weeks = [6, 6, 6, 6, 7, 9, 10, 10, 11, 13, 16, 17, 19, 20, 22, 23, 25, 32, 32, 34, 35]
    censored = [0, 0, 0, 1, 0, 1, 0, 1, 1, 0, 0, 1, 1, 1, 0, 0, 1, 1, 1, 1, 1]
    p5, p25, median, p95 = life_quantiles(weeks, np.array(censored, dtype=bool),
                                          (0.05, 0.25, 0.5, 0.95))  # fmt: skip
    assert p5 == {"value": 6.0, "lower_bound": False}
    assert p25 == {"value": 13.0, "lower_bound": False}  # F(13) = 1 - 0.690 >= 0.25
    assert median == {"value": 23.0, "lower_bound": False}
    assert p95 == {"value": 35.0, "lower_bound": True}
    # reading the censored weeks as remissions ended would put the median at 16 weeks
    assert np.quantile(weeks, 0.5, method="inverted_cdf") == 16


def test_all_censored_gives_lower_bounds_only() -> None:
    quantiles = life_quantiles([100.0, 100.0, 80.0], np.ones(3, dtype=bool))
    assert quantiles == [{"value": 100.0, "lower_bound": True}] * 3


def test_censored_cases_make_lower_bounds(paper_config: Config, tmp_path: Path) -> None:
    base = paper_config.replace(
        {
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 90,
            "simulation.revolutions": 2000,
            "life.peak_wear_depth": 1e-5,
        }
    )
    plan = life_plan(
        base, {KD: {"distribution": "loguniform", "low": 1e-13, "high": 1e-12}}, 20, seed=1
    )
    result = run_life(plan, tmp_path / "out", workers=1)
    stats = result.statistics
    assert 0 < stats["censored"] < 20
    assert stats["life_revolutions"]["p95"] == {"value": 2000.0, "lower_bound": True}
    assert stats["life_revolutions"]["p5"]["lower_bound"] is False
    assert stats["life_revolutions"]["p5"]["value"] < 2000
    # a censored case's life is the revolutions it ran, flagged; its hours follow
    data = strict_json((tmp_path / "out" / "life.json").read_text(encoding="utf-8"))
    lives = data["lives"]
    assert sum(life["censored"] for life in lives) == stats["censored"]
    for life in lives:
        if life["censored"]:
            assert life["life_revolutions"] == 2000
            assert life["life_hours"] == pytest.approx(2000 * 0.5 / 3600)
        else:
            assert life["life_revolutions"] <= 2000
    assert np.array_equal(result.censored, [life["censored"] for life in lives])
    # the longer the wear coefficient lets the joint last, the more often it is censored
    assert result.inputs[KD][result.censored].max() < result.inputs[KD][~result.censored].min()


def test_life_study_writes_its_folder(paper_config_path: Path, tmp_path: Path) -> None:
    """The study's files: life.json is the summary with every case's life (without this
    invocation's folder and wall-clock time), life.png drawn."""
    out = tmp_path / "life"
    result = life_study(
        paper_config_path,
        [f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.5)"],
        4,
        out=out,
        seed=2,
        overrides=["contact.nodes=60", "simulation.steps_per_revolution=60"],
        workers=1,
    )
    written = strict_json((out / "life.json").read_text(encoding="utf-8"))
    summary = result.summary()
    assert {k: v for k, v in written.items() if k != "lives"} == {
        k: v for k, v in summary.items() if k not in ("out", "runtime_s")
    }
    assert len(written["lives"]) == 4
    assert (out / "life.png").stat().st_size > 1000
    assert {p.name for p in out.iterdir()} == {
        "life.json",
        "life.png",
        "cases.csv",
        "sweep.nc",
        "cases",
        "sweep-plan.json",
    }


def test_life_study_checks_its_folder_before_reading_the_config(tmp_path: Path) -> None:
    with pytest.raises(ConfigError, match="--out: missing"):
        life_study(tmp_path / "missing.toml", [f"{KD}=lognormal(median=1e-13, sigma=1)"], 4)
    with pytest.raises(ConfigError, match="--cases"):
        life_study(tmp_path / "missing.toml", [], 10**12, out=tmp_path / "out")
    with pytest.raises(ConfigError, match="missing.toml: file not found"):
        life_study(tmp_path / "missing.toml", [], 4, out=tmp_path / "out")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (f"{KD}=lognormal", "expected NAME"),
        (f"{KD}=lognormal(median)", "param=value"),
        (f"{KD}=logn(median=1e-13, sigma=1)", "did you mean 'lognormal'"),
    ],
)
def test_bad_samples(paper_config: Config, text: str, message: str) -> None:
    def plan(text: str):
        key, table = parse_distribution(text)
        return life_plan(paper_config, {key: table}, 10)

    with pytest.raises(ConfigError, match=message):
        plan(text)


def _study_files(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in folder.iterdir() if p.is_file()}


def _without_wall_clock(csv_bytes: bytes) -> list[list[str]]:
    """cases.csv without the runtime_s column: the only number that is a wall-clock time."""
    import csv
    import io

    rows = list(csv.reader(io.StringIO(csv_bytes.decode("utf-8"))))
    keep = [i for i, name in enumerate(rows[0]) if name != "runtime_s"]
    return [[row[i] for i in keep] for row in rows]


def test_an_interrupted_study_resumes_to_the_same_outputs(
    paper_config_path: Path, tmp_path: Path
) -> None:
    """Stopped after 5 of 12 cases (Ctrl-C from the progress hook), `--resume` runs the
    other 7 and writes life.json, life.png and sweep-plan.json byte for byte as the
    uninterrupted study; cases.csv and sweep.nc differ only in each case's wall-clock
    runtime_s."""
    import xarray as xr

    from jointwear.interrupts import Interrupted

    options = {
        "samples": [f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.5)"],
        "cases": 12,
        "seed": 4,
        "overrides": [
            "contact.nodes=60",
            "simulation.steps_per_revolution=60",
            "life.peak_wear_depth=1e-5",
            "simulation.revolutions=2000",
        ],
        "workers": 1,
    }
    whole = life_study(paper_config_path, out=tmp_path / "whole", **options)
    assert 0 < whole.statistics["censored"] < 12  # both kinds of case are resumed

    def stop_after_five(done: int, total: int) -> None:
        if done == 5:
            raise KeyboardInterrupt

    parts = tmp_path / "parts"
    with pytest.raises(Interrupted) as stopped:
        life_study(paper_config_path, out=parts, progress=stop_after_five, **options)
    assert stopped.value.resume == f"jointwear life --resume {parts}"
    assert len(list((parts / "cases").glob("case-*.json"))) == 5
    assert not (parts / "life.json").exists()
    resumed = life_study(None, resume=parts, workers=1)
    assert resumed.sweep.skipped == 5
    first, second = _study_files(tmp_path / "whole"), _study_files(parts)
    assert set(first) == set(second) == {*LIFE_FILES, "sweep-plan.json"}
    for name in ("life.json", "life.png", "sweep-plan.json"):
        assert first[name] == second[name], name
    assert _without_wall_clock(first["cases.csv"]) == _without_wall_clock(second["cases.csv"])
    with (
        xr.open_dataset(tmp_path / "whole" / "sweep.nc") as a,
        xr.open_dataset(parts / "sweep.nc") as b,
    ):
        assert a.drop_vars("runtime_s").identical(b.drop_vars("runtime_s"))
    assert resumed.statistics == whole.statistics


def test_resume_refuses_what_the_stored_plan_fixes(paper_config_path: Path, tmp_path: Path) -> None:
    sweep_folder = tmp_path / "sweep"
    sweep_folder.mkdir()
    with pytest.raises(ConfigError, match="--resume: CONFIG is fixed"):
        life_study(paper_config_path, resume=sweep_folder)
    with pytest.raises(ConfigError, match="--resume: --cases is fixed"):
        life_study(None, cases=10, resume=sweep_folder)
    with pytest.raises(DataError, match="not a sweep directory"):
        life_study(None, resume=sweep_folder)
    assert list(sweep_folder.iterdir()) == []
