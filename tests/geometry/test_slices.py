"""The slices' contours of a wear map."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.errors import GeometryError
from jointwear.geometry.slices import SlicedContour
from jointwear.geometry.update import update_contour


def test_a_map_grows_slice_by_slice_and_keeps_its_digits():
    rng = np.random.default_rng(3)
    wear = rng.uniform(0, 1e-6, (4, 32))
    sliced = SlicedContour.of_depth(7.5e-3, wear, 0.02)
    assert sliced.count == 4
    assert sliced.axial_length == pytest.approx(0.02)
    assert all(c.axial_length == pytest.approx(0.005) for c in sliced.contours)
    increment = rng.uniform(0, 1e-7, (4, 32))
    grown = update_contour(sliced, increment, wall_thickness=2.5e-3)
    np.testing.assert_array_equal(grown.wear_depth, wear + increment)
    np.testing.assert_array_equal(grown.radius, sliced.radius + increment)
    with pytest.raises(GeometryError, match="shape"):
        sliced.worn(np.zeros((3, 32)))


def test_each_slice_contour_is_its_row_of_the_map_and_a_bad_map_is_refused():
    rng = np.random.default_rng(5)
    wear = rng.uniform(0, 1e-6, (3, 20))
    sliced = SlicedContour.of_depth(7.5e-3, wear, 0.03)
    for row, contour in enumerate(sliced.contours):
        np.testing.assert_array_equal(contour.wear_depth, wear[row])
        np.testing.assert_array_equal(contour.radius, 7.5e-3 + wear[row])
        assert contour.axial_length == pytest.approx(0.01)
    # the map is kept, not copied into every slice (memory linear in the slices)
    assert all(np.shares_memory(c.radius, sliced.radius) for c in sliced.contours)
    bad = wear.copy()
    bad[1, 4] = np.nan
    with pytest.raises(GeometryError, match="positive and finite"):
        SlicedContour.of_depth(7.5e-3, bad, 0.03)
    with pytest.raises(GeometryError, match="positive and finite"):
        sliced.worn(np.where(np.arange(20) == 3, -1.0, 0.0) * np.ones((3, 1)))
