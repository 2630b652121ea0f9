"""The lubricated slider-crank integrated by ``Rodas4-compiled`` (RODAS4, switching).

* on the paper's joint with a short-bearing film (the pin on the wall, the squeeze film
  stiff) its contact force agrees with ``RK45-compiled``'s at a tight tolerance and
  converges to it as the tolerance tightens, with far fewer right-hand sides;
* on the separating case with a long-bearing film (an impact) the two give the same
  impacts and loads, and so does ``Radau-compiled`` (RADAU5);
* ``auto`` picks ``Radau-compiled`` for an oiled joint and reports it; a dry joint and a
  film of zero viscosity keep ``RK45-compiled``, bit for bit; an explicit choice runs what
  it names (a dry joint named ``Rodas4-compiled`` or ``Radau-compiled``: the dry load).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.mechanism.impact.film import FilmParameters
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.slider_crank import contact_impact as ci
from jointwear.mechanism.slider_crank.dynamics import SliderCrank
from jointwear.mechanism.stage import mechanism_inputs

from .test_contact_impact import SEPARATING, impact_config

pytestmark = pytest.mark.skipif(
    ci.impact_kernel() is None, reason="numba missing or JOINTWEAR_NO_NUMBA set"
)

SHORT = FilmParameters("short-bearing", 0.1)


def system_and_start(config: Config, film: FilmParameters):
    inputs = replace(mechanism_inputs(config), film=film)
    settings = ContactImpactSettings.from_config(inputs.dynamics)
    contact = ci.slider_crank_contact(inputs, settings)
    mechanism = SliderCrank.from_config(inputs.mechanism)
    system = ci.SliderCrankContactSystem(mechanism, inputs.mechanism.crank_speed, contact, True)
    y0, _ = ci.initial_state(system, 360)
    return system, settings, y0


def forces(system, method: str, rtol: float, span: float, samples, y0, settings):
    """The normal contact force (the load cycle's) as a vector at ``samples`` [N] and the
    right-hand sides spent."""
    history, states, segments = system.integrate_compiled(
        (0.0, span), y0, True, settings, span / 100, samples, (rtol, rtol * 1e-2),
        method=method,
    )  # fmt: skip
    records = [
        system.evaluate(t, y, history.segments[k].impact_velocity)
        for t, y, k in zip(samples, states, segments, strict=True)
    ]
    load = [[r["normal_force"] * r["normal_x"], r["normal_force"] * r["normal_y"]] for r in records]
    return np.array(load), history.evaluations


def test_agrees_with_the_explicit_pair_on_the_wall(paper_config: Config) -> None:
    # the start transient (the pin pressed in, the squeeze film's spike) and 0.1 s on the wall
    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 0})
    system, settings, y0 = system_and_start(config, SHORT)
    span = 0.1
    samples = np.linspace(0.0, span, 41)[1:]
    reference, explicit = forces(system, "RK45-compiled", 1e-10, span, samples, y0, settings)
    peak = np.abs(reference).max()
    deviations, evaluations = [], []
    for rtol in (1e-8, 1e-9):
        stiff, count = forces(system, "Rodas4-compiled", rtol, span, samples, y0, settings)
        deviations.append(np.abs(stiff - reference).max() / peak)
        evaluations.append(count)
    # observed: 9.8e-6 and 1.4e-7 of the peak (RK45-compiled at 1e-8: 3e-7, its steps held
    # by stability far below the tolerance's)
    assert deviations[0] < 5e-5
    assert deviations[1] < 1e-6
    assert deviations[1] < 0.1 * deviations[0]
    # observed: 2.8e4 against 4.2e5 right-hand sides
    assert evaluations[0] < explicit / 10


@pytest.mark.parametrize(
    ("name", "ran"), [("Rodas4-compiled", "Rodas4-compiled"), ("auto", "Radau-compiled")]
)
def test_the_separating_case_impacts_alike(paper_config: Config, name: str, ran: str) -> None:
    # the stiff integrators (RODAS4, auto's RADAU5) against the explicit pair
    film = FilmParameters("long-bearing", 0.1)
    runs = {}
    for method in (name, "RK45-compiled"):
        config = impact_config(paper_config, **SEPARATING, **{"dynamics.integrator": method})
        inputs = replace(mechanism_inputs(config), film=film)
        runs[method] = ci.solve_contact_impact(inputs, compare=False)
    stiff, explicit = runs[name], runs["RK45-compiled"]
    assert stiff.summary()["integrator"] == ran
    assert explicit.summary()["integrator"] == "RK45-compiled"
    assert stiff.impacts == explicit.impacts
    assert stiff.peak_joint_force == pytest.approx(explicit.peak_joint_force, rel=1e-5)
    peak = explicit.load.load.max()
    assert peak > 0.0  # the pin reaches the wall
    x = lambda load: load.load * np.cos(load.azimuth)  # noqa: E731
    y = lambda load: load.load * np.sin(load.azimuth)  # noqa: E731
    difference = np.hypot(x(stiff.load) - x(explicit.load), y(stiff.load) - y(explicit.load))
    assert difference.max() < 1e-3 * peak


def test_auto_picks_radau5_for_an_oiled_joint_only(paper_config: Config) -> None:
    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 0})
    oiled, settings, _ = system_and_start(config, SHORT)
    dry, _, _ = system_and_start(config, None)
    unoiled, _, _ = system_and_start(config, FilmParameters("short-bearing", 0.0))
    assert settings.integrator == "auto"
    assert settings.integrator_for(oiled) == "Radau-compiled"
    assert settings.integrator_for(dry) == "RK45-compiled"
    assert settings.integrator_for(unoiled) == "RK45-compiled"
    for name in ("RK45-compiled", "Rodas4-compiled", "LSODA"):
        named = replace(settings, integrator=name)
        assert named.integrator_for(oiled) == name
        assert named.integrator_for(dry) == name
    python = ci.SliderCrankContactSystem(oiled.mechanism, oiled.omega, oiled.contact, False)
    assert replace(settings, integrator="Rodas4-compiled").integrator_for(python) == "Radau"
    assert settings.integrator_for(python) == "LSODA"


@pytest.mark.parametrize("name", ["Rodas4-compiled", "Radau-compiled"])
def test_an_explicit_stiff_choice_on_a_dry_joint_runs_it(paper_config: Config, name: str) -> None:
    config = impact_config(paper_config, **{"dynamics.integrator": name})
    solution = ci.solve_contact_impact(mechanism_inputs(config), compare=False)
    assert solution.summary()["integrator"] == name
    reference = ci.solve_contact_impact(
        mechanism_inputs(impact_config(paper_config)), compare=False
    )
    assert reference.summary()["integrator"] == "RK45-compiled"
    assert solution.peak_load == pytest.approx(reference.peak_load, rel=1e-5)
    difference = np.abs(solution.load.load - reference.load.load).max()
    assert difference < 1e-5 * reference.load.load.max()
