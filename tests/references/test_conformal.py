"""The rigid-conformal worn bore: its closed forms, limits and refusals."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.errors import ConfigError
from jointwear.references.conformal import (
    conformal_wear,
    contact_half_angle,
    sliding_distance,
    small_wear_sliding_distance,
)

RP, C, B, K, F = 19.95e-3, 0.05e-3, 20e-3, 1e-15, 8000.0


def _volume_rate(beta: float) -> float:
    """dV/ds of the rigid-conformal state: 2 K F sin(beta) / (beta + sin cos)."""
    return 2 * K * F * math.sin(beta) / (beta + math.sin(beta) * math.cos(beta))


def test_small_wear_limit_is_the_algebraic_form() -> None:
    """For c, d << R the quadrature tends to (R b c / K F)(alpha / cos(alpha) - sin(alpha))."""
    radius = 1.0  # a huge pin: first order in d / R is exact to ~1e-4
    for worn in (0.3, 2.0, 10.0):
        d = C * (1 + worn)
        exact = sliding_distance(d, F, radius, C, B, K)
        algebraic = small_wear_sliding_distance(d, F, radius + C / 2, C, B, K)
        assert exact == pytest.approx(float(algebraic), rel=2e-4)


def test_volume_rate_rises_from_kf_to_4kf_over_pi() -> None:
    """Worn volume per sliding distance: K F for a narrow contact, 4 K F / pi at a half bore."""
    narrow = conformal_wear(1e-3, F, RP, C, B, K)
    ds = 1e-6
    rate = (conformal_wear(1e-3 + ds, F, RP, C, B, K).wear_volume - narrow.wear_volume) / ds
    assert rate == pytest.approx(K * F, rel=2e-2, abs=0)
    assert rate == pytest.approx(_volume_rate(narrow.half_angle), rel=1e-3, abs=0)
    # the sinking at which the arc spans half the pin (beta_e = pi / 2): d^2 = R_b^2 - R_p^2
    d_half = math.sqrt((RP + C) ** 2 - RP**2)
    assert float(contact_half_angle(d_half, RP, C)) == pytest.approx(math.pi / 2, abs=1e-12)
    s_half = sliding_distance(d_half, F, RP, C, B, K)
    step = 1e-3 * s_half
    before = conformal_wear(s_half - step, F, RP, C, B, K).wear_volume
    after = conformal_wear(s_half + step, F, RP, C, B, K).wear_volume
    assert (after - before) / (2 * step) == pytest.approx(4 * K * F / math.pi, rel=1e-5, abs=0)


def test_groove_widens_as_it_deepens_and_load_balances() -> None:
    distances = np.geomspace(1e-2, 1e4, 12)
    states = [conformal_wear(s, F, RP, C, B, K) for s in distances]
    widths = [state.wear_width for state in states]
    depths = [state.peak_wear_depth for state in states]
    assert np.all(np.diff(widths) > 0)
    assert np.all(np.diff(depths) > 0)
    for state in states:
        beta = state.half_angle
        # p0 R b (beta + sin cos) = F, and the peak is the sinking beyond the clearance
        assert state.peak_pressure * RP * B * (beta + math.sin(beta) * math.cos(beta)) == (
            pytest.approx(F, rel=1e-12)
        )
        assert state.peak_wear_depth == pytest.approx(state.sinking - C, rel=1e-12, abs=0)


def test_volume_is_the_integral_of_the_depth_along_rays() -> None:
    """The disc-minus-lens area equals the integral of ((R_b + h)^2 - R_b^2) / 2 over angle."""
    state = conformal_wear(500.0, F, RP, C, B, K)
    theta = np.linspace(-math.pi, math.pi, 200_001)
    d, bore = state.sinking, RP + C
    reach = d * np.cos(theta) + np.sqrt(np.maximum(RP**2 - (d * np.sin(theta)) ** 2, 0.0))
    depth = np.maximum(reach - bore, 0.0)
    area = np.trapezoid(((bore + depth) ** 2 - bore**2) / 2, theta)
    assert state.wear_volume == pytest.approx(area * B, rel=1e-6, abs=0)
    # sliding to the same state twice gives the same sinking: the inversion is exact
    assert sliding_distance(state.sinking, F, RP, C, B, K) == pytest.approx(500.0, rel=1e-10)


def test_refuses_nonphysical_inputs() -> None:
    with pytest.raises(ConfigError, match="load"):
        conformal_wear(1.0, -1.0, RP, C, B, K)
    with pytest.raises(ConfigError, match="sliding_distance"):
        conformal_wear(math.nan, F, RP, C, B, K)
