"""Film forces of the short and long journal bearing against closed forms and quadrature."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

from jointwear.lubrication.film import (
    FilmForce,
    long_bearing_force,
    min_film_thickness,
    short_bearing_force,
    sommerfeld_angle,
    to_xy,
    wedge_speed,
)

RADIUS, LENGTH, CLEARANCE, VISCOSITY = 0.01, 0.006, 25e-6, 0.04


def test_sommerfeld_angle_is_continuous_and_satisfies_its_definition():
    eps = 0.9
    theta = np.linspace(-3 * np.pi, 3 * np.pi, 2001)
    gamma = sommerfeld_angle(theta, eps)
    assert np.all(np.diff(gamma) > 0)
    expected_cos = (eps + np.cos(theta)) / (1 + eps * np.cos(theta))
    np.testing.assert_allclose(np.cos(gamma), expected_cos, atol=1e-12)
    np.testing.assert_allclose(
        sommerfeld_angle(np.pi * np.arange(-3, 4), eps), np.pi * np.arange(-3, 4)
    )


@pytest.mark.parametrize("eps", [0.05, 0.4, 0.8, 0.97])
def test_steady_short_bearing_is_ocvirks_closed_form(eps):
    speed = 120.0
    force = short_bearing_force(RADIUS, LENGTH, CLEARANCE, VISCOSITY, eps, 0.0, speed)
    surface = RADIUS * speed
    radial = -VISCOSITY * surface * LENGTH**3 * eps**2 / (CLEARANCE**2 * (1 - eps**2) ** 2)
    tangential = (
        np.pi * VISCOSITY * surface * LENGTH**3 * eps / (4 * CLEARANCE**2 * (1 - eps**2) ** 1.5)
    )
    np.testing.assert_allclose([force.radial, force.tangential], [radial, tangential], rtol=1e-12)


@pytest.mark.parametrize("eps", [0.05, 0.4, 0.8, 0.97])
def test_steady_long_bearing_is_the_half_sommerfeld_closed_form(eps):
    speed = 120.0
    force = long_bearing_force(RADIUS, LENGTH, CLEARANCE, VISCOSITY, eps, 0.0, speed)
    k = VISCOSITY * RADIUS * speed * RADIUS**2 * LENGTH / CLEARANCE**2
    radial = -12 * k * eps**2 / ((2 + eps**2) * (1 - eps**2))
    tangential = 6 * np.pi * k * eps / ((2 + eps**2) * np.sqrt(1 - eps**2))
    np.testing.assert_allclose([force.radial, force.tangential], [radial, tangential], rtol=1e-11)


def short_pressure(theta, eps, rate, wedge):
    """Positive part of Ocvirk's pressure integrated over the length, per R dtheta."""
    value = (wedge * eps * np.sin(theta) - 2 * rate * np.cos(theta)) / (
        1 + eps * np.cos(theta)
    ) ** 3
    return max(value, 0.0) * VISCOSITY * LENGTH**3 / (2 * CLEARANCE**2)


def long_pressure(theta, eps, rate, wedge):
    film = 1 + eps * np.cos(theta)
    rotation = wedge * eps * np.sin(theta) * (2 + eps * np.cos(theta)) / ((2 + eps**2) * film**2)
    squeeze = rate / eps * (1 / film**2 - 2 / (2 + 3 * eps**2))
    return max(rotation + squeeze, 0.0) * 6 * VISCOSITY * RADIUS**2 * LENGTH / CLEARANCE**2


@pytest.mark.parametrize(
    ("model", "pressure"),
    [(short_bearing_force, short_pressure), (long_bearing_force, long_pressure)],
)
@pytest.mark.parametrize(
    ("eps", "rate", "wedge"),
    [(0.5, 10.0, 100.0), (0.8, -30.0, 50.0), (0.3, 5.0, 0.0), (0.6, 0.0, -80.0), (0.9, 3.0, 20.0)],
)
def test_rotation_and_squeeze_together_match_quadrature_of_the_positive_pressure(
    model, pressure, eps, rate, wedge
):
    force = model(RADIUS, LENGTH, CLEARANCE, VISCOSITY, eps, rate, wedge)
    expected = [
        RADIUS
        * quad(lambda t, f=f: pressure(t, eps, rate, wedge) * f(t), 0, 2 * np.pi, limit=400)[0]
        for f in (np.cos, np.sin)
    ]
    scale = np.hypot(*expected)
    np.testing.assert_allclose([force.radial, force.tangential], expected, atol=1e-7 * scale)


