"""Life with uncertainty: the Monte Carlo life against a closed form."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.stats import norm

from jointwear.cli import main
from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.life import life_plan, parse_distribution, run_life

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
    z = norm.ppf(0.95)
    assert quantiles["median"] == pytest.approx(median, rel=0.1)
    assert quantiles["p5"] == pytest.approx(median * math.exp(-z * SIGMA), rel=0.15)
    assert quantiles["p95"] == pytest.approx(median * math.exp(z * SIGMA), rel=0.15)
    # the life falls as the wear coefficient rises (lives are whole revolutions: ties)
    assert stats["sensitivity"][KD] == pytest.approx(-1.0, abs=1e-4)


def test_life_hours_follow_the_period(study) -> None:
    _, result, out = study
    stats = result.statistics
    assert stats["life_hours"]["median"] == pytest.approx(
        stats["life_revolutions"]["median"] * 0.5 / 3600
    )
    assert json.loads((out / "life.json").read_text(encoding="utf-8"))["cases"] == CASES


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
    stats = run_life(plan, tmp_path / "out", workers=1).statistics
    assert 0 < stats["censored"] < 20
    assert stats["life_revolutions"].get("p95_lower_bound") is True
    assert "p5_lower_bound" not in stats["life_revolutions"]


def test_life_cli(capsys, paper_config_path: Path, tmp_path: Path) -> None:
    main(
        [
            "life",
            str(paper_config_path),
            "--sample",
            f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.5)",
            "--sample",
            "joint.clearance=uniform(low=0.04 mm, high=0.06 mm)",
            "--cases",
            "12",
            "--seed",
            "3",
            "--set",
            "life.peak_wear_depth=0.01 mm",
            "--set",
            "simulation.revolutions=1000000",
            "--set",
            "contact.nodes=90",
            "--set",
            "simulation.steps_per_revolution=60",
            "--out",
            str(tmp_path / "life"),
            "--workers",
            "1",
            "--json",
            "--quiet",
        ]
    )
    data = json.loads(capsys.readouterr().out)
    assert data["cases"] == 12
    assert set(data["sensitivity"]) == {KD, "joint.clearance"}
    assert data["life_revolutions"]["p5"] <= data["life_revolutions"]["median"]
    assert (tmp_path / "life" / "life.png").exists()


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
