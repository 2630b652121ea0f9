"""Contact-impact dynamics of the slider-crank: the pin free in the clearance.

Physical checks, each of which fails if the mechanics is wrong:

* work-energy balance with elastic, frictionless contact (c_e = 1, mu = 0): the
  mechanical energy (kinetic + spring + gravity + contact K delta^(n+1)/(n+1)) changes
  by exactly the crank work, over an interval with many impacts;
* dissipation with damping and friction is never negative and never decreases;
* continuous contact (the paper's pull spring at 120 rpm): the load agrees with
  the massless-link model, the residue being the penetration's geometric effect;
* separation (push spring, tiny preload): impacts and free flight are detected
  where the massless-link model warns about contact loss.
"""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.config import Config
from jointwear.errors import ConfigError, ContactLossWarning, ConvergenceError
from jointwear.mechanism import DYNAMICS_MODELS, ContactImpactSolution, LoadCycle
from jointwear.mechanism.impact.integrator import integrate_contacts
from jointwear.mechanism.slider_crank.contact_impact import (
    initial_state,
    solve_contact_impact,
)
from jointwear.mechanism.slider_crank.massless_link import massless_link_load
from jointwear.mechanism.stage import load_cycle, mechanism_inputs

from ..joints import slider_crank_system

#: push spring with 1 N preload at 240 rpm, 0.2 mm clearance, light rod: the pin
#: separates from the wall twice per revolution
SEPARATING = {
    "mechanism.spring_mode": "push",
    "mechanism.spring_preload": "1 N",
    "mechanism.crank_speed": "240 rpm",
    "joint.clearance": "0.2 mm",
    "mechanism.rod_mass": "0.3 kg",
    "mechanism.rod_inertia": 0.3 * 0.2**2 / 12,
}


def impact_config(config: Config, **overrides: object) -> Config:
    return config.replace({"dynamics.model": "contact-impact", **overrides})


def solve(config: Config, **options: object) -> ContactImpactSolution:
    """:func:`solve_contact_impact` of the slider-crank of ``config``."""
    return solve_contact_impact(mechanism_inputs(config), **options)


# ------------------------------------------------------------------ energy


def energy_balance(config: Config, duration: float, rtol: float, atol: float):
    system = slider_crank_system(config)
    y0, _ = initial_state(system, 360)
    history = integrate_contacts(
        system,
        (0.0, duration),
        y0,
        in_contact=True,
        rtol=rtol,
        atol=atol,
        max_step=2 * math.pi / system.omega / 360,
    )
    times = np.linspace(0.0, duration, 2001)
    states, _ = history.state(times)
    energy = np.array([system.energy(t, y) for t, y in zip(times, states, strict=True)])
    work = states[:, 4]
    return energy - energy[0] - work, work, history


def test_energy_conserved_with_elastic_frictionless_impacts(paper_config: Config) -> None:
    config = impact_config(paper_config, **SEPARATING, **{"dynamics.restitution": 1.0})
    residue, work, history = energy_balance(config, 0.05, 1e-10, 1e-13)
    assert len(history.impact_times) >= 5  # the interval holds impacts
    assert np.max(np.abs(work)) > 1.0  # and the crank does work [J]
    # observed ~5e-9 J against ~4 J of crank work
    assert np.max(np.abs(residue)) < 1e-7


def test_energy_residue_shrinks_with_tolerance(paper_config: Config) -> None:
    # the residue is integration error, not a modelling term: it falls with rtol
    config = impact_config(paper_config, **SEPARATING, **{"dynamics.restitution": 1.0})
    loose, _, _ = energy_balance(config, 0.03, 1e-7, 1e-10)
    tight, _, _ = energy_balance(config, 0.03, 1e-10, 1e-13)
    assert np.max(np.abs(tight)) < 0.1 * np.max(np.abs(loose))


@pytest.mark.slow
@pytest.mark.parametrize("law", ["nlcp", "winkler"])
def test_energy_conserved_distributed_laws(paper_config: Config, law: str) -> None:
    config = impact_config(
        paper_config, **SEPARATING, **{"dynamics.restitution": 1.0, "dynamics.force_law": law}
    )
    residue, _, history = energy_balance(config, 0.05, 1e-10, 1e-13)
    assert len(history.impact_times) >= 5
    assert np.max(np.abs(residue)) < 1e-6


@pytest.mark.parametrize("friction", [0.0, 0.2])
def test_dissipation_is_positive_and_monotone(paper_config: Config, friction: float) -> None:
    config = impact_config(
        paper_config,
        **SEPARATING,
        **{"dynamics.restitution": 0.5, "dynamics.friction_coefficient": friction},
    )
    residue, _, history = energy_balance(config, 0.05, 1e-10, 1e-13)
    dissipated = -residue  # crank work not stored as mechanical energy
    assert len(history.impact_times) >= 2
    assert dissipated[-1] > 1e-3  # impacts (and friction) consume energy [J]
    assert np.all(np.diff(dissipated) > -1e-8)


