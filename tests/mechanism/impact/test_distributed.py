"""Distributed force laws: the bushing's springs (NLCP, Winkler) on the displaced pin.

The resultant is the gradient of its energy, nearly radial, along the offset on a
circle, agrees with the closed-form Winkler force, and the joint's gap is the
contour's largest signed penetration.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.contact import ContactParameters, contact_law
from jointwear.contact.winkler import circle_force
from jointwear.geometry import BushingContour, Pin
from jointwear.mechanism.impact import distributed as dl

from ..joints import joint_contact

# ------------------------------------------------------------------ distributed laws


@pytest.mark.parametrize("model", ["nlcp", "winkler"])
def test_spring_resultant_is_gradient_of_energy(
    model: str,
    params: ContactParameters,
    circle: BushingContour,
    worn: BushingContour,
    pin: Pin,
    clearance: float,
) -> None:
    law = contact_law(model, params)
    for contour in (circle, worn):
        e = np.array([0.3, -0.2]) / math.hypot(0.3, 0.2) * (clearance + 4e-6)
        force, energy, depth = dl.spring_resultant(contour, pin, e, law)
        assert energy > 0
        assert depth > 0
        h = 1e-11
        grad = [
            (
                dl.spring_resultant(contour, pin, e + h * u, law)[1]
                - dl.spring_resultant(contour, pin, e - h * u, law)[1]
            )
            / (2 * h)
            for u in np.eye(2)
        ]
        np.testing.assert_allclose(force, grad, rtol=1e-5)
        # the radial-spring resultant sum A p u_j differs by terms O(|e| / R_p)
        delta = contour.penetration(pin, e)
        area = law.force_area if law.force_area is not None else contour.spring_area
        radial = np.array(
            [
                np.sum(area * law.pressure(delta) * np.cos(contour.theta)),
                np.sum(area * law.pressure(delta) * np.sin(contour.theta)),
            ]
        )
        assert np.linalg.norm(force - radial) < 0.01 * np.linalg.norm(force)


def test_spring_resultant_along_offset_on_circle(
    params: ContactParameters, circle: BushingContour, pin: Pin, clearance: float
) -> None:
    law = contact_law("nlcp", params)
    direction = math.radians(37.0)
    e = (clearance + 5e-6) * np.array([math.cos(direction), math.sin(direction)])
    force, _, _ = dl.spring_resultant(circle, pin, e, law)
    assert math.atan2(force[1], force[0]) == pytest.approx(direction, abs=1e-3)
    assert dl.spring_gap(circle, pin, e) == pytest.approx(5e-6, rel=1e-3)
    assert dl.spring_gap(circle, pin, 0.5 * e) < 0


def test_joint_contact_gap_is_the_contour_penetration(
    paper_config, circle: BushingContour, pin: Pin, clearance: float
) -> None:
    """The integrator's gap of a distributed law is the largest signed node penetration."""
    contact = joint_contact(paper_config.replace({"dynamics.force_law": "nlcp"}), circle)
    rng = np.random.default_rng(5)
    for e in rng.uniform(-1.5 * clearance, 1.5 * clearance, size=(50, 2)):
        gap = contact.gap(*e)
        assert gap == dl.spring_gap(circle, pin, e)
        assert gap == circle.penetration(pin, e, signed=True).max()


def test_winkler_resultant_matches_closed_form(
    params: ContactParameters, pin: Pin, clearance: float
) -> None:
    fine = BushingContour.circle(params.bushing_radius, 7200, params.axial_length)
    law = contact_law("winkler", params)
    for approach in (2e-6, 1e-5):
        force, _, _ = dl.spring_resultant(fine, pin, np.array([clearance + approach, 0.0]), law)
        closed, _ = circle_force(
            approach,
            clearance,
            params.bushing_radius,
            params.axial_length,
            law.coefficient,
            params.pin_radius,
        )
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
    exact = dl.spring_resultant(circle, pin, e, power)
    approx = dl.spring_resultant(circle, pin, e, Linear())
    np.testing.assert_allclose(approx[0], exact[0], rtol=1e-12)
    assert approx[1] == pytest.approx(exact[1], rel=1e-12, abs=0)  # trapezoid exact for linear p
