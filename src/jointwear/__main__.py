"""``python -m jointwear`` (and the ``jointwear`` console script)."""

from __future__ import annotations

import contextlib
import os
import sys


def main() -> None:
    """Install the signal handlers before the command line's imports, then run it."""
    import warnings

    from jointwear.interrupts import exit_code, handling_signals, note

    with handling_signals():
        try:
            with warnings.catch_warnings():  # a library warning while importing: one line
                warnings.showwarning = _one_line
                from jointwear.cli import main as cli_main
        except KeyboardInterrupt as exc:  # Ctrl-C while numpy & co. load: no traceback
            sys.stderr.write(note(exc) + "\n")
            sys.exit(exit_code(exc))
        try:
            cli_main()
        except SystemExit as exc:
            if exc.code in (130, 143):
                _leave_now(exc.code)
            raise


def _leave_now(code: int) -> None:
    """End an interrupted process without the interpreter's finalisation.

    A signal can arrive while an extension (HDF5, numba, BLAS threads) is half-way
    through something; finalising its modules then may abort the process (exit -6
    instead of 130/143). By now the command has cleaned up after itself (staging
    removed, checkpoint kept) and said its one line, so nothing is left to finalise.
    """
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):  # a closed or broken pipe
            stream.flush()
    os._exit(code)


def _one_line(message, category, filename, lineno, file=None, line=None) -> None:
    sys.stderr.write("warning: " + str(message).replace("\n", " ") + "\n")


if __name__ == "__main__":
    main()
