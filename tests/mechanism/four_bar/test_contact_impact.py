"""Contact-impact dynamics of the four-bar: the pin free in one joint.

With a small clearance the load approaches the ideal-joint load; with elastic,
frictionless contact the energy changes by exactly the work of the crank and rocker
torques.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from jointwear.config import load_config
from jointwear.mechanism.four_bar.contact_impact import (
    FourBarContactSystem,
    four_bar_contact,
    four_bar_contact_impact,
)
from jointwear.mechanism.four_bar.dynamics import FourBar
from jointwear.mechanism.four_bar.massless_link import massless_link_cycles
from jointwear.mechanism.impact.film import joint_film_force
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.stage import load_cycles, mechanism_inputs

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "four_bar.toml"


# ------------------------------------------------------------------ load cycles


@pytest.fixture(scope="module")
def example():
    return load_config(EXAMPLE)


# ------------------------------------------------------------------ contact-impact


def impact_config(example, joint: str, body: str, **overrides: object):
    return example.replace(
        {
            "mechanism.clearance_joint": joint,
            "mechanism.bushing_body": body,
            "dynamics.model": "contact-impact",
            "dynamics.revolutions_settle": 1,
            "simulation.steps_per_revolution": 90,
            "joint.clearance": "0.01 mm",
            **overrides,
        }
    )


@pytest.mark.parametrize(
    ("joint", "body"),
    [("crank-coupler", "crank"), ("coupler-rocker", "rocker"), ("rocker-ground", "ground")],
)
def test_small_clearance_contact_impact_approaches_the_ideal_joint_load(
    example, joint, body
) -> None:
    config = impact_config(example, joint, body)
    cycle = load_cycles(config)[joint]
    ideal = massless_link_cycles(mechanism_inputs(config))[joint]
    assert cycle.model == "contact-impact"
    assert cycle.extras["impacts"] == 0
    assert cycle.extras["free_flight_fraction"] == 0.0
    diff = np.hypot(cycle.force_x - ideal.force_x, cycle.force_y - ideal.force_y)
    # observed 0.012-0.019 % of the peak (the residue: O(c/l) geometry, damping)
    assert diff.max() < 1e-3 * ideal.load.max()
    assert cycle.extras["load_difference_max_n"] == pytest.approx(diff.max(), rel=1e-9)
    np.testing.assert_allclose(cycle.relative_rotation, ideal.relative_rotation, atol=1e-4)
    assert cycle.relative_rotation.sum() == pytest.approx(ideal.relative_rotation.sum(), abs=1e-6)


def test_several_joints_each_free_with_the_others_ideal(example) -> None:
    """Several clearance joints: each joint's pin is freed in turn, the other joints ideal,
    so each joint's cycle is that of the same linkage with that joint alone."""
    fast = {
        "dynamics.model": "contact-impact",
        "dynamics.revolutions_settle": 0,
        "simulation.steps_per_revolution": 30,
    }
    together = load_cycles(example.replace(fast))
    assert list(together) == ["crank-coupler", "coupler-rocker", "rocker-ground"]
    alone = load_cycles(
        example.replace(
            {
                **fast,
                "mechanism.clearance_joint": "rocker-ground",
                "mechanism.bushing_body": "ground",
            }
        )
    )["rocker-ground"]
    np.testing.assert_array_equal(together["rocker-ground"].load, alone.load)
    np.testing.assert_array_equal(together["rocker-ground"].azimuth, alone.azimuth)


@pytest.mark.parametrize("joint", ["crank-coupler", "rocker-ground"])
def test_energy_balance_of_the_free_pin(example, joint: str) -> None:
    # elastic, frictionless contact (c_e = 1, mu = 0) with impacts: the energy changes
    # by exactly the work of the crank torque and the rocker torque
    config = impact_config(
        example,
        joint,
        "coupler" if joint == "crank-coupler" else "rocker",
        **{
            "dynamics.restitution": 1.0,
            "joint.clearance": "0.2 mm",
            "mechanism.crank_speed": "600 rpm",
            "mechanism.rocker_torque": 0.0,
            "mechanism.rocker_spring_stiffness": 0.0,
            "materials.bushing.youngs_modulus": "2 GPa",
        },
    )
    solution = four_bar_contact_impact(mechanism_inputs(config), compare=False)
    system = solution.system
    assert isinstance(system, FourBarContactSystem)
    history = solution.history
    duration = history.end_time
    times = np.linspace(0.0, duration, 801)
    states, _ = history.state(times)
    energy = np.array([system.energy(t, y) for t, y in zip(times, states, strict=True)])
    residue = energy - energy[0] - (states[:, 4] - states[0, 4])
    assert len(history.impact_times) >= 3
    work = np.abs(states[:, 4]).max()
    assert work > 0.05
    assert np.abs(residue).max() < 1e-5 * work


def test_an_oiled_joint_adds_the_film_force_of_both_bodies_spins(example) -> None:
    # crank-coupler: the film's wedge turns with omega_crank + omega_coupler
    joint = "crank-coupler"
    oil = {"lubrication.model": "short-bearing", "lubrication.viscosity": "0.1 Pa*s"}
    systems = []
    for overrides in ({}, oil):
        inputs = mechanism_inputs(
            impact_config(example, joint, "coupler", **{"joint.clearance": "0.2 mm", **overrides})
        )
        settings = ContactImpactSettings.from_config(inputs.dynamics)
        contact = four_bar_contact(inputs, settings, joint, "coupler")
        linkage = FourBar.from_config(inputs.mechanism)
        systems.append(FourBarContactSystem(linkage, inputs.mechanism.crank_speed, contact, joint))
    dry, oiled = systems
    assert dry.contact.film is None
    assert oiled.contact.film is not None
    # the pin on the wall at the start, its rates disturbed so that it moves across
    t, y = 0.0, dry.initial_state(np.array([10.0, 5.0])) + np.array([0, 0, 0.5, -0.3, 0])
    here = oiled.evaluate(t, y, 1e-3)
    step = 1e-7
    rates = np.array([0.0, 0.0, 0.0, 0.0, 0.0])
    rates[:2] = y[2:4]
    ahead = oiled.evaluate(t + step, y + step * rates, 1e-3)
    behind = oiled.evaluate(t - step, y - step * rates, 1e-3)
    vx = (ahead["ex"] - behind["ex"]) / (2 * step)
    vy = (ahead["ey"] - behind["ey"]) / (2 * step)
    spin = oiled.omega + y[2]
    film = joint_film_force(here["ex"], here["ey"], vx, vy, spin, *oiled.contact.film_arguments)
    without = dry.evaluate(t, y, 1e-3)
    assert math.hypot(*film) > 1.0
    assert here["force_x"] - without["force_x"] == pytest.approx(film[0], rel=1e-5)
    assert here["force_y"] - without["force_y"] == pytest.approx(film[1], rel=1e-5)
