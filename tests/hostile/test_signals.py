"""SIGINT and SIGTERM: exit 130 / 143 with one line, nothing half-written, resumable checkpoints.

Either signal raises :class:`jointwear.interrupts.Interrupted` in the main thread; staging
folders are removed on the way out, so ``--out`` holds either nothing new or, for a
checkpointed run, a complete checkpoint that ``jointwear run --resume DIR`` continues to
exactly the numbers of an uninterrupted run.
"""

from __future__ import annotations

import contextlib
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
from jointwear.checkpoint import CHECKPOINT_CONFIG, CHECKPOINT_STATE, Checkpointer, read_state
from jointwear.interrupts import Interrupted
from jointwear.results import read_result
from jointwear.results.summary import WALL_CLOCK_KEYS
from jointwear.workflows.run import add_checks
from tests.hostile.harness import PAPER, REPO, SMALL, Bad, run_cli, snapshot

#: the signal tests are free-form (real processes); no table cases
CASES: list[Bad] = []

UPDATE_CONFIG = REPO / "examples" / "paper" / "fig14_nlcp_update.toml"
#: a run that only a signal ends: every revolution updates the contour (without updates the
#: run would jump straight to its life limit, in about a second)
ENDLESS = [
    *SMALL,
    "--set",
    "simulation.update_contour=true",
    "--set",
    "simulation.revolutions=100000000",
    "--set",
    "simulation.update_every=1",
]
RESUMABLE = {
    "contact.nodes": 90,
    "contact.nlcp_variant": "mesh-independent",  # (NLCP's paper form needs 1 degree nodes)
    "simulation.steps_per_revolution": 90,
    "simulation.revolutions": 3000,
    "simulation.update_every": 1,
}


def default_signals() -> None:
    """In the child: SIGINT and SIGTERM as a shell starts a command (not inherited ignores)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def jointwear(*args: str) -> subprocess.Popen:
    return subprocess.Popen(
        [sys.executable, "-m", "jointwear", *args],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONPATH": str(REPO / "src")},
        preexec_fn=default_signals,  # a test runner's worker may ignore SIGINT
    )


def handler_installed(pid: int) -> bool:
    """Whether ``pid`` catches SIGTERM yet (jointwear's handler; Python's default does not)."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return False
    caught = next(line for line in status.splitlines() if line.startswith("SigCgt:"))
    return bool(int(caught.split()[1], 16) >> (signal.SIGTERM - 1) & 1)


def wait_for(condition, process: subprocess.Popen, what: str, limit: float = 120.0) -> None:
    deadline = time.monotonic() + limit
    while not condition():
        assert process.poll() is None, process.communicate()
        assert time.monotonic() < deadline, f"never saw {what}"
        time.sleep(0.005)


def finish(process: subprocess.Popen) -> tuple[int, str, str]:
    try:
        stdout, stderr = process.communicate(timeout=120)
    finally:
        process.kill()
    return process.returncode, stdout, stderr


def last_line(stderr: str) -> str:
    """The final stderr line (a run may print physics warnings before it)."""
    lines = stderr.splitlines()
    assert lines, "nothing on stderr"
    assert not any("Traceback" in line for line in lines), stderr
    return lines[-1]


# ---------------------------------------------------------------- real processes


@pytest.mark.parametrize(
    ("signum", "code", "note"),
    [(signal.SIGINT, 130, "interrupted"), (signal.SIGTERM, 143, "terminated")],
)
def test_signal_mid_run_exits_with_one_line_and_writes_nothing(tmp_path, signum, code, note):
    """A signal in the middle of a run: exit 130/143, one note, --out never created."""
    out = tmp_path / "out"
    process = jointwear("run", str(PAPER), *ENDLESS, "--out", str(out), "--quiet", "--json")
    wait_for(lambda: handler_installed(process.pid), process, "the signal handler")
    time.sleep(1.5)  # well inside the (endless) revolution loop
    process.send_signal(signum)
    returncode, stdout, stderr = finish(process)
    assert returncode == code, stderr
    assert stdout == ""
    assert last_line(stderr) == note
    assert list(tmp_path.iterdir()) == []


def test_ctrl_c_during_imports_prints_no_traceback(tmp_path):
    """Ctrl-C while the command line is still importing numpy & co.: `interrupted`, 130."""
    process = jointwear("run", str(PAPER), *ENDLESS, "--out", str(tmp_path / "out"))
    wait_for(lambda: handler_installed(process.pid), process, "the signal handler")
    process.send_signal(signal.SIGINT)
    returncode, stdout, stderr = finish(process)
    assert returncode == 130, stderr
    assert stdout == ""
    assert stderr == "interrupted\n"
    assert list(tmp_path.iterdir()) == []


