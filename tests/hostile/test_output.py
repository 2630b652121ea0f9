"""Hostile output targets: empty paths, files where folders go, links and pipes inside --out.

Every command that writes stages its files in a temporary folder and publishes them in
one step (:func:`jointwear.io.staged_output`): one rename of the whole folder when
``--out`` is new or empty, renames with a rollback when it merges into an existing one.
Nothing is ever written through a symbolic link or into a special file; a full disk or
a read-only file system is a one-line error naming the path.
"""

from __future__ import annotations

import contextlib
import errno
import os
import subprocess
import sys
from pathlib import Path

import pytest

from jointwear.errors import DataError
from jointwear.io import staged_output
from tests.hostile.harness import (
    CSV_HEADER,
    GRID,
    PAPER,
    SMALL,
    Bad,
    check_cases,
    check_contract,
    run_cli,
    snapshot,
    sweep_toml,
)

QUIET = ["--json", "--quiet"]
SWEEP = {"s.toml": sweep_toml(GRID), "tiny.toml": "@tiny"}
MEASURED = CSV_HEADER + "".join(f"{x},{y}\n" for x, y in ((7.5, 0), (0, 7.5), (-7.5, 0)))
PRECIOUS = {"elsewhere/keep.txt": "not yours\n", "elsewhere": "@dir"}

# (command, argv before --out, files it needs)
WRITERS = {
    "run": (["run", "{paper}", *SMALL], {}),
    "compare": (["compare", "{tmp}/result.nc", "{tmp}/m.csv"], {"result.nc": "@result"}),
    "plot": (["plot", "{tmp}/result.nc"], {"result.nc": "@result"}),
    "sweep": (["sweep", "{tmp}/s.toml"], SWEEP),
    "life": (["life", "{paper}", "--cases", "2"], {}),
    "compare-models": (["compare-models", "{paper}", "--loads", "1 kN"], {}),
    "reproduce": (["reproduce", "--no-calibrate"], {}),
}


def empty_out(command: str) -> Bad:
    argv, files = WRITERS[command]
    return Bad(
        f"{command}-out-empty", "output", [*argv, "--out", ""], ["--out", "empty path"], files
    )


def out_is_a_file(command: str) -> Bad:
    argv, files = WRITERS[command]
    return Bad(
        f"{command}-out-is-a-file",
        "output",
        [*argv, "--out", "{tmp}/taken"],
        ["taken", "exists and is not a directory"],
        {**files, "taken": "someone's notes\n"},
    )


def run_into(entries: dict[str, str], expect: list[str], name: str, *extra: str) -> Bad:
    """``jointwear run`` into an --out that already holds ``entries``."""
    return Bad(
        name, "output", ["run", "{paper}", *SMALL, "--out", "{out}", *extra], expect, entries
    )


