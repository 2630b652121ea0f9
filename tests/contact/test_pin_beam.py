"""The pin as a beam: Hetényi's beams on elastic foundation, Timoshenko, supports, limits."""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.contact.pin_beam import (
    Cantilever,
    Clevis,
    PinBeam,
    beam_on_foundation,
    bending,
    characteristic,
    compliance,
    element_stiffness,
    linearised_joint,
    shear_coefficient,
)
from jointwear.errors import ConfigError, GeometryError

#: a steel pin of the paper's joint (R_p = 7.45 mm) [N m^2]
STEEL = PinBeam.solid(7.45e-3, 209e9, 0.28, model="euler-bernoulli")
#: a foundation giving lambda = 30 / m with it [N/m^2]
FOUNDATION = 4 * STEEL.bending_stiffness * 30.0**4


def slices(length: float, count: int) -> tuple[np.ndarray, np.ndarray]:
    """Centres and widths of ``count`` equal slices over ``length`` [m]."""
    width = length / count
    return (np.arange(count) + 0.5) * width - length / 2, np.full(count, width)


def hetenyi_infinite(x, load, foundation, lam):
    """Infinite beam, point load: w = P lambda / 2k e^{-lambda|x|} (cos lambda x + sin
    lambda |x|) [m] (Hetényi 1946, §8)."""
    x = np.abs(x)
    return load * lam / (2 * foundation) * np.exp(-lam * x) * (np.cos(lam * x) + np.sin(lam * x))


def hetenyi_free_centre_load(load, foundation, lam, length):
    """Finite beam, free ends, central point load: deflection at the centre and at the
    ends [m] (Hetényi 1946, §15)."""
    t = lam * length
    denominator = np.sinh(t) + np.sin(t)
    centre = load * lam / (2 * foundation) * (np.cosh(t) + np.cos(t) + 2) / denominator
    ends = 2 * load * lam / foundation * np.cosh(t / 2) * np.cos(t / 2) / denominator
    return centre, ends


def test_infinite_beam_under_a_point_load():
    lam = characteristic(FOUNDATION, STEEL.bending_stiffness)
    assert lam == pytest.approx(30.0, rel=1e-14, abs=0)
    length = 20 / lam  # the free ends are 10 / lambda away: e^-10 of the load's effect
    z, h = slices(length, 801)
    w = beam_on_foundation(STEEL, z, np.full(z.size, FOUNDATION), h, forces=[(0.0, 1000.0)])
    exact = hetenyi_infinite(z, 1000.0, FOUNDATION, lam)
    near = np.abs(z) < 4 / lam
    assert np.abs(w - exact)[near].max() <= 1e-5 * exact.max()
    # the zero crossing at lambda x = 3 pi / 4 and the sign change beyond it
    assert np.all(w[np.abs(lam * z) < 0.7 * math.pi] > 0)
    assert np.all(w[(np.abs(lam * z) > 0.8 * math.pi) & near] < 0)


@pytest.mark.parametrize("lam_length", [0.5, 1.0, 2.0, 3.0, 5.0])
def test_finite_free_beam_under_a_central_load(lam_length):
    lam = characteristic(FOUNDATION, STEEL.bending_stiffness)
    length = lam_length / lam
    z, h = slices(length, 201)
    centre, ends = beam_on_foundation(
        STEEL, z, np.full(z.size, FOUNDATION), h, forces=[(0.0, 500.0)], at=[0.0, length / 2]
    )
    exact_centre, exact_ends = hetenyi_free_centre_load(500.0, FOUNDATION, lam, length)
    assert centre == pytest.approx(exact_centre, rel=1e-2)
    assert ends == pytest.approx(exact_ends, rel=1e-2, abs=1e-2 * exact_centre)
    if lam_length <= 1.0:  # a short beam is rigid on its foundation: w ~ P / (k L)
        assert centre == pytest.approx(500.0 / (FOUNDATION * length), rel=0.02)


def test_the_lumped_foundation_converges_as_h_squared():
    lam = characteristic(FOUNDATION, STEEL.bending_stiffness)
    length = 3 / lam
    exact, _ = hetenyi_free_centre_load(1.0, FOUNDATION, lam, length)
    errors = []
    for count in (11, 21, 41, 81):
        z, h = slices(length, count)
        w = beam_on_foundation(STEEL, z, np.full(count, FOUNDATION), h, [(0.0, 1.0)], at=[0.0])
        errors.append(abs(w[0] / exact - 1))
    order = np.log(np.array(errors[:-1]) / errors[1:]) / np.log(
        np.array([21, 41, 81]) / [11, 21, 41]
    )
    np.testing.assert_allclose(order, 2.0, atol=0.15)


