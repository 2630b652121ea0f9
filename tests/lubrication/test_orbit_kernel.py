"""The compiled orbit kernel against the Python mobility method it compiles.

The right-hand side (film force factor of every model, direction of motion, asperity
force, centre velocity) equals :meth:`OrbitSolver.velocity` to round-off; a cycle
integrated by the compiled Dormand--Prince pair lands where LSODA with the Python
right-hand side lands, within the integration tolerance; the periodic orbits of both
paths agree within the orbit's periodicity tolerance.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.interpolate import CubicSpline, bisplev

from jointwear.lubrication.orbit import (
    LEAVING_WALL,
    CycleMap,
    OrbitSolver,
    compiled_kernel,
    leaving_shape_table,
    periodic_orbit,
)

pytest.importorskip("numba")

RADIUS, LENGTH, CLEARANCE, ROUGHNESS, MODULUS = 0.01, 0.025, 20e-6, 0.4e-6, 115e9


@pytest.fixture(scope="module")
def kernel():
    module = compiled_kernel()
    if module is None:
        pytest.skip("the compiled kernel is switched off")
    return module


@pytest.mark.parametrize("model", ["short", "long", "finite"])
def test_the_compiled_velocity_is_the_python_velocity(kernel, model):
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, model)
    joint, asperity, memory, tables, nodes = solver.kernel_arguments()
    rng = np.random.default_rng(7)
    worst = 0.0
    # up to eps = 0.99: beyond it the short bearing's direction of motion is
    # ill-conditioned (both paths find it to their round-off only)
    for _ in range(200):
        eps, phi = rng.uniform(0.0, 0.99), rng.uniform(-np.pi, np.pi)
        # within the asperities' reach too (the gap down to a tenth of sigma)
        if rng.uniform() < 0.25:
            eps = 1.0 - rng.uniform(0.1, 3.0) * ROUGHNESS / CLEARANCE
        state = np.array([eps * math.cos(phi), eps * math.sin(phi)])
        load_x, load_y, speed = rng.normal(size=3) * [2000.0, 2000.0, 20.0]
        solver.last_direction, memory[0] = None, math.nan
        python = solver.velocity(state, load_x, load_y, speed)
        compiled = kernel.velocity(
            *state, load_x, load_y, speed, joint, asperity, memory, tables, nodes
        )
        worst = max(worst, np.max(np.abs(python - compiled)) / np.max(np.abs(python)))
    # both find the direction of motion to brentq's 1e-13 rad; near the wall the short
    # bearing's force turns slowly with it, which magnifies that up to a hundredfold
    assert worst < (1e-11 if model == "short" else 1e-12)


def test_the_compiled_bicubic_spline_is_fitpacks(kernel):
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, "finite")
    _, _, _, (tx, ty, radial, *_), _ = solver.kernel_arguments()
    rng = np.random.default_rng(3)
    # inside the table and beyond both ends (held at the end values, as FITPACK)
    for x, y in rng.uniform([-0.5, -3.5], [3.5, 3.5], size=(100, 2)):
        expected = bisplev(x, y, (tx, ty, radial, 3, 3))
        assert kernel.bicubic(tx, ty, radial, x, y) == pytest.approx(expected, rel=1e-13, abs=1e-15)


@pytest.mark.parametrize("samples", [4, 5, 9, 361])
def test_the_compiled_periodic_spline_is_scipys(kernel, samples):
    # uneven breaks and channels of different sizes, as a load cycle's (N, N, rad/s)
    rng = np.random.default_rng(samples)
    breaks = np.cumsum(rng.uniform(0.5, 1.5, samples))
    values = rng.normal(size=(3, samples)) * np.array([[3e4], [1e3], [20.0]])
    values[:, -1] = values[:, 0]
    expected = CubicSpline(breaks, values, axis=1, bc_type="periodic").c
    coefficients = kernel.periodic_spline(breaks, values)
    scale = np.abs(expected).max(axis=(0, 1))
    assert np.all(np.abs(coefficients - expected).max(axis=(0, 1)) <= 1e-13 * scale)


def test_the_compiled_spline_slope_along_the_direction_is_fitpacks(kernel):
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, "long")
    _, _, _, (tx, ty, radial, *_), _ = solver.kernel_arguments()
    columns = ty.size - 4
    rng = np.random.default_rng(5)
    for x, y in rng.uniform([0.0, -np.pi], [2.3, np.pi], size=(100, 2)):
        span_x = kernel._interval(tx, x, 3, tx.size - 5)
        span_y = kernel._interval(ty, y, 3, ty.size - 5)
        wx = kernel._basis(tx, x, span_x)
        slope = kernel._basis_slope(ty, y, span_y)
        compiled = kernel._bicubic_sum(radial, span_x, span_y, columns, wx, slope)
        expected = bisplev(x, y, (tx, ty, radial, 3, 3), dy=1)
        assert compiled == pytest.approx(expected, rel=1e-11, abs=1e-13 * np.abs(radial).max())


@pytest.mark.parametrize("model", ["long", "finite"])
def test_newtons_direction_of_motion_is_the_bracketed_one(kernel, model):
    """From the last root (within a tenth of a radian, as between the integration's
    calls) Newton's method finds the root that the scan and Brent's method find; on
    the finite bearing's leaving table (beyond eps = 0.9) it hands over to them."""
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, model)
    joint, _, memory, tables, nodes = solver.kernel_arguments()
    _, _, _, _, ratio, code, log_gap_max = joint
    arguments = (int(code), ratio, log_gap_max, *tables, nodes)
    rng = np.random.default_rng(11)
    for _ in range(200):
        eps, target = rng.uniform(0.0, 0.995), rng.uniform(-np.pi, 2 * np.pi)
        memory[0] = math.nan
        bracketed = kernel.direction_of_motion(eps, target, memory, *arguments)
        memory[0] = bracketed + rng.uniform(-0.1, 0.1)
        film = kernel.film_at(eps, *arguments[:-1])
        newton = kernel._newton(memory[0], target, film)[0]
        inner = math.atan2(math.sin(bracketed), math.sqrt(1.0 - eps * eps) * math.cos(bracketed))
        if model == "finite" and eps > 0.9 and -math.pi + LEAVING_WALL < inner < -LEAVING_WALL:
            assert math.isnan(newton)
            continue
        assert newton == pytest.approx(bracketed, abs=1e-12)
        assert kernel.direction_of_motion(eps, target, memory, *arguments) == newton


