"""`jointwear sensitivity`: the indices as strict JSON and as a table."""

from __future__ import annotations

from pathlib import Path

from jointwear.cli import main
from tests.conftest import strict_json

KD = "materials.bushing.wear_coefficient"
ARGS = [
    "--sample",
    f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.4)",
    "--sample",
    "joint.clearance=uniform(low=0.04 mm, high=0.06 mm)",
    "--set",
    "contact.nodes=60",
    "--set",
    "simulation.steps_per_revolution=60",
    "--set",
    "life.peak_wear_depth=1e-5",
    "--set",
    "simulation.revolutions=10000000",
    "--workers",
    "1",
    "--quiet",
]


def test_morris_json_and_files(capsys, paper_config_path: Path, tmp_path: Path) -> None:
    main(
        [
            "sensitivity",
            str(paper_config_path),
            *ARGS,
            "--cases",
            "12",
            "--method",
            "morris",
            "--out",
            str(tmp_path / "s"),
            "--json",
        ]
    )
    data = strict_json(capsys.readouterr().out)
    assert (data["method"], data["cases"], data["metric"]) == ("morris", 12, "life_revolutions")
    assert set(data["indices"]) == {KD, "joint.clearance"}
    for values in data["indices"].values():
        assert set(values) == {"mu_star", "sigma", "mu_star_conf"}
    # the wear coefficient scatters by a factor of 2.2 (1 sigma), the clearance by 20 %
    assert data["indices"][KD]["mu_star"] > data["indices"]["joint.clearance"]["mu_star"]
    assert (tmp_path / "s" / "sensitivity.png").is_file()


def test_sobol_table(capsys, paper_config_path: Path) -> None:
    main(["sensitivity", str(paper_config_path), *ARGS, "--cases", "16"])
    printed = capsys.readouterr().out
    assert "sobol sensitivity of life_revolutions (16 cases" in printed
    assert "S1_conf" in printed
    assert KD in printed
