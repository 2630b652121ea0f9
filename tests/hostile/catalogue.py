"""Render the hostile-input suite into ``docs/bad-input.md``.

Run ``python -m tests.hostile.catalogue`` from the repository root after adding or
changing a case: it imports every ``tests/hostile/test_*.py`` module, collects its
``CASES`` (:class:`~tests.hostile.harness.Bad`) and the docstrings of its other
tests, and writes the page grouped by area. ``tests/hostile/test_catalogue_doc.py``
fails while the page is out of date with the suite.
"""

from __future__ import annotations

import importlib
import inspect
import shlex
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

from tests.hostile.harness import REPO, Bad, sweep_toml

PAGE = REPO / "docs" / "bad-input.md"
FOLDER = Path(__file__).resolve().parent

#: section of the page -> the case areas it holds (in page order)
SECTIONS: dict[str, tuple[str, ...]] = {
    "Config files": ("config", "run"),
    "Numbers and units": ("numbers", "units"),
    "Resources": ("resources",),
    "Time": ("time",),
    "Network": ("network",),
    "Data files": ("data",),
    "Output": ("output",),
    "Files": ("files", "file"),
    "Signals": ("signals", "signal"),
    "Checkpoints": ("checkpoints", "checkpoint"),
    "Warnings": ("warnings", "warning"),
    "API": ("api",),
    "Sweeps": ("sweep", "sweeps"),
    "CLI": ("cli",),
}
AREAS = {area: section for section, areas in SECTIONS.items() for area in areas}
#: longest argument shown whole in a command
LONGEST_ARGUMENT = 48
#: longest file content shown whole
LONGEST_FILE = 120

