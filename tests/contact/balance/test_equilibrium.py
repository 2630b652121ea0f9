"""Full 2-D equilibrium (``balance="equilibrium"``,
:mod:`jointwear.contact.balance.equilibrium`): no sideways force left, and the cases
where Newton's method stalls."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.contact import contact_law, solve
from jointwear.geometry import BushingContour

from .common import EPS, SPRING_MODELS, bound, force_area, resultants


@pytest.mark.parametrize("model", SPRING_MODELS)
def test_circle_paper_and_equilibrium_agree(params, pin, circle, model):
    # a node on the load line: the discrete contact is symmetric, sideways force is round-off
    loads = np.array([1.0, 50.0, 200.0, 400.0])
    azimuth = np.array([0.0, 90.0, -33.0, 181.0]) * circle.dtheta
    paper = solve(circle, pin, loads, azimuth, model, params, balance="paper")
    eq = solve(circle, pin, loads, azimuth, model, params, balance="equilibrium")
    _, _, total = resultants(paper, circle, force_area(model, circle, params, azimuth), azimuth)
    assert np.all(np.abs(paper.tangential_force) <= bound(total))
    np.testing.assert_allclose(
        eq.pressure, paper.pressure, rtol=1e-9, atol=1e-12 * paper.pressure.max()
    )
    np.testing.assert_allclose(eq.eccentricity, paper.eccentricity, rtol=1e-10, atol=1e-17)
    # between nodes the discrete contact is lopsided: equilibrium moves the pin a little
    off = np.array([0.3, 0.5, 0.77]) * circle.dtheta
    paper = solve(circle, pin, np.full(3, 200.0), off, model, params, balance="paper")
    eq = solve(circle, pin, np.full(3, 200.0), off, model, params, balance="equilibrium")
    assert np.all(np.abs(paper.tangential_force) < 1e-3 * 200.0)
    np.testing.assert_allclose(eq.penetration, paper.penetration, rtol=1e-3)


@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp"])
def test_equilibrium_on_worn_contour_leaves_no_sideways_force(params, pin, worn, model):
    """The scar at +20 deg removes support on the left: paper mode pushes the resultant to the
    right (negative); full equilibrium moves the pin into the scar (+y) until it vanishes."""
    loads = np.array([50.0, 200.0, 400.0])
    paper = solve(worn, pin, loads, np.zeros(3), model, params, balance="paper")
    eq = solve(worn, pin, loads, np.zeros(3), model, params, balance="equilibrium")
    assert np.all(paper.tangential_force < -0.1 * loads)  # ~ -18 % of the load at 200 N
    _, _, total = resultants(eq, worn, force_area(model, worn, params, np.zeros(3)), np.zeros(3))
    assert np.all(np.abs(eq.tangential_force) <= bound(total))
    assert np.all(np.abs(eq.normal_force - loads) <= bound(total))
    assert np.all(eq.eccentricity[:, 1] > 5e-6)  # ~10 um sideways
    assert np.all(paper.eccentricity[:, 1] == 0.0)
    # moving sideways brings the left flank back into contact
    assert np.all(eq.springs_left > paper.springs_left)


@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp"])
def test_batch_window_finds_contact_beyond_a_wide_scar(params, pin, model):
    """A flat 30 um scar from 5 to 60 deg: paper mode touches only on the right (the coarse
    window is sized from that), but in 2-D equilibrium the pin slides into the scar and
    touches again beyond it, at ~70 deg. The narrow window must grow to see that contact
    (it is not connected to the contact at the window's edge)."""
    angle = np.degrees(np.angle(np.exp(1j * np.arange(360) * np.pi / 180)))
    wear = np.where((angle > 5) & (angle < 60), 30e-6, 0.0)
    contour = BushingContour.from_wear_profile(params.bushing_radius, wear, params.axial_length)
    loads = np.full(80, 200.0)
    batch = solve(contour, pin, loads, np.zeros(80), model, params, balance="equilibrium")
    one = solve(contour, pin, loads[:1], np.zeros(1), model, params, balance="equilibrium")
    np.testing.assert_allclose(
        batch.eccentricity, np.repeat(one.eccentricity, 80, axis=0), rtol=1e-10
    )
    assert np.degrees(one.half_angle_left[0]) > 65
    law = contact_law(model, params)
    delta = contour.penetration(pin, batch.eccentricity)
    np.testing.assert_allclose(
        batch.pressure, law.pressure(delta), rtol=1e-10, atol=1e-12 * batch.pressure.max()
    )


@pytest.mark.parametrize("model", ["winkler", "asymmetric-winkler", "nlcp"])
@pytest.mark.parametrize("fraction", [0.1, 0.2, 0.35, 0.5, 0.8])
def test_equilibrium_with_a_single_spring_in_contact(params, pin, circle, model, fraction):
    """At 1 mN on the 1 deg grid one Winkler spring carries the load in paper mode. A single
    radial spring cannot balance a load between two nodes: in equilibrium the pin slides
    until the two nodes bracketing the load share it, their sideways forces cancelling."""
    azimuth = np.array([fraction * circle.dtheta])
    load = np.array([1e-3])
    paper = solve(circle, pin, load, azimuth, model, params, balance="paper")
    eq = solve(circle, pin, load, azimuth, model, params, balance="equilibrium")
    area = force_area(model, circle, params, azimuth)
    _, _, total = resultants(eq, circle, area, azimuth)
    assert np.all(np.abs(eq.normal_force - load) <= bound(total))
    assert np.all(np.abs(eq.tangential_force) <= bound(total))
    touching = np.flatnonzero(eq.pressure[0])
    assert {0, 1} <= set(touching.tolist())
    if model == "asymmetric-winkler" and fraction != 0.5:
        assert np.count_nonzero(paper.pressure[0]) == 1  # the singular case
    f = eq.pressure[0] * area[0]
    phi = circle.theta - azimuth[0]
    assert abs(f @ np.sin(phi)) <= bound(total)[0] + 8 * EPS * total[0]
    if model != "nlcp":  # only the two bracketing nodes touch: lever rule
        assert touching.tolist() == [0, 1]
        expected = np.sin((1 - fraction) * circle.dtheta) / np.sin(fraction * circle.dtheta)
        assert f[0] / f[1] == pytest.approx(expected, rel=1e-6)
