"""Measured wear profile on the node grid, alignment by best fit, wear metrics."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.errors import DataError
from jointwear.geometry import BushingContour, node_angles
from jointwear.geometry.angles import wrap_angle
from jointwear.measurement.fit import CircleFit, fit_circle_robust
from jointwear.measurement.profile import (
    align_profiles,
    measured_contour,
    measured_wear_profile,
    wear_metrics,
)
from jointwear.measurement.synthetic import cosine_squared_scar, synthesize_measurement

from .conftest import Scenario

R = 7.5e-3


def true_centre(scenario: Scenario) -> CircleFit:
    return CircleFit(*scenario.center, scenario.radius, 0.0, "truth")


@pytest.mark.parametrize("method", ["interpolate", "bin"])
def test_profile_about_true_centre_reproduces_noise_free_wear(
    scenario: Scenario, method: str
) -> None:
    # 3 points per node at -1/3, 0, +1/3 node, no noise: interpolation is exact; binning
    # averages across the kink of the piecewise linear profile at the node (~1e-8 m)
    x, y = synthesize_measurement(
        scenario.depth, R, 3 * 360, 0.0, 0, scenario.center, scenario.rotation, random_spacing=False
    )
    depth = measured_wear_profile(x, y, true_centre(scenario), R, 360, scenario.rotation, method)
    assert depth.shape == (360,)
    tolerance = 1e-12 * R if method == "interpolate" else 2e-8
    np.testing.assert_allclose(depth, scenario.depth, rtol=0, atol=tolerance)


def test_profile_onto_a_coarser_and_finer_grid(scenario: Scenario) -> None:
    x, y = synthesize_measurement(
        scenario.depth, R, 3600, 0.0, 1, scenario.center, scenario.rotation
    )
    for nodes in (90, 720):
        depth = measured_wear_profile(x, y, true_centre(scenario), R, nodes, scenario.rotation)
        expected = cosine_squared_scar(nodes, scenario.peak, scenario.width, scenario.scar_angle)
        # limited by the linear interpolation of the 1 deg synthetic profile
        np.testing.assert_allclose(depth, expected, atol=0.01 * scenario.peak)


def test_negative_depths_are_kept(scenario: Scenario) -> None:
    x, y = synthesize_measurement(np.zeros(360), R, 720, 1e-6, 4)
    depth = measured_wear_profile(x, y, CircleFit(0.0, 0.0, R, 0.0, "truth"), R, 360)
    assert depth.min() < -1e-6  # noise below the unworn circle is not clipped
    assert abs(depth.mean()) < 0.2e-6


def test_bin_method_averages_noise(
    scenario: Scenario, worn_points: tuple[np.ndarray, np.ndarray]
) -> None:
    x, y = worn_points
    fit = true_centre(scenario)
    interpolated = measured_wear_profile(x, y, fit, R, 360, scenario.rotation, "interpolate")
    binned = measured_wear_profile(x, y, fit, R, 360, scenario.rotation, "bin")
    # 10 points per node: the mean of a node's points is about 3x less noisy
    assert np.std(binned - scenario.depth) < 0.5 * np.std(interpolated - scenario.depth)


def test_bin_method_fills_empty_nodes() -> None:
    depth = cosine_squared_scar(360, 60e-6, np.radians(170), 0.0)
    x, y = synthesize_measurement(depth, R, 100, 0.0, 2, random_spacing=False)
    binned = measured_wear_profile(x, y, CircleFit(0.0, 0.0, R, 0.0, "truth"), R, 360, method="bin")
    assert np.all(np.isfinite(binned))
    np.testing.assert_allclose(binned, depth, atol=0.03 * 60e-6)


@pytest.mark.parametrize("rotation_deg", [37.3, -101.6, 200.25, 0.4])
def test_alignment_recovers_a_known_rotation(scenario: Scenario, rotation_deg: float) -> None:
    rotation = np.radians(rotation_deg)
    x, y = synthesize_measurement(scenario.depth, R, 3600, 1e-6, 8, scenario.center, rotation)
    fit = fit_circle_robust(x, y, R)
    unaligned = measured_wear_profile(x, y, fit, R, 360)  # instrument frame
    offset, aligned = align_profiles(scenario.depth, unaligned)
    node = 2 * np.pi / 360
    error = wrap_angle(offset - rotation)
    assert abs(error) < node  # within a node ...
    assert abs(error) < 0.2 * node  # ... in fact well within (parabolic refinement)
    assert -np.pi < offset <= np.pi
    # the aligned profile is the profile taken at that offset
    direct = measured_wear_profile(x, y, fit, R, 360, angle_offset=offset)
    # (the two interpolate the 1 um noise differently)
    assert np.sqrt(np.mean((aligned - direct) ** 2)) < 1.5e-6
    assert np.sqrt(np.mean((aligned - scenario.depth) ** 2)) < 1.5e-6


def test_alignment_of_identical_profiles_is_zero(scenario: Scenario) -> None:
    offset, aligned = align_profiles(scenario.depth, scenario.depth)
    assert offset == pytest.approx(0.0, abs=1e-12)
    np.testing.assert_allclose(aligned, scenario.depth, atol=1e-15)


def test_alignment_rejects_mismatched_profiles() -> None:
    with pytest.raises(DataError, match="equal length"):
        align_profiles(np.zeros(360), np.zeros(180))
    with pytest.raises(DataError, match="finite"):
        align_profiles(np.zeros(360), np.full(360, np.nan))


# ------------------------------------------------------------------ metrics
def test_metrics_of_a_cos2_scar_match_closed_forms(scenario: Scenario) -> None:
    depth, peak, width = scenario.depth, scenario.peak, scenario.width
    metrics = wear_metrics(depth, R, threshold=0.01, axial_length=20e-3, density=2200.0)
    assert metrics.peak_depth == pytest.approx(peak, rel=1e-3)  # a node sits 0.003 deg off
    assert metrics.peak_angle_deg == pytest.approx(30.0)
    # h > 1 % of peak where |phi| < width * arccos(0.1) / pi, within one node
    expected_width = np.degrees(2 * width * np.arccos(0.1) / np.pi)
    assert metrics.width_deg == pytest.approx(expected_width, abs=1.0)
    # area = R0 * int h + 1/2 int h^2 = R0 * peak * w / 2 + 3 peak^2 w / 16
    expected_area = R * peak * width / 2 + 3 * peak**2 * width / 16
    assert metrics.area == pytest.approx(expected_area, rel=1e-6, abs=0)
    assert metrics.volume == pytest.approx(20e-3 * metrics.area, rel=1e-6, abs=0)
    assert metrics.mass == pytest.approx(2200.0 * 20e-3 * metrics.area)
    assert metrics.min_depth == 0.0


def test_metrics_agree_with_the_contour(scenario: Scenario) -> None:
    contour = measured_contour(scenario.depth, R, 20e-3)
    assert isinstance(contour, BushingContour)
    np.testing.assert_allclose(contour.wear_depth, scenario.depth, atol=1e-18)
    unworn = BushingContour.circle(R, 360, 20e-3)
    metrics = wear_metrics(scenario.depth, R)
    assert metrics.area == pytest.approx(contour.area - unworn.area, rel=1e-9, abs=0)
    assert np.isnan(metrics.volume)
    assert np.isnan(metrics.mass)


def test_width_floor_ignores_noise() -> None:
    rng = np.random.default_rng(3)
    depth = cosine_squared_scar(360, 60e-6, np.radians(120), 0.0) + rng.normal(0, 1e-6, 360)
    noisy = wear_metrics(depth, R)
    floored = wear_metrics(depth, R, floor=3e-6)
    # 1 % of 60 um is 0.6 um: a quarter of the 250 unworn nodes count as worn
    assert noisy.width_deg > 150
    # with the floor: h > 3 um where |phi| < w / pi * arccos(sqrt(3 / 60)), about 103 deg
    expected = 2 * 120 * np.arccos(np.sqrt(3 / 60)) / np.pi
    assert floored.width_deg == pytest.approx(expected, abs=6)


def test_metric_errors() -> None:
    with pytest.raises(DataError, match="threshold"):
        wear_metrics(np.zeros(360), R, threshold=1.5)
    with pytest.raises(DataError, match="axial length"):
        wear_metrics(np.zeros(360), R, axial_length=-1.0)
    with pytest.raises(DataError, match="original radius"):
        measured_wear_profile(np.ones(3), np.ones(3), CircleFit(0, 0, 1, 0, "x"), 0.0, 360)
    with pytest.raises(DataError, match="method"):
        measured_wear_profile(
            np.ones(3), np.ones(3), CircleFit(0, 0, 1, 0, "x"), R, 360, method="spline"
        )


def test_node_grid_is_the_simulation_grid(scenario: Scenario) -> None:
    # node j of the measured profile is at theta_j = 2 pi j / N, like the simulation's
    x, y = synthesize_measurement(scenario.depth, R, 7200, 0.0, 0, random_spacing=False)
    depth = measured_wear_profile(x, y, CircleFit(0.0, 0.0, R, 0.0, "truth"), R, 360)
    assert node_angles(360)[np.argmax(depth)] == pytest.approx(scenario.scar_angle)
