"""Two versions of the compiled kernel side by side, on the same inputs.

A developer's tool for changes to ``src/jointwear/contact/_compiled.py``, not a
benchmark of a target (``run_all.py`` runs the ``bench_*.py`` files only). From the
repository root::

    python benchmarks/kernel_ab.py HEAD src/jointwear/contact/_compiled.py
    python benchmarks/kernel_ab.py old.py new.py --models winkler nlcp

A version is a file, or a git revision whose ``src/jointwear/contact/_compiled.py`` is
taken. Each is loaded as a module of its own (from a copy named by its content, so
numba's cache of it is reused by the next call) and calls ``revolution`` on the same
arguments: those of a warm revolution after 20 revolutions of the paper case, built
once with the installed package (both versions must take the arguments of its
``kernel.py``). Fixed arguments matter: a variant that changes the wear (an
experiment that drops a pass) changes the state of the next revolutions, and a
run-based timing then measures other inputs. The two run in alternating blocks of
calls; printed are the medians, their ratio, the largest wear difference relative to
the peak and the evaluations of each version.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse  # noqa: E402
import hashlib  # noqa: E402
import importlib.util  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from bench_simulation import kernel_inputs, paper  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
KERNEL = "src/jointwear/contact/_compiled.py"
MODELS = ("winkler", "asymmetric-winkler", "nlcp")


def source(version: str) -> str:
    """The text of a ``_compiled.py``: a file, else a git revision's."""
    path = Path(version)
    if path.is_file():
        return path.read_text()
    return subprocess.run(
        ["git", "show", f"{version}:{KERNEL}"], cwd=REPO, check=True, capture_output=True,
        text=True,
    ).stdout  # fmt: skip


def load(text: str, label: str):
    """``text`` as a module of its own, from a copy named by its content."""
    folder = Path(tempfile.gettempdir()) / "jointwear-kernel-ab"
    folder.mkdir(exist_ok=True)
    name = f"kernel_{label}_{hashlib.sha1(text.encode()).hexdigest()[:12]}"
    path = folder / f"{name}.py"
    if not path.exists():
        path.write_text(text)
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def warm_arguments(model: str) -> dict:
    """The compiled revolution's inputs of a warm revolution of the paper case, after 20
    revolutions updated every revolution."""
    simulation, state = kernel_inputs(
        paper(**{"contact.model": model, "simulation.revolutions": 15000,
                 "simulation.update_every": 1}), 20,
    )  # fmt: skip
    contour = simulation.solver.contour(state.wear_depth)
    warm = simulation.solver._warm_revolutions(simulation.load_cycle, simulation.sliding_distance)
    nodes, grid, lines, _ = warm.arguments(contour)
    return {
        "load": warm.load, "sliding": warm.sliding, "nodes": nodes, "grid": grid,
        "lines": lines, "solver": warm.solver, "conformal": warm.known.zeros,
        "guess": np.array(state.warm_offset + state.warm_slope),
        "scale": warm.wear_coefficient * warm.law.coefficient,
        "padded": warm.known.padded.size, "quarter": warm.known.quarter,
        "nodes_count": contour.nodes,
    }  # fmt: skip


def call(module, inputs: dict) -> tuple:
    """``module.revolution``'s arguments on ``inputs``, with outputs of its own (five rows
    each: more than any version writes)."""
    m = inputs["load"].size
    return (
        inputs["load"], inputs["sliding"], inputs["guess"], True, inputs["conformal"],
        inputs["nodes"], inputs["grid"], inputs["lines"], inputs["solver"], np.empty((5, m)),
        np.empty((5, m), dtype=np.int64), np.empty(inputs["padded"]), inputs["scale"],
        np.empty(inputs["nodes_count"]), module.scratch(inputs["quarter"]),
    )  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("a", help="version A: a file or a git revision")
    parser.add_argument("b", help="version B: a file or a git revision")
    parser.add_argument("--models", nargs="+", default=list(MODELS), choices=MODELS)
    parser.add_argument("--rounds", type=int, default=30, help="alternations (30)")
    parser.add_argument("--block", type=int, default=60, help="calls per block (60)")
    args = parser.parse_args()
    versions = [load(source(args.a), "a"), load(source(args.b), "b")]
    for model in args.models:
        inputs = warm_arguments(model)
        calls = [call(module, inputs) for module in versions]
        for module, arguments in zip(versions, calls, strict=True):
            module.revolution(*arguments)  # compile or load, and warm up
        times: list[list[float]] = [[], []]
        for _ in range(args.rounds):
            for index, (module, arguments) in enumerate(zip(versions, calls, strict=True)):
                for _ in range(args.block):
                    start = time.perf_counter()
                    module.revolution(*arguments)
                    times[index].append(time.perf_counter() - start)
        a, b = (float(np.median(t)) * 1e6 for t in times)
        wear_a, wear_b = calls[0][13], calls[1][13]
        deviation = np.abs(wear_b - wear_a).max() / np.abs(wear_a).max()
        evaluations = [int(arguments[10][0].sum()) for arguments in calls]
        print(
            f"{model}: A {a:.1f} us, B {b:.1f} us, B/A {b / a:.3f}; wear |B - A| / peak "
            f"{deviation:.1e}; evaluations {evaluations[0]} / {evaluations[1]}",
            flush=True,
        )


if __name__ == "__main__":
    main()
