"""Every help page fits an 80-column terminal: no option text cut short with "…"."""

from __future__ import annotations

import pytest

from jointwear.cli import main

COMMANDS = [
    "",
    "calibrate",
    "compare",
    "compare-models",
    "contact",
    "dynamics",
    "measure",
    "models",
    "plot",
    "reproduce",
    "run",
    "life",
    "mechanisms",
    "sweep",
    "warm-up",
]


@pytest.mark.parametrize("command", COMMANDS)
def test_help_is_not_cut_at_80_columns(command, capsys, monkeypatch) -> None:
    monkeypatch.setenv("COLUMNS", "80")
    status = 0
    try:
        main([*command.split(), "--help"])
    except SystemExit as stop:  # subcommands exit after their help, the root returns
        status = stop.code
    assert status in (0, None)
    out = capsys.readouterr().out
    assert "Usage" in out
    assert max(len(line) for line in out.splitlines()) <= 80
    assert "…" not in out
