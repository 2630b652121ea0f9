"""Kinematics of the slider-crank: closed forms against dead-centre values and spectral derivatives.

The closed-form rod angle, slider position and their time derivatives are checked
against the known dead-centre accelerations, the loop closure and the spectral
derivatives of the positions (exact for the band-limited motion).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.mechanism.slider_crank.kinematics import (
    crank_angle_grid,
    rod_angle,
    rod_angular_acceleration,
    rod_angular_velocity,
    slider_acceleration,
    slider_position,
    slider_velocity,
    spectral_derivative,
)

RPM = 2.0 * math.pi / 60.0
L1, L2 = 0.07, 0.2


# ---------------------------------------------------------------- kinematics


@pytest.mark.parametrize("omega", [120 * RPM, 240 * RPM])
def test_dead_centre_slider_acceleration(omega: float) -> None:
    ratio = L1 / L2
    acc = slider_acceleration([0.0, math.pi], L1, L2, omega)
    assert acc[0] == pytest.approx(-L1 * omega**2 * (1 + ratio), rel=1e-14, abs=0)
    assert acc[1] == pytest.approx(L1 * omega**2 * (1 - ratio), rel=1e-14, abs=0)
    assert slider_position([0.0, math.pi], L1, L2) == pytest.approx(
        [L1 + L2, L2 - L1], rel=1e-15, abs=0
    )
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
        spectral_derivative(signal, omega, 1, max_harmonic=4),
        omega * np.cos(omega * t),
        atol=1e-12,
    )
