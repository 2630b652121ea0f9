"""The compiled Dormand-Prince integration of the slider-crank against LSODA.

``dynamics.integrator = "RK45-compiled"`` integrates the revolution in one compiled
function; LSODA (the default) stays the reference. Both integrate the same equations
to the same tolerances, so their load cycles agree to those tolerances where the
motion is not sensitive to them (the paper's joint: persistent contact). The
separation-prone joint on a worn contour is sensitive: at rtol = 1e-8 the time of a
late impact moves by milliseconds between any two integrators. A solve in which the pin
leaves the wall is therefore integrated again at ``dynamics.separation_rtol`` (1e-10),
where both have converged (``tests/mechanism/impact/test_separation_tolerance.py``).
"""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.mechanism.impact.free_pin import free_pin_impact
from jointwear.mechanism.impact.integrator import integrate_contacts
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.slider_crank import contact_impact as ci
from jointwear.mechanism.slider_crank.contact_impact import impact_kernel
from jointwear.mechanism.slider_crank.dynamics import SliderCrank
from jointwear.mechanism.stage import mechanism_inputs

from ..joints import joint_contact

pytestmark = pytest.mark.skipif(impact_kernel() is None, reason="needs numba")

#: the separation-prone slider-crank of the worn-contour benchmark (docs/wear-feedback.md)
SEPARATION_PRONE = {
    "mechanism.spring_mode": "push",
    "mechanism.spring_preload": "1 N",
    "mechanism.crank_speed": "240 rpm",
    "mechanism.rod_mass": "0.3 kg",
    "simulation.steps_per_revolution": 180,
}


def scar(nodes: int = 360) -> np.ndarray:
    """A wear scar 30 um deep (0.6 of the clearance) where the separating load sits [m]."""
    theta = 2.0 * np.pi * np.arange(nodes) / nodes
    return 3e-5 * np.exp(-(np.angle(np.exp(1j * (theta - 2.0))) ** 2) / 0.5)


def solve(config: Config, integrator: str, wear: np.ndarray | None = None, **overrides):
    config = config.replace(
        {"dynamics.model": "contact-impact", "dynamics.integrator": integrator, **overrides}
    )
    inputs = mechanism_inputs(config)
    return ci.solve_contact_impact(inputs, ci.worn_contour(inputs, wear), compare=False)


def load_vectors(solution) -> np.ndarray:
    """The normal contact force at the samples as complex numbers [N]."""
    return solution.load.load * np.exp(1j * solution.load.azimuth)


def relative_difference(a, b) -> float:
    """Largest sample difference of the load vectors, relative to the peak sample [-]."""
    fa, fb = load_vectors(a), load_vectors(b)
    return float(np.max(np.abs(fa - fb)) / np.max(np.abs(fa)))


def test_paper_joint_load_agrees_with_lsoda(paper_config: Config) -> None:
    # rtol = 1e-8 on states of ~1e-5 m penetration: measured 6.5e-6 of the peak
    reference = solve(paper_config, "LSODA")
    compiled = solve(paper_config, "RK45-compiled")
    assert compiled.system.compiled
    assert relative_difference(reference, compiled) < 1e-4
    assert compiled.impacts == reference.impacts == 0
    assert compiled.peak_load == pytest.approx(reference.peak_load, rel=1e-4)
    # the explicit pair is bounded by the contact stiffness: more, cheaper right-hand sides
    assert compiled.history.evaluations > reference.history.evaluations


def test_separating_joint_unworn_agrees_with_lsoda(paper_config: Config) -> None:
    reference = solve(paper_config.replace(SEPARATION_PRONE), "LSODA")
    compiled = solve(paper_config.replace(SEPARATION_PRONE), "RK45-compiled")
    assert relative_difference(reference, compiled) < 1e-3
    assert compiled.impacts == reference.impacts


