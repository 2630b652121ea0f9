"""Steady load shared by film and asperities: equilibria against closed forms and limits."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.errors import ConfigError
from jointwear.lubrication.asperity import journal_asperity_force
from jointwear.lubrication.mixed import steady_load_sharing

RADIUS, CLEARANCE, VISCOSITY, SPEED = 0.01, 20e-6, 0.05, 100.0
STEEL = 115e9  # E* of steel on steel [Pa]
SMOOTH = 1e-12  # a roughness that leaves no asperity in contact [m]


def ocvirk(eps, length):
    surface = RADIUS * SPEED
    load = VISCOSITY * surface * length**3 / (4 * CLEARANCE**2) * eps / (1 - eps**2) ** 2
    load = load * np.sqrt(np.pi**2 * (1 - eps**2) + 16 * eps**2)
    return load, np.arctan(np.pi * np.sqrt(1 - eps**2) / (4 * eps))


def sommerfeld(eps, length):
    k = 6 * VISCOSITY * RADIUS * SPEED * RADIUS**2 * length / CLEARANCE**2
    load = k * eps / ((2 + eps**2) * (1 - eps**2)) * np.sqrt(np.pi**2 * (1 - eps**2) + 4 * eps**2)
    return load, np.arctan(np.pi * np.sqrt(1 - eps**2) / (2 * eps))


@pytest.mark.parametrize(("model", "closed"), [("short", ocvirk), ("long", sommerfeld)])
def test_steady_load_on_a_turning_journal_is_the_closed_form_equilibrium(model, closed):
    eps = np.array([0.1, 0.3, 0.5, 0.7, 0.9])
    length = 0.01
    load, attitude = closed(eps, length)
    state = steady_load_sharing(
        load, RADIUS, length, CLEARANCE, VISCOSITY, SPEED, SMOOTH, STEEL, model=model
    )
    np.testing.assert_allclose(state.eccentricity_ratio, eps, rtol=0.01)
    np.testing.assert_allclose(state.attitude_angle, attitude, rtol=0.01)
    np.testing.assert_allclose(state.asperity_load_fraction, 0.0, atol=1e-12)
    np.testing.assert_allclose(state.min_film_thickness, CLEARANCE * (1 - eps), rtol=0.05)


def test_short_finite_bushing_has_ocvirks_equilibrium():
    eps = np.array([0.3, 0.6, 0.8])
    length = 0.05 * 2 * RADIUS
    load, attitude = ocvirk(eps, length)
    state = steady_load_sharing(
        load, RADIUS, length, CLEARANCE, VISCOSITY, SPEED, SMOOTH, STEEL, model="finite"
    )
    np.testing.assert_allclose(state.eccentricity_ratio, eps, rtol=0.01)
    np.testing.assert_allclose(state.attitude_angle, attitude, rtol=0.02)


@pytest.mark.parametrize(
    ("model", "tolerance"), [("short", 1e-9), ("long", 1e-9), ("finite", 1e-5)]
)
def test_turning_the_other_way_mirrors_the_attitude(model, tolerance):
    # exact for the closed forms; the finite table is mirror-symmetric to its interpolation
    args = (RADIUS, 0.01, CLEARANCE, VISCOSITY)
    forward = steady_load_sharing(300.0, *args, SPEED, SMOOTH, STEEL, model=model)
    backward = steady_load_sharing(300.0, *args, -SPEED, SMOOTH, STEEL, model=model)
    assert backward.eccentricity_ratio == pytest.approx(
        float(forward.eccentricity_ratio), rel=tolerance
    )
    assert backward.attitude_angle == pytest.approx(-float(forward.attitude_angle), rel=tolerance)


def test_a_thick_film_leaves_the_asperities_almost_nothing():
    roughness, length = 0.3e-6, 0.02
    load = ocvirk(1 - 3.5 * roughness / CLEARANCE, length)[0]  # lambda = 3.5 on film alone
    state = steady_load_sharing(
        load,
        RADIUS,
        length,
        CLEARANCE,
        VISCOSITY,
        SPEED,
        roughness,
        STEEL,
        model="short",
        exact=True,
    )
    assert 3.0 < state.film_parameter < 4.0
    assert state.regime == "hydrodynamic"
    assert 0.0 < state.asperity_load_fraction < 0.01


def test_as_the_viscosity_vanishes_the_asperities_carry_the_whole_load():
    roughness, length, load = 0.5e-6, 0.02, 100.0
    capacity = -journal_asperity_force(RADIUS, length, CLEARANCE, 1.0, roughness, STEEL)
    assert load < capacity
    viscosities = np.array([0.05, 1e-3, 1e-4, 1e-5, 1e-7, 0.0])
    state = steady_load_sharing(
        load, RADIUS, length, CLEARANCE, viscosities, SPEED, roughness, STEEL, model="finite"
    )
    share = state.asperity_load_fraction
    assert np.all(np.diff(share) > 0)
    assert share[0] < 0.01
    assert share[-2] > 0.99
    assert share[-1] == pytest.approx(1.0, abs=1e-9)
    assert not np.any(state.bulk_contact)
    assert np.all(np.diff(state.film_parameter) < 0)
    assert state.regime[0] == "hydrodynamic"
    assert state.regime[-1] != "hydrodynamic"


def test_beyond_the_asperity_capacity_without_film_the_bulk_takes_over():
    roughness, length = 0.5e-6, 0.02
    capacity = -journal_asperity_force(RADIUS, length, CLEARANCE, 1.0, roughness, STEEL)
    state = steady_load_sharing(
        np.array([0.5, 2.0]) * capacity, RADIUS, length, CLEARANCE, 0.0, SPEED, roughness, STEEL
    )
    assert list(state.bulk_contact) == [False, True]


def test_the_asperity_pressure_over_the_bushing_carries_the_asperity_load():
    roughness, length, load = 0.5e-6, 0.02, 200.0
    angles = np.linspace(0, 2 * np.pi, 3600, endpoint=False)
    direction = 1.0
    state = steady_load_sharing(
        load,
        RADIUS,
        length,
        CLEARANCE,
        1e-4,
        SPEED,
        roughness,
        STEEL,
        load_direction=direction,
        bushing_angles=angles,
    )
    pressure = state.asperity_pressure
    centre = direction + state.attitude_angle
    # the peak faces the pin's eccentricity
    peak = angles[np.argmax(pressure)]
    assert abs(np.angle(np.exp(1j * (peak - centre)))) < 2 * np.pi / 3600 + 1e-12
    carried = RADIUS * length * np.sum(pressure * np.cos(angles - centre)) * (2 * np.pi / 3600)
    assert carried == pytest.approx(float(state.asperity_load), rel=1e-3)


def test_thousands_of_states_in_one_call():
    loads = np.linspace(50.0, 3000.0, 2000)
    state = steady_load_sharing(loads, RADIUS, 0.02, CLEARANCE, 1e-3, SPEED, 0.4e-6, STEEL)
    assert state.eccentricity_ratio.shape == (2000,)
    assert np.all(np.diff(state.eccentricity_ratio) > 0)
    assert state.asperity_pressure.shape == (2000, 360)


def test_an_unknown_film_model_is_refused_with_the_closest_name():
    with pytest.raises(ConfigError, match="did you mean 'finite'"):
        steady_load_sharing(
            1.0, RADIUS, 0.01, CLEARANCE, VISCOSITY, SPEED, SMOOTH, STEEL, model="finit"
        )
