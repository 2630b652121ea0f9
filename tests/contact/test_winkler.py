"""Winkler foundation on a circular bushing against its closed-form integral (eqs. 4-5)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from jointwear.contact import ContactParameters, contact_law, solve, winkler
from jointwear.errors import ConfigError
from jointwear.geometry import BushingContour, Pin


def stiffness(params: ContactParameters) -> float:
    """Foundation stiffness k = E_w / L [Pa/m]."""
    modulus = winkler.foundation_modulus(
        params.bushing_youngs_modulus, params.bushing_poisson_ratio, params.foundation_modulus
    )
    return modulus / params.bushing_thickness


def closed_form(params, s, curvature=True):
    c = params.bushing_radius - params.pin_radius
    return winkler.circle_force(
        s - c,
        c,
        params.bushing_radius,
        params.axial_length,
        stiffness(params),
        pin_radius=params.pin_radius if curvature else None,
    )


def test_stiffness_of_the_paper_joint(params):
    # E = 500 MPa PTFE over a 2.5 mm wall
    assert stiffness(params) == pytest.approx(2e11, rel=1e-15)
    law = contact_law("winkler", params)
    assert law.coefficient == pytest.approx(2e11, rel=1e-15)
    assert law.exponent == 1.0


@pytest.mark.parametrize("model", ["winkler", "asymmetric-winkler"])
def test_numerical_balance_converges_to_the_closed_form(params, pin, clearance, model):
    load = 200.0
    errors, angle_errors, old_offsets = [], [], []
    for nodes in (360, 3600, 36000):
        contour = BushingContour.circle(params.bushing_radius, nodes, params.axial_length)
        sol = solve(contour, pin, [load], [0.0], model, params)
        s = sol.eccentricity[0, 0]
        assert sol.eccentricity[0, 1] == 0.0
        assert sol.penetration[0] == pytest.approx(s - clearance, rel=1e-12, abs=0)
        force, alpha = closed_form(params, s)
        errors.append(abs(force[()] / load - 1))
        angle_errors.append(abs(sol.half_angle_left[0] - alpha[()]))
        assert sol.half_angle_left[0] == pytest.approx(sol.half_angle_right[0], rel=1e-12, abs=0)
        old, _ = closed_form(params, s, curvature=False)
        old_offsets.append(old[()] / load - 1)
    # the node sum is a quadrature of a function with a kink at the contact edge: O(h^2)
    assert errors[0] > errors[1] > errors[2]
    assert errors[0] < 1e-3
    assert errors[2] <= 1e-4
    assert errors[1] / errors[0] < 0.05  # (1/10)^2 = 0.01 expected
    assert angle_errors[0] > angle_errors[2]
    assert angle_errors[2] < 1e-5  # rad; the half-angle is interpolated between nodes
    # the first-order closed form misses the pin-curvature term: ~0.36 % too stiff here
    for offset in old_offsets:
        assert 1e-3 < offset < 1e-2


def test_closed_form_against_direct_quadrature_of_exact_penetration(params, pin, clearance):
    """Independent of the balance: integrate k * delta * cos(phi) * R dphi * b on a fine grid."""
    nodes = 200_000
    contour = BushingContour.circle(params.bushing_radius, nodes, params.axial_length)
    phi = np.angle(np.exp(1j * contour.theta))
    for approach in (1e-7, 2e-6, 9.2e-6, 4e-5, 3e-4):
        s = clearance + approach
        delta = contour.penetration(pin, [s, 0.0])
        integral = np.sum(stiffness(params) * delta * np.cos(phi) * contour.spring_area)
        force, alpha = closed_form(params, s)
        # quadrature error ~1e-9; expansion error O((s / R_p)^2) relative
        assert force[()] == pytest.approx(integral, rel=1e-6 + 0.01 * (s / params.pin_radius) ** 2)
        edge = np.max(np.abs(phi[delta > 0]))
        assert alpha[()] == pytest.approx(edge, abs=2 * contour.dtheta)


def test_closed_form_limits(params, clearance):
    k, r, b = stiffness(params), params.bushing_radius, params.axial_length
    # no force before contact, both variants
    for rp in (None, params.pin_radius):
        f, a = winkler.circle_force([-1e-6, 0.0], clearance, r, b, k, pin_radius=rp)
        np.testing.assert_array_equal(f, 0.0)
        np.testing.assert_array_equal(a, 0.0)
    # a huge pin radius has no curvature term: back to the first-order form
    approach = np.array([1e-7, 1e-6, 1e-5, 1e-4])
    old = winkler.circle_force(approach, clearance, r, b, k)
    flat = winkler.circle_force(approach, clearance, r, b, k, pin_radius=1e9)
    np.testing.assert_allclose(flat[0], old[0], rtol=1e-9)
    np.testing.assert_allclose(flat[1], old[1], rtol=1e-9)
    # small approach d: delta ~ d - q phi^2 with q = s/2 + kappa, so F ~ (4/3) k b R d^1.5 / sqrt(q)
    d = 1e-9
    s = clearance + d
    q = s / 2 + s**2 / (2 * params.pin_radius)
    f, _ = winkler.circle_force(d, clearance, r, b, k, pin_radius=params.pin_radius)
    assert f[()] == pytest.approx(k * b * r * 4 / 3 * d**1.5 / np.sqrt(q), rel=1e-4)


def test_force_increases_with_approach(params, clearance):
    approach = np.geomspace(1e-9, 1e-3, 200)
    r, c = params.bushing_radius, clearance
    for rp in (None, params.pin_radius):
        f, a = winkler.circle_force(
            approach, c, r, params.axial_length, stiffness(params), pin_radius=rp
        )
        assert np.all(np.diff(f) > 0)
        assert np.all(a < np.pi / 2)
    # first order: cos(alpha) = c / s, the contact only widens
    assert np.all(np.diff(winkler.circle_force(approach, c, r, 1.0, 1.0)[1]) > 0)


def test_contact_angle_with_curvature_matches_circle_intersection(params, clearance):
    """Exact edge: |x| = R and |x - s e_x| = R_p give cos(alpha) = (c (2R - c) + s^2) / (2 s R).

    The exact half-angle is not monotone in s: it is widest, arccos(sqrt(c(2R-c))/R) ~ 83 deg,
    at s = sqrt(c (2R - c)) ~ 0.87 mm, and narrows beyond. The second-order form follows it.
    """
    r, c, rp = params.bushing_radius, clearance, params.pin_radius
    approach = np.geomspace(1e-9, 1.5e-3, 400)
    s = c + approach
    _, alpha = winkler.circle_force(approach, c, r, 1.0, 1.0, pin_radius=rp)
    exact = np.arccos((c * (2 * r - c) + s**2) / (2 * s * r))
    # the neglected terms are O(s^4 / R_p^3) in delta: ~0.12 (s / R_p)^3 in the angle
    assert np.all(np.abs(alpha - exact) <= 0.2 * (s / rp) ** 3 + 1e-12)
    turn = np.sqrt(c * (2 * r - c))
    assert np.all(np.diff(alpha[s < 0.95 * turn]) > 0)
    assert np.all(np.diff(alpha[s > 1.05 * turn]) < 0)
    assert np.degrees(alpha.max()) == pytest.approx(np.degrees(np.arccos(turn / r)), abs=0.05)


def test_pressure_function():
    p = winkler.pressure([-1e-6, 0.0, 2e-6], 5e8, 2.5e-3)
    np.testing.assert_allclose(p, [0.0, 0.0, 4e5])


def test_constrained_modulus_option(params, pin):
    e, nu = params.bushing_youngs_modulus, params.bushing_poisson_ratio
    expected = e * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    assert winkler.foundation_modulus(e, nu, "constrained") == pytest.approx(expected, rel=1e-15)
    assert expected / e == pytest.approx(0.62 / (1.38 * 0.24), rel=1e-14, abs=0)  # 1.872 for PTFE
    assert winkler.foundation_modulus(e, nu, "youngs") == e
    assert winkler.foundation_modulus(e, 0.0, "constrained") == e  # no Poisson effect
    with pytest.raises(ConfigError, match="foundation_modulus"):
        winkler.foundation_modulus(e, nu, "oedometric")
    # an incompressible layer has none (1 - 2 nu = 0): refused, not infinite or negative
    for incompressible in (0.5, 0.6):
        with pytest.raises(ConfigError, match=r"^contact\.foundation_modulus: .*below 0\.5"):
            winkler.foundation_modulus(e, incompressible, "constrained")
    assert winkler.foundation_modulus(e, 0.6, "youngs") == e

    stiff = dataclasses.replace(params, foundation_modulus="constrained")
    assert contact_law("asymmetric-winkler", stiff).coefficient == pytest.approx(
        expected / params.bushing_thickness, rel=1e-15
    )
    contour = BushingContour.circle(params.bushing_radius, 3600, params.axial_length)
    soft = solve(contour, pin, [200.0], [0.0], "winkler", params)
    hard = solve(contour, pin, [200.0], [0.0], "winkler", stiff)
    assert hard.penetration[0] < soft.penetration[0]
    force, _ = closed_form(stiff, hard.eccentricity[0, 0])
    assert force[()] == pytest.approx(200.0, rel=1e-5)


def test_constrained_modulus_from_config(paper_config):
    cfg = paper_config.replace({"contact.foundation_modulus": "constrained"})
    law = contact_law("winkler", ContactParameters.from_config(cfg))
    assert law.coefficient == pytest.approx(5e8 * 0.62 / (1.38 * 0.24) / 2.5e-3, rel=1e-14)


def test_winkler_pressure_is_linear_in_node_penetration(params, pin, circle):
    sol = solve(circle, pin, [200.0], [0.0], "asymmetric-winkler", params)
    delta = circle.penetration(pin, sol.eccentricity[0])
    np.testing.assert_allclose(
        sol.pressure[0], stiffness(params) * delta, rtol=1e-12, atol=1e-9 * sol.pressure.max()
    )
    # the Winkler laws are not mesh dependent: halving the spacing barely changes the answer
    fine = BushingContour.circle(params.bushing_radius, 720, params.axial_length)
    sol2 = solve(fine, Pin(params.pin_radius), [200.0], [0.0], "asymmetric-winkler", params)
    assert sol2.penetration[0] == pytest.approx(sol.penetration[0], rel=1e-3)


# ---------------------------------------------------------------- spread factor
def test_spread_factor_closed_form_and_its_small_arc_series() -> None:
    alpha = np.array([1e-3, 0.0299, 0.0301, 0.3, 0.7, np.pi / 2])
    kappa = winkler.spread_factor(alpha)
    # pi/2: p ~ cos(phi) over a half circle, sum|p| / sum p cos = 2 / (pi/2) = 4 / pi
    assert kappa[-1] == pytest.approx(4 / np.pi, rel=1e-14, abs=0)
    # small arcs: 1 + alpha^2/10 + 19 alpha^4/4200, continuous across the switch
    assert kappa[0] - 1 == pytest.approx(1e-7 + 19e-12 / 4200, rel=1e-9, abs=0)
    assert kappa[2] - kappa[1] == pytest.approx(0.2 * 0.03 * 2e-4, rel=1e-3)
    assert np.all(np.diff(kappa) > 0)


@pytest.mark.parametrize("load", [50.0, 200.0, 1000.0])
def test_springs_push_harder_than_the_load_by_the_spread_factor(params, pin, load) -> None:
    # what Archard's law wears is the sum of the spring forces, not the load: on a circle
    # the two differ by kappa(alpha), a pure function of the contact half-angle
    contour = BushingContour.circle(params.bushing_radius, 7200, params.axial_length)
    sol = solve(contour, pin, [load], [0.3], "winkler", params)
    law = contact_law("winkler", params)
    spring_sum = sol.pressure[0].sum() * contour.dtheta * contour.axial_length * contour.radius[0]
    assert law.exponent == 1.0
    alpha = sol.half_angle_left[0]
    # the pin's curvature (s^2 sin^2 / 2 R_p, dropped by kappa's kinematics) is the main error
    assert spring_sum / load == pytest.approx(winkler.spread_factor(alpha), rel=2e-4)
    assert spring_sum / load > 1.0


def test_spread_factor_falls_with_clearance_at_a_fixed_load(params) -> None:
    # why the wear mass per revolution falls when only the clearance grows (report T3, T9)
    ratios = []
    for clearance in (0.05e-3, 0.1e-3, 0.2e-3, 0.4e-3):
        p = dataclasses.replace(params, bushing_radius=params.pin_radius + clearance)
        contour = BushingContour.circle(p.bushing_radius, 3600, p.axial_length)
        sol = solve(contour, Pin(p.pin_radius), [250.0], [0.0], "winkler", p)
        area = contour.dtheta * contour.axial_length * contour.radius[0]
        ratios.append(sol.pressure[0].sum() * area / 250.0)
    assert np.all(np.diff(ratios) < 0)
    # 0.05 mm: a +-35 deg arc springs ~3.7 % harder than the load; 0.4 mm: under 1 %
    assert ratios[0] > 1.03
    assert ratios[-1] < 1.01
