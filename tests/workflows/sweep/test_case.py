"""One case: the material checks of `run`, as values, ratios and exceeded limits."""

from __future__ import annotations

import csv
import json

import pytest
import xarray as xr

from jointwear.cli import main
from jointwear.workflows.sweep import CASES_CSV, DATASET_FILE, load_sweep
from tests.conftest import strict_json
from tests.workflows.sweep.conftest import TINY, write_sweep

# ---------------------------------------------------------------- material checks


def test_cases_carry_the_checks_of_run(tmp_path, capsys):
    """Each case has the material checks `run --json` reports for its config (the same
    function), as values, ratios to the limits and the exceeded checks, and the sweep
    counts the cases that exceed a limit."""
    from jointwear.simulation import Simulation
    from jointwear.tribology.metrics import engineering_checks
    from jointwear.workflows.sweep import CHECK_COLUMNS

    path = write_sweep(
        tmp_path,
        TINY
        + """
        "materials.bushing.max_pv" = "0.035 MPa*m/s"
        "materials.bushing.max_static_pressure" = "3 MPa"
        "materials.bushing.max_sliding_speed" = "0.1 m/s"
        [grid]
        "mechanism.crank_speed" = ["60 rpm", "240 rpm", "480 rpm"]
    """,
    )
    out = tmp_path / "out"
    main(["sweep", str(path), "--out", str(out), "--json", "--workers", "1"])
    printed = strict_json(capsys.readouterr().out)
    plan = load_sweep(path)
    records = [json.loads((out / "cases" / f"{case.name}.json").read_text()) for case in plan.cases]
    exceeded = []
    for case, record in zip(plan.cases, records, strict=True):
        result = Simulation(plan.config(case)).run()
        checks = engineering_checks(result.joint_data(), result.config, warn=False)
        metrics = record["metrics"]
        for check, column in CHECK_COLUMNS.items():
            assert metrics[column] == pytest.approx(checks[check]["value"], rel=1e-9)
            limit = checks[check]["limit"]
            expected = None if limit is None else checks[check]["value"] / limit
            assert metrics[f"{check}_ratio"] == pytest.approx(expected, rel=1e-9)
        failing = [c for c in CHECK_COLUMNS if checks[c]["ok"] is False]
        assert metrics["exceeded_limits"].split() == failing
        ratios = [metrics[f"{c}_ratio"] for c in CHECK_COLUMNS if metrics[f"{c}_ratio"]]
        assert metrics["worst_limit_ratio"] == max(ratios)
        assert (metrics["worst_limit_ratio"] > 1) == bool(failing)
        exceeded.append(failing)
    # PV grows with the speed: within the limit at 60 rpm, beyond it at 480 rpm
    assert exceeded[0] == []
    assert "pv" in exceeded[-1]
    assert any("max_pv" in w for w in records[-1]["warnings"])
    assert printed["limits_checked"] == 3
    assert printed["limits_exceeded"] == sum(bool(e) for e in exceeded)
    assert printed["limits_exceeded_by"]["pv"] == sum("pv" in e for e in exceeded)
    with xr.open_dataset(out / DATASET_FILE, engine="h5netcdf") as ds:
        assert ds["pv_pa_m_s"].attrs["units"] == "Pa*m/s"
        assert "max_pv" in ds["pv_ratio"].attrs["long_name"]
        assert ds["worst_limit_ratio"].attrs["units"] == "1"
        assert list(ds["exceeded_limits"].values) == [" ".join(e) for e in exceeded]
    with open(out / CASES_CSV, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert float(rows[-1]["pv_ratio"]) == records[-1]["metrics"]["pv_ratio"]


def test_every_check_with_a_limit_has_its_columns():
    from jointwear.tribology.metrics import CHECKS
    from jointwear.workflows.sweep import CASE_RESULTS, CHECK_COLUMNS

    assert set(CHECK_COLUMNS) == {name for name, check in CHECKS.items() if check.limit_key}
    for check, column in CHECK_COLUMNS.items():
        assert CASE_RESULTS[column][0] == CHECKS[check].unit
        assert CASE_RESULTS[f"{check}_ratio"][0] == "1"


def test_cases_without_limits_have_no_ratios(serial):
    """The paper's bushing names no limits: values are reported, no ratio, none exceeded."""
    _, result = serial
    for record in result.records:
        metrics = record["metrics"]
        assert metrics["pv_pa_m_s"] > 0
        assert metrics["peak_pressure_pa"] is None  # no limit asks for the pressure field
        assert metrics["worst_limit_ratio"] is None
        assert metrics["exceeded_limits"] == ""
    summary = result.summary()
    assert summary["limits_checked"] == summary["limits_exceeded"] == 0