INTRO = """\
# Bad input: what jointwear says, and how it exits

Every mistake a user can make ends the same way: **one line on stderr** that starts with
`error:` and names the config key, option or file and the reason, **exit status 2**, no
traceback, and **nothing written** into `--out` (results are staged and moved in only when
complete; a run that fails mid-way removes its checkpoint). Exit status **1** is reserved for
internal errors (bugs): `internal error: <type>: <message> (rerun with --debug for the
traceback)`. `--debug` (before the command, `jointwear --debug run ...`) shows the full
traceback instead of the one-line message. A line break inside a message (a file name with a
newline) is shown as `\\n`, so the message stays one line.

| exit status | meaning |
|---|---|
| 0 | success (a sweep also exits 0 when some cases failed; they are listed, see below) |
| 1 | internal error: please report it, with the `--debug` traceback |
| 2 | bad input, physics the model cannot handle, or the `--time-limit` reached (`JointwearError`) |
| 130 | interrupted (Ctrl-C, SIGINT); a checkpointed run can continue with `--resume` |
| 143 | terminated (SIGTERM, e.g. a batch system's time limit); as 130 |

The error types (all in `jointwear.errors`, all subclasses of `JointwearError`):
`ConfigError` (a config value or option), `DataError` (a data, result, checkpoint or sweep
directory file), `GeometryError` (impossible joint geometry), `ContactError` /
`ConvergenceError` (no contact solution / an iteration did not converge), `MechanismError`
(the mechanism cannot run), `WearThroughError` (a calibration whose trial values wear
through the bushing wall), `TimeLimitError` (the `--time-limit` passed). The Python API
(`load_config`, `Config.replace`, `Config.to_toml`) raises these types only.

Wear that goes through the wall is **not** an error of a run: the wall is one of the
`[life]` limits, so the run ends at the revolution of wear-through with its results written
(exit 0, `stopped_by = "wall_thickness"` in `run --json`).

In a **sweep**, a bad sweep file, unknown key or unreadable value stops the whole sweep before
anything runs (exit 2). A case whose values are fine one by one but not together (e.g. a crank
longer than the rod), and a case whose run fails (no convergence ...), is
recorded in `cases.csv` with `status = failed` and its one-line `error`; the other cases run.

## Interrupting a command

Ctrl-C (SIGINT) and SIGTERM end any command the same way: the files it was writing are
removed, nothing half-written is left in `--out`, and one line goes to stderr:
`interrupted` (exit status 130) or `terminated` (143). The handler is installed before the
command line imports numpy and friends, so even a Ctrl-C right after pressing Enter prints
that one line and no traceback; a second signal while the first is being cleaned up is
ignored. A run with checkpoints (`jointwear run CONFIG --out DIR --checkpoint-every K`)
says how to continue:

```text
interrupted; continue with `jointwear run --resume DIR`
```

and `DIR` then holds exactly `checkpoint.toml` and `checkpoint.npz`. The resumed run
computes the same numbers, bit for bit, as a run that was never interrupted; this also
holds after SIGKILL (the state file is replaced atomically, so it is always the previous
or the next complete checkpoint). An interrupted sweep names its
own resume command the same way (`jointwear sweep --resume DIR`); its finished cases are
kept and not run again. A signal the parent process set to be ignored (a background job
of a non-interactive shell ignores Ctrl-C) stays ignored.

## Output: all or nothing

Every command that writes files (`run`, `plot`, `compare`, `compare-models`,
`dynamics --csv`, `sweep`, `life`, `reproduce`) checks its output path before any work:

* `--out ''` (an empty path, which would otherwise mean the current folder) is refused;
  so are an `--out` that is an existing file, one below a file, and a dangling link.
* Inside an existing `--out`, an entry the command would replace must be a regular file
  (or a folder where a folder goes): a **symbolic link** or a special file (pipe, device,
  socket) with the name of an output is refused, so no command ever writes or deletes
  through a link to somewhere else. A sweep, `life` and `reproduce` check their whole
  `cases/` (`figures/`, `results/`) tree the same way before a case runs.
* A folder named like an output file (`result.nc/`) or a file named like an output
  folder (`plots`) is refused rather than replaced.
* An `--out` that is itself a link to a folder is followed (the files go into the folder,
  the link stays).

The files are written into a hidden staging folder on the same file system (next to a
new `--out`, inside an existing one) and then published at once: a new `--out` appears
with one rename, complete; into an existing folder (a rerun, a checkpointed run, the
current folder) the files are moved in one by one, and if a move fails the ones already
moved are put back, so the folder is as it was. An existing folder itself is never
replaced (it keeps its other files, permissions and mount). On any
failure every folder the command created is removed again. A full disk or a read-only
file system is one line naming the folder, e.g.
`error: --out: results/run1: no space left on device` or `...: read-only file system`
(exit 2). Results are serialised to netCDF in memory and written as plain bytes, so a
disk that fills up half-way through `result.nc` cannot leave an HDF5 file handle open
(which used to crash the interpreter at exit).

## Input files

Every file jointwear reads (configs and sweep files, measured points, load histories,
`result.nc`, checkpoints) goes through one reader (`jointwear.io.read_input` /
`check_input`):

* it must be a **regular file** (or a link to one): a folder, a named pipe (FIFO), a
  device such as `/dev/zero` or a socket is refused by its kind without being opened, so
  nothing waits forever on a pipe;
* text files are limited to **64 MiB** (`error: FILE: TOML file too large (65.0 MiB >
  64 MiB; raise the limit with JOINTWEAR_MAX_INPUT_MB=N)`); set the environment variable
  `JOINTWEAR_MAX_INPUT_MB` to raise (or lower) it;
* text is **UTF-8**, with or without a byte-order mark (spreadsheet programs write one);
  anything else (UTF-16, Latin-1, binary) is `not a text file`;
* TOML may nest tables and arrays at most **32 levels** deep
  (`error: FILE: nested more than 32 levels deep`); deeper input would otherwise exhaust
  Python's recursion limit inside the TOML parser.

A netCDF file that is not a jointwear result (another program's, truncated, empty, a
config renamed `.nc`) given to `plot` or `compare` is refused naming the file.

## Checkpoints

`checkpoint.npz` carries a SHA-256 checksum of its own arrays and the digest of the
configuration in `checkpoint.toml`. `jointwear run --resume DIR` refuses, with one line
naming the checkpoint file (never a config key), a state that

* was edited, truncated or is not a checkpoint at all (`damaged checkpoint (its checksum
  does not match its contents)`, `not a readable checkpoint`);
* belongs to another configuration, e.g. swapped in from another run's folder, or whose
  `checkpoint.toml` was edited (`belongs to a different configuration than ...`);
* does not fit its configuration even though it is intact: per-node arrays of another
  length than `contact.nodes`, a revolution outside `0..simulation.revolutions`,
  non-finite values, update records or saved profiles that do not run forward to the
  state's revolution (`inconsistent checkpoint (...)`).

If the disk fills up while a run writes a checkpoint, the run stops (exit 2) with one
line, `error: DIR/checkpoint.npz: cannot write the checkpoint (no space left on device);
the previous checkpoint is kept: make room, then ...` followed by the resume command, and
the previous checkpoint stays usable. The refused checkpoint is left in place. A checkpoint
written by an older jointwear (without a checksum) is refused naming its format;
start that run again.

## Warnings

Warnings (the physics ones, such as contact loss or wear past the clearance, and any
library's) are printed as one line each, `warning: ...`, never with a source line, and
each message once per command; this also holds for a warning raised while the command
line is still importing. Warnings of the cases of a sweep are recorded with each case
(`cases/<case>.json`) instead of being printed. Progress bars (`run`, `sweep`, `life`,
`reproduce`) only appear on a terminal and are erased when the command ends, so a failing
command leaves its `error:` line as the only line on stderr.

## Numbers, units, memory and time

* **Numbers** are finite and really numbers: `true` is refused where a number is expected
  (`contact.exponent = true` does not run with n = 1), an integer of hundreds of digits is
  refused with one line, and no SI magnitude beyond 10^100 is accepted. Counts have upper
  bounds (`simulation.revolutions` and the update and checkpoint intervals at most 10^9).
  A direction angle given as an option (`--azimuth`, `--align`, `--angle-offset`) lies
  within two turns either way; config angles within +-4 pi.
* **Unit expressions** are read by one function (`jointwear.units.parse_quantity`) for
  config values, options, sweep values and the unit of every column header. pint evaluates
  them as arithmetic, so they are bounded first: at most 200 characters, numbers of at
  most 40 digits, exponents that are plain numbers within +-12, and no exponent of an
  exponent (`9**9**9 m` would otherwise compute a number of 370 million digits).
* **Memory** is estimated from the sizes before anything is allocated: a run's
  `contact.nodes x simulation.steps_per_revolution` arrays and saved profiles, a sweep's or
  life study's cases (at most 10^6), a measured profile's `--nodes`. Above the limit the
  command refuses, naming the keys and the estimate. The limit is `--max-memory SIZE`
  (e.g. `"16 GiB"`), else the environment variable `JOINTWEAR_MAX_MEMORY`, else half the
  machine's memory, at most 8 GiB.
* **Time**: every solver loop has an iteration bound; `dynamics.max_step` is refused when
  the contact-impact integrator would take more than 10^7 steps. `--time-limit` (`run`,
  `sweep`, `life`; e.g. `"2 h"`) ends the job between revolutions or cases with
  `error: time limit of N s reached after R of T revolutions`, exit status 2; a
  checkpointed run keeps its checkpoint, a sweep its finished cases, and the message names
  the `--resume` command.
* **Network**: `sweep --scheduler tcp://host:port` opens a connection and asks the
  scheduler for its identity (dask's handshake) within 10 s; a server that accepts the
  connection but never answers gives `no dask scheduler answered at ... within 10 s`.
* **Result files** given to `plot` or `compare` must hold wear: `wear_depth` over
  `(revolution, theta)` and `peak_wear_depth`, in metres, finite and non-negative.
"""

