"""Start-up of the command line: whole `jointwear run` processes, one revolution of the paper.

Run from the repository root::

    python benchmarks/bench_startup.py                    # ~1 minute
    python benchmarks/bench_startup.py --quick            # fewer repeats
    python benchmarks/bench_startup.py --baseline REV     # also the code of git revision REV

Each command runs as a fresh process, the commands taking turns after one warm-up run
each; the table gives the median wall time. With ``--baseline`` every command also runs
on the ``src`` of revision REV (unpacked from git) in the same turns, and the ratio is the
median of the run-by-run ratios. The last columns list the heavy libraries the command
loaded, and with ``--baseline`` those the baseline loaded (one extra, untimed run each).
Every process starts from bytecode, as an installed package does (``benchlib.environment``).

The processes share a memo of quantity texts of their own (``jointwear.quantity_memo``, in
the run's temporary folder), filled by the warm-up runs: a run of the paper's config then
imports no pint, and no dask where dask is installed. The row ``fresh install`` starts each
run from an empty memo folder (removed first), as a fresh install's first run does: the
memo begins from the package's seed of pint's factors for the examples' units. The row
``first run, units read before`` starts each run from a memo of the paper's units alone
(made without the seed, its texts dropped, copied in first). The row ``no memo`` runs with
the memo turned off (``JOINTWEAR_CACHE_DIR=''``): the seed only. The row ``a unit new to
it`` gives the clearance in a unit the seed lacks (``50 um``), with the memo turned off: pint
reads it, and imports ``dask.base`` where dask is installed.

Measured ``--baseline fd952ba --repeat 9`` with dask installed, on the shared 2-core
machine when quiet (load average 0.4-1.1), ratio = median of the run-by-run ratios:

==========================================  ===============
one revolution, paper case                  dask installed
==========================================  ===============
plain runs (memo of the texts)              0.75-0.86
``--out DIR --no-plots``                    0.54
fresh install (empty memo folder)           0.71
first run, units read before                0.72
no memo (turned off: the seed only)         0.80
no memo, a unit new to it (pint, dask.base) 1.20
nlcp run, median wall now / fd952ba         0.698 / 0.885 s
==========================================  ===============

(fd952ba hid dask from pint and xarray by editing ``sys.modules``.) A ``--out`` run
writes a single joint's result.nc with h5netcdf from the plain arrays
(``jointwear.results.netcdf_file``): no xarray, pandas or dask. docs/performance.md,
*Start-up*, has every row.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import tempfile
from importlib.util import find_spec
from pathlib import Path

from benchlib import (
    PAPER,
    SRC,
    Table,
    checkout,
    describe_machine,
    environment,
    interleaved,
    median,
    paired_ratio,
)

sys.path.insert(0, str(SRC))
from jointwear.contact.solver import COMPILED_KERNEL_SOLVES
from jointwear.quantity_memo import ENVIRONMENT as MEMO
from jointwear.quantity_memo import FILE_NAME

MODELS = ("nlcp", "winkler", "asymmetric-winkler", "hertz")
HEAVY = (
    "pint", "numba", "xarray", "pandas", "dask", "dask.array", "distributed", "h5py",
    "matplotlib",
)  # fmt: skip
#: target of a one-revolution run, whole process [s]
TARGET = 0.8
#: the paper's clearance in a unit the package's seed of pint's factors does not hold
NEW_UNIT = "50 um"


def run_command(*options: str) -> list[str]:
    return [
        sys.executable, "-m", "jointwear", "run", str(PAPER),
        "--set", "simulation.revolutions=1", "--json", "-q", *options,
    ]  # fmt: skip


def heavy_modules(command: list[str], env: dict[str, str]) -> str:
    """The heavy libraries loaded by ``command`` (``python -m jointwear ...`` or ``-c``)."""
    if command[1] == "-c":
        code = command[2]
    else:
        code = f"from jointwear.cli import main\nmain({command[3:]!r})"
    with tempfile.TemporaryDirectory() as folder:
        report = Path(folder) / "modules.json"
        indented = code.replace("\n", "\n    ")
        script = (
            f"import json, sys\ntry:\n    {indented}\nfinally:\n"
            f"    open({str(report)!r}, 'w').write(json.dumps(sorted(sys.modules)))\n"
        )
        subprocess.run(
            [sys.executable, "-c", script], env=env, stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )  # fmt: skip
        loaded = set(json.loads(report.read_text())) if report.exists() else set()
    return ", ".join(m for m in HEAVY if m in loaded) or "none"


def units_memo(out: Path) -> None:
    """A memo of the units of the paper's config and none of its texts, in ``out``.

    Filled by a run of the paper's config into a memo folder of its own (without the
    package's seed); its texts are then dropped, as if the units had been read in other
    texts.
    """
    folder = out / "memo-of-units"
    # without the package's seed, which would leave pint nothing to read
    script = (
        "from jointwear import quantity_memo\nquantity_memo.SEED = None\n"
        f"from jointwear.cli import main\nmain({run_command()[3:]!r})"
    )
    subprocess.run(
        [sys.executable, "-c", script], env=environment(**{MEMO: str(folder)}), capture_output=True
    )
    data = json.loads((folder / FILE_NAME).read_text())
    if not data["units"]:
        raise SystemExit("the run remembered no units")
    (out / "units-only.json").write_text(json.dumps({**data, "texts": {}}))


def first_run_script(out: Path) -> str:
    """A run of the paper's config from the memo of its units alone (:func:`units_memo`)."""
    return (
        f"import shutil, pathlib\nfolder = pathlib.Path({str(out / 'units-memo')!r})\n"
        f"folder.mkdir(exist_ok=True)\n"
        f"shutil.copyfile({str(out / 'units-only.json')!r}, folder / {FILE_NAME!r})\n"
        f"from jointwear.cli import main\nmain({run_command()[3:]!r})"
    )


