"""Batched bracketed Newton against scipy's brentq."""

from __future__ import annotations

import numpy as np
import pytest
from scipy import optimize

from jointwear.solvers import bracketed_newton

RNG = np.random.default_rng(12345)
M = 200
# flat-then-rising: f = max(x - a, 0)^1.5 - c, zero derivative for x < a
A = RNG.uniform(-1.0, 1.0, M)
CC = 10.0 ** RNG.uniform(-6, 2, M)


def flat_then_rising(x, index):
    lift = np.maximum(x - A[index], 0.0)
    f = lift**1.5 - CC[index]
    return f, 1.5 * np.sqrt(lift), lift**1.5 + CC[index]


def flat_scalar(i):
    return lambda x: max(x - A[i], 0.0) ** 1.5 - CC[i]


def test_flat_then_rising_matches_brentq():
    lower, upper = np.full(M, -2.0), np.full(M, 30.0)
    x0 = np.full(M, -1.5)  # in the flat part for every problem: plain Newton cannot move
    result = bracketed_newton(flat_then_rising, x0, lower, upper, atol=1e-12)
    assert result.converged.all()
    expected = np.array(
        [optimize.brentq(flat_scalar(i), -2.0, 30.0, xtol=1e-15, rtol=1e-15) for i in range(M)]
    )
    # exact root: a + c^(2/3)
    np.testing.assert_allclose(expected, A + CC ** (2 / 3), rtol=1e-12, atol=1e-14)
    # |f| <= 1e-12 and slope >= 1.5 sqrt(c^(2/3)) bound the error in x
    slope = 1.5 * CC ** (1 / 3)
    assert np.all(np.abs(result.x - expected) <= 1e-12 / slope + 4e-15)
    assert np.all(np.abs(result.residual) <= np.maximum(1e-12, 8 * np.finfo(float).eps * (2 * CC)))
    # Newton once inside the rising part; bisection only while in the flat part
    assert result.iterations.max() <= 30
    assert result.iterations.min() >= 2


def test_plain_newton_fails_where_bracketed_newton_succeeds():
    f = flat_scalar(0)
    with pytest.raises(RuntimeError, match="[Dd]erivative was zero"):
        optimize.newton(f, A[0] - 0.5, fprime=lambda x: 1.5 * max(x - A[0], 0.0) ** 0.5)
    one = bracketed_newton(
        lambda x, i: flat_then_rising(x, np.zeros_like(i)),
        np.array([A[0] - 0.5]),
        np.array([-2.0]),
        np.array([30.0]),
        atol=1e-12,
    )
    assert one.converged[0]
    assert one.x[0] == pytest.approx(A[0] + CC[0] ** (2 / 3), rel=1e-12, abs=0)


def mixed(x, index):
    """A batch of different increasing functions, chosen by index % 4."""
    kind = index % 4
    c = 0.1 * (index + 1)
    f = np.empty_like(x)
    df = np.empty_like(x)
    k0, k1, k2, k3 = (kind == k for k in range(4))
    f[k0] = x[k0] ** 3 + x[k0] - c[k0]
    df[k0] = 3 * x[k0] ** 2 + 1
    f[k1] = np.tanh(x[k1] - 1.0) - (c[k1] % 0.9)
    df[k1] = 1 - np.tanh(x[k1] - 1.0) ** 2
    f[k2] = np.expm1(x[k2]) - c[k2]
    df[k2] = np.exp(x[k2])
    lift = np.maximum(x[k3] - 0.5, 0.0)
    f[k3] = lift**2.5 - c[k3]
    df[k3] = 2.5 * lift**1.5
    return f, df, np.abs(f) + c


def scalar_mixed(i):
    return lambda x: mixed(np.array([x]), np.array([i]))[0][0]


def test_mixed_batch_matches_brentq_and_reports_iterations():
    n = 64
    lower, upper = np.full(n, -3.0), np.full(n, 8.0)
    rng = np.random.default_rng(7)
    x0 = rng.uniform(-5, 10, n)  # partly outside the bracket: clipped
    result = bracketed_newton(mixed, x0, lower, upper, atol=1e-13)
    expected = np.array([optimize.brentq(scalar_mixed(i), -3.0, 8.0, xtol=1e-15) for i in range(n)])
    assert result.converged.all()
    np.testing.assert_allclose(result.x, expected, rtol=1e-11, atol=1e-12)
    assert np.all(result.iterations >= 1)
    assert result.iterations.max() <= 25
    assert result.x.shape == result.residual.shape == result.iterations.shape == (n,)


def test_not_converged_is_flagged_and_iterations_capped():
    lower, upper = np.full(M, -2.0), np.full(M, 30.0)
    result = bracketed_newton(
        flat_then_rising, np.full(M, -1.5), lower, upper, atol=1e-12, max_iterations=3
    )
    assert not result.converged.any()
    assert np.all(result.iterations == 3)


def test_discontinuous_function_stops_on_a_collapsed_bracket():
    """A step has no |f| <= tol point: the bracket collapses onto the jump, then it stops."""
    jump = 0.3

    def step(x, index):
        return np.where(x < jump, -1.0, 1.0), np.zeros_like(x), np.ones_like(x)

    result = bracketed_newton(
        step, np.array([0.9]), np.array([0.0]), np.array([1.0]), atol=1e-12, max_iterations=500
    )
    assert not result.converged[0]
    assert abs(result.x[0] - jump) < 1e-14
    assert result.iterations[0] < 70  # bisection to round-off, not the 500 allowed


