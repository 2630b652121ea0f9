"""Hertz baseline (eqs. 1-3) against the textbook line-contact formulas."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from jointwear.contact import ContactParameters, effective_modulus, hertz, solve
from jointwear.errors import ContactError
from jointwear.geometry import BushingContour, Pin


def textbook(params: ContactParameters, load):
    """Half-width, peak pressure, K of eq. (2) and delta = (F/K)^(1/n), written out."""
    rp, rb, b = params.pin_radius, params.bushing_radius, params.axial_length
    sigma_p = (1 - params.pin_poisson_ratio**2) / (np.pi * params.pin_youngs_modulus)
    sigma_b = (1 - params.bushing_poisson_ratio**2) / (np.pi * params.bushing_youngs_modulus)
    e_star = 1 / (np.pi * (sigma_p + sigma_b))
    r_star = rp * rb / (rb - rp)
    k = 4 / (3 * np.pi * (sigma_p + sigma_b)) * np.sqrt(r_star)
    load = np.asarray(load, float)
    a = np.sqrt(4 * load * r_star / (np.pi * b * e_star))
    p0 = 2 * load / (np.pi * a * b)
    return a, p0, k, (load / k) ** (1 / params.exponent), e_star, r_star


def test_effective_modulus_is_pi_sigma(params):
    *_, e_star, _ = textbook(params, 1.0)
    assert params.effective_modulus == pytest.approx(e_star, rel=1e-14)
    assert effective_modulus(2e11, 0.3, 2e11, 0.3) == pytest.approx(2e11 / (2 * 0.91), rel=1e-15)


def test_stiffness_eq2(params):
    *_, k, _, _, _ = textbook(params, 1.0)
    got = hertz.stiffness(
        params.pin_radius,
        params.bushing_radius,
        params.pin_youngs_modulus,
        params.pin_poisson_ratio,
        params.bushing_youngs_modulus,
        params.bushing_poisson_ratio,
    )
    assert got == pytest.approx(k, rel=1e-14)
    # conformal: R* = R_p R_b / c ~ 1.12 m, far larger than either radius
    assert params.pin_radius * params.bushing_radius / 5e-5 == pytest.approx(1.11750, rel=1e-5)


def test_half_width_and_peak_pressure(params):
    load = np.array([1.0, 50.0, 200.0, 400.0])
    a, p0, *_, e_star, r_star = textbook(params, load)
    b = params.axial_length
    np.testing.assert_allclose(hertz.half_width(load, b, r_star, e_star), a, rtol=1e-14)
    np.testing.assert_allclose(hertz.peak_pressure(load, b, r_star, e_star), p0, rtol=1e-14)
    # the elliptical profile carries the load: int p0 sqrt(1 - x^2/a^2) dx * b = pi a p0 b / 2
    assert np.pi * a * p0 * b / 2 == pytest.approx(load, rel=1e-14, abs=0)
    assert hertz.peak_pressure(0.0, b, r_star, e_star) == 0.0
    x = np.linspace(-1.5, 1.5, 7) * a[2]
    profile = hertz.pressure_profile(x, a[2], p0[2])
    np.testing.assert_allclose(profile, p0[2] * np.sqrt(np.clip(1 - (x / a[2]) ** 2, 0, None)))
    assert profile[0] == profile[-1] == 0.0


def test_solution_matches_textbook_on_fine_grid(params, pin):
    contour = BushingContour.circle(params.bushing_radius, 7200, params.axial_length)
    load = np.array([10.0, 200.0, 400.0])
    sol = solve(contour, pin, load, np.zeros(3), "hertz", params)
    a, p0, _, delta, *_ = textbook(params, load)
    np.testing.assert_allclose(sol.penetration, delta, rtol=1e-14)
    np.testing.assert_allclose(sol.half_angle_left, a / params.bushing_radius, rtol=1e-14)
    np.testing.assert_allclose(sol.half_angle_right, a / params.bushing_radius, rtol=1e-14)
    clearance = params.bushing_radius - params.pin_radius
    np.testing.assert_allclose(sol.eccentricity[:, 0], clearance + delta, rtol=1e-14)
    # the discrete profile is rescaled to carry the load exactly; the projection (cos beta)
    # over a 38 deg arc lifts the peak above the flat-contact p0 by a few per cent
    ratio = sol.pressure.max(axis=1) / p0
    assert np.all(ratio > 1.0)
    assert np.all(ratio < 1.15)
    assert sol.model == "hertz"
    assert np.all(sol.iterations == 0)


def test_paper_joint_contact_is_not_small(params, pin, circle):
    """Hertz assumes a << R; in the conformal joint the arc at 200 N spans ~75 degrees."""
    sol = solve(circle, pin, [200.0], [0.0], "hertz", params)
    assert 35 < np.degrees(sol.half_angle_left[0]) < 40
    # for comparison, the exact-geometry Winkler contact at the same load: about 32 degrees
    winkler = solve(circle, pin, [200.0], [0.0], "asymmetric-winkler", params)
    assert 30 < np.degrees(winkler.half_angle_left[0]) < 34


@pytest.mark.parametrize("azimuth", [0.0, 0.3, np.radians(200.5), np.radians(-17.0), -1.0])
def test_discrete_resultant_equals_load(params, pin, circle, azimuth):
    load = np.array([0.0, 1e-3, 1.0, 200.0, 400.0, 5000.0])
    sol = solve(circle, pin, load, np.full(load.size, azimuth), "hertz", params)
    forces = sol.pressure * circle.spring_area
    bound = np.maximum(1e-12, 8 * np.finfo(float).eps * np.abs(forces).sum(axis=1))
    assert np.all(np.abs(sol.normal_force - load) <= bound)
    # symmetric profile on a circle: no sideways resultant when a node sits on the load line;
    # otherwise the sampled profile is lopsided by up to half a node (5e-4 of the load at
    # 200 N, 2e-3 at 1 N where only 3-4 nodes touch)
    on_node = np.isclose(np.mod(azimuth / circle.dtheta + 0.5, 1.0), 0.5, atol=1e-9)
    side = 1e-12 * np.maximum(load, 1) if on_node else 1e-2 * load
    assert np.all(np.abs(sol.tangential_force) <= side)
    assert np.all(sol.pressure >= 0)
    # an independent resultant along the load line
    phi = circle.theta - azimuth
    np.testing.assert_allclose(forces @ np.cos(phi), load, rtol=1e-12, atol=1e-15)


def test_contact_narrower_than_a_node_keeps_the_load(params, pin):
    contour = BushingContour.circle(params.bushing_radius, 36, params.axial_length)
    load = np.array([1e-6])
    azimuth = np.array([0.25 * contour.dtheta])  # between two nodes, a << node spacing
    sol = solve(contour, pin, load, azimuth, "hertz", params)
    assert np.count_nonzero(sol.pressure) == 2
    assert sol.normal_force[0] == pytest.approx(1e-6, rel=1e-12, abs=0)
    assert sol.half_angle_left[0] == 0.0
    # shared linearly: the nearer node carries three quarters of the weights
    assert sol.pressure[0, 0] / sol.pressure[0, 1] == pytest.approx(3.0, rel=1e-12)


def test_exponent_enters_penetration(params, pin, circle):
    other = dataclasses.replace(params, exponent=1.0)
    sol = solve(circle, pin, [200.0], [0.0], "hertz", other)
    *_, k, _, _, _ = textbook(params, 200.0)
    assert sol.penetration[0] == pytest.approx(200.0 / k, rel=1e-14, abs=0)


def test_through_the_wall_raises(params, pin, circle):
    with pytest.raises(ContactError, match="through the bushing wall"):
        solve(circle, pin, [200.0, 1e9], [0.0, 0.0], "hertz", params)
    # an explicit limit overrides the wall thickness
    with pytest.raises(ContactError):
        solve(circle, pin, [200.0], [0.0], "hertz", params, max_penetration=1e-6)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -1.0])
def test_bad_load_raises(params, pin, circle, bad):
    with pytest.raises(ContactError, match="load"):
        solve(circle, pin, [bad], [0.0], "hertz", params)


def test_pin_not_smaller_raises(params, circle):
    from jointwear.errors import GeometryError

    with pytest.raises(GeometryError):
        solve(circle, Pin(params.bushing_radius), [1.0], [0.0], "hertz", params)