# ------------------------------------------------------------------ continuous contact


def load_difference(a: LoadCycle, b: LoadCycle) -> np.ndarray:
    return np.hypot(
        a.load * np.cos(a.azimuth) - b.load * np.cos(b.azimuth),
        a.load * np.sin(a.azimuth) - b.load * np.sin(b.azimuth),
    )


def test_agrees_with_massless_link_when_spring_keeps_contact(paper_config: Config) -> None:
    solution = solve(impact_config(paper_config))
    load, massless = solution.load, solution.massless
    assert massless is not None
    assert not massless.contact_lost
    assert solution.impacts == 0
    assert solution.free_flight_fraction == 0.0
    assert not load.contact_lost
    assert not load.lost_steps.any()
    mean = massless.mean_load
    # observed: rms 0.067 N = 0.04 % of the 163 N mean, max 0.076 N, azimuth 0.004 deg
    assert solution.load_difference_rms < 2e-3 * mean
    assert solution.load_difference_max < 3e-3 * mean
    assert np.max(np.abs(load.azimuth - massless.azimuth)) < math.radians(0.05)
    assert (
        np.max(
            np.abs(
                load.diagnostics["crank_torque"].values
                - massless.diagnostics["crank_torque"].values
            )
        )
        < 0.01
    )
    assert load.total_relative_rotation == pytest.approx(massless.total_relative_rotation, rel=1e-3)
    # Hertz pin-in-hole stiffness: tens of micrometres into the PTFE
    assert 3e-5 < solution.max_penetration < 5e-5
    # the residue is geometric: a massless link as long as clearance + static
    # penetration (~34 um at the mean load) agrees ~10x better
    longer = massless_link_load(
        mechanism_inputs(paper_config.replace({"joint.clearance": 0.05e-3 + 34e-6}))
    )
    residue = load_difference(load, longer)
    assert np.sqrt(np.mean(residue**2)) < 0.2 * solution.load_difference_rms


@pytest.mark.parametrize("bushing_body", ["rod"])
def test_agrees_with_massless_link_bushing_in_rod(paper_config: Config, bushing_body: str) -> None:
    config = impact_config(
        paper_config, **{"mechanism.bushing_body": bushing_body, "dynamics.revolutions_settle": 1}
    )
    solution = solve(config)
    assert solution.load.extras["bushing_body"] == "rod"
    assert solution.load_difference_rms < 2e-3 * solution.massless.mean_load
    np.testing.assert_allclose(
        solution.load.relative_rotation, solution.massless.relative_rotation, atol=2e-4
    )


@pytest.mark.slow
@pytest.mark.parametrize("law", ["hunt-crossley", "flores", "nlcp", "winkler"])
@pytest.mark.parametrize(
    "overrides", [{}, {"mechanism.spring_preload": "120 N", "mechanism.crank_speed": "240 rpm"}]
)
def test_agreement_all_laws(paper_config: Config, law: str, overrides: dict) -> None:
    solution = solve(impact_config(paper_config, **{"dynamics.force_law": law, **overrides}))
    assert solution.impacts == 0
    assert solution.load_difference_rms < 2e-3 * solution.massless.mean_load


def test_wear_pipeline_consumes_contact_impact_load(paper_config: Config) -> None:
    from jointwear.simulation import Simulation

    config = impact_config(paper_config, **{"dynamics.revolutions_settle": 1})
    impact = Simulation(config).run().summary()
    massless = Simulation(paper_config).run().summary()
    assert impact["peak_wear_depth_m"] == pytest.approx(massless["peak_wear_depth_m"], rel=5e-3)
    assert impact["wear_mass_kg"] == pytest.approx(massless["wear_mass_kg"], rel=5e-3)


# ------------------------------------------------------------------ separation


def test_separation_detected_where_massless_link_warns(paper_config: Config) -> None:
    config = impact_config(paper_config, **SEPARATING)
    with pytest.warns(ContactLossWarning):
        massless_link_load(mechanism_inputs(config))
    solution = solve(config)
    load = solution.load
    assert solution.massless_contact_lost is True
    # observed: 9 impacts, 13 % free flight per revolution
    assert solution.impacts >= 2
    assert 0.02 < solution.free_flight_fraction < 0.5
    assert load.contact_lost
    assert load.lost_steps.any()
    assert np.min(load.load) == 0.0  # some samples fall in free flight
    # the contact-loss angles are where the massless-link model says so (its
    # half of the revolution with the rod in tension, near the outer dead centre)
    lost_deg = np.degrees(load.phase[load.lost_steps])
    warned_deg = np.degrees(solution.massless.phase[solution.massless.lost_steps])
    assert np.any(np.abs(lost_deg[:, None] - warned_deg[None, :]) < 30)
    # impacts are harder than anything in the massless-link load (observed 492 N vs 347 N)
    assert solution.peak_load >= load.load.max()
    assert solution.peak_load > 1.2 * solution.massless.load.max()


