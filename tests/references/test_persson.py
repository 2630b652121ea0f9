"""Persson's exact pin-in-hole solution: compliances, Hertz limit, closed form, neat fit."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.contact import ContactParameters, solve
from jointwear.contact.hertz import half_width, peak_pressure
from jointwear.errors import ContactError
from jointwear.geometry import BushingContour, Pin
from jointwear.references.persson import (
    PerssonModel,
    PerssonProblem,
    annulus_compliance,
    disk_compliance,
    hole_compliance,
    similar_neat_fit_angle,
    similar_solution,
)

R = 7.5e-3
C = 0.05e-3


def test_mode_compliance_structure() -> None:
    """C_k = (C_inf k + B)/(k^2 - 1), C_inf = 2R/E'_b + 2R/E'_p, B/C_inf = Dundurs beta."""
    problem = PerssonProblem(R, R, 2.09e11, 0.28, 5e8, 0.38)
    k = np.arange(2, 400)
    c_inf, b = problem.asymptotic_compliance
    np.testing.assert_allclose(problem.compliance(k), (c_inf * k + b) / (k**2 - 1.0), rtol=1e-12)
    e_b, e_p = 5e8 / (1 - 0.38**2), 2.09e11 / (1 - 0.28**2)
    assert c_inf == pytest.approx(2 * R / e_b + 2 * R / e_p, rel=1e-12, abs=0)
    mu = [2.09e11 / 2.56, 5e8 / 2.76]
    kappa = [3 - 4 * 0.28, 3 - 4 * 0.38]
    beta = (mu[0] * (kappa[1] - 1) - mu[1] * (kappa[0] - 1)) / (
        mu[0] * (kappa[1] + 1) + mu[1] * (kappa[0] + 1)
    )
    assert b / c_inf == pytest.approx(beta, rel=1e-10)


def test_uniform_mode_is_lame() -> None:
    """k = 0: Lamé's solutions of a disk and of a hole under uniform pressure (plane strain)."""
    e, nu = 2e9, 0.3
    assert disk_compliance([0], R, e, nu)[0] == pytest.approx(
        -R * (1 + nu) * (1 - 2 * nu) / e, rel=1e-6, abs=0
    )
    assert hole_compliance([0], R, e, nu, 2 * R)[0] == pytest.approx(
        R * (1 + nu) / e, rel=1e-6, abs=0
    )


def test_annulus_limits() -> None:
    """Thick ring -> hole in a plate (k >= 2); thin ring -> constrained layer L/E_c (k = 0)."""
    e, nu = 5e8, 0.38
    k = np.arange(2, 30)
    np.testing.assert_allclose(
        annulus_compliance(k, R, 1e3 * R, e, nu), hole_compliance(k, R, e, nu, 1e3 * R), rtol=1e-5
    )
    thin = 1e-4 * R
    constrained = e * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    assert annulus_compliance([0], R, R + thin, e, nu)[0] == pytest.approx(
        thin / constrained, rel=1e-3, abs=0
    )
    # high modes do not feel the housing; the switch-over to the plate formula is seamless
    k = np.arange(2, 5000)
    ring = annulus_compliance(k, R, 1.02 * R, e, nu)
    assert np.all(np.abs(np.diff(np.log(ring))) < 0.01)
    np.testing.assert_allclose(ring[-100:], hole_compliance(k[-100:], R, e, nu, 2 * R), rtol=1e-9)


def test_hertz_limit() -> None:
    """Small loads: half-width and peak pressure of Hertz with R* = R_p R_b / (R_b - R_p)."""
    problem = PerssonProblem(R - C, R, 2.09e11, 0.28, 5e8, 0.38, outer_radius=R + 3.65e-3)
    relative = (R - C) * R / C
    for load in (1.0, 10.0):  # N/m; contact half-angles 0.4 and 1.2 deg
        arc = problem.solve(load)
        a = half_width(load, 1.0, relative, problem.effective_modulus)
        p0 = peak_pressure(load, 1.0, relative, problem.effective_modulus)
        assert arc.half_angle * R == pytest.approx(float(a), rel=0.01)
        assert arc.peak_pressure == pytest.approx(float(p0), rel=0.01)
    # conformal loads: Hertz is not the answer any more
    arc = problem.solve(400 / 18.67e-3)
    p0 = peak_pressure(400 / 18.67e-3, 1.0, relative, problem.effective_modulus)
    assert arc.peak_pressure > 1.1 * float(p0)


