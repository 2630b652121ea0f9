"""Hostile durations: every loop is bounded, and a wall-clock limit ends a job cleanly.

Iteration counts have upper bounds; ``dynamics.max_step`` is refused up front when the
contact-impact integrator would take more than 10^7 steps; ``--time-limit`` ends a
run between revolutions, and a sweep between cases, with exit status 2 and
``error: time limit of N s reached after R ...`` (a checkpointed run keeps its
checkpoint, a sweep its finished cases, and the message names the ``--resume`` command).
"""

from __future__ import annotations

import pytest

from jointwear.errors import TimeLimitError
from jointwear.resources import Deadline, parse_time_limit
from tests.hostile.harness import PAPER, SMALL, Bad, check_contract, files_in, run_cli, sweep_toml

RUN = ["run", "{paper}", "--out", "{out}"]
IMPACT = ["--set", "dynamics.model=contact-impact"]
#: a run of many short contour updates, stopped by the time limit after the first
LONG_RUN = [
    *SMALL,
    "--set",
    "simulation.update_contour=true",
    "--set",
    "simulation.revolutions=1000000",
]

CASES: list[Bad] = [
    Bad(
        "integrator-step-too-small",
        "time",
        [*RUN, *IMPACT, "--set", "dynamics.max_step=1e-12 s"],
        ["dynamics.max_step", "1.5e+12 integrator steps", "at most 1e+07", "larger step"],
    ),
    Bad(
        "integrator-step-too-small-in-file",
        "time",
        ["dynamics", "{tmp}/d.toml"],
        ["dynamics.max_step", "integrator steps"],
        {"d.toml": '[dynamics]\nmodel = "contact-impact"\nmax_step = "1 ns"\n'},
    ),
    Bad(
        "integrator-settling-beyond-bound",
        "time",
        [*RUN, "--set", "dynamics.revolutions_settle=1000000"],
        ["dynamics.revolutions_settle", "less than or equal to 10000"],
    ),
    Bad(
        "contact-iterations-beyond-bound",
        "time",
        [*RUN, "--set", "contact.max_iterations=1000000"],
        ["contact.max_iterations", "less than or equal to 10000"],
    ),
    Bad(
        "dynamics-iterations-beyond-bound",
        "time",
        [*RUN, "--set", "dynamics.max_iterations=1000000"],
        ["dynamics.max_iterations", "less than or equal to 1000"],
    ),
    Bad(
        "time-limit-zero",
        "time",
        [*RUN, "--time-limit", "0"],
        ["--time-limit", "must be a positive time"],
    ),
    Bad(
        "time-limit-negative",
        "time",
        [*RUN, "--time-limit", "-5 min"],
        ["--time-limit", "must be a positive time"],
    ),
    Bad(
        "time-limit-underflow",
        "time",
        [*RUN, "--time-limit", "1e-400 s"],
        ["--time-limit", "must be a positive time"],
    ),
    Bad(
        "time-limit-nan",
        "time",
        [*RUN, "--time-limit", "nan"],
        ["--time-limit", "must be finite"],
    ),
    Bad(
        "time-limit-text",
        "time",
        ["sweep", "{tmp}/s.toml", "--out", "{out}", "--time-limit", "soon"],
        ["--time-limit", "cannot read 'soon'"],
        {"s.toml": sweep_toml('[grid]\n"joint.clearance" = ["0.05 mm"]\n'), "tiny.toml": "@tiny"},
    ),
    Bad(
        "time-limit-reached",
        "time",
        [*RUN, *LONG_RUN, "--time-limit", "1 us"],
        ["time limit of 1e-06 s reached after 1 of 1000000 revolutions"],
    ),
    Bad(
        "life-time-limit-as-mass",
        "time",
        [
            "life",
            "{paper}",
            "--sample",
            "joint.clearance=uniform(low=0.05 mm, high=0.06 mm)",
            "--out",
            "{out}",
            "--time-limit",
            "3 kg",
        ],
        ["--time-limit", "expected a time"],
    ),
]


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_duration(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)


def test_time_limit_keeps_the_checkpoint_and_names_the_resume(tmp_path, capsys):
    """A checkpointed run stopped by --time-limit keeps its checkpoint; --resume finishes it."""
    out = tmp_path / "out"
    argv = [
        "run",
        str(PAPER),
        *SMALL,
        "--set",
        "simulation.update_contour=true",
        "--set",
        "simulation.revolutions=6",
        "--checkpoint-every",
        "1",
        "--out",
        str(out),
        "--no-plots",
        "--quiet",
        "--time-limit",
        "1 us",
    ]
    code, stdout, stderr = run_cli(capsys, argv)
    assert code == 2
    assert stdout == ""
    assert stderr.startswith("error: time limit of 1e-06 s reached after 1 of 6 revolutions")
    assert f"continue with `jointwear run --resume {out}`" in stderr
    assert {p.name for p in files_in(out)} == {"checkpoint.toml", "checkpoint.npz"}
    code, _, stderr = run_cli(capsys, ["run", "--resume", str(out), "--no-plots", "--json"])
    assert code == 0, stderr
    assert (out / "result.nc").exists()
    assert not (out / "checkpoint.npz").exists()


def test_sweep_time_limit_keeps_finished_cases(tmp_path, capsys):
    """A sweep stopped by --time-limit keeps its plan and cases; --resume runs the rest."""
    sweep = tmp_path / "s.toml"
    sweep.write_text(
        sweep_toml(
            '"simulation.steps_per_revolution" = 60\n[grid]\n'
            '"joint.clearance" = ["0.05 mm", "0.06 mm", "0.07 mm"]\n'
        ),
        encoding="utf-8",
    )
    (tmp_path / "tiny.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    out = tmp_path / "out"
    argv = ["sweep", str(sweep), "--out", str(out), "--workers", "1", "--quiet", "--json"]
    code, stdout, stderr = run_cli(capsys, [*argv, "--time-limit", "1 us"])
    assert code == 2
    assert stdout == ""
    # checked before the first case too: the limit has passed before any case ran
    assert "time limit of 1e-06 s reached after 0 of 3 cases" in stderr
    assert f"continue with `jointwear sweep --resume {out}`" in stderr
    assert not (out / "cases.csv").exists()
    code, stdout, stderr = run_cli(capsys, ["sweep", "--resume", str(out), "--json", "--quiet"])
    assert code == 0, stderr
    assert '"ok": 3' in stdout


def test_deadline_counts_and_stops():
    """A Deadline raises only once expired and only while work remains."""
    deadline = Deadline(0.0, "cases", "jointwear sweep --resume out")
    deadline.check(5, 5)  # finished: nothing to stop
    with pytest.raises(TimeLimitError, match=r"after 2 of 5 cases; continue with `jointwear"):
        deadline.check(2, 5)
    Deadline(None).check(1, 2)  # no limit
    assert parse_time_limit("2 h") == 7200.0
    assert parse_time_limit(None) is None


def test_dynamics_step_bound_is_checked_only_for_contact_impact():
    """dynamics.max_step only bounds the contact-impact integrator that uses it."""
    from jointwear import load_config

    config = load_config(PAPER, {"dynamics.max_step": "1e-12 s"})
    assert config.dynamics.max_step == 1e-12
    load_config(PAPER, {"dynamics.model": "contact-impact", "dynamics.max_step": "1e-6 s"})
