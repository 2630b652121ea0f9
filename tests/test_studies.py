"""The studies behind the documentation's pages (docs/studies/): each run is a valid
configuration and runs (two revolutions each; the whole studies take minutes)."""

from __future__ import annotations

import importlib.util
import warnings
from pathlib import Path

import numpy as np
import pytest

import jointwear as jw

STUDY = Path(__file__).resolve().parents[1] / "docs" / "studies" / "wear_feedback.py"


@pytest.fixture(scope="module")
def study():
    spec = importlib.util.spec_from_file_location("wear_feedback_study", STUDY)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def short(study, overrides: dict) -> jw.WearResult:
    config = jw.load_config(study.PAPER, overrides={**overrides, "simulation.revolutions": 2})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return jw.Simulation(config).run(pressures=False)


def test_every_long_run_of_the_wear_feedback_study_runs(study) -> None:
    runs = study.long_runs()
    for group in runs.values():
        for overrides in group.values():
            summary = short(study, overrides).summary()
            assert summary["revolutions"] == 2
            assert summary["peak_wear_depth_m"] > 0.0


def test_the_separating_joint_keeps_the_papers_contact_law_on_its_coarse_mesh(study) -> None:
    """NLCP's mesh-independent form on 180 nodes wears as the paper's form on 360 (1°)."""
    coarse = study.long_runs()["separating"]["uncoupled"]
    fine = {**coarse, "contact.nodes": 360, "contact.nlcp_variant": "paper"}
    config = jw.load_config(study.PAPER, overrides=coarse)
    assert config.contact.model == "nlcp"
    assert config.contact.nodes == 180
    masses = [short(study, o).summary()["wear_mass_kg"] for o in (coarse, fine)]
    assert masses[0] == pytest.approx(masses[1], rel=1e-4, abs=0)  # (2x with the paper form)


def test_the_clearance_runs_are_valid(study) -> None:
    for spring in study.SPRINGS:
        for model in study.DYNAMICS:
            config = jw.load_config(
                study.PAPER, overrides=study.clearance_run(spring, model, study.CLEARANCES[-1])
            )
            assert config.dynamics.model == model
            assert np.isclose(config.joint.clearance, study.CLEARANCES[-1] * 1e-3, atol=0)
