"""Inverse dynamics of the slider-crank (eq. 11): statics by hand, omega^2 scaling, the spring.

The static part of the joint force and crank torque is the hand statics of slider,
rod and crank; what is not static grows with omega^2 componentwise; the spring has
its preload at a dead centre and the stated sense.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.errors import MechanismError
from jointwear.mechanism.slider_crank.dynamics import SliderCrank, inverse_dynamics, spring_force
from jointwear.mechanism.slider_crank.kinematics import (
    crank_angle_grid,
    ideal_motion,
    slider_position,
)

RPM = 2.0 * math.pi / 60.0
L1, L2 = 0.07, 0.2


def mechanism(config: Config, **changes: object) -> SliderCrank:
    data = {**SliderCrank.from_config(config.mechanism).__dict__, **changes}
    return SliderCrank(**data)


def test_statics_and_omega_squared_scaling(paper_config: Config) -> None:
    mech = mechanism(paper_config)
    phi = crank_angle_grid(360)
    omega = 120 * RPM

    def reaction(speed: float) -> np.ndarray:
        return np.array(inverse_dynamics(ideal_motion(phi, L1, L2, speed), mech))

    # static part: same positions, no velocity or acceleration
    motion = ideal_motion(phi, L1, L2, omega)
    still = motion._replace(
        crank_speed=0.0,
        rod_angular_velocity=0 * phi,
        rod_angular_acceleration=0 * phi,
        slider_velocity=0 * phi,
        slider_acceleration=0 * phi,
    )
    static = np.array(inverse_dynamics(still, mech))
    # statics by hand: slider x balance, rod moments about B, crank moments about A
    spring = spring_force(
        motion.slider_position, L1, L2, mech.spring_stiffness, mech.spring_preload, "pull"
    )
    theta = motion.rod_angle
    j_x = -spring
    j_y = np.tan(theta) * j_x - 0.5 * mech.rod_mass * mech.gravity
    b_x, b_y = L1 * np.cos(phi), L1 * np.sin(phi)
    torque = (
        b_x * (j_y + mech.rod_mass * mech.gravity)
        - b_y * j_x
        + 0.5 * mech.crank_mass * mech.gravity * b_x
    )
    np.testing.assert_allclose(static, [j_x, j_y, torque], rtol=1e-12, atol=1e-12)

    # what is not static is inertial and grows with omega^2, componentwise
    single, double = reaction(omega) - static, reaction(2 * omega) - static
    np.testing.assert_allclose(double, 4.0 * single, rtol=0, atol=1e-11 * np.abs(double).max())
    assert np.abs(single).max() > 10.0  # the inertial part is not negligible


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


def test_mechanism_that_cannot_assemble() -> None:
    with pytest.raises(MechanismError, match="crank_length"):
        SliderCrank(
            crank_length=0.3,
            rod_length=0.2,
            crank_mass=1,
            rod_mass=1,
            slider_mass=1,
            rod_inertia=0.1,
            spring_stiffness=0,
            spring_preload=0,
        )
