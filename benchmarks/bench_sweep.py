"""Throughput of sweeps: 64 cases x 15000 revolutions (adaptive) of the paper's joint.

Run from the repository root::

    python benchmarks/bench_sweep.py                   # ~3 minutes
    python benchmarks/bench_sweep.py --quick           # one round
    python benchmarks/bench_sweep.py --baseline REV    # also the code of git revision REV

Every mode runs ``run_sweep`` in a fresh process (so each pays its own start-up of the
compiled kernel), the modes taking turns; the table gives medians over the rounds of
the sweep's own wall time (cases/s) and of the cases' run times (``runtime_s`` of each
case: the time of one case on one worker), each as a ratio to the serial sweep of the
same round. The dask modes run on a ``LocalCluster`` of two single-threaded workers
started before the clock (a cluster is normally up already): once with the nanny's
default environment (``MALLOC_TRIM_THRESHOLD_=65536``) and once with that variable
unset through dask's configuration. The whole-process row times ``jointwear sweep``
with the default worker count, outputs included.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from benchlib import (
    PAPER,
    Table,
    checkout,
    describe_machine,
    environment,
    median,
)

CASES = 64
#: target throughput on two cores [cases/s]
TARGET = 30.0
SWEEP = f"""
base = "{PAPER}"
[set]
"simulation.revolutions" = 15000
"simulation.update_every" = "adaptive"
[grid]
"joint.clearance" = ["0.04 mm", "0.05 mm", "0.06 mm", "0.07 mm", "0.08 mm", "0.09 mm",
                     "0.1 mm", "0.12 mm"]
"materials.bushing.wear_coefficient" = ["3e-13 m^2/N", "4e-13 m^2/N", "5e-13 m^2/N",
                                        "6e-13 m^2/N", "7e-13 m^2/N", "8e-13 m^2/N",
                                        "9e-13 m^2/N", "1e-12 m^2/N"]
"""

#: one mode in a fresh interpreter; prints the sweep's numbers as JSON
MODE = """
import json, statistics, sys, warnings
warnings.simplefilter("ignore")
from jointwear.workflows.sweep import load_sweep, run_sweep
mode, sweep, out = sys.argv[1:4]
plan = load_sweep(sweep)
cluster = client = None
options = {}
if mode.startswith("dask"):
    import dask
    from dask.distributed import Client, LocalCluster
    if mode == "dask-untrimmed":
        dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None})
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None)
    client = Client(cluster)
    options["client"] = client
else:
    options["workers"] = None if mode == "default" else int(mode.split("-")[0])
result = run_sweep(plan, out, **options)
if client is not None:
    client.close(); cluster.close()
times = [r["metrics"]["runtime_s"] for r in result.records if r["status"] == "ok"]
print(json.dumps({"runtime": result.runtime, "per_case": statistics.median(times),
                  "ok": len(times), "workers": result.workers}))
"""


#: one case's work as a sweep did it before (pressure field, Dataset) and as it does now
CASE_WORK = """
import json, statistics, sys, time, warnings
warnings.simplefilter("ignore")
from jointwear.simulation import Simulation
from jointwear.workflows.sweep import load_sweep
plan = load_sweep(sys.argv[1])
configs = [plan.config(case) for case in plan.cases[:16]]
Simulation(configs[0]).run()  # the compiled kernel loaded
old, new = [], []
for config in configs:
    began = time.perf_counter()
    result = Simulation(config).run()
    result.dataset, result.summary()
    old.append(time.perf_counter() - began)
    began = time.perf_counter()
    Simulation(config).run(pressures=False).summary()
    new.append(time.perf_counter() - began)
print(json.dumps({"old": statistics.median(old), "new": statistics.median(new),
                  "ratio": statistics.median([n / o for n, o in zip(new, old)])}))