def cycle_inputs(steps: int = 60, period: float = 0.2):
    time = np.arange(steps) * period / steps
    phase = 2 * math.pi * time / period
    load = 300.0 * (1.0 + 0.5 * np.sin(phase))
    speed = 20.0 * np.cos(phase)  # a rocking pin: the wedge reverses twice a cycle
    return time, period, load * np.cos(phase), load * np.sin(phase), speed


@pytest.mark.parametrize("model", ["short", "finite"])
def test_a_compiled_cycle_lands_where_lsoda_lands(kernel, model):
    solver = OrbitSolver(RADIUS, 0.01, CLEARANCE, 0.05, 0.2e-6, MODULUS, model)
    inputs = cycle_inputs()
    start = np.array([0.3, -0.5])
    lsoda = CycleMap(solver, *inputs, compiled=False)(start)
    compiled = CycleMap(solver, *inputs)(start)
    # the gap 1 - eps to the integration's relative tolerance (rtol 1e-7) and a margin
    gap_lsoda = 1.0 - np.hypot(*(lsoda / (1.0 + np.hypot(*lsoda))))
    gap_compiled = 1.0 - np.hypot(*(compiled / (1.0 + np.hypot(*compiled))))
    np.testing.assert_allclose(gap_compiled, gap_lsoda, rtol=1e-5)


def test_the_periodic_orbit_is_the_same_on_both_paths(kernel):
    solver = OrbitSolver(RADIUS, 0.01, CLEARANCE, 0.05, 0.2e-6, MODULUS, "short")
    inputs = cycle_inputs()
    python = periodic_orbit(solver, *inputs, start=[0.0, 0.0], compiled=False)
    compiled = periodic_orbit(solver, *inputs, start=[0.0, 0.0])
    gap = 1.0 - python.eccentricity_ratio.max()
    np.testing.assert_allclose(compiled.eccentricity_x, python.eccentricity_x, atol=1e-3 * gap)
    np.testing.assert_allclose(compiled.eccentricity_y, python.eccentricity_y, atol=1e-3 * gap)


