"""Checkpoint / resume: a killed run continues to exactly the uninterrupted numbers."""

from __future__ import annotations

import json
import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.checkpoint import (
    CHECKPOINT_CONFIG,
    CHECKPOINT_STATE,
    Checkpointer,
    check_state,
    load_checkpoint,
    read_state,
    write_state,
)
from jointwear.cli import main
from jointwear.errors import DataError
from jointwear.results import read_result
from jointwear.results.summary import WALL_CLOCK_KEYS
from jointwear.state import Log
from jointwear.workflows.run import add_checks

REPO = Path(__file__).resolve().parents[1]
UPDATE_CONFIG = REPO / "examples" / "paper" / "fig14_nlcp_update.toml"
SMALL = {
    "contact.nodes": 60,
    "contact.nlcp_variant": "mesh-independent",  # (NLCP's paper form needs 1 degree nodes)
    "simulation.steps_per_revolution": 60,
    "simulation.revolutions": 120,
    "simulation.update_every": 1,
}


class Interrupt(Exception):
    """Stands in for a kill in the in-process tests."""


def interrupted_run(config, folder: Path, stop_at: int) -> None:
    saver = Checkpointer(folder, config)
    saver.begin()

    def on_step(state):
        saver(state)
        if state.revolution >= stop_at:
            raise Interrupt

    with pytest.raises(Interrupt):
        Simulation(config).run(on_step=on_step)


def assert_same_dataset(a, b) -> None:
    assert set(a.data_vars) == set(b.data_vars)
    for name in a.data_vars:
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
    for name in a.coords:
        np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)


@pytest.mark.parametrize(
    ("update_every", "every", "stop_at"), [(1, 25, 77), ("adaptive", 10, 40), (3, 7, 50)]
)
def test_resume_in_process_is_bitwise_identical(tmp_path, update_every, every, stop_at):
    config = load_config(
        UPDATE_CONFIG,
        {**SMALL, "simulation.update_every": update_every, "simulation.checkpoint_every": every},
    )
    reference = Simulation(config).run()
    interrupted_run(config, tmp_path, stop_at)
    resumed_config, state, saver = load_checkpoint(tmp_path)
    assert resumed_config.to_dict() == config.to_dict()
    assert 0 < state.revolution < config.simulation.revolutions
    resumed = Simulation(resumed_config).run(state=state, on_step=saver)
    assert_same_dataset(reference.dataset, resumed.dataset)
    ref, res = reference.summary(), resumed.summary()
    for key in WALL_CLOCK_KEYS:
        ref.pop(key), res.pop(key)
    assert ref == res


def test_state_round_trip_keeps_every_field(tmp_path):
    config = load_config(UPDATE_CONFIG, {**SMALL, "simulation.revolutions": 5})
    simulation = Simulation(config)
    state = simulation.initial_state()
    write_state(tmp_path / "a.npz", state, "digest")  # the None fields of a fresh state
    fresh, digest = read_state(tmp_path / "a.npz")
    assert digest == "digest"
    assert fresh.wear_rate is None
    assert fresh.warm_offset is None
    assert fresh.window is None
    for _ in range(3):
        state = simulation.step(state)
    write_state(tmp_path / "b.npz", state, "digest")
    back, _ = read_state(tmp_path / "b.npz")
    for name, value in vars(state).items():
        other = getattr(back, name)
        if isinstance(value, np.ndarray):
            np.testing.assert_array_equal(value, other)
        elif isinstance(value, Log):
            assert len(value) == len(other), name
            for mine, theirs in zip(value, other, strict=True):
                if isinstance(mine, dict):
                    assert mine == theirs, name
                else:
                    assert mine[0] == theirs[0], name
                    np.testing.assert_array_equal(mine[1], theirs[1])
        else:
            assert value == other, name
    assert all(isinstance(r, int) for r in back.history_columns["revolution"])


