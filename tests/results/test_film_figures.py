"""The figures of a lubricated run: the orbit in the clearance circle and the film."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.errors import JointwearError
from jointwear.mechanism.cycle import LoadCycle
from jointwear.plots import plot_dataset, plot_result


def crank_pin_cycle(steps: int = 60, period: float = 0.5, load: float = 300.0) -> LoadCycle:
    time = np.arange(steps) * period / steps
    phase = 2.0 * np.pi * time / period
    return LoadCycle(
        time=time,
        load=load * (1.0 + 0.5 * np.cos(phase)),
        azimuth=-np.pi / 2 + 0.3 * np.sin(phase),
        relative_rotation=np.full(steps, 2.0 * np.pi / steps),
        period=period,
    )


def dataset(*overrides: str):
    config = load_config(
        overrides=["mechanism.type=slider-crank", "simulation.steps_per_revolution=60", *overrides]
    )
    return Simulation(config, load_cycle=crank_pin_cycle()).run().dataset


@pytest.fixture(scope="module")
def wet():
    return dataset("lubrication.model=short-bearing", "lubrication.viscosity=0.01 Pa*s")


def test_a_lubricated_result_draws_its_orbit_and_film(wet, tmp_path):
    names = {path.stem for path in plot_result(wet, tmp_path)}
    assert {"journal_orbit", "film", "wear_polar"} <= names
    orbit = plot_dataset(wet, "journal_orbit")
    points = orbit.axes[0].collections[0].get_offsets()
    np.testing.assert_allclose(points[:, 0], wet["eccentricity_ratio_x"].values)
    assert np.all(np.hypot(points[:, 0], points[:, 1]) < 1.0)  # inside the clearance circle


def test_a_dry_result_draws_no_film(tmp_path):
    dry = dataset()
    names = {path.stem for path in plot_result(dry, tmp_path)}
    assert not names & {"journal_orbit", "film"}
    with pytest.raises(JointwearError, match="dry joint"):
        plot_dataset(dry, "film")
