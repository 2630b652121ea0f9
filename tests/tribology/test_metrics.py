"""Wear metrics: peak, width, removed area, volume, mass."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from jointwear.tribology import metrics


def test_removed_area_of_uniform_wear_is_the_exact_annulus() -> None:
    radius, depth = 7.5e-3, 3e-5
    worn = np.full(360, radius + depth)
    assert metrics.removed_area(radius, worn) == pytest.approx(
        np.pi * ((radius + depth) ** 2 - radius**2), rel=1e-13, abs=0
    )


def test_removed_area_is_exact_for_a_shifted_circle() -> None:
    # a circle of the same radius moved off-centre encloses the same area:
    # the polar area of the node contour must be unchanged to spectral accuracy
    radius, shift, n = 7.5e-3, 2e-4, 720
    theta = 2 * np.pi * np.arange(n) / n
    r = shift * np.cos(theta) + np.sqrt(radius**2 - (shift * np.sin(theta)) ** 2)
    assert metrics.removed_area(radius, r) == pytest.approx(0.0, abs=1e-18)


def test_width_counts_interpolated_crossings() -> None:
    depth = np.zeros(360)
    depth[10:20] = 1.0  # 10 nodes at the peak, linear ramps of one node each side
    # above 1 % of the peak: 9 full intervals inside, plus 0.99 of each ramp
    expected = (9 + 2 * 0.99) * np.pi / 180
    assert metrics.wear_width(depth, 0.01) == pytest.approx(expected, rel=1e-12, abs=0)


def test_width_of_no_wear_is_zero() -> None:
    assert metrics.wear_width(np.zeros(90)) == 0.0


def test_width_wraps_around_zero() -> None:
    depth = np.zeros(360)
    depth[-5:] = 1.0
    depth[:5] = 1.0
    assert metrics.wear_width(depth) == pytest.approx(metrics.wear_width(np.roll(depth, 100)))


@settings(max_examples=60, deadline=None)
@given(shift=st.integers(0, 359), scale=st.floats(1e-12, 1e-2))
def test_width_is_rotation_and_scale_invariant(shift: int, scale: float) -> None:
    theta = np.radians(np.arange(360))
    profile = np.clip(np.cos(theta - 1.0), 0.0, None) ** 2
    reference = metrics.wear_width(profile)
    assert metrics.wear_width(scale * np.roll(profile, shift)) == pytest.approx(reference, rel=1e-9)


def test_mass_and_volume() -> None:
    area, b, rho = 2e-10, 0.02, 2200.0
    assert metrics.wear_volume(area, b) == pytest.approx(4e-12, rel=1e-6, abs=0)
    assert metrics.wear_mass(area, b, rho) == pytest.approx(8.8e-9, rel=1e-6, abs=0)


def test_pin_wear_of_uniform_depth_is_the_exact_annulus(paper_config) -> None:
    """A pin worn inwards by ``h`` everywhere loses ``pi (R_p^2 - (R_p - h)^2) b``."""
    joint = paper_config.joint
    depth = 4e-5
    found = metrics.pin_metrics(np.full(180, depth), joint)
    radius = joint.pin_radius
    annulus = np.pi * (radius**2 - (radius - depth) ** 2) * joint.axial_length
    assert found["pin_wear_volume"] == pytest.approx(annulus, rel=1e-13, abs=0)
    assert found["pin_peak_wear_depth"] == depth
