r"""Validation of the wear simulation against references nobody here tuned.

Each case runs :class:`jointwear.Simulation` on a joint whose answer is known
independently and returns its deviations as rows of a table; the tests assert
the tolerances and ``python -m jointwear.references.validation DIR`` writes the
tables (Markdown) and figures of the documentation's Validation page.

=========================  =====================================================
``conformal``              a journal under a load fixed in the bushing, turning
                           or oscillating, against the rigid-conformal worn bore
                           (:mod:`jointwear.references.conformal`), up to 20
                           clearances of wear
``uniform``                a load turning with the pin wears the bore uniformly:
                           depth ``K kappa F s / (2 pi R b)`` with the spread
                           factor ``kappa`` of the contact arc in closed form
``archard``                Archard's global form: worn volume per revolution
                           ``K kappa sum_k N_k ds_k`` for every model and mesh
=========================  =====================================================
"""

from __future__ import annotations

import math
import tempfile
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear.references.conformal import conformal_wear, sliding_distance

__all__ = [
    "CONFORMAL_JOINTS",
    "ConformalComparison",
    "conformal_comparison",
    "main",
    "uniform_wear_comparison",
]

FloatArray = NDArray[np.float64]

#: joints for the rigid-conformal comparison: (description, config overrides)
CONFORMAL_JOINTS: dict[str, tuple[str, dict[str, Any]]] = {
    "bronze-40mm": (
        "steel pin 40 mm in a bronze bushing, c = 0.05 mm (c/R = 1/400), 8 kN",
        {
            "joint.pin_radius": "19.95 mm",
            "joint.clearance": "0.05 mm",
            "joint.axial_length": "20 mm",
            "joint.bushing_thickness": "5 mm",
            "materials.pin": "steel",
            "materials.bushing": "bronze",
            "load": 8000.0,
        },
    ),
    "ptfe-15mm": (
        "the paper's steel pin 14.9 mm in PTFE, c = 0.05 mm (c/R = 1/150), 1.5 kN",
        {
            "joint.pin_radius": "7.45 mm",
            "joint.clearance": "0.05 mm",
            "joint.axial_length": "20 mm",
            "joint.bushing_thickness": "2.5 mm",
            "load": 1500.0,
        },
    ),
}


def _config(
    model: str,
    motion: str,
    joint: str,
    revolutions: int,
    saved: int,
    folder: Path,
    extra: Mapping[str, Any] | None = None,
) -> Any:
    from jointwear.config import apply_overrides, config_from_dict

    overrides = dict(CONFORMAL_JOINTS[joint][1])
    load = float(overrides.pop("load"))
    if motion == "oscillating":
        mechanism: dict[str, Any] = {
            "type": "oscillating", "load": load, "load_frame": "bushing",
            "load_angle": "-90 deg", "amplitude": "25 deg", "frequency": "0.25 Hz",
        }  # fmt: skip
        steps = 180
    elif motion == "turning":
        # the pin turns once per cycle under a load fixed in the bushing
        csv = folder / "turning.csv"
        rows = ["time [s],force_x [N],force_y [N],rotation [deg]"]
        rows += [f"{i * 0.01:.2f},0,{-load:.17g},{i * 18}" for i in range(21)]
        csv.write_text("\n".join(rows) + "\n")
        mechanism = {"type": "load-history", "file": str(csv), "frame": "bushing"}
        steps = 20
    else:
        raise ValueError(f"motion: {motion!r} is neither 'oscillating' nor 'turning'")
    data: dict[str, Any] = {
        "mechanism": mechanism,
        "joint": {},
        "materials": {},
        "contact": {"model": model},
        "simulation": {
            "steps_per_revolution": steps,
            "revolutions": revolutions,
            "update_contour": True,
            "update_every": "adaptive",
            "saved_profiles": saved,
        },
    }
    apply_overrides(data, {**overrides, **(extra or {})})
    return config_from_dict(data)


