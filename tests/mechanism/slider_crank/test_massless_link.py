"""The slider-crank's massless-link model (paper eqs. 10-12), iterated to a fixed point.

Checks are physical: the power balance (crank power = rate of mechanical energy)
with and without clearance, the two-force member, the no-clearance limit, the
correction first order in the clearance with the loop closed along the load, the
pull/push trend and the contact-loss check.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.errors import ContactLossWarning, ConvergenceError, MechanismError
from jointwear.geometry.angles import wrap_angle
from jointwear.mechanism.slider_crank.dynamics import SliderCrank, spring_force
from jointwear.mechanism.slider_crank.kinematics import (
    SliderCrankMotion,
)
from jointwear.mechanism.slider_crank.massless_link import solve_massless_link
from jointwear.mechanism.stage import load_cycle

RPM = 2.0 * math.pi / 60.0
L1, L2 = 0.07, 0.2


def mechanism(config: Config, **changes: object) -> SliderCrank:
    data = {**SliderCrank.from_config(config.mechanism).__dict__, **changes}
    return SliderCrank(**data)


def energy_rate(motion: SliderCrankMotion, mech: SliderCrank) -> np.ndarray:
    """d/dt (kinetic + spring + gravity energy) from the motion's rates [W]."""
    phi, omega = motion.crank_angle, motion.crank_speed
    theta, theta_dot, theta_ddot = (
        motion.rod_angle,
        motion.rod_angular_velocity,
        motion.rod_angular_acceleration,
    )
    l1, l2 = mech.crank_length, mech.rod_length
    v_b = l1 * omega * np.array([-np.sin(phi), np.cos(phi)])
    a_b = -(omega**2) * l1 * np.array([np.cos(phi), np.sin(phi)])
    v_g = v_b + 0.5 * l2 * theta_dot * np.array([-np.sin(theta), np.cos(theta)])
    r_ddot = l2 * np.array(
        [
            -np.sin(theta) * theta_ddot - np.cos(theta) * theta_dot**2,
            np.cos(theta) * theta_ddot - np.sin(theta) * theta_dot**2,
        ]
    )
    a_g = a_b + 0.5 * r_ddot
    kinetic = (
        mech.slider_mass * motion.slider_velocity * motion.slider_acceleration
        + mech.rod_mass * np.sum(v_g * a_g, axis=0)
        + mech.rod_inertia * theta_dot * theta_ddot
        + mech.crank_mass * np.sum(0.5 * v_b * 0.5 * a_b, axis=0)  # zero at constant omega
    )
    force = spring_force(
        motion.slider_position, l1, l2, mech.spring_stiffness, mech.spring_preload, mech.spring_mode
    )
    spring = -force * motion.slider_velocity  # dV/dt with F = -dV/dx
    gravity = mech.gravity * (mech.rod_mass * v_g[1] + mech.crank_mass * 0.5 * v_b[1])
    return kinetic + spring + gravity


# ------------------------------------------------------------- ideal dynamics


@pytest.mark.parametrize("mode", ["pull", "push"])
@pytest.mark.parametrize("rpm", [120.0, 240.0])
def test_power_balance_without_clearance(paper_config: Config, mode: str, rpm: float) -> None:
    mech = mechanism(paper_config, spring_mode=mode, spring_preload=30.0)
    solution = solve_massless_link(mech, rpm * RPM, 0.0, 360)
    power = solution.reaction.crank_torque * rpm * RPM
    rate = energy_rate(solution.motion, mech)
    np.testing.assert_allclose(power, rate, rtol=0, atol=1e-9 * np.abs(power).max())


@pytest.mark.parametrize("rpm", [120.0, 240.0])
def test_power_balance_with_clearance(paper_config: Config, rpm: float) -> None:
    # the joint force does no net work: it is along the link, and the link only
    # turns (n . dn/dt = 0), so the balance holds with clearance too
    mech = mechanism(paper_config)
    solution = solve_massless_link(mech, rpm * RPM, 0.05e-3, 360)
    power = solution.reaction.crank_torque * rpm * RPM
    rate = energy_rate(solution.motion, mech)
    np.testing.assert_allclose(power, rate, rtol=0, atol=1e-8 * np.abs(power).max())


