"""Reliability of right-censored lives: B-lives, the Weibull fit, the limits' probabilities."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import CensoredData, ecdf

from jointwear.workflows.reliability import (
    b_life,
    headline,
    limit_probabilities,
    reliability_summary,
    weibull_fit,
)

SHAPE, SCALE = 2.5, 1.0e5


def weibull_lives(n: int, horizon: float, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Weibull(SHAPE, SCALE) lives, each case run to ``horizon`` at most."""
    lives = SCALE * np.random.default_rng(seed).weibull(SHAPE, n)
    censored = lives > horizon
    return np.where(censored, horizon, lives), censored


def closed_b(p: float) -> float:
    """B-life of the Weibull distribution: eta (-ln(1 - p))^(1 / beta)."""
    return SCALE * (-math.log1p(-p)) ** (1 / SHAPE)


def test_heavily_censored_weibull_lives_give_the_closed_form_b_lives() -> None:
    """Runs stopped at the 30 % life (about 70 % of the cases censored): the Kaplan-Meier
    B10 and the Weibull fit's B10 and B50 (extrapolated beyond every run) bracket the
    closed form within their 95 % bounds; the Kaplan-Meier B50 is only a lower bound.
    Dropping the censored cases would put B10 near the 3 % life, outside the bounds."""
    horizon = closed_b(0.3)
    lives, censored = weibull_lives(400, horizon, seed=12)
    assert 0.6 < censored.mean() < 0.8
    km = b_life(lives, censored, 0.1)
    assert km["lower_bound"] is False
    assert km["lower"] <= closed_b(0.1) <= km["upper"]
    assert b_life(lives, censored, 0.5) == {
        "value": horizon, "lower_bound": True, "lower": horizon, "upper": None
    }  # fmt: skip
    fit = weibull_fit(lives, censored)
    assert fit is not None
    assert (fit["reached"], fit["censored"]) == ((~censored).sum(), censored.sum())
    assert fit["shape"]["lower"] <= SHAPE <= fit["shape"]["upper"]
    assert fit["scale_revolutions"]["lower"] <= SCALE <= fit["scale_revolutions"]["upper"]
    for p in (0.1, 0.5):
        bounds = fit["b_lives"][p]
        assert bounds["lower"] <= closed_b(p) <= bounds["upper"]
    dropped = weibull_fit(lives[~censored], censored[~censored])
    assert not dropped["b_lives"][0.1]["lower"] <= closed_b(0.1) <= dropped["b_lives"][0.1]["upper"]


def test_b10_bounds_cover_the_closed_form_in_most_samples() -> None:
    """The 95 % bounds of B10 from 60 lives (40 % censored) cover the closed form in 85 to
    100 of 100 independent samples, for the Kaplan-Meier band inverted at p = 0.1 and
    for the Weibull fit's Fisher bounds alike (measured: 98 and 96)."""
    covered = {"kaplan-meier": 0, "weibull": 0}
    for seed in range(100):
        lives, censored = weibull_lives(60, closed_b(0.6), seed)
        entry = b_life(lives, censored, 0.1)
        covered["kaplan-meier"] += entry["lower"] <= closed_b(0.1) <= (entry["upper"] or math.inf)
        fit = weibull_fit(lives, censored)["b_lives"][0.1]
        covered["weibull"] += fit["lower"] <= closed_b(0.1) <= fit["upper"]
    assert all(85 <= n <= 100 for n in covered.values()), covered


def test_limit_probabilities_share_the_kaplan_meier_probability() -> None:
    """Cases censored at scattered times: the limits' cumulative incidences add up to the
    Kaplan-Meier probability of reaching any limit by N, and with one limit equal it;
    without censoring each is the plain fraction of cases that limit ended by N."""
    rng = np.random.default_rng(3)
    lives = rng.exponential(1000.0, 300).round()
    stop = rng.uniform(200.0, 3000.0, 300).round()
    censored = stop < lives
    lives = np.minimum(lives, stop)
    limits = np.where(rng.random(300) < 0.3, "peak_wear_depth", "min_wall_thickness")
    by = 900.0
    estimate = ecdf(CensoredData(uncensored=lives[~censored], right=lives[censored])).cdf
    shares = limit_probabilities(lives, censored, limits, by)
    assert shares["any"] == pytest.approx(estimate.evaluate(by), rel=1e-12, abs=0)
    assert shares["peak_wear_depth"] + shares["min_wall_thickness"] == pytest.approx(
        shares["any"], rel=1e-12, abs=0
    )
    one = limit_probabilities(lives, censored, ["peak_wear_depth"] * 300, by)
    assert one["peak_wear_depth"] == pytest.approx(one["any"], rel=1e-12, abs=0)
    plain = limit_probabilities(lives, np.zeros(300, dtype=bool), limits, by)
    assert plain["peak_wear_depth"] == pytest.approx(
        np.mean((lives <= by) & (limits == "peak_wear_depth")), rel=1e-12, abs=0
    )


def test_too_few_lives_reached_give_no_fit_and_lower_bounds() -> None:
    lives = np.array([500.0, 800.0, 800.0, 800.0])
    censored = np.array([False, True, True, True])
    summary = reliability_summary(lives, censored, ["peak_wear_depth", "", "", ""], 800.0)
    assert summary["weibull"] is None
    assert summary["b10"]["weibull"] is None
    assert summary["b10"]["value"] == 500.0  # F jumps to 0.25 at the one life reached
    assert summary["b50"]["lower_bound"] is True
    assert headline(summary) == {
        "b10_revolutions": 500.0,
        "b50_revolutions": 800.0,
        "weibull_shape": None,
        "weibull_scale_revolutions": None,
    }
    assert summary["reach_probability"]["limits"] == {"peak_wear_depth": 0.25, "any": 0.25}
