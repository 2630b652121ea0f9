"""Fuzzing the configuration space: no crash but the documented errors, no NaN in any metric.

Hypothesis draws whole configurations (lengths, masses, speeds, clearances,
moduli, exponents, contact models, meshes, revolutions, contour update on/off)
with values as SI numbers or strings with units. A configuration may be
rejected (:class:`~jointwear.errors.ConfigError`) or a run may fail with
another documented :class:`~jointwear.errors.JointwearError` subclass (wear
through the wall, no convergence, a mechanism that cannot run ...); anything
else is a bug. Successful runs must give finite metrics.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from jointwear import Simulation, load_config
from jointwear.errors import (
    ConfigError,
    ContactError,
    ContactLossWarning,
    ConvergenceError,
    DataError,
    GeometryError,
    JointwearError,
    MechanismError,
    WearThroughError,
)

DOCUMENTED = (
    ConfigError,
    ContactError,
    ConvergenceError,
    DataError,
    GeometryError,
    MechanismError,
    WearThroughError,
)
MODELS = ["hertz", "winkler", "asymmetric-winkler", "nlcp"]
METRICS = (
    "peak_wear_depth_m",
    "wear_width_deg",
    "wear_mass_kg",
    "wear_volume_m3",
    "min_wall_thickness_m",
    "runtime_s",
)


def quantity(low: float, high: float, unit: str, scale: float, log: bool = False):
    """An SI float in [low, high] given either as a number or as a string in ``unit``."""
    if log:
        values = st.floats(math.log10(low), math.log10(high)).map(lambda e: 10.0**e)
    else:
        values = st.floats(low, high, allow_nan=False, allow_infinity=False)
    return st.one_of(values, values.map(lambda v: f"{v / scale!r} {unit}"))


configs = st.fixed_dictionaries(
    {
        "mechanism.crank_length": quantity(0.01, 0.2, "mm", 1e-3),
        "mechanism.rod_length": quantity(0.05, 0.5, "mm", 1e-3),
        "mechanism.crank_mass": quantity(0.0, 5.0, "kg", 1.0),
        "mechanism.rod_mass": quantity(0.0, 5.0, "kg", 1.0),
        "mechanism.slider_mass": quantity(0.0, 20.0, "kg", 1.0),
        "mechanism.spring_stiffness": quantity(0.0, 1e4, "N/m", 1.0),
        "mechanism.spring_preload": quantity(0.0, 200.0, "N", 1.0),
        "mechanism.spring_mode": st.sampled_from(["pull", "push"]),
        "mechanism.crank_speed": quantity(1.0, 600.0, "rpm", 2 * math.pi / 60),
        "joint.pin_radius": quantity(2e-3, 20e-3, "mm", 1e-3),
        "joint.clearance": quantity(5e-6, 5e-4, "mm", 1e-3, log=True),
        "joint.axial_length": quantity(5e-3, 50e-3, "mm", 1e-3),
        "joint.bushing_thickness": quantity(0.5e-3, 5e-3, "mm", 1e-3),
        "materials.pin.youngs_modulus": quantity(1e10, 3e11, "GPa", 1e9, log=True),
        "materials.bushing.youngs_modulus": quantity(1e8, 1e10, "MPa", 1e6, log=True),
        "materials.pin.poisson_ratio": st.floats(0.0, 0.49),
        "materials.bushing.poisson_ratio": st.floats(0.0, 0.49),
        "materials.bushing.density": quantity(500.0, 9000.0, "kg/m^3", 1.0),
        "materials.bushing.wear_coefficient": quantity(1e-16, 1e-6, "m^2/N", 1.0, log=True),
        "contact.model": st.sampled_from(MODELS),
        "contact.exponent": st.floats(0.8, 2.5),
        "contact.nodes": st.integers(32, 180),
        "contact.foundation_modulus": st.sampled_from(["youngs", "constrained"]),
        "contact.balance": st.sampled_from(["paper", "equilibrium"]),
        "contact.nlcp_variant": st.sampled_from(["paper", "mesh-independent"]),
        "simulation.sliding": st.sampled_from(["relative-rotation", "contact-azimuth"]),
        "simulation.steps_per_revolution": st.integers(32, 180),
        "simulation.revolutions": st.integers(1, 5),
        "simulation.update_contour": st.booleans(),
        "simulation.update_every": st.sampled_from([1, 2, "adaptive"]),
    }
)


@settings(
    max_examples=60,
    deadline=None,
    derandomize=True,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(overrides=configs)
def test_any_configuration_runs_or_fails_cleanly(overrides):
    try:
        config = load_config(overrides=overrides)
    except ConfigError as exc:
        event("rejected config")
        message = str(exc)
    else:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ContactLossWarning)
            try:
                result = Simulation(config).run()
                message = None
            except DOCUMENTED as exc:
                event(f"run failed: {type(exc).__name__}")
                message = str(exc)
            except JointwearError as exc:  # pragma: no cover - an undocumented subclass
                pytest.fail(f"undocumented error type {type(exc).__name__}: {exc}")
    if message is not None:
        assert "\n" not in message
        assert ": " in message  # "key or file: reason"
        return
    event(f"ran: {config.contact.model}, update={config.simulation.update_contour}")
    summary = result.summary()
    for key in METRICS:
        assert math.isfinite(summary[key]), (key, summary[key])
    assert summary["peak_wear_depth_m"] >= 0
    assert summary["wear_mass_kg"] >= 0
    assert 0 <= summary["wear_width_deg"] <= 360
    if summary["stopped_by"] is None:
        assert summary["revolutions"] == config.simulation.revolutions
    else:  # a [life] limit (e.g. worn through the wall) ends the run early, and says which
        assert 0 < summary["revolutions"] <= config.simulation.revolutions
        assert summary["life_revolutions"] == summary["revolutions"]
    assert summary["min_wall_thickness_m"] >= 0  # a limit ends the run at the wall at most
    assert np.isfinite(result.wear_depth).all()


@settings(max_examples=40, deadline=None, derandomize=True)
@given(
    key=st.sampled_from(
        [
            "joint.clearance",
            "joint.pin_radius",
            "mechanism.crank_speed",
            "materials.bushing.youngs_modulus",
            "contact.exponent",
            "mechanism.slider_mass",
            "contact.nodes",
        ]
    ),
    value=st.one_of(
        st.floats(allow_nan=True, allow_infinity=True),
        st.integers(-(10**12), 10**12),
        st.text(max_size=12),
        st.booleans(),
        st.sampled_from(["5 kg", "nan mm", "-1 mm", "inf rpm", "1e999 m", "", " ", "mm"]),
    ),
)
def test_any_single_value_is_accepted_or_rejected_with_its_key(key, value):
    try:
        load_config(overrides={key: value})
    except ConfigError as exc:
        message = str(exc)
        assert message.startswith(key) or message.startswith(key.split(".")[0]), message
        assert "\n" not in message
