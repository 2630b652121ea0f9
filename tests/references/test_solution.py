"""What the references share: checked loads, contact edges, states sampled on the nodes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.errors import ContactError
from jointwear.geometry import BushingContour
from jointwear.geometry.angles import wrap_angle
from jointwear.references.solution import (
    ReferenceState,
    assemble_solution,
    check_loads,
    edge_from_pressure,
)


@pytest.mark.parametrize("edge", [0.3101, 0.3125, 0.3149])
def test_edge_of_a_square_root_pressure_is_found_exactly(edge: float) -> None:
    """``p^2`` is linear in the angle at a smooth contact edge: two loaded nodes give it."""
    before, last, free = 0.305, 0.31, 0.315
    p_before, p_last = 2e6 * np.sqrt(edge - np.array([before, last]))
    found = edge_from_pressure(last, free, float(p_last), float(p_before))
    assert found == pytest.approx(edge, abs=1e-12)
    # the edge stays between the last loaded and the first free node
    assert edge_from_pressure(last, free, float(p_last), float(p_last) * 1.0001) == free


def test_edge_without_a_second_loaded_node_is_midway() -> None:
    assert edge_from_pressure(0.2, 0.3, 5.0, None) == pytest.approx(0.25)
    # a pressure that does not fall towards the edge gives no slope to extrapolate
    assert edge_from_pressure(0.2, 0.3, 5.0, 4.0) == pytest.approx(0.25)


def test_loads_are_checked_and_azimuths_broadcast() -> None:
    load, azimuth = check_loads([1.0, 2.0, 3.0], 0.5)
    assert load.tolist() == [1.0, 2.0, 3.0]
    assert azimuth.tolist() == [0.5, 0.5, 0.5]
    with pytest.raises(ContactError, match="^load: must be >= 0"):
        check_loads([1.0, -1.0], [0.0, 0.0])
    with pytest.raises(ContactError, match="^load: loads and azimuths must be finite"):
        check_loads([1.0, math.nan], 0.0)


def test_states_on_the_nodes_count_springs_each_side_of_the_load() -> None:
    """A pressure symmetric about the load loads as many nodes left as right of it; a
    pressure beside the load only on its side."""
    contour = BushingContour.circle(7.5e-3, 360, 0.02)
    azimuth = np.radians([40.5, -170.5])  # halfway between nodes

    def state(centre: float, half: float) -> ReferenceState:
        def pressure(theta):
            phi = wrap_angle(np.asarray(theta) - centre)
            return np.where(np.abs(phi) < half, 1e6 * np.cos(np.pi * phi / (2 * half)), 0.0)

        return ReferenceState(pressure, np.zeros(2), 1e-6, 100.0, 0.0, half, half, 3)

    symmetric = state(azimuth[0], math.radians(20.2))
    beside = state(azimuth[1] + math.radians(30.0), math.radians(10.2))
    solution = assemble_solution(contour, azimuth, [symmetric, beside], "test")
    assert solution.springs_left[0] == solution.springs_right[0] == 20
    assert (solution.springs_left[1], solution.springs_right[1]) == (20, 0)
    assert np.all(solution.pressure >= 0)
    assert solution.iterations.tolist() == [3, 3]
    assert solution.model == "test"
