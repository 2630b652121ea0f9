"""Deferred log items: computed when read, in batches, each to the value it has alone."""

from __future__ import annotations

from typing import ClassVar

from jointwear import state as state_module
from jointwear.state import Deferred, Log


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
