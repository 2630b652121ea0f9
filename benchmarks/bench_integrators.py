"""Accuracy and cost of the contact-impact integrators: what ``dynamics.integrator = "auto"`` picks.

Run from the repository root::

    python benchmarks/bench_integrators.py            # three joints, ~2 minutes of CPU
    python benchmarks/bench_integrators.py --quick    # the paper's joint only

For each joint, LSODA and ``RK45-compiled`` at the default tolerances (rtol 1e-8, a
separating solve again at ``dynamics.separation_rtol`` 1e-10) against a converged
solution (LSODA at rtol 1e-12, atol 1e-14; ``RK45-compiled`` there as a cross-check):
the largest difference of the sampled normal-force vectors over their peak, the peak
contact force, the wear of one revolution on the joint's contour (peak depth and volume,
the solver's wear per revolution) and the CPU time of one solve (the worn dynamics of a
run, 2 settling + 1 recorded revolution; median of 3, the two integrators alternating,
after a warm-up that loads the compiled code). The joints: the paper's
(``tests/data/paper_joint.toml``, contact-impact), the separation-prone slider-crank of
``tests/mechanism/slider_crank/test_contact_impact_rk.py`` unworn and worn by its 30 um
scar. Prints one Markdown table.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))  # tests.mechanism.slider_crank.test_contact_impact_rk

from benchmarks.bench_simulation import machine  # noqa: E402
from tests.mechanism.slider_crank.test_contact_impact_rk import (  # noqa: E402
    SEPARATION_PRONE,
    scar,
)

from jointwear import Simulation, load_config  # noqa: E402
from jointwear.config import Config  # noqa: E402
from jointwear.coupling.dynamics import worn_cycle  # noqa: E402

PAPER = REPO / "tests" / "data" / "paper_joint.toml"
DEFAULTS = {
    "LSODA": {"dynamics.integrator": "LSODA"},
    "RK45-compiled": {"dynamics.integrator": "RK45-compiled"},
}
TIGHT = {"dynamics.rtol": 1e-12, "dynamics.atol": 1e-14}
REFERENCE = {"dynamics.integrator": "LSODA", **TIGHT}
CROSS_CHECK = {"dynamics.integrator": "RK45-compiled", **TIGHT}


def solve(config: Config, wear: np.ndarray) -> dict:
    """The worn dynamics (CPU timed) and one revolution's wear on that contour."""
    started = time.process_time()
    cycle = worn_cycle(config, None, wear)
    cpu = time.process_time() - started
    simulation = Simulation(config, load_cycle=cycle)
    contour = simulation.solver.contour(wear)
    depth = simulation.wear_per_revolution(simulation.solver.solve(contour, cycle))
    return {
        "cpu": cpu,
        "vectors": cycle.load * np.exp(1j * cycle.azimuth),
        "peak_load": cycle.extras["peak_load_n"],
        "peak_depth": float(depth.max()),
        "volume": float(np.sum(depth * contour.spring_area)),
        "impacts": cycle.extras["impacts"],
    }


def errors(found: dict, reference: dict) -> list[str]:
    """Relative errors of ``found`` against ``reference``, as table cells."""
    scale = np.abs(reference["vectors"]).max()
    history = np.abs(found["vectors"] - reference["vectors"]).max() / scale
    cells = [f"{history:.1e}"]
    for key in ("peak_load", "peak_depth", "volume"):
        cells.append(f"{found[key] / reference[key] - 1:+.1e}")
    return cells


def bench_joint(name: str, config: Config, wear: np.ndarray, repeat: int) -> list[str]:
    """Table rows of one joint: both defaults and the cross-check against the reference."""
    reference = solve(config.replace(REFERENCE), wear)
    runs: dict[str, list[dict]] = {label: [] for label in DEFAULTS}
    for _ in range(repeat):
        for label, overrides in DEFAULTS.items():
            runs[label].append(solve(config.replace(overrides), wear))
    rows = []
    for label, found in runs.items():
        cpu = float(np.median([run["cpu"] for run in found]))
        cells = [name, label, *errors(found[0], reference), str(found[0]["impacts"])]
        rows.append("| " + " | ".join([*cells, f"{cpu * 1e3:.0f} ms"]) + " |")
    check = solve(config.replace(CROSS_CHECK), wear)
    cells = [name, "RK45-compiled, rtol 1e-12", *errors(check, reference), str(check["impacts"])]
    rows.append("| " + " | ".join([*cells, f"{check['cpu'] * 1e3:.0f} ms"]) + " |")
    for line in rows:
        print("  " + line, file=sys.stderr, flush=True)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="the paper's joint only")
    args = parser.parse_args()
    warnings.simplefilter("ignore")  # the separation-prone joint's contact-loss warning
    paper = load_config(PAPER, overrides={"dynamics.model": "contact-impact"})
    nodes = paper.contact.nodes
    joints = {"paper": (paper, np.zeros(nodes))}
    if not args.quick:
        separating = paper.replace(SEPARATION_PRONE)
        joints["separation-prone, unworn"] = (separating, np.zeros(nodes))
        joints["separation-prone, 30 um scar"] = (separating, scar(nodes))
    for overrides in DEFAULTS.values():  # load (or compile) the kernels before timing
        solve(paper.replace(overrides), np.zeros(nodes))
    load = os.getloadavg()
    rows = [row for name, (c, w) in joints.items() for row in bench_joint(name, c, w, 3)]
    print(
        f"Machine: {machine()}; load average at start {load[0]:.2f}, "
        f"at end {os.getloadavg()[0]:.2f}\n\n"
        "Against LSODA at rtol 1e-12 (relative; force history: largest difference of the "
        "normal-force vectors over their peak):\n"
    )
    print(
        "| joint | integrator | force history | peak force | peak wear | worn volume "
        "| impacts | CPU per solve |"
    )
    print("|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))


if __name__ == "__main__":
    main()