@pytest.mark.parametrize("model", ["long", "finite"])
def test_the_steady_shape_is_the_scalar_shape(kernel, model):
    """The force factor of a steady solution (the orbit's first guess), compiled."""
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, model)
    steady = solver.steady_shape()
    assert steady is not solver.scalar_shape
    for eps in (0.1, 0.6, 0.99, 0.9999):
        for beta in (0.0, math.pi, 1.0):
            expected = solver.scalar_shape(eps, beta)
            np.testing.assert_allclose(steady(eps, beta), expected, rtol=1e-12)


@pytest.mark.parametrize("model", ["long", "finite"])
def test_the_compiled_velocity_is_the_python_velocity_close_to_the_wall(kernel, model):
    """Beyond the force table's end (eps > 0.995, down to 1e-9 of the clearance): the
    long bearing in closed form, the finite one on its wall table, in both paths."""
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, model)
    joint, asperity, memory, tables, nodes = solver.kernel_arguments()
    rng = np.random.default_rng(13)
    worst = 0.0
    for _ in range(100):
        eps, phi = 1.0 - 10.0 ** -rng.uniform(2.3, 9.0), rng.uniform(-np.pi, np.pi)
        state = np.array([eps * math.cos(phi), eps * math.sin(phi)])
        load_x, load_y, speed = rng.normal(size=3) * [2000.0, 2000.0, 20.0]
        solver.last_direction, memory[0] = None, math.nan
        python = solver.velocity(state, load_x, load_y, speed)
        compiled = kernel.velocity(
            *state, load_x, load_y, speed, joint, asperity, memory, tables, nodes
        )
        worst = max(worst, np.max(np.abs(python - compiled)) / np.max(np.abs(python)))
    # where the pin leaves the wall the long bearing's force is of order one, a
    # difference of terms of order (1 - eps^2)^-1.5: round-off grows with it (both
    # paths evaluate the same closed form; 1e-7 measured)
    assert worst < (1e-6 if model == "long" else 1e-10)


@pytest.mark.parametrize("model", ["long", "finite"])
def test_newton_on_the_wall_table_finds_the_bracketed_direction(kernel, model):
    """Beyond eps = 0.995 Newton's method runs on the wall table through the inner
    direction psi; the long bearing's leaves it to the bracketing where the pin leaves
    the wall (its closed form there)."""
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, model)
    joint, _, memory, tables, nodes = solver.kernel_arguments()
    _, _, _, _, ratio, code, log_gap_max = joint
    arguments = (int(code), ratio, log_gap_max, *tables, nodes)
    rng = np.random.default_rng(17)
    on_the_table = 0
    for _ in range(400):
        eps, target = 1.0 - 10.0 ** -rng.uniform(2.31, 8.0), rng.uniform(-np.pi, 2 * np.pi)
        memory[0] = math.nan
        bracketed = kernel.direction_of_motion(eps, target, memory, *arguments)
        film = kernel.film_at(eps, *arguments[:-1])
        newton = kernel._newton(bracketed + rng.uniform(-1e-3, 1e-3), target, film)[0]
        inner = math.atan2(math.sin(bracketed), math.sqrt(1.0 - eps * eps) * math.cos(bracketed))
        leaving = -np.pi + LEAVING_WALL - 0.05 < inner < -LEAVING_WALL + 0.05
        if leaving:  # (the finite wall table's turns within sqrt(1 - eps^2) there)
            continue
        on_the_table += 1
        assert newton == pytest.approx(bracketed, abs=1e-11)
    # (most random loads make the pin leave the wall)
    assert on_the_table > 20


