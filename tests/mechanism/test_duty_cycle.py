"""Duty cycles: several operating modes, the wear per cycle their share-weighted sum."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import config_from_dict
from jointwear.errors import ConfigError
from jointwear.mechanism.stage import load_cycle

DIGGING = {
    "type": "oscillating",
    "load": "3 kN",
    "load_angle": "-90 deg",
    "amplitude": "25 deg",
    "frequency": "0.5 Hz",
}
CRANK = {"type": "slider-crank", "crank_speed": "90 rpm"}  # the rest: the parameter set's
UPDATING = {
    "steps_per_revolution": 48,
    "revolutions": 400,
    "update_every": 40,
    "update_contour": True,
}
COMMON = {
    "contact": {"model": "asymmetric-winkler", "nodes": 120},
    "simulation": {"steps_per_revolution": 48, "revolutions": 1000, "update_contour": False},
    "materials": {"pin": {"wear_coefficient": 2e-14}},
}


def config(mechanism: dict, **sections):
    return config_from_dict({**COMMON, "mechanism": mechanism, **sections})


def duty(shares=(0.3, 0.7), modes=(DIGGING, CRANK)) -> dict:
    return {
        "type": "duty-cycle",
        "modes": [{**mode, "share": share} for mode, share in zip(modes, shares, strict=True)],
    }


def test_without_update_the_wear_is_the_share_weighted_sum() -> None:
    """Σ share_i w_i per cycle, bushing and pin, against separate single-mode runs."""
    shares = (0.3, 0.7)
    mixed = Simulation(config(duty(shares))).run(pressures=False)
    singles = [Simulation(config(mode)).run(pressures=False) for mode in (DIGGING, CRANK)]
    # (the bushing's saved profiles: the last; the pin's final profile)
    for name, final in (("wear_depth", -1), ("pin_wear_depth", ...)):
        expected = sum(
            s * r.dataset[name].values[final] for s, r in zip(shares, singles, strict=True)
        )
        got = mixed.dataset[name].values[final]
        assert got.shape == (120,)
        assert np.max(np.abs(got - expected)) <= 1e-9 * np.max(np.abs(expected))
    expected = sum(
        s * r.dataset["wear_depth"].values[-1] for s, r in zip(shares, singles, strict=True)
    )
    # the two modes wear different places: neither alone is the answer
    assert np.max(np.abs(singles[0].dataset["wear_depth"].values[-1] - expected)) > 0.1 * np.max(
        expected
    )


def test_a_mode_with_all_the_cycles_is_that_mode() -> None:
    """One mode of share one is the single mechanism, with the contour updated (bit for bit)."""
    update = {**UPDATING}
    alone = Simulation(config(DIGGING, simulation=update)).run(pressures=False)
    mixed = Simulation(config(duty((1.0,), (DIGGING,)), simulation=update)).run(pressures=False)
    np.testing.assert_array_equal(
        mixed.dataset["wear_depth"].values[-1], alone.dataset["wear_depth"].values[-1]
    )


def test_two_halves_of_one_mode_wear_as_that_mode_with_updates() -> None:
    """The same mode twice at 0.5 each: the contour update follows the one mode's run."""
    update = {**UPDATING}
    alone = Simulation(config(DIGGING, simulation=update)).run(pressures=False)
    halves = Simulation(config(duty((0.5, 0.5), (DIGGING, DIGGING)), simulation=update)).run(
        pressures=False
    )
    np.testing.assert_allclose(
        halves.dataset["wear_depth"].values[-1],
        alone.dataset["wear_depth"].values[-1],
        rtol=0,
        atol=1e-6 * float(alone.dataset["wear_depth"].values[-1].max()),
    )


def test_the_cycle_keeps_every_mode_and_its_share() -> None:
    cycle = load_cycle(config(duty()))
    osc, crank = load_cycle(config(DIGGING)), load_cycle(config(CRANK))
    assert cycle.steps == osc.steps + crank.steps
    assert cycle.duty.starts == (0, osc.steps)
    assert cycle.period == pytest.approx(osc.period + crank.period)
    assert cycle.duty.mean_period == pytest.approx(0.3 * osc.period + 0.7 * crank.period)
    np.testing.assert_array_equal(cycle.load, np.concatenate([osc.load, crank.load]))
    mode = cycle.diagnostics["duty_mode"].values
    np.testing.assert_array_equal(mode[osc.steps - 1 : osc.steps + 1], [0, 1])
    assert cycle.total_relative_rotation == pytest.approx(
        0.3 * osc.total_relative_rotation + 0.7 * crank.total_relative_rotation, rel=1e-12
    )


