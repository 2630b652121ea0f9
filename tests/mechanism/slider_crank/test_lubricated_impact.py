"""The lubricated slider-crank: the oil film's force in the contact-impact dynamics.

* a viscous film keeps the pin off the wall of the separating case (push spring, light
  rod, 0.2 mm clearance, 240 rpm), which runs dry with impacts, and the largest joint
  force falls below the dry one (Flores et al., Nonlinear Dyn. 56 (2009): the film
  cushions the impacts);
* as the viscosity goes to zero the load cycle goes to the dry one (and a film of zero
  viscosity gives the dry bits);
* the compiled right-hand side with a film equals the Python one.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.mechanism import ContactImpactSolution
from jointwear.mechanism.impact.film import FilmParameters
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.slider_crank.contact_impact import (
    SliderCrankContactSystem,
    impact_kernel,
    slider_crank_contact,
    solve_contact_impact,
)
from jointwear.mechanism.slider_crank.dynamics import SliderCrank
from jointwear.mechanism.stage import mechanism_inputs

from .test_contact_impact import SEPARATING, impact_config
from .test_contact_impact_kernel import assert_relative, random_states

pytestmark = pytest.mark.skipif(
    impact_kernel() is None, reason="numba missing or JOINTWEAR_NO_NUMBA set"
)


def solve(config: Config, film: FilmParameters | None, **options) -> ContactImpactSolution:
    inputs = replace(mechanism_inputs(config), film=film)
    return solve_contact_impact(inputs, compare=False, compiled=True, **options)


@pytest.fixture(scope="module")
def separating_dry(paper_config: Config) -> ContactImpactSolution:
    return solve(impact_config(paper_config, **SEPARATING), None)


@pytest.mark.parametrize("model", ["short-bearing", "long-bearing"])
def test_viscous_film_keeps_the_pin_off_the_wall(
    paper_config: Config, separating_dry: ContactImpactSolution, model: str
) -> None:
    dry = separating_dry
    assert dry.impacts >= 2  # dry, the pin flies and hits the wall
    config = impact_config(paper_config, **SEPARATING)
    lubricated = solve(config, FilmParameters(model, 1.0))
    clearance = config.joint.clearance
    summary = lubricated.summary()
    # observed: no impact, max |e|/c = 0.86 (short) and 0.99 (long), peak 214 N vs 493 N dry
    assert lubricated.impacts == 0
    assert lubricated.free_flight_fraction == 1.0
    assert lubricated.max_offset < clearance
    assert summary["max_eccentricity_ratio"] < 1.0
    assert summary["min_film_thickness_m"] > 0.0
    assert summary["film_model"] == model
    assert np.all(lubricated.load.load == 0.0)  # no solid contact to wear
    assert lubricated.peak_joint_force < 0.6 * dry.peak_joint_force
    assert dry.peak_joint_force == pytest.approx(dry.peak_load, rel=1e-12)  # mu = 0


def test_vanishing_viscosity_gives_the_dry_load(paper_config: Config) -> None:
    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 1})
    dry = solve(config, None).load
    zero = solve(config, FilmParameters("short-bearing", 0.0)).load
    np.testing.assert_array_equal(zero.load, dry.load)
    deviations = []
    for viscosity in (1e-4, 1e-6, 1e-8):
        load = solve(config, FilmParameters("short-bearing", viscosity)).load
        deviations.append(np.abs(load.load - dry.load).max() / dry.load.max())
    # observed: 7.8e-2, 7.9e-4, 8.5e-6: linear in the viscosity
    assert deviations[0] > deviations[1] > deviations[2]
    assert deviations[2] < 3e-5


@pytest.mark.parametrize("model", ["short-bearing", "long-bearing"])
def test_compiled_film_equals_python(paper_config: Config, model: str) -> None:
    config = impact_config(paper_config)
    inputs = replace(mechanism_inputs(config), film=FilmParameters(model, 0.05, roughness=1e-6))
    contact = slider_crank_contact(inputs, ContactImpactSettings.from_config(config.dynamics))
    mechanism, omega = SliderCrank.from_config(config.mechanism), config.mechanism.crank_speed
    fast = SliderCrankContactSystem(mechanism, omega, contact, compiled=True)
    reference = SliderCrankContactSystem(mechanism, omega, contact, compiled=False)
    times, states, velocities = random_states(reference, 300, seed=3)
    inside = 0
    for t, y, v in zip(times, states, velocities, strict=True):
        assert_relative(fast.rhs(t, y, v), reference.rhs(t, y, v), rtol=1e-11)
        a, b = fast.evaluate(t, y, v), reference.evaluate(t, y, v)
        assert_relative([a[k] for k in a], [b[k] for k in a], rtol=1e-11)
        inside += b["penetration"] < 0 and abs(b["force_x"]) > 0
    assert inside > 50  # the film acts in free flight
