"""The finite-length bearing and Booker's mobility method against closed forms and limits."""

from __future__ import annotations

import numpy as np
import pytest

import jointwear.lubrication.mobility as mobility_module
from jointwear.lubrication import reynolds
from jointwear.lubrication.film import long_bearing_force, short_bearing_force, wedge_speed
from jointwear.lubrication.mobility import (
    film_force,
    finite_bearing_force,
    journal_centre_velocity,
    mobility,
)

RADIUS, CLEARANCE, VISCOSITY, SPEED = 0.01, 20e-6, 0.05, 100.0


@pytest.mark.parametrize("ratio", [0.25, 0.5, 1.0, 2.0])
def test_small_eccentricity_matches_the_linear_finite_length_solution(ratio):
    # for eps -> 0 the Reynolds equation of a bushing of any length has the closed-form
    # solution Pi = (1 - cosh(z/R) / cosh(L/2R)) sin(theta - beta); half of it is positive
    length, eps, ell = 2 * RADIUS * ratio, 1e-3, ratio
    rotation = finite_bearing_force(RADIUS, length, CLEARANCE, VISCOSITY, eps, 0.0, SPEED)
    closed = 6 * np.pi * VISCOSITY * RADIUS**4 * eps * SPEED * (ell - np.tanh(ell)) / CLEARANCE**2
    assert rotation.tangential == pytest.approx(closed, rel=1e-3)
    assert abs(rotation.radial) < 2e-3 * closed
    squeeze = finite_bearing_force(RADIUS, length, CLEARANCE, VISCOSITY, eps, 1.0, 0.0)
    closed = -12 * np.pi * VISCOSITY * RADIUS**4 * (ell - np.tanh(ell)) / CLEARANCE**2
    # the half film of a squeeze has a correction of order eps (2.5 eps for a short one)
    assert squeeze.radial == pytest.approx(closed, rel=5e-3)


def relative_errors(ratio, reference, eccentricities=(0.3, 0.6, 0.8)):
    length = 2 * RADIUS * ratio
    out = []
    for eps in eccentricities:
        finite = finite_bearing_force(RADIUS, length, CLEARANCE, VISCOSITY, eps, 0.0, SPEED)
        other = reference(RADIUS, length, CLEARANCE, VISCOSITY, eps, 0.0, SPEED)
        out.append(
            np.hypot(finite.radial, finite.tangential) / np.hypot(other.radial, other.tangential)
            - 1
        )
    return np.abs(out)


def test_short_bushings_tend_to_ocvirk():
    errors = [relative_errors(r, short_bearing_force).max() for r in (0.25, 0.1, 0.05)]
    assert errors[2] < 0.015
    assert errors[0] > errors[1] > errors[2]


def test_long_bushings_tend_to_sommerfeld():
    errors = [relative_errors(r, long_bearing_force).max() for r in (4.0, 8.0, 16.0)]
    assert errors[2] < 0.07
    assert errors[0] > errors[1] > errors[2]
    # the end leakage falls as D / L
    assert errors[0] / errors[2] == pytest.approx(4.0, rel=0.15)


def test_the_finite_difference_grid_is_converged(monkeypatch):
    directions = np.array([0.0, 0.7, np.pi / 2, 2.5])
    for eps in (0.5, 0.8, 0.95):
        coarse = mobility_module.tabulated_forces(eps, 1.0, directions)
        monkeypatch.setattr(reynolds, "ANGLE_NODES", 240)
        monkeypatch.setattr(reynolds, "AXIAL_CELLS", 32)
        fine = mobility_module.tabulated_forces(eps, 1.0, directions)
        monkeypatch.undo()
        size = np.hypot(*fine)
        assert np.max(np.abs(coarse - fine) / size) < 2e-3


