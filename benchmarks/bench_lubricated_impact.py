"""Speed of the lubricated contact-impact dynamics: a revolution with the oil film vs a dry one.

Run from the repository root::

    python benchmarks/bench_lubricated_impact.py            # ~1 minute
    python benchmarks/bench_lubricated_impact.py --quick    # a smoke run

Prints one Markdown table: per case the median wall-clock and CPU time of one
integrated revolution (``solve_contact_impact`` with ``dynamics.revolutions_settle =
0``, compiled right-hand side, no massless-link comparison), dry and with the film,
taking turns in the same run (A B A B ...) after a warm-up each, and the median of the
run-by-run ratios lubricated / dry, wall-clock and CPU (target: at most 2). All
BLAS/OpenMP pools are pinned to one thread. The cases are the paper's joint
(``tests/data/paper_joint.toml``: pull spring, 120 rpm, 0.05 mm; the pin stays on the
wall and the film shares the load) and the separating case of the tests (push spring,
light rod, 0.2 mm, 240 rpm: dry, the pin flies and hits the wall; a viscous film keeps
it off the wall). Without settling revolutions the start transient is part of the
timed revolution (a squeeze-film spike where the pin starts pressed into the wall).
The numba kernels are compiled (or loaded from the cache) before anything is timed.
The lubricated runs integrate with ``auto``'s choice for a film, ``Radau-compiled`` (the
compiled RADAU5), or with ``--integrator NAME``; the dry ones with ``RK45-compiled``.
Last measured (``--quick``, docs/dynamics.md, CPU ratios, load average 7.4-8.0):
``Radau-compiled`` 1.27 / 1.51 / 1.58x on the paper's joint (15 / 10 / 20 k right-hand
sides) and 1.07 / 1.82 / 0.85x on the separating case (again at load 6.4: 1.27 / 1.52 /
1.60x and 1.09 / 1.86 / 0.85x); before its Newton sweeps stopped at
radau5.f's tolerance and its steps kept off a divergence 3.0 / 2.5 / 6.5x (43 / 18 / 95 k)
and 1.2 / 2.0 / 0.96x; ``Rodas4-compiled`` 43 / 18 / 211x and 12 / 8.0 / 18x;
``RK45-compiled`` 587 / 112 / 5453x and 10 / 7.6 / 19x.
The finite-length film is not offered in contact-impact.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from dataclasses import replace  # noqa: E402
from pathlib import Path  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from benchmarks.bench_simulation import ROWS, machine, ms, row  # noqa: E402
from benchmarks.benchlib import median, paired_ratio  # noqa: E402
from tests.mechanism.slider_crank.test_contact_impact import SEPARATING  # noqa: E402

from jointwear import load_config  # noqa: E402
from jointwear.mechanism.impact.film import FilmParameters  # noqa: E402
from jointwear.mechanism.slider_crank import contact_impact as ci  # noqa: E402
from jointwear.mechanism.stage import mechanism_inputs  # noqa: E402

PAPER = REPO / "tests" / "data" / "paper_joint.toml"
CASES = {
    "paper joint": {},
    "separating case": SEPARATING,
}
FILMS = {
    "short bearing, 0.1 Pa s": FilmParameters("short-bearing", 0.1),
    "long bearing, 0.1 Pa s": FilmParameters("long-bearing", 0.1),
    "short bearing, 1 Pa s": FilmParameters("short-bearing", 1.0),
}


def revolution(inputs):
    """One integrated revolution of ``inputs`` (compiled), its solution."""
    return ci.solve_contact_impact(inputs, compare=False, compiled=True)


def paired(dry, wet, repeat: int) -> dict[str, list[tuple[float, float]]]:
    """Wall and CPU seconds of both, taking turns after a warm-up each."""
    dry()
    wet()
    times: dict[str, list[tuple[float, float]]] = {"dry": [], "wet": []}
    for _ in range(repeat):
        for name, function in (("dry", dry), ("wet", wet)):
            w0, c0 = time.perf_counter(), time.process_time()
            function()
            times[name].append((time.perf_counter() - w0, time.process_time() - c0))
    return times


def bench_case(case: str, quick: bool, integrator: str) -> None:
    config = load_config(
        PAPER,
        overrides={
            "dynamics.model": "contact-impact",
            "dynamics.revolutions_settle": 0,
            **CASES[case],
        },
    )
    dry_inputs = mechanism_inputs(config)
    dry = revolution(dry_inputs)
    row(
        f"{case}, dry: one revolution",
        f"{dry.impacts} impacts, peak joint force {dry.peak_joint_force:.0f} N, "
        f"{dry.history.evaluations} RHS evaluations",
    )
    for label, film in FILMS.items():
        dynamics = dry_inputs.dynamics.model_copy(update={"integrator": integrator})
        wet_inputs = replace(dry_inputs, film=film, dynamics=dynamics)
        wet = revolution(wet_inputs)
        times = paired(
            lambda: revolution(dry_inputs),
            lambda wet_inputs=wet_inputs: revolution(wet_inputs),
            5 if quick else 15,
        )
        dry_wall = median([w for w, _ in times["dry"]])
        dry_cpu = median([c for _, c in times["dry"]])
        wet_wall = median([w for w, _ in times["wet"]])
        wet_cpu = median([c for _, c in times["wet"]])
        ratio = paired_ratio([w for w, _ in times["wet"]], [w for w, _ in times["dry"]])
        cpu_ratio = paired_ratio([c for _, c in times["wet"]], [c for _, c in times["dry"]])
        row(f"{case}, dry: one revolution (paired with {label})", ms(dry_wall, dry_cpu))
        row(
            f"{case}, {label}: one revolution",
            f"{ms(wet_wall, wet_cpu)}; {wet.impacts} impacts, peak joint force "
            f"{wet.peak_joint_force:.0f} N, {wet.history.evaluations} RHS evaluations",
        )
        row(
            f"{case}, {label}: lubricated / dry (median of paired ratios)",
            f"{ratio:.2f}x wall, {cpu_ratio:.2f}x CPU",
            "<= 2x",
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    parser.add_argument(
        "--integrator",
        default="auto",
        help="dynamics.integrator of the lubricated runs (the dry ones: auto's, RK45-compiled)",
    )
    args = parser.parse_args()
    if ci.impact_kernel() is None:
        raise SystemExit("bench_lubricated_impact: needs numba (and JOINTWEAR_NO_NUMBA unset)")
    load = os.getloadavg()
    for case in CASES:
        print(f"[{case}]", file=sys.stderr, flush=True)
        bench_case(case, args.quick, args.integrator)
    lines = [
        f"Machine: {machine()}; load average at start {load[0]:.2f}, "
        f"at end {os.getloadavg()[0]:.2f}; lubricated runs: integrator {args.integrator}\n",
        "| benchmark | result | target |",
        "|---|---|---|",
        *(f"| {name} | {value} | {target} |" for name, value, target in ROWS),
    ]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
