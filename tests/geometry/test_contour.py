"""Bushing contour and pin: exact penetration along the node rays, builders, errors."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.errors import GeometryError
from jointwear.geometry import BushingContour, Pin
from jointwear.geometry.contour import node_angles, ray_distance, ray_distance_derivative

R_P = 7.45e-3
C = 0.05e-3
R_B = R_P + C
B = 20e-3


def wavy(nodes: int = 360) -> BushingContour:
    theta = node_angles(nodes)
    wear = 8e-6 * np.cos(3 * theta) ** 2 + 3e-6 * np.sin(theta)
    return BushingContour.from_wear_profile(R_B, wear, B)


def brute_force_distance(
    theta: np.ndarray, e: np.ndarray, radius: float, samples: int = 400_000
) -> np.ndarray:
    """Distance to the pin surface along rays ``theta``, by sampling the pin circle.

    The bushing centre lies inside the pin (``|e| < R_p``), so every ray from it
    meets the pin circle exactly once and the polar angle of the sampled points
    is a monotone function of the circle parameter: interpolate the polar radius
    of the samples at the ray angles.
    """
    psi = np.linspace(0.0, 2 * np.pi, samples, endpoint=False)
    x = e[0] + radius * np.cos(psi)
    y = e[1] + radius * np.sin(psi)
    angle = np.mod(np.arctan2(y, x), 2 * np.pi)
    rho = np.hypot(x, y)
    order = np.argsort(angle)
    angle, rho = angle[order], rho[order]
    return np.interp(np.mod(theta, 2 * np.pi), angle, rho, period=2 * np.pi)


def quadratic_distance(theta: float, e: np.ndarray, radius: float) -> float:
    """Larger root of |t u - e|^2 = R_p^2, a quadratic in t, via numpy.roots."""
    u = np.array([np.cos(theta), np.sin(theta)])
    roots = np.roots([1.0, -2.0 * (u @ e), e @ e - radius**2])
    return float(np.max(roots.real))


# ---------------------------------------------------------------- penetration


@pytest.mark.parametrize(
    "ecc",
    [(6.0e-5, 0.0), (0.0, -5.5e-5), (4.1e-5, 4.3e-5), (-3e-4, 1e-4), (2e-3, -1.5e-3)],
)
def test_ray_distance_matches_brute_force_sampling(ecc):
    e = np.array(ecc)
    theta = node_angles(360)
    exact = ray_distance(theta, e[0], e[1], R_P)
    sampled = brute_force_distance(theta, e, R_P)
    # sampling error ~ |e| (2 pi / samples)^2 / 8, far below 1e-12 m
    np.testing.assert_allclose(exact, sampled, rtol=0, atol=1e-12)


@pytest.mark.parametrize("ecc", [(6.0e-5, 0.0), (4.1e-5, -4.3e-5), (2e-3, 1.5e-3)])
def test_ray_distance_matches_quadratic_roots(ecc):
    e = np.array(ecc)
    theta = node_angles(72)
    exact = ray_distance(theta, e[0], e[1], R_P)
    roots = np.array([quadratic_distance(t, e, R_P) for t in theta])
    np.testing.assert_allclose(exact, roots, rtol=1e-13, atol=0)


def test_penetration_is_exact_on_a_worn_contour():
    contour = wavy()
    pin = Pin(R_P)
    e = np.array([5.9e-5, 1.2e-5])
    expected = np.maximum(brute_force_distance(contour.theta, e, R_P) - contour.radius, 0.0)
    got = contour.penetration(pin, e)
    assert got.shape == (360,)
    assert np.all(got >= 0)
    assert np.count_nonzero(got) > 10
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12)


def test_signed_penetration_is_the_ray_distance_beyond_the_wall():
    """``signed`` keeps the gaps: ``t_j - r_j`` of the exact ray geometry, both signs."""
    contour = wavy()
    pin = Pin(R_P)
    for e in ([5.9e-5, 1.2e-5], [1e-5, -2e-5]):
        signed = contour.penetration(pin, e, signed=True)
        expected = ray_distance(contour.theta, e[0], e[1], R_P) - contour.radius
        # the ray distance is a difference of millimetre lengths: a few ulp of the radius
        np.testing.assert_allclose(signed, expected, rtol=0, atol=4 * np.spacing(R_B))
        np.testing.assert_array_equal(np.maximum(signed, 0.0), contour.penetration(pin, e))
        assert np.any(signed < 0)


def test_penetration_small_clearance_limit():
    """First order in |e|: delta = s cos(phi) - c; the curvature term is s^2 sin^2 / (2 R_p)."""
    contour = BushingContour.circle(R_B, 360, B)
    s = C + 10e-6
    got = contour.penetration(Pin(R_P), [s, 0.0])
    phi = np.angle(np.exp(1j * contour.theta))
    lateral2 = (s * np.sin(phi)) ** 2
    second_order = np.maximum(s * np.cos(phi) - C - lateral2 / (2 * R_P), 0.0)
    # the next term of the expansion is s^4 sin^4 / (8 R_p^3) ~ 3e-13 m at the contact edge
    np.testing.assert_allclose(got, second_order, rtol=0, atol=5e-13)
    fourth_order = np.maximum(
        s * np.cos(phi) - C - lateral2 / (2 * R_P) - lateral2**2 / (8 * R_P**3), 0.0
    )
    np.testing.assert_allclose(got, fourth_order, rtol=0, atol=1e-16)
    first_order = np.maximum(s * np.cos(phi) - C, 0.0)
    gap = np.max(np.abs(got - first_order))
    assert 5e-8 < gap < 2e-7  # the curvature term is not negligible at the contact edge


def test_penetration_zero_for_centred_pin():
    for contour in (BushingContour.circle(R_B, 360, B), wavy()):
        assert np.all(contour.penetration(Pin(R_P), [0.0, 0.0]) == 0.0)
        # and anywhere inside the clearance circle of the unworn bushing
        assert np.all(contour.penetration(Pin(R_P), [0.7 * C, -0.7 * C]) == 0.0)


def test_penetration_batches_over_eccentricities():
    contour = wavy()
    pin = Pin(R_P)
    ecc = np.array([[6e-5, 0.0], [0.0, 7e-5], [-5e-5, -5e-5]])
    batch = contour.penetration(pin, ecc)
    assert batch.shape == (3, 360)
    for row, e in zip(batch, ecc, strict=True):
        np.testing.assert_array_equal(row, contour.penetration(pin, e))


def test_ray_distance_derivative_matches_finite_differences():
    theta = node_angles(90)
    ex, ey, h = 4e-5, -3e-5, 1e-9
    dx, dy = ray_distance_derivative(theta, ex, ey, R_P)
    fx = (ray_distance(theta, ex + h, ey, R_P) - ray_distance(theta, ex - h, ey, R_P)) / (2 * h)
    fy = (ray_distance(theta, ex, ey + h, R_P) - ray_distance(theta, ex, ey - h, R_P)) / (2 * h)
    np.testing.assert_allclose(dx, fx, atol=1e-6)
    np.testing.assert_allclose(dy, fy, atol=1e-6)


# ---------------------------------------------------------------- builders


def test_circle_builder():
    contour = BushingContour.circle(R_B, 720, B)
    assert contour.nodes == 720
    np.testing.assert_array_equal(contour.radius, R_B)
    assert contour.original_radius == R_B
    assert contour.dtheta == pytest.approx(np.pi / 360)
    np.testing.assert_allclose(contour.spring_area, R_B * np.pi / 360 * B)
    np.testing.assert_array_equal(contour.wear_depth, 0.0)
    assert contour.area == pytest.approx(np.pi * R_B**2, rel=1e-14, abs=0)
    assert contour.theta[0] == 0.0
    assert contour.theta[-1] == pytest.approx(2 * np.pi * 719 / 720)


def test_from_wear_profile_keeps_original_radius():
    wear = np.linspace(0, 1e-5, 360)
    contour = BushingContour.from_wear_profile(R_B, wear, B)
    np.testing.assert_array_equal(contour.radius, R_B + wear)
    assert contour.original_radius == R_B
    np.testing.assert_allclose(contour.wear_depth, wear, atol=1e-20)
    # worn() grows it further and keeps the reference radius
    more = contour.worn(np.full(360, 2e-6))
    np.testing.assert_allclose(more.wear_depth, wear + 2e-6, atol=1e-19)
    assert more.original_radius == R_B


def test_radius_array_is_read_only():
    contour = wavy()
    with pytest.raises(ValueError, match="read-only"):
        contour.radius[0] = 1.0


def test_from_points_round_trip():
    contour = wavy(360)
    x = contour.radius * np.cos(contour.theta)
    y = contour.radius * np.sin(contour.theta)
    rng = np.random.default_rng(1)
    order = rng.permutation(360)  # the points need not be sorted
    back = BushingContour.from_points(x[order], y[order], 360, B, original_radius=R_B)
    np.testing.assert_allclose(back.radius, contour.radius, rtol=1e-13)
    assert back.original_radius == R_B


def test_from_points_with_offset_centre_and_resampling():
    centre = (1.5e-3, -0.7e-3)
    angles = np.sort(np.random.default_rng(2).uniform(0, 2 * np.pi, 5000))
    x = centre[0] + R_B * np.cos(angles)
    y = centre[1] + R_B * np.sin(angles)
    contour = BushingContour.from_points(x, y, 180, B, center=centre)
    np.testing.assert_allclose(contour.radius, R_B, rtol=1e-12)
    assert contour.original_radius == pytest.approx(R_B, rel=1e-12, abs=0)  # default: mean radius


def test_from_points_linear_interpolation_between_points():
    # four points of a square "contour": radius interpolates linearly in angle between them
    r = np.array([1.0, 2.0, 1.0, 2.0]) * 1e-2
    a = np.array([0.0, 0.5, 1.0, 1.5]) * np.pi
    contour = BushingContour.from_points(r * np.cos(a), r * np.sin(a), 16, B)
    rising = np.array([1.0, 1.25, 1.5, 1.75]) * 1e-2
    falling = np.array([2.0, 1.75, 1.5, 1.25]) * 1e-2
    expected = np.concatenate([rising, falling, rising, falling])  # last block wraps to 2 pi
    np.testing.assert_allclose(contour.radius, expected, rtol=1e-12)


# ---------------------------------------------------------------- radius_at


def test_radius_at_nodes_midpoints_and_period():
    contour = wavy(360)
    theta = contour.theta
    np.testing.assert_allclose(contour.radius_at(theta), contour.radius, rtol=1e-14)
    mid = theta + 0.5 * contour.dtheta
    average = 0.5 * (contour.radius + np.roll(contour.radius, -1))
    np.testing.assert_allclose(contour.radius_at(mid), average, rtol=1e-14)
    for k in (-3, -1, 1, 2):
        np.testing.assert_allclose(contour.radius_at(mid + 2 * np.pi * k), average, rtol=1e-12)


def test_radius_at_wraps_between_last_and_first_node():
    radius = np.full(16, R_B)
    radius[0], radius[-1] = R_B + 4e-6, R_B
    contour = BushingContour(radius, B)
    angle = 2 * np.pi - 0.25 * contour.dtheta  # 3/4 of the way from node 15 to node 0
    assert contour.radius_at(angle) == pytest.approx(R_B + 3e-6, rel=1e-14, abs=0)
    assert contour.radius_at(-0.25 * contour.dtheta) == pytest.approx(R_B + 3e-6, rel=1e-14, abs=0)


def test_rotated_shifts_the_contour_by_whole_nodes():
    contour = wavy(360)
    k = 37
    turned = contour.rotated(k)
    angles = np.linspace(0, 2 * np.pi, 1001)
    np.testing.assert_allclose(
        turned.radius_at(angles + k * contour.dtheta), contour.radius_at(angles), rtol=1e-13
    )


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize("radius", [R_B, R_B + 1e-6])
def test_pin_not_smaller_than_bushing_raises(radius):
    contour = BushingContour.circle(R_B, 360, B)
    with pytest.raises(GeometryError, match="pin_radius"):
        contour.check_pin(Pin(radius))


def test_pin_must_clear_the_smallest_radius_of_a_worn_contour():
    radius = np.full(360, R_B)
    radius[100] = R_P  # a bump down to the pin radius
    with pytest.raises(GeometryError, match="clearance must be > 0"):
        BushingContour(radius, B).check_pin(Pin(R_P))
    BushingContour.circle(R_B, 360, B).check_pin(Pin(R_P))  # fine


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf, 0.0, -1e-3])
def test_non_finite_or_non_positive_radii_raise(bad):
    radius = np.full(64, R_B)
    radius[5] = bad
    with pytest.raises(GeometryError, match="positive and finite"):
        BushingContour(radius, B)
    with pytest.raises(GeometryError):
        BushingContour.from_wear_profile(R_B, np.where(np.arange(64) == 3, bad - R_B, 0.0), B)


@pytest.mark.parametrize("bad", [0.0, -7e-3, np.nan, np.inf])
def test_bad_pin_radius_raises(bad):
    with pytest.raises(GeometryError, match="pin_radius"):
        Pin(bad)


@pytest.mark.parametrize("bad", [0.0, -1.0, np.nan, np.inf])
def test_bad_axial_length_raises(bad):
    with pytest.raises(GeometryError, match="axial_length"):
        BushingContour.circle(R_B, 64, bad)


def test_too_few_nodes_raises():
    with pytest.raises(GeometryError, match="at least 16"):
        BushingContour.circle(R_B, 8, B)
    with pytest.raises(GeometryError):
        BushingContour(np.full((4, 16), R_B), B)
