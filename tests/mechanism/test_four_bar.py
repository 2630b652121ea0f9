"""Four-bar linkage: closed-form kinematics, ideal-joint inverse dynamics, load cycles.

Checks that fail if the mechanics is wrong: loop closure, the assembly side,
finite differences of the positions, the power balance (crank and rocker-load power
= rate of kinetic + gravity + spring energy), hand statics, the mirror symmetry
open <-> crossed, Grashof and assembly errors, the contact-impact model against the
ideal-joint load with a stiff joint and its energy balance, and the example config
through the CLI.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.config import load_config
from jointwear.errors import ConfigError
from jointwear.mechanism import load_cycles
from jointwear.mechanism.four_bar import (
    FourBar,
    FourBarContactSystem,
    FourBarMotion,
    check_four_bar,
    four_bar_contact_impact,
    four_bar_cycles,
    four_bar_motion,
    inverse_dynamics,
    joint_positions,
)

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "four_bar.toml"
RPM = 2.0 * math.pi / 60.0
#: (l0, l1, l2, l3) [m]: the example and a stubbier crank-rocker with a long rocker
LINKAGES = [(0.2, 0.05, 0.18, 0.12), (0.1, 0.04, 0.12, 0.09)]


def linkage(lengths=LINKAGES[0], **changes: object) -> FourBar:
    data = dict(
        crank_mass=0.1,
        coupler_mass=0.3,
        rocker_mass=0.2,
        gravity=9.81,
        rocker_torque=2.0,
        rocker_spring_stiffness=1.0,
        rocker_spring_angle=math.pi / 2,
    )
    data.update(changes)
    l0, l1, l2, l3 = lengths
    for name, length in (("crank", l1), ("coupler", l2), ("rocker", l3)):
        data.setdefault(f"{name}_inertia", data[f"{name}_mass"] * length**2 / 12)
    return FourBar(l0, l1, l2, l3, **data)


def motion_of(link: FourBar, phi: np.ndarray, omega: float) -> FourBarMotion:
    return four_bar_motion(phi, *link.lengths, omega, link.assembly)


def unit(theta: np.ndarray) -> np.ndarray:
    return np.stack((np.cos(theta), np.sin(theta)), axis=-1)


def normal(theta: np.ndarray) -> np.ndarray:
    return np.stack((-np.sin(theta), np.cos(theta)), axis=-1)


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


# ------------------------------------------------------------------ validation


@pytest.mark.parametrize(
    ("lengths", "key", "words"),
    [
        ((0.2, 0.13, 0.18, 0.12), "mechanism.crank_length:", "shortest"),
        ((0.3, 0.05, 0.12, 0.12), "mechanism.crank_length:", "Grashof"),
        ((0.2, 0.05, 0.2, 0.05), "mechanism.crank_length:", "change-point"),
        ((0.2, 0.05, 0.15, 0.1), "mechanism.crank_length:", "change-point"),
    ],
)
def test_linkages_whose_crank_cannot_turn_are_rejected(lengths, key: str, words: str) -> None:
    with pytest.raises(ConfigError) as info:
        check_four_bar(*lengths)
    message = str(info.value)
    assert message.startswith(key)
    assert words in message
    assert "\n" not in message


def test_config_rejects_a_non_grashof_linkage_naming_the_key() -> None:
    with pytest.raises(ConfigError, match=r"^mechanism\.crank_length: Grashof"):
        load_config(EXAMPLE, {"mechanism.ground_length": "0.4 m"})
    with pytest.raises(ConfigError, match=r"^mechanism\.crank_length: the crank"):
        load_config(EXAMPLE).replace({"mechanism.crank_length": "0.15 m"})


def test_assembly_name_and_lengths_checked() -> None:
    with pytest.raises(ConfigError, match=r"^mechanism\.assembly:"):
        linkage(assembly="inverted")
    with pytest.raises(ConfigError, match=r"^mechanism\.ground_length:"):
        check_four_bar(-0.2, 0.05, 0.18, 0.12)


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


def test_joint_positions_are_the_ideal_pivots() -> None:
    link = linkage()
    m = motion_of(link, np.array([0.3, 2.0]), 5.0)
    pos = joint_positions(m, link)
    np.testing.assert_allclose(np.hypot(*(pos["C"] - pos["D"]).T), 0.12, rtol=1e-14)
    np.testing.assert_allclose(np.hypot(*(pos["B"] - pos["A"]).T), 0.05, rtol=1e-14)


# ------------------------------------------------------------------ load cycles


@pytest.fixture(scope="module")
def example():
    return load_config(EXAMPLE)


def test_cycles_are_the_pin_force_in_the_bushing_frame(example) -> None:
    cycles = four_bar_cycles(example, "massless-link")
    assert list(cycles) == ["crank-coupler", "coupler-rocker", "rocker-ground"]
    link = FourBar.from_config(example.mechanism)
    m = motion_of(link, 2 * np.pi * np.arange(360) / 360, example.mechanism.crank_speed)
    r = inverse_dynamics(m, link)
    expected = {  # force on the bushing body, and its angle
        "crank-coupler": (r.crank_on_coupler, m.coupler_angle),
        "coupler-rocker": (r.coupler_on_rocker, m.rocker_angle),
        "rocker-ground": (-r.ground_on_rocker, 0.0 * m.rocker_angle),
    }
    for joint, cycle in cycles.items():
        force, angle = expected[joint]
        assert cycle.mechanism == "four-bar"
        assert cycle.joint == joint
        assert cycle.model == "massless-link"
        c, s = np.cos(angle), np.sin(angle)
        local = np.stack((c * force[:, 0] + s * force[:, 1], -s * force[:, 0] + c * force[:, 1]))
        np.testing.assert_allclose(cycle.force_x, local[0], atol=1e-12)
        np.testing.assert_allclose(cycle.force_y, local[1], atol=1e-12)
        np.testing.assert_allclose(cycle.diagnostics["crank_torque"].values, r.crank_torque)
        assert cycle.period == pytest.approx(0.5)
        assert not cycle.contact_lost
        assert cycle.extras["contact_lost_crank_angles_deg"] == []
    # the crank turns once relative to the coupler; rocker and ground oscillate
    rotations = {j: c.relative_rotation.sum() for j, c in cycles.items()}
    assert rotations["crank-coupler"] == pytest.approx(2 * np.pi, abs=1e-12)
    assert rotations["coupler-rocker"] == pytest.approx(0.0, abs=1e-12)
    assert rotations["rocker-ground"] == pytest.approx(0.0, abs=1e-12)
    np.testing.assert_allclose(
        cycles["coupler-rocker"].relative_rotation,
        np.diff(
            np.append(m.coupler_angle - m.rocker_angle, m.coupler_angle[0] - m.rocker_angle[0])
        ),
        atol=1e-15,
    )


def test_bushing_on_the_other_body_reverses_the_view(example) -> None:
    config = example.replace({"mechanism.bushing_body": ["crank", "coupler", "rocker"]})
    swapped = four_bar_cycles(config, "massless-link")
    base = four_bar_cycles(example, "massless-link")
    np.testing.assert_allclose(
        swapped["crank-coupler"].relative_rotation, -base["crank-coupler"].relative_rotation
    )
    assert swapped["crank-coupler"].relative_rotation.sum() == pytest.approx(-2 * np.pi)
    for joint in base:
        np.testing.assert_allclose(swapped[joint].load, base[joint].load)
        # force on the crank, seen from the crank: -F_B turned by -phi
        gx = swapped[joint].diagnostics["global_force_x"].values
        np.testing.assert_allclose(gx, -base[joint].diagnostics["global_force_x"].values)


def test_vanishing_load_flags_lost_steps(example) -> None:
    # nothing loads the linkage (no mass, no gravity, no rocker load): zero load
    config = example.replace(
        {
            "mechanism.crank_mass": 0.0,
            "mechanism.coupler_mass": 0.0,
            "mechanism.rocker_mass": 0.0,
            "mechanism.rocker_torque": 0.0,
            "mechanism.rocker_spring_stiffness": 0.0,
            "mechanism.clearance_joint": "coupler-rocker",
            "mechanism.bushing_body": "rocker",
            "simulation.steps_per_revolution": 12,
        }
    )
    with pytest.warns(UserWarning, match="continuous-contact"):
        cycle = four_bar_cycles(config, "massless-link")["coupler-rocker"]
    assert cycle.lost_steps.all()


def test_cli_runs_the_example(capsys: pytest.CaptureFixture[str]) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        main(["dynamics", str(EXAMPLE), "--json"])
    data = json.loads(capsys.readouterr().out)
    assert set(data["joints"]) == {"crank-coupler", "coupler-rocker", "rocker-ground"}
    for joint, summary in data["joints"].items():
        assert summary["mechanism"] == "four-bar"
        assert summary["joint"] == joint
        assert summary["dynamics_model"] == "massless-link"
        assert 0 < summary["load_min_n"] <= summary["load_max_n"]
        assert summary["crank_speed_rpm"] == pytest.approx(120.0)
        for key in (
            "azimuth_range_deg",
            "total_relative_rotation_rad",
            "bushing_body",
            "crank_torque_rms_nm",
            "crank_torque_max_abs_nm",
        ):
            assert key in summary
    assert data["joints"]["crank-coupler"]["total_relative_rotation_rad"] == pytest.approx(
        2 * np.pi
    )


# ------------------------------------------------------------------ contact-impact


def impact_config(example, joint: str, body: str, **overrides: object):
    return example.replace(
        {
            "mechanism.clearance_joint": joint,
            "mechanism.bushing_body": body,
            "dynamics.model": "contact-impact",
            "dynamics.revolutions_settle": 1,
            "simulation.steps_per_revolution": 90,
            "joint.clearance": "0.01 mm",
            **overrides,
        }
    )


@pytest.mark.parametrize(
    ("joint", "body"),
    [("crank-coupler", "crank"), ("coupler-rocker", "rocker"), ("rocker-ground", "ground")],
)
def test_small_clearance_contact_impact_approaches_the_ideal_joint_load(
    example, joint, body
) -> None:
    config = impact_config(example, joint, body)
    cycle = load_cycles(config)[joint]
    ideal = four_bar_cycles(config, "massless-link")[joint]
    assert cycle.model == "contact-impact"
    assert cycle.extras["impacts"] == 0
    assert cycle.extras["free_flight_fraction"] == 0.0
    diff = np.hypot(cycle.force_x - ideal.force_x, cycle.force_y - ideal.force_y)
    # observed 0.012-0.019 % of the peak (the residue: O(c/l) geometry, damping)
    assert diff.max() < 1e-3 * ideal.load.max()
    assert cycle.extras["load_difference_max_n"] == pytest.approx(diff.max(), rel=1e-9)
    np.testing.assert_allclose(cycle.relative_rotation, ideal.relative_rotation, atol=1e-4)
    assert cycle.relative_rotation.sum() == pytest.approx(ideal.relative_rotation.sum(), abs=1e-6)


def test_contact_impact_needs_a_single_joint(example) -> None:
    config = example.replace({"dynamics.model": "contact-impact"})
    with pytest.raises(ConfigError, match="contact-impact models one clearance joint"):
        load_cycles(config)


@pytest.mark.parametrize("joint", ["crank-coupler", "rocker-ground"])
def test_energy_balance_of_the_free_pin(example, joint: str) -> None:
    # elastic, frictionless contact (c_e = 1, mu = 0) with impacts: the energy changes
    # by exactly the work of the crank torque and the rocker torque
    config = impact_config(
        example,
        joint,
        "coupler" if joint == "crank-coupler" else "rocker",
        **{
            "dynamics.restitution": 1.0,
            "joint.clearance": "0.2 mm",
            "mechanism.crank_speed": "600 rpm",
            "mechanism.rocker_torque": 0.0,
            "mechanism.rocker_spring_stiffness": 0.0,
            "materials.bushing.youngs_modulus": "2 GPa",
        },
    )
    solution = four_bar_contact_impact(config, compare=False)
    system = solution.system
    assert isinstance(system, FourBarContactSystem)
    history = solution.history
    duration = history.end_time
    times = np.linspace(0.0, duration, 801)
    states, _ = history.state(times)
    energy = np.array([system.energy(t, y) for t, y in zip(times, states, strict=True)])
    residue = energy - energy[0] - (states[:, 4] - states[0, 4])
    assert len(history.impact_times) >= 3
    work = np.abs(states[:, 4]).max()
    assert work > 0.05
    assert np.abs(residue).max() < 1e-5 * work
