"""The lubricated slider-crank integrated by ``Radau-compiled`` (RADAU5).

* on the paper's joint with a short-bearing film (the pin on the wall, the squeeze film
  stiff) its contact force agrees with ``RK45-compiled``'s at a tight tolerance, closer
  than RODAS4's at the same tolerance, with far fewer right-hand sides than either;
* on the separating case with a long-bearing film (an impact) it gives ``RK45-compiled``'s
  impacts and loads (``test_contact_impact_rosenbrock``, with RODAS4's);
* it runs where it is named (oiled or dry; a dry joint's load:
  ``test_contact_impact_rosenbrock``); where the system has no compiled integration it
  runs as scipy's ``Radau``; ``auto`` does not pick it.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.mechanism.impact.film import FilmParameters
from jointwear.mechanism.slider_crank import contact_impact as ci

from .test_contact_impact import impact_config
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
    # observed: 2.3e-7 of the peak (RODAS4: 9.8e-6) with 3.7e3 right-hand sides (RODAS4
    # 2.8e4, RK45-compiled 4.2e5)
    assert deviation < 1e-6
    assert deviation < 0.1 * np.abs(rosenbrock - reference).max() / peak
    assert count < rosenbrock_count / 2
    assert count < explicit / 20


def test_runs_where_named_and_auto_picks_it_with_a_film(paper_config: Config) -> None:
    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 0})
    oiled, settings, _ = system_and_start(config, SHORT)
    dry, _, _ = system_and_start(config, None)
    named = replace(settings, integrator="Radau-compiled")
    assert named.integrator_for(oiled) == "Radau-compiled"
    assert named.integrator_for(dry) == "Radau-compiled"
    assert settings.integrator_for(oiled) == "Radau-compiled"
    python = ci.SliderCrankContactSystem(oiled.mechanism, oiled.omega, oiled.contact, False)
    assert named.integrator_for(python) == "Radau"


def test_divergence_bound_saves_work_and_keeps_the_load(
    paper_config: Config, monkeypatch: pytest.MonkeyPatch
) -> None:
    # a whole revolution of the paper's joint under a viscous film (1 Pa s), the start's
    # squeeze spike included: the film bends within a step, so the Newton sweeps diverge
    # where the error estimate alone would let the step grow
    from jointwear.mechanism.impact import radau
    from jointwear.mechanism.slider_crank import _contact_impact_radau
    from jointwear.mechanism.slider_crank._contact_impact_rosenbrock import STIFF_SYSTEM

    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 0})
    system, settings, y0 = system_and_start(config, FilmParameters("short-bearing", 1.0))
    span = 2.0 * np.pi / system.omega
    samples = np.linspace(0.0, span, 101)[1:]
    reference, _ = forces(system, "Radau-compiled", 1e-11, span, samples, y0, settings)
    peak = np.abs(reference).max()
    bounded, count = forces(system, "Radau-compiled", 1e-8, span, samples, y0, settings)
    # the same steps without the bound: it is dropped at once after every divergence
    unbounded_integrate = radau.bind({**STIFF_SYSTEM, "FAST_CLEAR": 0}, "unbounded", cache=False)
    monkeypatch.setattr(_contact_impact_radau, "integrate_revolution_radau", unbounded_integrate)
    unbounded, unbounded_count = forces(system, "Radau-compiled", 1e-8, span, samples, y0, settings)
    # observed: 6.7e-8 and 8.1e-8 of the peak; 20 k right-hand sides against 46 k
    assert np.abs(bounded - reference).max() / peak < 1e-6
    assert np.abs(unbounded - reference).max() / peak < 1e-6
    assert count < unbounded_count / 2
