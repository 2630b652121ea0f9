"""Speed of the contact-impact dynamics: compiled right-hand side vs the Python reference.

Run from the repository root::

    python benchmarks/bench_dynamics.py            # everything, ~1 minute
    python benchmarks/bench_dynamics.py --quick    # a smoke run, ~20 s

Prints one Markdown table (median of repeats, wall-clock and CPU time of this process;
the reference and the compiled path alternate in the same run, so their ratio holds
when the machine's speed drifts). All BLAS/OpenMP pools are pinned to one thread: the
targets are for ONE core. The case is the paper's joint (``tests/data/paper_joint.toml``,
slider-crank, pull spring, 120 rpm, Lankarani-Nikravesh contact) with
``dynamics.model = "contact-impact"``. The reference is the readable Python right-hand
side (``JOINTWEAR_NO_NUMBA=1``); the straightforward integration -- Python right-hand
side and ``solve_ivp``'s own contact events -- is measured too
(:func:`tests.mechanism.impact.test_integrator.reference_contacts`).
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse  # noqa: E402
import math  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from contextlib import contextmanager  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))  # tests.mechanism.impact.test_integrator

from benchmarks.bench_simulation import (  # noqa: E402
    ROWS,
    machine,
    ms,
    numba_start_up,
    row,
)
from tests.mechanism.impact.test_integrator import reference_contacts  # noqa: E402
from tests.mechanism.slider_crank.test_contact_impact_rk import (  # noqa: E402
    SEPARATION_PRONE,  # the separation-prone slider-crank of docs/wear-feedback.md
    scar,
)

from jointwear import load_config  # noqa: E402
from jointwear.config import Config  # noqa: E402
from jointwear.mechanism.impact.integrator import integrate_contacts  # noqa: E402
from jointwear.mechanism.impact.settings import ContactImpactSettings  # noqa: E402
from jointwear.mechanism.slider_crank import contact_impact as ci  # noqa: E402
from jointwear.mechanism.slider_crank.dynamics import SliderCrank  # noqa: E402
from jointwear.mechanism.stage import mechanism_inputs  # noqa: E402

PAPER = REPO / "tests" / "data" / "paper_joint.toml"
SWITCH = "JOINTWEAR_NO_NUMBA"


def paper(**overrides) -> Config:
    return load_config(PAPER, overrides={"dynamics.model": "contact-impact", **overrides})


@contextmanager
def python_rhs():
    """The reference: the Python right-hand side (the compiled one switched off)."""
    before = os.environ.get(SWITCH)
    os.environ[SWITCH] = "1"
    try:
        yield
    finally:
        if before is None:
            del os.environ[SWITCH]
        else:
            os.environ[SWITCH] = before


def paired(reference, compiled, repeat: int):
    """Medians of wall and CPU seconds of both, run alternately after a warm-up each."""
    with python_rhs():
        reference()
    compiled()
    times: dict[str, list[tuple[float, float]]] = {"reference": [], "compiled": []}
    for _ in range(repeat):
        for name, function in (("reference", reference), ("compiled", compiled)):
            w0, c0 = time.perf_counter(), time.process_time()
            if name == "reference":
                with python_rhs():
                    function()
            else:
                function()
            times[name].append((time.perf_counter() - w0, time.process_time() - c0))
    return {name: tuple(np.median(np.array(v), axis=0)) for name, v in times.items()}


# ---------------------------------------------------------------- revolutions


def bench_revolutions(quick: bool) -> None:
    """``solve_contact_impact`` with 0 and 5 settling revolutions, reference vs compiled."""
    for settle, target in ((0, "<= 50 ms"), (5, "")):
        config = paper(**{"dynamics.revolutions_settle": settle})

        def solve(config=config):
            return ci.solve_contact_impact(mechanism_inputs(config), compare=False, compiled=True)

        result = paired(solve, solve, 5 if quick else 15)
        (ref_wall, ref_cpu), (wall, cpu) = result["reference"], result["compiled"]
        label = "one revolution" if settle == 0 else f"{settle} settling + 1 revolution"
        row(f"{label}: Python right-hand side (reference)", ms(ref_wall, ref_cpu))
        row(f"{label}: compiled right-hand side", ms(wall, cpu), target)
        row(f"{label}: speed-up", f"{ref_wall / wall:.2f}x wall, {ref_cpu / cpu:.2f}x CPU")
    config = paper(**{"dynamics.revolutions_settle": 0})
    fast = ci.solve_contact_impact(mechanism_inputs(config), compare=False, compiled=True)
    with python_rhs():
        reference = ci.solve_contact_impact(mechanism_inputs(config), compare=False, compiled=True)
    difference = np.abs(fast.load.load - reference.load.load).max() / reference.load.load.max()
    row(
        "one revolution: max |compiled - reference| / peak (normal force); RHS evaluations",
        f"{difference:.1e}; {fast.history.evaluations} vs {reference.history.evaluations}",
        "<= 1e-12",
    )


def bench_integration(quick: bool) -> None:
    """The integration alone: ``solve_ivp``'s own events + Python RHS vs this package's."""
    config = paper()
    inputs = mechanism_inputs(config)
    settings = ContactImpactSettings.from_config(config.dynamics)
    mechanism = SliderCrank.from_config(config.mechanism)
    contact = ci.slider_crank_contact(inputs, settings)
    omega = config.mechanism.crank_speed
    python = ci.SliderCrankContactSystem(mechanism, omega, contact, compiled=False)
    compiled = ci.SliderCrankContactSystem(mechanism, omega, contact)
    y0, _ = ci.initial_state(python, 360)
    period = 2 * math.pi / omega

    def straightforward():
        return reference_contacts(python, period, y0, in_contact=True, method="LSODA")

    samples = np.linspace(0.0, period, 361)

    def integrate(system, keep=None):
        return integrate_contacts(
            system, (0.0, period), y0, in_contact=True, max_step=period / 360, keep=keep
        )

    repeat = 5 if quick else 15
    result = paired(straightforward, lambda: integrate(compiled, samples), repeat)
    (ref_wall, ref_cpu), (wall, cpu) = result["reference"], result["compiled"]
    every_step = paired(lambda: integrate(python), lambda: integrate(compiled), repeat)
    label = "integration of one revolution"
    row(f"{label}: solve_ivp events + Python RHS (straightforward)", ms(ref_wall, ref_cpu))
    row(f"{label}: event watch + Python RHS", ms(*every_step["reference"]))
    row(f"{label}: event watch + compiled RHS", ms(*every_step["compiled"]))
    row(f"{label}: same, dense output kept at 361 samples only", ms(wall, cpu))
    row(
        f"{label}: speed-up over the straightforward integration",
        f"{ref_wall / wall:.2f}x wall, {ref_cpu / cpu:.2f}x CPU",
    )
    t, y = 0.1, y0
    calls = 2000 if quick else 20000
    for name, system in (("Python", python), ("compiled", compiled)):
        system.rhs(t, y, 0.01)
        w0 = time.perf_counter()
        for _ in range(calls):
            system.rhs(t, y, 0.01)
        seconds = (time.perf_counter() - w0) / calls
        row(f"one right-hand-side call, {name}", f"{seconds * 1e6:.2f} us")


# ---------------------------------------------------------------- worn joint


def bench_worn(quick: bool) -> None:
    """One solve of the dynamics on a worn contour (what a coupled run repeats), per case;
    the slider-crank with LSODA (the default) and the compiled Dormand-Prince integration
    (``dynamics.integrator = "RK45-compiled"``), alternately in the same run."""
    from jointwear.mechanism.stage import load_cycles

    wear = scar()
    compiled = {"dynamics.integrator": "RK45-compiled"}
    cases = {
        "separation-prone slider-crank (compiled RHS, LSODA)": paper(**SEPARATION_PRONE),
        "separation-prone slider-crank (RK45-compiled)": paper(**SEPARATION_PRONE, **compiled),
        "four-bar, coupler-rocker (Python RHS)": load_config(
            REPO / "examples" / "four_bar.toml",
            overrides={
                "dynamics.model": "contact-impact",
                "mechanism.clearance_joint": "coupler-rocker",
                "simulation.steps_per_revolution": 180,
            },
        ),
    }
    repeat = 2 if quick else 5
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in cases}
    extras = {}
    for config in cases.values():
        load_cycles(config, wear_depth=wear)  # compile or load the kernel, warm caches
    for _ in range(repeat):
        for name, config in cases.items():
            w0, c0 = time.perf_counter(), time.process_time()
            cycle = next(iter(load_cycles(config, wear_depth=wear).values()))
            times[name].append((time.perf_counter() - w0, time.process_time() - c0))
            extras[name] = cycle.extras
    for name in cases:
        wall, cpu = np.median(np.array(times[name]), axis=0)
        row(
            f"one solve on a worn contour: {name}",
            f"{ms(wall, cpu)} ({extras[name]['rhs_evaluations']} RHS calls, "
            f"{extras[name]['impacts']} impacts)",
            "<= 60 ms",
        )
    lsoda, fast = (np.median(np.array(times[n]), axis=0) for n in list(cases)[:2])
    row(
        "one solve on a worn contour, slider-crank: RK45-compiled speed-up over LSODA",
        f"{lsoda[0] / fast[0]:.1f}x wall, {lsoda[1] / fast[1]:.1f}x CPU",
    )


# ---------------------------------------------------------------- start-up


_START = """
import time
t0 = time.perf_counter()
from jointwear import load_config
from jointwear.mechanism.slider_crank import contact_impact as ci
from jointwear.mechanism.stage import mechanism_inputs
config = load_config({path!r}, overrides={{"dynamics.model": "contact-impact",
                                           "dynamics.revolutions_settle": 0}})