CASES: list[Bad] = [
    # ------------------------------------------------------------ the --out path itself
    *(empty_out(command) for command in WRITERS),
    Bad("run-out-equals-empty", "output", ["run", "{paper}", "--out="], ["--out", "empty path"]),
    Bad("run-resume-empty", "output", ["run", "--resume", ""], ["--resume", "empty path"]),
    Bad("dynamics-csv-empty", "output", ["dynamics", "{paper}", "--csv", ""], ["--csv", "empty"]),
    *(out_is_a_file(command) for command in WRITERS if command != "run"),  # run: catalogue
    Bad(
        "run-out-dangling-link",
        "output",
        ["run", "{paper}", "--out", "{tmp}/gone"],
        ["gone", "dangling symbolic link"],
        {"gone": "@link:nowhere"},
    ),
    Bad(
        "run-out-below-a-file",
        "output",
        ["run", "{paper}", "--out", "{tmp}/notes.txt/run"],
        ["notes.txt", "is not a directory"],
        {"notes.txt": "x\n"},
    ),
    Bad(
        "compare-out-below-a-file",
        "output",
        ["compare", "{tmp}/result.nc", "{tmp}/m.csv", "--out", "{tmp}/notes.txt/cmp"],
        ["notes.txt", "is not a directory"],
        {"result.nc": "@result", "m.csv": MEASURED, "notes.txt": "x\n"},
    ),
    Bad(
        "dynamics-csv-below-a-file",
        "output",
        ["dynamics", "{paper}", "--csv", "{tmp}/notes.txt/cycle.csv"],
        ["--csv", "notes.txt", "is not a directory"],
        {"notes.txt": "x\n"},
    ),
    Bad(
        "dynamics-csv-is-a-directory",
        "output",
        ["dynamics", "{paper}", "--csv", "{tmp}/cycle.csv"],
        ["--csv", "cycle.csv", "is a directory"],
        {"cycle.csv": "@dir"},
    ),
    Bad(
        "dynamics-csv-is-a-link",
        "output",
        ["dynamics", "{paper}", "--csv", "{tmp}/cycle.csv"],
        ["--csv", "cycle.csv", "not a regular file"],
        {**PRECIOUS, "cycle.csv": "@link:elsewhere/keep.txt"},
    ),
    Bad(
        "dynamics-csv-is-a-fifo",
        "output",
        ["dynamics", "{paper}", "--csv", "{tmp}/cycle.csv"],
        ["--csv", "cycle.csv", "not a regular file"],
        {"cycle.csv": "@fifo"},
    ),
    # ------------------------------------------------------------ entries inside --out
    run_into(
        {"out/result.nc": "@dir", "out/result.nc/old.txt": "x\n"},
        ["result.nc", "is a directory, not a file"],
        "run-result-name-is-a-directory",
    ),
    run_into(
        {"out/plots": "a file where the figures go\n"},
        ["plots", "is a file, not a directory"],
        "run-plots-name-is-a-file",
    ),
    run_into(
        {**PRECIOUS, "out/summary.json": "@link:elsewhere/keep.txt"},
        ["summary.json", "symbolic link"],
        "run-summary-is-a-link-outside",
    ),
    run_into(
        {**PRECIOUS, "out/plots": "@link:elsewhere"},
        ["plots", "symbolic link"],
        "run-plots-is-a-link-outside",
    ),
    run_into({"out/metrics.csv": "@fifo"}, ["metrics.csv", "named pipe"], "run-metrics-is-a-fifo"),
    run_into(
        {**PRECIOUS, "out/checkpoint.npz": "@link:elsewhere/keep.txt"},
        ["checkpoint.npz", "symbolic link"],
        "run-checkpoint-is-a-link-outside",
        "--checkpoint-every",
        "1",
    ),
    Bad(
        "compare-json-name-is-a-directory",
        "output",
        ["compare", "{tmp}/result.nc", "{tmp}/m.csv", "--out", "{out}"],
        ["comparison.json", "is a directory"],
        {"result.nc": "@result", "m.csv": MEASURED, "out/comparison.json": "@dir"},
    ),
    Bad(
        "compare-profiles-is-a-link-outside",
        "output",
        ["compare", "{tmp}/result.nc", "{tmp}/m.csv", "--out", "{out}"],
        ["profiles.csv", "symbolic link"],
        {
            "result.nc": "@result",
            "m.csv": MEASURED,
            **PRECIOUS,
            "out/profiles.csv": "@link:elsewhere/keep.txt",
        },
    ),
    Bad(
        "compare-models-plot-is-a-link-outside",
        "output",
        ["compare-models", "{paper}", "--loads", "1 kN", "--out", "{out}"],
        ["compare_models_pressure.png", "symbolic link"],
        {**PRECIOUS, "out/compare_models_pressure.png": "@link:elsewhere/keep.txt"},
    ),
    Bad(
        "sweep-cases-is-a-link-outside",
        "output",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["cases", "symbolic link"],
        {**SWEEP, **PRECIOUS, "out/cases": "@link:elsewhere"},
    ),
    Bad(
        "sweep-case-record-is-a-link-outside",
        "output",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["case-0000.json", "symbolic link"],
        {**SWEEP, **PRECIOUS, "out/cases/case-0000.json": "@link:elsewhere/keep.txt"},
    ),
    Bad(
        "sweep-case-folder-is-a-link-outside",
        "output",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["case-0000", "symbolic link"],
        {**SWEEP, **PRECIOUS, "out/cases/case-0000": "@link:elsewhere"},
    ),
    Bad(
        "sweep-dataset-name-is-a-directory",
        "output",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["sweep.nc", "is a directory"],
        {**SWEEP, "out/sweep.nc": "@dir"},
    ),
    Bad(
        "sweep-cases-is-a-fifo",
        "output",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["cases", "named pipe"],
        {**SWEEP, "out/cases": "@fifo"},
    ),
    Bad(
        "life-cases-is-a-link-outside",
        "output",
        ["life", "{paper}", "--cases", "2", "--out", "{out}"],
        ["cases", "symbolic link"],
        {**PRECIOUS, "out/cases": "@link:elsewhere"},
    ),
    Bad(
        "reproduce-figures-is-a-link-outside",
        "output",
        ["reproduce", "--no-calibrate", "--out", "{out}"],
        ["figures", "symbolic link"],
        {**PRECIOUS, "out/figures": "@link:elsewhere"},
    ),
    Bad(
        "reproduce-report-name-is-a-directory",
        "output",
        ["reproduce", "--no-calibrate", "--out", "{out}"],
        ["report.md", "is a directory"],
        {"out/report.md": "@dir"},
    ),
    # ------------------------------------------------------------ options before figures
    Bad(
        "plot-bad-magnification-writes-nothing",
        "output",
        ["plot", "{tmp}/result.nc", "--magnification", "0", "--out", "{out}"],
        ["--magnification", "positive"],
        {"result.nc": "@result"},
    ),
    Bad(
        "compare-models-calibrate-reference-before-plots",
        "output",
        [
            "compare-models",
            "{paper}",
            "--loads",
            "1 kN",
            "--reference",
            "winkler",
            "--calibrate",
            "--out",
            "{out}",
        ],
        ["--calibrate", "reference"],
    ),
]


