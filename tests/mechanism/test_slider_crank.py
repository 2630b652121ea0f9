"""Slider-crank dynamics with a clearance joint (massless-link model, paper eqs. 10-12).

Checks are physical: closed-form kinematics against known dead-centre values and
against spectral derivatives of the positions, the power balance (crank power =
rate of mechanical energy), statics, the omega^2 scaling of the inertial load,
the no-clearance limit, the pull/push trend and the contact-loss check.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.errors import ConfigError, ContactLossWarning, ConvergenceError, MechanismError
from jointwear.mechanism import (
    DYNAMICS_MODELS,
    LoadCycle,
    SliderCrank,
    SliderCrankMotion,
    crank_angle_grid,
    ideal_motion,
    inverse_dynamics,
    load_cycle,
    rod_angle,
    rod_angular_acceleration,
    rod_angular_velocity,
    slider_acceleration,
    slider_position,
    slider_velocity,
    solve_massless_link,
    spectral_derivative,
    spring_force,
    wrap_angle,
)

RPM = 2.0 * math.pi / 60.0
L1, L2 = 0.07, 0.2


def mechanism(config: Config, **changes: object) -> SliderCrank:
    data = {**SliderCrank.from_config(config.mechanism).__dict__, **changes}
    return SliderCrank(**data)


def energy_rate(motion: SliderCrankMotion, mech: SliderCrank) -> np.ndarray:
    """d/dt (kinetic + spring + gravity energy) from the motion's rates [W]."""
    phi, omega = motion.crank_angle, motion.crank_speed
    theta, theta_dot, theta_ddot = (
        motion.rod_angle, motion.rod_angular_velocity, motion.rod_angular_acceleration
    )
    l1, l2 = mech.crank_length, mech.rod_length
    v_b = l1 * omega * np.array([-np.sin(phi), np.cos(phi)])
    a_b = -(omega**2) * l1 * np.array([np.cos(phi), np.sin(phi)])
    v_g = v_b + 0.5 * l2 * theta_dot * np.array([-np.sin(theta), np.cos(theta)])
    r_ddot = l2 * np.array([
        -np.sin(theta) * theta_ddot - np.cos(theta) * theta_dot**2,
        np.cos(theta) * theta_ddot - np.sin(theta) * theta_dot**2,
    ])
    a_g = a_b + 0.5 * r_ddot
    kinetic = (
        mech.slider_mass * motion.slider_velocity * motion.slider_acceleration
        + mech.rod_mass * np.sum(v_g * a_g, axis=0)
        + mech.rod_inertia * theta_dot * theta_ddot
        + mech.crank_mass * np.sum(0.5 * v_b * 0.5 * a_b, axis=0)  # zero at constant omega
    )
    force = spring_force(motion.slider_position, l1, l2, mech.spring_stiffness,
                         mech.spring_preload, mech.spring_mode)
    spring = -force * motion.slider_velocity  # dV/dt with F = -dV/dx
    gravity = mech.gravity * (mech.rod_mass * v_g[1] + mech.crank_mass * 0.5 * v_b[1])
    return kinetic + spring + gravity


# ---------------------------------------------------------------- kinematics


@pytest.mark.parametrize("omega", [120 * RPM, 240 * RPM])
def test_dead_centre_slider_acceleration(omega: float) -> None:
    ratio = L1 / L2
    acc = slider_acceleration([0.0, math.pi], L1, L2, omega)
    assert acc[0] == pytest.approx(-L1 * omega**2 * (1 + ratio), rel=1e-14)
    assert acc[1] == pytest.approx(L1 * omega**2 * (1 - ratio), rel=1e-14)
    assert slider_position([0.0, math.pi], L1, L2) == pytest.approx([L1 + L2, L2 - L1], rel=1e-15)
    assert slider_velocity([0.0, math.pi], L1, L2, omega) == pytest.approx([0.0, 0.0], abs=1e-15)


def test_closure_of_ideal_mechanism() -> None:
    phi = np.linspace(0.0, 2 * np.pi, 97)
    theta = rod_angle(phi, L1, L2)
    c_x = L1 * np.cos(phi) + L2 * np.cos(theta)
    c_y = L1 * np.sin(phi) + L2 * np.sin(theta)
    np.testing.assert_allclose(c_x, slider_position(phi, L1, L2), rtol=1e-15)
    np.testing.assert_allclose(c_y, 0.0, atol=1e-16)


@pytest.mark.parametrize("omega", [120 * RPM, 900 * RPM])
def test_closed_form_derivatives_match_spectral_derivatives(omega: float) -> None:
    # the positions are analytic and periodic: their spectral derivatives on 256
    # samples are exact to round-off, an independent check of the closed forms
    phi = crank_angle_grid(256)
    theta, x = rod_angle(phi, L1, L2), slider_position(phi, L1, L2)
    checks = [
        (spectral_derivative(theta, omega, 1), rod_angular_velocity(phi, L1, L2, omega)),
        (spectral_derivative(theta, omega, 2), rod_angular_acceleration(phi, L1, L2, omega)),
        (spectral_derivative(x, omega, 1), slider_velocity(phi, L1, L2, omega)),
        (spectral_derivative(x, omega, 2), slider_acceleration(phi, L1, L2, omega)),
    ]
    for spectral, analytic in checks:
        np.testing.assert_allclose(spectral, analytic, atol=1e-12 * np.abs(analytic).max())


