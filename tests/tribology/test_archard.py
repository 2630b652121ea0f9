"""Archard wear: local law, global form, sliding distances."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.tribology import archard, sliding


def test_uniform_pressure_wears_k_d_p_s() -> None:
    """Closed form: a uniform 2 MPa sliding 50 x 0.1 mm wears K_d p s = 5.05 nm everywhere."""
    pressure = np.full((50, 36), 2e6)  # [Pa]
    ds = np.full(50, 1e-4)  # [m], 5 mm in all
    depth = archard.wear_depth(pressure, ds, 5.05e-13)
    assert depth.shape == (36,)
    np.testing.assert_allclose(depth, 5.05e-9, rtol=1e-12)


def test_wear_stays_where_and_when_the_pressure_is() -> None:
    """Pressure on node 3 during step 7 only: that node wears K_d p ds, no other node wears."""
    pressure = np.zeros((10, 8))
    pressure[7, 3] = 4e6
    ds = np.arange(1, 11) * 1e-5  # step 7 slides 80 um
    depth = archard.wear_depth(pressure, ds, 1e-12)
    assert depth[3] == pytest.approx(1e-12 * 4e6 * 8e-5)
    assert np.count_nonzero(depth) == 1


def test_local_law_summed_over_the_surface_is_the_global_form() -> None:
    """sum_j h_j A_j = K_d sum_k N_k ds_k with N_k = sum_j p_jk A_j (Archard's V = K_d N s)."""
    rng = np.random.default_rng(1)
    pressure = rng.random((50, 36)) * 1e6  # [Pa]
    ds = rng.random(50) * 1e-4  # [m]
    area = rng.random(36) * 1e-6  # [m^2], unequal springs
    volume = float(archard.wear_depth(pressure, ds, 5e-13) @ area)
    normal_force = pressure @ area  # [N] per step
    assert volume == pytest.approx(archard.archard_volume(normal_force, ds, 5e-13), rel=1e-12)


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
