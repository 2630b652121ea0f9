"""SIGINT and SIGTERM as one exception, so every command cleans up the same way.

The command line installs :func:`handling_signals` first thing (before its heavy
imports): either signal raises :class:`Interrupted` (a ``KeyboardInterrupt``) in the
main thread, every ``finally`` block and staging directory is cleaned up on the way
out, and the process ends with ``interrupted`` (exit status 130) or ``terminated``
(143) on stderr. A checkpointed run adds the command that continues it.

Only the standard library is imported here: the handler must be in place before
numpy, xarray or matplotlib start loading.
"""

from __future__ import annotations

import contextlib
import signal
import sys
import threading
from collections.abc import Iterator
from types import FrameType
from typing import Any

__all__ = [
    "Interrupted",
    "exit_code",
    "handling_signals",
    "last",
    "note",
    "raise_pending",
    "with_resume",
]

_SIGNALS = (signal.SIGINT, signal.SIGTERM)
_NOTES = {signal.SIGINT: "interrupted", signal.SIGTERM: "terminated"}
_last: list[Interrupted] = []
#: the interrupt a signal raised, until the command line has reported it
_pending: list[Interrupted] = []


class Interrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM arrived; ``signum`` says which, ``resume`` how to continue.

    Parameters
    ----------
    signum : int
        The signal number [-] (default SIGINT).
    """

    def __init__(self, signum: int = signal.SIGINT) -> None:
        super().__init__(_NOTES.get(signum, "interrupted"))
        self.signum = signum
        self.resume: str | None = None
        _last.append(self)  # the CLI reads it back where a framework swallowed the exception


def exit_code(exc: BaseException) -> int:
    """128 + the signal number (130 for SIGINT, 143 for SIGTERM).

    Parameters
    ----------
    exc : BaseException
        An :class:`Interrupted` (a plain ``KeyboardInterrupt`` counts as SIGINT).
    """
    return 128 + int(getattr(exc, "signum", signal.SIGINT))


def note(exc: BaseException) -> str:
    """The one line printed on stderr: ``interrupted`` / ``terminated`` (+ how to resume).

    Parameters
    ----------
    exc : BaseException
        An :class:`Interrupted` (its ``resume`` command is appended) or a plain
        ``KeyboardInterrupt``.
    """
    text = _NOTES.get(getattr(exc, "signum", signal.SIGINT), "interrupted")
    resume = getattr(exc, "resume", None)
    return f"{text}; continue with `{resume}`" if resume else text


def with_resume(exc: KeyboardInterrupt, command: str) -> Interrupted:
    """The interrupt ``exc`` carrying the command that continues the interrupted job.

    Parameters
    ----------
    exc : KeyboardInterrupt
        An :class:`Interrupted`, or a plain ``KeyboardInterrupt`` (counted as SIGINT).
    command : str
        E.g. ``jointwear run --resume DIR``, printed on the CLI's one line.
    """
    interrupt = exc if isinstance(exc, Interrupted) else Interrupted()
    interrupt.resume = command
    return interrupt


def last() -> Interrupted | None:
    """The latest :class:`Interrupted` (typer turns it into a plain exit status 130)."""
    return _last[-1] if _last else None


def _raise(signum: int, frame: FrameType | None) -> None:
    # a second signal while the first one is being cleaned up is ignored
    for each in _SIGNALS:
        signal.signal(each, signal.SIG_IGN)
    interrupt = Interrupted(signum)
    _pending[:] = [interrupt]
    raise interrupt


def raise_pending() -> None:
    """Raise the interrupt of a signal whose exception was swallowed on the way.

    A handler's exception raised inside a weakref callback or a ``__del__`` is printed
    and dropped by Python, and the work would go on. Called where work continues (a
    progress report, before publishing output), this stops it there instead.
    """
    if _pending:
        raise _pending.pop()


@contextlib.contextmanager
def handling_signals() -> Iterator[None]:
    """Turn SIGINT/SIGTERM into :class:`Interrupted` for the block; restore the old handlers.

    A signal the parent process set to be ignored (``nohup``, background jobs) stays
    ignored. An interrupt Python cannot raise (inside a weakref callback or ``__del__``)
    is not printed as a traceback: it stays pending for :func:`raise_pending`. Outside
    the main thread this does nothing.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = {each: signal.getsignal(each) for each in _SIGNALS}
    unraisable = sys.unraisablehook
    _last.clear()
    _pending.clear()
    for each, handler in previous.items():
        if handler is not signal.SIG_IGN:
            signal.signal(each, _raise)

    def pending_not_printed(info: Any) -> None:
        if not isinstance(info.exc_value, Interrupted):
            unraisable(info)

    sys.unraisablehook = pending_not_printed
    try:
        yield
    finally:
        sys.unraisablehook = unraisable
        for each, handler in previous.items():
            signal.signal(each, handler if handler is not None else signal.SIG_DFL)
