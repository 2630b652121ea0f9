"""``python -m jointwear`` (and the ``jointwear`` console script)."""

from __future__ import annotations

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
        cli_main()


def _one_line(message, category, filename, lineno, file=None, line=None) -> None:
    sys.stderr.write("warning: " + str(message).replace("\n", " ") + "\n")


if __name__ == "__main__":
    main()