@pytest.mark.slow
def test_separating_worn_joint_agrees_with_lsoda_when_converged(paper_config: Config) -> None:
    tight = {"dynamics.rtol": 1e-10, "dynamics.atol": 1e-12}
    config = paper_config.replace(SEPARATION_PRONE)
    reference = solve(config, "LSODA", scar(), **tight)
    compiled = solve(config, "RK45-compiled", scar(), **tight)
    assert compiled.impacts == reference.impacts == 7
    np.testing.assert_allclose(
        compiled.history.impact_times, reference.history.impact_times, atol=1e-4
    )
    # both within ~1 % of a rtol = 1e-12 solution at the worst sample (an impact's edge)
    assert relative_difference(reference, compiled) < 3e-2
    assert compiled.free_flight_fraction == pytest.approx(reference.free_flight_fraction, abs=1e-3)


def test_separating_worn_joint_counts_the_same_impacts(paper_config: Config) -> None:
    config = paper_config.replace(SEPARATION_PRONE)
    reference = solve(config, "LSODA", scar())
    compiled = solve(config, "RK45-compiled", scar())
    assert compiled.impacts == reference.impacts == 7
    history = compiled.history
    # the pin starts on the wall: contact ends and starts alternate, ends first
    assert len(history.separation_times) - len(history.impact_times) in (0, 1)
    assert history.separation_times[0] < history.impact_times[0]
    assert len(history.impact_times) == len(reference.history.impact_times)
    # the early impacts, before the tolerance-sensitive late ones, at the same speeds
    np.testing.assert_allclose(
        history.impact_velocities[:8], reference.history.impact_velocities[:8], atol=5e-4
    )
    assert compiled.free_flight_fraction == pytest.approx(reference.free_flight_fraction, abs=2e-3)


def test_other_systems_run_scipys_rk45(paper_config: Config) -> None:
    # the free pin has no compiled integration: the same pair through solve_ivp
    contact = joint_contact(paper_config)
    plain = free_pin_impact(contact, mass=0.4, impact_velocity=0.1, method="RK45")
    named = free_pin_impact(contact, mass=0.4, impact_velocity=0.1, method="RK45-compiled")
    assert named[0] == plain[0]
    assert named[1].evaluations == plain[1].evaluations


def test_tables_are_scipys_rk45() -> None:
    # written out (no scipy.integrate import in a run), to the bit scipy's
    from scipy.integrate import RK45

    from jointwear.mechanism.slider_crank import _contact_impact_rk as rk

    for name in "CABEP":
        ours, scipys = getattr(rk, f"_{name}"), getattr(RK45, name)
        assert ours.dtype == scipys.dtype, name
        assert ours.shape == scipys.shape, name
        assert ours.tobytes() == scipys.tobytes(), name


def test_compiled_steps_are_scipys_rk45(paper_config: Config) -> None:
    # without contact events the compiled loop takes RK45's steps: the same number of
    # right-hand sides, the same states but for the rounding of the sums
    config = paper_config.replace({"dynamics.model": "contact-impact"})
    inputs = mechanism_inputs(config)
    settings = ContactImpactSettings.from_config(config.dynamics)
    mechanism = SliderCrank.from_config(config.mechanism)
    contact = ci.slider_crank_contact(inputs, settings)
    system = ci.SliderCrankContactSystem(mechanism, config.mechanism.crank_speed, contact)
    y0, _ = ci.initial_state(system, 360)
    period = 2.0 * np.pi / system.omega
    samples = np.linspace(0.0, period, 361)
    scipy_run = integrate_contacts(
        system, (0.0, period), y0, in_contact=True, method="RK45", max_step=period / 360,
        keep=samples,
    )  # fmt: skip
    compiled, states, _ = system.integrate_compiled(
        (0.0, period), y0, True, settings, period / 360, samples
    )
    assert compiled.evaluations == scipy_run.evaluations
    assert not compiled.impact_times
    assert not scipy_run.impact_times
    expected, _ = scipy_run.state(samples)
    scale = np.max(np.abs(expected), axis=0)
    np.testing.assert_array_less(np.max(np.abs(states - expected), axis=0), 1e-11 * scale)
