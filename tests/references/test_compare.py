"""Every contact model against the references: the table, the plot, ``jointwear compare-models``."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.contact import ContactParameters
from jointwear.references.compare import DEFAULT_MODELS, compare_models, plot_pressure

LOADS = [50.0, 400.0]
METRICS = {"half_angle_deg", "peak_pressure_pa", "approach_m"}


@pytest.fixture(scope="module")
def comparison(joint: ContactParameters):
    return compare_models(joint, LOADS)


def test_compare_models_table(comparison) -> None:
    data = comparison.to_json()
    assert data["loads_n"] == LOADS
    assert list(data["models"]) == list(DEFAULT_MODELS)
    for metrics in data["models"].values():
        assert set(metrics) == METRICS
        assert all(math.isfinite(v) and v > 0 for values in metrics.values() for v in values)
    fem = comparison.models["fem"]
    # everything grows with the load
    for metrics in comparison.models.values():
        for values in metrics.values():
            assert values[1] > values[0]
    # the references disagree with each other by design (infinite plate vs thin bushing)
    assert comparison.models["persson"]["approach_m"][0] > 1.5 * fem["approach_m"][0]
    dev = comparison.deviation("fem")
    assert np.all(dev["fem"]["peak_pressure_pa"] == 0)


def test_pressure_plot(comparison, tmp_path: Path) -> None:
    paths = plot_pressure(comparison, tmp_path / "plots")
    assert sorted(p.suffix for p in paths) == [".png", ".svg"]
    assert all(p.stat().st_size > 1000 for p in paths)
    assert not list((tmp_path / "plots").glob(".*.tmp"))


def _run(capsys, *args: str) -> dict:
    main(["compare-models", *args, "--json"])
    out = capsys.readouterr().out.strip().splitlines()
    assert len(out) == 1
    return json.loads(out[0])


def test_cli_json_and_plot(capsys, paper_config_path: Path, tmp_path: Path) -> None:
    data = _run(
        capsys,
        str(paper_config_path),
        "--loads",
        "50 N, 0.2 kN",
        "--models",
        "winkler,nlcp",
        "--models",
        "persson",
        "--out",
        str(tmp_path),
    )
    assert data["loads_n"] == [50.0, 200.0]
    assert list(data["models"]) == ["winkler", "nlcp", "persson", "fem"]
    assert set(data["models"]["fem"]) == METRICS
    assert (tmp_path / "compare_models_pressure.png").exists()
    assert (tmp_path / "compare_models_pressure.svg").exists()


def test_cli_errors(capsys, paper_config_path: Path) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["compare-models", str(paper_config_path), "--models", "winklr"])
    assert exit_info.value.code == 2
    assert "did you mean 'winkler'" in capsys.readouterr().err
    with pytest.raises(SystemExit):
        main(["compare-models", str(paper_config_path), "--loads", "-5 N"])
