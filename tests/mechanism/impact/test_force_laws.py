"""Contact force laws of the contact-impact dynamics (``jointwear.mechanism.impact.force_laws``).

Physical checks: the elastic part is Hertz's eq. (1), the stored energy is the
integral of the force, the damping term is dissipative (loading above unloading,
never tensile), the hysteresis factors reduce to the same damping for c_e -> 1,
the restitution that a hysteresis factor produces, and the friction ramp.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.errors import ConfigError
from jointwear.mechanism.impact import force_laws as fl

POINT = ["lankarani-nikravesh", "hunt-crossley", "flores"]


@pytest.mark.parametrize(
    ("law", "factor"),
    [
        ("lankarani-nikravesh", lambda c: 3 * (1 - c**2) / 4),
        ("hunt-crossley", lambda c: 3 * (1 - c) / 2),
        ("flores", lambda c: 8 * (1 - c) / (5 * c)),
        ("nlcp", lambda c: 3 * (1 - c**2) / 4),
        ("winkler", lambda c: 3 * (1 - c**2) / 4),
    ],
)
def test_hysteresis_factors(law: str, factor) -> None:
    for ce in (0.3, 0.7, 0.95):
        assert fl.hysteresis_factor(law, ce) == pytest.approx(factor(ce), rel=1e-14, abs=0)
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
    assert loading == pytest.approx(k * 2e-5**n * (1 + chi * 0.5), rel=1e-14, abs=0)
    # never tensile: a fast withdrawal is clipped at zero
    assert force(2e-5, -10.0) == 0.0


def test_elastic_potential_is_integral_of_force() -> None:
    k, n = 8.2e8, 1.5
    delta = np.linspace(1e-7, 3e-5, 7)
    h = 1e-10
    derivative = fl.elastic_potential(delta + h, k, n) - fl.elastic_potential(delta - h, k, n)
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
        fl.hysteresis_restitution(0.5 + 1e-12), abs=1e-10
    )
    # e < 1/chi: the damped force cannot turn tensile during a free impact
    assert np.all(e[1:] * chis[1:] < 1)
    with pytest.raises(ConfigError):
        fl.hysteresis_restitution(-1.0)


def test_friction_ramp_and_force() -> None:
    v0, v1 = 1e-4, 3e-4
    speeds = np.array([0.0, 0.5e-4, 1e-4, 2e-4, 3e-4, 1.0])
    np.testing.assert_allclose(fl.friction_ramp(speeds, v0, v1), [0, 0, 0, 0.5, 1, 1], atol=1e-15)
    fine = np.linspace(0, 5e-4, 5001)
    ramp = fl.friction_ramp(fine, v0, v1)
    assert np.all(np.diff(ramp) >= 0)
    # C1: the slope is continuous (no jump at v0 and v1)
    slope = np.diff(ramp) / np.diff(fine)
    assert np.max(np.abs(np.diff(slope))) < 0.01 * np.max(slope)
    assert fl.friction_ramp(2e-4, v0) == 1.0  # default v1 = 2 v0
    force = fl.friction_force(np.array([-0.1, 0.0, 0.1]), 100.0, 0.2, v0, v1)
    np.testing.assert_allclose(force, [20.0, 0.0, -20.0])