def test_root_at_bracket_end_and_problems_leave_the_batch():
    calls = []

    def linear(x, index):
        calls.append(index.size)
        return x - np.array([0.0, 1.0, 0.25])[index], np.ones_like(x), np.ones_like(x)

    result = bracketed_newton(
        linear, np.array([0.0, 0.5, 0.5]), np.zeros(3), np.ones(3), atol=1e-15
    )
    np.testing.assert_allclose(result.x, [0.0, 1.0, 0.25], atol=1e-15)
    assert result.converged.all()
    assert result.iterations[0] == 1  # already a root: one evaluation
    assert calls[0] == 3
    assert calls[-1] < 3  # converged problems are not evaluated again


def test_stiff_equation_converges_to_round_off():
    """f = 1e12 (x - 1/3): one ulp of x moves f by ~1e-4, far above atol = 1e-12.

    The root is still located to machine precision and reported as converged.
    """
    slope = np.array([1e12, 1e15, 1.0])

    def stiff(x, index):
        return slope[index] * (x - 1 / 3), slope[index], np.abs(slope[index] * x)

    result = bracketed_newton(stiff, np.full(3, 0.9), np.zeros(3), np.ones(3), atol=1e-12, rtol=0.0)
    assert result.converged.all()
    np.testing.assert_allclose(result.x, 1 / 3, rtol=4 * np.finfo(float).eps)
    assert abs(result.residual[2]) <= 1e-12  # the well-scaled one meets atol itself
    assert result.iterations.max() < 70


# ---------------------------------------------------------------- second derivative, polish

POWER = 10.0 ** np.random.default_rng(7).uniform(-3, 3, M)


def power_law(x, index):
    """f = x^2.5 - c (x >= 0): the shape of a contact's force against its penetration."""
    lift = np.maximum(x, 0.0)
    return lift**2.5 - POWER[index], 2.5 * lift**1.5, lift**2.5 + POWER[index]


def power_law_with_second(x, index):
    return (*power_law(x, index), 3.75 * np.sqrt(np.maximum(x, 0.0)))


def power_law_with_third(x, index):
    return (*power_law_with_second(x, index), 1.875 / np.sqrt(np.maximum(x, 1e-300)))


def power_law_without_second(x, index):
    """Returns a second derivative, but never computes it (all NaN)."""
    return (*power_law(x, index), np.full(x.shape, np.nan))


@pytest.mark.parametrize(
    ("higher", "lower_order", "offset"),
    [
        # f'': Chebyshev's step (third order); from 1 % off two steps reach round-off
        # (three evaluations) where Newton needs three steps
        (power_law_with_second, power_law, 0.01),
        # f''' as well: a Newton step on the cubic Taylor polynomial follows the Chebyshev
        # step (fourth order); from 5 % off two steps, where Chebyshev alone needs three
        (power_law_with_third, power_law_with_second, 0.05),
    ],
)
def test_higher_derivatives_give_higher_order_steps(higher, lower_order, offset):
    root = POWER**0.4
    lower, upper = np.zeros(M), 2 * root + 1
    start = root * (1 + offset)
    fast = bracketed_newton(higher, start, lower, upper, atol=0.0)
    slow = bracketed_newton(lower_order, start, lower, upper, atol=0.0)
    assert fast.converged.all()
    assert slow.converged.all()
    np.testing.assert_allclose(fast.x, root, rtol=4 * np.finfo(float).eps)
    np.testing.assert_allclose(slow.x, root, rtol=4 * np.finfo(float).eps)
    assert fast.iterations.max() == 3
    assert slow.iterations.min() == 4


def test_missing_second_derivative_falls_back_to_the_curvature():
    """A NaN second derivative is "not computed": the step is the one ``curvature`` gives."""
    root = POWER**0.4
    lower, upper, start = np.zeros(M), 2 * root + 1, root * 1.01
    without = bracketed_newton(
        power_law_without_second, start, lower, upper, atol=0.0, curvature=0.6
    )
    three = bracketed_newton(power_law, start, lower, upper, atol=0.0, curvature=0.6)
    np.testing.assert_array_equal(without.x, three.x)
    np.testing.assert_array_equal(without.iterations, three.iterations)


def test_polish_takes_the_last_step_of_a_loose_solve():
    """rtol = 1e-3 stops at |f| ~ 6e-6 (x 2e-6 off); with polish x takes one more,
    unevaluated Newton step (1.6e-12 off) while the reported residual stays the evaluated one."""

    def square(x, index):
        return x * x - 2.0, 2 * x, x * x + 2.0

    args = (square, np.ones(3), np.zeros(3), np.full(3, 2.0))
    loose = bracketed_newton(*args, atol=0.0, rtol=1e-3)
    polished = bracketed_newton(*args, atol=0.0, rtol=1e-3, polish=True)
    assert loose.converged.all()
    assert polished.converged.all()
    np.testing.assert_array_equal(polished.iterations, loose.iterations)
    np.testing.assert_array_equal(polished.residual, loose.residual)
    assert np.all(np.abs(loose.x - np.sqrt(2)) > 1e-7)
    assert np.all(np.abs(polished.x - np.sqrt(2)) < 1e-11)