def interrupted_checkpointed_run(tmp_path: Path, signum: int) -> tuple[Path, str]:
    out = tmp_path / "run"
    args = [str(UPDATE_CONFIG), "--out", str(out), "--checkpoint-every", "50", "--quiet"]
    for key, value in RESUMABLE.items():
        args += ["--set", f"{key}={value}"]
    process = jointwear("run", *args, "--no-plots", "--json")
    wait_for(lambda: (out / CHECKPOINT_STATE).exists(), process, "a checkpoint")
    time.sleep(random.uniform(0.0, 0.3))
    process.send_signal(signum)
    returncode, stdout, stderr = finish(process)
    assert returncode == 128 + signum, stderr
    assert stdout == ""
    return out, stderr


@pytest.mark.slow
@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_signal_leaves_a_resumable_checkpoint_that_resumes_bit_identically(
    tmp_path, capsys, signum
):
    """SIGINT/SIGTERM during a checkpointed run: the resume hint, then identical numbers."""
    out, stderr = interrupted_checkpointed_run(tmp_path, signum)
    note = "interrupted" if signum == signal.SIGINT else "terminated"
    assert last_line(stderr) == f"{note}; continue with `jointwear run --resume {out}`"
    assert sorted(p.name for p in out.iterdir()) == sorted([CHECKPOINT_CONFIG, CHECKPOINT_STATE])
    stopped, _ = read_state(out / CHECKPOINT_STATE)
    assert 50 <= stopped.revolution < RESUMABLE["simulation.revolutions"]

    code, stdout, stderr = run_cli(capsys, ["run", "--resume", str(out), "--json", "--no-plots"])
    assert code == 0, stderr
    reference = Simulation(load_config(UPDATE_CONFIG, RESUMABLE)).run()
    summary, expected = json.loads(stdout), reference.summary()
    for key in WALL_CLOCK_KEYS:
        summary.pop(key), expected.pop(key)
    add_checks(expected, reference)  # `run --json` adds the material checks
    assert summary == expected
    dataset = read_result(out / "result.nc")
    for name in ("wear_depth", "peak_wear_depth", "wear_mass", "pressure_final"):
        np.testing.assert_array_equal(dataset[name].values, reference.dataset[name].values, name)


# ---------------------------------------------------------------- in-process


def test_interrupt_inside_a_command_is_one_line(tmp_path, capsys, monkeypatch):
    """An interrupt raised inside a command: `terminated`, 143, nothing in --out."""

    def stop(self, *args, **kwargs):
        raise Interrupted(signal.SIGTERM)

    monkeypatch.setattr(Simulation, "run", stop)
    out = tmp_path / "out"
    code, stdout, stderr = run_cli(capsys, ["run", str(PAPER), "--out", str(out)])
    assert (code, stdout, stderr) == (143, "", "terminated\n")
    assert list(tmp_path.iterdir()) == []


def test_interrupt_while_publishing_leaves_out_as_it_was(tmp_path, capsys, monkeypatch):
    """An interrupt between two renames into an existing --out rolls every file back."""
    import jointwear.io

    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.json").write_text("{}\n")
    (out / "notes.txt").write_text("mine\n")
    before = snapshot(tmp_path)
    real = Path.rename
    calls = {"n": 0}

    def rename(self, target):
        if ".staging-" in self.parent.name:
            calls["n"] += 1
            if calls["n"] == 3:
                raise Interrupted(signal.SIGINT)
        return real(self, target)

    monkeypatch.setattr(Path, "rename", rename)
    code, stdout, stderr = run_cli(
        capsys, ["run", str(PAPER), *SMALL, "--out", str(out), "--json", "--no-plots"]
    )
    assert (code, stdout, stderr) == (130, "", "interrupted\n")
    assert calls["n"] == 3
    assert snapshot(tmp_path) == before
    assert jointwear.io  # the module whose publishing was interrupted


def test_interrupted_checkpointed_run_resumes_bit_identically_in_process(
    tmp_path, capsys, monkeypatch
):
    """Interrupt after a checkpoint (in-process): the hint names the folder; resume matches."""
    overrides = {**RESUMABLE, "simulation.revolutions": 120, "contact.nodes": 60}
    overrides["simulation.steps_per_revolution"] = 60
    real = Checkpointer.__call__

    def call(self, state):
        real(self, state)
        if state.revolution >= 77:
            raise Interrupted(signal.SIGINT)

    monkeypatch.setattr(Checkpointer, "__call__", call)
    out = tmp_path / "run"
    sets = [f"--set={key}={value}" for key, value in overrides.items()]
    argv = ["run", str(UPDATE_CONFIG), *sets, "--out", str(out), "--checkpoint-every", "25"]
    code, stdout, stderr = run_cli(capsys, [*argv, "--json", "--no-plots"])
    assert code == 130
    assert stdout == ""
    assert stderr == f"interrupted; continue with `jointwear run --resume {out}`\n"
    assert read_state(out / CHECKPOINT_STATE)[0].revolution == 75
    monkeypatch.setattr(Checkpointer, "__call__", real)

    code, stdout, stderr = run_cli(capsys, ["run", "--resume", str(out), "--json", "--no-plots"])
    assert code == 0, stderr
    reference = Simulation(load_config(UPDATE_CONFIG, overrides)).run()
    dataset = read_result(out / "result.nc")
    for name in ("wear_depth", "peak_wear_depth", "wear_mass", "bushing_radius"):
        np.testing.assert_array_equal(dataset[name].values, reference.dataset[name].values, name)


