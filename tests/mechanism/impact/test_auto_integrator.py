"""``dynamics.integrator = "auto"`` (the default): the compiled integration where it runs.

On the slider-crank with a point force law ``auto`` is ``RK45-compiled``; everywhere
else (the distributed laws, no compiled right-hand side, the other mechanisms) it is
LSODA, to the bit. The run records which one ran; its configuration keeps ``auto``.
"""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config, config_from_dict, load_config
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.slider_crank import contact_impact as ci
from jointwear.mechanism.stage import load_cycles, mechanism_inputs

from ..test_oscillating_impact import BASE as OSCILLATING

pytestmark = pytest.mark.filterwarnings("ignore::jointwear.errors.ContactLossWarning")

QUICK = {
    "dynamics.model": "contact-impact",
    "dynamics.revolutions_settle": 1,
    "simulation.steps_per_revolution": 72,
}


@pytest.fixture(scope="module")
def impact(paper_config: Config) -> Config:
    return paper_config.replace(QUICK)


def solve(config: Config, compiled: bool | None = None):
    return ci.solve_contact_impact(mechanism_inputs(config), compare=False, compiled=compiled)


def assert_same_bits(first, second) -> None:
    np.testing.assert_array_equal(first.load.load, second.load.load)
    np.testing.assert_array_equal(first.load.azimuth, second.load.azimuth)


def test_auto_is_the_default(paper_config: Config) -> None:
    assert paper_config.dynamics.integrator == "auto"


def test_auto_runs_the_compiled_integration_on_the_slider_crank(impact: Config) -> None:
    auto = solve(impact)
    compiled = solve(impact.replace({"dynamics.integrator": "RK45-compiled"}))
    assert_same_bits(auto, compiled)
    assert auto.summary()["integrator"] == "RK45-compiled"


def test_auto_is_lsoda_without_the_compiled_right_hand_side(impact: Config) -> None:
    # no numba (or JOINTWEAR_NO_NUMBA=1): the Python right-hand side, integrated by LSODA
    auto = solve(impact, compiled=False)
    lsoda = solve(impact.replace({"dynamics.integrator": "LSODA"}), compiled=False)
    assert_same_bits(auto, lsoda)
    assert auto.summary()["integrator"] == "LSODA"


def test_auto_is_lsoda_for_a_distributed_force_law(impact: Config) -> None:
    winkler = impact.replace({"dynamics.force_law": "winkler", "contact.nodes": 90})
    auto = solve(winkler)
    lsoda = solve(winkler.replace({"dynamics.integrator": "LSODA"}))
    assert_same_bits(auto, lsoda)
    assert auto.summary()["integrator"] == "LSODA"


def test_auto_is_lsoda_for_the_oscillating_bearing() -> None:
    auto = load_cycles(config_from_dict(OSCILLATING))["bearing"]
    data = {**OSCILLATING, "dynamics": {**OSCILLATING["dynamics"], "integrator": "LSODA"}}
    lsoda = load_cycles(config_from_dict(data))["bearing"]
    np.testing.assert_array_equal(auto.load, lsoda.load)
    assert auto.extras["integrator"] == lsoda.extras["integrator"] == "LSODA"


def test_rk45_compiled_without_the_compiled_right_hand_side_is_reported_as_rk45(
    impact: Config,
) -> None:
    # asked for explicitly where it cannot run compiled, scipy's RK45 integrates (the same
    # pair and step control): the summary names what ran
    asked = solve(impact.replace({"dynamics.integrator": "RK45-compiled"}), compiled=False)
    rk45 = solve(impact.replace({"dynamics.integrator": "RK45"}), compiled=False)
    assert_same_bits(asked, rk45)
    assert asked.summary()["integrator"] == "RK45"


def test_rk45_compiled_on_the_oscillating_bearing_is_reported_as_rk45() -> None:
    data = {**OSCILLATING, "dynamics": {**OSCILLATING["dynamics"], "integrator": "RK45-compiled"}}
    assert load_cycles(config_from_dict(data))["bearing"].extras["integrator"] == "RK45"


def test_the_settings_object_defaults_to_the_configs_integrator(paper_config: Config) -> None:
    assert ContactImpactSettings().integrator == paper_config.dynamics.integrator == "auto"


def test_the_default_is_converged_on_the_papers_joint(paper_config: Config) -> None:
    # measured against rtol = 1e-12 (LSODA and RK45-compiled agree there to 1e-9):
    # RK45-compiled at the default 4.4e-7 of the peak, LSODA at the default 6.5e-6
    config = paper_config.replace({"dynamics.model": "contact-impact"})
    found = solve(config)
    tight = {"dynamics.integrator": "RK45-compiled", "dynamics.rtol": 1e-12, "dynamics.atol": 1e-14}
    converged = solve(config.replace(tight))
    vectors = [s.load.load * np.exp(1j * s.load.azimuth) for s in (found, converged)]
    peak = np.abs(vectors[1]).max()
    assert np.abs(vectors[0] - vectors[1]).max() / peak < 2e-6


def test_the_run_records_the_integrator_and_keeps_auto(impact: Config, tmp_path) -> None:
    result = Simulation(impact.replace({"simulation.revolutions": 1})).run()
    assert result.summary()["integrator"] == "RK45-compiled"
    path = tmp_path / "saved.toml"
    path.write_text(result.dataset.attrs["config"])
    assert load_config(path).dynamics.integrator == "auto"


def test_a_massless_link_run_names_no_integrator(paper_config: Config) -> None:
    result = Simulation(paper_config.replace({"simulation.revolutions": 1})).run()
    assert "integrator" not in result.summary()
