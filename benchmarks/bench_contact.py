"""Benchmark: one batched load balance of a revolution's loads (a plain script, not a test).

360 loads (50-400 N, azimuths spanning +-25 deg, as over one crank revolution) balanced
at once on a 720-node bushing contour, for the asymmetric Winkler and NLCP models in
paper and 2-D equilibrium modes, on the unworn circle and on a worn contour. Each case
is warmed up, then timed ``REPEATS`` times with ``time.perf_counter``; the median is
reported (target: < 20 ms per batch on one core).

Run: ``python benchmarks/bench_contact.py [--repeats N] [--quick]``
"""

from __future__ import annotations

import os

# single core: set before numpy is imported
for _var in ("OMP_NUM_THREADS", "MKL_NUM_THREADS", "OPENBLAS_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import platform  # noqa: E402
import statistics  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

from jointwear.config import load_config  # noqa: E402
from jointwear.contact import ContactParameters, solve  # noqa: E402
from jointwear.geometry import BushingContour, Pin  # noqa: E402

CONFIG = Path(__file__).resolve().parents[1] / "examples" / "paper" / "table3_winkler_120rpm.toml"
NODES = 720
LOADS = 360
TARGET_MS = 20.0


def revolution_loads(count: int = LOADS) -> tuple[np.ndarray, np.ndarray]:
    """Joint loads over one revolution: magnitude 50-400 N, azimuth within +-25 deg."""
    phase = 2 * np.pi * np.arange(count) / count
    load = 225.0 + 175.0 * np.sin(phase)
    azimuth = np.radians(25.0) * np.sin(2 * phase + 0.3)
    return load, azimuth


def contours(params: ContactParameters) -> dict[str, BushingContour]:
    theta = 2 * np.pi * np.arange(NODES) / NODES
    phi = np.angle(np.exp(1j * (theta - np.radians(10.0))))
    wear = 15e-6 * np.exp(-((phi / np.radians(20.0)) ** 2))  # a 15 um scar near the loads
    return {
        "circle": BushingContour.circle(params.bushing_radius, NODES, params.axial_length),
        "worn": BushingContour.from_wear_profile(params.bushing_radius, wear, params.axial_length),
    }


def time_case(contour, pin, params, model, balance, load, azimuth, repeats):
    def once():
        return solve(contour, pin, load, azimuth, model, params, balance=balance)

    for _ in range(3):  # warm-up
        solution = once()
    samples = []
    for _ in range(repeats):
        start = time.perf_counter()
        once()
        samples.append(time.perf_counter() - start)
    residual = np.abs(solution.normal_force - load).max()
    sideways = np.abs(solution.tangential_force).max()
    return statistics.median(samples), min(samples), solution, residual, sideways


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=25, help="timed repeats (>= 20)")
    parser.add_argument("--quick", action="store_true", help="the fewest repeats (20)")
    args = parser.parse_args()
    repeats = 20 if args.quick else max(args.repeats, 20)

    cfg = load_config(CONFIG)
    params = ContactParameters.from_config(cfg)
    pin = Pin(params.pin_radius)
    load, azimuth = revolution_loads()

    print("## jointwear contact benchmark\n")
    print(
        f"- machine: {platform.platform()}, {platform.machine()}, "
        f"processor {platform.processor() or 'n/a'}, {os.cpu_count()} CPUs "
        f"(run single-threaded: OMP/MKL/OPENBLAS_NUM_THREADS=1)"
    )
    print(f"- python {platform.python_version()}, numpy {np.__version__}")
    print(
        f"- batch: {LOADS} loads, {load.min():.0f}-{load.max():.0f} N, azimuth "
        f"{np.degrees(azimuth.min()):+.0f} to {np.degrees(azimuth.max()):+.0f} deg; "
        f"{NODES}-node contour; median of {repeats} repeats after 3 warm-up runs\n"
    )
    print(
        "| contour | model | balance | median [ms] | min [ms] | per load [us] "
        "| max iterations | max abs(F - F_N) [N] | max abs(sideways) [N] | < 20 ms |"
    )
    print("|---|---|---|---:|---:|---:|---:|---:|---:|:-:|")
    for name, contour in contours(params).items():
        for model in ("asymmetric-winkler", "nlcp"):
            for balance in ("paper", "equilibrium"):
                median, best, solution, residual, sideways = time_case(
                    contour, pin, params, model, balance, load, azimuth, repeats
                )
                print(
                    f"| {name} | {model} | {balance} | {1e3 * median:.2f} | {1e3 * best:.2f} "
                    f"| {1e6 * median / LOADS:.1f} | {solution.iterations.max()} "
                    f"| {residual:.1e} | {sideways:.1e} "
                    f"| {'yes' if 1e3 * median < TARGET_MS else 'no'} |"
                )


if __name__ == "__main__":
    main()
