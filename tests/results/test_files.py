"""Result files: netCDF round trip, attributes, metrics CSV, unreadable files refused."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import DataError
from jointwear.results import config_of, read_result, write_metrics_csv


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
        float(result.wear_depth.max()), rel=1e-9, abs=0
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
