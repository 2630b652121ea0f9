"""The four-bar's massless-link load cycles: the ideal-joint reactions in the bushing frame."""

from __future__ import annotations

import json
import warnings
from pathlib import Path

import numpy as np
import pytest

from jointwear.cli import main
from jointwear.config import load_config
from jointwear.mechanism.four_bar.dynamics import inverse_dynamics
from jointwear.mechanism.four_bar.geometry import FourBar
from jointwear.mechanism.four_bar.kinematics import FourBarMotion, four_bar_motion
from jointwear.mechanism.four_bar.massless_link import massless_link_cycles
from jointwear.mechanism.stage import mechanism_inputs

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "four_bar.toml"


# ------------------------------------------------------------------ load cycles


@pytest.fixture(scope="module")
def example():
    return load_config(EXAMPLE)


def motion_of(link: FourBar, phi: np.ndarray, omega: float) -> FourBarMotion:
    return four_bar_motion(phi, *link.lengths, omega, link.assembly)


def test_cycles_are_the_pin_force_in_the_bushing_frame(example) -> None:
    cycles = massless_link_cycles(mechanism_inputs(example))
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
    swapped = massless_link_cycles(mechanism_inputs(config))
    base = massless_link_cycles(mechanism_inputs(example))
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
        cycle = massless_link_cycles(mechanism_inputs(config))["coupler-rocker"]
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