@dataclass(frozen=True)
class ConformalComparison:
    """A worn joint against the rigid-conformal reference at its saved profiles.

    Attributes
    ----------
    model : str
        Contact model.
    motion : str
        ``"oscillating"`` (+-25 deg) or ``"turning"`` (whole turns).
    joint : str
        Key of :data:`CONFORMAL_JOINTS`.
    clearance : float
        Radial clearance ``c`` [m].
    sliding_distance : ndarray
        Sliding distance at each saved profile [m].
    depth, depth_reference : ndarray
        Peak wear depth, simulated and reference [m].
    volume, volume_reference : ndarray
        Worn volume, simulated and reference [m^3].
    width, width_reference : ndarray
        Wear width (1 % of the peak), simulated and reference [rad].
    runtime : float
        Wall-clock time of the simulation [s].
    """

    model: str
    motion: str
    joint: str
    clearance: float
    sliding_distance: FloatArray
    depth: FloatArray
    depth_reference: FloatArray
    volume: FloatArray
    volume_reference: FloatArray
    width: FloatArray
    width_reference: FloatArray
    runtime: float

    @property
    def clearances_worn(self) -> FloatArray:
        """Reference peak depth in clearances [-]."""
        return self.depth_reference / self.clearance

    def errors(self, from_clearances: float = 1.0) -> dict[str, float]:
        """Largest deviations where the reference has worn ``from_clearances`` or more.

        Returns
        -------
        dict
            ``depth`` and ``volume``: largest relative deviation [-]; ``width``: largest
            deviation [deg].
        """
        keep = self.clearances_worn >= from_clearances - 1e-9
        return {
            "depth": float(np.max(np.abs(self.depth[keep] / self.depth_reference[keep] - 1))),
            "volume": float(np.max(np.abs(self.volume[keep] / self.volume_reference[keep] - 1))),
            "width": float(
                np.degrees(np.max(np.abs(self.width[keep] - self.width_reference[keep])))
            ),
        }


def conformal_comparison(
    model: str,
    motion: str = "oscillating",
    joint: str = "bronze-40mm",
    clearances: float = 20.0,
    saved_profiles: int = 40,
    overrides: Mapping[str, Any] | None = None,
) -> ConformalComparison:
    """Run a journal under a fixed load to ``clearances`` of reference wear and compare.

    Parameters
    ----------
    model : str
        Contact model (``contact.model``).
    motion : {"oscillating", "turning"}
        +-25 deg swings, or whole turns, of the pin under a load fixed in the bushing.
    joint : str
        Key of :data:`CONFORMAL_JOINTS`.
    clearances : float
        Reference peak depth at the end of the run, in clearances [-].
    saved_profiles : int
        Profiles compared along the run [-].
    overrides : mapping, optional
        Further config overrides (dotted keys).
    """
    import time

    from jointwear.simulation import Simulation
    from jointwear.tribology.metrics import wear_width, worn_area

    with tempfile.TemporaryDirectory() as folder:
        probe = _config(model, motion, joint, 1, 1, Path(folder), overrides)
        cycle = Simulation(probe).load_cycle
        joint_cfg, wear = probe.joint, probe.materials.bushing
        load = float(np.max(cycle.load))
        per_cycle = float(np.sum(np.abs(cycle.relative_rotation))) * joint_cfg.bushing_radius
        target = sliding_distance(
            joint_cfg.clearance * (1 + clearances), load, joint_cfg.pin_radius,
            joint_cfg.clearance, joint_cfg.axial_length, wear.wear_coefficient,
        )  # fmt: skip
        revolutions = max(1, math.ceil(target / per_cycle))
        config = _config(model, motion, joint, revolutions, saved_profiles, Path(folder), overrides)
        start = time.perf_counter()
        result = Simulation(config).run(pressures=False)
        runtime = time.perf_counter() - start
    profiles = result.dataset["wear_depth"]
    marks = profiles["revolution"].values.astype(float)
    depths = profiles.values
    distance = marks * per_cycle
    references = [
        conformal_wear(
            s, load, joint_cfg.pin_radius, joint_cfg.clearance, joint_cfg.axial_length,
            wear.wear_coefficient, config.simulation.width_threshold,
        )
        for s in distance
    ]  # fmt: skip
    return ConformalComparison(
        model=model,
        motion=motion,
        joint=joint,
        clearance=joint_cfg.clearance,
        sliding_distance=distance,
        depth=depths.max(axis=1),
        depth_reference=np.array([r.peak_wear_depth for r in references]),
        volume=np.array(
            [worn_area(joint_cfg.bushing_radius, h) * joint_cfg.axial_length for h in depths]
        ),
        volume_reference=np.array([r.wear_volume for r in references]),
        width=np.array([wear_width(h, config.simulation.width_threshold) for h in depths]),
        width_reference=np.array([r.wear_width for r in references]),
        runtime=runtime,
    )