def direction_arguments(model: str) -> tuple[np.ndarray, tuple]:
    """The kernel's memory of the last root and the arguments of ``direction_of_motion``
    after ``eps, target, memory`` (``film_at``'s: all but the last)."""
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, model)
    joint, _, memory, tables, nodes = solver.kernel_arguments()
    _, _, _, _, ratio, code, log_gap_max = joint
    return memory, (int(code), ratio, log_gap_max, *tables, nodes)


@pytest.mark.parametrize("model", ["long", "finite"])
def test_newtons_force_factor_is_the_one_at_its_root(kernel, model):
    """Newton's method may stop one iteration early, its ``G`` moved along the tangent
    to the root (the quadratic convergence puts the next step below round-off): ``G``
    is still the film's at the root returned, in the table and on the wall table."""
    memory, arguments = direction_arguments(model)
    rng = np.random.default_rng(19)
    found = 0
    for _ in range(400):
        eps = 1.0 - 10.0 ** -rng.uniform(0.1, 7.0)
        target = rng.uniform(-np.pi, np.pi)
        memory[0] = math.nan
        bracketed = kernel.direction_of_motion(eps, target, memory, *arguments)
        film = kernel.film_at(eps, *arguments[:-1])
        newton, g_r, g_t = kernel._newton(bracketed + rng.uniform(-0.05, 0.05), target, film)
        if math.isnan(newton):
            continue
        found += 1
        expected = np.array(kernel.shape_along(film, newton))
        scale = 1e-12 * abs(expected).max()
        np.testing.assert_allclose([g_r, g_t], expected, rtol=1e-10, atol=scale)
    assert found > 100  # (the long bearing leaves the wall, its closed form, for many)


def test_newton_on_the_wall_table_follows_a_squeezing_pins_root():
    """Close to the wall a pin squeezing the film has ``psi`` near pi / 2 for most
    ``beta``: a root that turns by a tenth of a radian in ``psi`` (between two calls of
    the integration) turns by radians in ``beta``. Newton's method on ``psi`` follows it
    (on ``beta`` it strayed and the scan over all directions took over)."""
    kernel = compiled_kernel()
    arguments = direction_arguments("long")[1]
    eps = 1.0 - 1e-4
    root_q = math.sqrt(1.0 - eps * eps)
    film = kernel.film_at(eps, *arguments[:-1])
    followed = 0
    for inner in np.linspace(1.2, 1.95, 16):
        beta = math.atan2(root_q * math.sin(inner), math.cos(inner))
        g_r, g_t = kernel.shape_along(film, beta)
        target = math.atan2(g_t, g_r)
        shifted = inner + 0.15
        start = math.atan2(root_q * math.sin(shifted), math.cos(shifted))
        newton = kernel._newton(start, target, film)[0]
        assert math.remainder(newton - beta, 2 * math.pi) == pytest.approx(0.0, abs=1e-11)
        followed += abs(math.remainder(start - beta, 2 * math.pi)) > 1.0
    assert followed > 0  # some of these starts lie more than a radian from the root


@pytest.mark.parametrize("model", ["finite", "finite-reynolds"])
def test_the_compiled_force_where_the_pin_leaves_the_wall_is_the_pythons(kernel, model):
    """tan(beta) < -3 sqrt(1 - eps^2) beyond eps = 0.9: the finite bearing's leaving
    table (either cavitation) gives the same force factor in both paths, below the
    usual table's end and beyond it; its knots are its own (from s = 1)."""
    solver = OrbitSolver(RADIUS, LENGTH, CLEARANCE, 0.1, ROUGHNESS, MODULUS, model)
    steady = solver.steady_shape()
    tables = solver.kernel_arguments()[3]
    scaled, _ = leaving_shape_table(model, solver.ratio)
    np.testing.assert_array_equal(scaled.tck[0], tables[8])
    assert tables[8][3] == 1.0
    rng = np.random.default_rng(19)
    for _ in range(300):
        eps, beta = 1.0 - 10.0 ** -rng.uniform(0.8, 8.0), rng.uniform(-np.pi, 0.0)
        expected = solver.scalar_shape(eps, beta)
        np.testing.assert_allclose(steady(eps, beta), expected, rtol=1e-12, atol=1e-14)
