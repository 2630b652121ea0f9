"""Shared pieces of the sweep tests: the paper's joint on a coarse mesh, a sweep file
writer, and one serial sweep that the other ways of running are compared with."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from jointwear import load_config
from jointwear.workflows.sweep import load_sweep, run_sweep

REPO = Path(__file__).resolve().parents[3]
PAPER = REPO / "tests" / "data" / "paper_joint.toml"
#: a coarse mesh: NLCP in its mesh-independent form (the paper's needs 1 degree nodes)
TINY = """
[set]
"contact.nodes" = 60
"contact.nlcp_variant" = "mesh-independent"
"simulation.steps_per_revolution" = 60
"""


@pytest.fixture(scope="module")
def base():
    return load_config(
        PAPER,
        {
            "contact.nodes": 60,
            "contact.nlcp_variant": "mesh-independent",
            "simulation.steps_per_revolution": 60,
        },
    )


def write_sweep(folder: Path, body: str, base: str = "base.toml") -> Path:
    (folder / "base.toml").write_text(PAPER.read_text(encoding="utf-8"), encoding="utf-8")
    path = folder / "sweep.toml"
    path.write_text(f'base = "{base}"\n' + textwrap.dedent(body), encoding="utf-8")
    return path


def comparable(records):
    """Records without the wall-clock run time."""
    out = []
    for record in records:
        record = dict(record)
        record["metrics"] = {
            k: v for k, v in (record.get("metrics") or {}).items() if k != "runtime_s"
        }
        out.append(record)
    return out


SWEEP_BODY = (
    TINY
    + """
    [grid]
    "joint.clearance" = ["0.05 mm", "0.2 mm"]
    "mechanism.crank_speed" = ["120 rpm", "240 rpm"]
    [zip]
    "contact.model" = ["winkler", "nlcp"]
    "contact.exponent" = [1.0, 1.5]
"""
)


@pytest.fixture(scope="session")
def serial(tmp_path_factory):
    folder = tmp_path_factory.mktemp("serial")
    plan = load_sweep(write_sweep(folder, SWEEP_BODY))
    return plan, run_sweep(plan, folder / "out", workers=1)
