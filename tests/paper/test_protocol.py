"""The calibration protocol: one paper row, its three metrics, the undisclosed parameters."""

from __future__ import annotations

import pytest

from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.measurement.parameter_fit import resolve_parameter
from jointwear.paper.protocol import (
    CALIBRATION_CASE,
    CALIBRATION_PARAMETERS,
    calibrate_paper_row,
)

KD = "materials.bushing.wear_coefficient"


def test_paper_row_is_the_reproduction_protocol(
    paper_config: Config, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Config, targets and parameters of the reproduction's calibration (and of other rows)."""
    import jointwear.paper.protocol as protocol

    calls: list[tuple] = []

    def record(config: Config, targets: dict, parameters: list, initial: object = None) -> str:
        calls.append((config, dict(targets), list(parameters)))
        return "fitted"

    monkeypatch.setattr(protocol, "calibrate_metrics", record)
    coarse = {"contact.nodes": 90}
    # the reproduction's call: the calibration row, all three parameters and metrics
    assert calibrate_paper_row(overrides=coarse) == "fitted"
    assert calibrate_paper_row(CALIBRATION_CASE, overrides=coarse) == "fitted"
    assert calls[0] == calls[1]
    assert calls[0][0].contact.nodes == 90
    assert calls[0][1] == {
        "peak_wear_depth_m": 1.056e-8,
        "wear_width_deg": 115,
        "wear_mass_kg": 3.355e-9,
    }
    assert calls[0][2] == list(CALIBRATION_PARAMETERS)
    # fewer free parameters (the sensitivity's variants): as many metrics, mass first
    calibrate_paper_row(parameters=CALIBRATION_PARAMETERS[2:], metrics=1)
    assert calls[2][1] == {"wear_mass_kg": 3.355e-9}
    # another row, other parameters, a config of one's own
    own = paper_config.replace({"mechanism.crank_speed": "240 rpm"})
    calibrate_paper_row(
        "table3_winkler_240rpm", [resolve_parameter("wear_coefficient", own)], config=own
    )
    config, targets, parameters = calls[3]
    assert config == own
    assert targets["wear_width_deg"] == 118
    assert [p.key for p in parameters] == [KD]
    with pytest.raises(ConfigError, match="did you mean 'table3_winkler_120rpm'"):
        calibrate_paper_row("table3_winkler_120")
    with pytest.raises(ConfigError, match="metrics"):
        calibrate_paper_row(metrics=4)


def test_a_paper_row_calibration_refuses_measurements_and_unknown_rows(tmp_path) -> None:
    from jointwear.paper.protocol import paper_row_calibration

    with pytest.raises(ConfigError, match="--paper-row: fits the paper's table"):
        paper_row_calibration(CALIBRATION_CASE, measured=[tmp_path / "worn.csv"])
    with pytest.raises(ConfigError, match="did you mean 'table3_winkler_120rpm'"):
        paper_row_calibration("table3_winkler_120")
