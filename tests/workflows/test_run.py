"""A run to a folder: its files hold the run, an interrupted run resumes to the same numbers,
and a run that cannot finish leaves nothing behind."""

from __future__ import annotations

import json

import pytest

from jointwear import Simulation, load_config
from jointwear.checkpoint import load_checkpoint
from jointwear.errors import ConfigError, ConvergenceError, TimeLimitError
from jointwear.interrupts import Interrupted
from jointwear.results import read_wear_result
from jointwear.results.summary import WALL_CLOCK_KEYS
from jointwear.workflows.run import RUN_FILES, run_to_folder

SMALL = {
    "contact.nodes": 60,
    "contact.nlcp_variant": "mesh-independent",
    "simulation.steps_per_revolution": 60,
    "simulation.revolutions": 12,
    "simulation.update_contour": True,
    "simulation.update_every": 1,
}
SETS = [f"{key}={value}" for key, value in SMALL.items()]


def without_runtime(summary: dict) -> dict:
    return {key: value for key, value in summary.items() if key not in WALL_CLOCK_KEYS}


def stop_at(revolution: int, error: BaseException):
    """A progress callback that raises ``error`` once ``revolution`` is done."""

    def progress(done: float, total: float) -> None:
        if done >= revolution:
            raise error

    return progress


def test_the_folder_holds_the_run_and_its_summary(paper_config_path, tmp_path):
    out = tmp_path / "out"
    ended = []
    done = run_to_folder(paper_config_path, out, overrides=SETS, plots=False, on_end=ended.append)
    reference = Simulation(load_config(paper_config_path, SMALL)).run().summary()
    assert without_runtime(read_wear_result(out / "result.nc").summary()) == without_runtime(
        reference
    )
    written = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert written == json.loads(json.dumps(done.summary))
    assert set(written["checks"]) >= {"pv", "nominal_pressure", "sliding_speed"}
    assert ended == [done.summary]  # the summary the run ended with, checks added after
    assert {p.name for p in out.iterdir()} == set(RUN_FILES)
    assert (done.name, done.out) == ("paper_joint.toml", out)


def test_an_interrupted_run_resumes_to_the_uninterrupted_numbers(paper_config_path, tmp_path):
    out = tmp_path / "out"
    with pytest.raises(Interrupted) as info:
        run_to_folder(
            paper_config_path,
            out,
            overrides=SETS,
            checkpoint_every=2,
            plots=False,
            progress=stop_at(7, KeyboardInterrupt()),
        )
    assert info.value.resume == f"jointwear run --resume {out}"
    assert load_checkpoint(out)[1].revolution == 6  # the last checkpoint before the stop
    resumed = run_to_folder(resume=out, plots=False)
    reference = Simulation(load_config(paper_config_path, SMALL)).run().summary()
    assert without_runtime(resumed.summary) == without_runtime(reference) | {
        "checks": resumed.summary["checks"]
    }
    assert resumed.name == "out"
    assert not (out / "checkpoint.toml").exists()


def test_a_time_limit_keeps_the_checkpoint(paper_config_path, tmp_path):
    out = tmp_path / "out"
    with pytest.raises(TimeLimitError, match=f"continue with `jointwear run --resume {out}`"):
        run_to_folder(
            paper_config_path, out, overrides=SETS, checkpoint_every=1, plots=False, time_limit=0.0
        )
    assert (out / "checkpoint.toml").is_file()
    assert not (out / "result.nc").exists()


def test_a_run_that_cannot_finish_leaves_nothing_behind(paper_config_path, tmp_path):
    out = tmp_path / "new"
    with pytest.raises(ConvergenceError):
        run_to_folder(
            paper_config_path,
            out,
            overrides=SETS,
            checkpoint_every=2,
            progress=stop_at(5, ConvergenceError("no balance")),
        )
    assert not out.exists()


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        ({}, "CONFIG: missing"),
        ({"config": "paper", "checkpoint_every": 3}, "--checkpoint-every: needs --out"),
        ({"config": "paper", "resume": "out"}, "--resume: give either CONFIG"),
        ({"resume": "out", "overrides": ["joint.clearance=0.1 mm"]}, "--set: a resumed run"),
        ({"resume": "out", "out": "other"}, "--out: a resumed run writes"),
    ],
)
def test_conflicting_options_are_refused_before_anything_runs(
    paper_config_path, tmp_path, arguments, message
):
    paths = {"paper": paper_config_path, "out": tmp_path / "out", "other": tmp_path / "other"}
    arguments = {
        key: paths[value] if isinstance(value, str) else value for key, value in arguments.items()
    }
    with pytest.raises(ConfigError, match=message):
        run_to_folder(**arguments)
    assert not (tmp_path / "out").exists()
    assert not (tmp_path / "other").exists()