def test_timoshenko_elements_are_exact_for_point_loads():
    beam = PinBeam(500.0, 2e6)
    span = 0.04
    # simply supported, central load: P l^3 / 48 EI + P l / 4 kGA
    middle = compliance(beam, Clevis((-span / 2, span / 2)), [0.0, 0.01])
    assert middle[0, 0] == pytest.approx(span**3 / 48 / 500.0 + span / 4 / 2e6, rel=1e-12, abs=0)
    # cantilever, tip load: P l^3 / 3 EI + P l / kGA
    tip = compliance(beam, Cantilever(-span / 2), [span / 2])
    assert tip[0, 0] == pytest.approx(span**3 / 3 / 500.0 + span / 2e6, rel=1e-12, abs=0)
    # Maxwell-Betti: the flexibility is symmetric, and positive definite
    matrix = compliance(beam, Clevis((-0.015, 0.018)), slices(0.02, 9)[0])
    assert np.all(np.linalg.eigvalsh(matrix) > 0)


def test_timoshenko_tends_to_euler_bernoulli_as_the_shear_stiffness_grows():
    z, h = slices(0.02, 20)
    clevis = Clevis((-0.015, 0.015))
    euler = compliance(STEEL, clevis, z)
    shear = PinBeam.solid(7.45e-3, 209e9, 0.28).shear_stiffness
    gaps = []
    for factor in (1.0, 10.0, 100.0, 1e4):
        timoshenko = compliance(PinBeam(STEEL.bending_stiffness, factor * shear), clevis, z)
        assert np.all(timoshenko >= euler * (1 - 1e-12))  # shear adds deflection
        gaps.append(np.abs(timoshenko - euler).max() / np.abs(euler).max())
    # the shear deflection is proportional to 1 / kGA
    np.testing.assert_allclose(np.array(gaps[:-1]) / gaps[1:], [10.0, 10.0, 100.0], rtol=1e-6)
    assert gaps[-1] < 1e-4
    # on a foundation too
    load = [(0.0, 1.0)]
    w_euler = beam_on_foundation(STEEL, z, np.full(20, FOUNDATION), h, load)
    w_stiff = beam_on_foundation(PinBeam(STEEL.bending_stiffness, 1e8 * shear), z,
                                 np.full(20, FOUNDATION), h, load)  # fmt: skip
    np.testing.assert_allclose(w_stiff, w_euler, rtol=1e-7)


def test_a_short_steel_pin_shears_noticeably():
    """Shear over bending deflection of a simply supported pin under a central load is
    12 EI / (kappa G A l^2) = (6 (1 + nu) / kappa) (R / l)^2: about half for a pin spanning
    twice its diameter."""
    radius = 7.45e-3
    timoshenko = PinBeam.solid(radius, 209e9, 0.28)
    span = 4 * radius
    share = compliance(timoshenko, Clevis((-span / 2, span / 2)), [0.0])[0, 0]
    euler = compliance(STEEL, Clevis((-span / 2, span / 2)), [0.0])[0, 0]
    ratio = (span / 4 / timoshenko.shear_stiffness) / (span**3 / 48 / STEEL.bending_stiffness)
    assert share / euler - 1 == pytest.approx(ratio, rel=1e-12, abs=0)
    kappa = shear_coefficient(0.28)
    assert ratio == pytest.approx(6 * 1.28 / kappa * (radius / span) ** 2, rel=1e-12, abs=0)
    assert ratio == pytest.approx(0.5425, rel=1e-3)


def test_the_linearised_joint_of_a_rigid_pin():
    """EI -> infinity: the pin on its foundation moves rigidly, u = delta_0 + gamma z with
    delta_0 = W / kL and gamma = W a / (k h sum z_i^2)."""
    length, count, load, offset = 0.02, 16, 800.0, 3e-3
    z, h = slices(length, count)
    foundation = np.full(count, 2.3e9)
    delta = load / (2.3e9 * length)
    gamma = load * offset / (2.3e9 * h[0] * np.sum(z**2))
    rigid = delta + gamma * z
    for support in (Clevis((-0.015, 0.02)), Cantilever(-0.02), Cantilever(0.03)):
        misses = []
        for factor in (1.0, 1e1, 1e2, 1e4):
            beam = PinBeam(factor * STEEL.bending_stiffness)
            u = linearised_joint(beam, support, z, h, foundation, load, offset)
            misses.append(np.abs(u / rigid - 1).max())
            # the foundation carries the load and its moment whatever the pin's stiffness
            # (to the round-off of a stiff beam on soft springs, eps 12 EI / k h^4 ~ 2e-10
            # for the real pin here)
            force = foundation * h * u
            assert force.sum() == pytest.approx(load, rel=1e-8 * factor)
            assert force @ z == pytest.approx(load * offset, rel=1e-8 * factor)
        # the bending falls as 1 / EI (until the round-off of the stiffest pin)
        assert misses[0] > 1e-3
        np.testing.assert_allclose(np.array(misses[:2]) / misses[1:3], 10.0, rtol=0.02)
        assert misses[3] < misses[2] / 20


