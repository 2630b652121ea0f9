"""Every shipped paper config reproduces its row of the reproduction report."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest

import jointwear as jw
from jointwear.errors import WearFeedbackWarning
from jointwear.paper.cases import PAPER_ROWS
from jointwear.paper.reproduce import reproduce

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> dict:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", WearFeedbackWarning)
        return reproduce(tmp_path_factory.mktemp("reproduction"), with_sensitivity=False)


@pytest.mark.parametrize("name", sorted(PAPER_ROWS))
def test_shipped_config_reproduces_its_report_row(report: dict, name: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", WearFeedbackWarning)
        ours = jw.Simulation(jw.load_config(ROOT / "examples" / "paper" / f"{name}.toml")).run()
    summary = ours.summary()
    row = report["cases"][name]
    assert summary["peak_wear_depth_m"] == pytest.approx(row["peak_wear_depth_m"], rel=1e-3)
    assert summary["wear_width_deg"] == pytest.approx(row["wear_width_deg"], rel=1e-3)
    assert summary["wear_mass_kg"] == pytest.approx(row["wear_mass_kg"], rel=1e-3)


def test_calibrated_values_are_shipped(report: dict) -> None:
    config = jw.load_config(ROOT / "examples" / "paper" / "table3_winkler_120rpm.toml")
    for key, value in report["calibration"]["values"].items():
        section, name = key.split(".")
        assert getattr(getattr(config, section), name) == pytest.approx(value, rel=1e-6), key
