"""Speed of a wearing pin along the pin (``joint.axial_slices`` with
``materials.pin.wear_coefficient``) against the planar wearing pin and the rigid pin.

Run from the repository root::

    python benchmarks/bench_pin_slices.py            # everything, ~1 minute
    python benchmarks/bench_pin_slices.py --quick    # a smoke run

Prints one Markdown table: the median CPU time of one warm contour update
(``Simulation.step``, updated every revolution, the pin already worn so every step is
solved on its own contour) of the calibrated paper case (NLCP, 360 steps, 360 nodes), a
bore out of line by 0.2 mrad, for the planar wearing pin and for ``N`` slices with a
wearing pin, taking turns, and the median of their paired ratios; and the same slices
with a rigid pin. All BLAS/OpenMP pools are pinned to one thread."""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_name] = "1"

import argparse  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402

from benchlib import CALIBRATED, PAPER, Table, describe_machine, median, paired_ratio  # noqa: E402

from jointwear import Simulation, load_config  # noqa: E402

#: the pin's wear coefficient [1/Pa] (a fiftieth of the PTFE bushing's)
PIN_WEAR = 1e-14


def warm(slices: int, pin_wear: float | None):
    """A simulation of ``slices`` slices (1: planar) and its state three contour updates
    in: the kernel loaded, the warm starts set, the pin (where it wears) worn."""
    overrides = {
        **CALIBRATED,
        "simulation.revolutions": 15000,
        "simulation.update_every": 1,
        "materials.pin.wear_coefficient": pin_wear,
    }
    if slices > 1:
        overrides.update({"joint.axial_slices": slices, "joint.misalignment": 2e-4})
    simulation = Simulation(load_config(PAPER, overrides=overrides))
    state = simulation.initial_state()
    simulation.load.resume(state)
    for _ in range(3):
        state = simulation.step(state)
    return simulation, state


def paired(first, second, repeat: int) -> tuple[list[float], list[float]]:
    """CPU seconds of ``repeat`` contour updates of two warm runs, taking turns."""
    runs = [list(first), list(second)]
    times: tuple[list[float], list[float]] = ([], [])
    for _ in range(repeat):
        for run, spent in zip(runs, times, strict=True):
            began = time.process_time()
            run[1] = run[0].step(run[1])
            spent.append(time.process_time() - began)
    return times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    repeat = 3 if parser.parse_args().quick else 10
    warnings.simplefilter("ignore")
    print(describe_machine(), file=sys.stderr)
    table = Table("what", "CPU per revolution", "against")
    for slices in (5, 20):
        planar, sliced = paired(warm(1, PIN_WEAR), warm(slices, PIN_WEAR), repeat)
        table.add(
            f"{slices} slices, wearing pin",
            f"{median(sliced) * 1e3:.1f} ms (planar wearing pin {median(planar) * 1e3:.1f} ms)",
            f"{paired_ratio(sliced, planar):.2f} x the planar wearing pin (paired)",
        )
        rigid, sliced = paired(warm(slices, None), warm(slices, PIN_WEAR), repeat)
        table.add(
            f"{slices} slices, rigid pin",
            f"{median(rigid) * 1e3:.2f} ms",
            f"the wearing pin {paired_ratio(sliced, rigid):.0f} x (paired)",
        )
    table.print(f"A wearing pin along the pin ({describe_machine()})")


if __name__ == "__main__":
    main()
