"""The summary: the scalar results of a run, from one metric schema, checks when asked."""

from __future__ import annotations

import warnings

import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import MaterialLimitWarning
from jointwear.record import WALL_CLOCK_KEYS
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
            assert data[metric.key] == pytest.approx(last * metric.scale, rel=1e-15, abs=0)
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


def test_compile_time_is_reported_apart_from_the_run_time(paper_config, monkeypatch, tmp_path):
    """numba's compile seconds (a counter that gains 1 s per reading here): the set-up's and
    the loop's in ``compile_time_s``, the loop's taken off ``runtime_s``; kept by the file."""
    from itertools import count

    from jointwear import compile_time
    from jointwear.results.wear_result import read_wear_result

    readings = count()
    monkeypatch.setattr(compile_time, "compile_seconds", lambda: float(next(readings)))
    config = paper_config.replace({"simulation.steps_per_revolution": 60})
    result = Simulation(config).run(pressures=False)
    summary = result.summary()
    # readings: set-up 0 -> 1 (1 s), loop 2 -> 3 (1 s)
    assert summary["compile_time_s"] == 2.0
    assert summary["runtime_without_compile_s"] == pytest.approx(summary["runtime_s"] - 1.0)
    result.to_netcdf(tmp_path / "result.nc")
    again = read_wear_result(tmp_path / "result.nc").summary()
    assert {k: again[k] for k in WALL_CLOCK_KEYS} == {k: summary[k] for k in WALL_CLOCK_KEYS}
