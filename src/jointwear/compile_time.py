"""How long numba spent compiling in this process: compile time apart from run time.

numba compiles a kernel on its first call and keeps the machine code in its on-disk
cache; a process that finds it there only loads it (no compile event). The compiled
modules call :func:`watch_compiles` when they are imported, before any of their
functions is compiled, so :func:`compile_seconds` counts every compilation of the
process (``jointwear warm-up`` compiles them all once per machine and source
version). numba is imported only by that call: a process that never loads a
compiled module never imports it.
"""

from __future__ import annotations

from typing import Any

__all__ = ["compile_seconds", "watch_compiles"]

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