def test_output_cases_are_many_and_unique():
    """The output cases cover every writing command and each id is unique across the suite."""
    check_cases(CASES, "output", 40)


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_output(case: Bad, tmp_path, capsys, result_bytes):
    """The case's command fails with its one line, exit 2, nothing written."""
    check_contract(case, tmp_path, capsys, result_bytes)


# ---------------------------------------------------------------- publishing


def test_new_out_appears_complete_and_no_staging_is_left(tmp_path, capsys):
    """A new --out appears with every file at once; no staging folder is left next to it."""
    out = tmp_path / "deep" / "run"
    code, _, stderr = run_cli(capsys, ["run", str(PAPER), *SMALL, "--out", str(out), "--json"])
    assert code == 0, stderr
    names = {p.name for p in out.iterdir()}
    assert {"result.nc", "metrics.csv", "config.toml", "summary.json", "plots"} <= names
    assert [p.name for p in (tmp_path / "deep").iterdir()] == ["run"]
    assert not [p for p in out.rglob(".*")]


def test_rerun_replaces_its_files_and_keeps_the_users(tmp_path, capsys):
    """A rerun into an existing --out replaces the run's files and leaves other files alone."""
    out = tmp_path / "run"
    out.mkdir()
    (out / "notes.txt").write_text("mine\n")
    (out / "summary.json").write_text("{}\n")
    code, _, stderr = run_cli(
        capsys, ["run", str(PAPER), *SMALL, "--out", str(out), "--json", "--no-plots"]
    )
    assert code == 0, stderr
    assert (out / "notes.txt").read_text() == "mine\n"
    assert (out / "summary.json").read_text() != "{}\n"
    assert not [p for p in out.iterdir() if p.name.startswith(".")]


def test_out_that_is_a_link_to_a_folder_is_followed(tmp_path, capsys):
    """--out naming a link to a folder writes into that folder; the link stays a link."""
    real = tmp_path / "real"
    real.mkdir()
    link = tmp_path / "link"
    link.symlink_to(real)
    code, _, stderr = run_cli(
        capsys, ["run", str(PAPER), *SMALL, "--out", str(link), "--json", "--no-plots"]
    )
    assert code == 0, stderr
    assert link.is_symlink()
    assert (real / "result.nc").is_file()


def test_merge_rolls_back_when_a_rename_fails(tmp_path, monkeypatch):
    """A failure half-way through publishing into an existing folder restores it exactly."""
    out = tmp_path / "out"
    out.mkdir()
    for name in ("a.txt", "b.txt", "c.txt"):
        (out / name).write_text(f"old {name}\n")
    before = snapshot(out)
    real_rename = Path.rename
    calls = {"n": 0}

    def flaky(self, target):
        if self.parent.name.startswith(".out.staging-") or ".staging-" in self.parent.name:
            calls["n"] += 1
            if calls["n"] == 3:
                raise OSError(errno.ENOSPC, "No space left on device")
        return real_rename(self, target)

    monkeypatch.setattr(Path, "rename", flaky)

    def publish() -> None:
        with staged_output(out) as stage:
            for name in ("a.txt", "b.txt", "c.txt", "d.txt"):
                (stage / name).write_text(f"new {name}\n")

    with pytest.raises(DataError, match="no space left on device"):
        publish()
    assert snapshot(out) == before
    assert calls["n"] == 3


