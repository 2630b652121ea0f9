"""Centre and rotation of measured points against a known profile.

The robust circle fit has to decide which points are unworn; the scar's shallow flanks
(wear below a few noise standard deviations) pass for unworn and pull its centre towards
the scar. Fitted with the profile, every point is used for what it is: the centre and the
rotation come out unbiased, with the scatter the Jacobian predicts.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.errors import DataError
from jointwear.measurement.fit import fit_circle_robust
from jointwear.measurement.pointfit import fit_points, interpolation_weights
from jointwear.measurement.profile import align_profiles, measured_wear_profile
from jointwear.measurement.synthetic import cosine_squared_scar, synthesize_measurement

RADIUS = 7.5e-3  # [m]
NODES = 180
CENTER = (3.0e-3, -2.0e-3)  # [m]
ROTATION = math.radians(40.0)
SCAR = math.radians(-90.0)  # deepest point, bushing frame
NOISE = 2e-6  # [m]: a noisy instrument, a 20 um scar


def scar() -> np.ndarray:
    return cosine_squared_scar(NODES, 20e-6, math.radians(120.0), SCAR)


def measure(seed: int) -> tuple[np.ndarray, np.ndarray]:
    return synthesize_measurement(scar(), RADIUS, 2000, NOISE, seed, CENTER, ROTATION)


def fitted(x: np.ndarray, y: np.ndarray):
    circle = fit_circle_robust(x, y, RADIUS)
    first = measured_wear_profile(x, y, circle, RADIUS, NODES, 0.0, "bin")
    offset, _ = align_profiles(scar(), first)
    return circle, fit_points(x, y, scar(), RADIUS, circle.center, offset)


def test_interpolation_weights_reproduce_np_interp() -> None:
    depth = np.random.default_rng(1).normal(size=12)
    angles = np.linspace(-7.0, 13.0, 101)
    k, w = interpolation_weights(angles, depth.size)
    nodes = 2 * np.pi * np.arange(depth.size) / depth.size
    expected = np.interp(angles, nodes, depth, period=2 * np.pi)
    assert (1 - w) * depth[k] + w * depth[(k + 1) % depth.size] == pytest.approx(expected)


def test_noise_free_points_give_back_centre_and_rotation() -> None:
    x, y = synthesize_measurement(scar(), RADIUS, 1000, 0.0, 3, CENTER, ROTATION)
    start = (CENTER[0] + 2e-6, CENTER[1] - 3e-6)
    fit = fit_points(x, y, scar(), RADIUS, start, ROTATION + math.radians(2.0))
    assert (fit.center_x, fit.center_y) == pytest.approx(CENTER, abs=1e-10)
    assert fit.offset == pytest.approx(ROTATION, abs=1e-7)
    assert fit.rms_residual < 1e-10
    assert fit.free == ("center_x", "center_y", "offset")


def test_centre_is_unbiased_where_the_circle_fit_leans_towards_the_scar() -> None:
    towards_scar = np.array([math.cos(SCAR + ROTATION), math.sin(SCAR + ROTATION)])
    circle_lean, point_lean, z_scores = [], [], []
    for seed in range(12):
        x, y = measure(seed)
        circle, fit = fitted(x, y)
        circle_lean.append(np.dot(np.subtract(circle.center, CENTER), towards_scar))
        point_lean.append(np.dot(np.subtract((fit.center_x, fit.center_y), CENTER), towards_scar))
        dof = x.size - fit.jacobian.shape[1]
        covariance = np.linalg.inv(fit.jacobian.T @ fit.jacobian) * fit.cost / dof
        error = np.array(
            [fit.center_x - CENTER[0], fit.center_y - CENTER[1], fit.offset - ROTATION]
        )
        z_scores.append(error / np.sqrt(np.diag(covariance)))
        assert fit.rms_residual == pytest.approx(NOISE, rel=0.06)
    # the circle fit keeps the shallow flanks: its centre leans towards the scar by a
    # sizeable share of the noise, every time
    assert min(circle_lean) > 0.1 * NOISE
    # fitted with the profile: no lean beyond the scatter, and the scatter is the predicted one
    assert abs(np.mean(point_lean)) < 0.3 * np.mean(circle_lean)
    z = np.array(z_scores)
    assert np.sqrt(np.mean(z**2)) == pytest.approx(1.0, abs=0.4)


def test_fixed_centre_and_offset() -> None:
    x, y = measure(5)
    fixed = fit_points(x, y, scar(), RADIUS, CENTER, ROTATION, fit_center=False, fit_offset=False)
    assert fixed.free == ()
    assert (fixed.center_x, fixed.center_y, fixed.offset) == pytest.approx((*CENTER, ROTATION))
    assert fixed.jacobian.shape == (x.size, 0)
    turned = fit_points(x, y, scar(), RADIUS, CENTER, ROTATION + 0.05, fit_center=False)
    assert turned.free == ("offset",)
    assert turned.offset == pytest.approx(ROTATION, abs=math.radians(1.0))


def test_bad_input() -> None:
    x, y = measure(6)
    with pytest.raises(DataError, match="profile must be finite"):
        fit_points(x, y, np.full(NODES, np.nan), RADIUS, CENTER, 0.0)
    with pytest.raises(DataError, match="radius must be > 0"):
        fit_points(x, y, scar(), -1.0, CENTER, 0.0)
    with pytest.raises(DataError, match="at least 3 points"):
        fit_points(x[:2], y[:2], scar(), RADIUS, CENTER, 0.0)
