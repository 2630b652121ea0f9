"""RODAS4 and its switching with the Dormand-Prince pair (mechanism.impact.rosenbrock).

* the tableau's stability function matches ``exp(z)`` to order 4 and is L-stable
  (``|R(z)| <= 1`` on the left half-plane, ``R(z) -> 0``);
* Prothero-Robinson ``y' = -lambda (y - g) + g'`` with ``g = sin t``: the error falls with
  the tolerance at ``lambda = 1`` (order 4 on fixed steps) and stays at the tolerance at
  ``lambda = 1e9``, where an explicit method needs ``lambda T / 3.3`` steps;
* a stiff linear system with a slow and a fast mode: the closed form;
* Van der Pol at ``mu = 1000``, nonlinear and stiff: scipy's Radau;
* the switching runs the explicit pair alone on a non-stiff problem and RODAS4 on a stiff
  one.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.mechanism.impact import rosenbrock

numba = pytest.importorskip("numba")
njit = numba.njit


#: the test problems of :func:`_problems`, chosen by ``p[1]``
PROTHERO_ROBINSON, LINEAR, VAN_DER_POL = 0.0, 1.0, 2.0


@njit
def _problems(t, y, impact_velocity, p, wear):
    """``p[1]`` picks the problem (one compiled integrator serves all), ``p[0]`` its
    stiffness."""
    out = np.empty(y.size)
    if p[1] == PROTHERO_ROBINSON:
        out[0] = -p[0] * (y[0] - math.sin(t)) + math.cos(t)
    elif p[1] == LINEAR:
        # modes -1 and -p[0]: y = V diag(exp(lambda t)) V^-1 y0, V = [[1, 1], [1, -1]]
        slow, fast = -1.0, -p[0]
        out[0] = 0.5 * (slow + fast) * y[0] + 0.5 * (slow - fast) * y[1]
        out[1] = 0.5 * (slow - fast) * y[0] + 0.5 * (slow + fast) * y[1]
    else:
        out[0] = y[1]
        out[1] = p[0] * (1.0 - y[0] * y[0]) * y[1] - y[0]
    return out


@njit
def _never(t, y, p, wear):
    return -1.0


@njit
def _never_and_rate(t, y, p, wear):
    return -1.0, 0.0


@pytest.fixture(scope="module")
def integrators():
    """RODAS4 alone (``False``) and switching with the explicit pair (``True``)."""
    return {
        switching: rosenbrock.bind(
            {
                "rhs": _problems,
                "gap": _never,
                "gap_and_rate": _never_and_rate,
                "SWITCHING": switching,
            },
            f"test_problems_{int(switching)}",
            cache=False,
        )
        for switching in (False, True)
    }


def run(integrate, t_end, y0, parameters, rtol, samples, max_step=math.inf):
    """States at ``samples`` and the right-hand sides spent (no contact events)."""
    result = integrate(
        0.0, t_end, np.asarray(y0, dtype=float), False, 1e-3, 1e-3,
        np.asarray(parameters, dtype=float), np.empty(0), rtol, rtol * 1e-2, max_step,
        np.asarray(samples, dtype=float), 16, False,
    )  # fmt: skip
    assert result[0] == rosenbrock.OK
    assert result[9] == 1  # one segment: no event
    return result[2], result[1]


def linear_closed_form(samples, y0, fast):
    """The ``LINEAR`` problem's states at ``samples`` from ``y0``, modes -1 and ``-fast``."""
    # y0 = a (1, 1) + b (1, -1)
    a, b = 0.5 * (y0[0] + y0[1]), 0.5 * (y0[0] - y0[1])
    slow_mode, fast_mode = np.exp(-samples), np.exp(-fast * samples)
    return np.column_stack([a * slow_mode + b * fast_mode, a * slow_mode - b * fast_mode])


def test_tableau_is_l_stable_and_consistent() -> None:
    # on y' = lambda y with the exact Jacobian, W = (1/(gamma h) - lambda), z = h lambda:
    # the stability function R(z), 1 + z + z^2/2 + z^3/6 + z^4/24 + O(z^5), R(-inf) = 0
    gamma, a, c = rosenbrock.GAMMA, rosenbrock.A, rosenbrock.C

    def stability(z: complex) -> complex:
        k = np.zeros(6, dtype=complex)
        for s in range(6):
            point = 1.0 + a[s, :s] @ k[:s]
            k[s] = (z * point + c[s, :s] @ k[:s]) / (1.0 / gamma - z)
        return 1.0 + rosenbrock.B @ k

    for z in (1e-2, 2e-2):
        taylor = sum(z**j / math.factorial(j) for j in range(5))
        assert abs(stability(z) - taylor) < 0.05 * z**5
    for z in (-1e6, -1e9, -1e12):
        assert abs(stability(z)) < 1e-5
    for z in (-1.0, -10.0, -100.0, complex(-1e-3, 30.0)):
        assert abs(stability(z)) <= 1.0


