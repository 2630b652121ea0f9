"""What wear feedback changes: the study behind docs/wear-feedback.md.

Runs (about 10 minutes on one core):

1. the paper's joint (pulling spring), 10^5 revolutions, uncoupled and coupled;
2. a separation-prone joint (pushing spring, 1 N preload, 240 rpm, 0.3 kg rod),
   contact-impact dynamics, 10^5 revolutions, uncoupled and coupled (adaptive);
3. the paper's clearance -> wear-mass claim (one revolution, 240 rpm) with
   contact-impact dynamics, for the pulling and the pushing spring.

Writes the figures into docs/_static/ and prints the tables of the page.

Run: python docs/studies/wear_feedback.py
"""

from __future__ import annotations

import time
import warnings
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

import jointwear as jw

ROOT = Path(__file__).resolve().parents[2]
PAPER = ROOT / "examples" / "paper" / "table5_nlcp_15000r.toml"
STATIC = ROOT / "docs" / "_static"
LONG = {
    "simulation.revolutions": 100000,
    "simulation.update_contour": True,
    "simulation.update_every": "adaptive",
}
SEPARATING = {
    "mechanism.spring_mode": "push",
    "mechanism.spring_preload": "1 N",
    "mechanism.crank_speed": "240 rpm",
    "mechanism.rod_mass": "0.3 kg",
    "dynamics.model": "contact-impact",
    "simulation.steps_per_revolution": 180,
    # a 2-degree mesh: NLCP's pressure law integrated over the nodes' own areas (the paper's
    # node force belongs to 1-degree springs and would wear twice Archard's volume here)
    "contact.nodes": 180,
    "contact.nlcp_variant": "mesh-independent",
}
#: the spring, dynamics and clearances of the clearance -> wear-mass table (part 3)
SPRINGS = {
    "pull (paper)": {},
    "push, 1 N": {"mechanism.spring_mode": "push", "mechanism.spring_preload": "1 N"},
}
DYNAMICS = ("massless-link", "contact-impact")
CLEARANCES = (0.05, 0.1, 0.2, 0.3)


def long_runs() -> dict[str, dict[str, dict]]:
    """The overrides of the long runs (parts 1 and 2), by group and name."""
    coupled = {"simulation.dynamics_update": "adaptive"}
    return {
        "paper": {"uncoupled": LONG, "coupled (adaptive)": {**LONG, **coupled}},
        "separating": {
            "uncoupled": {**LONG, **SEPARATING},
            "coupled (adaptive)": {**LONG, **SEPARATING, **coupled},
        },
    }


def clearance_run(spring: str, model: str, clearance: float) -> dict:
    """The overrides of one revolution of part 3 [clearance in mm]."""
    return {
        **SPRINGS[spring],
        "mechanism.crank_speed": "240 rpm",
        "joint.clearance": f"{clearance} mm",
        "dynamics.model": model,
        "simulation.revolutions": 1,
        "simulation.update_contour": False,
        "simulation.steps_per_revolution": 360,
    }


def run(overrides: dict) -> jw.WearResult:
    config = jw.load_config(PAPER, overrides=overrides)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        start = time.perf_counter()
        result = jw.Simulation(config).run()
    print(f"  ran in {time.perf_counter() - start:.1f} s", flush=True)
    return result


def row(name: str, result: jw.WearResult) -> str:
    s = result.summary()
    return (
        f"| {name} | {s['peak_wear_depth_m'] * 1e3:.4g} | {s['wear_mass_kg'] * 1e3:.4g} | "
        f"{s['wear_width_deg']:.4g} | {s['dynamics_updates']} | {s['runtime_s']:.3g} |"
    )


def history_figure(results: dict[str, jw.WearResult], title: str) -> Figure:
    fig = Figure(figsize=(8, 3.4), layout="constrained")
    wear, impacts = fig.subplots(1, 2)
    for name, result in results.items():
        ds = result.dataset
        wear.plot(ds["update_revolution"], ds["wear_mass"] * 1e3, label=name)
        if ds.sizes.get("dynamics_update", 0) > 1:
            impacts.plot(ds["dynamics_revolution"], ds["dynamics_impacts"], ".-", label=name)
    wear.set_xlabel("revolutions")
    wear.set_ylabel("worn mass [g]")
    wear.legend()
    wear.grid(alpha=0.3)
    impacts.set_xlabel("revolutions")
    impacts.set_ylabel("impacts per revolution")
    impacts.grid(alpha=0.3)
    fig.suptitle(title)
    return fig


def main() -> None:
    STATIC.mkdir(exist_ok=True)
    runs = long_runs()
    print("1. paper joint, pulling spring")
    paper = {name: run(overrides) for name, overrides in runs["paper"].items()}
    print("2. separation-prone joint")
    separating = {name: run(overrides) for name, overrides in runs["separating"].items()}
    history_figure(separating, "separation-prone joint, contact-impact dynamics").savefig(
        STATIC / "wear_feedback_separating.png", dpi=110
    )
    header = "| run | peak [mm] | mass [g] | width [deg] | dynamics solves | time [s] |"
    print(header + "\n|---|---|---|---|---|---|")
    for group, results in (("paper", paper), ("separating", separating)):
        for name, result in results.items():
            print(row(f"{group}, {name}", result))
    print("3. clearance -> wear mass, one revolution, 240 rpm, contact-impact")
    clearances = list(CLEARANCES)
    table = {}
    for spring in SPRINGS:
        for model in DYNAMICS:
            masses, hits = [], []
            for c in clearances:
                result = run(clearance_run(spring, model, c))
                masses.append(result.summary()["wear_mass_kg"])
                ds = result.dataset
                hits.append(int(ds["dynamics_impacts"].values[0]))
            table[(spring, model)] = (masses, hits)
    print("| spring | dynamics | " + " | ".join(f"{c} mm" for c in clearances) + " |")
    print("|---|---|" + "---|" * len(clearances))
    for (spring, model), (masses, hits) in table.items():
        cells = " | ".join(f"{m * 1e9:.4g} ({h})" for m, h in zip(masses, hits, strict=True))
        print(f"| {spring} | {model} | {cells} |")
    fig = Figure(figsize=(5, 3.4), layout="constrained")
    ax = fig.subplots()
    for (spring, model), (masses, _) in table.items():
        ax.plot(clearances, np.array(masses) * 1e9, "o-", label=f"{spring}, {model}")
    ax.set_xlabel("clearance [mm]")
    ax.set_ylabel("worn mass per revolution [µg]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.savefig(STATIC / "wear_feedback_clearance.png", dpi=110)


if __name__ == "__main__":
    main()
