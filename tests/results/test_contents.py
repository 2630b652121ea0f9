"""A result as plain arrays: read like the Dataset it becomes, built once, shared."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from jointwear import Simulation
from jointwear.config import Config
from jointwear.errors import DataError
from jointwear.mechanism import LoadCycle
from jointwear.results import ResultContents, summarize
from jointwear.results.summary import WALL_CLOCK_KEYS
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
    for key in WALL_CLOCK_KEYS:
        summary.pop(key), reference.pop(key)
    assert summary == reference


def test_joint_data_names_the_joint_it_holds(result):
    own = result.joints[0]
    assert result.joint_data(own) is result.joint_data()
    with pytest.raises(DataError, match="no clearance joint 'crank-rod'"):
        result.joint_data("crank-rod")


def test_contents_are_built_from_a_plain_record_alone(paper_config):
    """No simulation needed: a record made by hand (a load history with a diagnostic beside
    it, two saved profiles, one dynamics solve) gives the variables, named and sized."""
    from jointwear.coupling import dynamics_row
    from jointwear.mechanism.cycle import Diagnostic
    from jointwear.record import RunRecord
    from jointwear.results import build_contents
    from jointwear.state import Log, SimulationState

    nodes, steps = paper_config.contact.nodes, 6
    phase = np.linspace(0.0, 2 * np.pi, steps, endpoint=False)
    cycle = LoadCycle.from_arrays(
        100 + 10 * np.cos(phase),
        0.2 * np.sin(phase),
        np.full(steps, 0.1),
        diagnostics={"torque": Diagnostic(np.sin(phase), "N m", "a torque")},
    )
    depth = np.linspace(0.0, 1e-6, nodes)
    rows = [{"revolution": r, "peak_wear_depth": float(r * depth.max())} for r in (1, 2)]
    state = SimulationState(
        revolution=2,
        wear_depth=2 * depth,
        history=Log.of(rows),
        profiles=Log.of([(1, depth), (2, 2 * depth)]),
        dynamics_updates=Log.of([dynamics_row(cycle, 0, 0 * depth, 5e-5, None)]),
    )
    record = RunRecord(paper_config, state, cycle, 0.0075 * 0.1 * np.ones(steps), "nlcp")
    contents = build_contents(record)
    assert contents.sizes == {
        "theta": nodes,
        "revolution": 2,
        "step": steps,
        "update": 2,
        "dynamics_update": 1,
    }
    np.testing.assert_array_equal(contents["wear_depth"].values[-1], 2 * depth)
    assert contents["torque"].attrs == {"units": "N m", "long_name": "a torque"}
    assert contents["dynamics_impacts"].values.tolist() == [0.0]
    assert contents["peak_wear_depth"].values.tolist() == [depth.max(), 2 * depth.max()]
    assert "pressure_initial" not in contents  # no contact snapshots in the record
    assert contents.attrs["contact_model"] == "nlcp"
    assert contents.attrs["mechanism"] == cycle.mechanism
