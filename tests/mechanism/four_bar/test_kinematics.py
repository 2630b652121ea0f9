"""Closed-form kinematics of the four-bar: loop closure, assembly side, finite differences."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.mechanism.four_bar.kinematics import four_bar_motion, joint_positions
from tests.mechanism.four_bar.linkages import LINKAGES, RPM, linkage, motion_of, unit

# ------------------------------------------------------------------ kinematics


@pytest.mark.parametrize("lengths", LINKAGES)
@pytest.mark.parametrize("assembly", ["open", "crossed"])
def test_loop_closure(lengths, assembly: str) -> None:
    l0, l1, l2, l3 = lengths
    phi = np.linspace(0.0, 2 * np.pi, 1441)
    m = four_bar_motion(phi, l0, l1, l2, l3, 10.0, assembly)
    b = l1 * unit(phi)
    via_coupler = b + l2 * unit(m.coupler_angle)
    via_rocker = np.array([l0, 0.0]) + l3 * unit(m.rocker_angle)
    np.testing.assert_allclose(via_coupler, via_rocker, rtol=0, atol=1e-12)
    # continuous branch: no jumps, and periodic over the revolution
    for angle in (m.coupler_angle, m.rocker_angle):
        assert np.max(np.abs(np.diff(angle))) < 0.05
        assert angle[-1] == pytest.approx(angle[0], abs=1e-12)


@pytest.mark.parametrize("lengths", LINKAGES)
def test_open_and_crossed_put_c_on_the_stated_side(lengths) -> None:
    l0, l1, l2, l3 = lengths
    phi = np.linspace(0.0, 2 * np.pi, 721)
    for assembly, sign in (("open", 1.0), ("crossed", -1.0)):
        m = four_bar_motion(phi, l0, l1, l2, l3, 10.0, assembly)
        b = l1 * unit(phi)
        c = b + l2 * unit(m.coupler_angle)
        d_minus_b = np.array([l0, 0.0]) - b
        cross = d_minus_b[:, 0] * (c - b)[:, 1] - d_minus_b[:, 1] * (c - b)[:, 0]
        assert np.all(sign * cross > 0)


@pytest.mark.parametrize("assembly", ["open", "crossed"])
def test_rates_match_finite_differences_of_positions(assembly: str) -> None:
    l0, l1, l2, l3 = LINKAGES[0]
    omega = 120 * RPM
    phi = np.linspace(0.0, 2 * np.pi, 73)

    def angles(phase: np.ndarray) -> np.ndarray:
        m = four_bar_motion(phase, l0, l1, l2, l3, omega, assembly)
        return np.array([m.coupler_angle, m.rocker_angle])

    m = four_bar_motion(phi, l0, l1, l2, l3, omega, assembly)
    rate = np.array([m.coupler_angular_velocity, m.rocker_angular_velocity])
    acc = np.array([m.coupler_angular_acceleration, m.rocker_angular_acceleration])
    h = 1e-6  # [s]
    central = (angles(phi + omega * h) - angles(phi - omega * h)) / (2 * h)
    np.testing.assert_allclose(central, rate, rtol=0, atol=1e-7 * np.abs(rate).max())
    h = 1e-4
    second = (angles(phi + omega * h) - 2 * angles(phi) + angles(phi - omega * h)) / h**2
    np.testing.assert_allclose(second, acc, rtol=0, atol=1e-5 * np.abs(acc).max())


def test_joint_positions_are_the_ideal_pivots() -> None:
    link = linkage()
    m = motion_of(link, np.array([0.3, 2.0]), 5.0)
    pos = joint_positions(m, link)
    np.testing.assert_allclose(np.hypot(*(pos["C"] - pos["D"]).T), 0.12, rtol=1e-14)
    np.testing.assert_allclose(np.hypot(*(pos["B"] - pos["A"]).T), 0.05, rtol=1e-14)
