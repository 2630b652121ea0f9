"""Adaptive contour updating (cycle jumping with error control) against per-revolution updating.

Per-revolution updating is the paper's scheme (explicit Euler with a step of one
revolution). The adaptive scheme jumps many revolutions with a trapezoid
predictor-corrector and controls the jump by an error estimate; its peak, mass and
profile must stay within ``simulation.adaptive_tolerance`` of per-revolution updating.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config, load_config
from jointwear.coupling.jumping import adaptive_interval, jump_error
from tests.conftest import REPO
from tests.contact.test_sliced import swing

PAPER = REPO / "examples" / "paper" / "table5_nlcp_15000r.toml"
CALIBRATED = {
    "joint.axial_length": 0.01867,
    "joint.bushing_thickness": 0.003653,
    "mechanism.spring_preload": 121.8,
}


def paper_case(revolutions: int, **overrides) -> Config:
    return load_config(
        PAPER, overrides={**CALIBRATED, "simulation.revolutions": revolutions, **overrides}
    )


def compare(adaptive, per_revolution) -> dict[str, float]:
    """Relative differences of the final peak, mass and profile (L2)."""
    a, p = adaptive.summary(), per_revolution.summary()
    depth_a, depth_p = adaptive.wear_depth, per_revolution.wear_depth
    return {
        "peak": abs(a["peak_wear_depth_m"] / p["peak_wear_depth_m"] - 1),
        "mass": abs(a["wear_mass_kg"] / p["wear_mass_kg"] - 1),
        "profile": float(np.linalg.norm(depth_a - depth_p) / np.linalg.norm(depth_p)),
    }


@pytest.fixture(scope="module")
def runs_2000():
    """The paper's case over 2000 revolutions: adaptive and per-revolution updating."""
    config = paper_case(2000)
    adaptive = Simulation(config).run()
    per_revolution = Simulation(config.replace({"simulation.update_every": 1})).run()
    return config, adaptive, per_revolution


def test_adaptive_matches_per_revolution_updating(runs_2000):
    config, adaptive, per_revolution = runs_2000
    tolerance = config.simulation.adaptive_tolerance
    differences = compare(adaptive, per_revolution)
    assert differences["peak"] <= tolerance
    assert differences["mass"] <= tolerance
    assert differences["profile"] <= tolerance
    assert max(differences.values()) <= 5e-3  # the 0.5 % target, with room
    # ... with a few dozen contour updates instead of 2000
    assert adaptive.summary()["contour_updates"] <= 40
    assert per_revolution.summary()["contour_updates"] == 2000


def test_saved_profiles_are_at_their_revolutions(runs_2000):
    """Profiles inside a jump come from the corrector's dense output, at the exact revolution."""
    config, adaptive, per_revolution = runs_2000
    revolutions = adaptive.dataset["revolution"].values
    np.testing.assert_array_equal(revolutions, per_revolution.dataset["revolution"].values)
    assert revolutions.size == config.simulation.saved_profiles
    tolerance = config.simulation.adaptive_tolerance
    for revolution in revolutions:
        a = adaptive.dataset["wear_depth"].sel(revolution=revolution).values
        p = per_revolution.dataset["wear_depth"].sel(revolution=revolution).values
        assert np.linalg.norm(a - p) <= tolerance * np.linalg.norm(p)
        assert abs(a.max() / p.max() - 1) <= tolerance


def test_a_tighter_tolerance_takes_more_updates_and_gets_closer(runs_2000):
    config, adaptive, per_revolution = runs_2000
    tight = Simulation(config.replace({"simulation.adaptive_tolerance": 2e-4})).run()
    assert tight.summary()["contour_updates"] > adaptive.summary()["contour_updates"]
    assert compare(tight, per_revolution)["profile"] <= 2e-4


def test_rejected_jumps_are_retried_shorter():
    """A jump whose error estimate exceeds the tolerance is rejected and retried shorter."""
    config = paper_case(400, **{"simulation.adaptive_tolerance": 1e-4})
    simulation = Simulation(config)
    state = simulation.initial_state()
    state = simulation.step(state)
    # propose a jump far too long for the tolerance
    state = replace(state, next_interval=300)
    new = simulation.step(state)
    assert new.interval < 300
    assert new.revolution == state.revolution + new.interval


def test_adaptive_state_survives_a_checkpoint_round_trip(tmp_path):
    """Resuming an adaptive run from a saved state gives the uninterrupted result."""
    from jointwear.checkpoint import read_state, write_state

    config = paper_case(600)
    simulation = Simulation(config)
    state = simulation.initial_state()
    for _ in range(5):
        state = simulation.step(state)
    write_state(tmp_path / "state.npz", state, "digest")
    resumed, _ = read_state(tmp_path / "state.npz")
    assert resumed.next_interval == state.next_interval
    np.testing.assert_array_equal(resumed.warm_slope, state.warm_slope)
    a = Simulation(config).run(state=resumed)
    b = Simulation(config).run()
    np.testing.assert_allclose(a.wear_depth, b.wear_depth, rtol=1e-12, atol=1e-18)


# ---------------------------------------------------------------- the controller


