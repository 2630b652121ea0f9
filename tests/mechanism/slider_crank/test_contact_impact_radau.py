"""The lubricated slider-crank integrated by ``Radau-compiled`` (RADAU5).

* on the paper's joint with a short-bearing film (the pin on the wall, the squeeze film
  stiff) its contact force agrees with ``RK45-compiled``'s at a tight tolerance, closer
  than RODAS4's at the same tolerance, with far fewer right-hand sides than either;
* on the separating case with a long-bearing film (an impact) it gives ``RK45-compiled``'s
  impacts and loads;
* it runs where it is named (oiled or dry); where the system has no compiled integration
  it runs as scipy's ``Radau``; ``auto`` does not pick it.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.mechanism.impact.film import FilmParameters
from jointwear.mechanism.slider_crank import contact_impact as ci
from jointwear.mechanism.stage import mechanism_inputs

from .test_contact_impact import SEPARATING, impact_config
from .test_contact_impact_rosenbrock import SHORT, forces, system_and_start

pytestmark = pytest.mark.skipif(
    ci.impact_kernel() is None, reason="numba missing or JOINTWEAR_NO_NUMBA set"
)


def test_agrees_with_the_explicit_pair_on_the_wall(paper_config: Config) -> None:
    # the start transient (the pin pressed in, the squeeze film's spike) and 0.1 s on the wall
    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 0})
    system, settings, y0 = system_and_start(config, SHORT)
    span = 0.1
    samples = np.linspace(0.0, span, 41)[1:]
    reference, explicit = forces(system, "RK45-compiled", 1e-10, span, samples, y0, settings)
    peak = np.abs(reference).max()
    implicit, count = forces(system, "Radau-compiled", 1e-8, span, samples, y0, settings)
    rosenbrock, rosenbrock_count = forces(
        system, "Rodas4-compiled", 1e-8, span, samples, y0, settings
    )
    deviation = np.abs(implicit - reference).max() / peak
    # observed: 1.0e-7 of the peak (RODAS4: 9.8e-6) with 8.6e3 right-hand sides (RODAS4
    # 2.8e4, RK45-compiled 4.2e5)
    assert deviation < 1e-6
    assert deviation < 0.1 * np.abs(rosenbrock - reference).max() / peak
    assert count < rosenbrock_count / 2
    assert count < explicit / 20


def test_the_separating_case_impacts_alike(paper_config: Config) -> None:
    film = FilmParameters("long-bearing", 0.1)
    runs = {}
    for name in ("Radau-compiled", "RK45-compiled"):
        config = impact_config(paper_config, **SEPARATING, **{"dynamics.integrator": name})
        inputs = replace(mechanism_inputs(config), film=film)
        runs[name] = ci.solve_contact_impact(inputs, compare=False)
    implicit, explicit = runs["Radau-compiled"], runs["RK45-compiled"]
    assert implicit.summary()["integrator"] == "Radau-compiled"
    assert implicit.impacts == explicit.impacts
    assert implicit.peak_joint_force == pytest.approx(explicit.peak_joint_force, rel=1e-5)
    peak = explicit.load.load.max()
    assert peak > 0.0  # the pin reaches the wall
    x = lambda load: load.load * np.cos(load.azimuth)  # noqa: E731
    y = lambda load: load.load * np.sin(load.azimuth)  # noqa: E731
    difference = np.hypot(x(implicit.load) - x(explicit.load), y(implicit.load) - y(explicit.load))
    assert difference.max() < 1e-3 * peak


def test_runs_where_named_and_auto_keeps_its_choice(paper_config: Config) -> None:
    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 0})
    oiled, settings, _ = system_and_start(config, SHORT)
    dry, _, _ = system_and_start(config, None)
    named = replace(settings, integrator="Radau-compiled")
    assert named.integrator_for(oiled) == "Radau-compiled"
    assert named.integrator_for(dry) == "Radau-compiled"
    assert settings.integrator_for(oiled) == "Rodas4-compiled"
    python = ci.SliderCrankContactSystem(oiled.mechanism, oiled.omega, oiled.contact, False)
    assert named.integrator_for(python) == "Radau"


def test_a_dry_joint_named_radau_compiled_gives_the_dry_load(paper_config: Config) -> None:
    config = impact_config(paper_config, **{"dynamics.integrator": "Radau-compiled"})
    solution = ci.solve_contact_impact(mechanism_inputs(config), compare=False)
    assert solution.summary()["integrator"] == "Radau-compiled"
    reference = ci.solve_contact_impact(
        mechanism_inputs(impact_config(paper_config)), compare=False
    )
    assert reference.summary()["integrator"] == "RK45-compiled"
    assert solution.peak_load == pytest.approx(reference.peak_load, rel=1e-5)
    difference = np.abs(solution.load.load - reference.load.load).max()
    assert difference < 1e-5 * reference.load.load.max()
