"""A joint of the user's own, through every command, with no Python written.

Each shipped example mechanism runs through ``dynamics``, ``run`` (with
checkpoint/resume), ``sweep`` and ``calibrate``; the saved config and the result
describe the mechanism that really ran.
"""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import pytest

from jointwear import Simulation
from jointwear.cli import main
from jointwear.config import load_config
from jointwear.measurement.synthetic import synthesize_measurement
from jointwear.results import config_of, read_result

from ..test_checkpoint import interrupted_run

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
#: example config -> mechanism type
OWN_JOINTS = {
    "oscillating_liner.toml": "oscillating",
    "four_bar.toml": "four-bar",
    "load_history/load_history.toml": "load-history",
}
#: small runs: the commands are under test here, not the physics
QUICK = [
    "--set",
    "simulation.revolutions=40",
    "--set",
    "simulation.update_every=10",
    "--set",
    "simulation.update_contour=true",
]


def cli_json(capsys: pytest.CaptureFixture[str], *args: str) -> dict:
    main([*args, "--json"])
    out = capsys.readouterr().out.strip().splitlines()
    assert len(out) == 1, out
    return json.loads(out[0])


@pytest.fixture(params=sorted(OWN_JOINTS), ids=lambda name: Path(name).stem)
def example(request: pytest.FixtureRequest) -> Path:
    return EXAMPLES / request.param


def test_dynamics(capsys: pytest.CaptureFixture[str], example: Path) -> None:
    data = cli_json(capsys, "dynamics", str(example))
    assert data["mechanism"] == OWN_JOINTS[example.relative_to(EXAMPLES).as_posix()]
    assert 0 <= data["load_min_n"] <= data["load_mean_n"] <= data["load_max_n"]
    assert data["load_max_n"] > 0
    assert data["total_relative_rotation_rad"] > 0


def test_run_saves_what_ran_and_resumes(
    capsys: pytest.CaptureFixture[str], example: Path, tmp_path: Path
) -> None:
    out = tmp_path / "run"
    # checkpoints hold one clearance joint
    single = ["--set", "mechanism.clearance_joint=coupler-rocker"]
    args = [*QUICK, *(single if example.name == "four_bar.toml" else [])]
    data = cli_json(
        capsys, "run", str(example), *args, "--out", str(out), "--checkpoint-every", "20"
    )
    assert data["peak_wear_depth_m"] > 0
    assert data["mechanism"] == OWN_JOINTS[example.relative_to(EXAMPLES).as_posix()]
    saved = tomllib.loads((out / "config.toml").read_text(encoding="utf-8"))
    assert saved["mechanism"]["type"] == OWN_JOINTS[example.relative_to(EXAMPLES).as_posix()]
    dataset = read_result(out / "result.nc")
    assert dataset.attrs["mechanism"] == OWN_JOINTS[example.relative_to(EXAMPLES).as_posix()]
    config = config_of(dataset)
    assert config.mechanism.type == OWN_JOINTS[example.relative_to(EXAMPLES).as_posix()]
    assert dataset.sizes["step"] == config.simulation.steps_per_revolution
    # the same run, straight through: the saved config reproduces the numbers
    again = Simulation(config).run().summary()
    assert again["peak_wear_depth_m"] == pytest.approx(data["peak_wear_depth_m"], rel=1e-12, abs=0)
    # interrupted half-way and resumed from its checkpoint: the same numbers, exactly
    interrupted = tmp_path / "interrupted"
    interrupted_run(config.replace({"simulation.checkpoint_every": 10}), interrupted, 20)
    resumed = cli_json(capsys, "run", "--resume", str(interrupted))
    assert resumed["peak_wear_depth_m"] == data["peak_wear_depth_m"]
    assert resumed["wear_mass_kg"] == data["wear_mass_kg"]


def test_sweep(capsys: pytest.CaptureFixture[str], example: Path, tmp_path: Path) -> None:
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(
        f'base = "{example.as_posix()}"\n'
        "[set]\n"
        '"simulation.revolutions" = 20\n'
        '"simulation.update_every" = 10\n'
        "[grid]\n"
        '"joint.clearance" = ["0.05 mm", "0.1 mm"]\n',
        encoding="utf-8",
    )
    main(["sweep", str(sweep), "--out", str(tmp_path / "out"), "--workers", "1"])
    capsys.readouterr()
    lines = (tmp_path / "out" / "cases.csv").read_text(encoding="utf-8").splitlines()
    assert len(lines) == 3
    assert all(",ok," in line for line in lines[1:])


def test_calibrate_recovers_the_wear_coefficient(
    capsys: pytest.CaptureFixture[str], example: Path, tmp_path: Path
) -> None:
    overrides = ["simulation.revolutions=200", "simulation.update_contour=false"]
    truth = load_config(example, overrides=[*overrides, "materials.bushing.wear_coefficient=2e-13"])
    depth = Simulation(truth).run().wear_depth
    x, y = synthesize_measurement(
        depth, truth.bushing_radius, 1500, 0.02 * depth.max(), 3, (1e-3, -2e-3), math.radians(40)
    )
    measured = tmp_path / "worn.csv"
    measured.write_text(
        "x [mm],y [mm]\n"
        + "".join(f"{a * 1e3:.9f},{b * 1e3:.9f}\n" for a, b in zip(x, y, strict=True)),
        encoding="utf-8",
    )
    data = cli_json(
        capsys,
        "calibrate",
        str(example),
        str(measured),
        *[arg for o in overrides for arg in ("--set", o)],
        "--fit",
        "materials.bushing.wear_coefficient",
    )
    fitted = data["parameters"]["materials.bushing.wear_coefficient"]["value"]
    assert fitted == pytest.approx(2e-13, rel=0.05, abs=0)


def test_several_joints_wear_as_each_alone(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    joints = ["crank-coupler", "coupler-rocker", "rocker-ground"]
    listed = "mechanism.clearance_joint=" + json.dumps(joints)
    out = tmp_path / "run"
    data = cli_json(
        capsys, "run", str(EXAMPLES / "four_bar.toml"), *QUICK, "--set", listed, "--out", str(out)
    )
    assert set(data["joints"]) == set(joints)
    peaks = {j: data["joints"][j]["peak_wear_depth_m"] for j in joints}
    assert data["joint"] == max(peaks, key=peaks.get)  # the top level is the most worn joint
    dataset = read_result(out / "result.nc")
    assert [str(j) for j in dataset["joint"].values] == joints
    assert (out / "plots" / "rocker-ground").is_dir()
    metrics = (out / "metrics.csv").read_text(encoding="utf-8").splitlines()
    assert metrics[0].startswith("joint,revolution,")
    for joint in joints:
        alone = cli_json(
            capsys,
            "run",
            str(EXAMPLES / "four_bar.toml"),
            *QUICK,
            "--set",
            f"mechanism.clearance_joint={joint}",
        )
        assert alone["peak_wear_depth_m"] == pytest.approx(peaks[joint], rel=1e-9, abs=0)
