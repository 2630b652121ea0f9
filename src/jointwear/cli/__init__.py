"""The ``jointwear`` command line.

Each command lives in its own module and registers itself on :data:`app`.
Errors the user can fix (:class:`~jointwear.errors.JointwearError`, bad
options) end with a one-line message on stderr and exit status 2; anything
else is an internal error (exit 1). ``--debug`` shows the traceback.
"""

from __future__ import annotations

import sys

import typer

from jointwear.cli.common import app, err_console
from jointwear.errors import JointwearError

# command modules register themselves on ``app`` when imported
from jointwear.cli import contact_cmd  # noqa: F401  isort: skip
from jointwear.cli import dynamics_cmd  # noqa: F401  isort: skip
from jointwear.cli import measure_cmd  # noqa: F401  isort: skip
from jointwear.cli import compare_cmd  # noqa: F401  isort: skip
from jointwear.cli import calibrate_cmd  # noqa: F401  isort: skip
from jointwear.cli import run_cmd  # noqa: F401  isort: skip
from jointwear.cli import reproduce_cmd  # noqa: F401  isort: skip
from jointwear.cli import compare_models_cmd  # noqa: F401  isort: skip
from jointwear.cli import sweep_cmd  # noqa: F401  isort: skip
from jointwear.cli import life_cmd  # noqa: F401  isort: skip
from jointwear.cli import materials_cmd  # noqa: F401  isort: skip

__all__ = ["app", "main"]



def _exception_types() -> tuple[tuple[type, ...], tuple[type, ...], tuple[type, ...]]:
    """Exit, abort and usage-error types of whichever click the installed typer uses.

    typer >= 0.20 parses with its own copy of click (``typer._click``) and does not
    install click; older typer uses click itself. Catch both where both exist.
    """
    exits: list[type] = [getattr(typer, "Exit", SystemExit)]
    aborts: list[type] = [getattr(typer, "Abort", KeyboardInterrupt)]
    usage: list[type] = [t for t in (getattr(typer, "TyperException", None),) if t]
    try:
        import click
    except ImportError:
        pass
    else:
        exits.append(click.exceptions.Exit)
        aborts.append(click.exceptions.Abort)
        usage.append(click.ClickException)
    return tuple(exits), tuple(aborts), tuple(usage)


_EXIT, _ABORT, _USAGE_ERRORS = _exception_types()


def _one_line_warnings(debug: bool):
    """Warnings as one ``warning: ...`` line each on stderr, each message once."""
    shown: set[str] = set()

    def show(message, category, filename, lineno, file=None, line=None) -> None:
        text = str(message).replace("\n", " ")
        if debug:
            text += f" [{category.__name__} at {filename}:{lineno}]"
        if text not in shown:
            shown.add(text)
            err_console.print(f"warning: {text}", markup=False, highlight=False, soft_wrap=True)

    return show


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``jointwear`` console script."""
    import warnings

    args = list(sys.argv[1:] if argv is None else argv)
    debug = "--debug" in args
    with warnings.catch_warnings():
        warnings.showwarning = _one_line_warnings(debug)
        _main(args, debug)


def _main(args: list[str], debug: bool) -> None:
    command = typer.main.get_command(app)
    try:
        code = command.main(args=args, prog_name="jointwear", standalone_mode=False)
        if isinstance(code, int) and code:  # e.g. 130 after Ctrl-C inside a command
            if code == 130:
                err_console.print("interrupted")
            sys.exit(code)
    except JointwearError as exc:
        if debug:
            raise
        err_console.print(f"error: {exc}", markup=False, highlight=False, soft_wrap=True)
        sys.exit(2)
    except _EXIT as exc:
        sys.exit(exc.exit_code)
    except _USAGE_ERRORS as exc:
        if debug:
            raise
        message = (getattr(exc, "format_message", None) or exc.__str__)().replace("\n", " ")
        if message.strip():  # empty for a bare `jointwear` (the help was shown)
            err_console.print(f"error: {message}", markup=False, highlight=False, soft_wrap=True)
        sys.exit(2)
    except _ABORT:
        err_console.print("aborted")
        sys.exit(130)
    except KeyboardInterrupt:
        sys.exit(130)
    except Exception as exc:
        if debug:
            raise
        err_console.print(
            f"internal error: {type(exc).__name__}: {exc} (rerun with --debug for the traceback)",
            markup=False,
            highlight=False,
            soft_wrap=True,
        )
        sys.exit(1)
