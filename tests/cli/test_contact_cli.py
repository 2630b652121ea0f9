"""``jointwear contact`` and ``jointwear models``: JSON output and one-line errors."""

from __future__ import annotations

import json
import subprocess
import sys

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.contact import ContactParameters, solve
from jointwear.geometry import BushingContour, Pin

KEYS = {
    "penetration_m",
    "contact_half_angle_left_deg",
    "contact_half_angle_right_deg",
    "peak_pressure_pa",
    "resultant_normal_n",
    "resultant_tangential_n",
    "springs_left",
    "springs_right",
    "iterations",
    "contact_model",
}
PAPER_MODELS = ["hertz", "winkler", "asymmetric-winkler", "nlcp"]


def run(capsys, *args):
    """Run the CLI in-process; return (exit status, stdout, stderr)."""
    try:
        main([str(a) for a in args])
        status = 0
    except SystemExit as exc:
        status = exc.code
    out, err = capsys.readouterr()
    return status, out, err


def contact_json(capsys, config, *args):
    status, out, err = run(capsys, "contact", config, *args, "--json")
    assert status == 0, err
    lines = out.strip().splitlines()
    assert len(lines) == 1, out  # exactly one JSON object, nothing else on stdout
    data = json.loads(lines[0])
    assert isinstance(data, dict)
    return data


def test_contact_json_has_the_documented_keys(capsys, paper_config_path, paper_config):
    data = contact_json(capsys, paper_config_path, "--load", "200 N", "--azimuth", "0 deg")
    assert set(data) >= KEYS
    assert data["contact_model"] == "asymmetric-winkler"  # from the example file
    # the same numbers as the library
    params = ContactParameters.from_config(paper_config)
    contour = BushingContour.circle(
        paper_config.joint.bushing_radius, 360, paper_config.joint.axial_length
    )
    ref = solve(
        contour, Pin(paper_config.joint.pin_radius), [200.0], [0.0], "asymmetric-winkler", params
    ).summary(0)
    for key in KEYS - {"contact_model"}:
        assert data[key] == pytest.approx(ref[key], rel=1e-12, abs=1e-12), key
    assert abs(data["resultant_normal_n"] - 200.0) <= 1e-12
    assert data["penetration_m"] == pytest.approx(9.213e-6, rel=1e-3)
    assert data["springs_left"] == data["springs_right"] == 32
    assert isinstance(data["springs_left"], int)
    assert isinstance(data["iterations"], int)


@pytest.mark.parametrize("model", PAPER_MODELS)
def test_contact_every_model(capsys, paper_config_path, model):
    data = contact_json(
        capsys, paper_config_path, "--model", model, "--load", "0.15 kN", "--azimuth", "30 deg"
    )
    assert data["contact_model"] == model
    assert data["resultant_normal_n"] == pytest.approx(150.0, abs=1e-9)
    assert data["penetration_m"] > 0
    assert data["peak_pressure_pa"] > 0
    assert np.isfinite(list(v for v in data.values() if isinstance(v, float))).all()


def test_contact_solves_a_circular_model_for_a_config_that_updates_its_contour(capsys):
    """One load on the unworn bushing: the contour update of the config plays no part."""
    from pathlib import Path

    updating = Path(__file__).resolve().parents[2] / "examples" / "paper" / "fig14_nlcp_update.toml"
    data = contact_json(capsys, updating, "--model", "winkler")
    same = contact_json(capsys, updating, "--model", "asymmetric-winkler")
    assert data["contact_model"] == "winkler"
    assert data["peak_pressure_pa"] == pytest.approx(same["peak_pressure_pa"], rel=1e-12)


def test_contact_units_and_equilibrium(capsys, paper_config_path):
    a = contact_json(capsys, paper_config_path, "--load", "200 N", "--azimuth", "0.5 rad")
    b = contact_json(
        capsys,
        paper_config_path,
        "--load",
        "0.2 kN",
        "--azimuth",
        f"{np.degrees(0.5)} deg",
        "--set",
        "contact.balance=equilibrium",
    )
    assert b["penetration_m"] == pytest.approx(a["penetration_m"], rel=1e-3)
    assert abs(b["resultant_tangential_n"]) <= 1e-12


def test_contact_set_changes_the_physics(capsys, paper_config_path):
    base = contact_json(capsys, paper_config_path)
    wider = contact_json(capsys, paper_config_path, "--set", 'joint.clearance="0.2 mm"')
    # a larger clearance makes the contact less conformal: narrower and deeper-pressed
    assert wider["contact_half_angle_left_deg"] < base["contact_half_angle_left_deg"]
    assert wider["peak_pressure_pa"] > base["peak_pressure_pa"]


def test_contact_table_output(capsys, paper_config_path):
    status, out, err = run(capsys, "contact", paper_config_path)
    assert status == 0, err
    assert "penetration" in out
    assert "N_L / N_R" in out


