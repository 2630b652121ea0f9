"""Fixtures of the hostile-input suite."""

from __future__ import annotations

import pytest

from jointwear import Simulation, load_config
from jointwear.results import write_netcdf
from tests.hostile.harness import PAPER


@pytest.fixture(scope="session")
def result_bytes(tmp_path_factory) -> bytes:
    """A real (tiny) result.nc."""
    config = load_config(PAPER, {"contact.nodes": 60, "simulation.steps_per_revolution": 60})
    path = tmp_path_factory.mktemp("result") / "result.nc"
    write_netcdf(Simulation(config).run().dataset, path)
    return path.read_bytes()