def test_handlers_are_restored_after_main(capsys):
    """Calling the CLI in-process leaves the caller's SIGINT/SIGTERM handlers as they were."""
    before = signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)
    run_cli(capsys, ["run", str(PAPER), "--set", "joint.clearance=5 kg"])
    assert (signal.getsignal(signal.SIGINT), signal.getsignal(signal.SIGTERM)) == before


@pytest.mark.slow
def test_interrupted_sweep_names_its_resume_and_resumes(tmp_path, capsys):
    """Ctrl-C to a sweep and its workers: one line with the resume command; resume finishes."""
    (tmp_path / "tiny.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    (tmp_path / "s.toml").write_text(
        'base = "tiny.toml"\n[set]\n"contact.nodes" = 60\n"simulation.revolutions" = 20000\n'
        '"simulation.update_every" = 1\n"simulation.update_contour" = true\n'
        '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm", "0.15 mm"]\n',
        encoding="utf-8",
    )
    out = tmp_path / "out"
    argv = ["sweep", str(tmp_path / "s.toml"), "--out", str(out), "--workers", "2", "--quiet"]
    process = subprocess.Popen(
        [sys.executable, "-m", "jointwear", *argv],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONPATH": str(REPO / "src")},
        start_new_session=True,  # a terminal's Ctrl-C reaches the whole process group
    )
    wait_for(lambda: (out / "sweep-plan.json").exists(), process, "the sweep plan")
    time.sleep(0.5)
    os.killpg(process.pid, signal.SIGINT)
    returncode, stdout, stderr = finish(process)
    assert returncode == 130, stderr
    assert stdout == ""
    assert stderr == f"interrupted; continue with `jointwear sweep --resume {out}`\n"
    code, stdout, stderr = run_cli(capsys, ["sweep", "--resume", str(out), "--json"])
    assert code == 0, stderr
    summary = json.loads(stdout)
    assert (summary["cases"], summary["ok"]) == (3, 3)


@pytest.mark.slow
def test_terminated_sweep_stops_its_running_cases(tmp_path):
    """SIGTERM to a sweep alone (not its workers): it exits 143 without finishing its cases."""
    (tmp_path / "tiny.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    (tmp_path / "s.toml").write_text(
        'base = "tiny.toml"\n[set]\n"contact.nodes" = 60\n"simulation.revolutions" = 100000000\n'
        '"simulation.update_every" = 1\n"simulation.update_contour" = true\n'
        '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n',
        encoding="utf-8",
    )
    out = tmp_path / "out"
    argv = ["sweep", str(tmp_path / "s.toml"), "--out", str(out), "--workers", "2", "--quiet"]
    process = jointwear(*argv)
    wait_for(lambda: (out / "sweep-plan.json").exists(), process, "the sweep plan")
    time.sleep(1.0)
    process.send_signal(signal.SIGTERM)
    returncode, stdout, stderr = finish(process)  # endless cases: only returns if they stop
    assert returncode == 143, stderr
    assert stdout == ""
    assert stderr == f"terminated; continue with `jointwear sweep --resume {out}`\n"
    assert list((out / "cases").glob("*.json")) == []


@contextlib.contextmanager
def interactive_signals():
    """SIGINT and SIGTERM as an interactive Python starts (a test runner's worker may ignore
    SIGINT, and jointwear keeps an inherited ignore); the old handlers afterwards."""
    previous = {each: signal.getsignal(each) for each in (signal.SIGINT, signal.SIGTERM)}
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    try:
        yield
    finally:
        for each, handler in previous.items():
            signal.signal(each, handler)


def test_a_signal_swallowed_by_python_still_stops_the_work(tmp_path):
    """A signal whose exception Python drops (a weakref callback) stops at the next step."""
    with interactive_signals():
        import weakref

        from jointwear.cli.progress import ProgressBar
        from jointwear.interrupts import handling_signals
        from jointwear.io import staged_output

        class Node:
            pass

        def swallowed(signum: int) -> None:
            """Deliver ``signum`` inside a weakref callback, where Python drops the exception."""

            def callback(_: object) -> None:
                signal.raise_signal(signum)
                for _ in range(1000):  # the handler runs here, inside the callback
                    pass

            node = Node()
            ref = weakref.ref(node, callback)
            del node
            assert ref() is None

        with handling_signals():
            swallowed(signal.SIGTERM)
            with pytest.raises(Interrupted) as stopped:
                ProgressBar("revolutions", quiet=True)(1, 10)
            assert stopped.value.signum == signal.SIGTERM

        def write_then_publish(out: Path) -> None:
            with handling_signals(), staged_output(out) as staging:
                (staging / "result.nc").write_text("complete")
                swallowed(signal.SIGINT)

        with pytest.raises(Interrupted):
            write_then_publish(tmp_path / "out")
        assert list(tmp_path.iterdir()) == []  # nothing published, no staging left
