"""Running a sweep: local processes equal serial, failed cases, resume, checkpoints."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest
import xarray as xr

from jointwear.errors import ConfigError
from jointwear.workflows.sweep import (
    CASES_CSV,
    DATASET_FILE,
    PLAN_FILE,
    expand_sweep,
    load_plan,
    load_sweep,
    run_sweep,
)
from tests.workflows.sweep.conftest import TINY, comparable, write_sweep


def test_local_processes_equal_serial_exactly(serial, tmp_path):
    plan, reference = serial
    result = run_sweep(plan, tmp_path / "out", workers=2)
    assert result.scheduler == "processes"
    assert comparable(result.records) == comparable(reference.records)


def test_failed_cases_are_recorded_not_fatal(tmp_path):
    path = write_sweep(
        tmp_path,
        TINY
        + """
        "simulation.update_contour" = true
        "simulation.revolutions" = 3
        [grid]
        "materials.bushing.wear_coefficient" = ["5.05e-13 m^2/N", "1e-3 m^2/N"]
        "mechanism.crank_length" = ["70 mm", "250 mm"]
    """,
    )
    plan = load_sweep(path)
    result = run_sweep(plan, tmp_path / "out", workers=2)
    statuses = [r["status"] for r in result.records]
    assert statuses == ["ok", "failed", "ok", "failed"]
    # wear-through ends a case at the wall, with its results
    assert result.records[2]["metrics"]["stopped_by"] == "wall_thickness"
    assert 0 < result.records[2]["metrics"]["life_revolutions"] < 1  # inside the first
    assert "cannot assemble" in result.records[1]["error"]  # invalid combination
    assert all("\n" not in r["error"] for r in result.records)
    with open(tmp_path / "out" / CASES_CSV, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert rows[3]["status"] == "failed"
    assert rows[3]["peak_wear_depth_m"] == ""
    assert "cannot assemble" in rows[3]["error"]
    assert rows[2]["stopped_by"] == "wall_thickness"
    with xr.open_dataset(tmp_path / "out" / DATASET_FILE, engine="h5netcdf") as ds:
        assert np.isnan(ds["peak_wear_depth_m"].values[3])
        assert np.isnan(ds["wear_depth"].values[3]).all()
        assert str(ds["stopped_by"].values[2]) == "wall_thickness"


def test_resume_skips_finished_cases(serial, tmp_path, monkeypatch):
    import jointwear.workflows.sweep.local as local

    plan, reference = serial
    out = tmp_path / "out"
    run_sweep(plan, out, workers=1)
    # lose two records (the sweep was killed before they finished), make one an internal error
    (out / "cases" / "case-0003.json").unlink()
    (out / "cases" / "case-0006.json").unlink()
    record = json.loads((out / "cases" / "case-0001.json").read_text())
    record["status"] = "error"
    (out / "cases" / "case-0001.json").write_text(json.dumps(record))
    (out / CASES_CSV).unlink()
    ran = []
    original = local.run_case
    monkeypatch.setattr(local, "run_case", lambda task: ran.append(task["case"]) or original(task))
    resumed = run_sweep(load_plan(out), out, workers=1, resume=True)
    assert sorted(ran) == ["case-0001", "case-0003", "case-0006"]
    assert resumed.skipped == 5
    assert comparable(resumed.records) == comparable(reference.records)
    assert (out / CASES_CSV).exists()


def test_new_sweep_refuses_an_existing_sweep_directory(serial):
    plan, result = serial
    with pytest.raises(ConfigError, match="already holds a sweep"):
        run_sweep(plan, result.out, workers=1)


def test_sweep_cases_checkpoint_and_resume_mid_case(tmp_path):
    """A case with checkpoint_every resumes from its own checkpoint after an interrupted sweep."""
    from jointwear.checkpoint import Checkpointer
    from jointwear.simulation import Simulation

    path = write_sweep(
        tmp_path,
        TINY
        + """
        "simulation.update_contour" = true
        "simulation.revolutions" = 40
        "simulation.checkpoint_every" = 10
        [grid]
        "joint.clearance" = ["0.05 mm", "0.1 mm"]
    """,
    )
    plan = load_sweep(path)
    reference = run_sweep(plan, tmp_path / "reference", workers=1)
    out = tmp_path / "out"
    # an interrupted sweep: the plan is written, case 0 got to revolution 20
    (out / "cases").mkdir(parents=True)
    (out / PLAN_FILE).write_text(json.dumps(plan.to_dict()))
    config = plan.config(plan.cases[0])
    saver = Checkpointer(out / "cases" / "case-0000", config)
    saver.begin()

    class Stop(Exception):
        pass

    def on_step(state):
        saver(state)
        if state.revolution >= 25:
            raise Stop

    with pytest.raises(Stop):
        Simulation(config).run(on_step=on_step)
    assert saver.load().revolution == 20
    resumed = run_sweep(load_plan(out), out, workers=1, resume=True)
    assert comparable(resumed.records) == comparable(reference.records)
    assert not (out / "cases" / "case-0000").exists()  # checkpoints removed when done


def test_the_largest_case_sets_the_memory_a_sweep_needs(base):
    """A budget the base case fits but a swept finer mesh does not refuses the sweep."""
    from jointwear.resources import check_sweep
    from jointwear.workflows.sweep import checked_progress

    plan = expand_sweep({"grid": {"contact.nodes": [60, 720]}}, base)
    small, large = (check_sweep(2, plan.config(c), "cases", "1 TiB", 1) for c in plan.cases)
    assert small < large
    budget = f"{(small + large) / 2:.0f} B"
    with pytest.raises(ConfigError, match="contact.nodes"):
        checked_progress(plan, workers=1, max_memory=budget)
    same_size = expand_sweep({"grid": {"joint.clearance": ["0.05 mm", "0.1 mm"]}}, base)
    checked_progress(same_size, workers=1, max_memory=budget)


def test_the_progress_stops_at_the_time_limit_naming_the_resume(base):
    from jointwear.errors import TimeLimitError
    from jointwear.workflows.sweep import checked_progress

    plan = expand_sweep({"grid": {"joint.clearance": ["0.05 mm", "0.1 mm"]}}, base)
    seen = []
    progress = checked_progress(
        plan, lambda done, total: seen.append(done), time_limit=0.0, resume="go on"
    )
    progress(2, 2)  # finished: nothing to stop
    with pytest.raises(TimeLimitError, match=r"after 1 of 2 cases; continue with `go on`"):
        progress(1, 2)
    assert seen == [2, 1]


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        ({"workers": 0}, "--workers: must be >= 1"),
        ({"workers": 2, "scheduler": "tcp://127.0.0.1:9"}, "--workers: a dask cluster"),
        ({"sweep_file": "sweep", "resume": "out"}, "--resume: give either SWEEP_FILE"),
        ({"resume": "out", "out": "other"}, "--out: a resumed sweep writes"),
        ({}, "SWEEP_FILE: missing"),
        ({"sweep_file": "sweep"}, "--out: missing"),
    ],
)
def test_sweep_to_folder_refuses_conflicting_options(tmp_path, arguments, message):
    from jointwear.workflows.sweep import sweep_to_folder

    paths = {
        "sweep": write_sweep(tmp_path, '[grid]\n"joint.clearance" = [1e-4]'),
        "out": tmp_path / "out",
        "other": tmp_path / "other",
    }
    arguments = {
        key: paths[value] if key in ("sweep_file", "resume", "out") else value
        for key, value in arguments.items()
    }
    with pytest.raises(ConfigError, match=message):
        sweep_to_folder(**arguments)
    assert not (tmp_path / "out").exists()
    assert not (tmp_path / "other").exists()