@pytest.mark.filterwarnings("ignore::jointwear.errors.WearFeedbackWarning")
def test_a_state_stopped_inside_a_revolution_round_trips(tmp_path):
    """A limit ends the run at a fractional revolution; its checkpoint keeps the fraction
    (revolution, record and last profile), and resuming it gives the same result."""
    config = load_config(
        UPDATE_CONFIG,
        {
            **SMALL,
            "simulation.revolutions": 10000,
            "simulation.update_every": 3,
            "materials.bushing.wear_coefficient": 1e-9,
        },
    )
    simulation = Simulation(config)
    state = simulation.initial_state()
    while state.stopped_by is None:
        state = simulation.step(state)
    assert not float(state.revolution).is_integer()
    path = tmp_path / "stopped.npz"
    write_state(path, state, "digest")
    back, _ = read_state(path)
    check_state(back, config, path)
    assert back.revolution == state.revolution
    assert back.history_columns["revolution"][-1] == state.revolution
    assert back.last_saved == state.revolution
    assert back.stopped_by == "wall_thickness"
    resumed = Simulation(config).run(state=back).summary()
    assert resumed["life_revolutions"] == state.revolution
    assert resumed["min_wall_thickness_m"] == pytest.approx(0.0, abs=1e-12)


def test_truncated_checkpoint_is_a_data_error(tmp_path):
    config = load_config(UPDATE_CONFIG, {**SMALL, "simulation.checkpoint_every": 5})
    interrupted_run(config, tmp_path, 12)
    path = tmp_path / CHECKPOINT_STATE
    path.write_bytes(path.read_bytes()[:200])
    with pytest.raises(DataError, match=r"checkpoint\.npz: not a readable checkpoint"):
        load_checkpoint(tmp_path)


def test_state_of_another_config_is_refused(tmp_path):
    config = load_config(UPDATE_CONFIG, {**SMALL, "simulation.checkpoint_every": 5})
    interrupted_run(config, tmp_path, 12)
    other = config.replace({"joint.clearance": "0.1 mm"})
    (tmp_path / CHECKPOINT_CONFIG).write_text(other.to_toml(), encoding="utf-8")
    with pytest.raises(DataError, match="different configuration"):
        load_checkpoint(tmp_path)
    # a sweep case simply starts again
    assert Checkpointer(tmp_path, other).load() is None


def run_cli(capsys, *args: str) -> tuple[int, str, str]:
    """Run the CLI in-process: (exit status, stdout, stderr)."""
    try:
        main([*args])
        code = 0
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 1
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def write_small_config(tmp_path: Path, **overrides) -> Path:
    config = load_config(UPDATE_CONFIG, {**SMALL, **overrides})
    path = tmp_path / "small.toml"
    path.write_text(config.to_toml(), encoding="utf-8")
    return path


def test_cli_checkpoint_then_resume(tmp_path, capsys):
    path = write_small_config(tmp_path)
    out = tmp_path / "out"
    config = load_config(path, {"simulation.checkpoint_every": 20})
    interrupted_run(config, out, 50)  # what a kill after revolution 50 leaves behind
    code, stdout, stderr = run_cli(capsys, "run", "--resume", str(out), "--json", "--no-plots")
    assert code == 0, stderr
    summary = json.loads(stdout)
    reference = Simulation(config).run()
    assert summary["peak_wear_depth_m"] == reference.summary()["peak_wear_depth_m"]
    assert summary["revolutions"] == 120
    assert not (out / CHECKPOINT_STATE).exists()
    assert not (out / CHECKPOINT_CONFIG).exists()
    assert {"result.nc", "metrics.csv", "summary.json", "config.toml"} <= {
        p.name for p in out.iterdir()
    }
    # nothing left to resume
    code, _, stderr = run_cli(capsys, "run", "--resume", str(out))
    assert code == 2
    assert "no checkpoint to resume" in stderr


def test_cli_refuses_to_overwrite_a_checkpoint(tmp_path, capsys):
    path = write_small_config(tmp_path)
    out = tmp_path / "out"
    interrupted_run(load_config(path, {"simulation.checkpoint_every": 20}), out, 30)
    code, _, stderr = run_cli(capsys, "run", str(path), "--out", str(out), "--no-plots")
    assert code == 2
    assert "--resume" in stderr
    assert stderr.count("\n") == 1


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--checkpoint-every", "5"], "--checkpoint-every: needs --out"),
        (["--checkpoint-every", "-1", "--out", "{out}"], "--checkpoint-every: must be >= 0"),
        (["--resume", "{out}"], "--resume: give either CONFIG"),
    ],
)
def test_cli_checkpoint_option_errors(tmp_path, capsys, args, message):
    path = write_small_config(tmp_path)
    args = [a.format(out=tmp_path / "out") for a in args]
    code, _, stderr = run_cli(capsys, "run", str(path), *args)
    assert code == 2
    assert message in stderr
    assert not (tmp_path / "out").exists()