CATALOGUE = """\
## The catalogue

Generated from `tests/hostile/` by `python -m tests.hostile.catalogue` (a test fails while
this page is out of date). Each row is a test case: the command, and fragments the one-line
message on stderr must contain (exit status 2, nothing written). `paper.toml` stands for the
paper's joint with the parameter set's round values (`tests/data/paper_joint.toml`, Table 3,
Winkler, 120 rpm), `DIR` for a directory, `out` for the `--out` directory; files the case
writes first are listed with their content. Below each table, the checks that are not one
command. Checks marked *slow* run with `python -m pytest -m slow` only.
"""

OUTRO = """\
## Where the checks live

* Config values: `jointwear.config` (pydantic models; units through `jointwear.units.to_si`,
  which reads text with `jointwear.units.parse_quantity`). Messages start with the dotted
  key; unknown keys and choices get a did-you-mean.
* Options: each command checks its own options before doing any work.
* Memory and time: `jointwear.resources` (estimates, `--max-memory`, `--time-limit`).
* Data files: `jointwear.io.read_input` / `check_input` (file kind, size, encoding) under
  `jointwear.results.read_result` (netCDF; content by
  `jointwear.results.check_result_content`), `jointwear.measurement.io.read_points` (CSV),
  `jointwear.checkpoint.read_state` and `check_state` (checkpoints),
  `jointwear.workflows.sweep.load_sweep` (sweep files), `jointwear.config.read_toml` (TOML depth).
* Output: `jointwear.io.check_out` (before any work) and `jointwear.io.staged_output`
  (publishing); `jointwear.io.check_tree` for folders filled case by case.
* Signals: `jointwear.interrupts` (installed by `python -m jointwear` and the console
  script before the heavy imports).
* Physics during a run: the contact solver (`ContactError`, `ConvergenceError`), the contour
  update (`WearThroughError`, which names `joint.bushing_thickness`), the mechanism
  (`MechanismError`; `dynamics.strict = true` turns contact-loss warnings into errors).
* `tests/test_fuzz.py` drives random configurations through the whole simulation and asserts
  that nothing but these errors escapes and that every metric of a finished run is finite.
"""


