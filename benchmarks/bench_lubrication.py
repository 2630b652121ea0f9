"""Benchmark: a lubricated quasi-static cycle against a dry wear revolution (a plain script).

The slider-crank of the paper's Table 3 (120 rpm, 360 steps, the rod-slider pin), run
for one revolution: ``Simulation.run()`` dry (contact and Archard's wear in the fused
kernel) and lubricated (the pin's periodic orbit by the mobility method, the asperity
pressure along it, the wear), the orbit integrated by the compiled kernel and, for
comparison, by ``solve_ivp`` (LSODA) with the Python right-hand side (what a run without
numba does). Then ten revolutions with the contour updated, where the orbit of the one
load cycle is computed once and reused. Each simulation is built outside the timer (the
mechanism's load cycle is the same for all); numba's kernels and the film models'
tables (long and finite bearing, built once per L/D and process) are warmed up first.
CPU time of this process (the machine is shared) and wall time, medians of ``--repeats``
runs (the Python path: ``--python-repeats``); each run of a case is followed by a dry run
of as many revolutions, and the ratio is that of the two CPU medians (a changing load
changes both alike); the last column is the number of cycles the orbit search integrated.
The load average is printed at the start and the end.
Target: a lubricated revolution within 2x of a dry one; the last measurement and where the
time goes are in docs/lubrication.md (*Speed*). Last measured (21 repeats, two runs taking
turns with two of the code before, load 5.0-5.2), one revolution's CPU ratio to the dry one:
short bearing 0.3 Pa s 1.60-1.62, 0.03 Pa s 1.56-1.61, finite length (ISO VG 68 at 60 degC)
1.64-1.67 (3 cycles), long bearing (0.3 Pa s) 1.67-1.69 (10 cycles); ten revolutions 0.44-0.45
(short) and 1.35-1.36 (finite). The code before in the same period: 1.66-1.83, 1.71-1.87,
2.00-2.25, 1.88-1.95; 0.52-0.54 and 1.48-1.52.
On a quiet machine (load 0.4-1.5, 21 repeats) with the finite bearing's leaving table from
eps = 0.9: 1.62, 1.68, 1.69, 1.75; 0.49 and 1.50.

Run: ``python benchmarks/bench_lubrication.py [--repeats N] [--python-repeats N]``
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "MKL_NUM_THREADS", "OPENBLAS_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from benchlib import Table, describe_machine  # noqa: E402

from jointwear import Simulation, load_config  # noqa: E402
from jointwear.lubrication import orbit  # noqa: E402

CONFIG = Path(__file__).resolve().parents[1] / "examples" / "paper" / "table3_winkler_120rpm.toml"
#: the lubricated cases: film model and oil
CASES = {
    "dry": [],
    "short bearing, 0.3 Pa s": [
        "lubrication.model=short-bearing",
        "lubrication.viscosity=0.3 Pa*s",
    ],
    "short bearing, 0.03 Pa s": [
        "lubrication.model=short-bearing",
        "lubrication.viscosity=0.03 Pa*s",
    ],
    "finite length, ISO VG 68 at 60 degC": [
        "lubrication.model=finite-length",
        "lubrication.lubricant=iso-vg-68",
        "lubrication.temperature=60 degC",
    ],
    "long bearing, 0.3 Pa s": ["lubrication.model=long-bearing", "lubrication.viscosity=0.3 Pa*s"],
}


def one_run(
    overrides: list[str], revolutions: int = 1, update: bool = False
) -> tuple[float, float, int]:
    """CPU and wall seconds of ``Simulation.run()`` (the simulation built outside the timer)
    and the cycles its orbit search integrated (0 for a dry run)."""
    config = load_config(
        CONFIG,
        overrides=[
            f"simulation.revolutions={revolutions}",
            f"simulation.update_contour={str(update).lower()}",
            *overrides,
        ],
    )
    simulation = Simulation(config)
    began, began_wall = time.process_time(), time.perf_counter()
    simulation.run(pressures=False)
    cpu, wall = time.process_time() - began, time.perf_counter() - began_wall
    lubrication = simulation.solver.lubrication
    cycles = lubrication.orbit(simulation.load_cycle)[0].cycles if lubrication else 0
    return cpu, wall, cycles


def paired(overrides: list[str], repeats: int, **run: object) -> tuple[float, float, float, int]:
    """Median CPU and wall seconds of ``repeats`` runs of a case, the median CPU seconds
    of as many dry runs, each right after one of the case (the machine's load changes
    the two alike), and the orbit's cycles; a warm-up of each first."""
    one_run(overrides, **run)  # warm-up: numba kernels, film tables
    one_run([], **run)
    case, dry = [], []
    for _ in range(repeats):
        case.append(one_run(overrides, **run))
        dry.append(one_run([], **run)[0])
    cpu = statistics.median(t[0] for t in case)
    return cpu, statistics.median(t[1] for t in case), statistics.median(dry), case[-1][2]


def row(table: Table, name: str, orbit_path: str, timed: tuple[float, float, float, int]) -> None:
    """A row: the case's CPU and wall medians [ms], its CPU ratio to the dry runs and
    the orbit's cycles."""
    cpu, wall, dry, cycles = timed
    table.add(
        name,
        orbit_path,
        f"{1e3 * cpu:.1f}",
        f"{1e3 * wall:.1f}",
        f"{cpu / dry:.2f}",
        str(cycles or "-"),
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--python-repeats", type=int, default=3, help="0: no Python orbit")
    arguments = parser.parse_args()
    print(f"Machine: {describe_machine()}\n")
    table = Table("case", "orbit", "CPU [ms]", "wall [ms]", "CPU ratio to dry", "cycles")
    row(table, "dry", "-", paired([], arguments.repeats))
    for name, overrides in list(CASES.items())[1:]:
        row(table, name, "compiled", paired(overrides, arguments.repeats))
        if arguments.python_repeats < 1:
            continue
        # the Python right-hand side under LSODA, as without numba (the contact
        # kernel stays compiled, so only the orbit differs)
        kernel, orbit._KERNEL = orbit._KERNEL, False
        try:
            row(table, name, "Python, LSODA", paired(overrides, arguments.python_repeats))
        finally:
            orbit._KERNEL = kernel
    many = {"revolutions": 10, "update": True}
    row(table, "dry, 10 revolutions", "-", paired([], arguments.repeats, **many))
    for name in ("short bearing, 0.3 Pa s", "finite length, ISO VG 68 at 60 degC"):
        timed = paired(CASES[name], arguments.repeats, **many)
        row(table, f"{name}, 10 revolutions", "compiled", timed)
    table.print(
        f"The Table 3 slider-crank (360 steps): one revolution, and ten with the contour "
        f"updated; medians of CPU and wall time, {arguments.repeats} repeats "
        f"({arguments.python_repeats} for the Python orbit), each after a dry run"
    )
    print(f"Load average at the end: {describe_machine().rsplit('load average ', 1)[-1]}")


if __name__ == "__main__":
    main()
