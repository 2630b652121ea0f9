"""Hostile input files: pipes, devices, folders, huge, deeply nested or mis-encoded files.

Every reader of user files (config and sweep TOML, measured-point and load-history CSV,
result netCDF, checkpoints) goes through one policy (:mod:`jointwear.io`): a regular file
only (a FIFO is refused without being opened, so nothing hangs), at most 64 MiB of text
(``JOINTWEAR_MAX_INPUT_MB`` raises it), UTF-8 with or without a byte-order mark, TOML
nested at most 32 levels deep.
"""

from __future__ import annotations

import json
import math

import pytest

from jointwear.config import MAX_TOML_DEPTH
from tests.hostile.harness import (
    CSV_HEADER,
    GRID,
    PAPER,
    REPO,
    Bad,
    check_cases,
    check_contract,
    run_cli,
    sweep_toml,
    tiny_toml,
)

HISTORY_TOML = (
    (REPO / "examples" / "load_history" / "load_history.toml")
    .read_text(encoding="utf-8")
    .replace("revolutions = 20000", "revolutions = 2")
)
RADIUS = ["--radius", "7.5 mm"]
LATIN1 = '[joint]\n# Spiel 0,05 mm \xb1 2 \xb5m\nclearance = "0.05 mm"\n'.encode("latin-1")
RESULT = {"result.nc": "@result"}


def nested_array(depth: int) -> str:
    return "[joint]\nclearance = " + "[" * depth + "1" + "]" * depth + "\n"


def nested_tables(depth: int) -> str:
    return "[" + ".".join(f"t{i}" for i in range(depth)) + "]\nx = 1\n"


def nested_inline(depth: int) -> str:
    return "a = " + "{ b = " * depth + "1" + " }" * depth + "\n"


def reader_cases(prefix: str, argv: list[str], name: str, extra: dict | None = None) -> list[Bad]:
    """The same hostile file kinds for one reader (``name`` is the file it reads)."""
    extra = extra or {}
    return [
        Bad(
            f"{prefix}-fifo",
            "files",
            argv,
            [name, "named pipe", "not a regular file"],
            {**extra, name: "@fifo"},
        ),
        Bad(
            f"{prefix}-directory",
            "files",
            argv,
            [name, "is a directory"],
            {**extra, name: "@dir"},
        ),
        Bad(
            f"{prefix}-link-to-directory",
            "files",
            argv,
            [name, "is a directory"],
            {**extra, "somewhere": "@dir", name: "@link:somewhere"},
        ),
        Bad(
            f"{prefix}-dangling-link",
            "files",
            argv,
            [name, "file not found"],
            {**extra, name: "@link:nowhere"},
        ),
        Bad(
            f"{prefix}-too-large",
            "files",
            argv,
            [name, "too large", "64 MiB", "JOINTWEAR_MAX_INPUT_MB"],
            {**extra, name: "@sparse:65"},
        ),
        Bad(
            f"{prefix}-utf16",
            "files",
            argv,
            [name, "not a text file"],
            {**extra, name: "x,y\n1,2\n".encode("utf-16")},
        ),
    ]


