"""Speed of the wear simulation: compiled kernel and fast path vs reference, long runs, memory.

Run from the repository root::

    python benchmarks/bench_simulation.py            # everything, ~3 minutes
    python benchmarks/bench_simulation.py --quick    # a smoke run, ~30 s

Prints one Markdown table (median of repeats; wall-clock and CPU time of this
process; ratios measured in the same run). All BLAS/OpenMP pools are pinned to one
thread: the targets are for ONE core. The straightforward reference is
``tests/reference_impl.py`` (brentq per step on the full node set, plain Python
loops, Archard per step).
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse  # noqa: E402
import json  # noqa: E402
import platform  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
from benchlib import CALIBRATED, PAPER  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))  # tests.reference_impl

from tests.reference_impl import reference_revolution  # noqa: E402

from jointwear import Simulation, load_config  # noqa: E402
from jointwear.config import Config  # noqa: E402
from jointwear.geometry import BushingContour  # noqa: E402

ROWS: list[tuple[str, str, str]] = []


def paper(**overrides) -> Config:
    """The calibrated paper case with ``overrides``; a model that solves circles without
    contour update (refused with it): the kernel benchmarks step the contour themselves
    (``Simulation.step``), the flag only decides what a whole run does."""
    from jointwear.contact import CIRCULAR_ONLY

    if overrides.get("contact.model") in CIRCULAR_ONLY:
        overrides = {"simulation.update_contour": False, **overrides}
    return load_config(PAPER, overrides={**CALIBRATED, **overrides})


def timed(function, repeat: int) -> tuple[float, float]:
    """Median wall-clock and CPU seconds of ``function()`` over ``repeat`` calls."""
    function()  # warm-up (caches, lazy imports)
    wall, cpu = [], []
    for _ in range(repeat):
        w0, c0 = time.perf_counter(), time.process_time()
        function()
        wall.append(time.perf_counter() - w0)
        cpu.append(time.process_time() - c0)
    return float(np.median(wall)), float(np.median(cpu))


def row(name: str, value: str, target: str = "") -> None:
    ROWS.append((name, value, target))
    print(f"  {name}: {value}  {target}", file=sys.stderr, flush=True)


def ms(wall: float, cpu: float) -> str:
    return f"{wall * 1e3:.3g} ms (CPU {cpu * 1e3:.3g} ms)"


# ---------------------------------------------------------------- one revolution


def one_revolution(config: Config):
    """The fast path: contact of every step of one revolution + Archard wear, cold."""
    simulation = Simulation(config)
    contour = simulation.initial_contour()
    _ = simulation.load_cycle

    def fast():
        return simulation.wear_per_revolution(simulation.contact(contour))

    def reference(steps=None):
        load = simulation.load_cycle
        index = slice(None) if steps is None else steps
        return reference_revolution(
            contour.radius,
            contour.axial_length,
            simulation.pin.radius,
            load.load[index],
            load.azimuth[index],
            simulation.law,
            simulation.sliding_distance[index],
            config.materials.bushing.wear_coefficient,
        )

    return simulation, fast, reference


def bench_revolution(quick: bool) -> None:
    config = paper(**{"simulation.revolutions": 1})
    _, fast, reference = one_revolution(config)
    wall, cpu = timed(fast, 7 if quick else 31)
    ref_wall, ref_cpu = timed(reference, 2 if quick else 5)
    row("1 rev 360x360, NumPy path, cold (contact + wear)", ms(wall, cpu), "<= 2 ms")
    row("1 rev 360x360, reference (brentq per step)", ms(ref_wall, ref_cpu))
    row(
        "1 rev 360x360, speed-up cold",
        f"{ref_wall / wall:.0f}x wall, {ref_cpu / cpu:.0f}x CPU",
        ">= 60x",
    )
    # warm: one per-revolution update inside a running simulation
    sim = Simulation(paper(**{"simulation.revolutions": 15000, "simulation.update_every": 1}))
    state = sim.initial_state()
    for _ in range(20):
        state = sim.step(state)

    def update():
        nonlocal state
        state = sim.step(state)

    wall_w, cpu_w = timed(update, 50 if quick else 301)
    row("1 rev 360x360, per-revolution update in a run (warm)", ms(wall_w, cpu_w), "<= 2 ms")
    row(
        "1 rev 360x360, speed-up warm",
        f"{ref_wall / wall_w:.0f}x wall, {ref_cpu / cpu_w:.0f}x CPU",
        ">= 60x",
    )
    fast_wear = fast()
    _, ref_wear = reference()
    row(
        "1 rev 360x360, max |fast - reference| / peak (wear)",
        f"{np.abs(fast_wear - ref_wear).max() / ref_wear.max():.1e}",
        "<= 1e-9",
    )


def bench_big_revolution(quick: bool) -> None:
    nodes = steps = 1800 if quick else 3600
    config = paper(
        **{
            "simulation.revolutions": 1,
            "contact.nodes": nodes,
            "simulation.steps_per_revolution": steps,
            "contact.nlcp_variant": "mesh-independent",
        }
    )
    _, fast, reference = one_revolution(config)
    wall, cpu = timed(fast, 2 if quick else 5)
    subset = np.arange(0, steps, steps // 36)  # 36 steps spread over the revolution
    ref_wall, ref_cpu = timed(lambda: reference(subset), 1 if quick else 2)
    scale = steps / subset.size
    row(f"1 rev {nodes}x{steps}, fast path, cold", ms(wall, cpu))
    row(
        f"1 rev {nodes}x{steps}, reference (estimated from {subset.size} steps x {scale:.0f})",
        ms(ref_wall * scale, ref_cpu * scale),
    )
    row(
        f"1 rev {nodes}x{steps}, speed-up",
        f"{ref_wall * scale / wall:.0f}x wall, {ref_cpu * scale / cpu:.0f}x CPU",
    )


# ---------------------------------------------------------------- the compiled kernel


KERNEL_MODELS = ("winkler", "asymmetric-winkler", "nlcp")


def kernel_inputs(config: Config, warm_revolutions: int = 0):
    """A simulation of ``config`` and its contour after ``warm_revolutions`` updates."""
    simulation = Simulation(config)
    # the kernel where it can, as in a long run (a circular model's config has no contour
    # update, which alone would choose the NumPy path)
    simulation.solver.compiled = None
    state = simulation.initial_state()
    for _ in range(warm_revolutions):
        state = simulation.step(state)
    return simulation, state


def bench_kernel(quick: bool) -> None:
    """revolution_wear against the reference, per model: cold, warm, evaluation counts."""
    from jointwear.contact.kernel import compiled_available

    row("compiled kernel available (numba)", str(compiled_available()))
    for model in KERNEL_MODELS:
        _bench_kernel_model(model, quick)
    config = paper(**{"contact.model": "hertz", "simulation.revolutions": 1})
    simulation = Simulation(config)
    contour = simulation.initial_contour()
    _ = simulation.load_cycle
    wall, cpu = timed(lambda: simulation.contact(contour), 7 if quick else 31)
    row("hertz: one revolution 360x360 (contact, dense pressure)", ms(wall, cpu), "<= 3 ms")


def _bench_kernel_model(model: str, quick: bool) -> None:
    """Cold and warm kernel revolutions of one model against the reference."""
    from jointwear.contact.kernel import revolution_wear

    repeat = 31 if quick else 201
    config = paper(
        **{
            "contact.model": model,
            "simulation.revolutions": 15000,
            "simulation.update_every": 1,
        }
    )
    simulation, state = kernel_inputs(config, 20)
    contour = simulation.initial_contour()
    load = simulation.load_cycle
    k_d = config.materials.bushing.wear_coefficient
    args = (contour, simulation.pin, load.load, load.azimuth, simulation.sliding_distance)
    options = {"max_penetration": config.joint.bushing_thickness}

    def cold():
        return revolution_wear(*args, simulation.law, k_d, **options)

    worn = simulation.solver.contour(state.wear_depth)

    def warm():
        # what a per-revolution update solves: the extrapolated offsets of the last one
        return simulation.wear_per_revolution(simulation.contact(worn, state))

    def reference():
        return reference_revolution(
            contour.radius, contour.axial_length, simulation.pin.radius, load.load,
            load.azimuth, simulation.law, simulation.sliding_distance, k_d,
        )  # fmt: skip

    wall, cpu = timed(cold, repeat)
    warm_wall, warm_cpu = timed(warm, repeat)
    ref_wall, ref_cpu = timed(reference, 2 if quick else 5)
    row(f"{model}: reference revolution 360x360 (brentq per step)", ms(ref_wall, ref_cpu))
    row(
        f"{model}: kernel, cold revolution (contact + wear)",
        f"{ms(wall, cpu)}; {ref_wall / wall:.0f}x wall, {ref_cpu / cpu:.0f}x CPU",
        ">= 500x",
    )
    row(
        f"{model}: kernel, warm revolution in a run (contact + wear)",
        f"{ms(warm_wall, warm_cpu)}; {ref_wall / warm_wall:.0f}x wall, "
        f"{ref_cpu / warm_cpu:.0f}x CPU",
        ">= 800x",
    )
    result = cold()
    _, ref_wear = reference()
    numpy_path = revolution_wear(*args, simulation.law, k_d, compiled=False, **options)
    row(
        f"{model}: max |kernel - reference| / peak (wear); kernel vs NumPy path",
        f"{np.abs(result.wear - ref_wear).max() / ref_wear.max():.1e}; "
        f"{np.abs(result.wear - numpy_path.wear).max() / numpy_path.wear.max():.1e}",
        "<= 1e-12 vs NumPy path",
    )


def bench_evaluations(quick: bool) -> None:
    """Residual evaluations per load: what keeps a solve short (no physics is asserted here;
    the tests hold every solve to its balance and to the reference)."""
    from tests.test_fast_path import contour_for

    from jointwear.contact import balance as load_balance
    from jointwear.contact import solve as solve_named
    from jointwear.contact.kernel import revolution_wear

    def counts(iterations) -> str:
        return f"mean {iterations.mean():.2f}, max {iterations.max()}"

    table5 = paper(**{"simulation.revolutions": 20, "simulation.update_every": 1})
    for model in KERNEL_MODELS:
        simulation, state = kernel_inputs(
            paper(**{"simulation.revolutions": 20, "simulation.update_every": 1,
                     "contact.model": model}), 6,
        )  # fmt: skip
        load = simulation.load_cycle
        k_d = table5.materials.bushing.wear_coefficient
        args = (
            simulation.initial_contour(), simulation.pin, load.load, load.azimuth,
            simulation.sliding_distance, simulation.law, k_d,
        )  # fmt: skip
        cold = revolution_wear(*args, max_penetration=table5.joint.bushing_thickness)
        worn = simulation.solver.contour(state.wear_depth)
        warm = simulation.contact(worn, state)
        row(
            f"evaluations per load, {model}, kernel: cold circle / warm in a run",
            f"{counts(cold.iterations)} / {counts(warm.iterations)}",
            "cold ~2-3, warm 2",
        )
        numpy_warm = revolution_wear(
            worn, *args[1:], max_penetration=table5.joint.bushing_thickness,
            initial_offset=state.warm_offset + state.warm_slope, compiled=False,
        )  # fmt: skip
        coarse = simulation.contact(contour_for(simulation, "worn"))
        row(
            f"evaluations per load, {model}, NumPy path: warm in a run / cold worn (coarse pass)",
            f"{counts(numpy_warm.iterations)} / {counts(coarse.iterations)}",
            "warm <= 2.05 (mean), coarse <= 3.0 (mean)",
        )
    simulation = Simulation(table5)
    cold = simulation.contact(simulation.initial_contour())
    row(
        "evaluations per load, nlcp, NumPy path, cold circle: share with 2, max",
        f"{np.mean(cold.iterations == 2):.3f}, {cold.iterations.max()}",
        ">= 0.95, <= 3",
    )
    # a generic batch on the paper's joint, 20 % zero loads
    params = simulation.parameters
    pin = simulation.pin
    circle = BushingContour.circle(params.bushing_radius, 360, params.axial_length)
    t = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    loads = 275 + 125 * np.sin(t) + 20 * np.sin(3 * t)
    loads[::37] = 0.0
    azimuth = np.radians(180 + 30 * np.sin(t))
    batch = load_balance.solve_contact(circle, pin, loads, azimuth, simulation.law)
    row(
        "evaluations per load, nlcp, NumPy path, cold circle with zero loads: share with 2, max",
        f"{np.mean(batch.iterations[loads > 0] == 2):.3f}, {batch.iterations.max()}",
        ">= 0.95, <= 8",
    )
    worn = contour_for(simulation, "worn")
    few = np.linspace(50, 400, 20)
    angles = np.radians(np.linspace(-25, 25, 20))
    exact = solve_named(worn, pin, few, angles, "nlcp", params)
    along = exact.eccentricity[:, 0] * np.cos(angles) + exact.eccentricity[:, 1] * np.sin(angles)
    again = solve_named(worn, pin, few, angles, "nlcp", params, initial_offset=along)
    row(
        "evaluations per load, nlcp, NumPy path, started on the root: max",
        f"{again.iterations.max()}",
        "<= 2",
    )


def bench_kernel_linearity(quick: bool) -> None:
    """Cost of a cold kernel revolution against nodes and steps, up to 5760."""
    from jointwear.contact.kernel import revolution_wear

    sizes = [360, 720, 1440] if quick else [360, 720, 1440, 2880, 5760]
    base = None
    for key, label in (("contact.nodes", "nodes"), ("simulation.steps_per_revolution", "steps")):
        cells = []
        for size in sizes:
            config = paper(
                **{
                    "simulation.revolutions": 1,
                    "contact.nlcp_variant": "mesh-independent",
                    key: size,
                }
            )
            simulation = Simulation(config)
            contour = simulation.initial_contour()
            load = simulation.load_cycle
            args = (
                contour, simulation.pin, load.load, load.azimuth, simulation.sliding_distance,
                simulation.law, config.materials.bushing.wear_coefficient,
            )  # fmt: skip
            _, cpu = timed(lambda args=args: revolution_wear(*args), 3 if quick else 9)
            base = cpu if size == 360 else base
            cells.append(f"{size}: {cpu * 1e3:.3g} ms ({cpu / base * 360 / size:.2f})")
        row(
            f"kernel, cold revolution vs {label} (other at 360): CPU (cost per "
            f"{label[:-1]} / at 360)",
            ", ".join(cells),
            "linear: ratios <= 1",
        )
    if quick:
        return
    out = subprocess.run(
        [sys.executable, "-c", _BIG_SCRIPT, str(PAPER), json.dumps(CALIBRATED)],
        capture_output=True, text=True, check=True, cwd=REPO,
    )  # fmt: skip
    big = json.loads(out.stdout.strip().splitlines()[-1])
    row(
        "kernel, cold revolution 5760 x 5760 (fresh process; median of 3)",
        f"{big['seconds'] * 1e3:.0f} ms, peak RSS {big['maxrss_kb'] / 1024:.0f} MB "
        f"(after imports {big['baseline_kb'] / 1024:.0f} MB)",
        "<= 400 MB",
    )


_BIG_SCRIPT = """
import json, sys, time
from jointwear import Simulation, load_config
from jointwear.contact.kernel import revolution_wear

