"""``jointwear dynamics``: JSON contract, CSV output, contact-loss warning and --strict."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest

from jointwear.cli import main

REQUIRED_KEYS = {
    "load_min_n",
    "load_max_n",
    "load_mean_n",
    "load_sliding_mean_n",
    "azimuth_range_deg",
    "azimuth_min_deg",
    "azimuth_max_deg",
    "contact_lost",
    "contact_lost_crank_angles_deg",
    "steps",
    "total_relative_rotation_rad",
    "crank_torque_rms_nm",
}
CONTACT_LOSS = [
    "--set",
    "mechanism.spring_mode=push",
    "--set",
    "mechanism.spring_preload=1",
    "--set",
    "mechanism.crank_speed=240 rpm",
]


def run_json(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[dict, str]:
    main(["dynamics", *args, "--json"])
    captured = capsys.readouterr()
    lines = captured.out.strip().splitlines()
    assert len(lines) == 1, captured.out
    return json.loads(lines[0]), captured.err


def test_json_has_contract_keys(
    capsys: pytest.CaptureFixture[str], paper_config_path: Path
) -> None:
    data, err = run_json(capsys, str(paper_config_path))
    assert data.keys() >= REQUIRED_KEYS
    assert err == ""
    assert data["steps"] == 360
    assert data["contact_lost"] is False
    assert data["contact_lost_crank_angles_deg"] == []
    assert 0 < data["load_min_n"] < data["load_mean_n"] < data["load_max_n"]
    assert data["azimuth_range_deg"] == pytest.approx(
        data["azimuth_max_deg"] - data["azimuth_min_deg"]
    )
    assert data["total_relative_rotation_rad"] == pytest.approx(4 * np.arcsin(0.07 / 0.2), rel=1e-3)


def test_speed_option_with_units_raises_sliding_mean_load(
    capsys: pytest.CaptureFixture[str], paper_config_path: Path
) -> None:
    slow, _ = run_json(capsys, str(paper_config_path))
    fast, _ = run_json(capsys, str(paper_config_path), "--set", "mechanism.crank_speed=240 rpm")
    assert fast["load_sliding_mean_n"] > slow["load_sliding_mean_n"]


def test_csv_has_unit_headers_and_matches_json(
    capsys: pytest.CaptureFixture[str], paper_config_path: Path, tmp_path: Path
) -> None:
    out = tmp_path / "sub" / "load.csv"
    data, _ = run_json(capsys, str(paper_config_path), "--csv", str(out))
    with out.open(newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    header, body = rows[0], np.array(rows[1:], dtype=float)
    assert header[:4] == ["time [s]", "force_x [N]", "force_y [N]", "rotation [rad]"]
    units = {"load [N]", "azimuth [deg]", "relative_rotation [rad]", "crank_torque [N m]"}
    assert units <= set(header)
    assert all("[" in name and name.endswith("]") for name in header)
    # one row per step and the closing row at the period
    assert body.shape == (361, len(header))
    load = body[:, header.index("load [N]")]
    assert load.max() == pytest.approx(data["load_max_n"], rel=1e-15, abs=0)
    np.testing.assert_allclose(body[:, header.index("phase [deg]")], np.arange(361.0))
    np.testing.assert_allclose(body[:, 0], np.arange(361.0) * data["period_s"] / 360)
    assert not list(tmp_path.glob("sub/.*.tmp"))  # no temporary file left behind


def test_table_output(capsys: pytest.CaptureFixture[str], paper_config_path: Path) -> None:
    main(["dynamics", str(paper_config_path)])
    out = capsys.readouterr().out
    assert "sliding-weighted mean" in out
    assert "massless-link" in out


def test_contact_loss_warns_on_stderr(
    capsys: pytest.CaptureFixture[str], paper_config_path: Path
) -> None:
    data, err = run_json(capsys, str(paper_config_path), *CONTACT_LOSS)
    assert data["contact_lost"] is True
    assert data["contact_lost_crank_angles_deg"][:3] == [0.0, 1.0, 2.0]
    assert err.startswith("warning:")
    assert "crank angles 0-30, 329-359 deg" in err


def test_strict_contact_loss_exits_2(
    capsys: pytest.CaptureFixture[str], paper_config_path: Path
) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["dynamics", str(paper_config_path), *CONTACT_LOSS, "--strict", "--json"])
    assert exit_info.value.code == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1
    assert lines[0].startswith("error: ")
    assert "reverses relative to the rod" in lines[0]


def test_unknown_dynamics_model_exits_2(
    capsys: pytest.CaptureFixture[str], paper_config_path: Path
) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["dynamics", str(paper_config_path), "--set", "dynamics.model=massles-link"])
    assert exit_info.value.code == 2
    assert "did you mean 'massless-link'" in capsys.readouterr().err


def test_mechanisms_lists_the_joints_own_keys_and_shows_table_headers_literally(capsys):
    """The catalogue names every key a user can set on the joint (slices along the pin, the
    pin, the oil), each accepted by the config; TOML table headers in descriptions are
    printed as written, not read as console markup."""
    from jointwear import load_config

    main(["mechanisms", "--json"])
    sections = json.loads(capsys.readouterr().out)["joint_sections"]
    assert {"axial_slices", "misalignment", "load_offset"} <= set(sections["joint"])
    assert {"model", "support", "forks"} <= set(sections["pin"])
    assert {"model", "viscosity", "lubricant", "roughness"} <= set(sections["lubrication"])
    config = load_config(None, {"joint.axial_slices": 4, "lubrication.model": "dry"})
    assert config.joint.axial_slices == 4
    main(["mechanisms"])
    text = " ".join(capsys.readouterr().out.split())
    assert "[[mechanism.modes" in text
    assert "[lubrication]" in text