def test_models_lists_the_four_models(capsys):
    status, out, err = run(capsys, "models")
    assert status == 0, err
    for name in PAPER_MODELS:
        assert name in out
    assert "[contact]" in out  # the title's TOML section is not eaten by rich markup
    status, out, _ = run(capsys, "models", "--json")
    data = json.loads(out)
    assert set(PAPER_MODELS) <= set(data["contact_models"])


def test_python_dash_m_entry_point(paper_config_path):
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "jointwear",
            "contact",
            str(paper_config_path),
            "--json",
            "--load",
            "100 N",
        ],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.strip().splitlines()
    assert len(lines) == 1
    assert json.loads(lines[0])["resultant_normal_n"] == pytest.approx(100.0, abs=1e-9)


BAD = [
    # (arguments, text that must appear in the one-line message)
    (["--set", "joint.clearance=0"], "joint.clearance"),
    (["--set", "joint.clearance=-1e-5"], "joint.clearance"),
    (["--set", 'joint.clearance="-0.01 mm"'], "joint.clearance"),
    (["--set", "joint.pin_radius=0"], "joint.pin_radius"),
    (["--set", "joint.axial_length=0"], "joint.axial_length"),
    (["--set", "joint.bushing_thickness=-2e-3"], "joint.bushing_thickness"),
    (["--set", "materials.bushing.youngs_modulus=0"], "materials.bushing.youngs_modulus"),
    (["--set", 'materials.pin.youngs_modulus="-209 GPa"'], "materials.pin.youngs_modulus"),
    (["--set", "materials.pin.poisson_ratio=0.5"], "materials.pin.poisson_ratio"),
    (["--set", "materials.bushing.poisson_ratio=-1"], "materials.bushing.poisson_ratio"),
    (["--set", "materials.bushing.poisson_ratio=0.7"], "materials.bushing.poisson_ratio"),
    (["--model", "nlpc"], "did you mean 'nlcp'"),
    (["--set", "contact.model=nlpc"], "did you mean 'nlcp'"),
    (["--set", 'joint.clearance="5 kg"'], "joint.clearance"),
    (["--set", 'joint.axial_length="5 kg"'], "expected a length"),
    (["--load", "5 kg"], "--load"),
    (["--load", "-5 N"], "--load"),
    (["--azimuth", "5 m"], "--azimuth"),
    (["--load", "1e9 N"], "through the bushing wall"),
    (["--load", "1e9 N", "--model", "hertz"], "through the bushing wall"),
    (["--load", "1e9 N", "--set", "contact.balance=equilibrium"], "through the bushing wall"),
    (["--set", "joint.clearance=nan"], "joint.clearance"),
    (["--set", "joint.clearance=inf"], "joint.clearance"),
    (["--set", 'joint.clearance="nan mm"'], "joint.clearance"),
    (["--set", "materials.bushing.youngs_modulus=-inf"], "materials.bushing.youngs_modulus"),
    (["--load", "nan N"], "--load"),
    (["--load", "inf N"], "--load"),
    (["--azimuth", "nan deg"], "--azimuth"),
    (["--set", "joint.clearence=1e-5"], "did you mean 'clearance'"),
    (["--set", "jiont.clearance=1e-5"], "did you mean 'joint'"),
    (["--set", "materials.pin.young_modulus=1e9"], "did you mean 'youngs_modulus'"),
    (["--set", "contact.balance=equilibirum"], "did you mean 'equilibrium'"),
    (["--set", "joint.clearance"], "--set"),
    (["--lod", "200 N"], "--lod"),
]


@pytest.mark.parametrize(("args", "needle"), BAD, ids=[" ".join(a) for a, _ in BAD])
def test_bad_input_one_line_exit_2(capsys, paper_config_path, args, needle):
    status, out, err = run(capsys, "contact", paper_config_path, "--json", *args)
    assert status == 2
    assert out == ""
    assert "Traceback" not in err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert needle in lines[0]
    assert lines[0].startswith("error:")


def test_missing_and_malformed_config_files(capsys, tmp_path):
    status, _, err = run(capsys, "contact", tmp_path / "nope.toml")
    assert status == 2
    assert "nope.toml" in err
    assert len(err.strip().splitlines()) == 1
    bad = tmp_path / "bad.toml"
    bad.write_text("[joint\nclearance = 1\n")
    status, _, err = run(capsys, "contact", bad)
    assert status == 2
    assert "bad.toml" in err
    assert "Traceback" not in err
    assert len(err.strip().splitlines()) == 1


def test_pin_not_smaller_than_bushing_from_a_config_file(capsys, tmp_path, paper_config_path):
    text = paper_config_path.read_text().replace('clearance = "0.05 mm"', "clearance = 0.0")
    path = tmp_path / "zero.toml"
    path.write_text(text)
    status, _, err = run(capsys, "contact", path, "--json")
    assert status == 2
    assert "joint.clearance" in err
    assert len(err.strip().splitlines()) == 1
