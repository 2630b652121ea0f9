"""``jointwear calibrate``: K_d from measured files, several cases, the paper row, errors."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from jointwear import Simulation
from jointwear.cli import main
from jointwear.config import Config
from jointwear.measurement.synthetic import synthesize_measurement

KD = "materials.bushing.wear_coefficient"
TRUE_KD = 3e-12

CONFIG = """\
parameter_set = "nlcp-paper"

[mechanism]
crank_length = "70 mm"
rod_length = "200 mm"
crank_mass = "0.46 kg"
rod_mass = "1.09 kg"
slider_mass = "5 kg"
spring_stiffness = "1800 N/m"
spring_mode = "pull"
spring_preload = "20 N"
crank_speed = "120 rpm"

[joint]
pin_radius = "7.45 mm"
clearance = "0.05 mm"
axial_length = "20 mm"
bushing_thickness = "2.5 mm"

[materials.pin]
youngs_modulus = "209 GPa"
poisson_ratio = 0.28

[materials.bushing]
youngs_modulus = "500 MPa"
poisson_ratio = 0.38
density = "2200 kg/m^3"
wear_coefficient = "3e-11 m^2/N"  # ten times the truth: the starting value

[contact]
model = "asymmetric-winkler"
nodes = 180

[simulation]
steps_per_revolution = 60
revolutions = 3000
update_contour = false
"""


def write_measurement(
    config: Config,
    path: Path,
    seed: int,
    rotation_deg: float,
    overrides: dict[str, object] | None = None,
) -> None:
    truth = config.replace({KD: TRUE_KD, **(overrides or {})})
    depth = Simulation(truth).run().wear_depth
    x, y = synthesize_measurement(
        depth,
        truth.bushing_radius,
        2000,
        0.5e-6,
        seed,
        (5e-3, 1e-3),
        math.radians(rotation_deg),
    )
    rows = "".join(f"{a * 1e3:.7f},{b * 1e3:.7f}\n" for a, b in zip(x, y, strict=True))
    path.write_text("x [mm],y [mm]\n" + rows, encoding="utf-8")


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    from jointwear.config import load_config

    folder = tmp_path_factory.mktemp("calibrate")
    config_path = folder / "joint.toml"
    config_path.write_text(CONFIG, encoding="utf-8")
    config = load_config(config_path)
    write_measurement(config, folder / "slow.csv", 1, 30.0)
    write_measurement(config, folder / "fast.csv", 2, 250.0, {"mechanism.crank_speed": "240 rpm"})
    (folder / "line.csv").write_text("x,y\n" + "".join(f"{i},{2 * i}\n" for i in range(20)))
    return {
        "config": config_path,
        "slow": folder / "slow.csv",
        "fast": folder / "fast.csv",
        "line": folder / "line.csv",
    }


def run_json(capsys: pytest.CaptureFixture[str], *args: str) -> dict:
    main(["calibrate", *args, "--json"])
    captured = capsys.readouterr()
    lines = captured.out.strip().splitlines()
    assert len(lines) == 1, captured.out
    assert captured.err == ""
    return json.loads(lines[0])


def test_json_shape_and_recovered_kd(capsys: pytest.CaptureFixture[str], files: dict) -> None:
    data = run_json(capsys, str(files["config"]), str(files["slow"]), "--fit", "wear_coefficient")
    assert set(data) >= {"parameters", "rms_residual", "evaluations", "cases"}
    assert list(data["parameters"]) == [KD]
    kd = data["parameters"][KD]
    assert set(kd) >= {"value", "uncertainty", "unit"}
    assert kd["unit"] == "1/Pa"
    assert kd["initial"] == pytest.approx(10 * TRUE_KD, rel=1e-6, abs=0)
    assert kd["value"] == pytest.approx(TRUE_KD, rel=0.02, abs=0)
    assert 0 < kd["uncertainty"] < 0.02 * TRUE_KD
    low, high = kd["interval"]
    assert low < TRUE_KD < high
    assert kd["confidence"] == 0.95
    assert data["method"]["global"] == "grid"
    assert data["method"]["polish"] == "least_squares"
    assert data["warnings"] == []
    assert data["cases"][0]["noise_m"] == pytest.approx(0.5e-6, rel=0.2)
    assert data["cases"][0]["misfit_ratio"] < 1.2
    assert data["rms_residual"] < 0.05
    assert data["evaluations"] > 1
    assert data["cases"][0]["name"] == "slow.csv"
    assert data["cases"][0]["alignment_offset_deg"] == pytest.approx(30, abs=0.5)


def test_two_cases_with_their_own_speed_and_table(
    capsys: pytest.CaptureFixture[str], files: dict
) -> None:
    main(
        [
            "calibrate",
            str(files["config"]),
            str(files["slow"]),
            "--case",
            f"{files['fast']}:mechanism.crank_speed=240 rpm",
            "--fit",
            f"{KD}=1e-14..1e-10",
            "--circle-fit",
            "robust",
        ]
    )
    out = capsys.readouterr().out
    assert "wear_coefficient" in out
    assert "1/Pa" in out
    assert "slow.csv" in out
    assert "fast.csv" in out
    assert "240 rpm" in out
    value = float(out.split("wear_coefficient")[1].split("│")[1])
    assert value == pytest.approx(TRUE_KD, rel=0.02, abs=0)


def test_a_model_that_cannot_explain_the_measurement_warns(
    capsys: pytest.CaptureFixture[str], files: dict
) -> None:
    """A bushing worn at 240 rpm fitted with the 120 rpm config: a warning line, exit 0."""
    main(
        [
            "calibrate",
            str(files["config"]),
            str(files["fast"]),
            "--fit",
            "wear_coefficient",
            "--json",
        ]
    )
    captured = capsys.readouterr()
    data = json.loads(captured.out)
    (line,) = captured.err.splitlines()
    assert line.startswith("warning: fast.csv: the fitted model misses the measured profile by")
    assert "times what the measurement noise" in line
    assert data["warnings"] == [line.removeprefix("warning: ")]
    assert data["cases"][0]["misfit_ratio"] > 1.5
    # a noise given far above the misfit: nothing to warn about
    main(
        [
            "calibrate",
            str(files["config"]),
            str(files["fast"]),
            "--fit",
            "wear_coefficient",
            "--noise",
            "10 um",
            "--json",
        ]
    )
    captured = capsys.readouterr()
    assert captured.err == ""
    data = json.loads(captured.out)
    assert data["cases"][0]["noise_m"] == pytest.approx(10e-6)
    assert data["cases"][0]["noise_source"] == "given"


def test_paper_row(capsys: pytest.CaptureFixture[str]) -> None:
    data = run_json(
        capsys,
        "--paper-row",
        "table3_winkler_120rpm",
        "--set",
        "contact.nodes=90",
        "--set",
        "simulation.steps_per_revolution=60",
    )
    assert data["paper_row"] == "table3_winkler_120rpm"
    assert set(data["parameters"]) == {
        "joint.axial_length",
        "joint.bushing_thickness",
        "mechanism.spring_preload",
    }
    for key in ("peak_wear_depth_m", "wear_width_deg", "wear_mass_kg"):
        assert data["achieved"][key] == pytest.approx(data["targets"][key], rel=1e-4, abs=0)
    assert data["parameters"]["joint.axial_length"]["unit"] == "m"
    assert data["parameters"]["mechanism.spring_preload"]["uncertainty"] is None  # exact fit


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            ["{config}", "{slow}", "--fit", "wear_coeficient"],
            "--fit: unknown parameter 'wear_coeficient'; did you mean 'wear_coefficient'?",
        ),
        (["{config}", "{slow}"], "--fit: name at least one parameter"),
        (["{config}", "--fit", "wear_coefficient"], "MEASURED: give at least one"),
        (["{config}", "{line}", "--fit", "wear_coefficient"], "line.csv: not a ring of points"),
        (
            ["{config}", "{slow}", "--fit", "wear_coefficient", "--units", "um"],
            "slow.csv: column 'x' is in mm but units 'um'",
        ),
        (
            ["{config}", "{slow}", "--fit", "wear_coefficient", "--units", "s"],
            "--units: 's' is not a length unit",
        ),
        (
            ["{config}", "--case", "{slow}:crank_speed", "--fit", "wear_coefficient"],
            "file not found",
        ),
        (["{config}", "--case", ":a=1", "--fit", "wear_coefficient"], "--case"),
        (
            [
                "{config}",
                "--case",
                "{slow}:materials.bushing.wear_coefficient=1e-12",
                "--fit",
                "wear_coefficient",
            ],
            "which is being fitted",
        ),
        (
            ["{config}", "{slow}", "--fit", "wear_coefficient", "--circle-fit", "lsq"],
            "--circle-fit: unknown circle fit",
        ),
        (["{config}", "{slow}", "--fit", "joint.axial_length=2 kg..3 kg"], "--fit"),
        (["{slow}", "{slow}", "--fit", "wear_coefficient"], "looks like a measurement"),
        (
            ["{config}", "{slow}", "--fit", "wear_coefficient", "--noise", "-1 um"],
            "--noise: must be > 0",
        ),
        (["{config}", "{slow}", "--fit", "wear_coefficient", "--noise", "2 kg"], "--noise"),
        (["--paper-row", "table3_winkler"], "did you mean"),
        (["{config}", "{slow}", "--paper-row", "table3_winkler_120rpm"], "drop them"),
        (["missing.toml", "{slow}", "--fit", "wear_coefficient"], "missing.toml: file not found"),
    ],
)
def test_errors_exit_2_with_one_line(
    capsys: pytest.CaptureFixture[str], files: dict, args: list[str], message: str
) -> None:
    args = [a.format(**files) for a in args]
    with pytest.raises(SystemExit) as info:
        main(["calibrate", *args, "--json"])
    assert info.value.code == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.count("\n") == 1, captured.err
    assert message in captured.err
    assert "Traceback" not in captured.err


def test_calibrate_contact_laws_to_the_fe_reference(capsys) -> None:
    """Winkler's stiffness fitted to the FE wall is close to the constrained modulus.

    A bonded wall much thinner than the contact arc is a constrained layer: the fitted
    stiffness must sit near E_c / L (not E / L, 1.87 times softer for nu = 0.38).
    """
    from jointwear.cli import main

    main(["calibrate", "--reference", "fem", "--loads", "50 N,200 N,400 N", "--json"])
    data = json.loads(capsys.readouterr().out)
    winkler = data["fits"]["winkler"]["equivalent"]
    assert 0.85 < winkler["ratio_to_constrained_over_thickness"] < 1.15
    assert winkler["ratio_to_youngs_over_thickness"] > 1.5
    assert data["fits"]["nlcp"]["values"]["exponent"] < 1.5