def test_paper_mechanism_keeps_contact(paper_config: Config) -> None:
    solution = solve(impact_config(paper_config, **{"dynamics.revolutions_settle": 1}))
    assert solution.impacts == 0
    assert solution.free_flight_fraction == 0.0


# ------------------------------------------------------------------ plumbing


def test_registered_and_joint_load(paper_config: Config) -> None:
    assert "contact-impact" in DYNAMICS_MODELS
    config = impact_config(
        paper_config, **{"simulation.steps_per_revolution": 72, "dynamics.revolutions_settle": 0}
    )
    load = load_cycle(config)
    assert isinstance(load, LoadCycle)
    assert load.model == "contact-impact"
    assert load.steps == 72
    np.testing.assert_allclose(load.phase, 2 * np.pi * np.arange(72) / 72)
    assert np.all(load.load >= 0)


def test_integrators_agree(paper_config: Config) -> None:
    base = {"dynamics.revolutions_settle": 0, "simulation.steps_per_revolution": 36}
    loads = {
        method: solve(
            impact_config(paper_config, **base, **{"dynamics.integrator": method}), compare=False
        ).load.load
        for method in ("LSODA", "Radau")
    }
    np.testing.assert_allclose(loads["Radau"], loads["LSODA"], rtol=1e-4)


@pytest.mark.parametrize(
    ("key", "value", "match"),
    [
        ("dynamics.restitution", 0.0, "dynamics.restitution"),
        ("dynamics.restitution", 1.5, "dynamics.restitution"),
        ("dynamics.integrator", "Euler", "dynamics.integrator"),
        ("dynamics.force_law", "hertz", "dynamics.force_law"),
        ("dynamics.friction_velocity_tolerance", "1 N", "dynamics.friction_velocity_tolerance"),
        ("dynamics.friction_velocity_full", 1e-5, "dynamics.friction_velocity_full"),
    ],
)
def test_bad_settings_raise_config_error(
    paper_config: Config, key: str, value: object, match: str
) -> None:
    with pytest.raises(ConfigError, match=match):
        paper_config.replace({key: value})


def test_velocity_with_units(paper_config: Config) -> None:
    config = paper_config.replace({"dynamics.friction_velocity_tolerance": "0.1 mm/s"})
    assert config.dynamics.friction_velocity_tolerance == pytest.approx(1e-4)
    defaults = paper_config.dynamics
    assert defaults.model == "massless-link"
    assert defaults.force_law == "lankarani-nikravesh"
    assert defaults.restitution == 0.9
    assert defaults.friction_coefficient == 0.0
    assert defaults.integrator == "auto"
    assert defaults.revolutions_settle == 2


def test_integrator_failure_raises_convergence_error(
    paper_config: Config, monkeypatch: pytest.MonkeyPatch
) -> None:
    import scipy.integrate

    real = scipy.integrate.solve_ivp

    def failing(*args, **kwargs):
        result = real(*args, **kwargs)
        result.status, result.message = -1, "Required step size is less than spacing"
        return result

    # contact_impact imports solve_ivp when it integrates: patch it at the source
    monkeypatch.setattr(scipy.integrate, "solve_ivp", failing)
    lsoda = {"dynamics.revolutions_settle": 0, "dynamics.integrator": "LSODA"}
    with pytest.raises(ConvergenceError, match="dynamics.integrator"):
        solve(impact_config(paper_config, **lsoda))


def test_cli_reports_impact_fields(capsys: pytest.CaptureFixture[str], paper_config_path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        main(
            [
                "dynamics",
                str(paper_config_path),
                "--set",
                "dynamics.model=contact-impact",
                "--set",
                "dynamics.revolutions_settle=1",
                "--json",
            ]
        )
    data = json.loads(capsys.readouterr().out)
    assert data["dynamics_model"] == "contact-impact"
    assert data["impacts"] == 0
    assert data["free_flight_fraction"] == 0.0
    assert 0 < data["max_penetration_m"] < 1e-4
    assert 0 <= data["load_difference_rms_n"] <= data["load_difference_max_n"] < 1.0


def test_compiled_and_python_right_hand_sides_give_the_same_revolution(
    paper_config: Config,
) -> None:
    # the right-hand sides under one integrator (LSODA: the Python one has no compiled loop)
    lsoda = {"dynamics.revolutions_settle": 0, "dynamics.integrator": "LSODA"}
    config = impact_config(paper_config, **lsoda)
    fast = solve(config, compare=False, compiled=True)
    reference = solve(config, compare=False, compiled=False)
    np.testing.assert_array_equal(fast.load.load, reference.load.load)
    np.testing.assert_array_equal(fast.load.azimuth, reference.load.azimuth)
    assert fast.history.evaluations == reference.history.evaluations
