"""The oscillating bearing: kinematics, load frames and Archard's global form."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import config_from_dict
from jointwear.contact import winkler
from jointwear.errors import ConfigError
from jointwear.mechanism.stage import load_cycle

BASE = {
    "mechanism": {
        "type": "oscillating",
        "load": "1.5 kN",
        "amplitude": "25 deg",
        "frequency": "0.5 Hz",
    },
    "contact": {"model": "winkler"},
}


def oscillating(**mechanism) -> dict:
    return {**BASE, "mechanism": {**BASE["mechanism"], **mechanism}}


def test_one_cycle_slides_four_amplitudes() -> None:
    cycle = load_cycle(config_from_dict(BASE))
    assert cycle.period == pytest.approx(2.0)
    assert cycle.total_relative_rotation == pytest.approx(4 * math.radians(25), rel=1e-12)
    # the pin swings back to where it started
    assert cycle.rotation[-1] == pytest.approx(0.0, abs=1e-15)
    assert cycle.rotation.max() == pytest.approx(math.radians(25), rel=1e-12, abs=0)
    np.testing.assert_allclose(cycle.load, 1500.0)


def test_load_in_the_pin_frame_turns_with_the_pin() -> None:
    fixed = load_cycle(config_from_dict(oscillating(load_angle="90 deg")))
    turning = load_cycle(config_from_dict(oscillating(load_angle="90 deg", load_frame="pin")))
    np.testing.assert_allclose(fixed.azimuth, math.pi / 2)
    np.testing.assert_allclose(turning.azimuth - fixed.azimuth, turning.rotation[:-1], atol=1e-15)


def test_load_variation_over_the_cycle() -> None:
    cycle = load_cycle(config_from_dict(oscillating(load_amplitude="500 N", load_harmonic=2)))
    assert cycle.load.max() == pytest.approx(2000.0)
    assert cycle.load.min() == pytest.approx(1000.0)
    assert cycle.mean_load == pytest.approx(1500.0, rel=1e-12)
    with pytest.raises(ConfigError, match=r"^mechanism.load_amplitude: .*reverse"):
        config_from_dict(oscillating(load_amplitude="2 kN"))


def test_fixed_load_wears_archards_global_form() -> None:
    """V = K_d kappa F R_b 4 A: the whole cycle presses the same arc with the same springs."""
    config = config_from_dict(BASE)
    simulation = Simulation(config)
    solution = simulation.contact(simulation.initial_contour())
    contour = simulation.initial_contour()
    spring_forces = solution.pressure @ contour.spring_area
    kappa = spring_forces[0] / 1500.0
    np.testing.assert_allclose(spring_forces, spring_forces[0], rtol=1e-12)
    # the spread factor of the discrete contact is the closed form's (small clearance)
    alpha = 0.5 * (solution.half_angle_left[0] + solution.half_angle_right[0])
    assert kappa == pytest.approx(float(winkler.spread_factor(alpha)), rel=2e-3)
    result = simulation.run()
    volume = result.summary()["wear_volume_m3"]
    k_d = config.materials.bushing.wear_coefficient
    sliding = config.joint.bushing_radius * 4 * math.radians(25)
    # Archard's form is the first-order term of the worn area 1/2 sum h (2 R_b + h) dtheta;
    # the reported volume keeps the h^2/2 term too (h / 2 R_b ~ 3e-6 here)
    depth = np.asarray(result.wear_depth)
    second_order = config.joint.axial_length * 0.5 * (depth**2).sum() * 2 * np.pi / depth.size
    expected = k_d * kappa * 1500.0 * sliding + second_order
    assert volume == pytest.approx(expected, rel=1e-9, abs=0)


def test_symmetric_swing_wears_symmetrically_about_the_load() -> None:
    config = config_from_dict(
        {
            **oscillating(load_angle="-90 deg"),
            # (the springs on the worn contour: winkler's circle cannot follow it)
            "contact": {"model": "asymmetric-winkler"},
            "simulation": {"revolutions": 2000, "update_contour": True, "update_every": 100},
        }
    )
    depth = Simulation(config).run().wear_depth
    nodes = depth.size
    bottom = nodes * 3 // 4  # the node at -90 deg
    mirrored = np.roll(depth[::-1], 2 * bottom + 1 - nodes)
    assert np.argmax(depth) == bottom
    np.testing.assert_allclose(depth, mirrored, rtol=0, atol=1e-9 * depth.max())


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"amplitude": 0}, r"^mechanism.amplitude: "),
        ({"frequency": "3 m"}, r"^mechanism.frequency: .*frequency"),
        ({"load": "-1 N"}, r"^mechanism.load: "),
        ({"load_frame": "crank"}, r"^mechanism.load_frame: 'crank' is not allowed"),
        ({"crank_length": 0.1}, r"^mechanism.crank_length: unknown key"),
    ],
)
def test_bad_oscillating_keys(change: dict, message: str) -> None:
    with pytest.raises(ConfigError, match=message):
        config_from_dict(oscillating(**change))