def test_adaptive_interval_step_size_control():
    # error at the tolerance: keep (safety factor 0.9)
    assert adaptive_interval(1e-3, 100, 1e-3) == 90
    # Euler's error grows as interval^2: a quarter of the error allows double the jump
    assert adaptive_interval(0.25e-3 * 0.81, 100, 1e-3) == 200
    # growth and shrink are limited
    assert adaptive_interval(0.0, 10, 1e-3) == 40
    assert adaptive_interval(1e-12, 10, 1e-3) == 40
    assert adaptive_interval(1.0, 100, 1e-3) == 20
    assert adaptive_interval(1.0, 3, 1e-3) == 1


def test_jump_error_is_the_euler_trapezoid_difference():
    nodes = 360
    theta = 2 * np.pi * np.arange(nodes) / nodes
    shape = np.exp(-((np.angle(np.exp(1j * (theta - 3.0))) / 0.6) ** 2))
    depth = 20e-6 * shape
    rate = 1e-8 * shape
    # a rate that does not change: Euler is exact
    assert jump_error(depth, rate, rate, 500, 7.5e-3) == 0.0
    # the estimate grows as interval^2 for a steadily changing rate
    slope = -1e-12 * shape  # change of the rate per revolution
    errors = [jump_error(depth, rate, rate + n * slope, n, 7.5e-3) for n in (100, 200)]
    assert errors[1] / errors[0] == pytest.approx(4.0, rel=0.15)
    # the largest of peak, profile (L2) and mass measures of d = n (w1 - w0) / 2
    n, radius = 100, 7.5e-3
    d = 0.5 * n * n * slope
    after = depth + 0.5 * n * (2 * rate + n * slope)
    measures = (
        np.abs(d).max() / after.max(),
        np.linalg.norm(d) / np.linalg.norm(after),
        abs(np.sum((radius + after) * d)) / np.sum((radius + 0.5 * after) * after),
    )
    assert errors[0] == pytest.approx(max(measures), rel=1e-9, abs=0)
    assert math.isfinite(jump_error(np.zeros(nodes), np.zeros(nodes), np.zeros(nodes), 1, 7.5e-3))


# ---------------------------------------------------------------- the paper's 15000 revolutions


@pytest.mark.slow
def test_paper_15000_revolutions_adaptive_matches_per_revolution():
    """Table 5: 15000 revolutions, adaptive vs updating every revolution (~30 s)."""
    config = paper_case(15000)
    adaptive = Simulation(config).run()
    per_revolution = Simulation(config.replace({"simulation.update_every": 1})).run()
    differences = compare(adaptive, per_revolution)
    tolerance = config.simulation.adaptive_tolerance
    assert differences["peak"] <= tolerance
    assert differences["mass"] <= tolerance
    assert differences["profile"] <= tolerance
    assert adaptive.summary()["contour_updates"] <= 80


def test_adaptive_wear_through_stops_at_the_wall():
    """Jumps shrink before the wall; the run stops where the wear reaches it, inside a
    revolution."""
    config = paper_case(200000, **{"joint.bushing_thickness": 6e-5, "simulation.saved_profiles": 4})
    simulation = Simulation(config)
    states = [simulation.initial_state()]
    while states[-1].stopped_by is None:
        states.append(simulation.step(states[-1]))
    last = states[-1]
    assert last.stopped_by == "wall_thickness"
    assert last.wear_depth.max() == pytest.approx(6e-5, rel=1e-12, abs=0)
    assert last.wear_depth.max() <= 6e-5
    assert states[-2].wear_depth.max() < 6e-5
    assert states[-2].revolution < last.revolution
    assert not float(last.revolution).is_integer()
    assert last.revolution < 200000


def wearing_pin_on_slices(update_every) -> Config:
    """A pin wearing (``K_p = 2e-13``) as it swings ±25° under 200 N fixed in the bushing,
    on 3 slices misaligned by 2e-4 rad: 800 revolutions, 8 steps, 72 nodes."""
    return swing(
        **{
            "simulation.revolutions": 800,
            "simulation.update_every": update_every,
            "joint.axial_slices": 3,
            "joint.misalignment": 2e-4,
            "materials.pin.wear_coefficient": 2e-13,
        }
    )


@pytest.mark.filterwarnings("ignore:joint.axial_slices:jointwear.errors.ContactModelWarning")
def test_adaptive_jumps_carry_a_wearing_pin_as_per_revolution_updating():
    """The pin's wear map jumps with the bushing's (predicted, corrected, its error
    controlled): both surfaces within the tolerance of per-revolution updating."""
    adaptive = Simulation(wearing_pin_on_slices("adaptive")).run()
    per_revolution = Simulation(wearing_pin_on_slices(1)).run()
    tolerance = adaptive.config.simulation.adaptive_tolerance
    a, p = adaptive.summary(), per_revolution.summary()
    for key in ("peak_wear_depth_m", "wear_volume_m3", "pin_peak_wear_depth_m"):
        assert a[key] == pytest.approx(p[key], rel=tolerance), key
    assert a["pin_wear_volume_m3"] == pytest.approx(p["pin_wear_volume_m3"], rel=tolerance, abs=0)
    pin_a, pin_p = (r.dataset["pin_wear_depth"].values for r in (adaptive, per_revolution))
    for maps in ((adaptive.wear_depth, per_revolution.wear_depth), (pin_a, pin_p)):
        assert np.linalg.norm(maps[0] - maps[1]) <= tolerance * np.linalg.norm(maps[1])
    # the pin wore over a fifth of the bushing's depth, and the jumps were few
    assert p["pin_peak_wear_depth_m"] > 0.2 * p["peak_wear_depth_m"]
    assert a["contour_updates"] <= 60 < p["contour_updates"]
