"""A lubricated run: film and asperities share each step's load, the wear follows the asperities.

Checked against the dry run of the same joint: a thick film (lambda > 3) leaves almost
no asperity load and no wear; a vanishing viscosity leaves the dry wear; in the mixed
regime a faster crank builds a thicker film and wears less.
"""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.contact.lubricated import film_speeds


def summary(*overrides: str) -> dict:
    config = load_config(overrides=["mechanism.type=slider-crank", *overrides])
    return Simulation(config).run(pressures=False).summary()


@pytest.fixture(scope="module")
def dry() -> dict:
    return summary()


def test_the_dry_default_has_no_film_keys(dry):
    for key in ("min_film_thickness_m", "min_film_parameter", "asperity_load_fraction"):
        assert key not in dry


def test_a_thick_film_carries_the_load_and_stops_the_wear(dry):
    wet = summary("lubrication.model=short-bearing", "lubrication.viscosity=10 Pa*s")
    assert wet["min_film_parameter"] > 3.0
    assert wet["lubrication_regime"] == "hydrodynamic"
    assert wet["asperity_load_fraction"] < 0.01
    assert wet["wear_volume_m3"] < 0.01 * dry["wear_volume_m3"]


def test_without_viscosity_the_dry_contact_carries_and_wears_the_same(dry):
    wet = summary("lubrication.model=short-bearing", "lubrication.viscosity=1e-9 Pa*s")
    assert wet["asperity_load_fraction"] == pytest.approx(1.0)
    assert wet["wear_volume_m3"] == pytest.approx(dry["wear_volume_m3"], rel=0.01)


def test_in_the_mixed_regime_wear_falls_with_speed():
    runs = [
        summary(
            "lubrication.model=short-bearing",
            "lubrication.viscosity=0.1 Pa*s",
            f"mechanism.crank_speed={rpm} rpm",
        )
        for rpm in (40, 60, 90)
    ]
    wear = [run["wear_volume_m3"] for run in runs]
    assert all(run["lubrication_regime"] != "hydrodynamic" for run in runs)
    assert wear[0] > wear[1] > wear[2] > 0.0


def test_film_speeds_of_a_steadily_turning_load():
    from jointwear.mechanism.cycle import LoadCycle

    steps, period = 8, 0.5
    time = np.arange(steps) * period / steps
    azimuth = 2.0 * np.pi * np.arange(steps) / steps
    cycle = LoadCycle(
        time=time,
        load=np.full(steps, 100.0),
        azimuth=azimuth - np.pi / 2,
        relative_rotation=np.full(steps, 2.0 * np.pi / steps),
        period=period,
    )
    pin, load = film_speeds(cycle)
    np.testing.assert_allclose(pin, 2.0 * np.pi / period)
    np.testing.assert_allclose(load, 2.0 * np.pi / period)
