"""The example scripts run (examples are documentation that must not rot)."""

from __future__ import annotations

import importlib.util
import runpy
from pathlib import Path

import pytest

EXAMPLES = sorted((Path(__file__).resolve().parents[1] / "examples").glob("*.py"))
#: examples that need an optional package, skipped where it is not installed
NEEDS = {"exudyn_handoff.py": "exudyn", "design_studies.py": "SALib"}


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(script: Path, capsys) -> None:
    needed = NEEDS.get(script.name)
    if needed and importlib.util.find_spec(needed) is None:
        pytest.skip(f"{script.name} needs {needed}")
    runpy.run_path(str(script), run_name="__main__")
    assert capsys.readouterr().out.strip()