def test_cli_checkpoint_files_removed_after_success(tmp_path, capsys):
    path = write_small_config(tmp_path)
    out = tmp_path / "out"
    code, _, stderr = run_cli(
        capsys,
        "run",
        str(path),
        "--out",
        str(out),
        "--checkpoint-every",
        "10",
        "--no-plots",
        "--json",
    )
    assert code == 0, stderr
    assert not (out / CHECKPOINT_STATE).exists()
    assert not [p for p in out.iterdir() if p.name.startswith(".")]


def test_sigkill_then_resume_gives_the_uninterrupted_numbers(tmp_path, capsys):
    """A real process killed with SIGKILL at a random point resumes to the same numbers."""
    overrides = {
        "contact.nodes": 90,
        "contact.nlcp_variant": "mesh-independent",
        "simulation.steps_per_revolution": 90,
        "simulation.revolutions": 3000,
        "simulation.update_every": 1,
    }
    out = tmp_path / "run"
    command = [
        sys.executable,
        "-m",
        "jointwear",
        "run",
        str(UPDATE_CONFIG),
        "--out",
        str(out),
        "--checkpoint-every",
        "50",
        "--quiet",
        "--no-plots",
        "--json",
    ]
    for key, value in overrides.items():
        command += ["--set", f"{key}={value}"]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        deadline = time.monotonic() + 120
        while not (out / CHECKPOINT_STATE).exists():
            assert process.poll() is None, process.communicate()
            assert time.monotonic() < deadline, "no checkpoint written"
            time.sleep(0.005)
        time.sleep(random.uniform(0.0, 0.3))
        os.kill(process.pid, signal.SIGKILL)
    finally:
        process.kill()
        process.communicate()
    assert process.returncode == -signal.SIGKILL
    killed_at, _ = read_state(out / CHECKPOINT_STATE)
    assert 50 <= killed_at.revolution < 3000
    assert not (out / "result.nc").exists()

    code, stdout, stderr = run_cli(
        capsys, "run", "--resume", str(out), "--json", "--quiet", "--no-plots"
    )
    assert code == 0, stderr
    summary = json.loads(stdout)

    reference = Simulation(load_config(UPDATE_CONFIG, overrides)).run()
    expected = reference.summary()
    add_checks(expected, reference)  # `run --json` adds the material checks
    for key in WALL_CLOCK_KEYS:
        expected.pop(key), summary.pop(key)
    assert summary == expected
    dataset = read_result(out / "result.nc")
    for name in (
        "wear_depth",
        "peak_wear_depth",
        "wear_mass",
        "wear_width",
        "bushing_radius",
        "wear_rate",
        "pressure_final",
        "contact_iterations",
    ):
        np.testing.assert_array_equal(dataset[name].values, reference.dataset[name].values, name)
    np.testing.assert_array_equal(
        dataset["update_revolution"].values, reference.dataset["update_revolution"].values
    )
    print(f"killed after revolution {killed_at.revolution}")


@pytest.mark.parametrize(
    ("update_every", "pin_wear"),
    [(1, None), ("adaptive", None), (1, 1e-13), (3, 1e-13), ("adaptive", 1e-13)],
)
def test_a_run_along_the_pin_resumes_bitwise(tmp_path, update_every, pin_wear):
    # the wear map (slices, nodes), its saved maps and rates through a checkpoint; a
    # wearing pin's map in its own frame too, the resumed run solving the pin's wear
    # facing each slice as before
    config = load_config(
        UPDATE_CONFIG,
        {
            **SMALL,
            "simulation.steps_per_revolution": 12,
            "simulation.revolutions": 30,
            "simulation.update_every": update_every,
            "simulation.checkpoint_every": 4,
            "joint.axial_slices": 3,
            "joint.misalignment": "0.02 deg",
            "materials.pin.wear_coefficient": pin_wear,
        },
    )
    reference = Simulation(config).run()
    assert reference.dataset["wear_depth"].dims == ("revolution", "z", "theta")
    interrupted_run(config, tmp_path, 9)
    resumed_config, state, saver = load_checkpoint(tmp_path)
    assert state.wear_depth.shape == (3, 60)
    if pin_wear is not None:
        assert reference.dataset["pin_wear_depth"].dims == ("z", "theta")
        assert state.pin_wear_depth.shape == (3, 60)
        assert state.pin_wear_depth.any()
    resumed = Simulation(resumed_config).run(state=state, on_step=saver)
    assert_same_dataset(reference.dataset, resumed.dataset)
