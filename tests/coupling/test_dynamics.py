"""Dynamics solved again on the worn joint: the schedule, the wear signature of a load
cycle, and the coupled runs against the uncoupled."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.coupling import DynamicsSchedule, load_change, wear_signature
from jointwear.errors import WearFeedbackWarning
from jointwear.mechanism import LoadCycle
from jointwear.results.summary import WALL_CLOCK_KEYS
from tests.coupling.conftest import summary


def test_wear_signature_sees_where_the_load_wears() -> None:
    steps = 360
    cycle = LoadCycle.from_arrays(
        np.full(steps, 100.0), np.full(steps, 0.3), np.full(steps, 0.01), period=1.0
    )
    signature = wear_signature(cycle)
    assert signature.sum() == pytest.approx(100.0 * 0.01 * steps)
    assert np.argmax(signature) == round(0.3 / (2 * np.pi) * 72)
    turned = LoadCycle.from_arrays(cycle.load, cycle.azimuth + 0.5, cycle.relative_rotation)
    assert load_change(cycle, cycle) == 0.0
    # the load now wears elsewhere: no overlap, so the change is the hypotenuse of both norms
    before, after = np.linalg.norm(signature), np.linalg.norm(wear_signature(turned))
    assert load_change(cycle, turned) == pytest.approx(math.hypot(before, after) / before)
    assert load_change(cycle, cycle.with_load(1.1 * cycle.load)) == pytest.approx(0.1)


def test_adaptive_schedule_aims_at_the_tolerance() -> None:
    schedule = DynamicsSchedule("adaptive", 0.02)
    assert schedule.first_threshold(5e-5) == pytest.approx(1e-6)
    # the load moved 1 % over 10 um of wear: 0.9 x 2 % needs 18 um, capped at 4 x
    assert schedule.next_threshold(1e-5, 0.01, 6e-5) == pytest.approx(1.8e-5)
    assert schedule.next_threshold(1e-5, 1e-6, 6e-5) == pytest.approx(4e-5)
    # scatter without wear does not drive the interval below tolerance x clearance
    assert schedule.next_threshold(1e-7, 0.5, 1e-4) == pytest.approx(2e-6)
    assert DynamicsSchedule(3, 0.02).due(3, 0.0, 1.0)
    assert not DynamicsSchedule("once", 0.02).due(10**6, 1.0, 0.0)


def test_once_is_todays_result(small: Config) -> None:
    config = small.replace(
        {
            "simulation.update_contour": True,
            "simulation.revolutions": 500,
            "simulation.update_every": 50,
        }
    )
    default = Simulation(config).run().summary()
    once = Simulation(config.replace({"simulation.dynamics_update": "once"})).run().summary()
    assert once == {**default, **{key: once[key] for key in WALL_CLOCK_KEYS}}
    assert default["dynamics_updates"] == 0


def test_paper_joint_coupling_changes_little(paper_config: Config) -> None:
    """Pulling spring, continuous contact: the worn joint's load hardly moves (0.12 % at 1e5 r)."""
    config = paper_config.replace(
        {
            "contact.model": "nlcp",
            "simulation.update_contour": True,
            "simulation.update_every": "adaptive",
            "simulation.revolutions": 100000,
        }
    )
    once = summary(config)
    coupled = summary(config.replace({"simulation.dynamics_update": "adaptive"}))
    assert coupled["dynamics_updates"] >= 2
    assert coupled["peak_wear_depth_m"] == pytest.approx(once["peak_wear_depth_m"], rel=5e-3)
    assert coupled["wear_mass_kg"] == pytest.approx(once["wear_mass_kg"], rel=5e-3)
    assert coupled["peak_wear_depth_m"] != once["peak_wear_depth_m"]


def test_separating_joint_impacts_appear_as_it_wears(paper_config: Config) -> None:
    """Push spring, 1 N preload, 240 rpm, light rod: continuous contact on the new joint,
    impacts once the clearance has grown; the coupled wear differs from the uncoupled."""
    config = paper_config.replace(
        {
            "mechanism.spring_mode": "push",
            "mechanism.spring_preload": 1.0,
            "mechanism.crank_speed": "240 rpm",
            "mechanism.rod_mass": 0.3,
            "dynamics.model": "contact-impact",
            "simulation.steps_per_revolution": 90,
            "contact.nodes": 120,
            "materials.bushing.wear_coefficient": 5e-11,
            "simulation.revolutions": 200,
            "simulation.update_contour": True,
            "simulation.update_every": 25,
        }
    )
    once = Simulation(config).run()
    with pytest.warns(WearFeedbackWarning, match="separates"):
        coupled = Simulation(config.replace({"simulation.dynamics_update": 2})).run()
    impacts = coupled.dataset["dynamics_impacts"].values
    clearance = coupled.dataset["dynamics_max_clearance"].values
    assert impacts[0] == 0  # the unworn joint stays in contact
    assert np.all(np.diff(clearance) > 0)
    assert impacts[-1] > 0
    assert impacts.max() >= 3
    a, b = once.summary(), coupled.summary()
    assert b["dynamics_updates"] == 3
    assert abs(b["wear_mass_kg"] / a["wear_mass_kg"] - 1) > 1e-3


def test_a_given_load_cycle_is_never_resolved(small: Config) -> None:
    cycle = Simulation(small).load_cycle
    config = small.replace(
        {
            "simulation.dynamics_update": 1,
            "simulation.update_contour": True,
            "simulation.revolutions": 5,
        }
    )
    result = Simulation(config, load_cycle=cycle).run().summary()
    assert result["dynamics_updates"] == 0
