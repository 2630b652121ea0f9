"""How long numba spent compiling in this process: compile time apart from run time.

numba compiles a kernel on its first call and keeps the machine code in its on-disk
cache; a process that finds it there only loads it (no compile event). The compiled
modules call :func:`watch_compiles` when they are imported, before any of their
functions is compiled, so :func:`compile_seconds` counts every compilation of the
process (``jointwear warm-up`` compiles them all once per machine and source
version). numba is imported only by that call: a process that never loads a
compiled module never imports it. A :class:`Clock` keeps a piece of work's wall time
and the compiling inside it apart.
"""

from __future__ import annotations

import time
from typing import Any

__all__ = ["Clock", "compile_seconds", "watch_compiles"]

_listener: Any = None


def watch_compiles() -> None:
    """Start counting numba's compile time (once per process; numba must import)."""
    global _listener
    if _listener is None:
        from numba.core import event

        _listener = event.TimingListener()
        event.register("numba:compile", _listener)


def compile_seconds() -> float:
    """Wall seconds numba spent compiling in this process so far [s] (0: none)."""
    if _listener is None or not _listener.done:
        return 0.0
    return float(_listener.duration)


class Clock:
    """Wall-clock seconds and numba's compile seconds since the clock was made [s]."""

    def __init__(self) -> None:
        self.started = time.perf_counter()
        self.compiled_before = compile_seconds()

    def elapsed(self) -> float:
        """Wall-clock seconds since the start [s]."""
        return time.perf_counter() - self.started

    def compiling(self) -> float:
        """Seconds numba spent compiling since the start [s]."""
        return compile_seconds() - self.compiled_before

    def times(self, compiled_earlier: float = 0.0) -> dict[str, float]:
        """A run's times for its record (:class:`~jointwear.record.RunRecord`) [s].

        Parameters
        ----------
        compiled_earlier : float
            Compile seconds of the run's work before the clock started (its setup) [s].

        Returns
        -------
        dict
            ``runtime`` (since the start), ``compile_time`` (``compiled_earlier`` and
            the compiling since the start) and ``compile_in_runtime`` (the latter) [s].
        """
        compiling = self.compiling()
        return {
            "runtime": self.elapsed(),
            "compile_time": compiling + compiled_earlier,
            "compile_in_runtime": compiling,
        }
