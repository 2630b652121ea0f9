"""`jointwear life`: the life distribution printed and written, in strict JSON."""

from __future__ import annotations

from pathlib import Path

from jointwear.cli import main
from tests.conftest import strict_json

KD = "materials.bushing.wear_coefficient"


def test_a_study_without_any_limit_reached_writes_strict_json(
    capsys, paper_config_path: Path, tmp_path: Path
) -> None:
    """Every case censored: hours, quantiles and rank correlations have no number, and
    life.json and --json say so in JSON (lower bounds and null), never NaN."""
    main(
        [
            "life",
            str(paper_config_path),
            "--sample",
            f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.5)",
            "--cases",
            "4",
            "--seed",
            "2",
            "--set",
            "life.peak_wear_depth=0.1 mm",
            "--set",
            "simulation.revolutions=50",
            "--set",
            "contact.nodes=60",
            "--set",
            "simulation.steps_per_revolution=60",
            "--out",
            str(tmp_path / "life"),
            "--workers",
            "1",
            "--json",
            "--quiet",
        ]
    )
    printed = strict_json(capsys.readouterr().out)
    written = strict_json((tmp_path / "life" / "life.json").read_text(encoding="utf-8"))
    for data in (printed, written):
        assert data["censored"] == 4
        assert data["life_revolutions"]["median"] == {"value": 50.0, "lower_bound": True}
        assert data["life_hours"]["median"] == {"value": 50 * 0.5 / 3600, "lower_bound": True}
        assert data["sensitivity"] == {KD: None}
    assert "lives" not in printed
    assert [life["censored"] for life in written["lives"]] == [True] * 4


def test_life_cli(capsys, paper_config_path: Path, tmp_path: Path) -> None:
    main(
        [
            "life",
            str(paper_config_path),
            "--sample",
            f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.5)",
            "--sample",
            "joint.clearance=uniform(low=0.04 mm, high=0.06 mm)",
            "--cases",
            "12",
            "--seed",
            "3",
            "--set",
            "life.peak_wear_depth=0.01 mm",
            "--set",
            "simulation.revolutions=1000000",
            "--set",
            "contact.nodes=90",
            "--set",
            "simulation.steps_per_revolution=60",
            "--out",
            str(tmp_path / "life"),
            "--workers",
            "1",
            "--json",
            "--quiet",
        ]
    )
    data = strict_json(capsys.readouterr().out)
    assert data["cases"] == 12
    assert set(data["sensitivity"]) == {KD, "joint.clearance"}
    revolutions = data["life_revolutions"]
    assert revolutions["p5"]["value"] <= revolutions["median"]["value"]
    assert (tmp_path / "life" / "life.png").exists()


def test_life_stopped_by_its_time_limit_is_finished_by_resume(
    capsys, paper_config_path: Path, tmp_path: Path
) -> None:
    """--time-limit stops the study after its first case and names `jointwear life
    --resume DIR`; `sweep --resume` refuses the folder (it would leave out life.json and
    life.png); `life --resume DIR` runs the other cases and writes every output."""
    import pytest

    from tests.hostile.harness import run_cli

    out = tmp_path / "life"
    argv = [
        "life",
        str(paper_config_path),
        "--sample",
        f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.5)",
        "--cases",
        "6",
        "--set",
        "life.peak_wear_depth=1e-5",
        "--set",
        "contact.nodes=60",
        "--set",
        "simulation.steps_per_revolution=60",
        "--out",
        str(out),
        "--workers",
        "1",
        "--json",
        "--quiet",
    ]
    code, stdout, stderr = run_cli(capsys, [*argv, "--time-limit", "1e-9 s"])
    assert (code, stdout) == (2, "")
    assert stderr.endswith(f"; continue with `jointwear life --resume {out}`\n")
    assert not (out / "life.json").exists()
    code, _, stderr = run_cli(capsys, ["sweep", "--resume", str(out)])
    assert code == 2
    assert stderr == (
        f"error: --resume: {out} holds a life study; continue it with "
        f"`jointwear life --resume {out}`\n"
    )
    code, stdout, stderr = run_cli(capsys, ["life", "--resume", str(out), "--json", "--quiet"])
    assert code == 0, stderr
    data = strict_json(stdout)
    assert data["cases"] == 6
    assert data["b10_revolutions"] == pytest.approx(data["reliability"]["b10"]["value"])
    assert {"weibull_shape", "weibull_scale_revolutions", "b50_revolutions"} <= set(data)
    assert (out / "life.json").is_file()
    assert (out / "life.png").is_file()


def test_a_study_whose_every_case_failed_prints_its_table(capsys, tmp_path: Path) -> None:
    """No life reached and no bound: the reliability table says n/a (no internal error)."""
    duty = tmp_path / "duty.toml"
    duty.write_text(
        '[mechanism]\ntype = "duty-cycle"\n'
        '[[mechanism.modes]]\ntype = "oscillating"\nshare = 0.4\nload = "1 kN"\n'
        'amplitude = "25 deg"\nfrequency = "1 Hz"\n'
        '[[mechanism.modes]]\ntype = "oscillating"\nshare = 0.6\nload = "2 kN"\n'
        'amplitude = "10 deg"\nfrequency = "1 Hz"\n'
        '[life]\npeak_wear_depth = "20 um"\n',
        encoding="utf-8",
    )
    # (a share drawn alone breaks the shares' sum: every case is invalid)
    sample = "mechanism.modes.0.share=uniform(low=0.1, high=0.3)"
    out = tmp_path / "life"
    args = ["life", str(duty), "--sample", sample, "--cases", "3", "--out", str(out), "-q"]
    main([*args, "--workers", "1"])
    printed = capsys.readouterr()
    assert "internal error" not in printed.err
    assert "B10" in printed.out
    assert (out / "life.json").exists()
