"""A run along the pin in its result: the z coordinate, the layout of the maps, the
summary's axial keys, and result.nc read back."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.contact.axial import AxialSlices
from jointwear.results import read_wear_result
from jointwear.results.axial import axial_summary

SMALL = {
    "contact.nodes": 48,
    "simulation.steps_per_revolution": 12,
    "simulation.revolutions": 3,
    "simulation.update_contour": True,
    "contact.spring_area": None,
}


def test_a_map_along_the_pin_is_written_and_read_back(tmp_path):
    config = load_config(overrides={**SMALL, "joint.axial_slices": 5, "joint.load_offset": "3 mm"})
    result = Simulation(config).run()
    dataset = result.dataset
    assert dataset["wear_depth"].dims == ("revolution", "z", "theta")
    assert dataset["wear_rate"].dims == dataset["bushing_radius"].dims == ("z", "theta")
    z = dataset["z"]
    np.testing.assert_array_equal(z.values, AxialSlices(0.02, 5).centres)
    assert z.attrs["units"] == "m"
    assert "mid-plane" in z.attrs["long_name"]
    np.testing.assert_array_equal(
        dataset["bushing_radius"].values, config.bushing_radius + result.wear_depth
    )
    summary = result.summary()
    assert summary["peak_wear_z_m"] == pytest.approx(0.008)  # the load is towards +z
    assert summary["edge_to_mid_wear_ratio"] > 1.0
    result.to_netcdf(tmp_path / "result.nc")
    back = read_wear_result(tmp_path / "result.nc")
    np.testing.assert_array_equal(back.wear_depth, result.wear_depth)
    assert back.summary()["peak_wear_z_m"] == summary["peak_wear_z_m"]
    assert back.summary()["edge_to_mid_wear_ratio"] == summary["edge_to_mid_wear_ratio"]


def test_a_planar_result_keeps_its_layout_and_keys(tmp_path):
    result = Simulation(load_config(overrides=SMALL)).run()
    assert result.dataset["wear_depth"].dims == ("revolution", "theta")
    assert "z" not in result.dataset.coords
    summary = result.summary()
    assert "peak_wear_z_m" not in summary
    assert "edge_to_mid_wear_ratio" not in summary


def test_the_axial_summary_of_a_map():
    z = AxialSlices(0.02, 4).centres
    theta = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    shape = np.cos(theta).clip(0)
    depth = np.outer([4.0, 1.0, 3.0, 2.0], shape)
    summary = axial_summary(depth, z)
    assert summary["peak_wear_z_m"] == z[0]
    # the deeper edge (4) over the mean of the two middle slices' peaks (2)
    assert summary["edge_to_mid_wear_ratio"] == pytest.approx(2.0)
    unworn_middle = np.outer([1.0, 0.0, 0.0, 1.0], shape)
    assert axial_summary(unworn_middle, z)["edge_to_mid_wear_ratio"] is None
