"""Engineering checks of a run against the bushing's datasheet limits (nominal p, v, PV)."""

from __future__ import annotations

import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from jointwear import Simulation, load_config
from jointwear.errors import MaterialLimitWarning
from jointwear.tribology.metrics import compare_with_limits, engineering_checks, operating_values

R_P, B = 7.45e-3, 20e-3


def test_constant_load_constant_speed_oscillation_is_the_datasheet_pv():
    # a triangular swing: the pin turns at constant speed w, back and forth
    steps, period, load, amplitude = 40, 2.0, 300.0, 0.4
    w = 4 * amplitude / period
    rotation = np.where(np.arange(steps) < steps // 2, 1.0, -1.0) * 2 * amplitude / (steps / 2)
    values = operating_values(
        np.full(steps, load), rotation, np.full(steps, period / steps), R_P, B
    )
    p, v = load / (2 * R_P * B), R_P * w
    assert values["nominal_pressure"] == pytest.approx(p, rel=1e-12)
    assert values["sliding_speed"] == pytest.approx(v, rel=1e-12)
    assert values["pv"] == pytest.approx(p * v, rel=1e-12)
    assert values["pv_max"] == pytest.approx(p * v, rel=1e-12)
    assert math.isnan(values["peak_pressure"])


def test_unequal_steps_weigh_pv_by_time():
    # half the period at rest under load F, half sliding at v under 2F: mean PV = (2F) v / 2 / A
    load = np.array([100.0, 200.0])
    values = operating_values(load, [0.0, 0.5], [1.0, 1.0], R_P, B)
    area = 2 * R_P * B
    assert values["pv"] == pytest.approx(0.5 * (200.0 / area) * R_P * 0.5, rel=1e-12)
    assert values["pv_max"] == pytest.approx((200.0 / area) * R_P * 0.5, rel=1e-12)


@pytest.fixture(scope="module")
def oscillating():
    # sinusoidal swing A sin(2 pi f t) under a constant load F (steps a multiple of 4, so
    # the turning points are step boundaries and the sliding per cycle is exactly 4 A R_p)
    load, amplitude, frequency = 1500.0, math.radians(25), 0.25
    cfg = load_config(
        overrides={
            "mechanism.type": "oscillating",
            "mechanism.load": load,
            "mechanism.amplitude": amplitude,
            "mechanism.frequency": frequency,
            "contact.model": "winkler",
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 400,
            "materials.bushing": "ptfe-fabric",
        }
    )
    result = Simulation(cfg).run()
    return cfg, result, (load, amplitude, frequency)


def test_oscillating_bearing_pv_is_the_closed_form(oscillating):
    cfg, result, (load, amplitude, frequency) = oscillating
    checks = engineering_checks(result.joint_dataset(), cfg)
    b = cfg.joint.axial_length
    # mean PV = F / (2 R_p b) * 4 A f R_p = 2 F A f / b; largest = F / (2 R_p b) * 2 pi f A R_p
    assert checks["pv"]["value"] == pytest.approx(2 * load * amplitude * frequency / b, rel=1e-9)
    assert checks["pv_max"]["value"] == pytest.approx(
        math.pi * load * amplitude * frequency / b, rel=2e-4
    )
    assert checks["sliding_speed"]["value"] == pytest.approx(
        2 * math.pi * frequency * amplitude * cfg.joint.pin_radius, rel=2e-4
    )
    # the local peak carries the load on less than the projected area
    assert checks["peak_pressure"]["value"] >= checks["nominal_pressure"]["value"]
    assert checks["pv_peak_local"]["value"] >= checks["pv"]["value"]
    assert checks["pv"]["limit"] == pytest.approx(1.6e6)
    assert checks["pv"]["ok"] is True
    assert checks["pv_max"]["ok"] is None  # reported, not compared


def material(**limits):
    keys = ("max_static_pressure", "max_dynamic_pressure", "max_pv", "max_sliding_speed")
    return SimpleNamespace(**{k: limits.get(k) for k in keys})


VALUES = {
    "nominal_pressure": 1e6,
    "peak_pressure": 5e6,
    "sliding_speed": 0.1,
    "pv": 1e5,
    "pv_max": 2e5,
    "pv_peak_local": 5e5,
}


def test_warns_once_per_exceeded_limit():
    with pytest.warns(MaterialLimitWarning, match=r"materials\.bushing\.max_pv: .*PV") as record:
        checks = compare_with_limits(
            VALUES, material(max_pv=0.9e5, max_sliding_speed=1.0), "bronze"
        )
    assert len(record) == 1
    assert "'bronze'" in str(record[0].message)
    assert checks["pv"]["ok"] is False
    assert checks["sliding_speed"]["ok"] is True


def test_no_warning_within_the_limits_or_without_limits():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        within = compare_with_limits(VALUES, material(max_pv=1e5, max_static_pressure=5e6))
        unknown = compare_with_limits(VALUES, {})
    assert within["pv"]["ok"] is True  # the limit itself is allowed
    assert within["peak_pressure"]["ok"] is True
    assert all(entry["ok"] is None for entry in unknown.values())
    assert unknown["pv"]["limit"] is None