def peak_rss_kb():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmHWM:"):
                return int(line.split()[1])

overrides = {**json.loads(sys.argv[2]), "simulation.revolutions": 1, "contact.nodes": 5760,
             "simulation.steps_per_revolution": 5760, "contact.nlcp_variant": "mesh-independent"}
config = load_config(sys.argv[1], overrides=overrides)
simulation = Simulation(config)
contour = simulation.initial_contour()
load = simulation.load_cycle
args = (contour, simulation.pin, load.load, load.azimuth, simulation.sliding_distance,
        simulation.law, config.materials.bushing.wear_coefficient)
baseline = peak_rss_kb()
times = []
for _ in range(3):
    t0 = time.perf_counter()
    revolution_wear(*args)
    times.append(time.perf_counter() - t0)
result = {"seconds": sorted(times)[1], "maxrss_kb": peak_rss_kb(), "baseline_kb": baseline}
print(json.dumps(result))
"""


def numba_start_up(script: str, runs: int, cwd: Path | None = None):
    """The two numbers ``script`` prints, in ``runs`` fresh processes sharing one empty
    numba cache: those of the first (it compiles) and the medians of the others (the
    cache loaded)."""
    with tempfile.TemporaryDirectory() as cache:
        numbers = []
        for _ in range(runs):
            out = subprocess.run(
                [sys.executable, "-c", script], capture_output=True, text=True, check=True,
                env={**os.environ, "NUMBA_CACHE_DIR": cache}, cwd=cwd,
            )  # fmt: skip
            numbers.append(tuple(map(float, out.stdout.split())))
    return numbers[0], np.median(numbers[1:], axis=0)


def bench_kernel_start(quick: bool) -> None:
    """Import and compile cost of the kernel, in fresh processes."""
    script = (
        "import time; t0 = time.perf_counter(); import numba; t1 = time.perf_counter(); "
        "from jointwear.contact import kernel; kernel._compiled(); import numpy as np; "
        "from jointwear.geometry import BushingContour, Pin; "
        "from jointwear.contact.laws import PowerLaw; "
        "c = BushingContour.circle(7.5e-3, 360, 0.02); "
        "t2 = time.perf_counter(); "
        "kernel.revolution_wear(c, Pin(7.45e-3), np.full(8, 200.0), np.linspace(0, 6, 8), "
        "np.full(8, 1e-4), PowerLaw(1e14, 1.5, force_area=1e-6), 1e-13); "
        "t3 = time.perf_counter(); print(t1 - t0, t3 - t2)"
    )
    compiled, loaded = numba_start_up(script, 3)
    row(
        "kernel start-up: import numba; first revolution (compile, empty cache)",
        f"{compiled[0]:.2f} s; {compiled[1]:.2f} s",
    )
    row(
        "kernel start-up: import numba; first revolution (cache loaded)",
        f"{loaded[0]:.2f} s; {loaded[1]:.2f} s",
    )


# ---------------------------------------------------------------- long runs


_RUN_SCRIPT = """
import os, json, resource, sys, time, tracemalloc
for n in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[n] = "1"

