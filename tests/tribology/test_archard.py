"""Archard wear: local law, global form, sliding distances."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.tribology import archard, sliding


def test_wear_depth_is_the_pressure_sliding_sum() -> None:
    rng = np.random.default_rng(1)
    pressure = rng.random((50, 36)) * 1e6
    ds = rng.random(50) * 1e-4
    expected = 5e-13 * np.array([sum(pressure[k, j] * ds[k] for k in range(50)) for j in range(36)])
    np.testing.assert_allclose(archard.wear_depth(pressure, ds, 5e-13), expected, rtol=1e-12)


def test_relative_rotation_sliding() -> None:
    np.testing.assert_allclose(sliding.relative_rotation([0.1, -0.2], 7.5e-3), [7.5e-4, 1.5e-3])


def test_contact_azimuth_sliding_is_periodic_and_wrapped() -> None:
    # the azimuth sweeps across the +-pi cut: increments must be wrapped, not 2 pi jumps
    psi = np.array([3.1, -3.1, -3.0, 3.1])
    ds = sliding.contact_azimuth(psi, 1.0)
    expected = np.abs(np.angle(np.exp(1j * (np.roll(psi, -1) - psi))))
    np.testing.assert_allclose(ds, expected)
    assert ds.max() < 1.0


def test_archard_volume() -> None:
    assert archard.archard_volume([100.0, 200.0], [1e-3, 2e-3], 1e-12) == pytest.approx(5e-13)
