"""Wear on both surfaces: the pin wears in its own frame and widens the gap."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config, config_from_dict
from jointwear.tribology import archard, metrics
from jointwear.tribology.pin_wear import pin_on_bushing, pin_wear_depth

K_PIN = 2e-14


@pytest.fixture(scope="module")
def small(paper_config: Config) -> Config:
    return paper_config.replace(
        {"contact.nodes": 120, "simulation.steps_per_revolution": 60, "contact.model": "winkler"}
    )


def test_worn_volumes_are_archards_global_form_with_both_coefficients(small: Config) -> None:
    config = small.replace({"materials.pin.wear_coefficient": K_PIN})
    simulation = Simulation(config)
    contour = simulation.initial_contour()
    solution = simulation.contact(contour)
    normal = solution.pressure @ contour.spring_area
    ds = simulation.sliding_distance
    summary = simulation.run().summary()
    k_bushing = config.materials.bushing.wear_coefficient
    assert summary["wear_volume_m3"] == pytest.approx(
        archard.archard_volume(normal, ds, k_bushing), rel=1e-6, abs=0
    )
    assert summary["pin_wear_volume_m3"] == pytest.approx(
        archard.archard_volume(normal, ds, K_PIN), rel=1e-6, abs=0
    )
    total = summary["wear_volume_m3"] + summary["pin_wear_volume_m3"]
    assert total == pytest.approx(
        archard.archard_volume(normal, ds, k_bushing + K_PIN), rel=1e-6, abs=0
    )


def test_a_pin_that_does_not_turn_wears_one_spot_and_the_mapping_round_trips() -> None:
    nodes = 72
    pressure = np.zeros((3, nodes))
    pressure[:, 10] = 1e6
    fixed = pin_wear_depth(pressure, [1e-3] * 3, 1e-12, np.full(nodes, 7.5e-3), 7.5e-3, [0, 0, 0])
    assert np.flatnonzero(fixed).tolist() == [10]
    # a pin turned by 3 nodes at every step has worn 3 nodes further back in its frame
    turn = 3 * 2 * np.pi / nodes
    turned = pin_wear_depth(pressure, [1e-3] * 3, 1e-12, np.full(nodes, 7.5e-3), 7.5e-3, [turn] * 3)
    np.testing.assert_allclose(turned, np.roll(fixed, -3), atol=1e-30)
    # seen from the bushing at that rotation, the scar faces node 10 again
    np.testing.assert_allclose(pin_on_bushing(turned, [turn])[0], fixed, atol=1e-30)
    # half a node: the scar splits evenly, and the total is kept
    half = pin_wear_depth(
        pressure, [1e-3] * 3, 1e-12, np.full(nodes, 7.5e-3), 7.5e-3, [np.pi / nodes] * 3
    )
    assert half.sum() == pytest.approx(fixed.sum(), rel=1e-14, abs=0)
    assert half[9] == pytest.approx(half[10], rel=1e-6, abs=0)


def test_a_swinging_pin_spreads_its_wear_over_the_swing() -> None:
    """Oscillating bearing, load fixed in the bushing, equal wear coefficients: the same
    volume comes off both, but the pin's scar is wider by up to the swing, so shallower."""
    config = config_from_dict(
        {
            "mechanism": {
                "type": "oscillating",
                "load": "1.5 kN",
                "amplitude": "25 deg",
                "frequency": "0.25 Hz",
                "load_angle": "-90 deg",
            },
            "contact": {"model": "asymmetric-winkler", "nodes": 180},
            "simulation": {
                "steps_per_revolution": 90,
                "revolutions": 2000,
                "update_contour": True,
                "update_every": 100,
            },
            "materials": {"pin": {"wear_coefficient": 5.05e-13}},
        }
    )
    result = Simulation(config).run()
    s = result.summary()
    pin_width = np.degrees(metrics.wear_width(result.dataset["pin_wear_depth"].values))
    assert s["wear_width_deg"] < pin_width < s["wear_width_deg"] + 50.0
    assert s["pin_peak_wear_depth_m"] < s["peak_wear_depth_m"]
    # equal coefficients, equal normal force and slip: equal volumes, to second order in h/R
    assert s["pin_wear_volume_m3"] == pytest.approx(s["wear_volume_m3"], rel=0.015)


@pytest.mark.parametrize(("model", "update"), [("asymmetric-winkler", True), ("winkler", False)])
def test_a_pin_on_slices_wears_archards_global_form_over_all_slices(
    small: Config, model: str, update: bool
) -> None:
    # a misaligned pin on 5 slices, one revolution: the volume off the pin, summed over
    # its slices (each of width L / 5), is K_p sum_k N_k ds_k with N_k the normal force
    # of all slices' nodes (the compiled balance in the loop; solve_axial, the symmetric
    # law, in a run without contour update)
    count = 5
    config = small.replace(
        {
            "contact.model": model,
            "joint.axial_slices": count,
            "joint.misalignment": "0.02 deg",
            "materials.pin.wear_coefficient": K_PIN,
            "simulation.revolutions": 1,
            "simulation.update_contour": update,
        }
    )
    simulation = Simulation(config)
    contour = simulation.initial_contour()
    solution = simulation.contact(contour)
    width = config.joint.axial_length / count
    area = contour.radius * contour.dtheta * width  # (slices, nodes) [m^2]
    normal = np.einsum("skj,sj->k", solution.slice_pressure, area)
    expected = archard.archard_volume(normal, simulation.sliding_distance, K_PIN)
    result = simulation.run()
    pin = result.dataset["pin_wear_depth"].values
    assert pin.shape == (count, config.contact.nodes)
    pin_radius = config.joint.pin_radius
    assert float(np.sum(pin) * pin_radius * contour.dtheta * width) == pytest.approx(
        expected, rel=1e-12, abs=0
    )
    # (the summary's volume takes the removed area to second order in h / R_p)
    assert result.summary()["pin_wear_volume_m3"] == pytest.approx(expected, rel=1e-6, abs=0)
    assert result.summary()["pin_peak_wear_depth_m"] == pin.max()
    # the slices differ (the tilt), so the sum is not one slice's times five
    peaks = pin.max(axis=1)
    assert peaks.max() > 1.1 * peaks.min()


def test_the_slices_are_a_leading_axis_of_the_pin_wear_functions() -> None:
    rng = np.random.default_rng(7)
    slices, steps, nodes = 3, 20, 36
    pressure = rng.random((slices, steps, nodes)) * 1e6
    radius = 7.5e-3 + rng.random((slices, nodes)) * 1e-5
    sliding, rotation = rng.random(steps) * 1e-3, np.cumsum(rng.random(steps))
    depth = pin_wear_depth(pressure, sliding, K_PIN, radius, 7.45e-3, rotation)
    facing = pin_on_bushing(depth, rotation)
    assert depth.shape == (slices, nodes)
    assert facing.shape == (slices, steps, nodes)
    for s in range(slices):
        one = pin_wear_depth(pressure[s], sliding, K_PIN, radius[s], 7.45e-3, rotation)
        np.testing.assert_array_equal(depth[s], one)
        np.testing.assert_array_equal(facing[s], pin_on_bushing(one, rotation))