def test_prothero_robinson_converges_with_the_tolerance(integrators) -> None:
    samples = np.linspace(0.0, 10.0, 21)
    errors = []
    for rtol in (1e-5, 1e-7, 1e-9):
        states, _ = run(
            integrators[False], 10.0, [0.0], [1.0, PROTHERO_ROBINSON], rtol, samples, 0.5
        )
        errors.append(np.abs(states[:, 0] - np.sin(samples)).max())
    # observed: each hundredfold tighter tolerance ~100x smaller error
    assert errors[0] > 20 * errors[1] > 400 * errors[2]
    assert errors[2] < 1e-8


def test_prothero_robinson_order_four_on_fixed_steps(integrators) -> None:
    # max_step far below the steps the tolerance allows: fixed steps h, error ~ h^4
    errors = []
    for steps in (20, 40, 80):
        h = 2.0 / steps
        states, _ = run(integrators[False], 2.0, [0.0], [1.0, PROTHERO_ROBINSON], 1e-2, [2.0], h)
        errors.append(abs(states[0, 0] - math.sin(2.0)))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 3.6)
    assert np.all(orders < 4.6)


@pytest.mark.parametrize("switching", [False, True])
def test_prothero_robinson_stiff(integrators, switching: bool) -> None:
    stiffness, t_end = 1e9, 2.0
    samples = np.linspace(0.0, t_end, 21)
    # the steps are held to 0.01 s: RODAS4's dense output (3rd order) is ~h^4 off between
    # the steps, which the error control does not see (1.6e-6 at 0.05 s)
    states, evaluations = run(
        integrators[switching], t_end, [0.0], [stiffness, PROTHERO_ROBINSON], 1e-8, samples, 0.01
    )
    assert np.abs(states[:, 0] - np.sin(samples)).max() < 1e-7
    # an explicit method's stability alone needs lambda T / 3.3 = 6e8 steps
    assert evaluations < 5_000


def test_stiff_linear_system_closed_form(integrators) -> None:
    fast, t_end = 1e8, 2.0
    samples = np.linspace(0.0, t_end, 41)
    y0 = np.array([1.0, 0.5])
    states, evaluations = run(integrators[True], t_end, y0, [fast, LINEAR], 1e-9, samples, 0.05)
    exact = linear_closed_form(samples, y0, fast)
    np.testing.assert_allclose(states[1:], exact[1:], rtol=1e-7, atol=1e-12)
    assert evaluations < 20_000  # RK45: ~lambda T / 3.3 = 6e7 steps


def test_van_der_pol_agrees_with_radau(integrators) -> None:
    from scipy.integrate import solve_ivp

    mu, t_end = 1000.0, 1500.0
    samples = np.linspace(0.0, t_end, 31)
    states, _ = run(integrators[True], t_end, [2.0, 0.0], [mu, VAN_DER_POL], 1e-8, samples, 5.0)

    def van_der_pol(t, y):
        return [y[1], mu * (1.0 - y[0] ** 2) * y[1] - y[0]]

    reference = solve_ivp(
        van_der_pol, (0.0, t_end), [2.0, 0.0], method="Radau", rtol=1e-11, atol=1e-13,
        t_eval=samples, jac=lambda t, y: [[0.0, 1.0], [-2 * mu * y[0] * y[1] - 1.0,
                                                      mu * (1.0 - y[0] ** 2)]],
    )  # fmt: skip
    assert reference.success
    # the slow variable y_0 (order 1) through two relaxation jumps
    np.testing.assert_allclose(states[:, 0], reference.y[0], rtol=0, atol=1e-5)


def test_switching_leaves_a_non_stiff_problem_to_the_explicit_pair(integrators) -> None:
    samples = np.linspace(0.0, 10.0, 11)
    _, switching = run(integrators[True], 10.0, [0.0], [1.0, PROTHERO_ROBINSON], 1e-8, samples, 0.5)
    _, stiff_only = run(
        integrators[False], 10.0, [0.0], [1.0, PROTHERO_ROBINSON], 1e-8, samples, 0.5
    )
    # explicit: six right-hand sides a step, no Jacobian; RODAS4: eleven with it
    assert switching % 6 == 2  # the initial f and initial step's, then 6 a step
    assert switching < stiff_only