def test_the_interpolated_table_matches_direct_solutions():
    rng = np.random.default_rng(1)
    eps, beta = rng.uniform(0, 0.99, 40), rng.uniform(-np.pi, np.pi, 40)
    table = mobility_module.dimensionless_finite(eps, beta, np.full(40, 1.0))
    # where the pin leaves the wall beyond eps = 0.9 the leaving table's finer grid
    inner = mobility_module.wall_direction(eps, beta)[0]
    leaving = (eps > mobility_module.LEAVING_START) & mobility_module.leaving_the_wall(inner)
    direct = np.array(
        [
            mobility_module.tabulated_forces(
                e,
                1.0,
                np.array([b]),
                *((mobility_module.WALL_GRID, mobility_module.leaving_crowding(e)) if on else ()),
            )[:, 0]
            for e, b, on in zip(eps, beta, leaving, strict=True)
        ]
    ).T
    assert np.any(leaving)
    assert np.max(np.abs(table - direct) / np.hypot(*direct)) < 5e-3


@pytest.mark.parametrize("ratio", [0.25, 0.5, 1.0])
def test_short_bearing_mobility_at_the_centre_is_bookers(ratio):
    # Booker (1965): a centred short bearing moves along the load with M = 1 / (pi (L/D)^2)
    vector = mobility(0.0, 0.0, ratio, "short")
    # (evaluated at eps = 1e-6, where the half film is off by 2.5 eps)
    assert vector.radial == pytest.approx(1 / (np.pi * ratio**2), rel=1e-5)
    assert abs(vector.tangential) < 1e-9 * vector.radial


def test_finite_mobility_tends_to_the_short_one():
    eps, angle = np.array([0.2, 0.5, 0.8]), np.array([0.3, 2.0, -1.2])
    short = mobility(eps, angle, 0.05, "short")
    finite = mobility(eps, angle, 0.05, "finite")
    np.testing.assert_allclose(
        np.hypot(finite.radial, finite.tangential),
        np.hypot(short.radial, short.tangential),
        rtol=0.02,
    )


@pytest.mark.parametrize("eps", [0.2, 0.5, 0.8])
def test_ocvirks_steady_equilibrium_does_not_move(eps):
    # a fixed load at Ocvirk's equilibrium: the mobility method must give a centre at rest
    length = 0.5 * 2 * RADIUS
    surface = RADIUS * SPEED
    load = (
        VISCOSITY
        * surface
        * length**3
        / (4 * CLEARANCE**2)
        * eps
        / (1 - eps**2) ** 2
        * np.sqrt(np.pi**2 * (1 - eps**2) + 16 * eps**2)
    )
    attitude = np.arctan(np.pi * np.sqrt(1 - eps**2) / (4 * eps))
    # load along -y, eccentricity at the attitude angle from it
    phi = -np.pi / 2 + attitude
    velocity = journal_centre_velocity(
        0.0, -load, phi, eps, RADIUS, length, CLEARANCE, VISCOSITY, SPEED, model="short"
    )
    assert abs(velocity.eccentricity_rate) < 1e-9 * SPEED
    assert abs(velocity.line_of_centres_speed) < 1e-9 * SPEED


@pytest.mark.parametrize("model", ["short", "long", "finite", "finite-reynolds"])
def test_the_velocity_of_the_mobility_method_balances_the_load(model):
    rng = np.random.default_rng(2)
    n = 60
    eps, phi = rng.uniform(0.05, 0.9, n), rng.uniform(-np.pi, np.pi, n)
    load_x, load_y = rng.normal(size=n) * 500, rng.normal(size=n) * 500
    pin, bushing = rng.uniform(-50, 50, n), rng.uniform(-10, 10, n)
    length = 0.02
    v = journal_centre_velocity(
        load_x, load_y, phi, eps, RADIUS, length, CLEARANCE, VISCOSITY, pin, bushing, model
    )
    wedge = wedge_speed(pin, bushing, v.line_of_centres_speed)
    force = film_force(model, RADIUS, length, CLEARANCE, VISCOSITY, eps, v.eccentricity_rate, wedge)
    fx = force.radial * np.cos(phi) - force.tangential * np.sin(phi)
    fy = force.radial * np.sin(phi) + force.tangential * np.cos(phi)
    np.testing.assert_allclose(
        np.hypot(fx + load_x, fy + load_y), 0.0, atol=1e-8 * np.hypot(load_x, load_y).max()
    )
    speed = np.hypot(v.velocity_x, v.velocity_y)
    np.testing.assert_allclose(
        speed, CLEARANCE * np.hypot(v.eccentricity_rate, eps * v.line_of_centres_speed), rtol=1e-12
    )
