"""A result file written from plain arrays with h5netcdf: the file xarray writes."""

from __future__ import annotations

import io
import math
from pathlib import Path

import h5py
import numpy as np
import pytest
import xarray as xr

from jointwear import Simulation, load_config
from jointwear.results import ResultContents, ResultVariable, read_result, write_netcdf
from jointwear.results.netcdf_file import contents_netcdf, writes_plainly

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

#: runs whose results differ in what they hold: contour updates, an oscillating liner's
#: cycle, a duty cycle (global number attribute), a lubricated run (film variables),
#: slices along a beam pin (a ``z`` coordinate, maps over (z, theta), the pin's wear)
RUNS = {
    "paper, updated": (
        None,
        {
            "simulation.revolutions": 300,
            "simulation.update_every": 50,
            "simulation.saved_profiles": 3,
        },
    ),
    "oscillating liner": (EXAMPLES / "oscillating_liner.toml", {"simulation.revolutions": 2}),
    "duty cycle": (EXAMPLES / "duty_cycle.toml", {"simulation.revolutions": 2}),
    "oiled": (
        "",
        {
            "materials.pin": "steel",
            "materials.bushing": "bronze",
            "simulation.steps_per_revolution": 90,
            "simulation.revolutions": 1,
            "lubrication.model": "finite-length",
            "lubrication.lubricant": "iso-vg-68",
            "lubrication.roughness": "0.1 um",
        },
    ),
    "slices along a beam pin": (
        "",
        {
            "contact.model": "asymmetric-winkler",
            "contact.nodes": 90,
            "simulation.steps_per_revolution": 45,
            "simulation.revolutions": 3,
            "simulation.update_contour": False,
            "joint.axial_slices": 4,
            "pin.model": "beam",
            "pin.support": "clevis",
            "pin.forks": ["-15 mm", "15 mm"],
            "joint.misalignment": "0.03 deg",
        },
    ),
}


def xarray_netcdf(contents: ResultContents) -> bytes:
    return bytes(contents.to_dataset().to_netcdf(engine="h5netcdf", invalid_netcdf=False))


def opened(data: bytes) -> xr.Dataset:
    with xr.open_dataset(io.BytesIO(data), engine="h5netcdf") as handle:
        return handle.load()


def hdf5_layout(data: bytes) -> dict[str, object]:
    """Every HDF5 object of a file: shape, dtype, layout, fill value and attributes."""

    def shown(value: object) -> str:  # (NaN fill values compare by their text)
        return repr(value.tolist() if isinstance(value, np.ndarray) else value)

    layout: dict[str, object] = {}
    with h5py.File(io.BytesIO(data), "r") as handle:
        layout["/"] = {key: shown(value) for key, value in handle.attrs.items()}

        def visit(name: str, item: object) -> None:
            if isinstance(item, h5py.Dataset):
                attrs = {
                    key: len(value) if key in ("DIMENSION_LIST", "REFERENCE_LIST") else shown(value)
                    for key, value in item.attrs.items()
                }
                layout[name] = (item.shape, str(item.dtype), item.chunks, item.compression)
                layout[name + " fill"] = shown(item.fillvalue)
                layout[name + " attrs"] = attrs

        handle.visititems(visit)
    return layout


@pytest.fixture(scope="module", params=list(RUNS))
def contents(request, paper_config_path) -> ResultContents:
    path, overrides = RUNS[request.param]
    config = load_config(paper_config_path if path is None else (path or None), overrides)
    data = Simulation(config).run().data
    assert isinstance(data, ResultContents)
    return data


def test_every_run_of_one_joint_is_written_plainly(contents) -> None:
    assert writes_plainly(contents)


def test_xarray_reads_the_file_as_it_reads_its_own(contents) -> None:
    ours, theirs = contents_netcdf(contents), xarray_netcdf(contents)
    mine, reference = opened(ours), opened(theirs)
    xr.testing.assert_identical(mine, reference)
    assert list(mine.variables) == list(reference.variables)
    assert list(mine.dims) == list(reference.dims)
    assert list(mine.attrs) == list(reference.attrs)
    for name, variable in mine.variables.items():
        own = {k: v for k, v in variable.encoding.items() if k != "source"}
        their = {k: v for k, v in reference[name].encoding.items() if k != "source"}
        assert repr(own) == repr(their), name
        assert list(variable.attrs) == list(reference[name].attrs), name


def test_the_hdf5_objects_are_those_xarray_writes(contents) -> None:
    # dimension scales, dtypes, contiguous layout, NaN fill values of floats only,
    # ``coordinates`` attributes of the non-dimension coordinates
    assert hdf5_layout(contents_netcdf(contents)) == hdf5_layout(xarray_netcdf(contents))


def test_read_result_reads_the_written_file(contents, tmp_path) -> None:
    path = tmp_path / "result.nc"
    write_netcdf(contents, path)
    back = read_result(path)
    xr.testing.assert_identical(back, contents.to_dataset())


def plain(**attrs: object) -> ResultContents:
    theta = ResultVariable(("theta",), np.linspace(0, 1, 4), {"units": "rad", "long_name": "a"})
    depth = ResultVariable(("theta",), np.zeros(4), {"units": "m", "long_name": "b"})
    return ResultContents({"wear_depth": depth}, {"theta": theta}, {"title": "t", **attrs})


@pytest.mark.parametrize(
    "contents",
    [
        plain(flag=True),
        plain(coordinates="theta"),
        plain(values=[1.0, 2.0]),
        ResultContents(
            {"name": ResultVariable(("theta",), np.array(["a", "b"]), {"units": "1"})}, {}, {}
        ),
        ResultContents(
            {"wear_depth": ResultVariable(("theta",), np.zeros(2), {"units": "m", "note": "x"})},
            {},
            {},
        ),
        ResultContents({"a/b": ResultVariable(("theta",), np.zeros(2), {"units": "m"})}, {}, {}),
    ],
    ids=["boolean attribute", "global coordinates", "list attribute", "text", "other", "slash"],
)
def test_other_contents_go_to_xarray(contents) -> None:
    assert not writes_plainly(contents)


def test_a_coordinate_no_variable_has_goes_into_the_global_attribute() -> None:
    contents = plain(period_s=0.5, count=3)
    contents.coords["label_angle"] = ResultVariable(
        ("snapshot",), np.arange(3.0), {"units": "rad", "long_name": "c"}
    )
    contents.coords["theta_m"] = ResultVariable(
        ("theta",), np.arange(4.0), {"units": "m", "long_name": "d"}
    )
    assert writes_plainly(contents)
    ours = contents_netcdf(contents)
    assert hdf5_layout(ours) == hdf5_layout(xarray_netcdf(contents))
    with h5py.File(io.BytesIO(ours), "r") as handle:
        assert handle.attrs["coordinates"] == "label_angle"
        assert handle["wear_depth"].attrs["coordinates"] == "theta_m"
    back = opened(ours)
    assert set(back.coords) == {"theta", "label_angle", "theta_m"}
    assert math.isclose(back.attrs["period_s"], 0.5)
    assert back.attrs["count"] == 3
