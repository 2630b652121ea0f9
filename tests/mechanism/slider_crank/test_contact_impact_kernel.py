"""The slider-crank's compiled contact-impact right-hand side against its Python reference.

The compiled functions (numba) mirror the reference expression by expression, so on
any state -- pin pressed into the wall or flying free, with friction, on a worn
bushing, either spring, either body carrying the bushing -- accelerations, contact
force, crank torque and gap agree to 1e-12 relative (in fact to the bit: the
integrator then takes the same steps with either).
"""

from __future__ import annotations

import math
import os

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.geometry import BushingContour
from jointwear.mechanism.slider_crank.contact_impact import impact_kernel

from ..joints import slider_crank_system

pytestmark = pytest.mark.skipif(
    impact_kernel() is None, reason="numba missing or JOINTWEAR_NO_NUMBA set"
)

VARIANTS = {
    "paper": {},
    "friction": {"dynamics.friction_coefficient": 0.2, "dynamics.restitution": 0.5},
    "push-spring": {"mechanism.spring_mode": "push", "mechanism.crank_speed": "240 rpm"},
    "bushing-in-rod": {"mechanism.bushing_body": "rod", "dynamics.force_law": "flores"},
    "hunt-crossley": {"dynamics.force_law": "hunt-crossley", "dynamics.restitution": 0.3},
}


def systems(config: Config, contour: BushingContour | None = None):
    """The compiled system and the Python one of ``config``."""
    return (
        slider_crank_system(config, contour, compiled=True),
        slider_crank_system(config, contour, compiled=False),
    )


def random_states(system, count: int, seed: int):
    """Times, states and approach velocities with the pin offset up to twice the clearance.

    The offset ``e`` is drawn in a disc of radius ``2 c`` and the rod angle and slider
    position follow from the loop closure at the drawn crank angle, so the pin is in
    contact for some samples and flies free for others.
    """
    rng = np.random.default_rng(seed)
    m, c = system.mechanism, system.contact.clearance
    times = rng.uniform(0.0, 2 * math.pi / system.omega, size=count)
    radius = 2 * c * np.sqrt(rng.uniform(size=count))
    angle = rng.uniform(0, 2 * np.pi, size=count)
    ex, ey = radius * np.cos(angle), radius * np.sin(angle)
    phi = system.omega * times
    theta = np.arcsin((ey - m.crank_length * np.sin(phi)) / m.rod_length)
    x3 = m.crank_length * np.cos(phi) + m.rod_length * np.cos(theta) - ex
    rates = rng.normal(size=(count, 3)) * [20.0, 2.0, 1.0]
    states = np.column_stack([theta, x3, rates])
    velocities = 10.0 ** rng.uniform(-5, 0, size=count)
    return times, states, velocities


def assert_relative(a, b, rtol=1e-12):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = np.maximum(np.abs(b), 1e-300)
    assert np.all(np.abs(a - b) <= rtol * scale), np.max(np.abs(a - b) / scale)


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_compiled_rhs_equals_python(paper_config: Config, variant: str) -> None:
    config = paper_config.replace({"dynamics.model": "contact-impact", **VARIANTS[variant]})
    fast, reference = systems(config)
    assert fast.compiled
    assert not reference.compiled
    times, states, velocities = random_states(reference, 400, seed=len(variant))
    contact = free = 0
    for t, y, v in zip(times, states, velocities, strict=True):
        assert_relative(fast.rhs(t, y, v), reference.rhs(t, y, v))
        a, b = fast.evaluate(t, y, v), reference.evaluate(t, y, v)
        assert a.keys() == b.keys()
        assert_relative([a[k] for k in a], [b[k] for k in a])
        assert_relative(
            [fast.gap(t, y), fast.gap_rate(t, y), *fast.gap_and_rate(t, y)],
            [reference.gap(t, y), reference.gap_rate(t, y), *reference.gap_and_rate(t, y)],
        )
        contact += b["normal_force"] > 0
        free += b["penetration"] < 0
    assert contact > 50
    assert free > 50


