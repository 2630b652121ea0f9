"""Figures of a wear result, drawn from its Dataset (so saved results redraw).

Every function returns a :class:`matplotlib.figure.Figure` built without
pyplot: no backend is selected and no global setting changes, so the figures
show inline in a notebook and work in scripts and servers alike. Writing files
is a separate step, :func:`save_figure` (PNG + SVG), and :func:`plot_result`
draws and writes them all:

* ``wear_polar``: the worn contour over the original bushing circle, wear
  magnified (the paper magnifies x1000 for one revolution; ``"auto"`` picks the
  power of ten that makes the scar visible);
* ``wear_profiles``: wear depth vs angle for the saved revolutions;
* ``pressure``: pressure distributions at chosen phases of the cycle;
* ``joint_load``: load magnitude and azimuth over a cycle;
* ``wear_history``: peak, width and mass vs revolutions;
* ``journal_orbit`` and ``film``, of a lubricated run only
  (:mod:`jointwear.lubrication.figures`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from jointwear.display import depth_unit, revolutions_text
from jointwear.errors import JointwearError
from jointwear.io import atomic_path
from jointwear.lubrication.figures import (
    LUBRICATION_FIGURES,
    film_figure,
    is_lubricated,
    orbit_figure,
)

__all__ = [
    "FIGURES",
    "depth_unit",
    "new_figure",
    "phase_coordinate",
    "plot_dataset",
    "plot_result",
    "plot_wear_result",
    "polar_magnification",
    "save_figure",
]

#: the figures of a result, in the order :func:`plot_result` draws them
FIGURES = ("wear_polar", "wear_profiles", "pressure", "joint_load", "wear_history")
#: the variables of a result each figure draws
FIGURE_VARIABLES = {
    "wear_polar": ("wear_depth", "bushing_radius", "revolution"),
    "wear_profiles": ("wear_depth", "revolution"),
    "pressure": ("pressure_initial", "pressure_final", "snapshot"),
    "joint_load": ("joint_load", "load_azimuth"),
    "wear_history": ("update_revolution", "peak_wear_depth", "wear_width", "wear_mass"),
}


def new_figure(figsize: tuple[float, float] = (7.0, 4.0), **kwargs: Any) -> Figure:
    """A matplotlib figure that belongs to no pyplot state and selects no backend.

    Parameters
    ----------
    figsize : tuple of float
        Width and height [inch].
    **kwargs
        Passed to :class:`matplotlib.figure.Figure`.

    Returns
    -------
    matplotlib.figure.Figure
        An empty figure; add axes with ``fig.subplots(...)`` or ``fig.add_subplot(...)``.
    """
    return Figure(figsize=figsize, **kwargs)


def save_figure(fig: Figure, directory: str | Path, name: str, dpi: int = 130) -> list[Path]:
    """Write a figure as ``NAME.png`` and ``NAME.svg``, each atomically.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure to write.
    directory : path-like
        Output folder (created).
    name : str
        File stem.
    dpi : int
        Resolution of the PNG [dots per inch].

    Returns
    -------
    list of Path
        The files written.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for suffix in ("png", "svg"):
        path = directory / f"{name}.{suffix}"
        with atomic_path(path) as tmp:
            fig.savefig(tmp, format=suffix, dpi=dpi, bbox_inches="tight")
        paths.append(path)
    return paths


def polar_magnification(peak: float, radius: float) -> float:
    """Power of ten that draws a wear peak [m] at 5-50 % of the radius [m].

    Parameters
    ----------
    peak : float
        Largest wear depth [m].
    radius : float
        Radius of the circle the wear is drawn on [m].

    Returns
    -------
    float
        The magnification [-]; 1 without wear.
    """
    if peak <= 0:
        return 1.0
    return 10.0 ** math.floor(math.log10(0.5 * radius / peak))


def phase_coordinate(dataset: xr.Dataset) -> np.ndarray:
    """Phase of each time step of the cycle [rad].

    Reads ``phase`` and, in results written before that name, ``crank_angle``.

    Parameters
    ----------
    dataset : xarray.Dataset
        A wear result.

    Returns
    -------
    numpy.ndarray
        The per-step phase [rad].
    """
    name = "phase" if "phase" in dataset.variables else "crank_angle"
    return np.asarray(dataset[name].values, dtype=float)


def _original_radius(dataset: xr.Dataset) -> float:
    depth = dataset["wear_depth"].values
    return float(np.median(dataset["bushing_radius"].values - depth[-1]))


def _wear_polar(dataset: xr.Dataset, label: str, magnification: float | str) -> Figure:
    theta = dataset["theta"].values
    depth = dataset["wear_depth"].values
    original = _original_radius(dataset)
    mag = (
        polar_magnification(float(depth[-1].max()), original)
        if magnification == "auto"
        else float(magnification)
    )
    fig = new_figure((5.5, 5.5))
    ax = fig.add_subplot(projection="polar")
    closed = np.append(theta, theta[0])
    ax.plot(closed, np.full_like(closed, original * 1e3), "k--", lw=1, label="original bushing")
    for rev, profile in zip(dataset["revolution"].values, depth, strict=True):
        ax.plot(
            closed,
            (original + mag * np.append(profile, profile[0])) * 1e3,
            lw=1.3,
            label=f"{revolutions_text(rev)} r",
        )
    ax.set_title(f"{label}: worn contour [mm], wear x{mag:g}", pad=14)
    ax.legend(loc="lower left", fontsize=7, bbox_to_anchor=(-0.1, -0.12), ncol=3)
    return fig