def fresh_install_script(out: Path) -> str:
    """A run of the paper's config from an empty memo folder, as after a fresh install:
    the memo begins from the package's seed (removed first, ~1 ms)."""
    return (
        f"import shutil\nshutil.rmtree({str(out / 'fresh-memo')!r}, ignore_errors=True)\n"
        f"from jointwear.cli import main\nmain({run_command()[3:]!r})"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 repeats instead of 9")
    parser.add_argument("--repeat", type=int, default=None, help="runs of each command")
    parser.add_argument("--baseline", default=None, help="git revision to compare with")
    args = parser.parse_args()
    repeat = args.repeat or (3 if args.quick else 9)
    machine = describe_machine()
    out = Path(tempfile.mkdtemp(prefix="jointwear-startup-"))
    # (winkler and hertz solve circles: refused with the case's contour update)
    circular = ("--set", "simulation.update_contour=false")
    cases: dict[str, list[str]] = {
        f"run, {model}": run_command(
            "--set", f"contact.model={model}", *(circular if model in ("winkler", "hertz") else ())
        )
        for model in MODELS
    }
    cases["run, nlcp, --out DIR --no-plots"] = run_command("--out", str(out / "run"), "--no-plots")
    cases["`import jointwear.cli`"] = [sys.executable, "-c", "import jointwear.cli"]
    # just above the kernel policy's threshold the two paths cost about the same
    above = COMPILED_KERNEL_SOLVES + 1
    at_threshold = [
        sys.executable, "-m", "jointwear", "run", str(PAPER), "--json", "-q",
        "--set", f"simulation.revolutions={above}", "--set", "simulation.update_every=1",
    ]  # fmt: skip
    cases[f"run, nlcp, {above} revolutions every 1 (compiled kernel)"] = at_threshold
    # yardstick without git: the same run with what the old path loaded imported first
    # (dask only where it is installed: the product's own install has none)
    first = "numba, xarray, dask.array" if find_spec("dask") else "numba, xarray"
    eager = (
        f"import {first}\nimport jointwear.contact._compiled\n"
        f"from jointwear.cli import main\nmain({run_command()[3:]!r})"
    )
    cases[f"run, nlcp, {first.replace(', ', ' + ')} imported first"] = [
        sys.executable, "-c", eager,
    ]  # fmt: skip
    # the memo of quantity texts in a folder of its own, filled by the warm-up runs; the
    # same run with the memo turned off reads the package's seed only (the code before
    # had neither), and with a unit the seed lacks, imports pint to read it
    memo = {MEMO: str(out / "memo")}
    no_memo = f"run, nlcp, no memo ({MEMO}='')"
    cases[no_memo] = run_command()
    new_unit = f"run, nlcp, no memo, clearance in a unit new to it ({NEW_UNIT})"
    cases[new_unit] = run_command("--set", f"joint.clearance={NEW_UNIT}")
    # a config's first run where its units were read before (in other texts): every run
    # starts from a memo of the paper's units alone, copied in first (~1 ms)
    units_only = "run, nlcp, first run, units read before"
    cases[units_only] = [sys.executable, "-c", first_run_script(out)]
    # a fresh install's first run: an empty memo folder, which begins from the seed
    fresh = "run, nlcp, fresh install (empty memo folder)"
    cases[fresh] = [sys.executable, "-c", fresh_install_script(out)]
    baseline = checkout(args.baseline) if args.baseline else None
    commands = {}
    units_memo(out)
    for name, command in cases.items():
        memo_env = {MEMO: ""} if name in (no_memo, new_unit) else memo
        if name == units_only:
            memo_env = {MEMO: str(out / "units-memo")}
        if name == fresh:
            memo_env = {MEMO: str(out / "fresh-memo")}
        commands[name] = (command, environment(**memo_env))
        if baseline is not None:
            # a memo folder of its own: a memo of other code is read as empty and replaced,
            # so two codes taking turns on one memo would each find the other's
            own = {MEMO: str(out / "memo-baseline")} if memo_env is memo else memo_env
            commands[f"{name} [baseline]"] = (command, environment(baseline, **own))
    commands[f"run, nlcp, {above} revolutions every 1, JOINTWEAR_NO_NUMBA=1"] = (
        at_threshold,
        environment(JOINTWEAR_NO_NUMBA="1", **memo),
    )
    times = interleaved(commands, repeat)
    header = ["command (paper case, one revolution)", "median wall [s]"]
    if baseline is not None:
        header += [f"baseline {args.baseline} [s]", "ratio new/baseline"]
    heavy_header = ["heavy libraries loaded"]
    if baseline is not None:
        heavy_header.append("by the baseline")
    table = Table(*header, "target", *heavy_header)
    for name, (command, env) in commands.items():
        if name.endswith("[baseline]"):
            continue
        cells = [name, f"{median(times[name]):.3f}"]
        if baseline is not None:
            old = times.get(f"{name} [baseline]")
            cells += (
                [f"{median(old):.3f}", f"{paired_ratio(times[name], old):.2f}"] if old else ["", ""]
            )
        plain = name.startswith("run, ") and "every 1" not in name and "first" not in name
        target = f"<= {TARGET} s" if plain else ""
        loaded = [heavy_modules(command, env)]
        if baseline is not None:
            old_env = commands.get(f"{name} [baseline]")
            loaded.append(heavy_modules(command, old_env[1]) if old_env else "")
        table.add(*cells, target, *loaded)
    table.print(
        f"Whole processes, median of {repeat} interleaved runs after a warm-up. Machine: {machine}"
    )


if __name__ == "__main__":
    main()
