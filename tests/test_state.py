"""What the loop carries between updates: immutable states, persistent logs, deferred items."""

from __future__ import annotations

from typing import ClassVar

import numpy as np
import pytest

from jointwear import Simulation
from jointwear import state as state_module
from jointwear.config import Config
from jointwear.state import Deferred, Log, revolution_number


class _Square(Deferred):
    __slots__ = ("value",)
    batches: ClassVar[list[int]] = []

    def __init__(self, value: int) -> None:
        self.value = value

    @classmethod
    def resolve(cls, items):
        cls.batches.append(len(items))
        return [item.value**2 for item in items]


def test_deferred_items_read_as_their_values():
    _Square.batches.clear()
    log = Log.of([1, _Square(2), _Square(3)])
    longer = log.append(_Square(4))
    assert log.last == 9
    assert _Square.batches == [2]  # both deferred items of ``log`` at once
    assert longer.items() == [1, 4, 9, 16]
    assert log.items() == [1, 4, 9]  # the shorter log does not see the newer item


def test_deferred_items_are_computed_before_too_many_wait(monkeypatch):
    monkeypatch.setattr(state_module, "DEFERRED_ITEMS", 3)
    _Square.batches.clear()
    log = Log()
    for value in range(7):
        log = log.append(_Square(value))
    assert _Square.batches == [3, 3]
    assert list(log) == [v * v for v in range(7)]
    assert _Square.batches == [3, 3, 1]


def test_states_are_immutable_and_do_not_share_records(paper_config: Config) -> None:
    small = paper_config.replace({"contact.nodes": 120, "simulation.steps_per_revolution": 90})
    simulation = Simulation(
        small.replace({"simulation.update_contour": True, "simulation.revolutions": 5})
    )
    s0 = simulation.initial_state()
    s1 = simulation.step(s0)
    s2 = simulation.step(s1)
    assert [len(s.history) for s in (s0, s1, s2)] == [0, 1, 2]
    assert s1.history_columns["revolution"] == [1]
    with pytest.raises(ValueError, match="read-only"):
        s2.wear_depth[0] = 1.0
    with pytest.raises(AttributeError):
        s2.revolution = 7  # type: ignore[misc]
    # a retried step from the same state gives the same state, not a longer record
    again = simulation.step(s1)
    np.testing.assert_array_equal(again.wear_depth, s2.wear_depth)
    assert len(again.history) == 2


def test_log_is_persistent() -> None:
    a = Log().append(1).append(2)
    b = a.append(3)
    c = a.append(4)
    assert [list(a), list(b), list(c)] == [[1, 2], [1, 2, 3], [1, 2, 4]]
    assert Log.of([{"x": 1}, {"x": 2}]).columns() == {"x": [1, 2]}


def test_an_evolved_state_is_a_new_state_with_read_only_arrays() -> None:
    base = state_module.SimulationState(revolution=0, wear_depth=np.zeros(16))
    depth = np.linspace(0.0, 1e-6, 16)
    new = base.evolved({"revolution": 3, "wear_depth": depth})
    assert (base.revolution, new.revolution) == (0, 3)
    assert not base.wear_depth.any()
    depth[0] = 1.0  # the caller's array: the state holds its own copy
    assert new.wear_depth[0] == 0.0
    assert not new.wear_depth.flags.writeable
    with pytest.raises(TypeError, match="no_such_field"):
        base.evolved({"no_such_field": 1})


def test_revolution_numbers_are_whole_where_they_can_be() -> None:
    assert revolution_number(12.0) == 12
    assert isinstance(revolution_number(12.0), int)
    assert revolution_number(12.25) == 12.25
