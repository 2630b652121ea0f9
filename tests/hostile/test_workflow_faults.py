"""Faults of whole workflows: a disk filling up under a sweep, seeds and keys beyond any
use, a stored plan changed by hand, a result missing what a figure draws.

Each is refused with one line naming the file or key and the reason, exit status 2, and
nothing half-written: a sweep's writes are atomic, and once its plan is stored, the cases
it finished are kept for ``--resume``.
"""

from __future__ import annotations

import contextlib
import errno
import json
import os
from functools import cache
from pathlib import Path

import pytest

from jointwear import load_config
from jointwear.workflows.sweep import expand_sweep
from tests.hostile.harness import (
    GRID,
    PAPER,
    Bad,
    check_contract,
    run_cli,
    snapshot,
    sweep_toml,
)

SEED = "1" * 400
DEEP_KEY = ".".join(["a"] * 5000)
CLEARANCE = "joint.clearance=uniform(low=0.04 mm, high=0.06 mm)"
SAMPLED = (
    '[sample]\n"joint.clearance" = {distribution = "uniform", low = "0.04 mm", '
    'high = "0.06 mm"}\nsamples = 2\n'
)


@cache
def tampered_plan(change: str) -> str:
    """A stored sweep plan of two cases, one changed by hand after it was written."""
    base = load_config(PAPER)
    plan = expand_sweep({"grid": {"joint.clearance": ["0.05 mm", "0.1 mm"]}}, base).to_dict()
    if change == "value":
        plan["cases"][1]["overrides"]["joint.clearance"] = "-3 mm"
    elif change == "key":
        plan["cases"][1]["overrides"] = {"joint.bore": "1 mm"}
    return json.dumps(plan)


CASES: list[Bad] = [
    Bad(
        "sweep-seed-of-400-digits",
        "sweep",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml: seed", "at most 2**63 - 1", "400 digits"],
        {"s.toml": sweep_toml(SAMPLED + f"seed = {SEED}\n"), "tiny.toml": "@tiny"},
    ),
    Bad(
        "life-seed-of-400-digits",
        "sweep",
        [
            "life",
            "{paper}",
            "--sample",
            CLEARANCE,
            "--cases",
            "2",
            "--seed",
            SEED,
            "--out",
            "{out}",
        ],
        ["--seed", "at most 2**63 - 1", "400 digits"],
    ),
    Bad(
        "sweep-resume-plan-with-a-changed-value",
        "sweep",
        ["sweep", "--resume", "{tmp}/done"],
        ["done/sweep-plan.json", "case-0001", "joint.clearance"],
        {"done/sweep-plan.json": tampered_plan("value")},
    ),
    Bad(
        "sweep-resume-plan-with-a-new-key",
        "sweep",
        ["sweep", "--resume", "{tmp}/done"],
        ["done/sweep-plan.json", "case-0001", "joint.bore is not a key of this sweep"],
        {"done/sweep-plan.json": tampered_plan("key")},
    ),
    Bad(
        "life-resume-of-a-sweep",
        "sweep",
        ["life", "--resume", "{tmp}/done"],
        ["--resume", "holds a sweep, not a life study", "jointwear sweep --resume"],
        {"done/sweep-plan.json": tampered_plan("")},
    ),
    Bad(
        "set-key-of-5000-parts",
        "config",
        ["run", "{paper}", "--set", f"{DEEP_KEY}=1"],
        ["a.a.a.a", "a dotted key of 5000 parts", "at most 16"],
    ),
    Bad(
        "life-sample-key-of-5000-parts",
        "config",
        ["life", "{paper}", "--sample", f"{DEEP_KEY}=uniform(low=1, high=2)", "--out", "{out}"],
        ["a dotted key of 5000 parts"],
    ),
    Bad(
        "sensitivity-too-few-cases",
        "sweep",
        ["sensitivity", "{paper}", "--sample", CLEARANCE, "--cases", "5", "--out", "{out}"],
        ["--cases", "Sobol indices of 1 input need at least 2 x 3 = 6 cases, got 5"],
    ),
    Bad(
        "sensitivity-unknown-method",
        "sweep",
        ["sensitivity", "{paper}", "--sample", CLEARANCE, "--method", "sobel", "--out", "{out}"],
        ["--method", "unknown method 'sobel'", "did you mean 'sobol'"],
    ),
    Bad(
        "sensitivity-unknown-metric",
        "sweep",
        ["sensitivity", "{paper}", "--sample", CLEARANCE, "--metric", "life_hour"],
        ["--metric", "unknown case metric 'life_hour'", "did you mean 'life_hours'"],
    ),
    Bad(
        "plot-result-without-joint-load",
        "data",
        ["plot", "{tmp}/r.nc"],
        ["r.nc", "no variable 'joint_load'", "joint_load figure", "not a complete"],
        {"r.nc": "@result-without:joint_load"},
    ),
]

FREE_AREAS = {"test_full_disk_during_sweep_output_is_one_line": "output"}


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_workflow_fault(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)


def _full_disk_at(name: str):
    """``jointwear.io.atomic_path`` whose file ``name`` fills the disk half-way through."""
    import jointwear.io

    real = jointwear.io.atomic_path

    @contextlib.contextmanager
    def filling(path):
        with real(path) as tmp:
            yield tmp
            if Path(path).name == name:
                with open(tmp, "ab") as handle:
                    handle.write(b"half a file")
                raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(tmp))

    return filling


@pytest.mark.parametrize("name", ["sweep-plan.json", "case-0001.json", "cases.csv", "sweep.nc"])
def test_full_disk_during_sweep_output_is_one_line(tmp_path, capsys, monkeypatch, name):
    """A disk that fills up while a sweep writes its plan, a case record, cases.csv or
    sweep.nc (simulated at the atomic writer): one line naming the file, exit 2, no
    temporary or half-written file. Before the plan is stored nothing is left; after it,
    the finished cases are kept and `sweep --resume` finishes once there is space."""
    import jointwear.io

    (tmp_path / "s.toml").write_text(sweep_toml(GRID), encoding="utf-8")
    (tmp_path / "tiny.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    before = snapshot(tmp_path)
    out = tmp_path / "out"
    argv = ["sweep", str(tmp_path / "s.toml"), "--out", str(out), "--workers", "1", "--json"]
    with monkeypatch.context() as patch:
        patch.setattr(jointwear.io, "atomic_path", _full_disk_at(name))
        code, stdout, stderr = run_cli(capsys, [*argv, "--quiet"])
    shown = f"{out}/cases/{name}" if name.startswith("case-") else f"{out}/{name}"
    assert (code, stdout) == (2, "")
    assert stderr.startswith(f"error: --out: {shown}: no space left on device")
    assert stderr.count("\n") == 1
    assert not [p for p in tmp_path.rglob("*") if p.name.startswith(".")]
    if name == "sweep-plan.json":
        assert snapshot(tmp_path) == before
        return
    assert stderr.endswith(f"continue with `jointwear sweep --resume {out}`\n")
    assert not (out / name).exists()
    for record in (out / "cases").glob("*.json"):
        assert json.loads(record.read_text(encoding="utf-8"))["status"] == "ok"
    code, stdout, stderr = run_cli(capsys, ["sweep", "--resume", str(out), "--json"])
    assert code == 0, stderr
    assert json.loads(stdout)["ok"] == 2
