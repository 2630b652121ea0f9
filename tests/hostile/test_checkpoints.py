"""Damaged, edited and swapped checkpoints: refused with one line naming the file, left in place.

A checkpoint's state (``checkpoint.npz``) carries a SHA-256 checksum of its own arrays
and the digest of the configuration it belongs to; on ``run --resume`` it is also
checked against that configuration (node count, revolutions, finite values, records
that run forward). Any damage is one ``error: DIR/checkpoint.npz: ...`` line, exit 2,
and the checkpoint stays as it was (a user may still want to inspect or repair it).
"""

from __future__ import annotations

import dataclasses
import io
import json

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.checkpoint import CHECKPOINT_CONFIG, CHECKPOINT_STATE, Checkpointer, _checksum
from tests.hostile.harness import PAPER, Bad, check_cases, check_contract

OVERRIDES = {
    "contact.nodes": 60,
    "simulation.steps_per_revolution": 60,
    "simulation.revolutions": 6,
    "simulation.update_contour": True,
    "simulation.update_every": 1,
    "simulation.checkpoint_every": 2,
}
RESUME = ["run", "--resume", "{tmp}/ck", "--json", "--no-plots"]
STATE, CONFIG = f"ck/{CHECKPOINT_STATE}", f"ck/{CHECKPOINT_CONFIG}"


def checkpoint(tmp, overrides: dict) -> tuple[bytes, str]:
    """(state bytes, config text) of a finished tiny checkpointed run."""
    config = load_config(PAPER, {**OVERRIDES, **overrides})
    saver = Checkpointer(tmp, config)
    saver.begin()
    Simulation(config).run(on_step=saver)
    return saver.state_path.read_bytes(), saver.config_path.read_text(encoding="utf-8")


def rewrite(state: bytes, change, checksum: bool = True) -> bytes:
    """``state`` with its arrays changed by ``change(arrays)``; checksum recomputed or not.

    A recomputed checksum stands for a state that is internally intact but does not fit
    its configuration (a writer's bug, or a file assembled from pieces).
    """
    with np.load(io.BytesIO(state), allow_pickle=False) as data:
        arrays = {name: data[name] for name in data.files}
    change(arrays)
    if checksum and "checksum" in arrays:
        arrays["checksum"] = np.array(_checksum(arrays))
    buffer = io.BytesIO()
    np.savez(buffer, **arrays)
    return buffer.getvalue()


def _set(name, value):
    return lambda arrays: arrays.__setitem__(name, np.asarray(value))


def _scale_wear(arrays):
    arrays["f_wear_depth"] = arrays["f_wear_depth"] * 1.01


def _nan_wear(arrays):
    depth = arrays["f_wear_depth"].copy()
    depth[3] = np.nan
    arrays["f_wear_depth"] = depth


def _swap_profiles(arrays):
    arrays["f_profiles__keys"] = arrays["f_profiles__keys"][::-1].copy()


EDITS = {
    # name: (change, recompute checksum, expected fragments)
    "edited-wear": (_scale_wear, False, ["damaged checkpoint", "checksum"]),
    "edited-revolution": (_set("f_revolution", 4), False, ["damaged checkpoint"]),
    "checksum-removed": (lambda a: a.pop("checksum"), False, ["damaged checkpoint"]),
    "checksum-garbage": (_set("checksum", "0" * 64), False, ["damaged checkpoint"]),
    "old-format": (_set("format", 2), True, ["checkpoint format 2", "reads format 3"]),
    "field-missing": (lambda a: a.pop("f_interval"), True, ["unusable checkpoint"]),
    "schema-garbage": (_set("schema", "{not json"), True, ["unusable checkpoint"]),
    "fewer-nodes": (
        lambda a: a.__setitem__("f_wear_depth", a["f_wear_depth"][:-1].copy()),
        True,
        ["inconsistent checkpoint", "wear_depth", "60 nodes"],
    ),
    "revolution-past-the-end": (
        _set("f_revolution", 10**6),
        True,
        ["inconsistent checkpoint", "revolution 1000000"],
    ),
    "revolution-negative": (_set("f_revolution", -3), True, ["inconsistent checkpoint"]),
    "revolution-behind-its-records": (
        _set("f_revolution", 2),
        True,
        ["inconsistent checkpoint", "do not run forward"],
    ),
    "nan-wear": (_nan_wear, True, ["inconsistent checkpoint", "non-finite"]),
    "infinite-threshold": (
        _set("f_dynamics_threshold", np.inf),
        True,
        ["inconsistent checkpoint", "dynamics_threshold"],
    ),
    "profiles-backwards": (_swap_profiles, True, ["inconsistent checkpoint", "profiles"]),
    "interval-zero": (_set("f_interval", 0), True, ["inconsistent checkpoint", "interval"]),
}


