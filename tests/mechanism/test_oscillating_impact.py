"""The oscillating bearing with its loaded pin free in the clearance (contact-impact).

Without friction the free pin sits on the load line with the load: the prescribed
cycle. With Coulomb friction the steadily sliding pin climbs the wall until the
contact force (normal plus friction) balances the load: the normal turns by
``atan(mu)`` against the sliding (the friction circle) and carries
``F / sqrt(1 + mu^2)``; at the stroke's reversal it turns to the other side.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.config import config_from_dict
from jointwear.mechanism.stage import load_cycles

BASE = {
    "mechanism": {
        "type": "oscillating",
        "load": "100 N",
        "load_angle": "-90 deg",
        "amplitude": "25 deg",
        "frequency": "1 Hz",
        "pin_mass": "1 kg",
    },
    "contact": {"model": "asymmetric-winkler", "nodes": 120},
    "simulation": {"steps_per_revolution": 40},
    "dynamics": {
        "model": "contact-impact",
        "revolutions_settle": 1,
        "friction_velocity_tolerance": "1e-3 m/s",
    },
}


def cycle(friction: float, model: str = "contact-impact"):
    data = {**BASE, "dynamics": {**BASE["dynamics"], "model": model}}
    data["dynamics"]["friction_coefficient"] = friction
    return load_cycles(config_from_dict(data))["bearing"]


def test_frictionless_free_pin_carries_the_prescribed_load() -> None:
    free, prescribed = cycle(0.0), cycle(0.0, "massless-link")
    assert free.model == "contact-impact"
    assert prescribed.model == "prescribed"
    assert free.extras["impacts"] == 0
    np.testing.assert_allclose(free.load, prescribed.load, rtol=1e-6)
    np.testing.assert_allclose(free.azimuth, prescribed.azimuth, atol=1e-6)
    np.testing.assert_array_equal(free.relative_rotation, prescribed.relative_rotation)


def test_friction_turns_the_contact_by_the_friction_angle() -> None:
    """Sliding, the contact turns by ``atan(mu)`` against the sliding, each stroke to its
    side; the pin swings about that balance along the wall (nothing damps its tangential
    motion, docs/dynamics.md), so the balance is checked on the stroke's mean."""
    mu = 0.2
    free = cycle(mu)
    steps = free.load.size
    phase = 2.0 * np.pi * np.arange(steps) / steps
    sliding = np.abs(np.cos(phase)) > 0.5  # |slip| > 10 v0 there
    forward, backward = sliding & (np.cos(phase) > 0), sliding & (np.cos(phase) < 0)
    tilt = free.azimuth - math.radians(-90.0)
    for stroke in (forward, backward):
        assert abs(tilt[stroke].mean()) == pytest.approx(math.atan(mu), rel=0.25)
        assert free.load[stroke].mean() == pytest.approx(100.0 / math.sqrt(1 + mu * mu), rel=0.01)
    assert tilt[forward].mean() * tilt[backward].mean() < 0
