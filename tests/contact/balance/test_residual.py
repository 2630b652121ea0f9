"""The fused residual on windows (:mod:`jointwear.contact.balance.residual`) is the plain
statement of the balance (:func:`jointwear.contact.balance.paper.paper_residual`)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from jointwear.contact import CallableSpringLaw, contact_law
from jointwear.contact.balance.paper import paper_balance, paper_residual
from jointwear.contact.balance.residual import PaperResidual
from jointwear.contact.balance.window import Window
from jointwear.geometry.angles import wrap_angle

LOADS = np.array([0.5, 20.0, 150.0, 400.0, 1500.0, 60.0])
AZIMUTHS = np.radians([0.0, 17.3, -8.0, 200.5, 33.0, 359.7])


def statement(contour, pin, law, s):
    """``f``, ``f'`` and ``sum |f_j|`` of eqs. (5)/(7) on every node, built here."""
    beta = wrap_angle(contour.theta[None, :] - AZIMUTHS[:, None])
    radius = np.broadcast_to(contour.radius, beta.shape)
    if law.symmetric:
        radius = np.broadcast_to(contour.radius_at(AZIMUTHS)[:, None], beta.shape)
    spring = contour.dtheta * contour.axial_length
    area = law.force_area if law.force_area is not None else radius * spring
    area = np.where(np.abs(beta) < 0.5 * np.pi, area * np.ones(beta.shape), 0.0)
    return paper_residual(s, beta, radius - pin.radius, area, law, pin.radius, LOADS)


@pytest.mark.parametrize("shape", ["circle", "worn"])
@pytest.mark.parametrize(
    "model", ["winkler", "asymmetric-winkler", "nlcp", "mesh-independent nlcp", "cubic"]
)
def test_the_fused_residual_is_the_statement(params, pin, circle, worn, shape, model):
    """At offsets around the balance, on a quarter-circle window: the same residual, slope
    and force sum as the plain statement on every node (fast paths for exponents 1 and
    1.5, the general path for another law)."""
    contour = circle if shape == "circle" else worn
    if model == "cubic":
        law = CallableSpringLaw(lambda delta: 1e20 * delta**3)
    elif model == "mesh-independent nlcp":
        law = contact_law("nlcp", dataclasses.replace(params, nlcp_variant="mesh-independent"))
    else:
        law = contact_law(model, params)
    balanced = paper_balance(contour, pin, LOADS, AZIMUTHS, law)
    window = Window(contour, AZIMUTHS, contour.nodes // 4, law, pin.radius)
    for factor in (0.999, 1.0005):
        s = balanced * factor
        fused = PaperResidual(window, law, pin.radius, LOADS, tolerance=0.0)
        f, slope, total = fused(s, np.arange(LOADS.size))[:3]
        f_ref, slope_ref, total_ref = statement(contour, pin, law, s)
        np.testing.assert_allclose(total, total_ref, rtol=1e-12)
        np.testing.assert_allclose(f, f_ref, rtol=1e-9, atol=1e-12 * LOADS.max())
        # (the slope steers Newton's steps only; a cubic law's loses a few digits more)
        np.testing.assert_allclose(slope, slope_ref, rtol=1e-10)