def test_the_result_names_each_steps_mode_and_the_hours_use_the_mean_cycle() -> None:
    cfg = config(duty(), life={"peak_wear_depth": "1 um"})
    result = Simulation(cfg).run(pressures=False)
    mode = result.dataset["duty_mode"]
    assert mode.attrs["units"] == "1"
    assert "mode" in mode.attrs["long_name"]
    summary = result.summary()
    assert summary["stopped_by"] is not None
    period = load_cycle(cfg).duty.mean_period
    assert summary["life_hours"] == pytest.approx(summary["life_revolutions"] * period / 3600)


@pytest.mark.parametrize(
    ("shares", "message"),
    [
        ((0.3, 0.6), r"^mechanism\.modes\.share: the shares of the modes sum to 0\.9, not 1"),
        ((0.3, 0.7 + 2e-9), r"^mechanism\.modes\.share: .*within 1e-09"),
    ],
)
def test_shares_must_sum_to_one(shares, message) -> None:
    with pytest.raises(ConfigError, match=message):
        config(duty(shares))


def test_shares_within_the_tolerance_are_accepted() -> None:
    assert config(duty((0.3, 0.7 + 5e-10))).mechanism.modes[1].share > 0.7


def test_a_duty_cycle_inside_a_duty_cycle_is_refused() -> None:
    inner = {**duty(), "share": 0.5}
    with pytest.raises(ConfigError, match=r"^mechanism\.modes\[1\]\.type: .*not another duty"):
        config({"type": "duty-cycle", "modes": [{**DIGGING, "share": 0.5}, inner]})


def test_a_bad_key_in_a_mode_names_it() -> None:
    message = r"^mechanism\.modes\.0\.amplitud: unknown key; did you mean 'amplitude'"
    with pytest.raises(ConfigError, match=message):
        config(duty(modes=({**DIGGING, "amplitud": 1.0}, CRANK)))


def test_the_saved_config_reads_back_as_the_same_duty_cycle() -> None:
    """Every mode written out with its share, each read back as the same type."""
    cfg = config(duty())
    again = config_from_dict(tomllib.loads(cfg.to_toml()))
    assert again.to_dict() == cfg.to_dict()


def test_a_run_resumed_from_a_midway_state_ends_where_the_whole_run_does() -> None:
    """Checkpoints hold a duty cycle's state: resuming gives the uninterrupted run's wear."""
    cfg = config(duty(), simulation=UPDATING)
    states = []
    whole = Simulation(cfg).run(on_step=states.append, pressures=False)
    midway = states[len(states) // 2]
    resumed = Simulation(cfg).run(state=midway, pressures=False)
    np.testing.assert_array_equal(
        resumed.dataset["wear_depth"].values[-1], whole.dataset["wear_depth"].values[-1]
    )
    np.testing.assert_array_equal(
        resumed.dataset["pin_wear_depth"].values, whole.dataset["pin_wear_depth"].values
    )


def test_setting_one_modes_speed_changes_that_modes_cycle_only() -> None:
    """``mechanism.modes.1.crank_speed``: the crank's period follows, the swing is kept."""
    cfg = config(duty())
    faster = cfg.replace({"mechanism.modes.1.crank_speed": "180 rpm"})
    before, after = load_cycle(cfg), load_cycle(faster)
    swing = before.duty.starts[1]
    assert after.duty.starts == before.duty.starts
    np.testing.assert_array_equal(after.load[:swing], before.load[:swing])
    np.testing.assert_array_equal(after.azimuth[:swing], before.azimuth[:swing])
    swing_period = load_cycle(config(DIGGING)).period  # 2 s; the crank's: 60/90 s, then 1/3 s
    assert after.period - swing_period == pytest.approx(1 / 3, rel=1e-12, abs=0)
    assert before.period - swing_period == pytest.approx(2 / 3, rel=1e-12, abs=0)
    assert not np.allclose(after.load[swing:], before.load[swing:])
