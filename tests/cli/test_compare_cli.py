"""``jointwear compare``: JSON contract, plots in --out, one-line errors with exit status 2."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.cli import main
from jointwear.config import Config
from jointwear.measurement.synthetic import synthesize_measurement

REQUIRED = {
    "rms_error_m",
    "peak_wear_depth_simulated_m",
    "peak_wear_depth_measured_m",
    "peak_error_rel",
    "wear_width_simulated_deg",
    "wear_width_measured_deg",
    "width_error_deg",
    "wear_mass_simulated_kg",
    "wear_mass_measured_kg",
    "mass_error_rel",
    "alignment_offset_deg",
    "fit",
}
ROTATION_DEG = 57.0


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory, paper_config: Config) -> dict[str, Path]:
    """A simulated result (K_d 3e-12, 3000 revolutions, contour update) and its 'measurement'."""
    folder = tmp_path_factory.mktemp("compare")
    config = paper_config.replace(
        {
            "contact.nodes": 180,
            "simulation.steps_per_revolution": 60,
            "simulation.revolutions": 3000,
            "simulation.update_contour": True,
            "simulation.update_every": 100,
            "materials.bushing.wear_coefficient": 3e-12,
        }
    )
    result = Simulation(config).run()
    result.to_netcdf(folder / "result.nc")
    x, y = synthesize_measurement(
        result.wear_depth,
        config.bushing_radius,
        3600,
        0.7e-6,
        11,
        (3e-3, -2e-3),
        math.radians(ROTATION_DEG),
    )
    rows = "".join(f"{a * 1e3:.7f},{b * 1e3:.7f}\n" for a, b in zip(x, y, strict=True))
    (folder / "worn.csv").write_text("x [mm],y [mm]\n" + rows, encoding="utf-8")
    (folder / "worn_plain.txt").write_text(rows.replace(",", " "), encoding="utf-8")
    arc = np.linspace(0.0, np.pi / 2, 50)
    (folder / "arc.csv").write_text(
        "x,y\n" + "".join(f"{7.5e-3 * np.cos(a)},{7.5e-3 * np.sin(a)}\n" for a in arc)
    )
    (folder / "fake.nc").write_text("this is not netCDF\n")
    return {
        "result": folder / "result.nc",
        "csv": folder / "worn.csv",
        "plain": folder / "worn_plain.txt",
        "arc": folder / "arc.csv",
        "fake": folder / "fake.nc",
        "peak": result.wear_depth.max(),  # type: ignore[dict-item]
    }


def run_json(capsys: pytest.CaptureFixture[str], *args: str) -> dict:
    main(["compare", *args, "--json"])
    captured = capsys.readouterr()
    lines = captured.out.strip().splitlines()
    assert len(lines) == 1, captured.out
    assert captured.err == ""
    return json.loads(lines[0])


def test_json_contract_and_recovery(capsys: pytest.CaptureFixture[str], files: dict) -> None:
    data = run_json(capsys, str(files["result"]), str(files["csv"]), "--floor", "2 um")
    assert data.keys() >= REQUIRED
    assert data["fit"] == "robust"
    assert data["peak_wear_depth_simulated_m"] == pytest.approx(files["peak"])
    assert abs(data["peak_error_rel"]) < 0.02
    assert data["rms_error_m"] < 0.5e-6
    assert abs(data["width_error_deg"]) < 3
    assert abs(data["mass_error_rel"]) < 0.01
    assert data["wear_mass_simulated_kg"] > 0  # axial length and density from the result
    assert data["alignment_offset_deg"] == pytest.approx(ROTATION_DEG, abs=0.3)
    assert data["original_radius_m"] == pytest.approx(7.5e-3)
    assert data["revolution"] == 3000
    assert data["nodes"] == 180
    assert "files" not in data


def test_plain_fit_given_alignment_and_units(
    capsys: pytest.CaptureFixture[str], files: dict
) -> None:
    plain = run_json(
        capsys,
        str(files["result"]),
        str(files["plain"]),
        "--units",
        "mm",
        "--fit",
        "least-squares",
        "--align",
        f"{ROTATION_DEG} deg",
    )
    assert plain["fit"] == "least-squares"
    assert plain["alignment"] == "given"
    assert plain["alignment_offset_deg"] == pytest.approx(ROTATION_DEG)
    assert plain["peak_error_rel"] < -0.3  # the biased centre under-reports the depth
    robust = run_json(capsys, str(files["result"]), str(files["plain"]), "--units", "mm")
    assert abs(robust["peak_error_rel"]) < abs(plain["peak_error_rel"]) / 10


def test_out_writes_plots_and_data(
    capsys: pytest.CaptureFixture[str], files: dict, tmp_path: Path
) -> None:
    out = tmp_path / "cmp"
    main(["compare", str(files["result"]), str(files["csv"]), "--out", str(out)])
    text = capsys.readouterr().out
    assert "wear peak" in text
    assert "RMS error" in text
    assert "--floor" in text  # the noise note
    names = sorted(p.name for p in out.iterdir())
    assert names == [
        "compare_polar.png",
        "compare_polar.svg",
        "compare_profile.png",
        "compare_profile.svg",
        "comparison.json",
        "profiles.csv",
    ]
    stored = json.loads((out / "comparison.json").read_text())
    assert stored.keys() >= REQUIRED
    table = (out / "profiles.csv").read_text().splitlines()
    assert table[0].startswith("theta [deg],simulated [m],measured [m]")
    assert len(table) == 1 + 180


def test_console_script_error_has_no_traceback(files: dict, tmp_path: Path) -> None:
    out = tmp_path / "out"
    result = subprocess.run(
        [
            sys.executable,
            "-c",
            "from jointwear.cli import main; main()",
            "compare",
            str(files["fake"]),
            str(files["csv"]),
            "--out",
            str(out),
            "--json",
        ],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2
    assert result.stdout == ""
    (line,) = result.stderr.strip().splitlines()
    assert line.startswith(f"error: {files['fake']}: not a readable netCDF result")
    assert not out.exists()


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["{fake}", "{csv}"], "fake.nc: not a readable netCDF result"),
        (["{csv}", "{csv}"], "worn.csv: not a readable netCDF result"),
        (["{result}", "{arc}"], "arc.csv: the points cover only"),
        (["{result}", "{result}"], "result.nc: not a text file"),
        (
            ["{result}", "{csv}", "--fit", "robustt"],
            "--fit: unknown circle fit 'robustt'; did you mean 'robust'?",
        ),
        (["{result}", "{csv}", "--units", "kg"], "--units: 'kg' is not a length unit"),
        (["{result}", "{csv}", "--units", "um"], "worn.csv: column 'x' is in mm but units 'um'"),
        (["{result}", "{csv}", "--align", "12 kg"], "--align:"),
        (["{result}", "{csv}", "--profile", "bins"], "did you mean 'bin'?"),
        (["{result}", "{csv}", "--revolution", "7"], "--revolution:"),
        (["{result}", "missing.csv"], "missing.csv: file not found"),
    ],
)
def test_errors_exit_2_one_line_and_no_partial_output(
    capsys: pytest.CaptureFixture[str],
    files: dict,
    tmp_path: Path,
    args: list[str],
    message: str,
) -> None:
    out = tmp_path / "out"
    args = [a.format(**files) for a in args]
    with pytest.raises(SystemExit) as info:
        main(["compare", *args, "--out", str(out), "--json"])
    assert info.value.code == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1, captured.err
    assert message in captured.err
    assert "Traceback" not in captured.err
    assert not out.exists()


def test_out_that_is_a_file(
    capsys: pytest.CaptureFixture[str], files: dict, tmp_path: Path
) -> None:
    target = tmp_path / "taken"
    target.write_text("keep me")
    with pytest.raises(SystemExit) as info:
        main(["compare", str(files["result"]), str(files["csv"]), "--out", str(target)])
    assert info.value.code == 2
    assert "is not a directory" in capsys.readouterr().err
    assert target.read_text() == "keep me"


def test_measured_frame_beside_the_alignment(
    capsys: pytest.CaptureFixture[str], files: dict
) -> None:
    """The measured peak angle is the one as measured; the rotation is shown on its own."""
    data = run_json(capsys, str(files["result"]), str(files["csv"]))
    # a deepest node of a flat-topped, noisy scar: good to two nodes (180 nodes)
    node = 2 * 2.0
    assert data["peak_angle_difference_deg"] == pytest.approx(ROTATION_DEG, abs=node)
    assert data["peak_angle_measured_deg"] == pytest.approx(
        (data["peak_angle_simulated_deg"] + ROTATION_DEG) % 360, abs=node
    )
    assert data["peak_angle_residual_deg"] == pytest.approx(0.0, abs=node)
    simulated = data["peak_angle_simulated_deg"]
    assert data["peak_angle_aligned_deg"] == pytest.approx(simulated, abs=node)
    main(["compare", str(files["result"]), str(files["csv"])])
    text = capsys.readouterr().out
    row = next(line for line in text.splitlines() if "peak angle as measured" in line)
    assert f"{data['peak_angle_measured_deg']:.4g}°" in row
    assert f"{data['peak_angle_difference_deg']:+.3g}°" in row
    assert "rotation (best fit)" in text
    assert f"peak angle, rotated {data['alignment_offset_deg']:+.3g}°" in text
