"""What the revolution loop carries from one contour update to the next.

:class:`SimulationState` is immutable: a step returns a new state and never
changes the one it was given, so a state kept by a caller (a checkpoint, a test,
an adaptive step that is retried) always shows what it showed when it was made.
Its records (per-update metrics, saved profiles, dynamics updates) are
:class:`Log` objects: persistent append-only sequences, so appending a row to a new
state shares the earlier rows without copying them and without the earlier
state seeing the new row.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np
from numpy.typing import NDArray

__all__ = ["Deferred", "Log", "SimulationState", "revolution_number"]

FloatArray = NDArray[np.float64]

#: deferred items a log holds at most before it computes them (bounds the memory they hold)
DEFERRED_ITEMS = 256


class Deferred:
    """A log item computed when first read, together with the deferred items before it.

    A subclass stands for a value that costs less computed for many items at once
    (:meth:`resolve`); :class:`Log` replaces it by its value when the log is read, or
    when :data:`DEFERRED_ITEMS` of them are waiting. The value must not depend on which
    other items it is computed with.
    """

    __slots__ = ()

    @classmethod
    def resolve(cls, items: list[Any]) -> list[Any]:
        """The values of ``items`` (consecutive items of this class), in order."""
        raise NotImplementedError


class Log(Sequence[Any]):
    """A persistent append-only sequence: ``log.append(x)`` returns a new, longer log.

    Appending costs O(1) and leaves ``log`` unchanged; the new log shares the
    earlier items. Reading the items walks back to the start (O(n)), which the
    simulation does once per run or checkpoint.
    """

    __slots__ = ("_deferred", "_item", "_length", "_parent")

    def __init__(self, *, parent: Log | None = None, item: Any = None) -> None:
        # (an empty log, or ``parent`` with ``item`` at the end: :meth:`append`)
        self._item = item
        self._parent = parent
        if parent is None:
            self._length = self._deferred = 0
        else:
            self._length = parent._length + 1
            self._deferred = parent._deferred + 1 if isinstance(item, Deferred) else 0

    @classmethod
    def of(cls, items: Iterable[Any]) -> Log:
        """A log holding ``items`` in order."""
        log = cls()
        for item in items:
            log = log.append(item)
        return log

    def append(self, item: Any) -> Log:
        """A new log with ``item`` at the end."""
        new = Log(parent=self, item=item)
        if new._deferred >= DEFERRED_ITEMS:
            new._resolve()
        return new

    def _resolve(self) -> None:
        """Compute the deferred items that end at this node (the value replaces each)."""
        nodes: list[Log] = []
        node: Log | None = self
        while node is not None and isinstance(node._item, Deferred):
            nodes.append(node)
            node = node._parent
        nodes.reverse()
        while nodes:
            kind = type(nodes[0]._item)
            run = 1
            while run < len(nodes) and type(nodes[run]._item) is kind:
                run += 1
            values = kind.resolve([n._item for n in nodes[:run]])
            for done, value in zip(nodes[:run], values, strict=True):
                done._item, done._deferred = value, 0
            del nodes[:run]

    def __len__(self) -> int:
        return self._length

    def __iter__(self) -> Iterator[Any]:
        return iter(self.items())

    def __getitem__(self, index: Any) -> Any:
        return self.items()[index]

    def items(self) -> list[Any]:
        """All items, oldest first."""
        out: list[Any] = []
        node: Log | None = self
        while node is not None and node._length:
            if isinstance(node._item, Deferred):
                node._resolve()
            out.append(node._item)
            node = node._parent
        out.reverse()
        return out

    @property
    def last(self) -> Any:
        """The newest item (``None`` for an empty log)."""
        if not self._length:
            return None
        if isinstance(self._item, Deferred):
            self._resolve()
        return self._item

    def columns(self) -> dict[str, list[Any]]:
        """Rows that are mappings, as one list per key (keys of the first row)."""
        rows = self.items()
        if not rows:
            return {}
        return {key: [row[key] for row in rows] for key in rows[0]}

    def __repr__(self) -> str:
        return f"Log({self._length} items)"


def revolution_number(value: float) -> int | float:
    """A revolution count as a state and a result hold it: an ``int`` if whole, else the
    ``float`` (where a ``[life]`` limit ended a run inside a revolution) [-].

    Parameters
    ----------
    value : float
        Revolutions [-].
    """
    value = float(value)
    return int(value) if value.is_integer() else value


def _frozen(value: Any) -> Any:
    if isinstance(value, np.ndarray) and value.flags.writeable:
        value = value.copy()
        value.flags.writeable = False
    return value


@dataclass(frozen=True, eq=False)
class SimulationState:
    """The state of a run between two contour updates (immutable; SI units).

    Attributes
    ----------
    revolution : int or float
        Revolutions (cycles) completed: whole until a ``[life]`` limit ends the run, and
        then where the limit was reached, a fraction of a revolution included.
    wear_depth : ndarray, shape (N,)
        Accumulated radial wear depth [m] (kept as depth, not radius, so small
        depths carry full precision).
    wear_rate : ndarray, shape (N,) or None
        Wear depth per revolution on the current contour [m].
    interval : int or float
        Revolutions covered by the last update (fractional where a limit ended it).
    history : Log of dict
        One row per contour update: ``revolution``, the wear metrics
        (:data:`~jointwear.tribology.metrics.WEAR_METRICS`) and ``contact_iterations``.
    profiles : Log of (int or float, ndarray)
        Saved wear-depth profiles ``(revolution, depth [m])``, by increasing revolution
        (the last one at the fractional revolution of a stop).
    warm_offset : ndarray or None
        Pin displacement along each load line at the last solve [m] (warm start).
    window : int or None
        Node window of the last contact solve.
    warm_slope : ndarray or None
        Change of ``warm_offset`` per revolution between the last two solves [m].
    next_interval : int or None
        Adaptive updating: the interval the step-size controller proposes next.
    stopped_by : str or None
        The life limit that ended the run (``None`` while running or if it ran to the
        end).
    load_depth : ndarray or None
        Wear depth on which the current load cycle was solved [m] (``None``: the
        unworn joint).
    dynamics_updates : Log of dict
        One row per solve of the dynamics: ``revolution`` and the load-cycle scalars.
    updates_since_dynamics : int
        Contour updates since the dynamics were last solved.
    dynamics_threshold : float
        Growth of the deepest wear since the last solve at which the adaptive
        coupling solves the dynamics again [m] (0: not yet set).
    pin_wear_depth : ndarray, shape (N,) or (slices, N), or None
        Accumulated wear depth of the pin in its own frame [m] (``None``: rigid pin; a
        map over the slices along the pin).
    pin_wear_rate : ndarray, shape (N,) or (slices, N), or None
        The pin's wear per revolution on the current contours [m] (adaptive jumps: at
        the state's wear, as ``wear_rate``).
    """

    revolution: int | float
    wear_depth: FloatArray
    wear_rate: FloatArray | None = None
    interval: int | float = 1
    history: Log = field(default_factory=Log)
    profiles: Log = field(default_factory=Log)
    warm_offset: FloatArray | None = None
    window: int | None = None
    warm_slope: FloatArray | None = None
    next_interval: int | None = None
    stopped_by: str | None = None
    load_depth: FloatArray | None = None
    dynamics_updates: Log = field(default_factory=Log)
    updates_since_dynamics: int = 0
    dynamics_threshold: float = 0.0
    pin_wear_depth: FloatArray | None = None
    pin_wear_rate: FloatArray | None = None

    def __post_init__(self) -> None:
        for name in _ARRAY_FIELDS:
            value = getattr(self, name)
            if value is not None:
                frozen = _frozen(value)
                if frozen is not value:
                    object.__setattr__(self, name, frozen)

    def evolved(self, changes: dict[str, Any]) -> SimulationState:
        """The state with ``changes`` (field name -> value): ``dataclasses.replace(self,
        **changes)`` without its checks of the field names, which ``__init__`` makes."""
        return SimulationState(**{**self.__dict__, **changes})

    @property
    def wear_growth(self) -> float:
        """Growth of the deepest wear since the load cycle was solved [m]."""
        if self.load_depth is None:
            return float(self.wear_depth.max())
        return float(self.wear_depth.max() - self.load_depth.max())

    @property
    def history_columns(self) -> dict[str, list[float]]:
        """The per-update record as one list per quantity."""
        return self.history.columns()

    @property
    def saved_profiles(self) -> dict[int | float, FloatArray]:
        """Saved wear-depth profiles by revolution [m]."""
        return dict(self.profiles.items())

    @property
    def last_saved(self) -> int | float:
        """Revolution of the last saved profile (0 if none)."""
        last = self.profiles.last
        return 0 if last is None else last[0]


#: the fields that may hold an array (made read-only, copied if given writeable)
_ARRAY_FIELDS = tuple(
    spec.name for spec in fields(SimulationState) if "FloatArray" in str(spec.type)
)
