"""The ``jointwear`` command line.

Each command lives in its own module and registers itself on :data:`app`.
Errors the user can fix (:class:`~jointwear.errors.JointwearError`, bad
options) end with a one-line message on stderr and exit status 2; anything
else is an internal error (exit 1). ``--debug`` shows the traceback.
"""

from __future__ import annotations

import copy
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
from jointwear.cli import sensitivity_cmd  # noqa: F401  isort: skip
from jointwear.cli import materials_cmd  # noqa: F401  isort: skip
from jointwear.cli import warm_up_cmd  # noqa: F401  isort: skip

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
            _say(f"warning: {text}")

    return show


#: options that name a file or directory: an empty value would silently mean "."
_PATH_OPTIONS = ("--out", "--resume", "--csv")


def _empty_path_option(args: list[str]) -> str | None:
    """The first path option given an empty value (``--out ''``), else ``None``."""
    for index, arg in enumerate(args):
        if arg == "--":
            break
        if arg in _PATH_OPTIONS and index + 1 < len(args) and not args[index + 1].strip():
            return arg
        name, equals, value = arg.partition("=")
        if equals and name in _PATH_OPTIONS and not value.strip():
            return name
    return None


def _click_command(args: list[str]):
    """The app as a click command; where ``args`` start with a command's name (after
    flags other than help), the app of that command alone: the parameters of every
    command built from its signature would cost ~0.03 s of each start."""
    name = next((arg for arg in args if not arg.startswith("-")), None)
    ahead = args[: args.index(name)] if name is not None else args
    chosen = [
        info
        for info in app.registered_commands
        if (info.name or typer.main.get_command_name(info.callback.__name__)) == name
    ]
    if len(chosen) != 1 or {"-h", "--help"} & set(ahead):
        return typer.main.get_command(app)
    alone = copy.copy(app)
    alone.registered_commands = chosen
    return typer.main.get_command(alone)


def _say(text: str) -> None:
    err_console.print(text, markup=False, highlight=False, soft_wrap=True)


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``jointwear`` console script."""
    import warnings

    from jointwear.interrupts import handling_signals

    args = list(sys.argv[1:] if argv is None else argv)
    debug = "--debug" in args
    with handling_signals(), warnings.catch_warnings():
        warnings.showwarning = _one_line_warnings(debug)
        _main(args, debug)


def _main(args: list[str], debug: bool) -> None:
    from jointwear.interrupts import exit_code, last, note, raise_pending

    earlier = last()  # an interrupt of an earlier in-process call is not this one's
    empty = _empty_path_option(args)
    if empty is not None:
        _say(f"error: {empty}: empty path")
        sys.exit(2)
    command = _click_command(args)
    try:
        code = command.main(args=args, prog_name="jointwear", standalone_mode=False)
        if code == 130:  # typer returns 130 for a KeyboardInterrupt inside a command
            interrupt = last() or KeyboardInterrupt()
            _say(note(interrupt))
            sys.exit(exit_code(interrupt))
        if isinstance(code, int) and code:
            sys.exit(code)
        raise_pending()  # a signal whose exception was swallowed still ends as interrupted
    except JointwearError as exc:
        if debug:
            raise
        _say(f"error: {exc}")
        sys.exit(2)
    except _EXIT as exc:
        # typer turns a KeyboardInterrupt (Ctrl-C, or SIGTERM via jointwear.interrupts)
        # into Exit(130) raised from it
        if isinstance(exc.__cause__, KeyboardInterrupt):
            _say(note(exc.__cause__))
            sys.exit(exit_code(exc.__cause__))
        sys.exit(exc.exit_code)
    except _USAGE_ERRORS as exc:
        if debug:
            raise
        message = (getattr(exc, "format_message", None) or exc.__str__)().replace("\n", " ")
        if message.strip():  # empty for a bare `jointwear` (the help was shown)
            _say(f"error: {message}")
        sys.exit(2)
    except _ABORT as exc:
        cause = exc.__cause__ or exc.__context__
        _say(note(cause) if isinstance(cause, KeyboardInterrupt) else "aborted")
        sys.exit(exit_code(cause) if isinstance(cause, KeyboardInterrupt) else 130)
    except KeyboardInterrupt as exc:
        _say(note(exc))
        sys.exit(exit_code(exc))
    except Exception as exc:
        interrupt = _interrupt_behind(exc, earlier)
        if interrupt is not None:  # a signal arrived inside code that wrapped it (an import)
            _say(note(interrupt))
            sys.exit(exit_code(interrupt))
        if debug:
            raise
        _say(f"internal error: {type(exc).__name__}: {exc} (rerun with --debug for the traceback)")
        sys.exit(1)


def _interrupt_behind(exc: BaseException, earlier: object) -> KeyboardInterrupt | None:
    """The interrupt an exception wraps (e.g. a signal during a class definition), if any.

    Parameters
    ----------
    exc : BaseException
        The exception that ended the command.
    earlier : Interrupted or None
        The latest interrupt before the command started (not counted).
    """
    from jointwear.interrupts import last

    seen: set[int] = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, KeyboardInterrupt):
            return exc
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    latest = last()
    return latest if latest is not earlier else None
