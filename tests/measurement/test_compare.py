"""Comparison of measured and simulated wear profiles, with a simulated truth.

The "measurement" is a SIMULATED worn contour (known K_d, contour update) seen
by a synthetic instrument: randomly spaced points, 0.7 um noise, the bushing
shifted and rotated in the instrument frame. Comparing it with the simulation
it came from must give back the profile.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import ConfigError, DataError
from jointwear.geometry import node_angles
from jointwear.measurement.compare import (
    compare_measurement,
    compare_profiles,
    fit_circle,
    plot_comparison,
    resolve_profile_method,
)
from jointwear.measurement.synthetic import synthesize_measurement

TRUE_KD = 3e-12  # [1/Pa], 3000 revolutions -> a Table 5-sized scar (about 65 um, 155 deg)
ROTATION_DEG = 57.0
CENTER = (3.0e-3, -2.0e-3)
NOISE = 0.7e-6


@dataclass(frozen=True)
class Worn:
    config: Config
    depth: np.ndarray
    x: np.ndarray
    y: np.ndarray

    @property
    def radius(self) -> float:
        return self.config.bushing_radius


def simulated_config(paper_config: Config, **overrides: object) -> Config:
    """A short run with contour update on a coarse grid (fractions of a second)."""
    return paper_config.replace(
        {
            "contact.nodes": 180,
            "simulation.steps_per_revolution": 60,
            "simulation.revolutions": 3000,
            "simulation.update_contour": True,
            "simulation.update_every": 100,
            "materials.bushing.wear_coefficient": TRUE_KD,
            **overrides,
        }
    )


@pytest.fixture(scope="module")
def worn(paper_config: Config) -> Worn:
    config = simulated_config(paper_config)
    depth = Simulation(config).run().wear_depth
    x, y = synthesize_measurement(
        depth, config.bushing_radius, 3600, NOISE, 7, CENTER, math.radians(ROTATION_DEG)
    )
    return Worn(config, depth, x, y)


def test_the_simulated_scar_is_table5_sized(worn: Worn) -> None:
    assert 50e-6 < worn.depth.max() < 80e-6
    assert np.count_nonzero(worn.depth > 0.01 * worn.depth.max()) < 0.5 * worn.depth.size


def test_compare_recovers_the_simulated_profile(worn: Worn) -> None:
    cmp = compare_measurement(
        worn.depth,
        worn.x,
        worn.y,
        worn.radius,
        axial_length=worn.config.joint.axial_length,
        density=worn.config.materials.bushing.density,
        floor=3 * NOISE,
    )
    assert cmp.fit is not None
    assert cmp.fit.method == "robust"
    assert np.hypot(cmp.fit.center_x - CENTER[0], cmp.fit.center_y - CENTER[1]) < 0.3e-6
    assert math.degrees(cmp.alignment_offset) == pytest.approx(ROTATION_DEG, abs=0.3)
    assert cmp.aligned
    assert cmp.profile_method == "bin"  # 20 points per node
    assert abs(cmp.peak_error_rel) < 0.02
    assert cmp.rms_error < 0.5 * NOISE  # averaged over ~20 points per node
    assert abs(cmp.width_error_deg) < 3.0
    assert abs(cmp.mass_error_rel) < 0.01
    assert cmp.mass_error_rel == pytest.approx(cmp.area_error_rel)
    assert cmp.simulated_metrics.mass == pytest.approx(2200 * 20e-3 * cmp.simulated_metrics.area)
    np.testing.assert_allclose(cmp.simulated, worn.depth)
    np.testing.assert_allclose(cmp.theta, node_angles(worn.depth.size))
    summary = cmp.summary()
    assert summary["fit"] == "robust"
    assert summary["peak_error_rel"] == cmp.peak_error_rel
    assert summary["alignment_offset_deg"] == pytest.approx(ROTATION_DEG, abs=0.3)


def test_a_load_direction_off_by_8_deg_shows_as_measured_and_is_aligned_away(
    worn: Worn,
) -> None:
    """The real load 8 deg from the model's: the measured frame says so, the alignment undoes it.

    The measured bushing wears like the simulation but with its scar turned 8 deg
    (instrument frame = bushing frame). As measured, the peak sits 8 deg from the
    predicted one; rotated by the best alignment (~8 deg) it sits on it.
    """
    shift = 8.0
    theta = node_angles(worn.depth.size)
    turned = np.interp(theta - math.radians(shift), theta, worn.depth, period=2 * np.pi)
    x, y = synthesize_measurement(turned, worn.radius, 3600, NOISE, 5, (0.0, 0.0), 0.0)
    node = 360.0 / worn.depth.size
    cmp = compare_measurement(worn.depth, x, y, worn.radius, floor=3 * NOISE)
    summary = cmp.summary()
    # the measured frame: no rotation
    simulated_peak = summary["peak_angle_simulated_deg"]
    assert summary["peak_angle_measured_deg"] == pytest.approx(simulated_peak + shift, abs=node)
    assert summary["peak_angle_difference_deg"] == pytest.approx(shift, abs=node)
    assert summary["rms_error_measured_frame_m"] > 5 * summary["rms_error_m"]
    np.testing.assert_allclose(cmp.measured_unrotated, turned, atol=3e-6)
    # the best alignment: rotated by the shift, nothing left over
    assert summary["alignment"] == "best"
    assert summary["alignment_offset_deg"] == pytest.approx(shift, abs=0.3)
    assert summary["peak_angle_aligned_deg"] == pytest.approx(simulated_peak, abs=node)
    assert summary["peak_angle_residual_deg"] == pytest.approx(0.0, abs=node)
    assert summary["rms_error_m"] < 0.5 * NOISE
    # a given offset of zero keeps the measured frame: the 8 deg stay a residual
    as_is = compare_measurement(worn.depth, x, y, worn.radius, align=0.0).summary()
    assert as_is["peak_angle_residual_deg"] == pytest.approx(shift, abs=node)
    assert as_is["peak_angle_measured_deg"] == summary["peak_angle_measured_deg"]


def test_robust_fit_beats_the_plain_fit_on_the_one_sided_scar(worn: Worn) -> None:
    robust = compare_measurement(worn.depth, worn.x, worn.y, worn.radius, fit="robust")
    plain = compare_measurement(worn.depth, worn.x, worn.y, worn.radius, fit="least-squares")
    assert plain.fit is not None
    assert plain.fit.method == "least_squares"
    assert plain.summary()["fit"] == "least-squares"
    # the plain centre is pulled towards the scar: the peak looks far too shallow
    assert plain.peak_error_rel < -0.3
    assert abs(robust.peak_error_rel) < abs(plain.peak_error_rel) / 10
    assert robust.rms_error < plain.rms_error / 10
    # ... while the removed area (a centre shift moves area around) nearly survives
    assert abs(plain.area_error_rel) < 0.01


def test_given_offset_and_interpolated_profile(worn: Worn) -> None:
    best = compare_measurement(worn.depth, worn.x, worn.y, worn.radius)
    given = compare_measurement(
        worn.depth,
        worn.x,
        worn.y,
        worn.radius,
        align=math.radians(ROTATION_DEG),
        profile="interpolate",
    )
    assert not given.aligned
    assert given.alignment_offset == pytest.approx(math.radians(ROTATION_DEG))
    assert given.profile_method == "interpolate"
    # single noisy points per node: noisier, but the same profile
    assert given.rms_error < 1.5 * NOISE
    assert abs(given.peak_error_rel) < 0.05
    assert best.rms_error < given.rms_error
    wrong = compare_measurement(worn.depth, worn.x, worn.y, worn.radius, align=0.0)
    assert wrong.rms_error > 10 * best.rms_error


def test_compare_profiles_finds_a_sub_node_rotation_and_signs() -> None:
    nodes = 360
    theta = node_angles(nodes)
    simulated = 40e-6 * np.cos(0.5 * (theta - 2.0)) ** 8
    offset = math.radians(33.3)  # not a whole node
    measured = 1.1 * np.interp(theta - offset, theta, simulated, period=2 * np.pi)
    cmp = compare_profiles(simulated, measured, 7.5e-3, axial_length=0.02, density=2200.0)
    assert cmp.alignment_offset == pytest.approx(offset, abs=1e-3)
    # linear interpolation of a rotated grid profile clips its peak a little
    assert cmp.peak_error == pytest.approx(4e-6, rel=0.01)
    assert cmp.peak_error_rel == pytest.approx(0.1, abs=1e-3)
    assert cmp.mass_error_rel == pytest.approx(0.1, abs=2e-3)  # area is nearly linear in h
    assert cmp.mass_error > 0
    assert cmp.width_error_deg == pytest.approx(0.0, abs=1.5)
    assert cmp.rms_error == pytest.approx(0.1 * np.sqrt(np.mean(simulated**2)), rel=0.01)
    # the same without mass: NaN, not an error
    bare = compare_profiles(simulated, measured, 7.5e-3)
    assert math.isnan(bare.mass_error_rel)
    assert math.isnan(bare.summary()["wear_mass_measured_kg"])
    # a floor above the threshold narrows both widths alike
    floored = compare_profiles(simulated, measured, 7.5e-3, floor=10e-6)
    assert floored.simulated_metrics.width < cmp.simulated_metrics.width


def test_profile_choice() -> None:
    assert resolve_profile_method("auto", 3600, 360) == "bin"
    assert resolve_profile_method("auto", 500, 360) == "interpolate"
    assert resolve_profile_method("interpolate", 3600, 360) == "interpolate"
    with pytest.raises(ConfigError, match="did you mean 'bin'"):
        resolve_profile_method("bins", 3600, 360)


def test_bad_inputs(worn: Worn) -> None:
    with pytest.raises(DataError, match="180"):
        compare_profiles(worn.depth, worn.depth[:90], worn.radius)
    with pytest.raises(DataError, match="finite"):
        compare_profiles(np.full(180, np.nan), worn.depth, worn.radius)
    with pytest.raises(ConfigError, match="did you mean 'robust'"):
        fit_circle(worn.x, worn.y, worn.radius, "robustt")
    with pytest.raises(ConfigError, match="align"):
        compare_profiles(worn.depth, worn.depth, worn.radius, align="worst")
    with pytest.raises(ConfigError, match="align"):
        compare_profiles(worn.depth, worn.depth, worn.radius, align=math.inf)


def test_plot_comparison_writes_png_and_svg(worn: Worn, tmp_path: Path) -> None:
    cmp = compare_measurement(worn.depth, worn.x, worn.y, worn.radius)
    paths = plot_comparison(cmp, tmp_path / "plots", worn.x, worn.y, label="test")
    names = sorted(p.name for p in paths)
    assert names == [
        "compare_polar.png",
        "compare_polar.svg",
        "compare_profile.png",
        "compare_profile.svg",
    ]
    assert all(p.stat().st_size > 1000 for p in paths)
    assert not [p for p in (tmp_path / "plots").iterdir() if p.name.startswith(".")]