def state_case(name: str, expect: list[str]) -> Bad:
    return Bad(
        f"checkpoint-{name}",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, *expect],
        {CONFIG: "@ck-config", STATE: f"@ck-state:{name}"},
    )


CASES: list[Bad] = [
    *(state_case(name, expect) for name, (_, _, expect) in EDITS.items()),
    Bad(
        "checkpoint-truncated",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "not a readable checkpoint"],
        {CONFIG: "@ck-config", STATE: "@ck-state:truncated"},
    ),
    Bad(
        "checkpoint-empty",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "not a readable checkpoint"],
        {CONFIG: "@ck-config", STATE: b""},
    ),
    Bad(
        "checkpoint-text",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "not a readable checkpoint"],
        {CONFIG: "@ck-config", STATE: "revolution = 4\n"},
    ),
    Bad(
        "checkpoint-pickled-objects",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "not a readable checkpoint"],
        {CONFIG: "@ck-config", STATE: "@ck-state:pickle"},
    ),
    Bad(
        "checkpoint-state-of-another-run",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "different configuration"],
        {CONFIG: "@ck-config", STATE: "@ck-other-state"},
    ),
    Bad(
        "checkpoint-config-of-another-run",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "different configuration", CHECKPOINT_CONFIG],
        {CONFIG: "@ck-other-config", STATE: "@ck-state"},
    ),
    Bad(
        "checkpoint-config-edited",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "different configuration"],
        {CONFIG: "@ck-config:edited", STATE: "@ck-state"},
    ),
    Bad(
        "checkpoint-config-bad-value",
        "checkpoint",
        RESUME,
        [f"error: {{tmp}}/{CONFIG}: joint.pin_radius"],
        {CONFIG: "@ck-config:bad-value", STATE: "@ck-state"},
    ),
    Bad(
        "checkpoint-config-not-toml",
        "checkpoint",
        RESUME,
        [CHECKPOINT_CONFIG, "not valid TOML"],
        {CONFIG: "[joint\n", STATE: "@ck-state"},
    ),
    Bad(
        "checkpoint-config-missing",
        "checkpoint",
        RESUME,
        ["no checkpoint to resume"],
        {STATE: "@ck-state"},
    ),
    Bad(
        "checkpoint-state-is-a-directory",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "is a directory, not a file"],
        {CONFIG: "@ck-config", STATE: "@dir"},
    ),
    Bad(
        "checkpoint-state-is-a-fifo",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "named pipe"],
        {CONFIG: "@ck-config", STATE: "@fifo"},
    ),
    Bad(
        "checkpoint-state-is-a-link",
        "checkpoint",
        RESUME,
        [CHECKPOINT_STATE, "symbolic link"],
        {CONFIG: "@ck-config", "elsewhere.npz": "@ck-state", STATE: "@link:elsewhere.npz"},
    ),
    Bad(
        "checkpoint-config-is-a-fifo",
        "checkpoint",
        RESUME,
        [CHECKPOINT_CONFIG, "named pipe"],
        {CONFIG: "@fifo", STATE: "@ck-state"},
    ),
    Bad(
        "resume-directory-missing",
        "checkpoint",
        ["run", "--resume", "{tmp}/nothing"],
        ["nothing", "no such directory"],
    ),
    Bad(
        "resume-a-file",
        "checkpoint",
        ["run", "--resume", "{tmp}/notes.txt"],
        ["notes.txt", "is not a directory"],
        {"notes.txt": "x\n"},
    ),
    Bad(
        "resume-a-finished-run",
        "checkpoint",
        ["run", "--resume", "{tmp}/ck"],
        ["no checkpoint to resume"],
        {"ck/result.nc": "@result", "ck/summary.json": "{}\n"},
    ),
]


