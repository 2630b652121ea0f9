"""The plain statement of the paper balance (:mod:`jointwear.contact.balance.paper`), and
the windowed solver held to it."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from jointwear.contact import contact_law, solve_contact
from jointwear.contact.balance.paper import paper_balance, paper_pressure, paper_residual

from .common import SPRING_MODELS, force_area, pin_frame

LOADS = np.array([0.5, 20.0, 150.0, 400.0, 1500.0])
AZIMUTHS = np.radians([0.0, 17.3, -8.0, 200.5, 33.0])


def laws(params):
    for model in SPRING_MODELS:
        yield model, contact_law(model, params)
    mesh = dataclasses.replace(params, nlcp_variant="mesh-independent")
    yield "nlcp", contact_law("nlcp", mesh)


@pytest.mark.parametrize("shape", ["circle", "worn"])
def test_the_windowed_solver_solves_the_stated_balance(params, pin, circle, worn, shape):
    """Windows, warm guesses and fused arithmetic give the offsets of eqs. (5)/(7) solved on
    every node, and the pressure of those offsets, to 1e-12 relative."""
    contour = circle if shape == "circle" else worn
    for _, law in laws(params):
        stated = paper_balance(contour, pin, LOADS, AZIMUTHS, law)
        solution = solve_contact(contour, pin, LOADS, AZIMUTHS, law)
        along, _ = pin_frame(solution, AZIMUTHS)
        np.testing.assert_allclose(along, stated, rtol=1e-12)
        pressure = paper_pressure(contour, pin, stated, AZIMUTHS, law)
        scale = pressure.max(axis=1, keepdims=True)
        assert np.max(np.abs(solution.pressure - pressure) / scale) <= 1e-9


@pytest.mark.parametrize("model", SPRING_MODELS)
def test_the_stated_pressure_carries_the_load(params, pin, worn, model):
    """The resultant of the stated pressure along the load is the load (eqs. 5/7)."""
    law = contact_law(model, params)
    stated = paper_balance(worn, pin, LOADS, AZIMUTHS, law)
    pressure = paper_pressure(worn, pin, stated, AZIMUTHS, law)
    area = force_area(model, worn, params, AZIMUTHS)
    phi = worn.theta[None, :] - AZIMUTHS[:, None]
    normal = (pressure * area * np.cos(phi)).sum(axis=1)
    np.testing.assert_allclose(normal, LOADS, rtol=1e-12)
    # nothing beyond 90 degrees of the load line
    beyond = np.cos(phi) <= 0
    assert np.all(pressure[beyond] == 0.0)


def test_the_residuals_slope_is_its_derivative(params, pin, worn):
    """f'(s) of the statement is the derivative of f(s) (central differences)."""
    law = contact_law("nlcp", params)
    beta = np.angle(np.exp(1j * (worn.theta[None, :] - AZIMUTHS[:, None])))
    area = np.where(np.abs(beta) < 0.5 * np.pi, law.force_area, 0.0)
    gap = worn.radius - pin.radius
    s = paper_balance(worn, pin, LOADS, AZIMUTHS, law) * 1.01
    step = 1e-6 * s
    f, slope, _ = paper_residual(s, beta, gap, area, law, pin.radius, LOADS)
    up, _, _ = paper_residual(s + step, beta, gap, area, law, pin.radius, LOADS)
    down, _, _ = paper_residual(s - step, beta, gap, area, law, pin.radius, LOADS)
    np.testing.assert_allclose((up - down) / (2 * step), slope, rtol=1e-6)
    assert np.all(f > 0)  # beyond the balance the springs carry more than the load
