"""The figures along the pin, on results in the layout of a run cut into axial slices.

``wear_depth`` over ``("revolution", "z", "theta")``, ``bushing_radius`` and
``wear_rate`` over ``("z", "theta")``, ``z`` the slice centres [m] (0 at the mid-plane).
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from matplotlib.collections import QuadMesh
from matplotlib.figure import Figure

from jointwear.errors import DataError
from jointwear.plots_axial import (
    AXIAL_FIGURES,
    deepest_slice,
    edge_profiles,
    wear_map,
    worn_bore,
)

RADIUS = 7.5e-3
LENGTH = 20e-3
NODES = 72
SLICES = 8


def slice_centres(count: int = SLICES) -> np.ndarray:
    return ((np.arange(count) + 0.5) / count - 0.5) * LENGTH


def axial_wear(
    z: np.ndarray, theta: np.ndarray, peak: float, where: tuple[float, float]
) -> np.ndarray:
    """A scar around ``where = (theta, z)`` [rad, m] of depth ``peak`` [m] (no other maximum)."""
    angle = np.angle(np.exp(1j * (theta[None, :] - where[0])))
    axial = (z[:, None] - where[1]) / LENGTH
    return peak * np.exp(-((angle / 0.5) ** 2) - (axial / 0.4) ** 2)


def axial_result(peak: float = 12e-6, where: tuple[float, float] = (np.pi / 2, -8.75e-3)):
    """A synthetic result of three saved revolutions on ``SLICES`` slices."""
    theta = np.linspace(0.0, 2 * np.pi, NODES, endpoint=False)
    z = slice_centres()
    revolutions = np.array([0.0, 500.0, 1000.0])
    final = axial_wear(z, theta, peak, where)
    depth = np.stack([final * (rev / revolutions[-1]) for rev in revolutions])
    return xr.Dataset(
        {
            "wear_depth": (("revolution", "z", "theta"), depth, {"units": "m"}),
            "bushing_radius": (("z", "theta"), RADIUS + final, {"units": "m"}),
            "wear_rate": (("z", "theta"), final / revolutions[-1], {"units": "m"}),
        },
        coords={
            "revolution": revolutions,
            "z": ("z", z, {"units": "m", "long_name": "axial position of the slice centre"}),
            "theta": theta,
        },
        attrs={"contact_model": "asymmetric-winkler"},
    )


def planar_result() -> xr.Dataset:
    theta = np.linspace(0.0, 2 * np.pi, NODES, endpoint=False)
    depth = np.stack([np.zeros(NODES), 1e-6 * np.cos(theta) ** 2])
    return xr.Dataset(
        {
            "wear_depth": (("revolution", "theta"), depth),
            "bushing_radius": (("theta",), RADIUS + depth[-1]),
        },
        coords={"revolution": [0.0, 10.0], "theta": theta},
    )


def heat_map(fig: Figure) -> QuadMesh:
    (cells,) = [c for c in fig.axes[0].collections if isinstance(c, QuadMesh)]
    return cells


#: (angle [rad], z [m]) on a node and a slice centre: 70 deg, 280 deg, 0 deg
PLACES = [(np.radians(70.0), -8.75e-3), (np.radians(280.0), 6.25e-3), (0.0, 1.25e-3)]


@pytest.mark.parametrize("where", PLACES)
def test_wear_map_shows_the_deepest_cell_where_it_is(where):
    dataset = axial_result(where=where)
    fig = wear_map(dataset)
    cells = heat_map(fig)
    values = np.asarray(cells.get_array()).reshape(SLICES, NODES)
    np.testing.assert_allclose(values, dataset["wear_depth"].values[-1] * 1e6, rtol=1e-12)
    row, col = np.unravel_index(np.argmax(values), values.shape)
    # the cell's centre: its corners' mean, in the axes' units (deg across, mm up)
    corners = cells.get_coordinates()
    centre = corners[row : row + 2, col : col + 2].reshape(4, 2).mean(axis=0)
    assert centre[0] == pytest.approx(np.degrees(where[0]), abs=1e-9)
    assert centre[1] == pytest.approx(where[1] * 1e3, abs=1e-9)
    # the slices' cells tile the bushing's length: the outer edges are the bushing's ends
    assert corners[0, 0, 1] == pytest.approx(-LENGTH / 2 * 1e3)
    assert corners[-1, 0, 1] == pytest.approx(LENGTH / 2 * 1e3)


def test_wear_map_labels_its_axes_and_colour_bar_in_their_units():
    fig = wear_map(axial_result())
    ax, bar = fig.axes
    assert ax.get_xlabel() == "bushing angle θ [deg]"
    assert ax.get_ylabel() == "axial position z [mm]"
    assert bar.get_ylabel() == "wear depth [µm]"
    assert "after 1000 revolutions" in ax.get_title()
    assert ax.get_title().startswith("asymmetric-winkler: ")
    _, high = heat_map(fig).get_clim()
    assert high == pytest.approx(12.0, rel=1e-3)  # the deepest wear, 12 µm


def test_edge_profiles_are_the_edge_slices_and_the_interpolated_mid_plane():
    dataset = axial_result(where=(2.0, -8.75e-3))
    final = dataset["wear_depth"].values[-1]
    fig = edge_profiles(dataset)
    ax = fig.axes[0]
    lines = {line.get_label(): line.get_ydata() for line in ax.lines}
    assert list(lines) == [
        "mid-plane, z = 0",
        "edge slice, z = -8.75 mm",
        "edge slice, z = +8.75 mm",
    ]
    # an even slice count: the mid-plane lies halfway between the two central slices
    middle = SLICES // 2
    np.testing.assert_allclose(
        lines["mid-plane, z = 0"], 0.5 * (final[middle - 1] + final[middle]) * 1e6, rtol=1e-12
    )
    np.testing.assert_allclose(lines["edge slice, z = -8.75 mm"], final[0] * 1e6, rtol=1e-12)
    np.testing.assert_allclose(lines["edge slice, z = +8.75 mm"], final[-1] * 1e6, rtol=1e-12)
    assert ax.get_ylabel() == "wear depth [µm]"
    assert ax.get_xlabel() == "bushing angle θ [deg]"
    # the scar sits at the z < 0 edge: that edge's line holds the peak
    assert max(lines["edge slice, z = -8.75 mm"]) == pytest.approx(12.0, rel=1e-2)


def test_worn_bore_draws_the_cylinder_with_the_stated_exaggeration():
    dataset = axial_result(peak=12e-6, where=(0.0, 8.75e-3))
    fig = worn_bore(dataset, exaggeration=50.0)
    ax, bar = fig.axes
    assert "radial wear x50" in ax.get_title()
    assert bar.get_ylabel() == "wear depth [µm]"
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()) == ("x [mm]", "y [mm]", "z [mm]")
    # the surface reaches out to R_0 + 50 h_max at the scar (theta = 0: along x)
    x_high = ax.get_xlim()[1]
    assert x_high >= (RADIUS + 50 * 12e-6) * 1e3 * 0.999
    auto = worn_bore(dataset)
    assert "radial wear x100" in auto.axes[0].get_title()  # 10^floor(log10(0.5 R / h))
    with pytest.raises(DataError, match="^worn bore: exaggeration must be a positive number"):
        worn_bore(dataset, exaggeration=-3.0)


@pytest.mark.parametrize("draw", [wear_map, edge_profiles, worn_bore, deepest_slice])
def test_a_planar_result_is_refused(draw):
    with pytest.raises(DataError, match=r"the result is planar \(wear_depth has no axial"):
        draw(planar_result())


def test_deepest_slice_is_the_slice_holding_the_peak():
    dataset = axial_result(where=(1.0, 3.75e-3))
    single = deepest_slice(dataset)
    assert "z" not in single.dims
    assert float(single["z"]) == pytest.approx(3.75e-3)
    assert single["wear_depth"].dims == ("revolution", "theta")
    assert single["bushing_radius"].dims == ("theta",)


@pytest.fixture(scope="module")
def sliced_run():
    """A short planar run, its wear spread over slices (deepest at the z < 0 edge)."""
    import jointwear as jw

    config = jw.load_config(None, {"contact.nodes": NODES, "simulation.steps_per_revolution": 90})
    dataset = jw.Simulation(config).run().dataset
    z = xr.DataArray(slice_centres(), dims="z")
    edge = 1.0 - z / LENGTH  # 1.4375 at the z < 0 edge slice, 0.5625 at the other
    dataset = dataset.assign(
        wear_depth=dataset["wear_depth"] * edge,
        bushing_radius=dataset["bushing_radius"]
        + (dataset["wear_depth"].isel(revolution=-1) * (edge - 1)),
    )
    return dataset.assign_coords(z=z.assign_attrs(units="m", long_name="slice centre"))


def test_a_run_with_slices_draws_the_maps_beside_the_deepest_slice(sliced_run, tmp_path):
    from jointwear.plots import FIGURES
    from jointwear.workflows.run import plot_joints

    assert float(deepest_slice(sliced_run)["z"]) == pytest.approx(slice_centres()[0])
    written = plot_joints(sliced_run, tmp_path)
    stems = sorted({path.stem for path in written})
    assert stems == sorted((*FIGURES, *AXIAL_FIGURES))
    assert all(path.stat().st_size > 1000 for path in written)
    # without z: the planar figures only, as before
    planar = plot_joints(sliced_run.isel(z=3), tmp_path / "planar")
    assert sorted({path.stem for path in planar}) == sorted(FIGURES)
