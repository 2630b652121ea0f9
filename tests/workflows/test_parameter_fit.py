"""Calibration recovers known parameters; the paper row is matched exactly."""

from __future__ import annotations

import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.paper.protocol import CALIBRATION_PARAMETERS
from jointwear.workflows.parameter_fit import Parameter, calibrate_metrics


def test_recovers_known_parameters(paper_config: Config) -> None:
    base = paper_config.replace({"contact.nodes": 180, "simulation.steps_per_revolution": 120})
    truth = {
        "joint.axial_length": 0.024,
        "joint.bushing_thickness": 0.0021,
        "mechanism.spring_preload": 60.0,
    }
    summary = Simulation(base.replace(truth)).run().summary()
    targets = {k: summary[k] for k in ("peak_wear_depth_m", "wear_width_deg", "wear_mass_kg")}
    fit = calibrate_metrics(base, targets, CALIBRATION_PARAMETERS)
    for key, value in truth.items():
        assert fit.values[key] == pytest.approx(value, rel=0.01), key
    assert fit.rms_residual < 1e-6


def test_recovers_the_wear_coefficient_from_mass(paper_config: Config) -> None:
    base = paper_config.replace({"contact.nodes": 120, "simulation.steps_per_revolution": 90})
    summary = (
        Simulation(base.replace({"materials.bushing.wear_coefficient": 2e-13})).run().summary()
    )
    fit = calibrate_metrics(
        base,
        {"wear_mass_kg": summary["wear_mass_kg"]},
        [Parameter("materials.bushing.wear_coefficient", 1e-15, 1e-10)],
    )
    assert fit.values["materials.bushing.wear_coefficient"] == pytest.approx(2e-13, rel=1e-4, abs=0)


def test_bad_bounds_and_keys(paper_config: Config) -> None:
    with pytest.raises(ConfigError, match="joint.axial_length"):
        Parameter("joint.axial_length", 1.0, 0.5)
    with pytest.raises(ConfigError, match="joint.nope"):
        calibrate_metrics(paper_config, {"wear_mass_kg": 1e-9}, [Parameter("joint.nope", 1, 2)])
