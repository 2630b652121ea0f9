"""How well the separating coupled run's peak wear is defined: a convergence study.

Run from the repository root::

    python benchmarks/study_separating_tolerance.py              # 21 runs, ~5-10 minutes
    python benchmarks/study_separating_tolerance.py --jobs 1     # one run at a time
    python benchmarks/study_separating_tolerance.py --only rtol  # one group

The case is ``bench_coupled.py``'s: the separation-prone slider-crank, contact-impact,
``RK45-compiled``, 10^5 revolutions, contour and dynamics updated adaptively. Each row is
a whole ``jointwear run`` with the integration of its separating solves changed:
``dynamics.separation_rtol`` from 1e-6 to 1e-12 (looser than the run's ``rtol`` = 1e-8:
``rtol``, ``atol`` and ``separation_rtol`` together), ``dynamics.revolutions_settle`` 0-4,
and perturbations of the tight reference (rtol 1e-12, 2 settling revolutions) that are
as converged as it is (rtol 0.9e-12 and 1.1e-12, 3 settling revolutions). Their spread is
the scatter the peak wear has whatever the tolerance: the separating trajectory is not
periodic, and what moves it by a rounding error moves the 10^5-revolution wear by ~1e-3.
The table gives the peak wear depth, its difference from the reference, the dynamics
solves and the process's CPU time (user + system); results are appended to
``--results`` (JSON lines) as they come, and rows already there are not run again.
The results: ``docs/wear-feedback.md``, *How well a separating run is defined*.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path

from bench_coupled import run_command, timed
from benchlib import SRC, describe_machine, environment

#: the reference: the separating solves at rtol 1e-12 (atol scaled alike), 2 settling
REFERENCE = "rtol 1e-12 (reference)"


def loose(rtol: float) -> dict[str, str]:
    """The whole solve at ``rtol`` (looser than the run's 1e-8), ``atol`` scaled alike."""
    return {
        "dynamics.rtol": f"{rtol:g}",
        "dynamics.atol": f"{rtol * 1e-2:g}",
        "dynamics.separation_rtol": f"{rtol:g}",
    }


def separating(rtol: float, settle: int | None = None) -> dict[str, str]:
    """The separating solves at ``rtol``, optionally with ``settle`` settling revolutions."""
    out = {"dynamics.separation_rtol": f"{rtol:g}"}
    if settle is not None:
        out["dynamics.revolutions_settle"] = str(settle)
    return out


#: group -> row -> overrides of the benchmark's case
VARIANTS: dict[str, dict[str, dict[str, str]]] = {
    "rtol": {
        "rtol 1e-6 throughout": loose(1e-6),
        "rtol 1e-7 throughout": loose(1e-7),
        "rtol 1e-8, one pass (now)": separating(1e-8),
        "rtol 1e-9": separating(1e-9),
        "rtol 1e-10 (before)": separating(1e-10),
        "rtol 1e-11": separating(1e-11),
        REFERENCE: separating(1e-12),
    },
    "scatter": {
        "rtol 0.9e-12": separating(0.9e-12),
        "rtol 1.1e-12": separating(1.1e-12),
        "rtol 1e-12, 3 settling": separating(1e-12, 3),
        "rtol 1e-11, 3 settling": separating(1e-11, 3),
        "rtol 0.9e-10": separating(0.9e-10),
        "rtol 1.1e-10": separating(1.1e-10),
    },
    "settle": {
        "rtol 1e-10, 0 settling": separating(1e-10, 0),
        "rtol 1e-10, 1 settling": separating(1e-10, 1),
        "rtol 1e-10, 3 settling": separating(1e-10, 3),
        "rtol 1e-10, 4 settling": separating(1e-10, 4),
    },
    "cheap": {
        "rtol 1e-8, 1 settling": separating(1e-8, 1),
        "rtol 1e-9, 1 settling": separating(1e-9, 1),
        "rtol 1e-8, 3 settling": separating(1e-8, 3),
        "rtol 0.9e-8 throughout": loose(0.9e-8),
    },
}


def one_run(name: str, overrides: dict[str, str]) -> dict[str, object]:
    command = run_command()
    for key, value in overrides.items():
        command += ["--set", f"{key}={value}"]
    wall, cpu, out = timed_alone(command)
    summary = json.loads(out)
    return {
        "name": name,
        "overrides": overrides,
        "peak_wear_depth_m": summary["peak_wear_depth_m"],
        "wear_volume_m3": summary["wear_volume_m3"],
        "dynamics_updates": summary["dynamics_updates"],
        "cpu_s": cpu,
        "wall_s": wall,
    }


def timed_alone(command: list[str]) -> tuple[float, float, str]:
    """Wall and CPU seconds of one process, its own (``wait4``: runs side by side in
    threads would each be charged the other's CPU under ``RUSAGE_CHILDREN``)."""
    began = time.perf_counter()
    with subprocess.Popen(
        command, env=environment(SRC), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
    ) as process:
        reader = ThreadPoolExecutor(2)
        out, err = reader.submit(process.stdout.read), reader.submit(process.stderr.read)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
        reader.shutdown()
    wall = time.perf_counter() - began
    if process.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed: {err.result()[-800:]}")
    return wall, usage.ru_utime + usage.ru_stime, out.result()


def table(rows: dict[str, dict[str, object]]) -> str:
    reference = rows.get(REFERENCE)
    lines = [
        "| separating solves | peak wear [mm] | vs reference | volume vs reference "
        "| dynamics solves | CPU [s] |",
        "|---|---|---|---|---|---|",
    ]
    for group in VARIANTS.values():
        for name in group:
            row = rows.get(name)
            if row is None:
                continue
            peak = float(row["peak_wear_depth_m"])
            cpu = "" if row["cpu_s"] is None else f"{float(row['cpu_s']):.2f}"
            volume = float(row["wear_volume_m3"])
            versus = vol = ""
            if reference is not None:
                versus = f"{peak / float(reference['peak_wear_depth_m']) - 1:+.2e}"
                vol = f"{volume / float(reference['wear_volume_m3']) - 1:+.2e}"
            lines.append(
                f"| {name} | {peak * 1e3:.5f} | {versus} | {vol} | {row['dynamics_updates']} "
                f"| {cpu} |"
            )
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (default 2)")
    parser.add_argument("--only", nargs="*", default=list(VARIANTS), help=" ".join(VARIANTS))
    parser.add_argument(
        "--results", type=Path, default=Path("separating-tolerance.jsonl"), help="JSON lines"
    )
    args = parser.parse_args()
    rows: dict[str, dict[str, object]] = {}
    if args.results.is_file():
        for line in args.results.read_text().splitlines():
            row = json.loads(line)
            rows[row["name"]] = row
    todo = [
        (name, overrides)
        for group in args.only
        for name, overrides in VARIANTS[group].items()
        if name not in rows
    ]
    start = describe_machine()
    timed(run_command(), environment(SRC))  # warm-up: the numba cache of this tree
    with ThreadPoolExecutor(args.jobs) as pool, args.results.open("a") as handle:
        for future in as_completed([pool.submit(one_run, *item) for item in todo]):
            row = future.result()
            rows[str(row["name"])] = row
            handle.write(json.dumps(row) + "\n")
            handle.flush()
            print(f"  {row['name']}: {row['peak_wear_depth_m']!r} m", file=sys.stderr)
    print(f"Machine at start: {start}\nMachine at end: {describe_machine()}\n")
    print(table(rows))


if __name__ == "__main__":
    main()