def uniform_wear_comparison(
    model: str, revolutions: int = 2000, nodes: int = 360
) -> dict[str, float]:
    """A load turning with the pin: uniform wear against its closed form.

    The load keeps its direction in the pin's frame, so every node of the bushing
    sees the same pressure history and the bore grows as a circle. Archard's law
    then gives the depth per sliding distance

    .. math:: \\frac{dh}{ds} = \\frac{K \\kappa(\\alpha) F}{2\\pi (R_b + h) b},

    with ``kappa`` the spread factor of the contact arc (sum of the spring forces
    over the load, :func:`jointwear.contact.winkler.spread_factor`) and ``alpha`` the
    half-angle of the Winkler contact on the circle of clearance ``c + h``
    (:func:`jointwear.contact.winkler.circle_force`), integrated here with
    :func:`scipy.integrate.solve_ivp`.

    Parameters
    ----------
    model : str
        Contact model with linear springs (``winkler`` family) [-].
    revolutions : int
        Revolutions of the pin [-].
    nodes : int
        Nodes of the bushing and steps per revolution [-].

    Returns
    -------
    dict
        ``depth`` and ``depth_reference`` [m], ``nonuniformity`` (range over mean of
        the final profile) [-], ``error`` (relative) [-].
    """
    load = 200.0
    depth, config, stiffness = _turning_load_run(model, revolutions, nodes, load)
    distance = revolutions * 2 * math.pi * config.joint.bushing_radius
    reference = _uniform_depth(config, stiffness, load, distance)
    mean = float(depth.mean())
    return {
        "depth": mean,
        "depth_reference": reference,
        "nonuniformity": float((depth.max() - depth.min()) / mean),
        "error": mean / reference - 1.0,
    }


def _turning_load_run(
    model: str, revolutions: int, nodes: int, load: float
) -> tuple[FloatArray, Any, float]:
    """Wear a bushing under a load turning with the pin.

    Returns the final wear profile [m], the run's config and the stiffness ``E_w / L``
    of its spring law [Pa/m].
    """
    from jointwear.config import config_from_dict
    from jointwear.simulation import Simulation

    with tempfile.TemporaryDirectory() as folder:
        csv = Path(folder) / "turning_load.csv"
        rows = ["time [s],force_x [N],force_y [N],rotation [rad]"]
        for i in range(nodes + 1):
            phi = 2 * math.pi * i / nodes
            rows.append(
                f"{i * 1e-3:.6f},{load * math.cos(phi):.17g},{load * math.sin(phi):.17g},{phi:.17g}"
            )
        csv.write_text("\n".join(rows) + "\n")
        data = {
            "mechanism": {"type": "load-history", "file": str(csv), "frame": "bushing"},
            "joint": {"bushing_thickness": "2.5 mm"},
            "materials": {},
            "contact": {"model": model, "nodes": nodes, "foundation_modulus": "constrained"},
            "simulation": {
                "revolutions": revolutions, "update_contour": True, "update_every": "adaptive",
            },
        }  # fmt: skip
        config = config_from_dict(data)
        simulation = Simulation(config)
        result = simulation.run(pressures=False)
    # the run's own spring law: its stiffness E_w / L is the closed form's
    return result.dataset["wear_depth"].values[-1], config, simulation.law.coefficient


def _uniform_depth(config: Any, stiffness: float, load: float, distance: float) -> float:
    """Depth [m] of uniform wear after sliding ``distance`` [m], by ``solve_ivp``.

    ``dh/ds = K kappa(alpha) F / (2 pi (R_b + h) b)`` with the half-angle ``alpha`` of
    the Winkler contact of stiffness ``stiffness`` [Pa/m] on the circle of clearance
    ``c + h`` that carries the load ``load`` [N].
    """
    from scipy import integrate, optimize

    from jointwear.contact import winkler

    joint, bushing = config.joint, config.materials.bushing
    radius0 = joint.bushing_radius

    def rate(_s: float, h: FloatArray) -> list[float]:
        radius, clearance = radius0 + h[0], joint.clearance + h[0]
        approach = optimize.brentq(
            lambda a: (
                float(
                    winkler.circle_force(
                        a, clearance, radius, joint.axial_length, stiffness, joint.pin_radius
                    )[0]
                )
                - load
            ),
            1e-15,
            joint.bushing_thickness,
            xtol=1e-16,
        )
        _, alpha = winkler.circle_force(
            approach, clearance, radius, joint.axial_length, stiffness, joint.pin_radius
        )
        kappa = float(winkler.spread_factor(alpha))
        return [
            bushing.wear_coefficient * kappa * load / (2 * math.pi * radius * joint.axial_length)
        ]

    solved = integrate.solve_ivp(rate, (0.0, distance), [0.0], rtol=1e-10, atol=1e-18)
    return float(solved.y[0, -1])


def _table(rows: Iterable[Mapping[str, Any]], columns: Mapping[str, str]) -> str:
    lines = ["| " + " | ".join(columns.values()) + " |", "|" + "---|" * len(columns)]
    for row in rows:
        lines.append("| " + " | ".join(str(row[key]) for key in columns) + " |")
    return "\n".join(lines)


