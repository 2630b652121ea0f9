"""Starting points of the balance (:mod:`jointwear.contact.balance.guesses`)."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.contact import CallableSpringLaw, contact_law, solve_contact
from jointwear.contact.balance.guesses import circle_guess

from .common import pin_frame, revolution_loads


@pytest.mark.parametrize(("model", "accuracy"), [("nlcp", 2e-5), ("asymmetric-winkler", 5e-4)])
def test_circle_guess_is_within_the_node_ripple(params, pin, circle, model, accuracy):
    """The node-free contact of a pin in a circle starts every load within the ripple of
    where the contact edges fall between nodes (~1e-5 of the penetration for NLCP, more for
    linear springs), and estimates the widest contact to a fraction of a node."""
    law = contact_law(model, params)
    load, azimuth = revolution_loads()
    guess, widest = circle_guess(circle, pin, law, load, azimuth)
    sol = solve_contact(circle, pin, load, azimuth, law)
    along, _ = pin_frame(sol, azimuth)
    clearance = circle.radius[0] - pin.radius
    assert np.max(np.abs(guess - along) / (along - clearance)) < accuracy
    half = np.maximum(sol.half_angle_left, sol.half_angle_right)
    assert abs(widest - half.max()) < 0.1 * circle.dtheta
    # a long batch is solved at Chebyshev points of ln F and interpolated; a short one
    # load by load: the same offsets
    few, _ = circle_guess(circle, pin, law, load[:5], azimuth[:5])
    np.testing.assert_allclose(few, guess[:5], rtol=1e-9)


def test_circle_guess_only_where_the_springs_lie_on_a_circle(params, pin, circle, worn):
    load, azimuth = revolution_loads(8)
    nlcp = contact_law("nlcp", params)
    assert circle_guess(worn, pin, nlcp, load, azimuth) is None
    custom = CallableSpringLaw(lambda delta: 1e12 * delta)
    assert circle_guess(circle, pin, custom, load, azimuth) is None
    # the symmetric law's springs lie on the circle through each compression centre
    winkler = contact_law("winkler", params)
    guess, _ = circle_guess(worn, pin, winkler, load, azimuth)
    sol = solve_contact(worn, pin, load, azimuth, winkler)
    along, _ = pin_frame(sol, azimuth)
    np.testing.assert_allclose(guess, along, rtol=1e-4)
    # no load: the pin touches
    zero, widest = circle_guess(circle, pin, nlcp, np.zeros(3), azimuth[:3])
    np.testing.assert_array_equal(zero, circle.radius[0] - pin.radius)
    assert widest == 0.0
