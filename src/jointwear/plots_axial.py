"""Figures of a result along the pin: the wear map over angle and axial position.

A result cut into axial slices stores the wear depth with a dimension ``z`` (the slice
centres [m], 0 at the bushing's mid-plane): ``wear_depth`` over ``("revolution", "z",
"theta")`` and ``bushing_radius`` over ``("z", "theta")``. These figures draw the last
saved revolution of such a result. Like :mod:`jointwear.plots`, every function returns a
:class:`matplotlib.figure.Figure` built without pyplot:

* ``wear_map``: the bore unrolled, a heat map of the wear depth over the bushing angle
  [deg] and the axial position [mm], its colour bar in µm;
* ``edge_profiles``: the worn profile at the mid-plane and in each edge slice vs angle;
* ``worn_bore``: a 3-D view of the worn bore, the cylinder coloured by the wear depth and
  its radius moved out by the wear times a stated exaggeration.

A planar result (one slice, no ``z``) is refused with a :class:`jointwear.errors.DataError`.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import xarray as xr
from matplotlib import colormaps
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize
from matplotlib.figure import Figure

from jointwear.display import revolutions_text
from jointwear.errors import DataError
from jointwear.geometry.angles import wrap_angle
from jointwear.plots import new_figure, plot_result, polar_magnification, save_figure

__all__ = [
    "AXIAL_FIGURES",
    "deepest_slice",
    "edge_profiles",
    "plot_axial_result",
    "wear_map",
    "worn_bore",
]

#: the figures of a result along the pin, in the order :func:`plot_axial_result` draws them
AXIAL_FIGURES = ("wear_map", "edge_profiles", "worn_bore")

#: micrometres per metre: the wear maps show depths in µm
MICRON = 1e6
#: millimetres per metre: the axial position is shown in mm
MILLI = 1e3


def _checked(dataset: xr.Dataset, figure: str) -> xr.DataArray:
    """The final wear depth over ``(z, theta)`` [m]; a planar result is refused."""
    if "wear_depth" not in dataset.variables:
        raise DataError(f"{figure}: the result has no variable 'wear_depth'")
    depth = dataset["wear_depth"]
    if "z" not in depth.dims:
        raise DataError(
            f"{figure}: the result is planar (wear_depth has no axial dimension 'z'); "
            "a wear map needs a run cut into axial slices"
        )
    final = depth.isel(revolution=-1) if "revolution" in depth.dims else depth
    return final.transpose("z", "theta")


def _title(dataset: xr.Dataset, figure: str, label: str | None) -> str:
    prefix = label if label is not None else str(dataset.attrs.get("contact_model", ""))
    if "revolution" in dataset["wear_depth"].dims:
        revolution = float(dataset["revolution"].values[-1])
        figure = f"{figure} after {revolutions_text(revolution)} revolutions"
    return f"{prefix}: {figure}" if prefix else figure


def wear_map(dataset: xr.Dataset, label: str | None = None) -> Figure:
    """The unrolled bore: a heat map of the final wear depth over angle and axial position.

    Each cell is one node of one slice, centred on its angle and on its slice's centre.

    Parameters
    ----------
    dataset : xarray.Dataset
        A result with slices along the pin (``wear_depth`` over ``z``, slice centres [m]).
    label : str, optional
        Title prefix; default the contact model's name.

    Returns
    -------
    matplotlib.figure.Figure
        Bushing angle [deg] across, axial position [mm] up, wear depth [µm] in colour.

    Raises
    ------
    DataError
        A planar result (no ``z``).
    """
    depth = _checked(dataset, "wear map")
    fig = new_figure((8.0, 4.0))
    ax = fig.subplots()
    cells = ax.pcolormesh(
        np.degrees(depth["theta"].values),
        depth["z"].values * MILLI,
        depth.values * MICRON,
        shading="nearest",
        cmap="viridis",
    )
    fig.colorbar(cells, ax=ax, label="wear depth [µm]")
    ax.set_xlabel("bushing angle θ [deg]")
    ax.set_ylabel("axial position z [mm]")
    ax.set_title(_title(dataset, "wear map", label))
    return fig


def _profile_rows(depth: xr.DataArray) -> list[tuple[str, np.ndarray]]:
    """The profiles at the mid-plane (interpolated between slices) and at both edges."""
    z = depth["z"].values
    rows = [("mid-plane, z = 0", depth.interp(z=0.0).values)]
    for index in (0, z.size - 1):
        rows.append((f"edge slice, z = {z[index] * MILLI:+.2f} mm", depth.values[index]))
    return rows


def edge_profiles(dataset: xr.Dataset, label: str | None = None) -> Figure:
    """The worn profile at the mid-plane and in each edge slice, against the angle.

    The mid-plane profile is interpolated linearly between the two slices around ``z = 0``
    (an even number of slices has no slice there); the edge profiles are the first and
    last slices', labelled with their centres.

    Parameters
    ----------
    dataset : xarray.Dataset
        A result with slices along the pin.
    label : str, optional
        Title prefix; default the contact model's name.

    Returns
    -------
    matplotlib.figure.Figure
        Wear depth [µm] against the bushing angle [deg], one line per position.

    Raises
    ------
    DataError
        A planar result (no ``z``).
    """
    depth = _checked(dataset, "edge profiles")
    theta_deg = np.degrees(depth["theta"].values)
    fig = new_figure()
    ax = fig.subplots()
    for name, profile in _profile_rows(depth):
        ax.plot(theta_deg, profile * MICRON, label=name)
    ax.set_xlabel("bushing angle θ [deg]")
    ax.set_ylabel("wear depth [µm]")
    ax.set_xlim(0, 360)
    ax.set_title(_title(dataset, "wear at the mid-plane and the edges", label))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def _original_radius(dataset: xr.Dataset, depth: xr.DataArray) -> float:
    """The unworn bore radius [m]: the final radius less the wear, or the joint's radius."""
    if "bushing_radius" in dataset.variables:
        radius = dataset["bushing_radius"].transpose("z", "theta").values - depth.values
        return float(np.median(radius))
    return float(dataset.attrs["bushing_radius"])


