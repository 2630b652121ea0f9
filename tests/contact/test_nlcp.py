"""NLCP (eq. 7): stiffness, the paper form's mesh dependence, the mesh-independent variant."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from jointwear.contact import contact_law, nlcp, solve
from jointwear.geometry import BushingContour, Pin


@pytest.fixture(scope="module")
def independent(params):
    return dataclasses.replace(params, nlcp_variant="mesh-independent")


def contour(params, nodes):
    return BushingContour.circle(params.bushing_radius, nodes, params.axial_length)


def test_stiffness_is_cylinder_on_plane(params):
    """Eq. (2) with R_j -> inf: K = 4/(3 pi (sigma_i + sigma_j)) sqrt(R_i) = 4/3 E* sqrt(R_p)."""
    sigma_p = (1 - params.pin_poisson_ratio**2) / (np.pi * params.pin_youngs_modulus)
    sigma_b = (1 - params.bushing_poisson_ratio**2) / (np.pi * params.bushing_youngs_modulus)
    expected = 4 / (3 * np.pi * (sigma_p + sigma_b)) * np.sqrt(params.pin_radius)
    k = nlcp.stiffness(
        params.pin_radius,
        params.pin_youngs_modulus,
        params.pin_poisson_ratio,
        params.bushing_youngs_modulus,
        params.bushing_poisson_ratio,
    )
    assert k == pytest.approx(expected, rel=1e-14)
    assert k == pytest.approx(
        4 / 3 * params.effective_modulus * np.sqrt(params.pin_radius), rel=1e-14
    )
    assert k == pytest.approx(6.71e7, rel=1e-2)  # PTFE on steel, R_p = 7.45 mm [N/m^1.5]


def test_spring_law_and_pressure(params, independent):
    k = nlcp.stiffness(
        params.pin_radius,
        params.pin_youngs_modulus,
        params.pin_poisson_ratio,
        params.bushing_youngs_modulus,
        params.bushing_poisson_ratio,
    )
    area = params.bushing_radius * np.radians(1.0) * params.axial_length  # 1 degree spring
    assert params.spring_area == pytest.approx(area, rel=1e-15, abs=0)
    law = contact_law("nlcp", params)
    assert law.exponent == 1.5
    assert law.coefficient == pytest.approx(k / area, rel=1e-15)
    assert law.force_area == params.spring_area  # the paper: force K delta^n per spring
    assert contact_law("nlcp", independent).force_area is None  # integrated over r dtheta b
    delta = np.array([-1e-6, 0.0, 1e-6, 4e-6])
    np.testing.assert_allclose(
        nlcp.pressure(delta, k, 1.5, area), k * np.maximum(delta, 0) ** 1.5 / area
    )
    np.testing.assert_allclose(
        law.pressure(np.maximum(delta, 0)), nlcp.pressure(delta, k, 1.5, area), rtol=1e-15
    )


def test_paper_form_force_per_spring_is_k_delta_n(params, pin, circle):
    """p_j A = K delta_j^n (eq. 7): the spring force does not depend on the node spacing."""
    sol = solve(circle, pin, [200.0], [0.0], "nlcp", params)
    k = nlcp.stiffness(
        params.pin_radius,
        params.pin_youngs_modulus,
        params.pin_poisson_ratio,
        params.bushing_youngs_modulus,
        params.bushing_poisson_ratio,
    )
    delta = circle.penetration(pin, sol.eccentricity[0])
    spring_force = sol.pressure[0] * params.spring_area
    np.testing.assert_allclose(
        spring_force, k * delta**1.5, rtol=1e-12, atol=1e-12 * spring_force.max()
    )
    assert spring_force @ np.cos(circle.theta) == pytest.approx(200.0, abs=1e-12)


def test_paper_form_stiffens_as_the_mesh_is_refined(params, pin):
    """Doubling N doubles the number of springs K delta^n in the arc, so the joint is twice as
    stiff. With F ~ delta^m locally (m between 1.5 for delta >> c and 2 for delta << c; m ~ 1.83
    at 200 N in the paper's joint), the penetration for a fixed load falls by 2^(-1/m) ~ 0.69.
    """
    loads = np.array([50.0, 200.0, 400.0])
    coarse = solve(contour(params, 360), pin, loads, np.zeros(3), "nlcp", params)
    fine = solve(contour(params, 720), pin, loads, np.zeros(3), "nlcp", params)
    ratio = fine.penetration / coarse.penetration
    assert np.all(ratio > 2 ** (-1 / 1.5))  # 0.63
    assert np.all(ratio < 2 ** (-1 / 2.0))  # 0.71
    assert ratio[1] == pytest.approx(0.690, abs=0.005)
    # the local exponent m from the 200 N -> 400 N step at N = 360 predicts the factor
    m = np.log(2.0) / np.log(coarse.penetration[2] / coarse.penetration[1])
    assert 1.5 < m < 2.0
    assert ratio[1] == pytest.approx(2 ** (-1 / m), rel=0.02)
    # narrower contact, lower peak pressure
    assert np.all(fine.half_angle_left < coarse.half_angle_left)
    assert np.all(fine.pressure.max(axis=1) < 0.7 * coarse.pressure.max(axis=1))
    # and it keeps going: 36000 nodes give a tenth of the 1 degree penetration at 200 N
    finest = solve(contour(params, 36000), pin, [200.0], [0.0], "nlcp", params)
    assert finest.penetration[0] < 0.1 * coarse.penetration[1]


def test_paper_form_is_the_independent_form_with_load_scaled_by_spacing(params, independent, pin):
    """Paper at N nodes == mesh-independent at N nodes carrying F * 360 / N (exact scaling)."""
    for nodes in (720, 1440):
        paper = solve(contour(params, nodes), pin, [200.0], [0.0], "nlcp", params)
        scaled = solve(
            contour(params, nodes), pin, [200.0 * 360 / nodes], [0.0], "nlcp", independent
        )
        assert paper.penetration[0] == pytest.approx(scaled.penetration[0], rel=1e-10, abs=0)
        # same penetration, same pressure law p = K delta^n / A: same pressure
        np.testing.assert_allclose(
            paper.pressure, scaled.pressure, rtol=1e-9, atol=1e-9 * scaled.pressure.max()
        )


def test_mesh_independent_form_converges(params, independent, pin):
    reference = solve(contour(params, 36000), pin, [200.0], [0.0], "nlcp", independent)
    errors = []
    for nodes in (360, 720, 1440, 2880):
        sol = solve(contour(params, nodes), pin, [200.0], [0.0], "nlcp", independent)
        errors.append(abs(sol.penetration[0] / reference.penetration[0] - 1))
        assert sol.half_angle_left[0] == pytest.approx(reference.half_angle_left[0], rel=1e-4)
        assert sol.pressure.max() == pytest.approx(reference.pressure.max(), rel=1e-4)
    assert errors[0] < 1e-5
    assert errors[-1] < errors[0]
    assert max(errors[1:]) < 1e-6


def test_variants_coincide_at_one_degree(params, independent, pin, circle):
    loads = np.array([1.0, 50.0, 200.0, 400.0])
    paper = solve(circle, pin, loads, np.zeros(4), "nlcp", params)
    other = solve(circle, pin, loads, np.zeros(4), "nlcp", independent)
    np.testing.assert_allclose(paper.penetration, other.penetration, rtol=1e-12)
    np.testing.assert_allclose(
        paper.pressure, other.pressure, rtol=1e-12, atol=1e-12 * paper.pressure.max()
    )


def test_nlcp_vs_winkler_paper_joint(params, pin, circle):
    """At 200 N the 1 degree NLCP joint is softer than Winkler: deeper, wider, lower peak."""
    n = solve(circle, pin, [200.0], [0.0], "nlcp", params)
    w = solve(circle, pin, [200.0], [0.0], "asymmetric-winkler", params)
    assert n.penetration[0] > 1.5 * w.penetration[0]  # 16.2 um vs 9.2 um
    assert n.half_angle_left[0] > w.half_angle_left[0]  # 40.8 vs 32.3 deg
    assert n.pressure.max() < w.pressure.max()  # 1.68 vs 1.84 MPa
    # the NLCP pressure profile falls off faster at the edges: delta^1.5
    profile = n.pressure[0] / n.pressure[0].max()
    delta = circle.penetration(pin, n.eccentricity[0])
    np.testing.assert_allclose(profile, (delta / delta.max()) ** 1.5, rtol=1e-10, atol=1e-15)


def test_custom_spring_area_scales_the_pressure_not_the_force(params, pin, circle):
    bigger = dataclasses.replace(params, spring_area=2 * params.spring_area)
    a = solve(circle, pin, [200.0], [0.0], "nlcp", params)
    b = solve(circle, pin, [200.0], [0.0], "nlcp", bigger)
    assert b.penetration[0] == pytest.approx(a.penetration[0], rel=1e-12, abs=0)
    np.testing.assert_allclose(b.pressure, a.pressure / 2, rtol=1e-12, atol=1e-6)


def test_exponent_parameter(params, pin, circle):
    linear = dataclasses.replace(params, exponent=1.0)
    law = contact_law("nlcp", linear)
    assert law.exponent == 1.0
    sol = solve(circle, pin, [200.0], [0.0], "nlcp", linear)
    delta = circle.penetration(Pin(params.pin_radius), sol.eccentricity[0])
    np.testing.assert_allclose(
        sol.pressure[0] * params.spring_area,
        law.coefficient * params.spring_area * delta,
        rtol=1e-12,
        atol=1e-9,
    )


def test_explicit_stiffness_replaces_eq2(params, pin, circle):
    k = contact_law("nlcp", params).coefficient * params.spring_area
    same = dataclasses.replace(params, stiffness=k)
    a = solve(circle, pin, [200.0], [0.0], "nlcp", params)
    b = solve(circle, pin, [200.0], [0.0], "nlcp", same)
    np.testing.assert_array_equal(a.pressure, b.pressure)
    # a softer spring: K / pi. Force per spring K delta^1.5 carries the same load, so the
    # penetration grows and the arc widens; the pressure peak falls
    soft = dataclasses.replace(params, stiffness=k / np.pi)
    c = solve(circle, pin, [200.0], [0.0], "nlcp", soft)
    assert c.penetration[0] > a.penetration[0]
    assert c.half_angle_left[0] > a.half_angle_left[0]
    assert c.pressure.max() < a.pressure.max()
    # the balance still holds and the law is exactly p = (K/pi) delta^1.5 / A
    delta = circle.penetration(pin, c.eccentricity[0])
    np.testing.assert_allclose(
        c.pressure[0],
        k / np.pi * np.maximum(delta, 0) ** 1.5 / params.spring_area,
        rtol=1e-12,
        atol=1e-9,
    )