@pytest.mark.parametrize("clearance", [0.0, 0.05e-3])
def test_force_along_massless_rod(paper_config: Config, clearance: float) -> None:
    mech = mechanism(paper_config, rod_mass=0.0, rod_inertia=0.0, gravity=0.0)
    solution = solve_massless_link(mech, 240 * RPM, clearance, 360)
    r = solution.reaction
    theta = solution.motion.rod_angle
    # a massless rod is a two-force member: (C - B) x J = 0
    cross = np.cos(theta) * r.force_y - np.sin(theta) * r.force_x
    np.testing.assert_allclose(cross, 0.0, atol=1e-12 * np.hypot(r.force_x, r.force_y).max())
    # with rod mass the force leaves the rod axis
    heavy = solve_massless_link(mechanism(paper_config), 240 * RPM, clearance, 360)
    heavy_cross = (
        np.cos(heavy.motion.rod_angle) * heavy.reaction.force_y
        - np.sin(heavy.motion.rod_angle) * heavy.reaction.force_x
    )
    assert np.abs(heavy_cross).max() > 1.0


def test_total_relative_rotation_is_four_rod_swings(paper_config: Config) -> None:
    load = load_cycle(paper_config.replace({"joint.clearance": 1e-12}))
    # theta_2 swings 0 -> -asin(l1/l2) -> 0 -> +asin(l1/l2) -> 0 (extremes at 90 and 270 deg)
    assert load.total_relative_rotation == pytest.approx(4 * math.asin(L1 / L2), rel=1e-9)
    assert load.relative_rotation.sum() == pytest.approx(0.0, abs=1e-12)
    # exact increments: they telescope to the rod angle
    np.testing.assert_allclose(
        np.cumsum(load.relative_rotation)[:-1],
        load.diagnostics["rod_angle"].values[1:] - load.diagnostics["rod_angle"].values[0],
        atol=1e-14,
    )


# ------------------------------------------------------------------ clearance


