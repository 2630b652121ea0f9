"""Shared harness of the hostile-input suite.

A case is a :class:`Bad`: a command line (with ``{tmp}``, ``{out}`` and ``{paper}``
placeholders), the files it needs, and the fragments the one-line error must contain.
Each ``test_*.py`` module of this package holds a ``CASES`` list of them;
``python -m tests.hostile.catalogue`` (once written) renders every list, grouped by
``area``, into ``docs/bad-input.md``.

The contract every case asserts: exit status 2, exactly one line on stderr starting
with ``error:`` and containing every fragment, nothing on stdout, no traceback, and
nothing written or changed in ``--out`` or next to the inputs (no file, folder or link
created, none changed or removed).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import pytest
import typer

from jointwear import load_config
from jointwear.cli import app, main

REPO = Path(__file__).resolve().parents[2]
PAPER = REPO / "tests" / "data" / "paper_joint.toml"
SMALL = ["--set", "contact.nodes=60", "--set", "simulation.steps_per_revolution=60"]
COMMANDS = set(typer.main.get_command(app).commands)


@dataclass(frozen=True)
class Bad:
    """One bad input: the command line, the files it needs, what the message must say."""

    id: str
    area: str  # config | cli | data | sweep | run | output | files | signals | checkpoint
    argv: list[str]
    expect: list[str]
    files: dict[str, str | bytes] = field(default_factory=dict)
    command: str = ""

    def needs(self) -> str:
        return self.command or self.argv[0]


def tiny_toml() -> str:
    return PAPER.read_text(encoding="utf-8")


def sweep_toml(body: str) -> str:
    return 'base = "tiny.toml"\n[set]\n"contact.nodes" = 60\n' + body


GRID = '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n'
CSV_HEADER = "x [mm],y [mm]\n"

# ---------------------------------------------------------------- file makers


def materialise(tmp: Path, files: dict[str, str | bytes], result: bytes) -> None:
    """Create ``files`` under ``tmp``; besides text and bytes, a few markers.

    ``@dir`` a folder, ``@fifo`` a named pipe, ``@link:NAME`` a symbolic link to
    ``tmp/NAME``, ``@sparse:N`` an N MiB file of zeros (sparse), ``@tiny`` /
    ``@config`` / ``@result`` / ``@truncated-result`` / ``@foreign-netcdf`` real inputs,
    ``@result-without:NAME`` the real result without its variable ``NAME``.
    """
    import io
    import os

    import xarray as xr

    for name, content in files.items():
        path = tmp / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if content == "@dir":
            path.mkdir(exist_ok=True)
        elif content == "@fifo":
            os.mkfifo(path)
        elif isinstance(content, str) and content.startswith("@link:"):
            path.symlink_to(tmp / content.removeprefix("@link:"))
        elif isinstance(content, str) and content.startswith("@sparse:"):
            with open(path, "wb") as handle:
                handle.truncate(int(content.removeprefix("@sparse:")) * 2**20)
        elif content == "@tiny":
            path.write_text(tiny_toml(), encoding="utf-8")
        elif content == "@config":
            path.write_text(load_config(PAPER).to_toml(), encoding="utf-8")
        elif content == "@result":
            path.write_bytes(result)
        elif content == "@truncated-result":
            path.write_bytes(result[: len(result) // 3])
        elif isinstance(content, str) and content.startswith("@result-without:"):
            with xr.open_dataset(io.BytesIO(result), engine="h5netcdf") as whole:
                missing = whole.drop_vars(content.removeprefix("@result-without:")).load()
            missing.to_netcdf(path, engine="h5netcdf")
        elif content == "@foreign-netcdf":
            xr.Dataset({"a": ("x", [1.0, 2.0])}).to_netcdf(path, engine="h5netcdf")
        elif isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content, encoding="utf-8")


def expand(argv: list[str], tmp: Path, out: Path) -> list[str]:
    return [a.format(tmp=tmp, out=out, paper=PAPER) for a in argv]


def run_cli(capsys, argv: list[str]) -> tuple[int, str, str]:
    try:
        main(argv)
        code = 0
    except SystemExit as exc:
        code = exc.code if isinstance(exc.code, int) else 1
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def files_in(folder: Path) -> list[Path]:
    return [p for p in folder.rglob("*") if p.is_file()] if folder.exists() else []


def snapshot(folder: Path) -> dict[Path, tuple[str, bytes | str | None]]:
    """Every entry under ``folder`` (links not followed): its kind and content."""
    import os
    import stat

    entries: dict[Path, tuple[str, bytes | str | None]] = {}
    for root, dirs, names in os.walk(folder):
        for name in [*dirs, *names]:
            path = Path(root) / name
            mode = path.lstat().st_mode
            if stat.S_ISLNK(mode):
                entries[path] = ("link", os.readlink(path))
            elif stat.S_ISREG(mode):
                entries[path] = ("file", path.read_bytes())
            else:
                entries[path] = ("dir" if stat.S_ISDIR(mode) else "special", None)
    return entries


def check_contract(case: Bad, tmp_path: Path, capsys, result: bytes) -> None:
    """Run ``case`` in-process in ``tmp_path`` and assert the bad-input contract."""
    if case.needs() not in COMMANDS:
        pytest.fail(f"no `jointwear {case.needs()}` command")
    materialise(tmp_path, case.files, result)
    before = set(files_in(tmp_path))
    entries = snapshot(tmp_path)
    out = tmp_path / "out"
    argv = expand(case.argv, tmp_path, out)
    if case.area == "run" and "--out" not in argv:
        argv += ["--out", str(out), "--json", "--no-plots", "--quiet"]
    code, stdout, stderr = run_cli(capsys, argv)
    assert code == 2, stderr
    assert stdout == ""
    assert stderr.endswith("\n")
    assert stderr.count("\n") == 1, stderr
    assert stderr.startswith("error: ")
    assert "Traceback" not in stderr
    for fragment in case.expect:
        assert fragment in stderr, f"{fragment!r} not in {stderr!r}"
    # nothing written or changed: no results, no checkpoints, no temporary files or folders
    assert set(files_in(out)) <= before
    assert set(files_in(tmp_path)) == before
    assert snapshot(tmp_path) == entries


def check_cases(cases: list[Bad], area: str, minimum: int) -> None:
    """A module's ``CASES``: at least ``minimum``, all of ``area``, ids unique in the package."""
    import importlib
    import pkgutil

    assert len(cases) >= minimum
    assert {case.area for case in cases} == {area}
    package = Path(__file__).parent
    ids = [
        case.id
        for module in pkgutil.iter_modules([str(package)])
        if module.name.startswith("test_")
        for case in getattr(importlib.import_module(f"tests.hostile.{module.name}"), "CASES", [])
    ]
    assert len(ids) == len(set(ids)), sorted(i for i in ids if ids.count(i) > 1)
