"""Synthetic measurements: the scar's closed forms, and points where the instrument sees them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.errors import DataError
from jointwear.geometry import node_angles
from jointwear.geometry.angles import wrap_angle
from jointwear.measurement.synthetic import cosine_squared_scar, synthesize_measurement
from jointwear.tribology.metrics import wear_width

R = 7.5e-3


@pytest.mark.parametrize("centre_deg", [0.0, 30.0, 179.5, -170.0])
def test_scar_peak_support_and_width_at_one_percent(centre_deg: float) -> None:
    """``h = peak cos^2(pi phi / w)``: deepest at its centre (also across theta = 0),
    zero beyond ``w / 2``, and ``w arccos(0.1) / (pi / 2)`` wide at 1 % of the peak."""
    width = math.radians(170.0)
    depth = cosine_squared_scar(3600, 60e-6, width, math.radians(centre_deg))
    theta = node_angles(3600)
    assert depth.max() == pytest.approx(60e-6, rel=1e-6)
    distance = np.abs(wrap_angle(theta - math.radians(centre_deg)))
    assert math.degrees(distance[np.argmax(depth)]) < 0.1
    assert np.all(depth[distance >= width / 2 + 1e-12] == 0.0)
    expected = width * math.acos(0.1) / (math.pi / 2)
    assert wear_width(depth, 0.01) == pytest.approx(expected, abs=math.radians(0.2))


def test_noise_free_points_lie_at_the_worn_radius_in_the_instrument_frame() -> None:
    depth = cosine_squared_scar(360, 40e-6, math.radians(120.0), math.radians(60.0))
    centre, rotation = (2e-3, -5e-3), math.radians(35.0)
    x, y = synthesize_measurement(depth, R, 720, 0.0, 1, centre, rotation, random_spacing=False)
    dx, dy = x - centre[0], y - centre[1]
    # equally spaced from 0: point 2 j sits on node j, seen at theta_j + rotation
    assert np.hypot(dx, dy)[::2] == pytest.approx(R + depth, abs=1e-15)
    seen = np.arctan2(dy, dx)[::2] - rotation
    assert np.allclose(np.cos(seen), np.cos(node_angles(360)), atol=1e-12)


def test_noise_has_the_given_spread_and_the_seed_repeats_it() -> None:
    flat = np.zeros(360)
    x, y = synthesize_measurement(flat, R, 20000, 1e-6, 5)
    assert np.std(np.hypot(x, y) - R) == pytest.approx(1e-6, rel=0.03)
    again = synthesize_measurement(flat, R, 20000, 1e-6, 5)
    assert np.array_equal(x, again[0])


def test_bad_synthetic_inputs() -> None:
    with pytest.raises(DataError, match="scar width"):
        cosine_squared_scar(360, 1e-6, 0.0)
    with pytest.raises(DataError, match="noise_std"):
        synthesize_measurement(np.zeros(360), R, 10, -1.0)
