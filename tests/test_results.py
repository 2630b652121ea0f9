"""Results: netCDF round trip, attributes, metrics CSV."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import DataError
from jointwear.results import (
    ResultContents,
    config_of,
    read_result,
    summarize,
    write_metrics_csv,
)
from jointwear.tribology.metrics import engineering_checks


@pytest.fixture(scope="module")
def result(paper_config: Config):
    config = paper_config.replace(
        {
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 90,
            "simulation.revolutions": 300,
            "simulation.update_contour": True,
            "simulation.update_every": 50,
            "simulation.saved_profiles": 3,
        }
    )
    return Simulation(config).run()


def test_netcdf_round_trip(result, tmp_path) -> None:
    path = tmp_path / "result.nc"
    result.to_netcdf(path)
    back = read_result(path)
    xr.testing.assert_identical(back, result.dataset)
    # the stored config has every default written out: it resolves to the same values
    assert config_of(back).to_dict() == result.config.to_dict()


def test_every_variable_has_units_and_long_name(result) -> None:
    for name, variable in result.dataset.variables.items():
        assert "units" in variable.attrs, name
        assert "long_name" in variable.attrs, name
    assert result.dataset["wear_depth"].attrs["units"] == "m"
    assert "[contact]" in result.dataset.attrs["config"]


def test_metrics_csv_has_a_row_per_update(result, tmp_path) -> None:
    path = tmp_path / "metrics.csv"
    write_metrics_csv(result.dataset, path)
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == result.dataset.sizes["update"] == 6
    assert float(rows[-1]["wear_width [deg]"]) == pytest.approx(
        result.summary()["wear_width_deg"], rel=1e-9
    )
    assert float(rows[-1]["peak_wear_depth [m]"]) == pytest.approx(
        float(result.wear_depth.max()), rel=1e-9
    )


def test_final_profile_matches_the_final_radius(result) -> None:
    ds = result.dataset
    np.testing.assert_allclose(
        ds["bushing_radius"].values - result.config.joint.bushing_radius,
        ds["wear_depth"].values[-1],
        rtol=1e-6,
        atol=1e-15,
    )


@pytest.mark.parametrize("content", [b"", b"not a netcdf file", b"\x89HDF\r\n\x1a\n" + b"\0" * 40])
def test_unreadable_result_is_a_data_error(tmp_path, content: bytes) -> None:
    path = tmp_path / "broken.nc"
    path.write_bytes(content)
    with pytest.raises(DataError, match="broken.nc"):
        read_result(path)


def test_truncated_result_is_a_data_error(result, tmp_path) -> None:
    path = tmp_path / "result.nc"
    result.to_netcdf(path)
    data = path.read_bytes()
    path.write_bytes(data[: len(data) // 2])
    with pytest.raises(DataError, match="result.nc"):
        read_result(path)


# ---------------------------------------------------------------- plain arrays


def test_contents_read_like_the_dataset(result):
    contents = result.joint_data()
    assert isinstance(contents, ResultContents)
    dataset = result.dataset
    assert set(contents.data_vars) == set(dataset.data_vars)
    assert set(contents.coords) == set(dataset.coords)
    for name in (*contents.data_vars, *contents.coords):
        assert name in contents
        assert contents[name].dims == dataset[name].dims
        assert contents[name].attrs == dataset[name].attrs
        assert contents[name].dtype == dataset[name].dtype
        np.testing.assert_array_equal(contents[name].values, dataset[name].values)
    assert contents.attrs == dataset.attrs
    assert contents.sizes == dict(dataset.sizes)
    assert "no_such_variable" not in contents
    with pytest.raises(KeyError):
        contents["no_such_variable"]


def test_summary_and_checks_equal_those_of_the_dataset(result):
    config = result.config
    assert summarize(result.joint_data()) == summarize(result.dataset)
    assert engineering_checks(result.joint_data(), config, warn=False) == engineering_checks(
        result.dataset, config, warn=False
    )
    np.testing.assert_array_equal(
        result.wear_depth, result.dataset["wear_depth"].isel(revolution=-1).values
    )


def test_the_dataset_is_built_once_and_shares_the_arrays(result):
    assert result.dataset is result.dataset
    assert isinstance(result.dataset, xr.Dataset)
    assert np.shares_memory(result.dataset["wear_depth"].values,
                            result.joint_data()["wear_depth"].values)


def test_without_pressures_the_wear_is_the_same(result):
    lean = Simulation(result.config).run(pressures=False)
    contents = lean.joint_data()
    for name in ("pressure_initial", "pressure_final", "contact_half_angle", "snapshot"):
        assert name not in contents
        assert name not in lean.dataset
    np.testing.assert_array_equal(lean.wear_depth, result.wear_depth)
    full = result.joint_data()
    for name in contents.data_vars:
        np.testing.assert_array_equal(contents[name].values, full[name].values)
    summary, reference = lean.summary(), result.summary()
    for key in ("runtime_s",):
        summary.pop(key), reference.pop(key)
    assert summary == reference


def test_joint_data_names_the_joint_it_holds(result):
    own = result.joints[0]
    assert result.joint_data(own) is result.joint_data()
    with pytest.raises(DataError, match="no clearance joint 'crank-rod'"):
        result.joint_data("crank-rod")
