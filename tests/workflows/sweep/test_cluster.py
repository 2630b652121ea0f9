"""Cases on a dask cluster: the records of a serial sweep; one-line errors without one."""

from __future__ import annotations

import sys

import numpy as np
import pytest
import xarray as xr

from jointwear.errors import ConfigError
from jointwear.workflows.sweep import DATASET_FILE, run_sweep
from tests.workflows.sweep.conftest import comparable


def test_missing_dask_is_a_one_line_error(tmp_path, monkeypatch, serial):
    plan, _ = serial
    monkeypatch.setitem(sys.modules, "dask.distributed", None)
    with pytest.raises(ConfigError, match=r"dask.distributed is not installed.*jointwear\[sweep\]"):
        run_sweep(plan, tmp_path / "out", scheduler="tcp://127.0.0.1:8786")
    assert not (tmp_path / "out").exists()


def test_unreachable_scheduler_leaves_nothing_behind(tmp_path, serial):
    pytest.importorskip("dask.distributed")
    plan, _ = serial
    with pytest.raises(ConfigError, match="--scheduler: cannot connect to tcp://127.0.0.1:9"):
        run_sweep(plan, tmp_path / "out", scheduler="tcp://127.0.0.1:9", connect_timeout=0.5)
    assert not (tmp_path / "out").exists()


# ---------------------------------------------------------------- dask (last: its threads
# make later local pools start by forkserver instead of fork)


def test_dask_local_cluster_equals_serial_exactly(serial, tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    plan, reference = serial
    with (
        distributed.LocalCluster(
            n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        result = run_sweep(plan, tmp_path / "out", client=client)
    assert result.scheduler.startswith("tcp://")
    assert comparable(result.records) == comparable(reference.records)
    with (
        xr.open_dataset(tmp_path / "out" / DATASET_FILE, engine="h5netcdf") as ds,
        xr.open_dataset(reference.out / DATASET_FILE, engine="h5netcdf") as ref,
    ):
        np.testing.assert_array_equal(ds["wear_depth"].values, ref["wear_depth"].values)