@pytest.fixture(scope="module")
def checkpoints(tmp_path_factory) -> dict[str, str | bytes]:
    """Marker -> content of the checkpoint files the cases use."""
    state, config = checkpoint(tmp_path_factory.mktemp("ck"), {})
    other_state, other_config = checkpoint(
        tmp_path_factory.mktemp("other"), {"joint.clearance": "0.06 mm"}
    )
    markers: dict[str, str | bytes] = {
        "@ck-state": state,
        "@ck-config": config,
        "@ck-other-state": other_state,
        "@ck-other-config": other_config,
        "@ck-state:truncated": state[: len(state) // 2],
        "@ck-state:pickle": rewrite(
            state, _set("f_wear_depth", np.array([{"a": 1}], dtype=object)), checksum=False
        ),
        "@ck-config:edited": config.replace(
            "steps_per_revolution = 60", "steps_per_revolution = 61"
        ),
    }
    lines = [
        'pin_radius = "-1 mm"' if line.startswith("pin_radius") else line
        for line in config.splitlines()
    ]
    markers["@ck-config:bad-value"] = "\n".join(lines) + "\n"
    for name, (change, checksum, _) in EDITS.items():
        markers[f"@ck-state:{name}"] = rewrite(state, change, checksum)
    return markers


def resolved(case: Bad, markers: dict[str, str | bytes], tmp_path) -> Bad:
    files = {
        name: markers.get(content, content) if isinstance(content, str) else content
        for name, content in case.files.items()
    }
    expect = [fragment.replace("{tmp}", str(tmp_path)) for fragment in case.expect]
    return dataclasses.replace(case, files=files, expect=expect)


def test_checkpoint_cases_are_many_and_unique():
    """The checkpoint cases cover edits, truncation, swaps and file kinds; ids are unique."""
    check_cases(CASES, "checkpoint", 25)


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_checkpoint(case: Bad, tmp_path, capsys, result_bytes, checkpoints):
    """The case's command fails with its one line, exit 2, nothing written."""
    check_contract(resolved(case, checkpoints, tmp_path), tmp_path, capsys, result_bytes)


def test_intact_checkpoint_resumes(tmp_path, capsys, checkpoints):
    """The untouched fixture checkpoint resumes (so the refusals above are about the damage)."""
    from tests.hostile.harness import run_cli

    folder = tmp_path / "ck"
    folder.mkdir()
    (folder / CHECKPOINT_STATE).write_bytes(checkpoints["@ck-state"])
    (folder / CHECKPOINT_CONFIG).write_text(checkpoints["@ck-config"], encoding="utf-8")
    code, stdout, stderr = run_cli(capsys, ["run", "--resume", str(folder), "--json", "--no-plots"])
    assert code == 0, stderr
    assert json.loads(stdout)["revolutions"] == OVERRIDES["simulation.revolutions"]
    assert not (folder / CHECKPOINT_STATE).exists()


def test_full_disk_while_checkpointing_keeps_the_previous_checkpoint(tmp_path):
    """A disk that fills up between checkpoints: one line, exit 2, the last checkpoint intact."""
    import os
    import subprocess
    import sys

    from jointwear.checkpoint import read_state
    from tests.hostile.harness import REPO
    from tests.hostile.test_output import small_filesystem

    with small_filesystem(tmp_path / "disk", "size=96k") as disk:
        out = disk / "run"
        sets = [
            "--set=simulation.revolutions=400",
            "--set=simulation.update_every=1",
            "--set=simulation.update_contour=true",
            "--set=contact.nodes=60",
            "--set=simulation.steps_per_revolution=60",
        ]
        argv = ["run", str(PAPER), *sets, "--out", str(out), "--checkpoint-every", "5", "--json"]
        done = subprocess.run(
            [sys.executable, "-m", "jointwear", *argv],
            capture_output=True,
            text=True,
            check=False,
            timeout=300,
            env={**os.environ, "PYTHONPATH": str(REPO / "src")},
        )
        assert done.returncode == 2, done.stderr
        assert done.stdout == ""
        line = done.stderr.splitlines()[-1]
        assert line.startswith(f"error: {out / CHECKPOINT_STATE}: cannot write the checkpoint")
        assert "no space left on device" in line
        assert f"jointwear run --resume {out}" in line
        state, _ = read_state(out / CHECKPOINT_STATE)
        assert 5 <= state.revolution < 400
        assert sorted(p.name for p in out.iterdir()) == [CHECKPOINT_STATE, CHECKPOINT_CONFIG]