@pytest.mark.parametrize("eps", [0.0, 0.2, 0.6, 0.9])
def test_pin_moving_straight_at_the_bushing_squeezes_the_half_film_facing_the_wall(eps):
    rate = 4.0  # deps/dt, towards the wall
    force = short_bearing_force(RADIUS, LENGTH, CLEARANCE, VISCOSITY, eps, rate, 0.0)
    # Guembel film pi/2 < theta < 3 pi/2: -(mu R L^3 deps/dt / c^2)(1 - eps^2)^-2.5
    # [(1 + 2 eps^2)(pi/2 + asin eps) + 3 eps sqrt(1 - eps^2)]
    bracket = (1 + 2 * eps**2) * (np.pi / 2 + np.arcsin(eps)) + 3 * eps * np.sqrt(1 - eps**2)
    closed = -VISCOSITY * RADIUS * LENGTH**3 * rate / CLEARANCE**2 * bracket / (1 - eps**2) ** 2.5
    assert force.radial == pytest.approx(closed, rel=1e-12, abs=0)
    assert abs(force.tangential) < 1e-12 * abs(closed)


def test_squeeze_of_the_long_bearing_pushes_back_along_the_line_of_centres_only():
    rates = np.array([-3.0, 3.0])
    force = long_bearing_force(RADIUS, LENGTH, CLEARANCE, VISCOSITY, 0.5, rates, 0.0)
    assert force.radial[1] < 0 < force.radial[0]
    np.testing.assert_allclose(force.tangential, 0.0, atol=1e-12 * np.abs(force.radial).max())


def test_mirror_image_reverses_the_tangential_force_and_viscosity_scales_it():
    # turning the other way is the mirror image about the line of centres
    args = (RADIUS, LENGTH, CLEARANCE)
    for model in (short_bearing_force, long_bearing_force):
        base = model(*args, VISCOSITY, 0.6, 2.0, 90.0)
        mirrored = model(*args, VISCOSITY, 0.6, 2.0, -90.0)
        thicker = model(*args, 3 * VISCOSITY, 0.6, 2.0, 90.0)
        assert mirrored.radial == pytest.approx(float(base.radial), rel=1e-10)
        assert mirrored.tangential == pytest.approx(-float(base.tangential), rel=1e-10)
        np.testing.assert_allclose(
            [thicker.radial, thicker.tangential], [3 * base.radial, 3 * base.tangential], rtol=1e-12
        )


def test_a_pin_whirling_at_half_the_surface_speed_carries_no_load():
    whirl = wedge_speed(pin_speed=100.0, bushing_speed=20.0, line_of_centres_speed=60.0)
    assert whirl == 0.0
    force = short_bearing_force(RADIUS, LENGTH, CLEARANCE, VISCOSITY, 0.5, 0.0, whirl)
    assert force.radial == 0.0
    assert force.tangential == 0.0


def test_rotation_to_xy_keeps_the_magnitude_and_turns_by_the_line_of_centres():
    force = FilmForce(np.array(-3.0), np.array(4.0))
    fx, fy = to_xy(force, np.pi / 2)
    np.testing.assert_allclose([fx, fy], [-4.0, -3.0], atol=1e-12)
    assert np.hypot(fx, fy) == pytest.approx(5.0)


def test_min_film_thickness():
    np.testing.assert_allclose(min_film_thickness(20e-6, [0.0, 0.5, 1.0]), [20e-6, 10e-6, 0.0])


def test_forces_are_vectorised_over_states():
    rng = np.random.default_rng(3)
    eps, rate, wedge = rng.uniform(0, 0.95, 200), rng.normal(0, 5, 200), rng.normal(0, 100, 200)
    for model in (short_bearing_force, long_bearing_force):
        together = model(RADIUS, LENGTH, CLEARANCE, VISCOSITY, eps, rate, wedge)
        one = model(RADIUS, LENGTH, CLEARANCE, VISCOSITY, eps[17], rate[17], wedge[17])
        assert together.radial.shape == (200,)
        assert together.radial[17] == pytest.approx(float(one.radial), rel=1e-12)
