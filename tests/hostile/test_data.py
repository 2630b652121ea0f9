"""Hostile data content: results whose numbers are not wear, rings far from the origin.

A result file must hold wear depths: ``wear_depth`` over ``(revolution, theta)`` and
``peak_wear_depth``, in metres, finite and non-negative; ``plot`` and ``compare``
refuse anything else naming the file and the variable. A measured ring far from the
origin is fitted without reporting the coordinates' round-off as a wear scar.
"""

from __future__ import annotations

import tempfile
from functools import cache
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from jointwear.measurement.fit import (
    coordinate_resolution,
    fit_circle_least_squares,
    fit_circle_robust,
)
from jointwear.measurement.profile import measured_wear_profile, wear_metrics
from tests.hostile.harness import CSV_HEADER, Bad, check_contract, run_cli

RING = CSV_HEADER + "".join(
    f"{7.5 * np.cos(t):.6f},{7.5 * np.sin(t):.6f}\n"
    for t in np.linspace(0, 2 * np.pi, 36, endpoint=False)
)


@cache
def _result(change: str = "") -> bytes:
    """A minimal result file; ``change`` names what is wrong with it."""
    depth = np.tile(np.linspace(0.0, 1e-6, 36), (2, 1))
    peak = np.array([1e-6])
    depth_units, depth_dims = "m", ("revolution", "theta")
    if change == "negative":
        depth[1, 3] = -2e-3
    elif change == "nan":
        depth[1, 3] = np.nan
    elif change == "inf-peak":
        peak[0] = np.inf
    elif change == "negative-peak":
        peak[0] = -1e-6
    elif change == "millimetres":
        depth_units = "mm"
    data = {
        "wear_depth": xr.Variable(depth_dims, depth, {"units": depth_units}),
        "peak_wear_depth": xr.Variable(("update",), peak, {"units": "m"}),
    }
    coords = {"theta": np.linspace(0, 2 * np.pi, 36, endpoint=False), "revolution": [0, 1]}
    if change == "flat":
        data["wear_depth"] = xr.Variable(("x",), depth.ravel(), {"units": "m"})
        coords = {}
    elif change == "text":
        data["wear_depth"] = xr.Variable(depth_dims, np.full(depth.shape, "a"), {"units": "m"})
    elif change == "no-theta":
        coords = {"revolution": [0, 1]}
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "r.nc"
        xr.Dataset(data, coords=coords).to_netcdf(path, engine="h5netcdf")
        return path.read_bytes()


def _compare() -> list[str]:
    return ["compare", "{tmp}/bad.nc", "{tmp}/ring.csv", "--out", "{out}"]


CASES: list[Bad] = [
    Bad(
        "plot-negative-wear",
        "data",
        ["plot", "{tmp}/bad.nc"],
        ["bad.nc", "variable 'wear_depth' has negative wear", "-0.002 m"],
        {"bad.nc": _result("negative")},
    ),
    Bad(
        "compare-negative-wear",
        "data",
        _compare(),
        ["bad.nc", "variable 'wear_depth' has negative wear"],
        {"bad.nc": _result("negative"), "ring.csv": RING},
    ),
    Bad(
        "compare-nan-wear",
        "data",
        _compare(),
        ["bad.nc", "variable 'wear_depth' has 1 non-finite value(s)"],
        {"bad.nc": _result("nan"), "ring.csv": RING},
    ),
    Bad(
        "plot-infinite-peak",
        "data",
        ["plot", "{tmp}/bad.nc"],
        ["bad.nc", "variable 'peak_wear_depth'", "non-finite"],
        {"bad.nc": _result("inf-peak")},
    ),
    Bad(
        "compare-negative-peak",
        "data",
        _compare(),
        ["bad.nc", "variable 'peak_wear_depth' has negative wear"],
        {"bad.nc": _result("negative-peak"), "ring.csv": RING},
    ),
    Bad(
        "plot-wear-in-millimetres",
        "data",
        ["plot", "{tmp}/bad.nc"],
        ["bad.nc", "variable 'wear_depth' is in 'mm', expected 'm'"],
        {"bad.nc": _result("millimetres")},
    ),
    Bad(
        "plot-wear-without-grid",
        "data",
        ["plot", "{tmp}/bad.nc"],
        ["bad.nc", "variable 'wear_depth' has dimensions ('x',)"],
        {"bad.nc": _result("flat")},
    ),
    Bad(
        "compare-wear-as-text",
        "data",
        _compare(),
        ["bad.nc", "variable 'wear_depth'", "not real numbers"],
        {"bad.nc": _result("text"), "ring.csv": RING},
    ),
    Bad(
        "plot-without-theta",
        "data",
        ["plot", "{tmp}/bad.nc"],
        ["bad.nc", "no 'theta' coordinate"],
        {"bad.nc": _result("no-theta")},
    ),
    Bad(
        "compare-garbage-netcdf",
        "data",
        _compare(),
        ["bad.nc", "not a readable netCDF result"],
        {"bad.nc": b"\x89HDF\r\n\x1a\n garbage", "ring.csv": RING},
    ),
    Bad(
        "measure-overflowing-coordinate",
        "data",
        ["measure", "{tmp}/big.csv", "--radius", "7.5 mm"],
        ["big.csv", "non-finite"],
        {"big.csv": CSV_HEADER + "1e400,0\n0,7.5\n-7.5,0\n"},
    ),
    Bad(
        "compare-measured-nan",
        "data",
        ["compare", "{tmp}/result.nc", "{tmp}/nan.csv"],
        ["nan.csv", "non-finite"],
        {"result.nc": "@result", "nan.csv": CSV_HEADER + "7.5,nan\n0,7.5\n-7.5,0\n"},
    ),
]


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_data(case: Bad, tmp_path, capsys, result_bytes):
    check_contract(case, tmp_path, capsys, result_bytes)