def test_no_clearance_limit(paper_config: Config) -> None:
    config = paper_config.replace({"joint.clearance": 1e-12, "mechanism.crank_speed": 240 * RPM})
    load = load_cycle(config)
    ideal = solve_massless_link(SliderCrank.from_config(config.mechanism), 240 * RPM, 0.0, 360)
    j_x, j_y = ideal.reaction.force_x, ideal.reaction.force_y
    scale = np.hypot(j_x, j_y).max()
    np.testing.assert_allclose(load.force_x, j_x, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(load.force_y, j_y, rtol=0, atol=1e-9 * scale)
    np.testing.assert_allclose(load.load, np.hypot(j_x, j_y), rtol=1e-9)
    np.testing.assert_allclose(wrap_angle(load.azimuth - np.arctan2(j_y, j_x)), 0.0, atol=1e-9)
    np.testing.assert_allclose(
        load.diagnostics["crank_torque"].values,
        ideal.reaction.crank_torque,
        rtol=0,
        atol=1e-9 * np.abs(ideal.reaction.crank_torque).max(),
    )


@pytest.mark.parametrize("rpm", [120.0, 240.0])
def test_clearance_correction_small_linear_and_fast(paper_config: Config, rpm: float) -> None:
    mech = mechanism(paper_config)
    omega = rpm * RPM
    ideal = solve_massless_link(mech, omega, 0.0, 360)

    def correction(clearance: float) -> tuple[np.ndarray, int]:
        solution = solve_massless_link(mech, omega, clearance, 360)
        delta = np.array(solution.reaction[:2]) - np.array(ideal.reaction[:2])
        return delta, solution.iterations

    small, iterations = correction(0.05e-3)
    double, _ = correction(0.1e-3)
    scale = np.hypot(*ideal.reaction[:2]).max()
    size = np.abs(small).max()
    assert 1e-6 * scale < size < 1e-2 * scale
    assert iterations <= 8
    # first order in e: doubling the clearance doubles the correction
    np.testing.assert_allclose(double, 2 * small, rtol=0, atol=1e-2 * size)
    # the loop A-B-C-D closes with |C - D| = e along J
    solution = solve_massless_link(mech, omega, 0.05e-3, 360)
    phi, theta = solution.motion.crank_angle, solution.motion.rod_angle
    c = np.array([L1 * np.cos(phi) + L2 * np.cos(theta), L1 * np.sin(phi) + L2 * np.sin(theta)])
    d = np.array([solution.motion.slider_position, 0 * phi])
    link = c - d
    np.testing.assert_allclose(np.hypot(*link), 0.05e-3, rtol=1e-9)
    j = np.array(solution.reaction[:2])
    np.testing.assert_allclose(
        link[0] * j[1] - link[1] * j[0], 0.0, atol=1e-9 * 0.05e-3 * np.hypot(*j).max()
    )
    assert np.all(np.sum(link * j, axis=0) > 0)


def test_large_clearance_high_speed_no_pin_flutter(paper_config: Config) -> None:
    # paper Table 4 case: the plain iteration would amplify round-off into a
    # pin flutter near the pin's lateral clearance mode (~50th harmonic)
    config = paper_config.replace({"joint.clearance": 0.2e-3, "mechanism.crank_speed": 240 * RPM})
    load = load_cycle(config)
    ideal = solve_massless_link(SliderCrank.from_config(config.mechanism), 240 * RPM, 0.0, 360)
    ideal_load = np.hypot(*ideal.reaction[:2])
    assert load.converged
    assert not load.contact_lost
    assert np.abs(load.load - ideal_load).max() < 1e-2 * ideal_load.max()
    assert load.azimuth.max() - load.azimuth.min() < np.radians(60)


def test_fixed_point_budget_exhausted_raises(paper_config: Config) -> None:
    config = paper_config.replace({"dynamics.max_iterations": 1})
    with pytest.raises(ConvergenceError, match=r"dynamics\.max_iterations"):
        load_cycle(config)


def test_paper_one_pass_scheme_is_first_iterate(paper_config: Config) -> None:
    mech = mechanism(paper_config)
    one_pass = solve_massless_link(mech, 120 * RPM, 0.05e-3, 360, scheme="paper")
    converged = solve_massless_link(mech, 120 * RPM, 0.05e-3, 360)
    assert one_pass.iterations == 1
    gap = np.abs(np.array(one_pass.reaction[:2]) - np.array(converged.reaction[:2])).max()
    assert 0.0 < gap < 1e-3


@pytest.mark.parametrize(
    ("mode", "preload", "faster_wears_more"), [("pull", 20.0, True), ("push", 400.0, False)]
)
def test_speed_trend_of_sliding_mean_load(
    paper_config: Config, mode: str, preload: float, faster_wears_more: bool
) -> None:
    def sliding_mean(rpm: float) -> float:
        config = paper_config.replace(
            {
                "mechanism.spring_mode": mode,
                "mechanism.spring_preload": preload,
                "mechanism.crank_speed": rpm * RPM,
            }
        )
        with warnings.catch_warnings():
            warnings.simplefilter("error", ContactLossWarning)
            return load_cycle(config).sliding_mean_load

    slow, fast = sliding_mean(120.0), sliding_mean(240.0)
    assert (fast > slow) is faster_wears_more
    assert abs(fast - slow) > 0.03 * slow


def contact_loss_config(paper_config: Config, strict: bool = False) -> Config:
    return paper_config.replace(
        {
            "mechanism.spring_mode": "push",
            "mechanism.spring_preload": 1.0,
            "mechanism.crank_speed": 240 * RPM,
            "dynamics.strict": strict,
        }
    )


def test_contact_loss_warns_with_angles(paper_config: Config) -> None:
    with pytest.warns(ContactLossWarning, match=r"crank angles 0-30, 329-359 deg") as record:
        load = load_cycle(contact_loss_config(paper_config))
    assert len(record) == 1
    assert load.contact_lost
    lost_deg = np.degrees(load.phase[load.lost_steps])
    assert lost_deg.size == 62
    # near the outer dead centre the slider decelerates hard, more than the weak
    # push spring can supply, so the rod goes into tension
    assert np.all((lost_deg <= 30.5) | (lost_deg >= 328.5))


def test_contact_loss_pull_spring_too_fast(paper_config: Config) -> None:
    # pull: around the inner dead centre the slider accelerates away from the crank
    # faster than the spring can drive it (m3 x3'' > F_spring): the rod would push
    config = paper_config.replace({"mechanism.crank_speed": 480 * RPM})
    with pytest.warns(ContactLossWarning, match="needs the rod in tension") as record:
        load = load_cycle(config)
    assert len(record) == 1
    lost_deg = np.degrees(load.phase[load.lost_steps])
    assert np.any(np.isclose(lost_deg, 180.0))
    assert np.all((lost_deg > 60) & (lost_deg < 300))


def test_contact_loss_strict_raises(paper_config: Config) -> None:
    with pytest.raises(MechanismError, match="reverses relative to the rod"):
        load_cycle(contact_loss_config(paper_config, strict=True))


def test_paper_mechanism_keeps_contact(paper_config: Config) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", ContactLossWarning)
        for rpm in (120.0, 240.0):
            config = paper_config.replace({"mechanism.crank_speed": rpm * RPM})
            assert not load_cycle(config).contact_lost
