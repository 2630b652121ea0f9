"""The summary: the scalar results of a run, from one metric schema, checks when asked."""

from __future__ import annotations

import warnings

import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import MaterialLimitWarning
from jointwear.results import write_metrics_csv
from jointwear.tribology.metrics import WEAR_METRICS, engineering_checks


def test_one_metric_schema_drives_record_dataset_summary_and_csv(
    paper_config: Config, tmp_path
) -> None:
    small = paper_config.replace({"contact.nodes": 120, "simulation.steps_per_revolution": 90})
    result = Simulation(
        small.replace(
            {
                "simulation.update_contour": True,
                "simulation.revolutions": 20,
                "simulation.update_every": 5,
            }
        )
    ).run()
    data = result.summary()
    for metric in WEAR_METRICS:
        assert result.dataset[metric.name].attrs["units"] == metric.units
        if metric.key is not None:
            last = float(result.dataset[metric.name].values[-1])
            assert data[metric.key] == pytest.approx(last * metric.scale, rel=1e-15)
    write_metrics_csv(result.dataset, tmp_path / "m.csv")
    header = (tmp_path / "m.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    assert header == ["revolution"] + [m.header for m in WEAR_METRICS]


def test_the_summary_with_checks_is_the_summary_and_the_checks(paper_config: Config) -> None:
    """``summary(checks=True)``, the object ``run --json`` prints: the plain summary, with
    the engineering checks of the most worn joint added (and nothing else changed)."""
    result = Simulation(paper_config.replace({"simulation.revolutions": 10})).run()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MaterialLimitWarning)
        checked = result.summary(checks=True)
        expected = engineering_checks(result.joint_data(), result.config, warn=False)
    plain = result.summary()
    assert checked.pop("checks") == expected
    assert checked == plain
    assert "checks" not in plain