def peak_rss_kb():
    # VmHWM: peak resident set of this process image (ru_maxrss survives exec on
    # Linux and would report the parent's peak)
    try:
        with open("/proc/self/status") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
from jointwear import Simulation, load_config
overrides = json.loads(sys.argv[2])
trace = sys.argv[3] == "trace"
config = load_config(sys.argv[1], overrides=overrides)
simulation = Simulation(config)
_ = simulation.load_cycle
import jointwear.results  # xarray: imported by every run's end, not the simulation's cost
baseline = peak_rss_kb()
if trace:
    tracemalloc.start()
w0, c0 = time.perf_counter(), time.process_time()
result = simulation.run()
wall, cpu = time.perf_counter() - w0, time.process_time() - c0
peak = tracemalloc.get_traced_memory()[1] if trace else 0
summary = result.summary()
print(json.dumps({
    "wall": wall, "cpu": cpu, "maxrss_kb": peak_rss_kb(),
    "baseline_rss_kb": baseline, "traced_peak": peak,
    "profiles": int(result.dataset.sizes["revolution"]),
    "peak": summary["peak_wear_depth_m"], "mass": summary["wear_mass_kg"],
    "updates": summary["contour_updates"],
}))
"""


def run_case(overrides: dict, trace: bool = False) -> dict:
    """One run in a fresh interpreter (clean peak-memory figures)."""
    out = subprocess.run(
        [
            sys.executable,
            "-c",
            _RUN_SCRIPT,
            str(PAPER),
            json.dumps({**CALIBRATED, **overrides}),
            "trace" if trace else "plain",
        ],
        capture_output=True,
        text=True,
        check=True,
        cwd=REPO,
    )
    return json.loads(out.stdout.strip().splitlines()[-1])


def bench_long_runs(quick: bool) -> None:
    revolutions = 1500 if quick else 15000
    every = [
        run_case(
            {
                "simulation.revolutions": revolutions,
                "simulation.update_every": 1,
                "simulation.saved_profiles": 100,
            }
        )
        for _ in range(1 if quick else 3)
    ]
    per_rev = every[0]
    walls = sorted(r["wall"] for r in every)
    row(
        f"Table 5, {revolutions} rev, update every revolution (100 profiles saved; "
        f"median of {len(every)} processes, range)",
        f"{np.median(walls):.3f} s (CPU {np.median([r['cpu'] for r in every]):.3f} s; "
        f"{walls[0]:.3f}-{walls[-1]:.3f} s)",
        "<= 3 s" if revolutions == 15000 else "",
    )
    row(
        "  peak memory of that run (peak RSS, VmHWM; after imports "
        f"{per_rev['baseline_rss_kb'] / 1024:.0f} MB)",
        f"{per_rev['maxrss_kb'] / 1024:.0f} MB",
        "<= 200 MB",
    )
    runs = [
        run_case({"simulation.revolutions": revolutions, "simulation.saved_profiles": 100})
        for _ in range(3 if quick else 5)
    ]
    adaptive = runs[0]
    wall = float(np.median([r["wall"] for r in runs]))
    cpu = float(np.median([r["cpu"] for r in runs]))
    row(
        f"Table 5, {revolutions} rev, adaptive jumping ({adaptive['updates']} updates)",
        f"{wall:.3f} s (CPU {cpu:.3f} s)",
        "<= 0.5 s" if revolutions == 15000 else "",
    )
    peak = adaptive["peak"] / per_rev["peak"] - 1
    mass = adaptive["mass"] / per_rev["mass"] - 1
    row(
        "  adaptive vs per-revolution: peak, mass",
        f"{peak * 100:+.3f} %, {mass * 100:+.3f} %",
        "within 0.5 %",
    )
    deep = 100_000 if quick else 1_000_000
    runs = [
        run_case(
            {
                "simulation.revolutions": deep,
                "joint.bushing_thickness": "20 mm",
                "simulation.saved_profiles": 100,
            }
        )
        for _ in range(1 if quick else 3)
    ]
    row(
        f"thick wall (20 mm), {deep} rev, adaptive ({runs[0]['updates']} updates, peak "
        f"{runs[0]['peak'] * 1e3:.2f} mm)",
        f"{np.median([r['wall'] for r in runs]):.3f} s "
        f"(CPU {np.median([r['cpu'] for r in runs]):.3f} s)",
        "<= 1.5 s" if deep == 1_000_000 else "",
    )
    traced = run_case(
        {"simulation.revolutions": revolutions, "simulation.saved_profiles": 100}, trace=True
    )
    row(
        "  adaptive run, tracemalloc peak / peak RSS",
        f"{traced['traced_peak'] / 2**20:.1f} MB / {traced['maxrss_kb'] / 1024:.0f} MB",
        "<= 200 MB",
    )


# ---------------------------------------------------------------- linearity


def bench_linearity(quick: bool) -> None:
    sizes = [180, 360, 720] if quick else [180, 360, 720, 1440]
    repeat = 3 if quick else 7
    for key, label in (("contact.nodes", "nodes"), ("simulation.steps_per_revolution", "steps")):
        times = []
        for size in sizes:
            config = paper(
                **{
                    "simulation.revolutions": 1,
                    "contact.nlcp_variant": "mesh-independent",
                    key: size,
                }
            )
            _, fast, _ = one_revolution(config)
            times.append(timed(fast, repeat))
        base = times[sizes.index(360)][1]
        cells = ", ".join(
            f"{size}: {cpu * 1e3:.3g} ms ({cpu / base * 360 / size:.2f})"
            for size, (_, cpu) in zip(sizes, times, strict=True)
        )
        row(
            f"one revolution vs {label} (other at 360): CPU (cost per {label[:-1]} / at 360)",
            cells,
            "linear: ratios ~1",
        )


# ---------------------------------------------------------------- cold start


_COLD_SCRIPT = """
import time
t0 = time.perf_counter()
import jointwear.cli
from jointwear.simulation import Simulation
from jointwear.config import load_config
t1 = time.perf_counter()
import sys
simulation = Simulation(load_config(sys.argv[1]))
state = simulation.step(simulation.initial_state())
t2 = time.perf_counter()
print(t1 - t0, t2 - t0)
"""


def bench_cold_start(quick: bool) -> None:
    env = {**os.environ}
    with tempfile.TemporaryDirectory() as tmp:
        one = Path(tmp) / "one.toml"
        text = PAPER.read_text(encoding="utf-8")
        text = text.replace("revolutions = 15000", "revolutions = 1").replace(
            'update_every = "adaptive"', "update_every = 1"
        )
        one.write_text(text, encoding="utf-8")
        imports, first = [], []
        for _ in range(3 if quick else 7):
            out = subprocess.run(
                [sys.executable, "-c", _COLD_SCRIPT, str(one)],
                capture_output=True,
                text=True,
                check=True,
                env=env,
            )
            a, b = map(float, out.stdout.split())
            imports.append(a)
            first.append(b)
        cli = []
        for _ in range(3 if quick else 5):
            w0 = time.perf_counter()
            subprocess.run(
                [sys.executable, "-m", "jointwear", "run", str(one), "--json", "--quiet"],
                capture_output=True,
                check=True,
                env=env,
            )
            cli.append(time.perf_counter() - w0)
    row(
        "cold start: import jointwear.cli -> first revolution done",
        f"{np.median(first):.2f} s (imports {np.median(imports):.2f} s)",
        "<= 1.5 s",
    )
    row(
        "cold start: `jointwear run one-revolution.toml --json`, whole process",
        f"{np.median(cli):.2f} s",
    )


def machine() -> str:
    model = platform.processor() or platform.machine()
    try:
        for line in subprocess.run(["lscpu"], capture_output=True, text=True).stdout.splitlines():
            if line.startswith("Model name:"):
                model = line.split(":", 1)[1].strip()
    except OSError:
        pass
    return (
        f"{model}, {os.cpu_count()} cores; Python {platform.python_version()}, "
        f"NumPy {np.__version__}; 1 BLAS/OpenMP thread"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="smaller sizes, fewer repeats")
    parser.add_argument(
        "--only",
        nargs="*",
        default=None,
        help=(
            "sections: kernel evaluations kernel-linearity kernel-start revolution big long "
            "linearity cold"
        ),
    )
    args = parser.parse_args()
    sections = {
        "kernel": bench_kernel,
        "evaluations": bench_evaluations,
        "kernel-linearity": bench_kernel_linearity,
        "kernel-start": bench_kernel_start,
        "revolution": bench_revolution,
        "big": bench_big_revolution,
        "long": bench_long_runs,
        "linearity": bench_linearity,
        "cold": bench_cold_start,
    }
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    for name, function in sections.items():
        if args.only is None or name in args.only:
            print(f"[{name}]", file=sys.stderr, flush=True)
            function(args.quick)
    print(f"Machine: {machine()}; load average at start {load:.2f}\n")
    print("| benchmark | result | target |")
    print("|---|---|---|")
    for name, value, target in ROWS:
        print(f"| {name} | {value} | {target} |")


if __name__ == "__main__":
    main()
