"""Sliding distance: the one formula, its radius, and the slip of rigid pin kinematics."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.tribology import sliding

#: the paper's joint: pin radius and radial clearance [m]
PIN_RADIUS, CLEARANCE = 7.45e-3, 0.05e-3
BUSHING_RADIUS = PIN_RADIUS + CLEARANCE


def test_relative_rotation_sliding() -> None:
    np.testing.assert_allclose(sliding.relative_rotation([0.1, -0.2], 7.5e-3), [7.5e-4, 1.5e-3])


def test_contact_azimuth_sliding_is_periodic_and_wrapped() -> None:
    # the azimuth sweeps across the +-pi cut: increments must be wrapped, not 2 pi jumps
    psi = np.array([3.1, -3.1, -3.0, 3.1])
    ds = sliding.contact_azimuth(psi, 1.0)
    expected = np.abs(np.angle(np.exp(1j * (np.roll(psi, -1) - psi))))
    np.testing.assert_allclose(ds, expected, rtol=1e-12)
    assert ds.max() < 1.0


def test_both_readings_and_the_speed_are_the_one_distance() -> None:
    """Relative rotation, contact azimuth and the checks' speed are R_b |angle| [/ dt]."""
    rng = np.random.default_rng(3)
    rotation = rng.normal(size=40) * 0.05
    duration = rng.uniform(1e-4, 1e-3, 40)
    distance = sliding.sliding_distance(rotation, BUSHING_RADIUS)
    np.testing.assert_array_equal(sliding.relative_rotation(rotation, BUSHING_RADIUS), distance)
    psi = np.cumsum(rotation) - rotation[0]
    turned = sliding.contact_azimuth(psi, BUSHING_RADIUS)
    # the azimuth's increments are the rotations, the last one closing the cycle
    np.testing.assert_allclose(turned[:-1], distance[1:], rtol=1e-9)
    np.testing.assert_array_equal(
        sliding.sliding_speed(rotation, duration, BUSHING_RADIUS), distance / duration
    )
    assert sliding.SLIDING_MODELS.get("relative-rotation") is not None


def slip_of_the_pin(phi: np.ndarray, psi: np.ndarray, eccentricity: float) -> np.ndarray:
    """Slip along the bushing of the pin's material at the contact, step by step [m].

    Rigid kinematics in the bushing's frame: the pin turns by ``phi`` about its centre,
    which sits ``eccentricity`` from the bushing centre towards the load azimuth ``psi``;
    the contact is on the load line. The material at the contact at step k (pin angle
    ``psi_k - phi_k``) moves along the bushing's tangent there by the step's slip.
    """
    material = psi[:-1] - phi[:-1]

    def position(centre_angle, turned):
        return eccentricity * np.stack(
            [np.cos(centre_angle), np.sin(centre_angle)]
        ) + PIN_RADIUS * np.stack([np.cos(material + turned), np.sin(material + turned)])

    move = position(psi[1:], phi[1:]) - position(psi[:-1], phi[:-1])
    tangent = np.stack([-np.sin(psi[:-1]), np.cos(psi[:-1])])
    return np.abs(np.sum(move * tangent, axis=0))


@pytest.mark.parametrize(
    ("load", "radius"),
    [("turns with the pin", BUSHING_RADIUS), ("fixed in the bushing", PIN_RADIUS)],
)
def test_the_slip_at_the_contact_is_r_b_for_a_load_turning_with_the_pin(load, radius) -> None:
    """The sliding radius R_b is the slip of a load that turns with the pin (a two-force
    link carrying the pin, the paper's joint); a load fixed in the bushing slides on the
    pin's radius, c / R_b = 0.67 % less (the module notes)."""
    phi = np.linspace(0.0, 0.6, 60001)  # steps of 1e-5 rad: the slip to ~1e-5
    psi = phi + 0.3 if load == "turns with the pin" else np.full(phi.size, 0.3)
    slip = slip_of_the_pin(phi, psi, CLEARANCE).sum()
    distance = sliding.sliding_distance(np.diff(phi), BUSHING_RADIUS).sum()
    assert slip == pytest.approx(radius * 0.6, rel=1e-4)
    assert slip / distance == pytest.approx(radius / BUSHING_RADIUS, rel=1e-4)
    if load == "fixed in the bushing":
        assert 1 - slip / distance == pytest.approx(CLEARANCE / BUSHING_RADIUS, rel=2e-2)