def test_failed_block_leaves_no_folder_behind(tmp_path):
    """An exception inside the staged block creates nothing: not --out, not its parents."""
    out = tmp_path / "a" / "b" / "out"

    def fail() -> None:
        with staged_output(out) as stage:
            (stage / "x.txt").write_text("x")
            raise RuntimeError("boom")

    with pytest.raises(RuntimeError):
        fail()
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- full and read-only disks


@contextlib.contextmanager
def small_filesystem(path: Path, options: str):
    """A tmpfs mounted at ``path`` (skips the test where mounting is not allowed)."""
    path.mkdir()
    done = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", options, "tmpfs", str(path)],
        capture_output=True,
        check=False,
    )
    if done.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here ({done.stderr.decode().strip()})")
    try:
        yield path
    finally:
        subprocess.run(["umount", str(path)], check=False)


def test_full_disk_is_one_line_and_no_crash_at_exit(tmp_path, result_bytes):
    """A disk that fills up while writing result.nc: one line, exit 2, no segfault at exit."""
    with small_filesystem(tmp_path / "full", "size=160k") as disk:
        out = disk / "run"
        done = subprocess.run(
            [
                sys.executable,
                "-m",
                "jointwear",
                "run",
                str(PAPER),
                *SMALL,
                "--out",
                str(out),
                *QUIET,
            ],
            capture_output=True,
            text=True,
            check=False,
            timeout=300,
            env={**os.environ, "PYTHONPATH": str(Path(__file__).parents[2] / "src")},
        )
        assert done.returncode == 2, done.stderr
        assert done.stderr.splitlines() == [f"error: --out: {out}: no space left on device"]
        assert done.stdout == ""
        assert list(disk.iterdir()) == []


def test_read_only_disk_is_one_line(tmp_path, capsys):
    """A read-only file system: one line naming --out, exit 2."""
    with small_filesystem(tmp_path / "ro", "ro,size=1m") as disk:
        out = disk / "run"
        code, stdout, stderr = run_cli(
            capsys, ["run", str(PAPER), *SMALL, "--out", str(out), "--json"]
        )
        assert code == 2
        assert stdout == ""
        assert stderr == f"error: --out: {out}: read-only file system\n"


WRITE_FAILURES = [
    (errno.ENOSPC, "no space left on device"),
    (errno.EROFS, "read-only file system"),
    (errno.EACCES, "permission denied"),
]
STAGED = {
    "run": ["run", "{paper}", *SMALL, "--json"],
    "plot": ["plot", "{tmp}/result.nc"],
    "compare": ["compare", "{tmp}/result.nc", "{tmp}/m.csv", "--json"],
    "compare-models": ["compare-models", "{paper}", "--loads", "1 kN", "--json"],
}


@pytest.mark.parametrize(("number", "reason"), WRITE_FAILURES, ids=["enospc", "erofs", "eacces"])
@pytest.mark.parametrize("command", list(STAGED))
def test_write_failure_of_every_writer_is_one_line(
    tmp_path, capsys, monkeypatch, result_bytes, command, number, reason
):
    """Each writer, its file system failing on publishing (simulated): one line, no trace."""
    import numpy as np

    import jointwear.io

    (tmp_path / "result.nc").write_bytes(result_bytes)
    theta = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    points = "".join(f"{7.5 * np.cos(t)},{7.5 * np.sin(t)}\n" for t in theta)
    (tmp_path / "m.csv").write_text(CSV_HEADER + points)
    before = snapshot(tmp_path)

    def failing(staging, out, flag):
        raise OSError(number, os.strerror(number))

    monkeypatch.setattr(jointwear.io, "_publish", failing)
    out = tmp_path / "new"
    argv = [a.format(tmp=tmp_path, paper=PAPER) for a in STAGED[command]]
    code, stdout, stderr = run_cli(capsys, [*argv, "--out", str(out)])
    assert (code, stdout) == (2, "")
    assert stderr == f"error: --out: {out}: {reason}\n"
    assert snapshot(tmp_path) == before
