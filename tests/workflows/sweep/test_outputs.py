"""What a sweep writes: cases.csv and sweep.nc, one row and one entry per case."""

from __future__ import annotations

import csv

import numpy as np
import pytest
import xarray as xr

from jointwear.workflows.sweep import CASES_CSV, DATASET_FILE, METRICS


def test_serial_sweep_writes_cases_csv_and_dataset(serial):
    _, result = serial
    out = result.out
    assert result.scheduler == "serial"
    assert result.counts == {"ok": 8, "failed": 0, "error": 0}
    with open(out / CASES_CSV, newline="", encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 8
    header = list(rows[0])
    assert header[:5] == [
        "case",
        "joint.clearance [m]",
        "mechanism.crank_speed [rad/s]",
        "contact.model",
        "contact.exponent",
    ]
    assert header[5:] == [*METRICS, "status", "error"]
    assert float(rows[-1]["joint.clearance [m]"]) == pytest.approx(2e-4)
    assert rows[1]["contact_model"] == "nlcp"
    assert float(rows[0]["peak_wear_depth_m"]) == result.records[0]["metrics"]["peak_wear_depth_m"]
    with xr.open_dataset(out / DATASET_FILE, engine="h5netcdf") as ds:
        assert ds.sizes == {"case": 8, "theta": 60}
        assert ds["wear_depth"].attrs["units"] == "m"
        assert ds["joint.clearance"].attrs["units"] == "m"
        np.testing.assert_array_equal(
            ds["peak_wear_depth_m"].values,
            [r["metrics"]["peak_wear_depth_m"] for r in result.records],
        )
        np.testing.assert_array_equal(
            ds["wear_depth"].values.max(axis=1), ds["peak_wear_depth_m"].values
        )
        assert list(ds["status"].values) == ["ok"] * 8
    assert not [p for p in out.rglob(".*")]  # no temporary files