@pytest.mark.parametrize("alpha_deg", [5.0, 30.0, 60.0])
def test_closed_form_beta_zero(alpha_deg: float) -> None:
    """Rigid pin in an incompressible plate (beta = 0): numerical == closed form."""
    problem = PerssonProblem(R - C, R, math.inf, 0.3, 5e8, 0.5, gap="linear", outer_radius=2 * R)
    c_inf, b = problem.asymptotic_compliance
    assert b == 0.0
    c0 = float(problem.compliance([0])[0])
    alpha = math.radians(alpha_deg)
    load, pressure = similar_solution(alpha, C, R, c0, c_inf)
    arc = problem.solve(load)
    assert math.degrees(arc.half_angle) == pytest.approx(alpha_deg, abs=0.05)
    theta = np.linspace(0.0, 0.9 * alpha, 9)
    np.testing.assert_allclose(
        arc.pressure_at(theta), pressure(theta), rtol=0, atol=1e-3 * pressure(0)
    )
    # small angles: the closed form is Hertz
    if alpha_deg == 5.0:
        a = half_width(load, 1.0, (R - C) * R / C, problem.effective_modulus)
        assert alpha * R == pytest.approx(float(a), rel=0.01)


def test_neat_fit_angle_does_not_depend_on_load() -> None:
    """Zero clearance: the contact arc is fixed by the materials alone."""
    similar = PerssonProblem(R, R, math.inf, 0.3, 5e8, 0.5, gap="linear", outer_radius=2 * R)
    angles = [similar.solve(p).half_angle for p in (1e3, 1e5)]
    assert angles[0] == pytest.approx(angles[1], rel=1e-9)
    # beta = 0 closed form: C_0/C_inf = 1 here (1/2 for identical materials)
    assert math.degrees(angles[0]) == pytest.approx(
        math.degrees(similar_neat_fit_angle(1.0)), abs=0.1
    )
    identical = PerssonProblem(R, R, 5e8, 0.3, 5e8, 0.3, gap="linear", outer_radius=2 * R)
    assert math.degrees(identical.solve(1e4).half_angle) == pytest.approx(
        math.degrees(similar_neat_fit_angle(0.5)), abs=0.15
    )
    # the paper's materials: below 90 deg in a plate, close to 90 deg in the thin bushing
    paper = PerssonProblem(R, R, 2.09e11, 0.28, 5e8, 0.38, outer_radius=R + 3.65e-3)
    bushing = PerssonProblem(
        R, R, 2.09e11, 0.28, 5e8, 0.38, housing="rigid", outer_radius=R + 3.65e-3
    )
    assert 70 < math.degrees(paper.solve(1e4).half_angle) < 85
    assert 85 < math.degrees(bushing.solve(1e4).half_angle) < 90


def test_clearance_to_zero_approaches_neat_fit() -> None:
    """The contact angle grows towards the neat-fit value as the clearance shrinks."""
    angles = []
    for clearance in (50e-6, 5e-6, 0.5e-6, 0.05e-6, 0.0):
        problem = PerssonProblem(R - clearance, R, 2.09e11, 0.28, 5e8, 0.38, outer_radius=2 * R)
        angles.append(math.degrees(problem.solve(200 / 0.02).half_angle))
    assert np.all(np.diff(angles[:-1]) > 0)
    assert abs(angles[-1] - angles[-2]) < 0.1


def test_contact_model_interface(joint: ContactParameters, joint_pin: Pin) -> None:
    contour = BushingContour.circle(joint.bushing_radius, 360, joint.axial_length)
    solution = solve(contour, joint_pin, [100.0, 100.0], [0.0, math.radians(90)], "persson", joint)
    assert solution.model == "persson"
    np.testing.assert_allclose(solution.normal_force, 100.0)
    assert solution.half_angle_left[0] == solution.half_angle_right[0]
    assert np.argmax(solution.pressure[0]) == 0
    assert np.argmax(solution.pressure[1]) == 90
    np.testing.assert_allclose(solution.pressure[1], np.roll(solution.pressure[0], 90), atol=1e-6)
    # approach = pin displacement - clearance
    clearance = joint.bushing_radius - joint.pin_radius
    assert np.hypot(*solution.eccentricity[0]) - clearance == pytest.approx(solution.penetration[0])


def test_worn_contour_is_refused(joint: ContactParameters, joint_pin: Pin) -> None:
    wear = np.zeros(360)
    wear[10] = 5e-6
    worn = BushingContour.from_wear_profile(joint.bushing_radius, wear, joint.axial_length)
    with pytest.raises(ContactError, match="circular"):
        PerssonModel(joint).solve(worn, joint_pin, [100.0], [0.0])