def test_spectral_derivative_of_trigonometric_polynomial() -> None:
    omega = 3.0
    t = 2 * np.pi * np.arange(64) / 64 / omega
    signal = np.sin(omega * t) + 0.5 * np.cos(5 * omega * t)
    first = omega * np.cos(omega * t) - 2.5 * omega * np.sin(5 * omega * t)
    second = -(omega**2) * np.sin(omega * t) - 12.5 * omega**2 * np.cos(5 * omega * t)
    np.testing.assert_allclose(spectral_derivative(signal, omega, 1), first, atol=1e-12)
    np.testing.assert_allclose(spectral_derivative(signal, omega, 2), second, atol=1e-11)
    # band limit below harmonic 5 keeps only the fundamental
    np.testing.assert_allclose(
        spectral_derivative(signal, omega, 1, max_harmonic=4), omega * np.cos(omega * t),
        atol=1e-12,
    )


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


def test_statics_and_omega_squared_scaling(paper_config: Config) -> None:
    mech = mechanism(paper_config)
    phi = crank_angle_grid(360)
    omega = 120 * RPM

    def reaction(speed: float) -> np.ndarray:
        return np.array(inverse_dynamics(ideal_motion(phi, L1, L2, speed), mech))

    # static part: same positions, no velocity or acceleration
    motion = ideal_motion(phi, L1, L2, omega)
    still = motion._replace(
        crank_speed=0.0, rod_angular_velocity=0 * phi, rod_angular_acceleration=0 * phi,
        slider_velocity=0 * phi, slider_acceleration=0 * phi,
    )
    static = np.array(inverse_dynamics(still, mech))
    # statics by hand: slider x balance, rod moments about B, crank moments about A
    spring = spring_force(motion.slider_position, L1, L2, mech.spring_stiffness,
                          mech.spring_preload, "pull")
    theta = motion.rod_angle
    j_x = -spring
    j_y = np.tan(theta) * j_x - 0.5 * mech.rod_mass * mech.gravity
    b_x, b_y = L1 * np.cos(phi), L1 * np.sin(phi)
    torque = (b_x * (j_y + mech.rod_mass * mech.gravity) - b_y * j_x
              + 0.5 * mech.crank_mass * mech.gravity * b_x)
    np.testing.assert_allclose(static, [j_x, j_y, torque], rtol=1e-12, atol=1e-12)

    # what is not static is inertial and grows with omega^2, componentwise
    single, double = reaction(omega) - static, reaction(2 * omega) - static
    np.testing.assert_allclose(double, 4.0 * single, rtol=0, atol=1e-11 * np.abs(double).max())
    assert np.abs(single).max() > 10.0  # the inertial part is not negligible


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
    heavy_cross = (np.cos(heavy.motion.rod_angle) * heavy.reaction.force_y
                   - np.sin(heavy.motion.rod_angle) * heavy.reaction.force_x)
    assert np.abs(heavy_cross).max() > 1.0


