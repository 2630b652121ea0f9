"""``jointwear measure``: JSON contract, both fits, and one-line errors with exit status 2."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.measurement.synthetic import cosine_squared_scar, synthesize_measurement

FIT_KEYS = {
    "center_x_m",
    "center_y_m",
    "radius_m",
    "peak_wear_depth_m",
    "wear_width_deg",
    "wear_area_m2",
    "rms_residual_m",
    "points",
    "points_used",
}
R0 = 7.5e-3
CENTER = (12.3e-3, -4.0e-3)


@pytest.fixture(scope="module")
def measured_csv(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A Table 5-sized scar (60 um, 170 deg at 30 deg), 3600 points in mm, 1 um noise."""
    depth = cosine_squared_scar(360, 60e-6, np.radians(170), np.radians(30))
    x, y = synthesize_measurement(depth, R0, 3600, 1e-6, 99, CENTER, rotation=0.0)
    path = tmp_path_factory.mktemp("measure") / "worn.csv"
    rows = "".join(f"{a * 1e3:.7f},{b * 1e3:.7f}\n" for a, b in zip(x, y, strict=True))
    path.write_text("x [mm],y [mm]\n" + rows, encoding="utf-8")
    return path


def run_json(capsys: pytest.CaptureFixture[str], *args: str) -> dict:
    main(["measure", *args, "--json"])
    captured = capsys.readouterr()
    lines = captured.out.strip().splitlines()
    assert len(lines) == 1, captured.out
    assert captured.err == ""
    return json.loads(lines[0])


def test_json_is_one_object_with_both_fits(
    capsys: pytest.CaptureFixture[str], measured_csv: Path
) -> None:
    data = run_json(capsys, str(measured_csv), "--radius", "7.5 mm")
    assert set(data) == {"fits"}
    assert set(data["fits"]) == {"least_squares", "robust"}
    for fit in data["fits"].values():
        assert fit.keys() >= FIT_KEYS
        assert fit["points"] == 3600
    robust, plain = data["fits"]["robust"], data["fits"]["least_squares"]
    # the robust fit finds the true centre and depth; least squares is pulled ~25 um
    assert np.hypot(robust["center_x_m"] - CENTER[0], robust["center_y_m"] - CENTER[1]) < 0.5e-6
    assert robust["radius_m"] == R0
    assert robust["peak_wear_depth_m"] == pytest.approx(60e-6, rel=0.05)
    assert robust["peak_angle_deg"] == pytest.approx(30, abs=3)
    assert np.hypot(plain["center_x_m"] - CENTER[0], plain["center_y_m"] - CENTER[1]) > 20e-6
    assert plain["peak_wear_depth_m"] < 0.7 * 60e-6
    assert robust["points_used"] < plain["points_used"] == 3600
    assert robust["wear_volume_m3"] is None  # no --axial-length


def test_options_units_nodes_mass_and_offset(
    capsys: pytest.CaptureFixture[str], measured_csv: Path, tmp_path: Path
) -> None:
    # the same points as bare metres in a whitespace file
    lines = measured_csv.read_text().splitlines()[1:]
    plain = tmp_path / "worn.txt"
    plain.write_text("".join(line.replace(",", " ") + "\n" for line in lines))
    data = run_json(
        capsys,
        str(plain),
        "--radius",
        "7.5e-3",
        "--units",
        "mm",
        "--nodes",
        "180",
        "--axial-length",
        "20 mm",
        "--density",
        "2200 kg/m^3",
        "--angle-offset",
        "30 deg",
        "--profile",
        "bin",
        "--floor",
        "3 um",
    )
    robust = data["fits"]["robust"]
    assert robust["nodes"] == 180
    assert robust["peak_angle_deg"] == pytest.approx(0, abs=4)  # 30 deg scar seen from 30 deg
    assert robust["wear_volume_m3"] == pytest.approx(
        20e-3 * robust["wear_area_m2"], rel=1e-6, abs=0
    )
    assert robust["wear_mass_kg"] == pytest.approx(2200 * 20e-3 * robust["wear_area_m2"])
    # h > 3 um over |phi| < 170 deg / pi * arccos(sqrt(3 / 60)), about 146 deg
    assert robust["wear_width_deg"] == pytest.approx(146, abs=6)


def test_table_output(capsys: pytest.CaptureFixture[str], measured_csv: Path) -> None:
    main(["measure", str(measured_csv), "--radius", "7.5 mm"])
    out = capsys.readouterr().out
    assert "least squares" in out
    assert "robust" in out
    assert "peak wear depth" in out


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["missing.csv", "--radius", "7.5 mm"], "missing.csv: file not found"),
        (["{bad}", "--radius", "7.5 mm"], "bad.csv: only 3 point(s)"),
        (["{good}", "--radius", "-7.5 mm"], "--radius: must be > 0"),
        (["{good}", "--radius", "7.5 kg"], "--radius:"),
        (["{good}", "--radius", "7.5 mm", "--units", "deg"], "--units: 'deg' is not a length"),
        (["{good}", "--radius", "7.5 mm", "--nodes", "4"], "--nodes: must be >= 16"),
        (["{good}"], "--radius"),  # required
    ],
)
def test_errors_exit_2_with_one_line(
    capsys: pytest.CaptureFixture[str],
    tmp_path: Path,
    measured_csv: Path,
    args: list[str],
    message: str,
) -> None:
    bad = tmp_path / "bad.csv"
    bad.write_text("x,y\n1,2\n3,4\n5,7\n")
    args = [a.format(bad=bad, good=measured_csv) for a in args]
    with pytest.raises(SystemExit) as info:
        main(["measure", *args, "--json"])
    assert info.value.code == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1
    assert message in captured.err
    assert "Traceback" not in captured.err


def test_console_script_bad_file_has_no_traceback(tmp_path: Path) -> None:
    result = subprocess.run(
        [
            sys.executable,
            "-c",
            "from jointwear.cli import main; main()",
            "measure",
            str(tmp_path / "nope.csv"),
            "--radius",
            "7.5 mm",
            "--json",
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr.strip().splitlines() == [f"error: {tmp_path / 'nope.csv'}: file not found"]
