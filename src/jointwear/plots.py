"""Figures of a wear result, drawn from its Dataset (so saved results redraw).

Every figure is written as PNG and SVG. :func:`plot_result` draws them all:

* ``wear_polar``: the worn contour over the original bushing circle, wear
  magnified (the paper magnifies x1000 for one revolution; ``"auto"`` picks the
  power of ten that makes the scar visible);
* ``wear_profiles``: wear depth vs angle for the saved revolutions;
* ``pressure``: pressure distributions at chosen crank angles;
* ``joint_load``: load magnitude and azimuth over a revolution;
* ``wear_history``: peak, width and mass vs revolutions.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import xarray as xr

from jointwear.io import atomic_path

__all__ = ["FIGURES", "plot_result", "polar_magnification"]

FIGURES = ("wear_polar", "wear_profiles", "pressure", "joint_load", "wear_history")


def _pyplot():
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def polar_magnification(peak: float, radius: float) -> float:
    """Power of ten that draws a wear peak [m] at 5-50 % of the radius [m]."""
    if peak <= 0:
        return 1.0
    return 10.0 ** math.floor(math.log10(0.5 * radius / peak))


def depth_unit(peak: float) -> tuple[float, str]:
    """Scale [m per unit] and name of the length unit that shows ``peak`` [m] legibly."""
    for scale, unit in ((1e-9, "nm"), (1e-6, "µm")):
        if peak < 1000 * scale:
            return scale, unit
    return 1e-3, "mm"


def _save(fig, directory: Path, name: str) -> list[Path]:
    paths = []
    for suffix in ("png", "svg"):
        path = directory / f"{name}.{suffix}"
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format=suffix, dpi=130, bbox_inches="tight")
        paths.append(path)
    return paths


def plot_result(
    dataset: xr.Dataset,
    directory: str | Path,
    magnification: float | str = "auto",
    label: str | None = None,
) -> list[Path]:
    """Draw all figures of a result into ``directory``.

    Parameters
    ----------
    dataset : xarray.Dataset
        A result (:meth:`jointwear.WearResult.dataset` or :func:`jointwear.results.read_result`).
    directory : path-like
        Output folder (created).
    magnification : float or "auto"
        Wear magnification of the polar plot [-].
    label : str, optional
        Title prefix.
    """
    plt = _pyplot()
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    label = label or f"{dataset.attrs.get('contact_model', '')}"
    written: list[Path] = []
    theta = dataset["theta"].values
    theta_deg = np.degrees(theta)
    depth = dataset["wear_depth"].values
    revolutions = dataset["revolution"].values
    original = float(np.median(dataset["bushing_radius"].values - depth[-1]))

    # -- polar wear profile over the original circle
    mag = (
        polar_magnification(float(depth[-1].max()), original)
        if magnification == "auto"
        else float(magnification)
    )
    fig, ax = plt.subplots(subplot_kw={"projection": "polar"}, figsize=(5.5, 5.5))
    closed = np.append(theta, theta[0])
    ax.plot(closed, np.full_like(closed, original * 1e3), "k--", lw=1, label="original bushing")
    for rev, profile in zip(revolutions, depth, strict=True):
        ax.plot(
            closed,
            (original + mag * np.append(profile, profile[0])) * 1e3,
            lw=1.3,
            label=f"{rev} r",
        )
    ax.set_title(f"{label}: worn contour [mm], wear x{mag:g}", pad=14)
    ax.legend(loc="lower left", fontsize=7, bbox_to_anchor=(-0.1, -0.12), ncol=3)
    written += _save(fig, directory, "wear_polar")
    plt.close(fig)

    # -- wear depth vs angle
    fig, ax = plt.subplots(figsize=(7, 4))
    scale, unit = depth_unit(float(depth.max()))
    for rev, profile in zip(revolutions, depth, strict=True):
        ax.plot(theta_deg, profile / scale, label=f"{rev} r")
    ax.set_xlabel("bushing angle θ [deg]")
    ax.set_ylabel(f"wear depth [{unit}]")
    ax.set_xlim(0, 360)
    ax.set_title(f"{label}: wear depth")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    written += _save(fig, directory, "wear_profiles")
    plt.close(fig)

    # -- pressure at chosen crank angles
    fig, ax = plt.subplots(figsize=(7, 4))
    snapshots = dataset["snapshot"].values
    chosen = np.unique(np.linspace(0, snapshots.size, 6, endpoint=False).astype(int))
    for i in chosen:
        ax.plot(
            theta_deg,
            dataset["pressure_initial"].values[i] / 1e6,
            label=f"crank {np.degrees(snapshots[i]):.0f}°",
        )
        if dataset.sizes.get("update", 0) > 1:
            ax.plot(
                theta_deg,
                dataset["pressure_final"].values[i] / 1e6,
                ls=":",
                color=ax.lines[-1].get_color(),
            )
    ax.set_xlabel("bushing angle θ [deg]")
    ax.set_ylabel("contact pressure [MPa]")
    ax.set_xlim(0, 360)
    ax.set_title(f"{label}: pressure (solid: unworn, dotted: final contour)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    written += _save(fig, directory, "pressure")
    plt.close(fig)

    # -- joint load and azimuth
    phase_name = "phase" if "phase" in dataset else "crank_angle"
    crank = np.degrees(dataset[phase_name].values)
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 5))
    ax1.plot(crank, dataset["joint_load"].values)
    ax1.set_ylabel("joint load [N]")
    ax1.grid(alpha=0.3)
    ax2.plot(crank, np.degrees(np.unwrap(dataset["load_azimuth"].values)))
    ax2.set_ylabel("load azimuth [deg]")
    ax2.set_xlabel("cycle phase [deg]")
    ax2.grid(alpha=0.3)
    ax1.set_title(f"{label}: joint load over a cycle")
    written += _save(fig, directory, "joint_load")
    plt.close(fig)

    # -- history
    revs = dataset["update_revolution"].values
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
    for ax, name, scale, unit in zip(
        axes,
        ("peak_wear_depth", "wear_width", "wear_mass"),
        (1e6, 180 / np.pi, 1e6),
        ("µm", "deg", "mg"),
        strict=True,
    ):
        ax.plot(revs, dataset[name].values * scale, marker="." if revs.size < 50 else None)
        ax.set_ylabel(f"{name.replace('_', ' ')} [{unit}]")
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel("revolutions")
    axes[0].set_title(f"{label}: wear vs revolutions")
    written += _save(fig, directory, "wear_history")
    plt.close(fig)
    return written
