"""The package's one angle wrap: intervals, periodicity and the edge cases of mod."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from jointwear.geometry.angles import angle_in_turn, wrap_angle

angles = st.floats(min_value=-1e4, max_value=1e4, allow_nan=False)


@given(angles)
def test_wrap_angle_is_in_the_half_open_interval_and_congruent(angle: float) -> None:
    wrapped = float(wrap_angle(angle))
    assert -np.pi < wrapped <= np.pi
    turns = (angle - wrapped) / (2 * np.pi)
    assert abs(turns - round(turns)) < 1e-9


@given(angles)
def test_angle_in_turn_is_in_one_turn_and_congruent(angle: float) -> None:
    position = float(angle_in_turn(angle))
    assert 0.0 <= position < 2 * np.pi
    turns = (angle - position) / (2 * np.pi)
    assert abs(turns - round(turns)) < 1e-9


def test_the_interval_edges() -> None:
    assert wrap_angle(np.pi) == np.pi
    assert wrap_angle(-np.pi) == np.pi
    assert angle_in_turn(-1e-300) == 0.0
    assert angle_in_turn(2 * np.pi) == 0.0