CASES: list[Bad] = [
    # ------------------------------------------------------------ config (TOML)
    *reader_cases("config", ["run", "{tmp}/c.toml", "--out", "{out}"], "c.toml"),
    Bad(
        "config-device",
        "files",
        ["run", "/dev/null", "--out", "{out}"],
        ["/dev/null", "is a device"],
    ),
    Bad(
        "config-latin1",
        "files",
        ["run", "{tmp}/c.toml"],
        ["c.toml", "not a text file", "UTF-8"],
        {"c.toml": LATIN1},
    ),
    Bad(
        "config-nested-arrays",
        "files",
        ["run", "{tmp}/c.toml"],
        ["c.toml", f"nested more than {MAX_TOML_DEPTH} levels"],
        {"c.toml": nested_array(MAX_TOML_DEPTH + 1)},
    ),
    Bad(
        "config-arrays-past-the-recursion-limit",
        "files",
        ["run", "{tmp}/c.toml"],
        ["c.toml", "nested more than"],
        {"c.toml": nested_array(5000)},
    ),
    Bad(
        "config-nested-tables",
        "files",
        ["run", "{tmp}/c.toml"],
        ["c.toml", "nested more than"],
        {"c.toml": nested_tables(MAX_TOML_DEPTH + 5)},
    ),
    Bad(
        "config-nested-inline-tables",
        "files",
        ["run", "{tmp}/c.toml"],
        ["c.toml", "nested more than"],
        {"c.toml": nested_inline(2000)},
    ),
    Bad(
        "config-nul-bytes",
        "files",
        ["run", "{tmp}/c.toml"],
        ["c.toml", "not valid TOML"],
        {"c.toml": b'[joint]\nclearance = "0.05 mm"\x00\x00\n'},
    ),
    # ------------------------------------------------------------ sweep files
    *reader_cases("sweep-file", ["sweep", "{tmp}/s.toml", "--out", "{out}"], "s.toml"),
    Bad(
        "sweep-file-nested",
        "files",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["s.toml", "nested more than"],
        {"s.toml": sweep_toml(GRID) + nested_inline(MAX_TOML_DEPTH + 1), "tiny.toml": "@tiny"},
    ),
    Bad(
        "sweep-base-fifo",
        "files",
        ["sweep", "{tmp}/s.toml", "--out", "{out}"],
        ["tiny.toml", "named pipe"],
        {"s.toml": sweep_toml(GRID), "tiny.toml": "@fifo"},
    ),
    # ------------------------------------------------------------ measured points (CSV)
    *reader_cases("measured", ["measure", "{tmp}/m.csv", *RADIUS], "m.csv"),
    Bad(
        "measured-device",
        "files",
        ["measure", "/dev/zero", *RADIUS],
        ["/dev/zero", "is a device"],
    ),
    Bad(
        "compare-measured-fifo",
        "files",
        ["compare", "{tmp}/result.nc", "{tmp}/m.csv", "--out", "{out}"],
        ["m.csv", "named pipe"],
        {**RESULT, "m.csv": "@fifo"},
    ),
    # ------------------------------------------------------------ load histories (CSV)
    *reader_cases("history", ["dynamics", "{tmp}/h.toml"], "loads.csv", {"h.toml": HISTORY_TOML}),
    Bad(
        "history-binary",
        "files",
        ["dynamics", "{tmp}/h.toml"],
        ["loads.csv", "not a text file"],
        {"h.toml": HISTORY_TOML, "loads.csv": b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\xff\xfe"},
    ),
    # ------------------------------------------------------------ results (netCDF)
    Bad(
        "plot-result-fifo",
        "files",
        ["plot", "{tmp}/r.nc", "--out", "{out}"],
        ["r.nc", "named pipe"],
        {"r.nc": "@fifo"},
    ),
    Bad(
        "plot-result-directory",
        "files",
        ["plot", "{tmp}/r.nc", "--out", "{out}"],
        ["r.nc", "is a directory"],
        {"r.nc": "@dir"},
    ),
    Bad(
        "plot-result-device",
        "files",
        ["plot", "/dev/zero", "--out", "{out}"],
        ["/dev/zero", "is a device"],
    ),
    Bad(
        "plot-result-empty",
        "files",
        ["plot", "{tmp}/r.nc", "--out", "{out}"],
        ["r.nc", "not a readable netCDF result"],
        {"r.nc": b""},
    ),
    Bad(
        "plot-result-is-a-config",
        "files",
        ["plot", "{tmp}/r.nc", "--out", "{out}"],
        ["r.nc", "not a readable netCDF result"],
        {"r.nc": tiny_toml()},
    ),
    Bad(
        "compare-foreign-netcdf",
        "files",
        ["compare", "{tmp}/r.nc", "{tmp}/m.csv", "--out", "{out}"],
        ["r.nc", "not a jointwear result"],
        {"r.nc": "@foreign-netcdf", "m.csv": CSV_HEADER + "1,2\n"},
    ),
    Bad(
        "compare-truncated-netcdf",
        "files",
        ["compare", "{tmp}/r.nc", "{tmp}/m.csv", "--out", "{out}"],
        ["r.nc", "not a readable netCDF result"],
        {"r.nc": "@truncated-result", "m.csv": CSV_HEADER + "1,2\n"},
    ),
    Bad(
        "compare-result-fifo",
        "files",
        ["compare", "{tmp}/r.nc", "{tmp}/m.csv", "--out", "{out}"],
        ["r.nc", "named pipe"],
        {"r.nc": "@fifo", "m.csv": CSV_HEADER + "1,2\n"},
    ),
]


def test_file_cases_are_many_and_unique():
    """The file cases cover every reader and each id is unique across the suite."""
    check_cases(CASES, "files", 40)


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_file(case: Bad, tmp_path, capsys, result_bytes):
    """The case's command fails with its one line, exit 2, nothing written."""
    check_contract(case, tmp_path, capsys, result_bytes)


def test_byte_order_mark_is_accepted(tmp_path, capsys):
    """A config and a measured CSV saved with a UTF-8 byte-order mark read like without one."""
    config = tmp_path / "bom.toml"
    config.write_bytes(b"\xef\xbb\xbf" + tiny_toml().encode("utf-8"))
    code, stdout, stderr = run_cli(capsys, ["contact", str(config), "--load", "1 kN", "--json"])
    assert code == 0, stderr
    plain_code, plain, _ = run_cli(capsys, ["contact", str(PAPER), "--load", "1 kN", "--json"])
    assert plain_code == 0
    assert json.loads(stdout) == json.loads(plain)

    theta = [i * 0.1 for i in range(60)]
    rows = CSV_HEADER + "".join(f"{7.5 * math.cos(t)},{7.5 * math.sin(t)}\n" for t in theta)
    summaries = []
    for name, prefix in (("bom.csv", b"\xef\xbb\xbf"), ("plain.csv", b"")):
        (tmp_path / name).write_bytes(prefix + rows.encode("utf-8"))
        code, stdout, stderr = run_cli(
            capsys, ["measure", str(tmp_path / name), *RADIUS, "--nodes", "60", "--json"]
        )
        assert code == 0, stderr
        summaries.append({k: v for k, v in json.loads(stdout).items() if "csv" not in str(v)})
    assert summaries[0] == summaries[1]


def test_size_limit_is_configurable(tmp_path, capsys, monkeypatch):
    """JOINTWEAR_MAX_INPUT_MB lowers (or raises) the limit; a bad value is a one-line error."""
    config = tmp_path / "c.toml"
    config.write_text(tiny_toml() + "#" * 2000 + "\n", encoding="utf-8")
    monkeypatch.setenv("JOINTWEAR_MAX_INPUT_MB", "0.001")
    code, _, stderr = run_cli(capsys, ["contact", str(config), "--load", "1 kN"])
    assert code == 2
    assert "too large" in stderr
    assert stderr.count("\n") == 1
    monkeypatch.setenv("JOINTWEAR_MAX_INPUT_MB", "lots")
    code, _, stderr = run_cli(capsys, ["contact", str(config), "--load", "1 kN"])
    assert code == 2
    assert stderr.startswith("error: JOINTWEAR_MAX_INPUT_MB: expected a number")
    monkeypatch.setenv("JOINTWEAR_MAX_INPUT_MB", "1")
    code, _, stderr = run_cli(capsys, ["contact", str(config), "--load", "1 kN", "--json"])
    assert code == 0, stderr


def test_nesting_at_the_limit_is_read(tmp_path):
    """A TOML file nested exactly MAX_TOML_DEPTH levels deep is still read."""
    from jointwear.config import read_toml

    path = tmp_path / "deep.toml"
    path.write_text(nested_inline(MAX_TOML_DEPTH - 1), encoding="utf-8")
    data = read_toml(path)
    depth = 0
    while isinstance(data, dict):
        data, depth = next(iter(data.values())), depth + 1
    assert depth == MAX_TOML_DEPTH
