"""A result as plain arrays: read like the Dataset it becomes, built once, shared."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import DataError
from jointwear.results import ResultContents, summarize
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
    assert np.shares_memory(
        result.dataset["wear_depth"].values, result.joint_data()["wear_depth"].values
    )


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
