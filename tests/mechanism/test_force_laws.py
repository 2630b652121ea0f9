"""Contact force laws of the contact-impact dynamics (``jointwear.mechanism.force_laws``).

Physical checks: the elastic part is Hertz's eq. (1)-(2) for a pin in a hole,
the stored energy is the integral of the force, the damping term is dissipative
(loading above unloading, never tensile), the hysteresis factors reduce to the
same damping for c_e -> 1, the restitution that a hysteresis factor produces, the
friction ramp, and the distributed (NLCP/Winkler) resultant is the gradient of its
energy, nearly radial, and agrees with the closed-form Winkler force.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.contact import ContactParameters, contact_law
from jointwear.contact.winkler import circle_force
from jointwear.errors import ConfigError
from jointwear.geometry import BushingContour, Pin
from jointwear.mechanism import force_laws as fl

POINT = ["lankarani-nikravesh", "hunt-crossley", "flores"]


def test_pin_in_hole_stiffness_is_eq_2(params: ContactParameters) -> None:
    sigma_p = (1 - params.pin_poisson_ratio**2) / (math.pi * params.pin_youngs_modulus)
    sigma_b = (1 - params.bushing_poisson_ratio**2) / (math.pi * params.bushing_youngs_modulus)
    r_p, r_b = params.pin_radius, params.bushing_radius
    expected = 4 / (3 * math.pi * (sigma_p + sigma_b)) * math.sqrt(r_p * r_b / (r_b - r_p))
    k = fl.pin_in_hole_stiffness(r_p, r_b, params.pin_youngs_modulus, params.pin_poisson_ratio,
                                 params.bushing_youngs_modulus, params.bushing_poisson_ratio)
    assert k == pytest.approx(expected, rel=1e-12)
    # paper's joint: PTFE bushing, R* = 1.12 m -> K ~ 8.2e8 N/m^1.5
    assert 8.0e8 < k < 8.4e8


@pytest.mark.parametrize(("law", "factor"), [
    ("lankarani-nikravesh", lambda c: 3 * (1 - c**2) / 4),
    ("hunt-crossley", lambda c: 3 * (1 - c) / 2),
    ("flores", lambda c: 8 * (1 - c) / (5 * c)),
    ("nlcp", lambda c: 3 * (1 - c**2) / 4),
    ("winkler", lambda c: 3 * (1 - c**2) / 4),
])
def test_hysteresis_factors(law: str, factor) -> None:
    for ce in (0.3, 0.7, 0.95):
        assert fl.hysteresis_factor(law, ce) == pytest.approx(factor(ce), rel=1e-14)
    assert fl.hysteresis_factor(law, 1.0) == 0.0


def test_factors_near_elastic_limit() -> None:
    # LN and HC are the same first-order expansion about c_e = 1 (chi = 3/2 (1 - c_e));
    # Flores' chi is 16/15 of it there, so it dissipates 6.7 % more per nearly elastic impact
    ce = 1 - 1e-6
    ln, hc, flores = (fl.hysteresis_factor(law, ce) for law in POINT)
    assert ln == pytest.approx(1.5e-6, rel=1e-6)
    assert hc == pytest.approx(1.5e-6, rel=1e-6)
    assert flores == pytest.approx(1.6e-6, rel=2e-6)


@pytest.mark.parametrize("ce", [0.0, -0.1, 1.01, math.nan])
def test_bad_restitution_and_law_rejected(ce: float) -> None:
    with pytest.raises(ConfigError, match="dynamics.restitution"):
        fl.hysteresis_factor("flores", ce)
    with pytest.raises(ConfigError, match="dynamics.force_law"):
        fl.hysteresis_factor("kelvin-voigt", 0.5)


@pytest.mark.parametrize("law", POINT)
def test_point_law_elastic_part_and_hysteresis(law: str) -> None:
    """Each point law is Hertz's force with its hysteresis factor, as the joint applies it."""
    k, n, ce, v_in = 8.2e8, 1.5, 0.6, 0.2
    chi = fl.hysteresis_factor(law, ce)

    def force(delta, rate):
        return fl.dissipative_force(delta, rate, v_in, k, chi, n)

    delta = np.array([-1e-6, 0.0, 1e-6, 2e-5])
    # no rate: Hertz, zero without penetration
    np.testing.assert_allclose(force(delta, 0.0), k * np.maximum(delta, 0) ** n, rtol=1e-14)
    loading = force(2e-5, 0.1)
    unloading = force(2e-5, -0.1)
    assert loading > k * 2e-5**n > unloading >= 0  # energy is lost over a cycle
    assert loading == pytest.approx(k * 2e-5**n * (1 + chi * 0.5), rel=1e-14)
    # never tensile: a fast withdrawal is clipped at zero
    assert force(2e-5, -10.0) == 0.0


def test_elastic_potential_is_integral_of_force() -> None:
    k, n = 8.2e8, 1.5
    delta = np.linspace(1e-7, 3e-5, 7)
    h = 1e-10
    derivative = (fl.elastic_potential(delta + h, k, n) - fl.elastic_potential(delta - h, k, n))
    np.testing.assert_allclose(derivative / (2 * h), fl.elastic_force(delta, k, n), rtol=1e-6)
    assert fl.elastic_potential(-1e-6, k, n) == 0.0