def _wear_profiles(dataset: xr.Dataset, label: str) -> Figure:
    theta_deg = np.degrees(dataset["theta"].values)
    depth = dataset["wear_depth"].values
    fig = new_figure()
    ax = fig.subplots()
    scale, unit = depth_unit(float(depth.max()))
    for rev, profile in zip(dataset["revolution"].values, depth, strict=True):
        ax.plot(theta_deg, profile / scale, label=f"{revolutions_text(rev)} r")
    ax.set_xlabel("bushing angle θ [deg]")
    ax.set_ylabel(f"wear depth [{unit}]")
    ax.set_xlim(0, 360)
    ax.set_title(f"{label}: wear depth")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    return fig


def _pressure(dataset: xr.Dataset, label: str) -> Figure:
    theta_deg = np.degrees(dataset["theta"].values)
    fig = new_figure()
    ax = fig.subplots()
    snapshots = dataset["snapshot"].values
    chosen = np.unique(np.linspace(0, snapshots.size, 6, endpoint=False).astype(int))
    for i in chosen:
        ax.plot(
            theta_deg,
            dataset["pressure_initial"].values[i] / 1e6,
            label=f"phase {np.degrees(snapshots[i]):.0f}°",
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
    return fig


def _joint_load(dataset: xr.Dataset, label: str) -> Figure:
    phase = np.degrees(phase_coordinate(dataset))
    fig = new_figure((7, 5))
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    ax1.plot(phase, dataset["joint_load"].values)
    ax1.set_ylabel("joint load [N]")
    ax1.grid(alpha=0.3)
    ax2.plot(phase, np.degrees(np.unwrap(dataset["load_azimuth"].values)))
    ax2.set_ylabel("load azimuth [deg]")
    ax2.set_xlabel("cycle phase [deg]")
    ax2.grid(alpha=0.3)
    ax1.set_title(f"{label}: joint load over a cycle")
    return fig


def _wear_history(dataset: xr.Dataset, label: str) -> Figure:
    revs = dataset["update_revolution"].values
    fig = new_figure((7, 7))
    axes = fig.subplots(3, 1, sharex=True)
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
    return fig


_DRAW: dict[str, Callable[[xr.Dataset, str], Figure]] = {
    "wear_profiles": _wear_profiles,
    "pressure": _pressure,
    "joint_load": _joint_load,
    "wear_history": _wear_history,
    "journal_orbit": orbit_figure,
    "film": film_figure,
}


def plot_dataset(
    dataset: xr.Dataset,
    kind: str = "wear_polar",
    magnification: float | str = "auto",
    label: str | None = None,
) -> Figure:
    """Draw one figure of a result dataset.

    Parameters
    ----------
    dataset : xarray.Dataset
        A result (``WearResult.dataset`` or :func:`jointwear.results.read_result`).
    kind : str
        One of :data:`FIGURES`.
    magnification : float or "auto"
        Wear magnification of the ``wear_polar`` figure [-].
    label : str, optional
        Title prefix; default the contact model's name.

    Returns
    -------
    matplotlib.figure.Figure
        The figure (not registered with pyplot; nothing is written).

    Raises
    ------
    JointwearError
        For an unknown ``kind``.
    """
    if kind not in FIGURES + LUBRICATION_FIGURES:
        raise JointwearError(f"unknown figure {kind!r}; choose one of {', '.join(FIGURES)}")
    if kind in LUBRICATION_FIGURES and not is_lubricated(dataset):
        raise JointwearError(f"figure {kind!r}: the result is of a dry joint (no film)")
    label = label or f"{dataset.attrs.get('contact_model', '')}"
    if "z" in dataset["wear_depth"].dims:  # along the pin: the slice worn deepest
        deepest = int(dataset["wear_depth"].isel(revolution=-1).max("theta").argmax("z"))
        dataset = dataset.isel(z=deepest)
        label = f"{label}, z = {float(dataset['z']) * 1e3:.3g} mm"
    if kind == "wear_polar":
        return _wear_polar(dataset, label, magnification)
    return _DRAW[kind](dataset, label)


def plot_wear_result(
    result: Any,
    kind: str = "wear_polar",
    magnification: float | str = "auto",
    label: str | None = None,
) -> Figure:
    """Draw one figure of a wear result (what ``WearResult.plot`` returns).

    Parameters
    ----------
    result : WearResult or xarray.Dataset
        A simulation result, or its dataset.
    kind : str
        One of :data:`FIGURES`: ``"wear_polar"`` (default), ``"wear_profiles"``,
        ``"pressure"``, ``"joint_load"``, ``"wear_history"``.
    magnification : float or "auto"
        Wear magnification of the ``wear_polar`` figure [-].
    label : str, optional
        Title prefix; default the contact model's name.

    Returns
    -------
    matplotlib.figure.Figure
        The figure; write it with :func:`save_figure` or ``fig.savefig``.
    """
    dataset = result if isinstance(result, xr.Dataset) else result.dataset
    return plot_dataset(dataset, kind, magnification=magnification, label=label)


def plot_result(
    dataset: xr.Dataset,
    directory: str | Path,
    magnification: float | str = "auto",
    label: str | None = None,
) -> list[Path]:
    """Draw all figures of a result into ``directory`` (PNG + SVG each).

    Parameters
    ----------
    dataset : xarray.Dataset
        A result (``WearResult.dataset`` or :func:`jointwear.results.read_result`).
    directory : path-like
        Output folder (created).
    magnification : float or "auto"
        Wear magnification of the polar plot [-].
    label : str, optional
        Title prefix.

    Returns
    -------
    list of Path
        The files written.
    """
    written: list[Path] = []
    for kind in FIGURES + (LUBRICATION_FIGURES if is_lubricated(dataset) else ()):
        fig = plot_dataset(dataset, kind, magnification=magnification, label=label)
        written += save_figure(fig, directory, kind)
    return written
