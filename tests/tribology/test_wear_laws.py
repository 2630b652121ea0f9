"""Wear laws: the energy law at constant friction is Archard's; callables are wear laws."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.tribology.wear_laws import energy_wear_depth, wear_law


@pytest.fixture(scope="module")
def small(paper_config: Config) -> Config:
    return paper_config.replace(
        {
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 90,
            "simulation.revolutions": 3000,
            "simulation.update_contour": True,
            "simulation.update_every": 100,
        }
    )


def test_energy_law_with_constant_friction_is_archard_with_k_mu(small: Config) -> None:
    k_energy, mu = 2.5e-12, 0.2
    energy = small.replace(
        {"wear.law": "energy", "wear.energy_coefficient": k_energy, "wear.friction_coefficient": mu}
    )
    archard = small.replace({"materials.bushing.wear_coefficient": k_energy * mu})
    a = Simulation(energy).run()
    b = Simulation(archard).run()
    np.testing.assert_allclose(a.wear_depth, b.wear_depth, rtol=1e-9, atol=0)
    assert a.summary()["wear_mass_kg"] == pytest.approx(
        b.summary()["wear_mass_kg"], rel=1e-9, abs=0
    )


def test_energy_law_follows_a_pressure_dependent_friction() -> None:
    """mu falling with pressure wears the loaded node less than a constant mu would."""
    pressure = np.array([[1e6, 4e6], [1e6, 4e6]])
    sliding = np.array([1e-3, 2e-3])
    constant = energy_wear_depth(pressure, sliding, 1e-12, 0.2)
    np.testing.assert_allclose(constant, 1e-12 * 0.2 * 3e-3 * np.array([1e6, 4e6]), rtol=1e-15)
    falling = energy_wear_depth(pressure, sliding, 1e-12, lambda p: 0.2 * (1e6 / p) ** 0.5)
    np.testing.assert_allclose(falling, [constant[0], constant[1] / 2], rtol=1e-15)


def test_callable_wear_law(small: Config) -> None:
    k = small.materials.bushing.wear_coefficient
    doubled = Simulation(small, wear_law=lambda p, ds: (2 * k) * (ds @ p)).run()
    named = Simulation(small.replace({"materials.bushing.wear_coefficient": 2 * k})).run()
    np.testing.assert_allclose(doubled.wear_depth, named.wear_depth, rtol=1e-12, atol=0)


def test_bad_wear_law_settings(small: Config) -> None:
    with pytest.raises(ConfigError, match=r"wear.law: unknown wear law 'enrgy'; did you mean"):
        small.replace({"wear.law": "enrgy"})
    with pytest.raises(ConfigError, match=r"wear.energy_coefficient: missing"):
        small.replace({"wear.law": "energy", "wear.friction_coefficient": 0.2})


def test_the_laws_read_their_sections(small: Config) -> None:
    """Archard's law takes K_d from the bushing's material, the energy law k_E mu from
    [wear]: h_j = K sum_k p_jk ds_k on a two-step, two-node cycle."""
    pressure = np.array([[1e6, 4e6], [2e6, 0.0]])
    sliding = np.array([1e-3, 2e-3])
    work = sliding @ pressure  # [Pa m]
    bushing = small.materials.bushing
    archard = wear_law(small.wear, bushing)
    np.testing.assert_allclose(
        archard(pressure, sliding), bushing.wear_coefficient * work, rtol=1e-15
    )
    energy = small.replace(
        {"wear.law": "energy", "wear.energy_coefficient": 3e-12, "wear.friction_coefficient": 0.25}
    )
    law = wear_law(energy.wear, energy.materials.bushing)
    np.testing.assert_allclose(law(pressure, sliding), 3e-12 * 0.25 * work, rtol=1e-15)
    # a name given to the call wins over the section's
    named = wear_law(energy.wear, bushing, "archard")
    np.testing.assert_allclose(named(pressure, sliding), bushing.wear_coefficient * work)
