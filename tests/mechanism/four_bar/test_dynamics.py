"""Inverse dynamics of the ideal four-bar.

The power balance (crank and rocker-load power = rate of kinetic + gravity + spring
energy), hand statics of a heavy crank and a heavy rocker, and the mirror symmetry
open <-> crossed.
"""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.mechanism.four_bar.dynamics import inverse_dynamics
from jointwear.mechanism.four_bar.geometry import FourBar
from jointwear.mechanism.four_bar.kinematics import FourBarMotion
from tests.mechanism.four_bar.linkages import LINKAGES, RPM, linkage, motion_of, normal, unit

# ------------------------------------------------------------------ dynamics


def energy_rate(m: FourBarMotion, link: FourBar) -> np.ndarray:
    """d/dt (kinetic + gravity + spring energy) from the closed-form rates [W]."""
    _, l1, l2, l3 = link.lengths
    w, phi = m.crank_speed, m.crank_angle
    t2, t2d, t2dd = m.coupler_angle, m.coupler_angular_velocity, m.coupler_angular_acceleration
    t3, t3d, t3dd = m.rocker_angle, m.rocker_angular_velocity, m.rocker_angular_acceleration
    v_b, a_b = l1 * w * normal(phi), -l1 * w * w * unit(phi)
    v2 = v_b + 0.5 * l2 * t2d[:, None] * normal(t2)
    a2 = a_b + 0.5 * l2 * (t2dd[:, None] * normal(t2) - (t2d**2)[:, None] * unit(t2))
    v3 = 0.5 * l3 * t3d[:, None] * normal(t3)
    a3 = 0.5 * l3 * (t3dd[:, None] * normal(t3) - (t3d**2)[:, None] * unit(t3))
    kinetic = (
        link.crank_mass * np.sum(0.5 * v_b * 0.5 * a_b, axis=1)  # zero at constant omega
        + link.coupler_mass * np.sum(v2 * a2, axis=1)
        + link.rocker_mass * np.sum(v3 * a3, axis=1)
        + link.coupler_inertia * t2d * t2dd
        + link.rocker_inertia * t3d * t3dd
    )
    gravity = link.gravity * (
        link.crank_mass * 0.5 * v_b[:, 1]
        + link.coupler_mass * v2[:, 1]
        + link.rocker_mass * v3[:, 1]
    )
    spring = link.rocker_spring_stiffness * (t3 - link.rocker_spring_angle) * t3d
    return kinetic + gravity + spring


@pytest.mark.parametrize("lengths", LINKAGES)
@pytest.mark.parametrize("assembly", ["open", "crossed"])
@pytest.mark.parametrize("rpm", [30.0, 600.0])
def test_power_balance(lengths, assembly: str, rpm: float) -> None:
    link = linkage(lengths, assembly=assembly)
    omega = rpm * RPM
    m = motion_of(link, 2 * np.pi * np.arange(360) / 360, omega)
    reaction = inverse_dynamics(m, link)
    power = reaction.crank_torque * omega + link.rocker_torque * m.rocker_angular_velocity
    rate = energy_rate(m, link)
    scale = np.abs(reaction.crank_torque * omega).max()
    # observed ~1e-15 relative
    np.testing.assert_allclose(power, rate, rtol=0, atol=1e-8 * scale)


def test_statics_of_a_heavy_crank() -> None:
    # only the crank has mass, nothing loads the rocker: coupler and rocker carry no
    # force, the ground holds the crank's weight and T = m1 g (l1 / 2) cos(phi)
    link = linkage(
        coupler_mass=0.0,
        rocker_mass=0.0,
        coupler_inertia=0.0,
        rocker_inertia=0.0,
        rocker_torque=0.0,
        rocker_spring_stiffness=0.0,
    )
    phi = np.linspace(0.0, 2 * np.pi, 37)
    r = inverse_dynamics(motion_of(link, phi, 1e-6), link)
    weight = link.crank_mass * link.gravity
    for force in (r.crank_on_coupler, r.coupler_on_rocker, r.ground_on_rocker):
        np.testing.assert_allclose(force, 0.0, atol=1e-12)
    np.testing.assert_allclose(r.ground_on_crank, np.tile([0.0, weight], (37, 1)), atol=1e-12)
    np.testing.assert_allclose(r.crank_torque, weight * 0.025 * np.cos(phi), atol=1e-12)


@pytest.mark.parametrize("assembly", ["open", "crossed"])
def test_statics_of_a_heavy_rocker(assembly: str) -> None:
    # the massless coupler is a two-force member, F_C = f e2; moments about D:
    # l3 f sin(theta2 - theta3) = (l3 / 2) m3 g cos(theta3); crank: T = l1 f sin(theta2 - phi)
    link = linkage(
        crank_mass=0.0,
        coupler_mass=0.0,
        crank_inertia=0.0,
        coupler_inertia=0.0,
        rocker_torque=0.0,
        rocker_spring_stiffness=0.0,
        assembly=assembly,
    )
    phi = np.linspace(0.0, 2 * np.pi, 37)
    m = motion_of(link, phi, 1e-6)
    r = inverse_dynamics(m, link)
    t2, t3 = m.coupler_angle, m.rocker_angle
    weight = link.rocker_mass * link.gravity
    f = weight * np.cos(t3) / (2 * np.sin(t2 - t3))
    np.testing.assert_allclose(r.coupler_on_rocker, f[:, None] * unit(t2), atol=1e-10)
    np.testing.assert_allclose(r.crank_on_coupler, r.coupler_on_rocker, atol=1e-10)
    np.testing.assert_allclose(
        r.ground_on_rocker, np.array([0.0, weight]) - r.coupler_on_rocker, atol=1e-10
    )
    np.testing.assert_allclose(r.crank_torque, 0.05 * f * np.sin(t2 - phi), atol=1e-10)


def test_mirror_symmetry_open_and_crossed() -> None:
    # reflecting y -> -y and reversing time maps the open linkage at crank angle -phi
    # onto the crossed one at phi; without gravity, and with the rocker load
    # reflected too, forces reflect and the crank torque changes sign
    phi = 2 * np.pi * np.arange(90) / 90
    omega = 300 * RPM
    open_ = linkage(gravity=0.0, rocker_torque=1.5, rocker_spring_angle=2.0)
    crossed = linkage(gravity=0.0, rocker_torque=-1.5, rocker_spring_angle=-2.0, assembly="crossed")
    m_open, m_crossed = motion_of(open_, -phi, omega), motion_of(crossed, phi, omega)
    np.testing.assert_allclose(m_crossed.rocker_angle, -m_open.rocker_angle, atol=1e-13)
    np.testing.assert_allclose(
        m_crossed.rocker_angular_velocity, m_open.rocker_angular_velocity, rtol=1e-11, atol=1e-12
    )
    r_open, r_crossed = inverse_dynamics(m_open, open_), inverse_dynamics(m_crossed, crossed)
    mirror = np.array([1.0, -1.0])
    scale = np.abs(r_open.ground_on_rocker).max()
    for a, b in zip(r_open[:4], r_crossed[:4], strict=True):
        np.testing.assert_allclose(b, a * mirror, rtol=0, atol=1e-11 * scale)
    np.testing.assert_allclose(r_crossed.crank_torque, -r_open.crank_torque, atol=1e-11 * scale)