def test_total_relative_rotation_is_four_rod_swings(paper_config: Config) -> None:
    load = load_cycle(paper_config.replace({"joint.clearance": 1e-12}))
    # theta_2 swings 0 -> -asin(l1/l2) -> 0 -> +asin(l1/l2) -> 0 (extremes at 90 and 270 deg)
    assert load.total_relative_rotation == pytest.approx(4 * math.asin(L1 / L2), rel=1e-9)
    assert load.relative_rotation.sum() == pytest.approx(0.0, abs=1e-12)
    # exact increments: they telescope to the rod angle
    np.testing.assert_allclose(
        np.cumsum(load.relative_rotation)[:-1], load.diagnostics['rod_angle'].values[1:]
        - load.diagnostics['rod_angle'].values[0], atol=1e-14
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
    np.testing.assert_allclose(load.diagnostics["crank_torque"].values,
                               ideal.reaction.crank_torque, rtol=0,
                               atol=1e-9 * np.abs(ideal.reaction.crank_torque).max())


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
    np.testing.assert_allclose(link[0] * j[1] - link[1] * j[0], 0.0,
                               atol=1e-9 * 0.05e-3 * np.hypot(*j).max())
    assert np.all(np.sum(link * j, axis=0) > 0)


def test_large_clearance_high_speed_no_pin_flutter(paper_config: Config) -> None:
    # paper Table 4 case: the plain iteration would amplify round-off into a
    # pin flutter near the pin's lateral clearance mode (~50th harmonic)
    config = paper_config.replace({"joint.clearance": 0.2e-3,
                                   "mechanism.crank_speed": 240 * RPM})
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


# --------------------------------------------------------------- load object


def test_joint_load_fields_and_sliding(paper_config: Config) -> None:
    load = load_cycle(paper_config)
    n = paper_config.simulation.steps_per_revolution
    assert isinstance(load, LoadCycle)
    for name in ("phase", "time", "load", "azimuth", "relative_rotation", "force_x", "force_y"):
        assert getattr(load, name).shape == (n,)
    for name in ("crank_torque", "slider_position", "rod_angle"):
        assert load.diagnostics[name].values.shape == (n,)
    np.testing.assert_allclose(load.phase, 2 * np.pi * np.arange(n) / n)
    np.testing.assert_allclose(load.time, load.phase / paper_config.mechanism.crank_speed)
    assert load.period == pytest.approx(2 * np.pi / paper_config.mechanism.crank_speed)
    assert np.all(load.load >= 0)
    np.testing.assert_allclose(load.load, np.hypot(load.force_x, load.force_y))
    # pull spring, bushing on the slider: the pin presses towards the crank (-x)
    np.testing.assert_allclose(np.cos(load.azimuth), load.force_x / load.load)
    assert np.all(load.force_x < 0)
    radius = paper_config.joint.bushing_radius
    np.testing.assert_allclose(
        load.sliding_distance(radius), radius * np.abs(load.relative_rotation)
    )
    dpsi = wrap_angle(np.roll(load.azimuth, -1) - load.azimuth)
    np.testing.assert_allclose(
        load.sliding_distance(radius, "contact-azimuth"), radius * np.abs(dpsi)
    )
    weights = np.abs(load.relative_rotation)
    assert load.sliding_mean_load == pytest.approx(np.sum(load.load * weights) / weights.sum())
    assert not load.contact_lost
    assert not load.lost_steps.any()


def test_bushing_on_rod_frame(paper_config: Config) -> None:
    on_slider = load_cycle(paper_config)
    on_rod = load_cycle(paper_config.replace({"mechanism.bushing_body": "rod"}))
    np.testing.assert_allclose(on_rod.load, on_slider.load)
    np.testing.assert_allclose(on_rod.relative_rotation, -on_slider.relative_rotation)
    # the bushing sees -J, turned into the rod's frame
    expected = on_slider.azimuth + np.pi - on_slider.diagnostics["rod_angle"].values
    np.testing.assert_allclose(wrap_angle(on_rod.azimuth - expected), 0.0, atol=1e-12)
    # a bushing in the rod sees the load almost along the rod: a narrow azimuth band
    assert np.ptp(on_rod.azimuth) < 0.2 * np.ptp(on_slider.azimuth)


# -------------------------------------------------------- spring sense, contact


def test_spring_force_sense_and_preload() -> None:
    x = slider_position(crank_angle_grid(360), L1, L2)
    pull = spring_force(x, L1, L2, 1800.0, 20.0, "pull")
    push = spring_force(x, L1, L2, 1800.0, 20.0, "push")
    assert pull.min() == pytest.approx(20.0)
    assert np.all(pull > 0)
    assert push.max() == pytest.approx(-20.0)
    assert np.all(push < 0)
    assert pull.max() == pytest.approx(20.0 + 1800.0 * 2 * L1)


@pytest.mark.parametrize(("mode", "preload", "faster_wears_more"),
                         [("pull", 20.0, True), ("push", 400.0, False)])
def test_speed_trend_of_sliding_mean_load(
    paper_config: Config, mode: str, preload: float, faster_wears_more: bool
) -> None:
    def sliding_mean(rpm: float) -> float:
        config = paper_config.replace({
            "mechanism.spring_mode": mode, "mechanism.spring_preload": preload,
            "mechanism.crank_speed": rpm * RPM,
        })
        with warnings.catch_warnings():
            warnings.simplefilter("error", ContactLossWarning)
            return load_cycle(config).sliding_mean_load

    slow, fast = sliding_mean(120.0), sliding_mean(240.0)
    assert (fast > slow) is faster_wears_more
    assert abs(fast - slow) > 0.03 * slow


def contact_loss_config(paper_config: Config, strict: bool = False) -> Config:
    return paper_config.replace({
        "mechanism.spring_mode": "push", "mechanism.spring_preload": 1.0,
        "mechanism.crank_speed": 240 * RPM, "dynamics.strict": strict,
    })


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


# ------------------------------------------------------------------ registry


def test_registry_and_unknown_model(paper_config: Config) -> None:
    assert "massless-link" in DYNAMICS_MODELS
    message = r"dynamics\.model: unknown dynamics model .*massless-link"
    with pytest.raises(ConfigError, match=message):
        load_cycle(paper_config.replace({"dynamics.model": "massles-link"}))


def test_mechanism_that_cannot_assemble() -> None:
    with pytest.raises(MechanismError, match="crank_length"):
        SliderCrank(crank_length=0.3, rod_length=0.2, crank_mass=1, rod_mass=1, slider_mass=1,
                    rod_inertia=0.1, spring_stiffness=0, spring_preload=0)