"""


def case_work(sweep: Path, env: dict[str, str]) -> dict:
    done = subprocess.run(
        [sys.executable, "-c", CASE_WORK, str(sweep)], env=env, capture_output=True, text=True,
        check=True,
    )  # fmt: skip
    return json.loads(done.stdout.strip().splitlines()[-1])


def run_mode(mode: str, sweep: Path, folder: Path, env: dict[str, str]) -> dict:
    out = folder / f"{mode}-{time.monotonic_ns()}"
    done = subprocess.run(
        [sys.executable, "-c", MODE, mode.removesuffix(" [baseline]"), str(sweep), str(out)],
        env=env, capture_output=True, text=True,
    )  # fmt: skip
    if done.returncode != 0:
        raise RuntimeError(f"{mode}: {done.stderr[-800:]}")
    result = json.loads(done.stdout.strip().splitlines()[-1])
    if result["ok"] != CASES:
        raise RuntimeError(f"{mode}: only {result['ok']} of {CASES} cases ok")
    return result


def whole_process(sweep: Path, folder: Path, env: dict[str, str]) -> float:
    began = time.perf_counter()
    subprocess.run(
        [sys.executable, "-m", "jointwear", "sweep", str(sweep), "--out",
         str(folder / f"cli-{time.monotonic_ns()}"), "--json", "-q"],
        env=env, check=True, stdout=subprocess.DEVNULL,
    )  # fmt: skip
    return time.perf_counter() - began


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="one round instead of three")
    parser.add_argument("--rounds", type=int, default=None, help="rounds of every mode")
    parser.add_argument("--baseline", default=None, help="git revision to compare with")
    parser.add_argument("--no-dask", action="store_true", help="leave out the dask modes")
    args = parser.parse_args()
    rounds = args.rounds or (1 if args.quick else 3)
    machine = describe_machine()
    folder = Path(tempfile.mkdtemp(prefix="jointwear-sweep-bench-"))
    sweep = folder / "sweep.toml"
    sweep.write_text(SWEEP, encoding="utf-8")
    env = environment()
    env.pop("MALLOC_TRIM_THRESHOLD_", None)
    modes = {"1 (serial)": env, "2 processes": env, "default": env}
    try:
        import distributed  # noqa: F401
    except ImportError:
        args.no_dask = True
    if not args.no_dask:
        modes.update({"dask": env, "dask-untrimmed": env})
    if args.baseline:
        old = environment(checkout(args.baseline))
        modes.update({"1 [baseline]": old, "2 [baseline]": old})
        # not counted: numba compiles the unpacked revision's kernel once (its cache)
        run_mode("1 [baseline]", sweep, folder, old)
    results: dict[str, list[dict]] = {mode: [] for mode in modes}
    cli: list[float] = []
    for index in range(rounds):
        print(f"round {index + 1} of {rounds}", file=sys.stderr, flush=True)
        for mode, mode_env in modes.items():
            name = mode.split(" ")[0] if mode[0].isdigit() else mode
            if mode.endswith("[baseline]"):
                name += " [baseline]"
            results[mode].append(run_mode(name, sweep, folder, mode_env))
        cli.append(whole_process(sweep, folder, env))
    serial = results["1 (serial)"]
    table = Table(
        "mode", "workers", "sweep wall [s]", "cases/s", "vs serial", "case run time [ms]",
        "case vs 2 processes", "target",
    )  # fmt: skip
    local = median([r["per_case"] for r in results["2 processes"]])
    for mode, runs in results.items():
        wall = median([r["runtime"] for r in runs])
        speedup = median([s["runtime"] / r["runtime"] for s, r in zip(serial, runs, strict=True)])
        per_case = median([r["per_case"] for r in runs])
        workers = {r["workers"] for r in runs}
        target = f">= {TARGET:g} cases/s" if mode == "2 processes" else ""
        if mode.startswith("dask"):
            target = "case within 20 % of local"
        table.add(
            mode, ",".join(str(w) for w in sorted(workers, key=str)), f"{wall:.2f}",
            f"{CASES / wall:.1f}", f"{speedup:.2f}x", f"{per_case * 1e3:.1f}",
            f"{per_case / local:.2f}", target,
        )  # fmt: skip
    table.add(
        "`jointwear sweep` whole process, default workers", "", f"{median(cli):.2f}",
        f"{CASES / median(cli):.1f}", "", "", "", "",
    )  # fmt: skip
    work = case_work(sweep, env)
    table.add(
        "one case in one process: with pressure field and Dataset (before) -> without",
        "1", "", "", "", f"{work['old'] * 1e3:.1f} -> {work['new'] * 1e3:.1f}",
        f"ratio {work['ratio']:.2f}", "",
    )  # fmt: skip
    table.print(
        f"{CASES} cases x 15000 revolutions, adaptive updating, paper joint (NLCP); "
        f"medians of {rounds} round(s); {os.cpu_count()} cores. Machine: {machine}"
    )


if __name__ == "__main__":
    main()
