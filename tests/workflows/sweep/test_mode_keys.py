"""Sweeps and life studies over a duty cycle's modes (``mechanism.modes.N.KEY``)."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import config_from_dict
from jointwear.errors import ConfigError
from jointwear.workflows.life import life_plan
from jointwear.workflows.sweep import expand_sweep, run_sweep

DIG = {"type": "oscillating", "load": "3 kN", "load_angle": "-90 deg", "amplitude": "25 deg"}
TRAVEL = {"type": "oscillating", "load": "0.8 kN", "load_angle": "60 deg", "amplitude": "40 deg"}
COMMON = {
    "contact": {"model": "asymmetric-winkler", "nodes": 120},
    "simulation": {"steps_per_revolution": 48, "revolutions": 1000, "update_contour": False},
}


def config(mechanism):
    return config_from_dict({**COMMON, "mechanism": mechanism})


@pytest.fixture(scope="module")
def base():
    modes = [
        {**DIG, "frequency": "0.5 Hz", "share": 0.3},
        {**TRAVEL, "frequency": "0.25 Hz", "share": 0.7},
    ]
    return config({"type": "duty-cycle", "modes": modes})


def test_a_sweep_over_the_shares_gives_the_share_weighted_wear(base, tmp_path) -> None:
    """Each case's peak wear is that of Σ share_i w_i over single-mode runs (no update)."""
    shares = [(0.2, 0.8), (0.6, 0.4)]
    spec = {
        "zip": {
            "mechanism.modes.0.share": [s[0] for s in shares],
            "mechanism.modes.1.share": [s[1] for s in shares],
        }
    }
    result = run_sweep(expand_sweep(spec, base), tmp_path / "out", workers=1)
    singles = [
        Simulation(config(mode.model_dump(mode="json", exclude={"share"})))
        .run(pressures=False)
        .dataset["wear_depth"]
        .values[-1]
        for mode in base.mechanism.modes
    ]
    peaks = [record["metrics"]["peak_wear_depth_m"] for record in result.records]
    for (a, b), peak in zip(shares, peaks, strict=True):
        assert peak == pytest.approx(np.max(a * singles[0] + b * singles[1]), rel=1e-9, abs=0)
    assert peaks[1] > 1.2 * peaks[0]  # the heavy mode's share counts


def test_a_mode_frequency_is_swept_with_units(base) -> None:
    plan = expand_sweep({"grid": {"mechanism.modes.1.frequency": ["15 rpm", "0.5 Hz"]}}, base)
    speeds = [plan.config(case).mechanism.modes[1].frequency for case in plan.cases]
    assert speeds == pytest.approx([0.25, 0.5], rel=1e-12, abs=0)
    assert all(plan.config(c).mechanism.modes[0] == base.mechanism.modes[0] for c in plan.cases)


def test_a_life_study_samples_a_modes_key(base) -> None:
    sample = {"mechanism.modes.0.load": {"distribution": "uniform", "low": "2 kN", "high": "4 kN"}}
    plan = life_plan(base, sample, cases=6, seed=3)
    loads = [plan.config(case).mechanism.modes[0].load for case in plan.cases]
    assert all(2000.0 <= load <= 4000.0 for load in loads)
    assert len(set(loads)) == 6


def test_a_key_of_a_mode_the_base_lacks_fails_before_any_case(base) -> None:
    spec = {"grid": {"mechanism.modes.2.share": [0.5]}}
    with pytest.raises(ConfigError, match=r"\[grid\] mechanism\.modes\.2\.share: no mode 2"):
        expand_sweep(spec, base)
