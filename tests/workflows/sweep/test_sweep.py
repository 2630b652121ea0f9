"""Parameter sweeps: expansion, local processes vs a real dask LocalCluster, failures, resume."""

from __future__ import annotations

import csv
import json
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jointwear import load_config
from jointwear.cli import main
from jointwear.errors import ConfigError, DataError
from jointwear.workflows.sweep import (
    CASES_CSV,
    DATASET_FILE,
    METRICS,
    PLAN_FILE,
    SweepPlan,
    expand_sweep,
    load_plan,
    load_sweep,
    run_sweep,
)
from tests.conftest import strict_json

REPO = Path(__file__).resolve().parents[3]
PAPER = REPO / "tests" / "data" / "paper_joint.toml"
#: a coarse mesh: NLCP in its mesh-independent form (the paper's needs 1 degree nodes)
TINY = """
[set]
"contact.nodes" = 60
"contact.nlcp_variant" = "mesh-independent"
"simulation.steps_per_revolution" = 60
"""


@pytest.fixture(scope="module")
def base():
    return load_config(
        PAPER,
        {
            "contact.nodes": 60,
            "contact.nlcp_variant": "mesh-independent",
            "simulation.steps_per_revolution": 60,
        },
    )


def write_sweep(folder: Path, body: str, base: str = "base.toml") -> Path:
    (folder / "base.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    path = folder / "sweep.toml"
    path.write_text(f'base = "{base}"\n' + textwrap.dedent(body), encoding="utf-8")
    return path


def comparable(records):
    """Records without the wall-clock run time."""
    out = []
    for record in records:
        record = dict(record)
        record["metrics"] = {
            k: v for k, v in (record.get("metrics") or {}).items() if k != "runtime_s"
        }
        out.append(record)
    return out


# ---------------------------------------------------------------- expansion


def test_grid_is_the_cartesian_product_in_file_order(base):
    plan = expand_sweep(
        {
            "grid": {
                "joint.clearance": ["0.05 mm", "0.1 mm", 2e-4],
                "mechanism.crank_speed": ["120 rpm", "240 rpm"],
            }
        },
        base,
    )
    assert plan.keys == ["joint.clearance", "mechanism.crank_speed"]
    assert [c.overrides for c in plan.cases][:3] == [
        {"joint.clearance": "0.05 mm", "mechanism.crank_speed": "120 rpm"},
        {"joint.clearance": "0.05 mm", "mechanism.crank_speed": "240 rpm"},
        {"joint.clearance": "0.1 mm", "mechanism.crank_speed": "120 rpm"},
    ]
    assert len(plan.cases) == 6
    assert plan.config(plan.cases[5]).joint.clearance == pytest.approx(2e-4)
    assert plan.config(plan.cases[5]).mechanism.crank_speed == pytest.approx(8 * np.pi)


def test_zip_goes_row_by_row_and_multiplies_the_grid(base):
    plan = expand_sweep(
        {
            "grid": {"joint": {"clearance": ["0.05 mm", "0.1 mm"]}},  # nested table form
            "zip": {"contact.model": ["winkler", "nlcp"], "contact.exponent": [1.0, 1.5]},
        },
        base,
    )
    assert len(plan.cases) == 4
    assert plan.cases[1].overrides == {
        "joint.clearance": "0.05 mm",
        "contact.model": "nlcp",
        "contact.exponent": 1.5,
    }


def test_zip_lists_of_different_length_fail(base):
    with pytest.raises(ConfigError, match=r"\[zip\] lists must have the same length"):
        expand_sweep(
            {"zip": {"contact.model": ["winkler", "nlcp"], "contact.exponent": [1.0]}}, base
        )


def test_samples_are_seeded_and_reproducible(base):
    spec = {
        "sample": {
            "materials.bushing.wear_coefficient": {
                "distribution": "lognormal",
                "median": "5.05e-13 m^2/N",
                "sigma": 0.5,
            },
            "joint.clearance": {"distribution": "uniform", "low": "0.05 mm", "high": "0.2 mm"},
            "contact.nodes": {"distribution": "loguniform", "low": 40, "high": 90},
            "mechanism.spring_preload": {"distribution": "normal", "mean": "20 N", "std": "1 N"},
            "contact.model": {"distribution": "choice", "values": ["winkler", "nlcp"]},
        },
        "samples": 50,
        "seed": 7,
    }
    first, again = expand_sweep(spec, base), expand_sweep(spec, base)
    assert [c.overrides for c in first.cases] == [c.overrides for c in again.cases]
    other = expand_sweep({**spec, "seed": 8}, base)
    assert [c.overrides for c in first.cases] != [c.overrides for c in other.cases]
    k = np.array([c.overrides["materials.bushing.wear_coefficient"] for c in first.cases])
    assert 1e-13 < np.median(k) < 2e-12  # SI (1/Pa), around the median
    clearance = np.array([c.overrides["joint.clearance"] for c in first.cases])
    assert clearance.min() >= 5e-5
    assert clearance.max() <= 2e-4
    assert all(isinstance(c.overrides["contact.nodes"], int) for c in first.cases)
    assert {c.overrides["contact.model"] for c in first.cases} == {"winkler", "nlcp"}
    assert all(c.invalid is None for c in first.cases)


def test_samples_and_seed_may_follow_the_sample_table(tmp_path):
    path = write_sweep(
        tmp_path,
        TINY
        + """
        [sample]
        "joint.clearance" = {distribution = "uniform", low = "0.05 mm", high = "0.2 mm"}
        samples = 3
        seed = 2
    """,
    )
    plan = load_sweep(path)
    assert len(plan.cases) == 3
    assert plan.seed == 2


def test_set_applies_to_every_case(tmp_path):
    plan = load_sweep(
        write_sweep(
            tmp_path,
            TINY
            + """
        [grid]
        "joint.clearance" = ["0.05 mm", "0.1 mm"]
    """,
        )
    )
    assert plan.base.contact.nodes == 60
    assert all(plan.config(c).simulation.revolutions == 1 for c in plan.cases)


@pytest.mark.parametrize(
    ("body", "message"),
    [
        ('[grid]\n"joint.clearnce" = [1e-4]', "unknown key 'clearnce'.*did you mean 'clearance'"),
        ('[grid]\n"jont.clearance" = [1e-4]', "did you mean 'joint'"),
        ('[grid]\n"joint.clearance" = ["5 kg"]', r"\[grid\] joint.clearance = '5 kg'.*dimension"),
        ('[grid]\n"joint.clearance" = 1e-4', "expected a list of values"),
        ('[grid]\n"joint.clearance" = []', "empty"),
        ('[grid]\n"contact.model" = ["nlcpp"]', "did you mean 'nlcp'"),
        ('[grids]\n"joint.clearance" = [1e-4]', "unknown key 'grids'.*did you mean 'grid'"),
        ("samples = 3", "given without a .sample. table"),
        (
            '[sample]\n"joint.clearance" = {distribution = "gauss", mean = 1}\nsamples = 2',
            "unknown distribution 'gauss'",
        ),
        (
            '[sample]\n"joint.clearance" = {distribution = "uniform", low = 1e-4}\nsamples = 2',
            "high missing",
        ),
        (
            '[sample]\n"joint.clearance" = {distribution = "uniform", low = 2e-4, high = 1e-4}\n'
            "samples = 2",
            "low < high",
        ),
        (
            '[sample]\n"joint.clearance" = {distribution = "uniform", low = "1 kg", high = 1}\n'
            "samples = 2",
            "dimension",
        ),
        (
            '[sample]\n"contact.model" = {distribution = "uniform", low = 1, high = 2}\n'
            "samples = 2",
            "use 'choice'",
        ),
        (
            '[grid]\n"joint.clearance" = [1e-4]\n[zip]\n"joint.clearance" = [1e-4]',
            "appears in both",
        ),
        ('[grid]\n"joint" = [1]', "is a section"),
        ("", "nothing to sweep"),
    ],
)
def test_bad_sweep_files_fail_before_running(tmp_path, body, message):
    path = write_sweep(tmp_path, body)
    with pytest.raises(ConfigError, match=message) as info:
        load_sweep(path)
    assert str(info.value).startswith(str(path))
    assert "\n" not in str(info.value)


def test_missing_base_names_the_file(tmp_path):
    path = write_sweep(tmp_path, '[grid]\n"joint.clearance" = [1e-4]', base="nope.toml")
    with pytest.raises(ConfigError, match=r"base = 'nope.toml'.*nope.toml: file not found"):
        load_sweep(path)


# ---------------------------------------------------------------- running

SWEEP_BODY = (
    TINY
    + """
    [grid]
    "joint.clearance" = ["0.05 mm", "0.2 mm"]
    "mechanism.crank_speed" = ["120 rpm", "240 rpm"]
    [zip]
    "contact.model" = ["winkler", "nlcp"]
    "contact.exponent" = [1.0, 1.5]
"""
)


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    folder = tmp_path_factory.mktemp("serial")
    plan = load_sweep(write_sweep(folder, SWEEP_BODY))
    return plan, run_sweep(plan, folder / "out", workers=1)


def test_serial_sweep_writes_cases_csv_and_dataset(serial):
    _, result = serial
    out = result.out
    assert result.scheduler == "serial"
    assert result.counts == {"ok": 8, "failed": 0, "error": 0}
    with open(out / CASES_CSV, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 8
    header = list(rows[0])
    assert header[:5] == [
        "case",
        "joint.clearance [m]",
        "mechanism.crank_speed [rad/s]",
        "contact.model",
        "contact.exponent",
    ]
    assert header[5:] == [*METRICS, "status", "error"]
    assert float(rows[-1]["joint.clearance [m]"]) == pytest.approx(2e-4)
    assert rows[1]["contact_model"] == "nlcp"
    assert float(rows[0]["peak_wear_depth_m"]) == result.records[0]["metrics"]["peak_wear_depth_m"]
    with xr.open_dataset(out / DATASET_FILE, engine="h5netcdf") as ds:
        assert ds.sizes == {"case": 8, "theta": 60}
        assert ds["wear_depth"].attrs["units"] == "m"
        assert ds["joint.clearance"].attrs["units"] == "m"
        np.testing.assert_array_equal(
            ds["peak_wear_depth_m"].values,
            [r["metrics"]["peak_wear_depth_m"] for r in result.records],
        )
        np.testing.assert_array_equal(
            ds["wear_depth"].values.max(axis=1), ds["peak_wear_depth_m"].values
        )
        assert list(ds["status"].values) == ["ok"] * 8
    assert not [p for p in out.rglob(".*")]  # no temporary files


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
    import jointwear.workflows.sweep as sweep_module

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
    original = sweep_module.run_case
    monkeypatch.setattr(
        sweep_module, "run_case", lambda task: ran.append(task["case"]) or original(task)
    )
    resumed = run_sweep(load_plan(out), out, workers=1, resume=True)
    assert sorted(ran) == ["case-0001", "case-0003", "case-0006"]
    assert resumed.skipped == 5
    assert comparable(resumed.records) == comparable(reference.records)
    assert (out / CASES_CSV).exists()


def test_stored_plan_gives_the_same_case_configs(base):
    """Derived defaults (rod inertia, spring area) follow the swept keys after --resume too."""
    plan = expand_sweep(
        {
            "grid": {
                "mechanism.rod_mass": ["1 kg", "3 kg"],
                "joint.axial_length": ["10 mm", "30 mm"],
            }
        },
        base,
    )
    again = SweepPlan.from_dict(json.loads(json.dumps(plan.to_dict())), "plan")
    configs = [plan.config(c) for c in plan.cases]
    assert [again.config(c).to_dict() for c in again.cases] == [c.to_dict() for c in configs]
    assert configs[0].spring_area != configs[1].spring_area
    assert (
        configs[0].mechanism.rod_centroidal_inertia != configs[2].mechanism.rod_centroidal_inertia
    )


def test_new_sweep_refuses_an_existing_sweep_directory(serial):
    plan, result = serial
    with pytest.raises(ConfigError, match="already holds a sweep"):
        run_sweep(plan, result.out, workers=1)


def test_cli_sweep_resume(tmp_path, capsys):
    path = write_sweep(tmp_path, TINY + '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n')
    out = tmp_path / "out"
    main(["sweep", str(path), "--out", str(out), "--json", "--workers", "1"])
    first = json.loads(capsys.readouterr().out)
    assert first["ok"] == 2
    (out / "cases" / "case-0001.json").unlink()
    main(["sweep", "--resume", str(out), "--json", "--workers", "1"])
    second = json.loads(capsys.readouterr().out)
    assert second["skipped"] == 1
    assert second["ok"] == 2
    assert json.loads((out / PLAN_FILE).read_text())["keys"] == ["joint.clearance"]


def test_resume_of_a_non_sweep_directory(tmp_path):
    with pytest.raises(DataError, match="not a sweep directory"):
        load_plan(tmp_path)


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


def test_missing_dask_is_a_one_line_error(tmp_path, monkeypatch, serial):
    plan, _ = serial
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    with pytest.raises(ConfigError, match=r"dask.distributed is not installed.*jointwear\[sweep\]"):
        run_sweep(plan, tmp_path / "out", scheduler="tcp://127.0.0.1:8786")
    assert not (tmp_path / "out").exists()


def test_unreachable_scheduler_leaves_nothing_behind(tmp_path, serial):
    pytest.importorskip("dask.distributed")
    plan, _ = serial
    with pytest.raises(ConfigError, match="--scheduler: cannot connect to tcp://127.0.0.1:9"):
        run_sweep(plan, tmp_path / "out", scheduler="tcp://127.0.0.1:9", connect_timeout=0.5)
    assert not (tmp_path / "out").exists()


# ---------------------------------------------------------------- dask (last: its threads
# make later local pools start by forkserver instead of fork)


def test_dask_local_cluster_equals_serial_exactly(serial, tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    plan, reference = serial
    with (
        distributed.LocalCluster(
            n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        result = run_sweep(plan, tmp_path / "out", client=client)
    assert result.scheduler.startswith("tcp://")
    assert comparable(result.records) == comparable(reference.records)
    with (
        xr.open_dataset(tmp_path / "out" / DATASET_FILE, engine="h5netcdf") as ds,
        xr.open_dataset(reference.out / DATASET_FILE, engine="h5netcdf") as ref,
    ):
        np.testing.assert_array_equal(ds["wear_depth"].values, ref["wear_depth"].values)


def test_cli_sweep_on_a_dask_scheduler(tmp_path, capsys):
    distributed = pytest.importorskip("dask.distributed")
    path = write_sweep(tmp_path, TINY + '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n')
    with distributed.LocalCluster(
        n_workers=1, processes=False, threads_per_worker=2, dashboard_address=None
    ) as cluster:
        main(
            [
                "sweep",
                str(path),
                "--out",
                str(tmp_path / "out"),
                "--json",
                "--scheduler",
                cluster.scheduler_address,
            ]
        )
    summary = json.loads(capsys.readouterr().out)
    assert summary["scheduler"] == cluster.scheduler_address
    assert summary["ok"] == 2


@pytest.mark.parametrize(
    ("case_seconds", "remaining", "cpus", "method", "workers"),
    [
        (0.01, 7, 2, "fork", 1),  # 0.07 s of work: starting workers costs more
        (0.05, 63, 2, "fork", 2),  # 3 s of work: half of it saved on two processes
        (0.05, 63, 1, "fork", 1),  # one processor: nothing to share
        (0.05, 63, 8, "fork", 8),
        (0.5, 3, 8, "fork", 3),  # never more workers than cases
        (5.0, 1, 8, "fork", 1),  # one case left: it runs here
        (0.05, 63, 2, "spawn", 1),  # 3 s of work cannot pay for fresh interpreters
        (0.5, 63, 2, "spawn", 2),
        (0.5, 63, 2, "forkserver", 2),
    ],
)
def test_default_workers_pay_for_their_start(case_seconds, remaining, cpus, method, workers):
    from jointwear.workflows.sweep import WORKER_START, default_workers

    assert default_workers(case_seconds, remaining, cpus, method) == workers
    if workers > 1:  # parallel: the estimated time beats running here
        start = WORKER_START[method]
        assert start + case_seconds * remaining / workers < case_seconds * remaining


def test_small_sweep_by_default_runs_here_and_says_so(tmp_path, capsys):
    path = write_sweep(tmp_path, TINY + '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n')
    main(["sweep", str(path), "--out", str(tmp_path / "out"), "--json"])
    summary = json.loads(capsys.readouterr().out)
    assert summary["ok"] == 2
    assert (summary["scheduler"], summary["workers"]) == ("serial", 1)


def test_default_workers_give_the_serial_records(serial, tmp_path):
    plan, reference = serial
    result = run_sweep(plan, tmp_path / "out")
    assert 1 <= result.workers <= len(plan.cases)
    assert comparable(result.records) == comparable(reference.records)


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