@dataclass(frozen=True)
class FreeTest:
    """A test of the suite that is not one command: its name, what it checks, where."""

    name: str
    doc: str
    module: str
    slow: bool
    area: str


def modules() -> list[ModuleType]:
    """Every ``tests/hostile/test_*.py`` module, in file-name order."""
    return [
        importlib.import_module(f"tests.hostile.{path.stem}")
        for path in sorted(FOLDER.glob("test_*.py"))
    ]


def _slow(func: Callable) -> bool:
    return any(mark.name == "slow" for mark in getattr(func, "pytestmark", []))


def collect(found: Iterable[ModuleType]) -> tuple[list[Bad], list[FreeTest]]:
    """The cases and the documented free-form tests of ``found`` modules."""
    cases: list[Bad] = []
    free: list[FreeTest] = []
    for module in found:
        cases.extend(getattr(module, "CASES", []))
        short = module.__name__.rsplit(".", 1)[-1]
        # a module's tests belong to the area of its name, unless FREE_AREAS says otherwise
        default = short.removeprefix("test_")
        areas = getattr(module, "FREE_AREAS", {})
        for name, func in vars(module).items():
            if not (name.startswith("test_") and inspect.isfunction(func)):
                continue
            if "case" in inspect.signature(func).parameters or not func.__doc__:
                continue  # the runner of CASES, or an undocumented test
            doc = " ".join(func.__doc__.strip().split("\n\n")[0].split())
            area = areas.get(name, default if default in AREAS else "cli")
            free.append(FreeTest(name, doc, short, _slow(func), area))
    ids = [case.id for case in cases]
    duplicates = sorted({i for i in ids if ids.count(i) > 1})
    if duplicates:
        raise ValueError(f"case ids used twice: {', '.join(duplicates)}")
    unknown = sorted({item.area for item in [*cases, *free]} - set(AREAS))
    if unknown:
        raise ValueError(f"areas without a section of the page: {', '.join(unknown)}")
    return cases, free