def worn_bore(
    dataset: xr.Dataset, exaggeration: float | str = "auto", label: str | None = None
) -> Figure:
    """A 3-D view of the worn bore: the cylinder coloured by wear, the wear exaggerated.

    The half of the bore centred on the deepest wear is drawn, seen from the cut-away
    half. The surface point of node ``j`` in slice ``i`` is drawn at radius ``R_0 + m h_ij``
    (``R_0`` the unworn radius, ``h`` the final wear depth, ``m`` the exaggeration, stated
    in the title) and axial position ``z_i``; its colour is ``h_ij`` [µm].

    Parameters
    ----------
    dataset : xarray.Dataset
        A result with slices along the pin.
    exaggeration : float or "auto"
        Factor on the radial wear [-]; ``"auto"`` takes the power of ten that draws the
        deepest wear at 5-50 % of the radius (:func:`jointwear.plots.polar_magnification`).
    label : str, optional
        Title prefix; default the contact model's name.

    Returns
    -------
    matplotlib.figure.Figure
        A 3-D axes in mm with a colour bar of the wear depth [µm].

    Raises
    ------
    DataError
        A planar result (no ``z``), or an exaggeration that is not a positive number.
    """
    depth = _checked(dataset, "worn bore")
    radius = _original_radius(dataset, depth)
    wear = depth.values
    if exaggeration == "auto":
        factor = polar_magnification(float(wear.max()), radius)
    elif isinstance(exaggeration, (int, float)) and exaggeration > 0:
        factor = float(exaggeration)
    else:
        raise DataError(
            f"worn bore: exaggeration must be a positive number or 'auto', got {exaggeration!r}"
        )
    theta, wear = _half_facing_the_peak(depth)
    drawn = (radius + factor * wear) * MILLI
    z = np.broadcast_to(depth["z"].values[:, None] * MILLI, drawn.shape)
    norm = Normalize(vmin=0.0, vmax=max(float(wear.max()) * MICRON, 1e-12))
    colours = colormaps["viridis"](norm(wear * MICRON))
    fig = new_figure((6.5, 5.5))
    ax = fig.add_subplot(projection="3d")
    ax.plot_surface(
        drawn * np.cos(theta), drawn * np.sin(theta), z, facecolors=colours, shade=False
    )
    # look into the cut-away bore from the open side, at the scar on the far wall
    peak_angle = float(np.degrees(theta[np.argmax(wear.max(axis=0))]))
    ax.view_init(elev=25.0, azim=peak_angle + 180.0)
    fig.colorbar(
        ScalarMappable(norm=norm, cmap=colormaps["viridis"]),
        ax=ax,
        shrink=0.7,
        label="wear depth [µm]",
    )
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_zlabel("z [mm]")
    ax.set_title(_title(dataset, f"worn bore, radial wear x{factor:g}", label), fontsize=10)
    return fig


