"""RADAU5, compiled (mechanism.impact.radau), on stiff model problems.

* its steps are scipy's ``Radau``'s: on Van der Pol at ``mu = 1000`` (nonlinear, stiff)
  the two agree through the relaxation jumps, with a comparable count of right-hand
  sides;
* a stiff linear system with a slow and a fast mode: the closed form;
* Prothero-Robinson ``y' = -lambda (y - g) + g'``, ``g = sin t``: order 5 on fixed steps
  at ``lambda = 1``, the tolerance kept at ``lambda = 1e9``, where an explicit method
  needs ``lambda T / 3.3`` steps.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.mechanism.impact import radau

# the model problems of RODAS4's tests (they skip without numba): one compiled
# right-hand side, the problem picked by ``p[1]``
from tests.mechanism.impact.test_rosenbrock import (
    LINEAR,
    PROTHERO_ROBINSON,
    VAN_DER_POL,
    _never,
    _never_and_rate,
    _problems,
    linear_closed_form,
)


@pytest.fixture(scope="module")
def integrate():
    return radau.bind(
        {"rhs": _problems, "gap": _never, "gap_and_rate": _never_and_rate},
        "test_problems",
        cache=False,
    )


def run(integrate, t_end, y0, parameters, rtol, samples, max_step=math.inf, atol=None):
    """States at ``samples`` and the right-hand sides spent (no contact events)."""
    result = integrate(
        0.0, t_end, np.asarray(y0, dtype=float), False, 1e-3, 1e-3,
        np.asarray(parameters, dtype=float), np.empty(0), rtol,
        rtol * 1e-2 if atol is None else atol, max_step, np.asarray(samples, dtype=float), 16,
        False,
    )  # fmt: skip
    assert result[0] == radau.OK
    assert result[9] == 1  # one segment: no event
    return result[2], result[1]


def test_van_der_pol_agrees_with_scipy_radau(integrate) -> None:
    from scipy.integrate import solve_ivp

    mu, t_end, rtol, atol = 1000.0, 1500.0, 1e-6, 1e-8
    samples = np.linspace(0.0, t_end, 31)
    states, evaluations = run(integrate, t_end, [2.0, 0.0], [mu, VAN_DER_POL], rtol, samples,
                              atol=atol)  # fmt: skip

    def van_der_pol(t, y):
        return [y[1], mu * (1.0 - y[0] ** 2) * y[1] - y[0]]

    same = solve_ivp(van_der_pol, (0.0, t_end), [2.0, 0.0], method="Radau", rtol=rtol,
                     atol=atol, t_eval=samples)  # fmt: skip
    reference = solve_ivp(
        van_der_pol, (0.0, t_end), [2.0, 0.0], method="Radau", rtol=1e-11, atol=1e-13,
        t_eval=samples, jac=lambda t, y: [[0.0, 1.0], [-2 * mu * y[0] * y[1] - 1.0,
                                                      mu * (1.0 - y[0] ** 2)]],
    )  # fmt: skip
    assert same.success
    assert reference.success
    # the slow variable y_0 (order 1) through two relaxation jumps, as close to the
    # converged solution as scipy's Radau at the same tolerances
    ours = np.abs(states[:, 0] - reference.y[0]).max()
    theirs = np.abs(same.y[0] - reference.y[0]).max()
    assert ours < max(3 * theirs, 1e-5)
    # the same algorithm: a comparable work (the Jacobians differ: forward differences
    # here, scipy's adaptive ones)
    assert 0.5 < evaluations / same.nfev < 2.0


def test_stiff_linear_system_closed_form(integrate) -> None:
    fast, t_end = 1e8, 2.0
    samples = np.linspace(0.0, t_end, 41)
    y0 = np.array([1.0, 0.5])
    states, evaluations = run(integrate, t_end, y0, [fast, LINEAR], 1e-9, samples, 0.05)
    exact = linear_closed_form(samples, y0, fast)
    np.testing.assert_allclose(states[1:], exact[1:], rtol=1e-7, atol=1e-12)
    assert evaluations < 20_000  # RK45: ~lambda T / 3.3 = 6e7 steps


def test_prothero_robinson_order_five_on_fixed_steps(integrate) -> None:
    # max_step far below the steps the tolerance allows: fixed steps h, error ~ h^5
    errors = []
    for steps in (10, 20, 40):
        h = 2.0 / steps
        states, _ = run(integrate, 2.0, [0.0], [1.0, PROTHERO_ROBINSON], 1e-3, [2.0], h)
        errors.append(abs(states[0, 0] - math.sin(2.0)))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 4.5)
    assert np.all(orders < 5.6)


def test_prothero_robinson_stiff(integrate) -> None:
    stiffness, t_end = 1e9, 2.0
    samples = np.linspace(0.0, t_end, 21)
    states, evaluations = run(
        integrate, t_end, [0.0], [stiffness, PROTHERO_ROBINSON], 1e-8, samples, 0.01
    )
    assert np.abs(states[:, 0] - np.sin(samples)).max() < 1e-7
    # an explicit method's stability alone needs lambda T / 3.3 = 6e8 steps
    assert evaluations < 5_000


def test_step_after_a_newton_divergence() -> None:
    # the step control's Python source (bind compiles it): after the sweeps diverged on
    # h_d with a fresh Jacobian and converged on h_d / 2, the steps stay below h_d / 2,
    # growing by NEWTON_RELAX a step, until two steps in a row converge in one sweep
    control = np.zeros(9)
    control[radau.H_DIVERGED] = 2e-4
    h, tiny_error, sweeps, rate = 1e-4, 1e-6, 2, 0.05
    steps = []
    for _ in range(3):
        h, recompute = radau._after_step(h, h, tiny_error, sweeps, rate, control)
        steps.append(h)
        assert not recompute  # two sweeps at 0.05: the Jacobian is kept
    relax = radau.NEWTON_RELAX
    assert relax < radau.KEEP_STEP < relax**2
    np.testing.assert_allclose(steps, [1e-4, 1e-4, 1e-4 * relax**2], rtol=1e-12)
    for _ in range(radau.FAST_CLEAR):
        h, _ = radau._after_step(h, h, tiny_error, 1, -1.0, control)
    assert control[radau.H_DIVERGED] == 0.0
    # unbounded, the tiny error lets the step grow tenfold
    assert radau._after_step(h, h, tiny_error, 1, -1.0, control)[0] == pytest.approx(
        radau.MAX_FACTOR * h
    )
    # two sweeps at a slow rate refresh the Jacobian
    assert radau._after_step(h, h, tiny_error, 2, 0.5, control)[1]
