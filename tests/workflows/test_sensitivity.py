"""Global sensitivity: Sobol indices and Morris screening against what must come out."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from scipy.stats import kstest, lognorm

from jointwear.config import Config
from jointwear.errors import ConfigError, DataError
from jointwear.workflows.life import parse_distribution
from jointwear.workflows.sensitivity import (
    case_outputs,
    sensitivity_indices,
    sensitivity_plan,
    sensitivity_study,
)
from tests.conftest import strict_json

KD = "materials.bushing.wear_coefficient"
DENSITY = "materials.bushing.density"
SAMPLES = [
    f"{KD}=lognormal(median=5.05e-13 m^2/N, sigma=0.4)",
    f"{DENSITY}=uniform(low=2000 kg/m^3, high=2400 kg/m^3)",
]
LINEAR = [
    "contact.nodes=60",
    "simulation.steps_per_revolution=60",
    "life.peak_wear_depth=1e-5",
    "simulation.revolutions=10000000",
]


@pytest.fixture(scope="module")
def sobol(paper_config_path: Path, tmp_path_factory: pytest.TempPathFactory):
    """Without contour update the life is C / K_d; the bushing's density changes the
    wear's mass, never its depth, so it cannot move the depth limit."""
    out = tmp_path_factory.mktemp("sobol")
    return sensitivity_study(
        paper_config_path, SAMPLES, 256, out=out, overrides=LINEAR, workers=1
    ), out


def test_sobol_gives_the_wear_coefficient_all_and_the_density_none(sobol) -> None:
    """life = C / K with K lognormal and an input that cannot change the limit: K's total
    index above 0.95, the density's below 0.02 (both its indices exactly 0: its cases'
    lives are identical)."""
    result, _ = sobol
    assert len(result.sweep.records) == 64 * (2 + 2)
    k, density = result.indices[KD], result.indices[DENSITY]
    assert k["ST"] > 0.95
    assert k["ST"] - k["ST_conf"] < 1.0 < k["ST"] + k["ST_conf"]
    assert density["ST"] < 0.02
    assert density == {"S1": 0.0, "ST": 0.0, "S1_conf": 0.0, "ST_conf": 0.0}


def test_the_design_has_each_input_distribution(sobol) -> None:
    """The Saltelli design mapped through the inverse CDFs: the wear coefficients of the
    cases follow their lognormal (Kolmogorov-Smirnov), the lives are C / K."""
    result, _ = sobol
    k = np.array([r["parameters"][KD] for r in result.sweep.records])
    assert kstest(k, lognorm(0.4, scale=5.05e-13).cdf).pvalue > 0.01
    product = result.outputs * k
    assert np.ptp(product) / np.median(product) < 2.0 / result.outputs.min()


def test_the_study_writes_json_and_a_bar_chart(sobol) -> None:
    result, out = sobol
    written = strict_json((out / "sensitivity.json").read_text(encoding="utf-8"))
    assert written == {k: v for k, v in result.summary().items() if k not in ("out", "runtime_s")}
    assert set(written["indices"][KD]) == {"S1", "ST", "S1_conf", "ST_conf"}
    assert (out / "sensitivity.png").stat().st_size > 1000
    assert {p.name for p in out.iterdir()} >= {"cases.csv", "sweep.nc", "sweep-plan.json"}


def test_morris_screens_the_inert_input_out(paper_config_path: Path) -> None:
    """Morris on the same joint without a folder: the density's elementary effects are
    all zero, the wear coefficient's are not; the life falls as K rises, so every
    effect of K has one sign and |mean| = mu*."""
    result = sensitivity_study(
        paper_config_path, SAMPLES, 30, method="morris", overrides=LINEAR, workers=1
    )
    assert result.out is None
    assert len(result.sweep.records) == 10 * 3
    assert result.indices[DENSITY] == {"mu_star": 0.0, "sigma": 0.0, "mu_star_conf": 0.0}
    assert result.indices[KD]["mu_star"] > 0
    assert not result.sweep.out.exists()  # the temporary folder is gone


def test_sobol_of_a_closed_form_function() -> None:
    """Y = X1 + 2 X2 on independent uniforms: S1 = ST = (1/5, 4/5) (Var = 1/12 + 4/12)."""
    from SALib.sample import sobol

    problem = {"num_vars": 2, "names": ["a", "b"], "bounds": [[0.0, 1.0]] * 2}
    design = sobol.sample(problem, 1024, calc_second_order=False, seed=3)
    indices = sensitivity_indices("sobol", ["a", "b"], design, design[:, 0] + 2 * design[:, 1])
    for key, share in (("a", 0.2), ("b", 0.8)):
        assert indices[key]["S1"] == pytest.approx(share, abs=0.05)
        assert indices[key]["ST"] == pytest.approx(share, abs=0.05)


def test_bad_studies(paper_config: Config) -> None:
    tables = dict(parse_distribution(text) for text in SAMPLES)
    with pytest.raises(ConfigError, match="--cases: Sobol indices of 2 inputs need at least"):
        sensitivity_plan(paper_config, tables, 7)
    with pytest.raises(ConfigError, match="did you mean 'morris'"):
        sensitivity_plan(paper_config, tables, 64, method="moris")
    with pytest.raises(ConfigError, match="--sample: name at least one"):
        sensitivity_plan(paper_config, {}, 64)
    with pytest.raises(DataError, match="case-0003: no convergence; the sensitivity indices"):
        case_outputs(
            [{"case": "case-0003", "status": "failed", "error": "no convergence"}],
            "life_revolutions",
        )
