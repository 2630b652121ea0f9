"""Benchmark: a lubricated quasi-static cycle against a dry wear revolution (a plain script).

The slider-crank of the paper's Table 3 (120 rpm, 360 steps, the rod-slider pin), run
for one revolution: ``Simulation.run()`` dry (contact and Archard's wear in the fused
kernel) and lubricated (the pin's periodic orbit by the mobility method, the asperity
pressure along it, the wear). Each simulation is built outside the timer (the mechanism's
load cycle is the same for both); the film models' tables (long and finite bearing,
built once per L/D and process) are warmed up first. Medians of ``REPEATS`` runs, and
the ratio lubricated / dry measured in the same run.

Run: ``python benchmarks/bench_lubrication.py [--repeats N]``
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


def one_revolution(overrides: list[str]) -> float:
    """Seconds of ``Simulation.run()`` for one revolution (built outside the timer)."""
    config = load_config(
        CONFIG,
        overrides=["simulation.revolutions=1", "simulation.update_contour=false", *overrides],
    )
    simulation = Simulation(config)
    began = time.perf_counter()
    simulation.run(pressures=False)
    return time.perf_counter() - began


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    repeats = parser.parse_args().repeats
    print(f"Machine: {describe_machine()}\n")
    table = Table("case", "median [ms]", "min [ms]", "ratio to dry (median)")
    dry = None
    for name, overrides in CASES.items():
        one_revolution(overrides)  # warm-up: numba kernels, film tables
        times = [one_revolution(overrides) for _ in range(repeats)]
        median = statistics.median(times)
        dry = median if dry is None else dry
        table.add(name, f"{1e3 * median:.1f}", f"{1e3 * min(times):.1f}", f"{median / dry:.1f}")
    table.print(f"One revolution of the Table 3 slider-crank (360 steps), {repeats} repeats")


if __name__ == "__main__":
    main()