def _half_facing_the_peak(depth: xr.DataArray) -> tuple[np.ndarray, np.ndarray]:
    """The half of the bore centred on the deepest wear: angles [rad] and wear [m].

    The near half is cut away so that the worn inner surface can be seen; the angles run
    without a jump across 0.
    """
    theta = depth["theta"].values
    wear = depth.values
    centre = theta[np.argmax(wear.max(axis=0))]
    relative = wrap_angle(theta - centre)
    order = np.argsort(relative)
    kept = order[np.abs(relative[order]) <= np.pi / 2 + 1e-12]
    return centre + relative[kept], wear[:, kept]


_DRAW: dict[str, Callable[[xr.Dataset, str | None], Figure]] = {
    "wear_map": wear_map,
    "edge_profiles": edge_profiles,
    "worn_bore": lambda dataset, label: worn_bore(dataset, label=label),
}


def deepest_slice(dataset: xr.Dataset) -> xr.Dataset:
    """The result of the slice with the deepest final wear, its ``z`` dropped.

    Every variable over ``z`` is taken at that slice; the planar figures
    (:func:`jointwear.plots.plot_result`) draw it as one cross-section.

    Parameters
    ----------
    dataset : xarray.Dataset
        A result with slices along the pin.

    Returns
    -------
    xarray.Dataset
        The planar result of that slice; its ``z`` [m] stays as a scalar coordinate.

    Raises
    ------
    DataError
        A planar result (no ``z``).
    """
    depth = _checked(dataset, "deepest slice")
    row = int(np.unravel_index(int(np.argmax(depth.values)), depth.shape)[0])
    return dataset.isel(z=row)


def plot_axial_result(
    dataset: xr.Dataset,
    directory: str | Path,
    magnification: float | str = "auto",
    label: str | None = None,
) -> list[Path]:
    """Draw a result along the pin into ``directory`` (PNG + SVG each).

    First the planar figures (:data:`jointwear.plots.FIGURES`) of the slice with the
    deepest wear (:func:`deepest_slice`), its position in their titles, then
    :data:`AXIAL_FIGURES`.

    Parameters
    ----------
    dataset : xarray.Dataset
        A result with slices along the pin.
    directory : path-like
        Output folder (created).
    magnification : float or "auto"
        Wear magnification of the planar polar plot [-].
    label : str, optional
        Title prefix; default the contact model's name.

    Returns
    -------
    list of Path
        The files written.

    Raises
    ------
    DataError
        A planar result (no ``z``).
    """
    deepest = deepest_slice(dataset)
    prefix = label if label is not None else str(dataset.attrs.get("contact_model", ""))
    where = f"slice z = {float(deepest['z']) * MILLI:+.2f} mm"
    written = plot_result(
        deepest, directory, magnification=magnification, label=f"{prefix}, {where}".lstrip(", ")
    )
    for kind in AXIAL_FIGURES:
        written += save_figure(_DRAW[kind](dataset, label), directory, kind)
    return written