def _conformal_figure(
    comparisons: list[ConformalComparison], labels: list[str], path: Path
) -> None:
    from matplotlib.figure import Figure

    figure = Figure(figsize=(12, 3.2), layout="constrained")
    axes = figure.subplots(1, 4)
    first = comparisons[0]
    axes[0].plot(
        first.clearances_worn, np.degrees(first.width_reference), "k-", lw=2.5,
        label="rigid-conformal",
    )  # fmt: skip
    for comparison, label in zip(comparisons, labels, strict=True):
        worn = comparison.clearances_worn
        axes[0].plot(worn, np.degrees(comparison.width), "o", ms=3, label=label)
        axes[1].plot(worn, 100 * (comparison.depth / comparison.depth_reference - 1), "o-", ms=3)
        axes[2].plot(worn, 100 * (comparison.volume / comparison.volume_reference - 1), "o-", ms=3)
        axes[3].plot(worn, np.degrees(comparison.width - comparison.width_reference), "o-", ms=3)
    ylabels = (
        "wear width [deg]",
        "peak depth deviation [%]",
        "worn volume deviation [%]",
        "width deviation [deg]",
    )
    for ax, ylabel in zip(axes, ylabels, strict=True):
        ax.set_xlabel("reference wear [clearances]")
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    for ax in axes[1:]:
        ax.axhline(0.0, color="k", lw=1)
    axes[0].legend(fontsize=7)
    figure.savefig(path, dpi=110)


def build(folder: Path) -> dict[str, str]:
    """Run every validation case; write the figures into ``folder``; return Markdown tables.

    Returns
    -------
    dict of str to str
        Table name (``conformal_<joint>``, ``uniform``) -> Markdown table.

    Parameters
    ----------
    folder : pathlib.Path
        Where the figures go (created).
    """
    folder.mkdir(parents=True, exist_ok=True)
    parts: dict[str, str] = {}
    for joint, (description, _) in CONFORMAL_JOINTS.items():
        parts[f"conformal_{joint}"] = (
            f"**{description}** (largest deviation in depth / volume / width)\n\n"
            + _conformal_table(joint, folder)
        )
    parts["uniform"] = _uniform_table()
    return parts


def _conformal_table(joint: str, folder: Path) -> str:
    """Every contour model and motion of one joint against the rigid-conformal bore.

    Writes the joint's figure into ``folder``; returns the Markdown table.
    """
    comparisons, labels, rows = [], [], []
    for model, extra in (
        ("asymmetric-winkler", {}),
        ("nlcp", {"contact.nlcp_variant": "mesh-independent"}),
        ("nlcp", {}),
    ):
        for motion in ("oscillating", "turning"):
            comparison = conformal_comparison(model, motion, joint, overrides=extra)
            comparisons.append(comparison)
            labels.append(model + (" (mesh-independent)" if extra else "") + f", {motion}")
            one, two = comparison.errors(1.0), comparison.errors(2.0)
            end = comparison.errors(comparison.clearances_worn[-1])
            rows.append(
                {
                    "model": model + (" (mesh-independent)" if extra else ""),
                    "motion": motion,
                    "one": f"{one['depth']:.2%} / {one['volume']:.2%} / {one['width']:.1f}°",
                    "two": f"{two['depth']:.2%} / {two['volume']:.2%} / {two['width']:.1f}°",
                    "end": f"{end['depth']:.2%} / {end['volume']:.2%} / {end['width']:.1f}°",
                    "time": f"{comparison.runtime:.2f} s",
                }
            )
    _conformal_figure(comparisons[::2], labels[::2], folder / f"conformal_{joint}.png")
    columns = {
        "model": "model",
        "motion": "motion",
        "one": "from 1 c",
        "two": "from 2 c",
        "end": "at 20 c",
        "time": "run time",
    }
    return _table(rows, columns)


def _uniform_table() -> str:
    """The uniform-wear case against its closed form, as a Markdown table."""
    uniform = []
    for model in ("asymmetric-winkler",):
        values = uniform_wear_comparison(model)
        uniform.append(
            {
                "model": model,
                "depth": f"{values['depth'] * 1e6:.4f} µm",
                "reference": f"{values['depth_reference'] * 1e6:.4f} µm",
                "error": f"{values['error']:+.2e}",
                "range": f"{values['nonuniformity']:.1e}",
            }
        )
    return _table(
        uniform,
        {
            "model": "model",
            "depth": "mean depth",
            "reference": "closed form",
            "error": "deviation",
            "range": "(max − min) / mean",
        },
    )


def main(argv: list[str] | None = None) -> int:
    """``python -m jointwear.references.validation DIR``: figures and tables into DIR."""
    import sys

    args = sys.argv[1:] if argv is None else argv
    folder = Path(args[0] if args else "validation")
    for name, table in build(folder).items():
        (folder / f"{name}.md").write_text(table + "\n")
        print(table, end="\n\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