def test_hysteresis_restitution_limits_and_monotonicity() -> None:
    assert fl.hysteresis_restitution(0.0) == 1.0
    # first order: e = 1 - 2 chi / 3, so LN and HC give c_e to first order in (1 - c_e)
    assert fl.hysteresis_restitution(1e-4) == pytest.approx(1 - 2e-4 / 3, abs=1e-8)
    chis = np.linspace(0.0, 6.0, 61)
    e = np.array([fl.hysteresis_restitution(c) for c in chis])
    assert np.all(np.diff(e) < 0)
    assert np.all(e > 0)
    # both branches (series below chi = 0.5, logarithms above) join continuously
    assert fl.hysteresis_restitution(0.5 - 1e-12) == pytest.approx(
        fl.hysteresis_restitution(0.5 + 1e-12), abs=1e-10)
    # e < 1/chi: the damped force cannot turn tensile during a free impact
    assert np.all(e[1:] * chis[1:] < 1)
    with pytest.raises(ConfigError):
        fl.hysteresis_restitution(-1.0)


def test_friction_ramp_and_force() -> None:
    v0, v1 = 1e-4, 3e-4
    speeds = np.array([0.0, 0.5e-4, 1e-4, 2e-4, 3e-4, 1.0])
    np.testing.assert_allclose(fl.friction_ramp(speeds, v0, v1), [0, 0, 0, 0.5, 1, 1],
                               atol=1e-15)
    fine = np.linspace(0, 5e-4, 5001)
    ramp = fl.friction_ramp(fine, v0, v1)
    assert np.all(np.diff(ramp) >= 0)
    # C1: the slope is continuous (no jump at v0 and v1)
    slope = np.diff(ramp) / np.diff(fine)
    assert np.max(np.abs(np.diff(slope))) < 0.01 * np.max(slope)
    assert fl.friction_ramp(2e-4, v0) == 1.0  # default v1 = 2 v0
    force = fl.friction_force(np.array([-0.1, 0.0, 0.1]), 100.0, 0.2, v0, v1)
    np.testing.assert_allclose(force, [20.0, 0.0, -20.0])


# ------------------------------------------------------------------ distributed laws


@pytest.mark.parametrize("model", ["nlcp", "winkler"])
def test_spring_resultant_is_gradient_of_energy(
    model: str, params: ContactParameters, circle: BushingContour, worn: BushingContour,
    pin: Pin, clearance: float,
) -> None:
    law = contact_law(model, params)
    for contour in (circle, worn):
        e = np.array([0.3, -0.2]) / math.hypot(0.3, 0.2) * (clearance + 4e-6)
        force, energy, depth = fl.spring_resultant(contour, pin, e, law)
        assert energy > 0
        assert depth > 0
        h = 1e-11
        grad = [
            (fl.spring_resultant(contour, pin, e + h * u, law)[1]
             - fl.spring_resultant(contour, pin, e - h * u, law)[1]) / (2 * h)
            for u in np.eye(2)
        ]
        np.testing.assert_allclose(force, grad, rtol=1e-5)
        # the radial-spring resultant sum A p u_j differs by terms O(|e| / R_p)
        delta = contour.penetration(pin, e)
        area = law.force_area if law.force_area is not None else contour.spring_area
        radial = np.array([np.sum(area * law.pressure(delta) * np.cos(contour.theta)),
                           np.sum(area * law.pressure(delta) * np.sin(contour.theta))])
        assert np.linalg.norm(force - radial) < 0.01 * np.linalg.norm(force)


def test_spring_resultant_along_offset_on_circle(
    params: ContactParameters, circle: BushingContour, pin: Pin, clearance: float
) -> None:
    law = contact_law("nlcp", params)
    direction = math.radians(37.0)
    e = (clearance + 5e-6) * np.array([math.cos(direction), math.sin(direction)])
    force, _, _ = fl.spring_resultant(circle, pin, e, law)
    assert math.atan2(force[1], force[0]) == pytest.approx(direction, abs=1e-3)
    assert fl.spring_gap(circle, pin, e) == pytest.approx(5e-6, rel=1e-3)
    assert fl.spring_gap(circle, pin, 0.5 * e) < 0


def test_joint_contact_gap_is_the_contour_penetration(
    paper_config, circle: BushingContour, pin: Pin, clearance: float
) -> None:
    """The integrator's gap of a distributed law is the largest signed node penetration."""
    contact = fl.JointContact.from_config(
        paper_config.replace({"dynamics.force_law": "nlcp"}), circle
    )
    rng = np.random.default_rng(5)
    for e in rng.uniform(-1.5 * clearance, 1.5 * clearance, size=(50, 2)):
        gap = contact.gap(*e)
        assert gap == fl.spring_gap(circle, pin, e)
        assert gap == circle.penetration(pin, e, signed=True).max()


def test_winkler_resultant_matches_closed_form(
    params: ContactParameters, pin: Pin, clearance: float
) -> None:
    fine = BushingContour.circle(params.bushing_radius, 7200, params.axial_length)
    law = contact_law("winkler", params)
    for approach in (2e-6, 1e-5):
        force, _, _ = fl.spring_resultant(fine, pin, np.array([clearance + approach, 0.0]), law)
        closed, _ = circle_force(approach, clearance, params.bushing_radius,
                                 params.axial_length, law.coefficient, params.pin_radius)
        assert force[0] == pytest.approx(float(closed), rel=2e-3)
        assert abs(force[1]) < 1e-9 * force[0]


def test_callable_spring_law_energy_quadrature(
    params: ContactParameters, circle: BushingContour, pin: Pin, clearance: float
) -> None:
    power = contact_law("winkler", params)

    class Linear(type(power).__mro__[1]):  # a plain SpringLaw with the same pressure
        force_area = None

        def pressure(self, penetration):
            return power.coefficient * np.asarray(penetration)

    e = np.array([clearance + 3e-6, 0.0])
    exact = fl.spring_resultant(circle, pin, e, power)
    approx = fl.spring_resultant(circle, pin, e, Linear())
    np.testing.assert_allclose(approx[0], exact[0], rtol=1e-12)
    assert approx[1] == pytest.approx(exact[1], rel=1e-12)  # trapezoid exact for linear p
