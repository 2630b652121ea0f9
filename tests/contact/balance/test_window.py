"""Node windows about the load lines (:mod:`jointwear.contact.balance.window`)."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.contact import contact_law
from jointwear.contact.balance.window import (
    PIN_REACH,
    angle_addition,
    half_angles,
    nearest_nodes,
    reach_width,
    upper_bound,
    widest_half_angle,
)

from .common import RNG


def test_widest_is_the_largest_half_angle():
    """The coarse pass sizes the window from the rows in the outermost contact columns only."""
    rng = np.random.default_rng(5)
    dtheta = np.radians(1.0)
    for _ in range(300):
        rows, half = rng.integers(1, 30), rng.integers(2, 20)
        offsets = np.arange(-half, half + 1) * dtheta
        phi = offsets + rng.uniform(-0.5, 0.5, (rows, 1)) * dtheta
        depth = rng.normal(size=phi.shape) - rng.uniform(0, 3) * np.abs(phi) / (half * dtheta)
        contact = depth > 0
        left, right = half_angles(phi, depth, contact)
        widest = max(left.max(), right.max())
        assert widest_half_angle(phi, depth, contact) == widest


@pytest.mark.parametrize("model", ["winkler", "asymmetric-winkler"])
def test_reach_on_the_load_line_equals_the_general_bound(params, pin, worn, model):
    """Paper mode's reach bound (pin on the load line): the general one, nothing sideways."""
    law = contact_law(model, params)
    azimuth = RNG.uniform(-np.pi, np.pi, 50)
    centre = worn.radius_at(azimuth)
    gap = worn.radius.min() - pin.radius
    for scale in (0.5, 1.0, 1.01, 1.3, 3.0):
        along = scale * gap * RNG.uniform(0.9, 1.1, azimuth.size)
        on_line = reach_width(worn, pin, law, centre, along, None)
        general = reach_width(worn, pin, law, centre, along, np.zeros_like(along))
        assert on_line == general


def test_nearest_node_and_its_shift_put_every_load_line_back():
    """``centre dtheta - shift`` is the azimuth (any number of turns), the nearest node is
    at most half a node away, and a line a hair below 0 is at node 0 (or N), not 2 pi off."""
    nodes = 360
    dtheta = 2 * np.pi / nodes
    azimuth = np.concatenate([RNG.uniform(-20, 20, 500), [0.0, -1e-18, 2 * np.pi, 1e-300]])
    position, centre, shift = nearest_nodes(nodes, azimuth)
    assert np.all((position >= 0) & (position < 2 * np.pi))
    assert np.all(np.abs(shift) <= 0.5 * dtheta * (1 + 1e-12))
    np.testing.assert_allclose(
        np.angle(np.exp(1j * (centre * dtheta - shift - azimuth))), 0.0, atol=1e-13
    )
    assert set((centre[-4:] % nodes).tolist()) == {0}
    np.testing.assert_allclose(shift[-4:], 0.0, atol=1e-15)


def test_angle_addition_is_the_angle():
    offsets = np.arange(-90, 91)
    dtheta = np.radians(1.0)
    shift = RNG.uniform(-0.5, 0.5, 20) * dtheta
    cos, sin = angle_addition(offsets, dtheta, shift)
    angle = offsets * dtheta + shift[:, None]
    np.testing.assert_allclose(cos, np.cos(angle), atol=4e-16)
    np.testing.assert_allclose(sin, np.sin(angle), atol=4e-16)


def test_upper_bound_is_the_wall_or_the_pins_reach_never_below_the_lower():
    pin_radius = 7.45e-3
    gap = np.array([50e-6, 50e-6, 8e-3, 1e-5])
    lower = np.array([40e-6, 40e-6, 8e-3, 2e-5])
    upper = upper_bound(gap, pin_radius, 3.65e-3, lower)
    np.testing.assert_array_equal(upper[:2], gap[:2] + 3.65e-3)  # the wall
    assert upper[2] == 8e-3  # beyond the pin's reach: the lower end, an empty bracket
    assert upper[3] == 1e-5 + 3.65e-3
    unbounded = upper_bound(gap, pin_radius, None, lower)
    np.testing.assert_array_equal(unbounded[[0, 1, 3]], PIN_REACH * pin_radius)
    assert np.all(unbounded >= lower)
