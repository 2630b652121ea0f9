"""Measured bushings: a measured scar is measured back, a run compared with its own wear."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.measurement.synthetic import synthesize_measurement
from jointwear.workflows.measured import (
    COMPARE_FILES,
    compare_run_to_measurement,
    measure_bushing,
)
from tests.conftest import scar

RADIUS = 7.5e-3
DEPTH = 20e-6


def write_points(path: Path, x: np.ndarray, y: np.ndarray) -> Path:
    rows = "".join(f"{a * 1e3:.8f},{b * 1e3:.8f}\n" for a, b in zip(x, y, strict=True))
    path.write_text("x [mm],y [mm]\n" + rows, encoding="utf-8")
    return path


def test_the_robust_fit_measures_the_scar_the_plain_fit_underestimates(tmp_path):
    """A 20 um scar on a noise-free bushing: the fit of the unworn arc finds its depth; the
    paper's plain circle is pulled towards the wear (a shallower scar)."""
    depth = scar(360, depth=DEPTH)
    x, y = synthesize_measurement(depth, RADIUS, 3600, 0.0, 1, (2e-3, -1e-3), 0.0)
    measured = measure_bushing(
        write_points(tmp_path / "worn.csv", x, y),
        "7.5 mm",
        axial_length="20 mm",
        density="2200 kg/m^3",
    )
    robust, plain = measured.fits["robust"], measured.fits["least_squares"]
    assert robust["peak_wear_depth_m"] == pytest.approx(DEPTH, rel=0.02)
    assert plain["peak_wear_depth_m"] < 0.9 * DEPTH
    assert robust["peak_angle_deg"] == pytest.approx(20.0, abs=1.0)
    # mass = density x length x area removed
    assert robust["wear_mass_kg"] == pytest.approx(2200 * 0.02 * robust["wear_area_m2"])
    assert (measured.points, measured.radius, measured.floor) == (3600, RADIUS, 0.0)
    assert measured.noise < 1e-9


@pytest.mark.parametrize(
    ("options", "message"),
    [
        ({"radius": "7.5"}, "--radius"),  # a bare 7.5 m bushing is a unit slip
        ({"nodes": 8}, "--nodes: must be >= 16"),
        ({"threshold": 1.0}, "--threshold"),
        ({"profile": "spline"}, "--profile: must be one of"),
        ({"density": "-1 kg/m^3"}, "--density: must be > 0"),
    ],
)
def test_bad_options_are_refused_before_the_file_is_read(tmp_path, options, message):
    options = {"radius": "7.5 mm", **options}
    with pytest.raises(ConfigError, match=message):
        measure_bushing(tmp_path / "missing.csv", **options)


@pytest.fixture(scope="module")
def run_file(tmp_path_factory: pytest.TempPathFactory, paper_config: Config) -> Path:
    folder = tmp_path_factory.mktemp("run")
    config = paper_config.replace(
        {
            "contact.nodes": 180,
            "simulation.steps_per_revolution": 60,
            "simulation.revolutions": 2000,
            "simulation.update_contour": True,
            "simulation.update_every": 100,
            "materials.bushing.wear_coefficient": 3e-12,
        }
    )
    result = Simulation(config).run()
    result.to_netcdf(folder / "result.nc")
    return folder / "result.nc"


def test_a_run_compared_with_its_own_wear_agrees(run_file, tmp_path):
    """The run's final profile, 'measured' turned by 40 deg about another centre: the
    rotation is found and the profiles agree to a small fraction of the peak."""
    from jointwear.results import read_wear_result

    result = read_wear_result(run_file)
    x, y = synthesize_measurement(
        result.wear_depth, result.config.bushing_radius, 3600, 0.0, 3, (1e-3, 2e-3), 0.7
    )
    out = tmp_path / "out"
    done = compare_run_to_measurement(
        run_file, write_points(tmp_path / "worn.csv", x, y), out=out, align="best"
    )
    summary = done.summary
    peak = float(np.max(result.wear_depth))
    assert summary["alignment_offset_deg"] == pytest.approx(math.degrees(0.7), abs=1.0)
    assert summary["rms_error_m"] < 0.05 * peak
    assert summary["peak_error_rel"] == pytest.approx(0.0, abs=0.05)
    assert done.out == out
    assert sorted(p.name for p in out.iterdir()) == sorted(COMPARE_FILES)
    written = json.loads((out / "comparison.json").read_text(encoding="utf-8"))
    assert written["rms_error_m"] == summary["rms_error_m"]


def test_a_comparison_refuses_bad_options_before_reading_the_result(tmp_path):
    out = tmp_path / "out"
    with pytest.raises(ConfigError, match="--fit: unknown circle fit"):
        compare_run_to_measurement(tmp_path / "no.nc", tmp_path / "no.csv", fit="ransac", out=out)
    with pytest.raises(ConfigError, match="--floor: must be >= 0"):
        compare_run_to_measurement(tmp_path / "no.nc", tmp_path / "no.csv", floor="-1 um")
    assert not out.exists()