def test_compiled_rhs_on_a_worn_bushing(paper_config: Config) -> None:
    """A point law on a worn bushing: the clearance grows by the interpolated wear."""
    config = paper_config.replace(
        {"dynamics.model": "contact-impact", "dynamics.friction_coefficient": 0.1}
    )
    nodes = config.contact.nodes
    theta = 2 * np.pi * np.arange(nodes) / nodes
    wear = 2e-5 * np.exp(-(((theta - 2.5 + np.pi) % (2 * np.pi) - np.pi) ** 2) / 0.3)
    contour = BushingContour.from_wear_profile(
        config.joint.bushing_radius, wear, config.joint.axial_length
    )
    fast, reference = systems(config, contour)
    times, states, velocities = random_states(reference, 400, seed=7)
    for t, y, v in zip(times, states, velocities, strict=True):
        assert_relative(fast.rhs(t, y, v), reference.rhs(t, y, v))
        assert_relative(fast.gap(t, y), reference.gap(t, y))


def test_compiled_clearance_is_pythons(paper_config: Config) -> None:
    """The worn clearance in every direction, the axes and the branch cut included, gives
    the reference's bits (the kernel adds 2 pi to a negative angle instead of ``%``)."""
    config = paper_config.replace({"dynamics.model": "contact-impact"})
    nodes = config.contact.nodes
    wear = 1e-5 * (1.0 + np.sin(3.0 * 2 * np.pi * np.arange(nodes) / nodes))
    contour = BushingContour.from_wear_profile(
        config.joint.bushing_radius, wear, config.joint.axial_length
    )
    fast, reference = systems(config, contour)
    kernel, clearance = impact_kernel(), reference.contact.clearance
    profile = reference.contact.wear_profile
    rng = np.random.default_rng(11)
    angles = [*rng.uniform(-np.pi, np.pi, 4000), *np.arange(-4, 5) * np.pi / 2]
    offsets = [(math.cos(a), math.sin(a)) for a in angles]
    offsets += [(1.0, 0.0), (1.0, -0.0), (-1.0, 0.0), (-1.0, -0.0), (1.0, -1e-300), (-1.0, -1e-300)]
    for ex, ey in offsets:
        expected = reference.contact.clearance_at(ex, ey)
        assert kernel.clearance_at(ex, ey, clearance, profile) == expected, (ex, ey)
    assert fast.compiled


def test_compiled_hypot_is_pythons() -> None:
    """The kernel's hypot gives CPython's ``math.hypot`` bits, over 40 decades."""
    kernel = impact_kernel()
    rng = np.random.default_rng(3)
    x = rng.normal(size=20000) * 10.0 ** rng.uniform(-20, 20, size=20000)
    y = x * 10.0 ** rng.uniform(-8, 8, size=20000) * rng.choice([-1, 1], size=20000)
    for a, b in zip(x, y, strict=True):
        assert kernel.hypot(a, b) == math.hypot(a, b)
    assert kernel.hypot(0.0, -0.0) == 0.0
    assert kernel.hypot(-math.inf, math.nan) == math.inf
    assert math.isnan(kernel.hypot(1.0, math.nan))


def test_switch_and_distributed_laws_use_python(paper_config: Config) -> None:
    """JOINTWEAR_NO_NUMBA=1 and the distributed laws keep the Python right-hand side."""
    config = paper_config.replace({"dynamics.model": "contact-impact"})
    os.environ["JOINTWEAR_NO_NUMBA"] = "1"
    try:
        assert impact_kernel() is None
        with pytest.raises(Exception, match="numba"):
            systems(config)
    finally:
        del os.environ["JOINTWEAR_NO_NUMBA"]
    system = slider_crank_system(config.replace({"dynamics.force_law": "nlcp"}))
    assert not system.compiled
