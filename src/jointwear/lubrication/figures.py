"""Figures of a lubricated result: the pin's orbit and the film over the cycle.

Drawn from the Dataset of a lubricated run (the variables ``eccentricity_ratio_x``,
``eccentricity_ratio_y``, ``min_film_thickness``, ``film_parameter``,
``asperity_load_fraction`` and ``bulk_load_fraction`` of
:func:`jointwear.results.contents.film_variables`); a dry result has none of them and
draws neither figure. Like :mod:`jointwear.plots`, every function returns a
:class:`matplotlib.figure.Figure` that belongs to no pyplot state.

* ``journal_orbit``: the pin centre's orbit in the clearance circle (eccentricity over
  the radial clearance, in the bushing's frame), with the circles where the film
  parameter is 3 and 1 (the hydrodynamic and boundary limits);
* ``film``: the minimum film thickness and the share of the load the solid contact
  (asperities and bulk) carries over the cycle.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

__all__ = ["LUBRICATION_FIGURES", "film_figure", "is_lubricated", "orbit_figure"]

#: the lubricated run's figures, in the order they are drawn
LUBRICATION_FIGURES = ("journal_orbit", "film")


def is_lubricated(dataset: xr.Dataset) -> bool:
    """The dataset holds a lubricated run's orbit and film."""
    return "eccentricity_ratio_x" in dataset and "film_parameter" in dataset


def cycle_phase(dataset: xr.Dataset) -> np.ndarray:
    """The phase of each step over the cycle [deg]."""
    name = "phase" if "phase" in dataset.variables else "crank_angle"
    return np.degrees(np.asarray(dataset[name].values, dtype=float))


def orbit_figure(dataset: xr.Dataset, label: str) -> Figure:
    """The pin centre's orbit in the clearance circle, coloured by the film parameter.

    Parameters
    ----------
    dataset : xarray.Dataset
        A lubricated result.
    label : str
        Title prefix.
    """
    x = np.asarray(dataset["eccentricity_ratio_x"].values, float)
    y = np.asarray(dataset["eccentricity_ratio_y"].values, float)
    lam = np.asarray(dataset["film_parameter"].values, float)
    # lambda = (1 - eps) c / sigma: the circle of a film parameter is eps = 1 - lambda / ratio
    ratio = float(np.median(lam / np.maximum(1.0 - np.hypot(x, y), 1e-300)))
    fig = Figure(figsize=(5.5, 5.0), layout="constrained")
    ax = fig.add_subplot()
    turn = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(np.cos(turn), np.sin(turn), color="0.2", lw=1.0, label="clearance circle")
    for limit, style in ((3.0, "--"), (1.0, ":")):
        radius = 1.0 - limit / ratio
        if radius > 0.0:
            ax.plot(
                radius * np.cos(turn),
                radius * np.sin(turn),
                "0.5",
                ls=style,
                lw=0.8,
                label=f"film parameter {limit:g}",
            )
    path = ax.scatter(x, y, c=lam, s=6, cmap="viridis")
    fig.colorbar(path, ax=ax, label="film parameter h_min / sigma")
    ax.plot(x[0], y[0], "k+", ms=8, label="start of the cycle")
    ax.set_aspect("equal")
    ax.set_xlabel("e_x / c")
    ax.set_ylabel("e_y / c")
    ax.legend(fontsize=7, loc="upper right")
    ax.set_title(f"{label}: journal orbit")
    return fig


def film_figure(dataset: xr.Dataset, label: str) -> Figure:
    """Minimum film thickness and solid-contact load share over the cycle.

    Parameters
    ----------
    dataset : xarray.Dataset
        A lubricated result.
    label : str
        Title prefix.
    """
    phase = cycle_phase(dataset)
    fig = Figure(figsize=(7.0, 5.0), layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(phase, 1e6 * np.asarray(dataset["min_film_thickness"].values, float))
    top.set_ylabel("min film thickness [um]")
    top.grid(alpha=0.3)
    bottom.plot(phase, dataset["asperity_load_fraction"].values, label="solid contact")
    bottom.plot(phase, dataset["bulk_load_fraction"].values, "--", label="of which bulk")
    bottom.set_ylabel("share of the load [-]")
    bottom.set_xlabel("cycle phase [deg]")
    bottom.set_ylim(-0.02, 1.02)
    bottom.grid(alpha=0.3)
    bottom.legend(fontsize=7)
    top.set_title(f"{label}: film over the cycle")
    return fig
