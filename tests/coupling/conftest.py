"""Shared fixtures of the coupling tests: the paper's joint on a coarse mesh."""

from __future__ import annotations

import warnings

import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import WearFeedbackWarning


@pytest.fixture(scope="module")
def small(paper_config: Config) -> Config:
    return paper_config.replace(
        {
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 90,
            "contact.model": "asymmetric-winkler",
        }
    )


def simulate(config: Config, pressures: bool = True):
    """The result of a run (the worn joint's load warnings are not the question here)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", WearFeedbackWarning)
        return Simulation(config).run(pressures=pressures)


def summary(config: Config) -> dict:
    return simulate(config).summary()
