"""Shared pieces of the CLI: the app, consoles, common options, JSON output."""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

if TYPE_CHECKING:
    from rich.console import Console

__all__ = [
    "ConfigArg",
    "DebugOpt",
    "JsonOpt",
    "MaxMemoryOpt",
    "QuietOpt",
    "SetOpt",
    "TimeLimitOpt",
    "UnitsOpt",
    "app",
    "console",
    "emit_json",
    "err_console",
]

app = typer.Typer(
    name="jointwear",
    help="Wear of planar revolute joints with clearance (NLCP / Winkler / Hertz + Archard).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    context_settings={"help_option_names": ["-h", "--help"]},
)


class _Console:
    """A rich :class:`~rich.console.Console` made when first used: a command that prints
    only JSON never imports rich (~0.035 s of a process's start)."""

    def __init__(self, **options: Any) -> None:
        self._options = options
        self._made: Console | None = None

    def made(self) -> Console:
        """The console itself, made on the first call."""
        if self._made is None:
            from rich.console import Console

            self._made = Console(**self._options)
        return self._made

    def __getattr__(self, name: str) -> Any:
        return getattr(self.made(), name)

    # (rich's live display enters its console: special methods are looked up on the type)
    def __enter__(self) -> Console:
        return self.made().__enter__()

    def __exit__(self, *exc: object) -> None:
        self.made().__exit__(*exc)


console = _Console(highlight=False)
err_console = _Console(stderr=True, highlight=False)

ConfigArg = Annotated[Path, typer.Argument(help="Config file (TOML).", show_default=False)]
SetOpt = Annotated[
    list[str] | None,
    typer.Option(
        "--set",
        help="Override a config value: section.key=VALUE "
        '(units allowed, e.g. joint.clearance="0.2 mm").',
    ),
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print exactly one JSON object on stdout.")]
MeasuredArg = Annotated[
    Path,
    typer.Argument(
        help="Measured inner-surface points: CSV with an 'x,y' header (units in brackets, "
        "e.g. 'x \\[mm],y \\[mm]') or two whitespace-separated columns.",
        show_default=False,
    ),
]
ThresholdOpt = Annotated[
    float, typer.Option("--threshold", help="Wear width threshold, fraction of the peak.")
]
UnitsOpt = Annotated[
    str | None,
    typer.Option("--units", help="Length unit of columns without one (default m), e.g. mm."),
]
DebugOpt = Annotated[bool, typer.Option("--debug", help="Show tracebacks.")]
QuietOpt = Annotated[bool, typer.Option("--quiet", "-q", help="No progress bar.")]
MaxMemoryOpt = Annotated[
    str | None,
    typer.Option(
        "--max-memory",
        help='Refuse work whose arrays would need more memory than this, e.g. "16 GiB" '
        "(default: JOINTWEAR_MAX_MEMORY, else half the RAM, at most 8 GiB).",
        show_default=False,
    ),
]
TimeLimitOpt = Annotated[
    str | None,
    typer.Option(
        "--time-limit",
        help='Stop with exit status 2 after this wall-clock time, e.g. "2 h" (a bare number '
        "is seconds); checked between revolutions (run) or cases (sweep, life). A "
        "checkpointed run or a sweep can continue with --resume.",
        show_default=False,
    ),
]


@app.callback()
def _root(debug: DebugOpt = False) -> None:
    """Wear of planar revolute joints with clearance."""


def emit_json(data: dict[str, Any]) -> None:
    """Print one JSON object on stdout (strict JSON: non-finite numbers become null)."""
    from jointwear.io import json_ready

    sys.stdout.write(json.dumps(json_ready(data), allow_nan=False) + "\n")
    sys.stdout.flush()