def test_a_clevis_pin_loads_the_bushing_ends():
    z, h = slices(0.02, 20)
    foundation = np.full(20, 1e12)  # a stiff bushing: lambda L ~ 4.5
    u = linearised_joint(STEEL, Clevis((-0.016, 0.016)), z, h, foundation, 5000.0)
    assert u[0] == pytest.approx(u[-1], rel=1e-9, abs=0)
    assert u[0] > 2 * u[10]
    for support in (Clevis((-0.016, 0.016)), Cantilever(-0.02)):
        for offset in (0.0, 3e-3):
            u = linearised_joint(STEEL, support, z, h, foundation, 5000.0, offset)
            force = foundation * h * u
            assert force.sum() == pytest.approx(5000.0, rel=1e-12)
            assert force @ z == pytest.approx(5000.0 * offset, rel=1e-9, abs=1e-9)


def test_bending_adds_to_the_offset_against_the_forces():
    z, _ = slices(0.02, 10)
    clevis = Clevis((-0.015, 0.015))
    forces = np.linspace(10.0, 50.0, 10)
    w = bending(STEEL, clevis, z, forces)
    assert np.all(w < 0)  # the slices push the pin back, against the load
    np.testing.assert_allclose(w, -compliance(STEEL, clevis, z) @ forces)
    # statics of a simply supported beam: w at the forks is 0 (the support line)
    pushes = [(zi, -f) for zi, f in zip(z, forces, strict=True)]
    at_forks = beam_on_foundation(STEEL, z, np.zeros(10), np.full(10, 2e-3), pushes,
                                  supports=clevis, at=list(clevis.forks) + list(z))  # fmt: skip
    np.testing.assert_allclose(at_forks[:2], 0.0, atol=1e-30)
    np.testing.assert_allclose(at_forks[2:], w, rtol=1e-12)


def test_supports_statics():
    clevis = Clevis((-0.015, 0.025), fit_clearance=20e-6)
    (a, ra), (b, rb) = clevis.reactions(1000.0, 0.002)[0]
    assert ra + rb == pytest.approx(1000.0, rel=1e-15)
    assert ra * a + rb * b == pytest.approx(1000.0 * 0.002, rel=1e-12)
    assert clevis.tilt_play == pytest.approx(2 * 20e-6 / 0.04, rel=1e-15, abs=0)
    forces, moments = Cantilever(-0.02).reactions(1000.0, 0.002)
    assert forces == [(-0.02, 1000.0)]
    assert moments[0][1] == pytest.approx(1000.0 * 0.022, rel=1e-15, abs=0)


def test_solid_section():
    beam = PinBeam.solid(0.01, 200e9, 0.3)
    assert beam.bending_stiffness == pytest.approx(200e9 * math.pi * 1e-8 / 4, rel=1e-15)
    kappa = shear_coefficient(0.3)
    assert kappa == pytest.approx(7.8 / 8.8, rel=1e-15, abs=0)  # Cowper: 0.886 for nu = 0.3
    shear = kappa * 200e9 / 2.6 * math.pi * 1e-4
    assert beam.shear_stiffness == pytest.approx(shear, rel=1e-15)
    assert beam.model == "timoshenko"
    assert STEEL.model == "euler-bernoulli"
    stiffness = element_stiffness(STEEL, [0.01, 0.02])
    assert stiffness.shape == (2, 4, 4)
    np.testing.assert_allclose(stiffness, np.swapaxes(stiffness, 1, 2))
    # rigid-body motions cost nothing
    for motion in ([1, 0, 1, 0], [0, 1, 0.01, 1]):
        np.testing.assert_allclose(stiffness[0] @ motion, 0.0, atol=1e-6)


def test_refusals():
    z, h = slices(0.02, 4)
    with pytest.raises(GeometryError, match="pin.support: the pin is not held"):
        beam_on_foundation(STEEL, z, np.zeros(4), h, [(0.0, 1.0)])
    with pytest.raises(ConfigError, match="pin.model"):
        PinBeam.solid(0.01, 200e9, 0.3, model="rigid-ish")
    with pytest.raises(ConfigError, match="pin.model"):
        PinBeam(-1.0)
    with pytest.raises(ConfigError, match="pin.support"):
        Clevis((0.01, -0.01))
    with pytest.raises(ConfigError, match="pin.support"):
        Clevis((-0.01, 0.01), fit_clearance=-1e-6)
