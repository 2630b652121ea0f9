"""Speed and memory of runs along the pin (``joint.axial_slices``) against the planar joint.

Run from the repository root::

    python benchmarks/bench_slices.py            # everything, ~8 minutes (CPU ~4 minutes)
    python benchmarks/bench_slices.py --quick    # a smoke run, ~1 minute

Prints one Markdown table: the median CPU time of one contour update of the
calibrated paper case (NLCP, 360 steps, 360 nodes; ``Simulation.step`` in the
revolution loop, warm, updated every revolution) for the planar joint and for ``N``
slices, taking turns, and the median of their paired ratios over ``N``; a whole run of
20 slices over 15000 revolutions updated every revolution (the median of three runs,
CPU and wall; target 60 s); and the memory a revolution allocates per slice
(tracemalloc peak). All BLAS/OpenMP pools are pinned to one thread; the load average
is printed with the machine (CPU time is what a shared machine inflates least)."""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import tracemalloc  # noqa: E402
import warnings  # noqa: E402

from benchlib import (  # noqa: E402
    CALIBRATED,
    PAPER,
    Table,
    describe_machine,
    median,
    paired_ratio,
)

from jointwear import Simulation, load_config  # noqa: E402

#: the joint along the pin: a bore out of line by 0.2 mrad, or a load 2 mm off the
#: mid-plane with the pin free to tilt
CASES = {
    "misaligned": {"joint.misalignment": 2e-4},
    "load offset": {"joint.load_offset": 2e-3},
}


def config(slices: int, case: str, revolutions: int = 15000):
    overrides = {
        **CALIBRATED,
        "simulation.revolutions": revolutions,
        "simulation.update_every": 1,
    }
    if slices > 1:
        overrides.update({"joint.axial_slices": slices, **CASES[case]})
    return load_config(PAPER, overrides=overrides)


def warm(slices: int, case: str):
    """A simulation and its state three contour updates in (the cold first solve done,
    the kernel loaded, the warm starts set)."""
    simulation = Simulation(config(slices, case))
    state = simulation.initial_state()
    simulation.load.resume(state)
    for _ in range(3):
        state = simulation.step(state)
    return simulation, state


def paired_steps(slices: int, case: str, repeat: int) -> tuple[list[float], list[float]]:
    """CPU seconds of ``repeat`` warm contour updates of the planar joint and of ``slices``
    slices, taking turns (one thread: CPU time is what a shared machine does not inflate)."""
    planar, planar_state = warm(1, case)
    sliced, sliced_state = warm(slices, case)
    planar_times, sliced_times = [], []
    for _ in range(repeat):
        began = time.process_time()
        planar_state = planar.step(planar_state)
        planar_times.append(time.process_time() - began)
        began = time.process_time()
        sliced_state = sliced.step(sliced_state)
        sliced_times.append(time.process_time() - began)
    return planar_times, sliced_times


def allocated(slices: int, case: str) -> float:
    """Peak bytes a warm contour update allocates (tracemalloc)."""
    simulation, state = warm(slices, case)
    tracemalloc.start()
    simulation.step(state)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return float(peak)


def whole_run(revolutions: int) -> tuple[float, float, float]:
    """Wall and CPU seconds of a whole run of 20 misaligned slices, and its peak wear [m]
    (the compiled balance already loaded from numba's cache by the rows before)."""
    began, cpu = time.perf_counter(), time.process_time()
    result = Simulation(config(20, "misaligned", revolutions)).run()
    took, cpu = time.perf_counter() - began, time.process_time() - cpu
    return took, cpu, result.summary()["peak_wear_depth_m"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats, a shorter run")
    quick = parser.parse_args().quick
    warnings.simplefilter("ignore")
    repeat = 5 if quick else 30
    table = Table("what", "measured", "against")
    print(describe_machine(), file=sys.stderr)
    for case in CASES:
        for slices in (5, 20):
            planar, sliced = paired_steps(slices, case, repeat)
            ratio = paired_ratio(sliced, planar)
            table.add(
                f"{slices} slices, {case}, one revolution",
                f"CPU {median(sliced) * 1e3:.2f} ms (planar {median(planar) * 1e3:.3f} ms)",
                f"{ratio / slices:.2f} x {slices} planar revolutions (target <= 1.2)",
            )
    revolutions = 1000 if quick else 15000
    runs = [whole_run(revolutions) for _ in range(1 if quick else 3)]
    took, cpu = median([r[0] for r in runs]), median([r[1] for r in runs])
    table.add(
        f"20 slices x {revolutions} revolutions, misaligned, updated every revolution "
        f"(median of {len(runs)})",
        f"{took:.1f} s, CPU {cpu:.1f} s, {cpu / revolutions * 1e3:.2f} ms a revolution "
        f"(peak wear {runs[0][2] * 1e6:.2f} um)",
        "15000 revolutions <= 60 s",
    )
    memory = {n: allocated(n, "misaligned") for n in (5, 10, 20)}
    table.add(
        "memory a revolution allocates, 5 / 10 / 20 slices",
        " / ".join(f"{memory[n] / 2**20:.2f} MiB" for n in memory),
        "per slice: " + " / ".join(f"{memory[n] / n / 2**10:.0f} KiB" for n in memory),
    )
    table.print(f"Along the pin ({describe_machine()})")


if __name__ == "__main__":
    main()