t1 = time.perf_counter()
ci.impact_kernel()
t2 = time.perf_counter()
ci.solve_contact_impact(mechanism_inputs(config), compare=False, compiled=True)
t3 = time.perf_counter()
print(t2 - t1, t3 - t2)
"""


def bench_start(quick: bool) -> None:
    """Import of the kernel and first revolution (compile or cache load), fresh processes."""
    script = _START.format(path=str(PAPER))
    compiled, loaded = numba_start_up(script, 2 if quick else 3, cwd=REPO)
    row(
        "start-up, empty numba cache: import kernel; first revolution (compiles)",
        f"{compiled[0]:.2f} s; {compiled[1]:.2f} s",
    )
    row(
        "start-up, cache filled: import kernel; first revolution",
        f"{loaded[0]:.2f} s; {loaded[1]:.2f} s",
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    parser.add_argument(
        "--only", nargs="*", default=None, help="sections: revolutions integration worn start"
    )
    args = parser.parse_args()
    chosen = args.only or ["revolutions", "integration", "worn", "start"]
    if ci.impact_kernel() is None:
        raise SystemExit("bench_dynamics: needs numba (and JOINTWEAR_NO_NUMBA unset)")
    load = os.getloadavg()
    for name in chosen:
        print(f"[{name}]", file=sys.stderr, flush=True)
        globals()[f"bench_{name}"](args.quick)
    lines = [
        f"Machine: {machine()}; load average at start {load[0]:.2f}, "
        f"at end {os.getloadavg()[0]:.2f}\n",
        "| benchmark | result | target |",
        "|---|---|---|",
        *(f"| {name} | {value} | {target} |" for name, value, target in ROWS),
    ]
    print("\n".join(lines))


if __name__ == "__main__":
    main()