def _argument(text: str) -> str:
    text = text.replace("{paper}", "paper.toml").replace("{out}", "out")
    text = text.replace("{tmp}/", "").replace("{tmp}", "DIR")
    if len(text) > LONGEST_ARGUMENT:
        text = f"{text[:20]}...{text[-12:]} ({len(text)} chars)"
    return shlex.quote(text)


def command(case: Bad) -> str:
    """The case's command line as a user would type it."""
    return "jointwear " + " ".join(_argument(a) for a in case.argv)


def _file(name: str, content: str | bytes) -> str:
    if content in ("@tiny", "@config"):
        return f"{name} (the paper's joint)"
    if content in ("@result",):
        return f"{name} (a result)"
    if isinstance(content, str) and content.startswith("@"):
        return f"{name} ({content[1:].replace('-', ' ')})"
    if isinstance(content, bytes):
        return f"{name} ({len(content)} bytes)"
    base = sweep_toml("")
    if content.startswith(base):  # the harness's sweep on the paper's joint: what it adds
        content = "(sweep of tiny.toml) " + content[len(base) :]
    flat = content.replace("\n", " ⏎ ").strip().removesuffix("⏎").strip()
    if len(flat) > LONGEST_FILE:
        flat = f"{flat[: LONGEST_FILE - 30]}... ({len(content)} chars)"
    return f"{name}: {flat}"


def _code(text: str) -> str:
    """``text`` as a Markdown code span in a table cell."""
    text = text.replace("|", "\\|")
    fence = "``" if "`" in text else "`"
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def _row(case: Bad) -> str:
    files = "<br>".join(_code(_file(n, c)) for n, c in case.files.items())
    expect = "<br>".join(_code(fragment) for fragment in case.expect)
    return f"| `{case.id}` | {_code(command(case))} | {files} | {expect} |"


def render(cases: list[Bad], free: list[FreeTest]) -> str:
    """The whole page."""
    parts = [INTRO, CATALOGUE]
    total = len(cases)
    parts.append(f"{total} cases and {len(free)} further checks in all.\n")
    for section, areas in SECTIONS.items():
        rows = [case for case in cases if case.area in areas]
        others = [test for test in free if test.area in areas]
        if not rows and not others:
            continue
        lines = [f"### {section}", ""]
        if rows:
            lines += [
                "| case | command | files | stderr contains |",
                "|---|---|---|---|",
                *(_row(case) for case in rows),
                "",
            ]
        for test in others:
            mark = " *(slow)*" if test.slow else ""
            lines.append(f"* {test.doc}{mark} (`{test.module}.py::{test.name}`)")
        if others:
            lines.append("")
        parts.append("\n".join(lines))
    parts.append(OUTRO)
    return "\n".join(parts)


def page() -> str:
    """The page for the suite as it is now."""
    cases, free = collect(modules())
    return render(cases, free)


def main(argv: list[str] | None = None) -> int:
    """Write ``docs/bad-input.md`` (``--check``: only say whether it is up to date)."""
    args = sys.argv[1:] if argv is None else argv
    text = page()
    if "--check" in args:
        current = PAGE.read_text(encoding="utf-8") if PAGE.exists() else ""
        if current != text:
            print(f"{PAGE} is out of date; run python -m tests.hostile.catalogue")
            return 1
        return 0
    PAGE.write_text(text, encoding="utf-8")
    print(f"wrote {PAGE}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
