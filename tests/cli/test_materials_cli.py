"""``jointwear materials`` and the material checks of ``jointwear run``."""

from __future__ import annotations

import json

from jointwear.cli import main
from jointwear.materials import library

FAST = ["--set", "contact.nodes=120", "--set", "simulation.steps_per_revolution=90"]


def test_materials_json_lists_every_material_with_sources(capsys):
    main(["materials", "--json"])
    data = json.loads(capsys.readouterr().out)
    assert set(data["materials"]) == set(library())
    bronze = data["materials"]["bronze"]
    assert bronze["max_pv"] == 2.625e6
    assert data["units"]["max_pv"] == "Pa*m/s"
    assert set(bronze["sources"]) == set(bronze["values"])


def test_materials_table_and_one_material(capsys):
    main(["materials"])
    out = capsys.readouterr().out
    assert all(name in out for name in library())
    main(["materials", "bronze-sintered"])
    out = capsys.readouterr().out
    assert "Mott 16-1" in out
    assert "1.75 MPa m/s" in out


def test_run_reports_pv_against_the_bronze_limit(paper_config_path, capsys):
    main(["run", str(paper_config_path), *FAST, "--set", "materials.bushing=bronze", "--json"])
    captured = capsys.readouterr()
    checks = json.loads(captured.out)["checks"]
    assert checks["pv"]["limit"] == 2.625e6
    assert checks["pv"]["unit"] == "Pa*m/s"
    assert checks["pv"]["ok"] is True
    assert 0 < checks["pv"]["value"] <= checks["pv_max"]["value"]
    assert checks["pv"]["limit_key"] == "materials.bushing.max_pv"
    assert "warning" not in captured.err


def test_run_warns_in_one_line_when_a_limit_is_exceeded(paper_config_path, capsys):
    main(
        [
            "run",
            str(paper_config_path),
            *FAST,
            "--set",
            "materials.bushing=ptfe",
            "--set",
            "materials.bushing.max_pv=0.001 MPa*m/s",
            "--json",
        ]
    )
    captured = capsys.readouterr()
    assert json.loads(captured.out)["checks"]["pv"]["ok"] is False
    lines = captured.err.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("warning: materials.bushing.max_pv: nominal PV (cycle mean)")
    assert "exceeds the limit 0.001 MPa m/s of 'ptfe'" in lines[0]
