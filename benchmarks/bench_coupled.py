"""Coupled contact-impact runs: the separation-prone slider-crank over 10^5 revolutions,
and a life distribution of it.

Run from the repository root::

    python benchmarks/bench_coupled.py                  # ~6 minutes
    python benchmarks/bench_coupled.py --quick          # one round, 6 life cases
    python benchmarks/bench_coupled.py --baseline REV ...  # also the code of git revisions
    python benchmarks/bench_coupled.py --only run --repeat 7 --baseline main  # the run, A/B

The case is the separation-prone slider-crank of ``docs/wear-feedback.md``
(``tests/data/paper_joint.toml`` with ``SEPARATION_PRONE`` of
``tests/mechanism/slider_crank/test_contact_impact_rk.py``: push spring, 1 N preload,
240 rpm, 0.3 kg rod, 180 steps) under ``dynamics.model = "contact-impact"``,
``dynamics.integrator = "RK45-compiled"``, contour and dynamics updated adaptively
over 10^5 revolutions. Every run is a whole ``jointwear run`` process (start-up, numba
cache loads and outputs included), the variants taking turns; the table gives medians
of wall and CPU time (the process's user + system time, ``RUSAGE_CHILDREN``). The life
row runs ``jointwear life`` on the same case (the wear coefficient lognormal, the
clearance uniform, life to 0.15 mm of wear) with ``--workers 2`` and extrapolates the
200-case time linearly in the cases; with ``--baseline`` the revisions take turns with
this tree in the life rows too. The machine is shared: read the CPU times, and the load
average printed with the table. The results and where the time goes:
``docs/performance.md``, *The whole run*. Measured (``--repeat 7 --life-repeat 3
--baseline 502034c``, one run, load average 2-7): the run 5.07 s of CPU against 8.64 s
(0.59x; the separating solves of a coupled run integrated once at its rtol,
``docs/wear-feedback.md``), a life case 2.56 s against 5.38 s (0.48x), 200 cases ~256 s
on two free cores against ~538 s.
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchlib import REPO, SRC, Table, checkout, describe_machine, environment, median

CASE = REPO / "tests" / "data" / "paper_joint.toml"
#: the separation-prone slider-crank, coupled, 10^5 revolutions
SETTINGS = {
    "mechanism.spring_mode": "push",
    "mechanism.spring_preload": "1 N",
    "mechanism.crank_speed": "240 rpm",
    "mechanism.rod_mass": "0.3 kg",
    "simulation.steps_per_revolution": "180",
    "dynamics.model": "contact-impact",
    "dynamics.integrator": "RK45-compiled",
    "simulation.revolutions": "100000",
    "simulation.update_contour": "true",
    "simulation.update_every": "adaptive",
    "simulation.dynamics_update": "adaptive",
}
LIFE_SAMPLES = [
    "materials.bushing.wear_coefficient=lognormal(median=5.05e-13 m^2/N, sigma=0.3)",
    "joint.clearance=uniform(low=0.045 mm, high=0.055 mm)",
]
LIFE_LIMIT = "life.peak_wear_depth=0.15 mm"
#: targets on the two shared cores of this round [s]
RUN_TARGET, LIFE_TARGET, LIFE_CASES = 8.0, 300.0, 200


def sets(settings: dict[str, str]) -> list[str]:
    return [arg for key, value in settings.items() for arg in ("--set", f"{key}={value}")]


def timed(command: list[str], env: dict[str, str]) -> tuple[float, float, str]:
    """Wall and CPU seconds of one process (its children included), and its stdout."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    began = time.perf_counter()
    done = subprocess.run(command, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - began
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed: {done.stderr[-800:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, done.stdout


def run_command() -> list[str]:
    return [sys.executable, "-m", "jointwear", "run", str(CASE), *sets(SETTINGS), "--json", "-q",
            "--no-plots"]  # fmt: skip


def life_command(cases: int, out: Path) -> list[str]:
    samples = [arg for sample in LIFE_SAMPLES for arg in ("--sample", sample)]
    return [
        sys.executable, "-m", "jointwear", "life", str(CASE), *sets(SETTINGS),
        "--set", LIFE_LIMIT, *samples, "--cases", str(cases), "--seed", "7",
        "--workers", "2", "--out", str(out), "--json", "-q",
    ]  # fmt: skip


def bench_run(variants: dict[str, Path], repeat: int, table: Table) -> None:
    """The 10^5-revolution coupled run per variant, taking turns after a warm-up each."""
    envs = {name: environment(src) for name, src in variants.items()}
    summaries = {}
    for name, env in envs.items():  # warm-up: fills the numba cache of that source tree
        summaries[name] = json.loads(timed(run_command(), env)[2])
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in variants}
    for _ in range(repeat):
        for name, env in envs.items():
            wall, cpu, _ = timed(run_command(), env)
            times[name].append((wall, cpu))
    for name in variants:
        wall = median([w for w, _ in times[name]])
        cpu = median([c for _, c in times[name]])
        s = summaries[name]
        table.add(
            f"separation-prone slider-crank, 1e5 revolutions coupled ({name})",
            f"{cpu:.2f} s CPU, {wall:.2f} s wall ({s['dynamics_updates']} dynamics solves, "
            f"peak {s['peak_wear_depth_m'] * 1e3:.5f} mm)",
            f"<= {RUN_TARGET:g} s",
        )


def bench_life(variants: dict[str, Path], cases: int, repeat: int, table: Table) -> None:
    """``jointwear life`` on the case with two workers per variant, taking turns,
    extrapolated to 200 cases."""
    envs = {name: environment(src) for name, src in variants.items()}
    walls: dict[str, list[float]] = {name: [] for name in variants}
    cpus: dict[str, list[float]] = {name: [] for name in variants}
    lives: dict[str, dict] = {}
    for _ in range(repeat):
        for name, env in envs.items():
            with tempfile.TemporaryDirectory(prefix="jointwear-life-") as folder:
                wall, cpu, out = timed(life_command(cases, Path(folder) / "life"), env)
            walls[name].append(wall)
            cpus[name].append(cpu)
            lives[name] = json.loads(out)
    for name in variants:
        wall, cpu = median(walls[name]), median(cpus[name])
        b50 = lives[name].get("b50_revolutions")
        median_life = "?" if b50 is None else f"{b50:.0f} revolutions"
        table.add(
            f"life distribution, {cases} cases on 2 workers (`jointwear life`, {name})",
            f"{wall:.1f} s wall, {cpu:.1f} s CPU, {cpu / cases:.2f} s CPU a case "
            f"(B50 {median_life})",
            "",
        )
        table.add(
            f"life distribution, {LIFE_CASES} cases on 2 workers, extrapolated ({name})",
            f"{wall * LIFE_CASES / cases:.0f} s wall as measured; "
            f"{cpu * LIFE_CASES / cases / 2:.0f} s on two free cores (CPU / 2)",
            f"<= {LIFE_TARGET:g} s",
        )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one round, 6 life cases")
    parser.add_argument("--repeat", type=int, default=None, help="run rounds (default 3)")
    parser.add_argument("--baseline", nargs="*", default=[], help="also time these revisions")
    parser.add_argument("--cases", type=int, default=None, help="life cases (default 20)")
    parser.add_argument("--life-repeat", type=int, default=None, help="life rounds (default 3)")
    parser.add_argument("--only", nargs="*", default=["run", "life"], help="run life")
    args = parser.parse_args()
    repeat = args.repeat or (1 if args.quick else 3)
    variants = {"this tree": SRC}
    for revision in args.baseline:
        variants[revision] = checkout(revision)
    table = Table("benchmark", "result", "target")
    start = describe_machine()
    if "run" in args.only:
        bench_run(variants, repeat, table)
    if "life" in args.only:
        cases = args.cases or (6 if args.quick else 20)
        bench_life(variants, cases, args.life_repeat or repeat, table)
    print(f"Machine at start: {start}\nMachine at end: {describe_machine()}\n")
    table.print("Coupled contact-impact runs (medians; CPU = user + system of the process)")


if __name__ == "__main__":
    main()
