"""Calibration workflows: the wear coefficient recovered from measured files, the contact
laws fitted to a reference, and the checks that come before any simulation."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import jointwear as jw
from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.measurement.synthetic import synthesize_measurement
from jointwear.workflows import parameter_fit
from jointwear.workflows.calibration import (
    calibrate_contact_laws,
    calibrate_to_measurements,
)

KD = "materials.bushing.wear_coefficient"
TRUE_KD = 3e-12
FAST = {
    "contact.nodes": 180,
    "simulation.steps_per_revolution": 60,
    "simulation.revolutions": 3000,
    "simulation.update_contour": False,
}


def measurement(config: Config, path: Path, seed: int) -> Path:
    depth = Simulation(config.replace({KD: TRUE_KD})).run().wear_depth
    x, y = synthesize_measurement(depth, config.bushing_radius, 2000, 0.5e-6, seed, (5e-3, 1e-3))
    rows = "".join(f"{a * 1e3:.7f},{b * 1e3:.7f}\n" for a, b in zip(x, y, strict=True))
    path.write_text("x [mm],y [mm]\n" + rows, encoding="utf-8")
    return path


@pytest.mark.filterwarnings("ignore::jointwear.errors.WearFeedbackWarning")
def test_the_wear_coefficient_is_recovered_from_two_measured_bushings(paper_config, tmp_path):
    config = paper_config.replace(FAST)
    path = tmp_path / "joint.toml"
    path.write_text(config.replace({KD: 10 * TRUE_KD}).to_toml(), encoding="utf-8")
    worn = measurement(config, tmp_path / "worn.csv", seed=3)
    outcome = calibrate_to_measurements(path, [worn, worn], [f"{KD}=1e-13..1e-10"])
    summary = outcome.summary()
    fitted = summary["parameters"][KD]
    assert fitted["value"] == pytest.approx(TRUE_KD, rel=0.02, abs=0)
    assert fitted["interval"][0] < TRUE_KD < fitted["interval"][1]
    assert [case["name"] for case in summary["cases"]] == ["worn.csv", "worn.csv#2"]


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        ({"config": None}, "CONFIG: missing"),
        ({"config": "worn.csv"}, "looks like a measurement"),
        ({"fit": []}, "--fit: name at least one parameter"),
        ({"fit": ["wear_coefficient", KD]}, "--fit: a parameter is named twice"),
        ({"circle_fit": "ransac"}, "--circle-fit: unknown circle fit"),
        ({"noise": "-1 um"}, "--noise: must be > 0"),
        ({"measured": []}, "MEASURED: give at least one measured file"),
    ],
)
def test_bad_calibrations_are_refused_before_a_simulation(
    paper_config_path, tmp_path, arguments, message
):
    arguments = {"config": paper_config_path, "measured": [tmp_path / "x.csv"], **arguments}
    if arguments["config"] == "worn.csv":
        arguments["config"] = tmp_path / "worn.csv"
    fit = arguments.pop("fit", ["wear_coefficient"])
    with pytest.raises(ConfigError, match=message):
        calibrate_to_measurements(
            arguments.pop("config"), arguments.pop("measured"), fit, **arguments
        )


def test_contact_laws_fitted_to_the_exact_reference(paper_config_path):
    """Winkler's stiffness fitted to Persson's exact pressure: a positive stiffness, and the
    fit's JSON names the reference and the loads in newtons."""
    laws = calibrate_contact_laws(
        "persson", "100 N,0.2 kN", config=paper_config_path, overrides=["contact.nodes=180"]
    )
    summary = laws.summary()
    assert (summary["reference"], summary["loads_n"]) == ("persson", [100.0, 200.0])
    assert set(summary["fits"]) >= {"winkler"}
    winkler = laws.fits["winkler"]
    assert all(v > 0 and math.isfinite(v) for v in winkler.values.values())


def test_contact_laws_refuse_an_unknown_reference_and_measured_files(tmp_path):
    with pytest.raises(ConfigError, match="--reference: unknown reference 'pers'"):
        calibrate_contact_laws("pers", "100 N")
    with pytest.raises(ConfigError, match="not measured files"):
        calibrate_contact_laws("fem", "100 N", measured=[tmp_path / "worn.csv"])


def test_jw_calibration_keeps_the_least_squares_names():
    assert jw.calibration.__name__ == "jointwear.workflows.calibration"
    for name in ("Parameter", "CalibrationResult", "calibrate", "calibrate_metrics"):
        assert getattr(jw.calibration, name) is getattr(parameter_fit, name)
