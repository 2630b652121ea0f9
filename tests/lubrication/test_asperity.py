"""Greenwood--Tripp asperity contact, film parameter and regime."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import quad

from jointwear.lubrication.asperity import (
    asperity_pressure,
    composite_modulus,
    composite_roughness,
    film_parameter,
    greenwood_tripp_fit,
    greenwood_tripp_integral,
    journal_asperity_force,
    lubrication_regime,
)


def f52_by_quadrature(h):
    return quad(lambda s: (s - h) ** 2.5 * np.exp(-s * s / 2) / np.sqrt(2 * np.pi), h, np.inf)[0]


@pytest.mark.parametrize("h", [-0.5, 0.0, 1.0, 2.5, 4.0])
def test_exact_f52_is_the_gaussian_integral(h):
    assert greenwood_tripp_integral(h) == pytest.approx(f52_by_quadrature(h), rel=1e-8, abs=0)


def test_the_fit_follows_the_integral_where_asperities_carry_load():
    separations = np.linspace(0.0, 2.0, 41)
    ratio = greenwood_tripp_fit(separations) / greenwood_tripp_integral(separations)
    assert np.all(np.abs(ratio - 1) < 0.11)
    assert greenwood_tripp_fit(4.0) == 0.0
    assert greenwood_tripp_fit(5.0) == 0.0
    assert greenwood_tripp_fit(0.0) == pytest.approx(4.4086e-5 * 4**6.804)


def test_asperity_pressure_scales_as_greenwood_tripp():
    base = asperity_pressure(1e-6, 1e-6, 100e9)
    assert base == pytest.approx(
        16 * np.sqrt(2) / 15 * np.pi * 0.04**2 * np.sqrt(1e-3) * 100e9 * greenwood_tripp_fit(1.0)
    )
    assert asperity_pressure(1e-6, 1e-6, 100e9, eta_beta_sigma=0.08) == pytest.approx(4 * base)
    assert asperity_pressure(1e-6, 1e-6, 100e9, sigma_over_beta=4e-3) == pytest.approx(2 * base)
    # only the ratio h / sigma matters
    assert asperity_pressure(2e-6, 2e-6, 100e9) == pytest.approx(base)
    thinner = asperity_pressure(np.array([3e-6, 2e-6, 1e-6, 0.0]), 1e-6, 100e9)
    assert np.all(np.diff(thinner) > 0)


def test_composite_modulus_and_roughness():
    # steel on steel: E* = E / (2 (1 - nu^2))
    assert composite_modulus(210e9, 0.3, 210e9, 0.3) == pytest.approx(210e9 / (2 * 0.91))
    assert composite_roughness(0.3e-6, 0.4e-6) == pytest.approx(0.5e-6, rel=1e-6, abs=0)


@pytest.mark.parametrize("eps", [0.95, 0.97, 0.995, 1.0])
@pytest.mark.parametrize("exact", [False, True])
def test_journal_asperity_force_is_the_integral_of_the_pressure(eps, exact):
    radius, length, clearance, sigma, modulus = 0.01, 0.02, 20e-6, 0.5e-6, 115e9
    force = journal_asperity_force(radius, length, clearance, eps, sigma, modulus, exact=exact)

    def pressure(theta):
        film = clearance * (1 + eps * np.cos(theta))
        return asperity_pressure(film, sigma, modulus, exact=exact) * np.cos(theta)

    expected = radius * length * quad(pressure, 0, 2 * np.pi, points=[np.pi], limit=400)[0]
    assert force == pytest.approx(expected, rel=1e-6)
    assert force < 0


def test_no_asperity_force_on_a_thick_film():
    force = journal_asperity_force(0.01, 0.02, 20e-6, 0.5, 0.5e-6, 115e9)
    assert force == 0.0


def test_film_parameter_and_regimes():
    lam = film_parameter(np.array([4e-6, 3e-6, 2e-6, 1e-6, 0.5e-6]), 1e-6)
    np.testing.assert_allclose(lam, [4, 3, 2, 1, 0.5])
    assert list(lubrication_regime(lam)) == [
        "hydrodynamic",
        "mixed",
        "mixed",
        "boundary",
        "boundary",
    ]
    assert lubrication_regime(3.0001) == "hydrodynamic"
