"""``jointwear run``, ``plot`` and ``reproduce`` from the command line."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.config import config_from_dict

REPO = Path(__file__).resolve().parents[2]
FAST = ["--set", "contact.nodes=120", "--set", "simulation.steps_per_revolution=90"]
REQUIRED = {
    "peak_wear_depth_m",
    "wear_width_deg",
    "wear_mass_kg",
    "wear_volume_m3",
    "revolutions",
    "contact_model",
    "runtime_s",
}


def run_cli(args, capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(args)
    captured = capsys.readouterr()
    return exit_info.value.code, captured.out, captured.err


def ok_cli(args, capsys):
    main(args)
    return capsys.readouterr()


def test_run_json_is_exactly_one_object(paper_config_path, capsys) -> None:
    out = ok_cli(["run", str(paper_config_path), *FAST, "--json"], capsys).out
    data = json.loads(out)
    assert out.count("\n") == 1
    assert set(data) >= REQUIRED
    assert data["revolutions"] == 1
    assert data["contact_model"] == "asymmetric-winkler"


def test_run_accepts_units_in_overrides(paper_config_path, capsys) -> None:
    base = json.loads(ok_cli(["run", str(paper_config_path), *FAST, "--json"], capsys).out)
    wide = json.loads(
        ok_cli(
            [
                "run",
                str(paper_config_path),
                *FAST,
                "--json",
                "--set",
                'joint.clearance="0.2 mm"',
                "--set",
                "mechanism.crank_speed=240 rpm",
            ],
            capsys,
        ).out
    )
    assert wide["wear_width_deg"] < base["wear_width_deg"]
    assert wide["peak_wear_depth_m"] > base["peak_wear_depth_m"]


def test_run_out_writes_everything(paper_config_path, tmp_path, capsys) -> None:
    out = tmp_path / "run"
    ok_cli(["run", str(paper_config_path), *FAST, "--out", str(out), "--quiet"], capsys)
    names = {p.name for p in out.iterdir()}
    assert {"result.nc", "metrics.csv", "config.toml", "summary.json", "plots"} <= names
    assert not [n for n in names if n.startswith(".")]
    for figure in ("wear_polar", "wear_profiles", "pressure", "joint_load", "wear_history"):
        assert (out / "plots" / f"{figure}.png").stat().st_size > 1000
        assert (out / "plots" / f"{figure}.svg").exists()
    # every default is written: the saved config alone reproduces the run
    saved = tomllib.loads((out / "config.toml").read_text())
    assert saved["contact"]["spring_area"] > 0
    assert saved["mechanism"]["rod_inertia"] == pytest.approx(1.09 * 0.2**2 / 12)
    config = config_from_dict(saved, defaults=False)
    assert config.contact.nodes == 120


def test_summary_json_is_the_object_run_json_prints(paper_config_path, tmp_path, capsys) -> None:
    # the engineering checks are part of the object whether or not a limit is known
    out = tmp_path / "run"
    args = ["run", str(paper_config_path), *FAST, "--out", str(out), "--no-plots", "--json"]
    printed = json.loads(ok_cli(args, capsys).out)
    written = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert "checks" in printed
    assert list(written) == list(printed)
    for key in printed:
        assert written[key] == printed[key], key


def test_plot_redraws_from_a_saved_result(paper_config_path, tmp_path, capsys) -> None:
    out = tmp_path / "run"
    ok_cli(["run", str(paper_config_path), *FAST, "--out", str(out), "--no-plots", "-q"], capsys)
    assert not (out / "plots").exists()
    ok_cli(["plot", str(out / "result.nc"), "--magnification", "1000"], capsys)
    assert (out / "plots" / "wear_polar.png").exists()


def test_bad_config_fails_cleanly_and_writes_nothing(paper_config_path, tmp_path, capsys) -> None:
    out = tmp_path / "run"
    code, _stdout, stderr = run_cli(
        ["run", str(paper_config_path), "--out", str(out), "--set", "joint.clearance=-1"], capsys
    )
    assert code == 2
    assert stderr.count("\n") == 1
    assert "joint.clearance" in stderr
    assert "Traceback" not in stderr
    assert not out.exists()


def test_wear_through_ends_the_run_with_its_results(paper_config_path, tmp_path, capsys) -> None:
    out = tmp_path / "run"
    captured = ok_cli(
        [
            "run",
            str(paper_config_path),
            *FAST,
            "--out",
            str(out),
            "--set",
            "materials.bushing.wear_coefficient=1e-8",
            "--set",
            "simulation.revolutions=10000",
            "--set",
            "simulation.update_contour=true",
            "--set",
            "simulation.update_every=7",
            "--json",
        ],
        capsys,
    )
    data = json.loads(captured.out)
    assert data["stopped_by"] == "wall_thickness"
    assert 0 < data["life_revolutions"] == data["revolutions"] < 10000
    assert data["min_wall_thickness_m"] == pytest.approx(0.0, abs=1e-12)
    assert data["min_wall_thickness_m"] >= 0
    assert data["life_hours"] == pytest.approx(data["revolutions"] * 0.5 / 3600)
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    for key in ("revolutions", "life_revolutions", "life_hours", "stopped_by"):
        assert summary[key] == data[key]
    assert (out / "result.nc").exists()


def test_run_says_why_and_when_it_ended(paper_config_path, capsys) -> None:
    stopped = ok_cli(
        ["run", str(paper_config_path), *FAST, "--set", "materials.bushing.wear_coefficient=1e-3"],
        capsys,
    ).out
    data = json.loads(
        ok_cli(
            [
                "run",
                str(paper_config_path),
                *FAST,
                "--set",
                "materials.bushing.wear_coefficient=1e-3",
                "--json",
            ],
            capsys,
        ).out
    )
    life, hours = data["life_revolutions"], data["life_hours"]
    assert f"stopped: wall_thickness reached at {life:.3g} revolutions ({hours:.3g} h)" in stopped
    completed = ok_cli(["run", str(paper_config_path), *FAST], capsys).out
    assert "completed: 1 revolutions (no life limit reached)" in completed


def test_joints_that_end_apart_are_written_drawn_and_read_back(tmp_path, capsys) -> None:
    """Each clearance joint of a four-bar ends on its own, one at a limit: each keeps its
    own profiles and its own end (the other joints' ends are not NaN rows of its own)."""
    out = tmp_path / "run"
    captured = ok_cli(
        [
            "run",
            str(REPO / "examples" / "four_bar.toml"),
            *FAST,
            "--set",
            "contact.model=asymmetric-winkler",
            "--set",
            "simulation.revolutions=150",
            "--set",
            "simulation.update_contour=true",
            "--set",
            "simulation.update_every=3",
            "--set",
            "materials.bushing.wear_coefficient=2e-10",
            "--set",
            "life.peak_wear_depth=0.05 mm",
            "--out",
            str(out),
        ],
        capsys,
    )
    from jointwear.results import joint_datasets, read_result

    joints = json.loads((out / "summary.json").read_text(encoding="utf-8"))["joints"]
    stopped = joints.pop("crank-coupler")
    assert stopped["stopped_by"] == "peak_wear_depth"
    assert 0 < stopped["life_revolutions"] == stopped["revolutions"] < 150
    assert "crank-coupler: stopped: peak_wear_depth reached at" in captured.out
    for joint, entry in joints.items():
        assert entry["stopped_by"] is None
        assert entry["revolutions"] == 150
        assert f"{joint}: completed: 150 revolutions" in captured.out
    for joint, single in joint_datasets(read_result(out / "result.nc")).items():
        profiles = single["wear_depth"].values
        assert np.isfinite(profiles).all()
        end = stopped["revolutions"] if joint == "crank-coupler" else 150
        assert single["revolution"].values[-1] == end
        assert single["update_revolution"].values[-1] == end
        assert (out / "plots" / joint / "wear_polar.png").exists()


def test_plot_of_a_broken_file(tmp_path, capsys) -> None:
    broken = tmp_path / "broken.nc"
    broken.write_text("nope")
    code, _, stderr = run_cli(["plot", str(broken)], capsys)
    assert code == 2
    assert "broken.nc" in stderr


def test_debug_shows_the_traceback(paper_config_path) -> None:
    from jointwear.errors import ConfigError

    with pytest.raises(ConfigError):
        main(["--debug", "run", str(paper_config_path), "--set", "joint.clearance=-1"])


def test_cli_needs_no_click_of_its_own(paper_config_path) -> None:
    """typer >= 0.20 vendors click and does not install it: the CLI must not import it.

    (Found from a fresh install of the main command, where only dask's extra pulled
    click in for the test environment.)
    """
    import subprocess
    import sys

    code = (
        "import sys; sys.modules['click'] = None\n"  # any `import click` now fails
        "from jointwear.cli import main\n"
        f"cases = (([r'{paper_config_path}', '--json'], 0), (['--no-such-option'], 2))\n"
        "for args, status in cases:\n"
        "    try:\n"
        "        main(['run', *args] if status == 0 else args)\n"
        "        code = 0\n"
        "    except SystemExit as exc:\n"
        "        code = exc.code\n"
        "    assert code == status, (args, code)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "internal error" not in done.stderr