# ---------------------------------------------------------------- rings far from the origin


def _ring(center: float, radius: float = 7.5e-3, scar: float = 0.0, points: int = 720):
    theta = np.linspace(0, 2 * np.pi, points, endpoint=False)
    # a scar of depth ``scar`` around theta = 90 deg, 60 deg wide
    depth = scar * np.clip(1 - np.abs(theta - np.pi / 2) / np.radians(30), 0, None)
    r = radius + depth
    return center + r * np.cos(theta), center + r * np.sin(theta)


@pytest.mark.parametrize("center", [0.0, 1e4, 1e6 * 1e-3])
@pytest.mark.parametrize("fit", [fit_circle_least_squares, fit_circle_robust])
def test_unworn_ring_far_from_the_origin_has_no_scar(center, fit):
    """An unworn ring centred 10 km (or 1e6 mm) from the origin shows no wear at all."""
    x, y = _ring(center)
    result = fit(x, y) if fit is fit_circle_least_squares else fit(x, y, 7.5e-3)
    assert result.center_x == pytest.approx(center, abs=1e-9)
    depth = measured_wear_profile(x, y, result, 7.5e-3, 360)
    metrics = wear_metrics(depth, 7.5e-3, 0.01)
    assert metrics.peak_depth == 0.0
    assert metrics.width_deg == 0.0


@pytest.mark.parametrize("center", [0.0, 1e4])
def test_worn_ring_far_from_the_origin_keeps_its_scar(center):
    """A 20 um scar is measured the same at the origin and 10 km from it."""
    x, y = _ring(center, scar=20e-6)
    fit = fit_circle_robust(x, y, 7.5e-3)
    depth = measured_wear_profile(x, y, fit, 7.5e-3, 360)
    metrics = wear_metrics(depth, 7.5e-3, 0.01)
    assert metrics.peak_depth == pytest.approx(20e-6, rel=1e-3)
    assert metrics.peak_angle_deg == pytest.approx(90.0, abs=1.0)


def test_resolution_follows_the_coordinates():
    """The round-off floor is a few ulps of the largest coordinate: ~1e-11 m at 10 km."""
    assert coordinate_resolution([7.5e-3], [0.0]) < 1e-17
    assert 1e-12 < coordinate_resolution([1e4], [1e4]) < 1e-10


def test_far_ring_through_the_cli(tmp_path, capsys):
    """`measure` on a ring written in mm 1e6 mm from the origin reports zero wear."""
    x, y = _ring(1e3)
    path = tmp_path / "far.csv"
    np.savetxt(
        path,
        np.c_[x * 1e3, y * 1e3],
        delimiter=",",
        header="x [mm],y [mm]",
        comments="",
        fmt="%.17g",
    )
    code, out, err = run_cli(capsys, ["measure", str(path), "--radius", "7.5 mm", "--json"])
    assert code == 0, err
    import json

    fits = json.loads(out)["fits"]
    for name in ("least_squares", "robust"):
        assert fits[name]["peak_wear_depth_m"] == 0.0
        assert fits[name]["wear_width_deg"] == 0.0
