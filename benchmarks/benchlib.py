"""Helpers shared by the whole-process benchmarks: timing, the machine, the table.

Not a benchmark itself (``run_all.py`` runs the ``bench_*.py`` files only).
"""

from __future__ import annotations

import os
import platform
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SRC = REPO / "src"
PAPER = REPO / "examples" / "paper" / "table5_nlcp_15000r.toml"
#: the paper case as calibrated to its published wear (docs/reproduction.md)
CALIBRATED = {
    "joint.axial_length": 0.01867,
    "joint.bushing_thickness": 0.003653,
    "mechanism.spring_preload": 121.8,
}
#: BLAS/OpenMP pools pinned to one thread in every process started here
ONE_THREAD = dict.fromkeys(("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"), "1")


class Table:
    """Rows of a Markdown table, echoed to stderr as they come."""

    def __init__(self, *header: str) -> None:
        self.header = header
        self.rows: list[tuple[str, ...]] = []

    def add(self, *cells: str) -> None:
        self.rows.append(cells)
        print("  " + " | ".join(cells), file=sys.stderr, flush=True)

    def print(self, title: str) -> None:
        print(f"{title}\n")
        print("| " + " | ".join(self.header) + " |")
        print("|" + "---|" * len(self.header))
        for cells in self.rows:
            print("| " + " | ".join(cells) + " |")
        print()


def describe_machine() -> str:
    """Processor, cores, Python and the load average, for the head of a report."""
    name = platform.machine()
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as handle:
            name = next(
                (line.split(":", 1)[1].strip() for line in handle if line.startswith("model name")),
                name,
            )
    except OSError:
        pass
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg()) if hasattr(os, "getloadavg") else "?"
    return (
        f"{name}; {os.cpu_count()} cores; Python {platform.python_version()}; load average {load}"
    )


def environment(src: Path = SRC, **extra: str) -> dict[str, str]:
    """The environment of a benchmarked process: ``src`` importable, one BLAS thread, and
    bytecode written (the warm-up run writes it), so that every process starts from it as
    from an installed package, not compiling the sources again (PYTHONDONTWRITEBYTECODE
    would charge each run ~0.3 s, more to the code with more modules)."""
    env = {**os.environ, **ONE_THREAD, **extra}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPATH"] = str(src)
    return env


def wall(command: Sequence[str], env: dict[str, str]) -> float:
    """Wall-clock seconds of one run of ``command`` (its output is discarded)."""
    began = time.perf_counter()
    done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    took = time.perf_counter() - began
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed: {done.stderr.decode()[-500:]}")
    return took


def interleaved(
    commands: dict[str, tuple[Sequence[str], dict[str, str]]], repeat: int
) -> dict[str, list[float]]:
    """Each command ``repeat`` times, taking turns (A B A B ...) after one warm-up each."""
    for command, env in commands.values():
        wall(command, env)
    times: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(repeat):
        for name, (command, env) in commands.items():
            times[name].append(wall(command, env))
    return times


def median(values: Sequence[float]) -> float:
    return float(statistics.median(values))


def paired_ratio(a: Sequence[float], b: Sequence[float]) -> float:
    """Median of the run-by-run ratios a/b (robust to drifting machine speed)."""
    return median([x / y for x, y in zip(a, b, strict=True)])


def checkout(revision: str) -> Path:
    """The ``src`` folder of ``revision`` of this repository, unpacked into a temporary folder."""
    target = Path(tempfile.mkdtemp(prefix="jointwear-baseline-"))
    archive = target / "src.tar"
    with open(archive, "wb") as handle:
        subprocess.run(
            ["git", "-C", str(REPO), "archive", revision, "src"], stdout=handle, check=True
        )
    with tarfile.open(archive) as tar:
        tar.extractall(target, filter="data")
    return target / "src"
