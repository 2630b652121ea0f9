"""Cases on this machine: workers only where they pay for their start."""

from __future__ import annotations

import json

import pytest

from jointwear.cli import main
from jointwear.workflows.sweep import run_sweep
from tests.workflows.sweep.conftest import TINY, comparable, write_sweep


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
