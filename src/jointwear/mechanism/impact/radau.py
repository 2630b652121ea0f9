r"""A stiff integration through the contact events: the Radau IIA method RADAU5, compiled.

Where the squeeze film of a lubricated joint holds the pin on the wall and the film's
wedge speed passes through zero, the film force is a steep ramp in the pin's radial
speed: a Rosenbrock method (:mod:`jointwear.mechanism.impact.rosenbrock`), which
linearises once a step, is held there to steps of a fraction of a microsecond. A fully
implicit method iterates its stages to the nonlinear solution instead.

RADAU5 (Hairer & Wanner [1]_, Sec. IV.8, their code ``radau5.f``; the algorithm and
constants of ``scipy.integrate.Radau``, which follows it) is the 3-stage Radau IIA
collocation method of order 5, L-stable and stiffly accurate. The stage increments
``Z_i = Y_i - y_0`` at ``t + c_i h`` solve ``Z = h (A \otimes I) F(Z)``; with ``A =
T diag(mu_r, mu_c, conj mu_c)^{-1} T^{-1}`` the simplified Newton iteration on ``W = T^{-1}
Z`` needs one real and one complex linear system a sweep,

.. math::

    (\mu_r / h\, I - J)\, \Delta W_1 = \sum_i (T^{-1})_{1i} F_i - \mu_r / h\, W_1, \qquad
    (\mu_c / h\, I - J)\, (\Delta W_2 + i \Delta W_3) = \ldots ,

with the same ``J`` (a forward difference, step :data:`DIFFERENCE_STEP`, over the first
:data:`JACOBIAN_COLUMNS` components) and factors kept over the sweeps and steps. The
sweeps stop when the predicted remaining error ``rate / (1 - rate) ||dW||`` is below
``max(10 eps / r, min(0.03, r^{1/2}))``, ``r = 0.1 rtol^{2/3}`` (``radau5.f``'s; scipy's
``Radau`` takes ``r = rtol``), after the first sweep with the rate of the last sweeps
(``radau5.f``'s ``FACCON``, raised to the power 0.8 a step), and give up at a rate >= 1
or a prediction that six sweeps cannot reach it: then the Jacobian is refreshed, and if
it was fresh the step halved. The error estimate is the embedded 3rd-order one filtered
by one more solve with the real factors, ``err = (mu_r/h I - J)^{-1} (f_0 + sum_i e_i
Z_i / h)`` (after a rejection, once more with ``f(t, y_0 + err)``); the new step is ``h
err^{-1/4}`` with Gustafsson's predictive controller [2]_, a safety factor that falls
with the Newton sweeps, at most 10 times larger (5 times smaller after a rejection, half
the step where the sweeps fail); the step (and its factors) is kept unless it would grow
by 1.2 or more, and the Jacobian is recomputed after a step whose sweeps converged
slowly (more than two at a rate above 1e-3, or two at a rate above :data:`SLOW_RATE`).
Where the sweeps diverged with a fresh Jacobian, the steps stay below
:data:`NEWTON_MARGIN` times the step that diverged (so the halved step that converged is
not followed by a larger one, as in ``radau5.f``), a bound relaxed by
:data:`NEWTON_RELAX` an accepted step and dropped after :data:`FAST_CLEAR` one-sweep
steps: where the film's force bends within a step, the error estimate alone lets the
step grow tenfold into the same divergence, each time paying the failed sweeps, a
Jacobian and two factorizations. The first guess of the stages is the previous step's
collocation polynomial, which is also the dense output (cubic in ``s``).

The initial step, the contact events, the penetration maxima and the samples are those
of :mod:`jointwear.mechanism.impact.rosenbrock` (its functions are compiled again here
with the system, on RADAU5's dense output); a contact event starts a new segment with
a fresh Jacobian and no extrapolated guess. :func:`bind` compiles the integration for
one system, as :func:`jointwear.mechanism.impact.rosenbrock.bind` does, with the same
arguments and results.

References
----------
.. [1] E. Hairer, G. Wanner, *Solving Ordinary Differential Equations II: Stiff and
   Differential-Algebraic Problems*, 2nd ed., Springer (1996), Sec. IV.8 (the code
   ``radau5.f``).
.. [2] K. Gustafsson, "Control-theoretic techniques for stepsize selection in implicit
   Runge-Kutta methods", ACM Trans. Math. Softw. 20 (1994) 496-517.
"""

from __future__ import annotations

import math
import types
from collections.abc import Callable
from typing import Any

import numpy as np

from jointwear.mechanism.impact import rosenbrock

__all__ = ["MU_COMPLEX", "MU_REAL", "STATUS", "TI", "C", "E", "P", "T", "bind"]

OK, STEP_TOO_SMALL, TOO_MANY_EVENTS, CHATTER, SEPARATED = (
    rosenbrock.OK, rosenbrock.STEP_TOO_SMALL, rosenbrock.TOO_MANY_EVENTS, rosenbrock.CHATTER,
    rosenbrock.SEPARATED,
)  # fmt: skip
#: status codes of the bound ``integrate``, as RODAS4's
STATUS = rosenbrock.STATUS

#: RODAS4's functions that serve RADAU5 as they are (the norm, the small LU, the dense
#: output's evaluation, the events, the samples, the initial step): :func:`bind` compiles
#: them again with the system, callees first
_SHARED = (
    "_rms",
    "_lu_factor",
    "_lu_solve",
    "_dense",
    "_event_value",
    "_root",
    "_take_samples",
    "_initial_step",
    "_step_events",
    "_segment_end",
    "_open_segment",
    "_close_segment",
    "_records",
)
(
    _rms, _lu_factor, _lu_solve, _dense, _event_value, _root, _take_samples, _initial_step,
    _step_events, _segment_end, _open_segment, _close_segment, _records,
) = (getattr(rosenbrock, name) for name in _SHARED)  # fmt: skip

_S6 = 6**0.5
#: the nodes ``c_i`` of Radau IIA (order 5)
C = np.array([(4 - _S6) / 10, (4 + _S6) / 10, 1.0])
#: the embedded error estimate's weights on ``Z_i / h``
E = np.array([-13 - 7 * _S6, -13 + 7 * _S6, -1.0]) / 3
#: the eigenvalues of ``A^{-1}``: one real, a complex pair
MU_REAL = 3 + 3 ** (2 / 3) - 3 ** (1 / 3)
MU_COMPLEX = 3 + 0.5 * (3 ** (1 / 3) - 3 ** (2 / 3)) - 0.5j * (3 ** (5 / 6) + 3 ** (7 / 6))
#: ``A^{-1} = T diag(mu) T^{-1}`` in real form (scipy's, ``radau5.f``'s)
T = np.array(
    [
        [0.09443876248897524, -0.14125529502095421, 0.03002919410514742],
        [0.25021312296533332, 0.20412935229379994, -0.38294211275726192],
        [1.0, 1.0, 0.0],
    ]
)
TI = np.array(
    [
        [4.17871859155190428, 0.32768282076106237, 0.52337644549944951],
        [-4.17871859155190428, -0.32768282076106237, 0.47662355450055044],
        [0.50287263494578682, -2.57192694985560522, 0.59603920482822492],
    ]
)
#: the collocation polynomial: ``y(t + s h) = y_0 + (Z^T P) (s, s^2, s^3)``
P = np.array(
    [
        [13 / 3 + 7 * _S6 / 3, -23 / 3 - 22 * _S6 / 3, 10 / 3 + 5 * _S6],
        [13 / 3 - 7 * _S6 / 3, -23 / 3 + 22 * _S6 / 3, 10 / 3 - 5 * _S6],
        [1 / 3, -8 / 3, 10 / 3],
    ]
)
NEWTON_MAXITER = 6
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
#: the largest step growth that keeps the step (and its factors) unchanged
KEEP_STEP = 1.2
#: how many leading state components the right-hand side depends on (-1: all); bound
JACOBIAN_COLUMNS = -1
#: the forward differences' step over ``max(|y_j|, 1)``; bound (as RODAS4's)
DIFFERENCE_STEP = 1.4901161193847656e-08

#: a Newton rate above which the Jacobian is recomputed after the step even if the sweeps
#: converged in two (a rate of 0.3-0.6 in two sweeps foretells a failure on the next step)
SLOW_RATE = 0.3
#: after the sweeps diverged on a step ``h_d`` with a fresh Jacobian, the next steps stay
#: below ``NEWTON_MARGIN h_d``, a bound that grows by ``NEWTON_RELAX`` an accepted step
#: and is dropped after ``FAST_CLEAR`` steps in a row that converged in one sweep (a
#: divergence that was the rounding of a stiff linear system's sweeps, not the film)
NEWTON_MARGIN = 0.5
NEWTON_RELAX = 1.1
FAST_CLEAR = 2

#: the step control's state, indices of ``control``: the previous step's prediction and
#: error norm (``HAVE_OLD``: whether they exist), the Jacobian fresh at the step's start,
#: the factors valid, a previous step's polynomial to start the stages from, the step
#: whose sweeps diverged last (:data:`NEWTON_MARGIN`; 0: none), ``radau5.f``'s ``FACCON``
#: (the last Newton rate's ``rate / (1 - rate)``, 1 at a segment's start), the accepted
#: steps in a row that took one sweep
H_OLD, ERR_OLD, HAVE_OLD, CURRENT_JAC, LU_VALID, HAVE_GUESS = 0, 1, 2, 3, 4, 5
H_DIVERGED, FACCON, FAST_STEPS = 6, 7, 8


def rhs(t, y, impact_velocity, p, wear):  # type: ignore[no-untyped-def]
    """The system's right-hand side (supplied by :func:`bind`)."""
    raise NotImplementedError("radau.rhs: compile the integrator with bind()")


def gap(t, y, p, wear):  # type: ignore[no-untyped-def]
    """The system's signed penetration (supplied by :func:`bind`)."""
    raise NotImplementedError("radau.gap: compile the integrator with bind()")


def gap_and_rate(t, y, p, wear):  # type: ignore[no-untyped-def]
    """The system's penetration and its rate (supplied by :func:`bind`)."""
    raise NotImplementedError("radau.gap_and_rate: compile the integrator with bind()")


def _radau_jacobian(t, y, f, v_imp, p, wear, jac, work):  # type: ignore[no-untyped-def]
    """Forward-difference ``df/dy`` into ``jac``; the count of right-hand sides [-]."""
    n = y.size
    columns = n if JACOBIAN_COLUMNS < 0 else JACOBIAN_COLUMNS
    for j in range(n):
        work[j] = y[j]
    for j in range(columns):
        step = DIFFERENCE_STEP * max(abs(y[j]), 1.0)
        work[j] = y[j] + step
        step = work[j] - y[j]
        shifted = rhs(t, work, v_imp, p, wear)
        for i in range(n):
            jac[i, j] = (shifted[i] - f[i]) / step
        work[j] = y[j]
    for j in range(columns, n):
        for i in range(n):
            jac[i, j] = 0.0
    return columns


def _factor(jac, h, lu_real, piv_real, lu_complex, piv_complex):  # type: ignore[no-untyped-def]
    """LU of ``mu_r / h I - J`` and ``mu_c / h I - J``; False if one is singular."""
    n = jac.shape[0]
    for i in range(n):
        for j in range(n):
            lu_real[i, j] = -jac[i, j]
            lu_complex[i, j] = -jac[i, j]
        lu_real[i, i] += MU_REAL / h
        lu_complex[i, i] += MU_COMPLEX / h
    if not _lu_factor(lu_real, piv_real):
        return False
    return _lu_factor(lu_complex, piv_complex)


def _collocation(t, y, h, scale, tol, v_imp, p, wear, lu_real, piv_real, lu_complex,
                 piv_complex, z, w, stages, point, dw, dw_real, dw_complex, control):  # type: ignore[no-untyped-def]  # fmt: skip
    """Simplified Newton sweeps on the stages from the guess in ``z`` (``Z``, overwritten
    by the solution): ``(converged, sweeps, rate, right-hand sides)``, ``rate`` -1 if
    there was one sweep only. One sweep suffices where the last known rate (``control``'s
    ``FACCON``, ``radau5.f``'s) predicts the remaining error below ``tol``."""
    n = y.size
    m_real, m_complex = MU_REAL / h, MU_COMPLEX / h
    for s in range(3):
        for i in range(n):
            w[s, i] = TI[s, 0] * z[0, i] + TI[s, 1] * z[1, i] + TI[s, 2] * z[2, i]
    norm_old, rate, nfev, sweeps = -1.0, -1.0, 0, 0
    faccon = max(control[FACCON], 2.220446049250313e-16) ** 0.8
    control[FACCON] = faccon
    for k in range(NEWTON_MAXITER):
        sweeps = k + 1
        finite = True
        for s in range(3):
            for i in range(n):
                point[i] = y[i] + z[s, i]
            value = rhs(t + C[s] * h, point, v_imp, p, wear)
            nfev += 1
            for i in range(n):
                stages[s, i] = value[i]
                finite = finite and math.isfinite(value[i])
        if not finite:
            break
        for i in range(n):
            dw_real[i] = (
                TI[0, 0] * stages[0, i] + TI[0, 1] * stages[1, i] + TI[0, 2] * stages[2, i]
                - m_real * w[0, i]
            )  # fmt: skip
            re = TI[1, 0] * stages[0, i] + TI[1, 1] * stages[1, i] + TI[1, 2] * stages[2, i]
            im = TI[2, 0] * stages[0, i] + TI[2, 1] * stages[1, i] + TI[2, 2] * stages[2, i]
            dw_complex[i] = complex(re, im) - m_complex * complex(w[1, i], w[2, i])
        _lu_solve(lu_real, piv_real, dw_real)
        _lu_solve(lu_complex, piv_complex, dw_complex)
        total = 0.0
        for i in range(n):
            dw[0, i], dw[1, i], dw[2, i] = dw_real[i], dw_complex[i].real, dw_complex[i].imag
            for s in range(3):
                ratio = dw[s, i] / scale[i]
                total += ratio * ratio
        norm = math.sqrt(total / (3 * n))
        if norm_old >= 0.0:
            rate = norm / norm_old
            if rate >= 1.0 or rate ** (NEWTON_MAXITER - k) / (1.0 - rate) * norm > tol:
                break
            control[FACCON] = rate / (1.0 - rate)
        for s in range(3):
            for i in range(n):
                w[s, i] += dw[s, i]
        for s in range(3):
            for i in range(n):
                z[s, i] = T[s, 0] * w[0, i] + T[s, 1] * w[1, i] + T[s, 2] * w[2, i]
        if norm == 0.0 or control[FACCON] * norm < tol:
            return True, sweeps, rate, nfev
        norm_old = norm
    return False, sweeps, rate, nfev


def _predict_factor(h_abs, h_abs_old, err, err_old, have_old):  # type: ignore[no-untyped-def]
    """scipy's ``predict_factor``: ``err^{-1/4}``, Gustafsson's two-step prediction once
    there is a previous step [-]."""
    if err == 0.0:
        return math.inf
    multiplier = 1.0
    if have_old:
        multiplier = h_abs / h_abs_old * (err_old / err) ** 0.25
    return min(1.0, multiplier) * err**-0.25


def _guess(t, h, y, z, q_old, t_old, h_old, y_old, have_guess):  # type: ignore[no-untyped-def]
    """The stages' first guess: the previous step's polynomial at ``t + c_i h``, or 0."""
    for s in range(3):
        if have_guess:
            # _dense's polynomial, evaluated in place (no array a stage)
            x = (t + C[s] * h - t_old) / h_old
            for i in range(y.size):
                value = y_old[i] + h_old * (
                    q_old[i, 0] * x + q_old[i, 1] * x * x + q_old[i, 2] * x**3 + q_old[i, 3] * x**4
                )
                z[s, i] = value - y[i]
        else:
            for i in range(y.size):
                z[s, i] = 0.0


def _error_norm(err, y, y_new, rtol, atol):  # type: ignore[no-untyped-def]
    """``||err / (atol + rtol max(|y|, |y_new|))||_rms`` without an array for the scale."""
    total = 0.0
    for i in range(err.size):
        ratio = err[i] / (atol + max(abs(y[i]), abs(y_new[i])) * rtol)
        total += ratio * ratio
    return math.sqrt(total / err.size)


def _error(t, y, y_new, f, z, h, rejected, v_imp, p, wear, lu_real, piv_real, err, ze, rtol, atol):  # type: ignore[no-untyped-def]  # fmt: skip
    """The embedded estimate filtered by the real factors: ``(error norm, right-hand
    sides)``; after a rejection, filtered once more through ``f(t, y + err)``."""
    n = y.size
    for i in range(n):
        ze[i] = (E[0] * z[0, i] + E[1] * z[1, i] + E[2] * z[2, i]) / h
        err[i] = f[i] + ze[i]
        y_new[i] = y[i] + z[2, i]
    _lu_solve(lu_real, piv_real, err)
    norm = _error_norm(err, y, y_new, rtol, atol)
    nfev = 0
    if rejected and norm > 1.0:
        value = rhs(t, y + err, v_imp, p, wear)
        nfev = 1
        for i in range(n):
            err[i] = value[i] + ze[i]
        _lu_solve(lu_real, piv_real, err)
        norm = _error_norm(err, y, y_new, rtol, atol)
    return (norm if math.isfinite(norm) else math.inf), nfev


def _attempt(t, t_end, y, f, h_abs, min_step, tol, v_imp, p, wear, jac, work, lu_real,
             piv_real, lu_complex, piv_complex, z, w, stages, point, dw, dw_real, dw_complex,
             err, ze, y_new, rtol, atol, control, q_old, t_old, h_old, y_old, scale):  # type: ignore[no-untyped-def]  # fmt: skip
    """Steps from ``(t, y)`` until one is accepted, into ``y_new`` and ``z`` (scipy's
    ``Radau._step_impl``): ``(accepted, t_new, h, error norm, sweeps, rate, right-hand
    sides)``."""
    nfev = 0
    rejected = False
    while True:
        if h_abs < min_step:
            return False, t, h_abs, 0.0, 0, -1.0, nfev
        t_new = min(t + h_abs, t_end)
        h = t_new - t
        h_abs = h
        _guess(t, h, y, z, q_old, t_old, h_old, y_old, control[HAVE_GUESS] != 0.0)
        for i in range(y.size):
            scale[i] = atol + abs(y[i]) * rtol
        converged, sweeps, rate = False, 0, -1.0
        while not converged:
            if control[LU_VALID] == 0.0:
                if not _factor(jac, h, lu_real, piv_real, lu_complex, piv_complex):
                    break
                control[LU_VALID] = 1.0
            converged, sweeps, rate, spent = _collocation(
                t, y, h, scale, tol, v_imp, p, wear, lu_real, piv_real, lu_complex,
                piv_complex, z, w, stages, point, dw, dw_real, dw_complex, control,
            )  # fmt: skip
            nfev += spent
            if not converged:
                if control[CURRENT_JAC] != 0.0:
                    control[H_DIVERGED] = h
                    break
                nfev += _radau_jacobian(t, y, f, v_imp, p, wear, jac, work)
                control[CURRENT_JAC], control[LU_VALID] = 1.0, 0.0
                _guess(t, h, y, z, q_old, t_old, h_old, y_old, control[HAVE_GUESS] != 0.0)
        if not converged:
            h_abs *= 0.5
            control[LU_VALID] = 0.0
            continue
        error_norm, spent = _error(t, y, y_new, f, z, h, rejected, v_imp, p, wear, lu_real,
                                   piv_real, err, ze, rtol, atol)  # fmt: skip
        nfev += spent
        if error_norm <= 1.0:
            return True, t_new, h, error_norm, sweeps, rate, nfev
        safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + sweeps)
        factor = _predict_factor(h_abs, control[H_OLD], error_norm, control[ERR_OLD],
                                 control[HAVE_OLD] != 0.0)  # fmt: skip
        h_abs *= max(MIN_FACTOR, safety * factor)
        control[LU_VALID] = 0.0
        rejected = True


def _after_step(h, h_abs_predicted, error_norm, sweeps, rate, control):  # type: ignore[no-untyped-def]
    """The next step's size after an accepted one of ``h``; whether to recompute the
    Jacobian at the new point (the factors marked stale with a new step)."""
    recompute = (sweeps > 2 and rate > 1e-3) or rate > SLOW_RATE
    safety = 0.9 * (2 * NEWTON_MAXITER + 1) / (2 * NEWTON_MAXITER + sweeps)
    factor = _predict_factor(h, control[H_OLD], error_norm, control[ERR_OLD],
                             control[HAVE_OLD] != 0.0)  # fmt: skip
    factor = min(MAX_FACTOR, safety * factor)
    control[FAST_STEPS] = control[FAST_STEPS] + 1.0 if sweeps == 1 else 0.0
    if control[FAST_STEPS] >= FAST_CLEAR:
        control[H_DIVERGED] = 0.0
    if control[H_DIVERGED] > 0.0:
        factor = min(factor, max(NEWTON_MARGIN * control[H_DIVERGED] / h, 1.0))
        control[H_DIVERGED] *= NEWTON_RELAX
    if not recompute and factor < KEEP_STEP:
        factor = 1.0
    else:
        control[LU_VALID] = 0.0
    control[H_OLD], control[ERR_OLD], control[HAVE_OLD] = h_abs_predicted, error_norm, 1.0
    return h * factor, recompute


def _accept(t_new, y_new, h, h_predicted, error_norm, sweeps, rate, v_imp, p, wear, jac, work,
            z, q, control):  # type: ignore[no-untyped-def]  # fmt: skip
    """After an accepted step to ``(t_new, y_new)``: the next step's size, ``f(t_new,
    y_new)`` and the right-hand sides spent; the Jacobian recomputed where the sweeps were
    slow, the step's polynomial into ``q``."""
    h_abs, recompute = _after_step(h, h_predicted, error_norm, sweeps, rate, control)
    f_new = rhs(t_new, y_new, v_imp, p, wear)
    nfev = 1
    if recompute:
        nfev += _radau_jacobian(t_new, y_new, f_new, v_imp, p, wear, jac, work)
    control[CURRENT_JAC] = 1.0 if recompute else 0.0
    _collocation_interpolant(z, h, q)
    control[HAVE_GUESS] = 1.0
    return h_abs, f_new, nfev


def _radau_work(n):  # type: ignore[no-untyped-def]
    """The Jacobian, a state, the real and complex LUs with their pivots, ``Z``, ``W``,
    the stages' right-hand sides, a stage point, ``dW`` (real, its real and complex
    parts), the error and ``Z E / h``, the dense output's coefficients, the control, the
    Newton sweeps' scale."""
    return (
        np.zeros((n, n)), np.empty(n), np.empty((n, n)), np.zeros(n, dtype=np.int64),
        np.empty((n, n), dtype=np.complex128), np.zeros(n, dtype=np.int64), np.zeros((3, n)),
        np.empty((3, n)), np.empty((3, n)), np.empty(n), np.empty((3, n)), np.empty(n),
        np.empty(n, dtype=np.complex128), np.empty(n), np.empty(n), np.zeros((n, 4)),
        np.zeros(9), np.empty(n),
    )  # fmt: skip


def _collocation_interpolant(z, h, q):  # type: ignore[no-untyped-def]
    """The step's collocation polynomial as ``q`` of RODAS4's dense output: ``Z^T P / h``."""
    for i in range(z.shape[1]):
        for c in range(3):
            q[i, c] = (z[0, i] * P[0, c] + z[1, i] * P[1, c] + z[2, i] * P[2, c]) / h
        q[i, 3] = 0.0


def integrate(
    t0, t_end, y0, in_contact, v_imp, floor, p, wear, rtol, atol, max_step, samples, capacity,
    stop_on_separation,
):  # type: ignore[no-untyped-def]  # fmt: skip
    """Integrate through the contact events by RADAU5; states at ``samples``.

    The arguments and the returned tuple are those of
    :func:`jointwear.mechanism.impact.rosenbrock.integrate`.
    """
    n = y0.size
    sample_states, sample_segment, seg_start, seg_end, seg_contact, seg_velocity, seg_rate = (
        _records(samples.size, capacity, n)
    )
    peak_t, peak_y = np.empty(capacity), np.empty((capacity, n))
    peak_segment = np.zeros(capacity, dtype=np.int64)
    n_seg = n_peaks = nfev = next_sample = stalled = 0
    status = OK
    (jac, work, lu_real, piv_real, lu_complex, piv_complex, z, w, stages, point, dw, dw_real,
     dw_complex, err, ze, q, control, scale) = _radau_work(n)  # fmt: skip
    # radau5.f's stopping test, from the tolerance it transforms for its error control
    # (0.1 rtol^{2/3}): at rtol = 1e-8 the sweeps stop at 7e-4 of the local error allowed,
    # where scipy's Radau (rtol itself) sweeps on to 1e-4
    newton_rtol = 0.1 * rtol ** (2.0 / 3.0)
    tol = max(10 * 2.220446049250313e-16 / newton_rtol, min(0.03, newton_rtol**0.5))
    t, y = t0, y0.copy()
    t_old, h_old, y_old = t0, 1.0, y0.copy()
    while status == OK:
        full, f, h_abs, g, rate = _open_segment(
            t, y, t_end, in_contact, v_imp, p, wear, rtol, atol, max_step, n_seg, capacity,
            seg_start, seg_contact, seg_velocity, seg_rate,
        )  # fmt: skip
        if full:
            status = TOO_MANY_EVENTS
            break
        nfev += 2 + _radau_jacobian(t, y, f, v_imp, p, wear, jac, work)
        control[:] = 0.0
        control[CURRENT_JAC], control[FACCON] = 1.0, 1.0
        event = False
        while t < t_end:
            min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
            if h_abs > max_step or h_abs < min_step:
                h_abs = max_step if h_abs > max_step else min_step
                control[HAVE_OLD] = 0.0
            h_predicted = h_abs
            y_new = np.empty(n)
            ok, t_new, h, error_norm, sweeps, newton_rate, spent = _attempt(
                t, t_end, y, f, h_abs, min_step, tol, v_imp, p, wear, jac, work, lu_real,
                piv_real, lu_complex, piv_complex, z, w, stages, point, dw, dw_real, dw_complex,
                err, ze, y_new, rtol, atol, control, q, t_old, h_old, y_old, scale,
            )  # fmt: skip
            nfev += spent
            if not ok:
                status = STEP_TOO_SMALL
                break
            h_abs, f_new, spent = _accept(
                t_new, y_new, h, h_predicted, error_norm, sweeps, newton_rate, v_imp, p, wear,
                jac, work, z, q, control,
            )  # fmt: skip
            nfev += spent
            t_old, h_old, y_old = t, h, y
            g_new, rate_new = gap_and_rate(t_new, y_new, p, wear)
            crossed, t_stop, next_sample, n_peaks = _step_events(
                in_contact, g, rate, g_new, rate_new, t, t_new, h, t_end, y, q, p, wear,
                samples, next_sample, sample_states, sample_segment, n_seg, peak_t, peak_y,
                peak_segment, n_peaks,
            )  # fmt: skip
            if crossed:
                t, y, event = t_stop, _dense(t_stop, t, h, y, q), True
                break
            t, y, f, g = t_new, y_new, f_new, g_new
            rate = rate_new if in_contact else rate
        if status != OK:
            break
        status, done, n_seg, stalled, v_imp, in_contact = _close_segment(
            t, y, p, wear, in_contact, event, stop_on_separation, seg_start, seg_end, seg_rate,
            n_seg, stalled, v_imp, floor,
        )  # fmt: skip
        if done:
            break
    return (
        status, nfev, sample_states, sample_segment, seg_start, seg_end, seg_contact,
        seg_velocity, seg_rate, n_seg, peak_t, peak_y, peak_segment, n_peaks,
    )  # fmt: skip


_ORDER = (
    "_radau_jacobian",
    "_factor",
    "_collocation",
    "_predict_factor",
    "_guess",
    "_error_norm",
    "_error",
    "_attempt",
    "_after_step",
    "_collocation_interpolant",
    "_accept",
    "_radau_work",
    "integrate",
)


def bind(system: dict[str, Any], tag: str, cache: bool = True) -> Callable[..., tuple[Any, ...]]:
    """:func:`integrate` compiled for one contact system.

    Parameters
    ----------
    system : dict
        The system's compiled ``rhs``, ``gap`` and ``gap_and_rate`` (the signatures of
        :mod:`jointwear.mechanism.impact.rosenbrock`) and optionally
        ``JACOBIAN_COLUMNS`` and ``DIFFERENCE_STEP`` [-].
    tag : str
        Names the compiled functions' disk-cache entries: it must change whenever the
        system's functions do [-].
    cache : bool
        Cache the machine code on disk, next to the modules.

    Returns
    -------
    callable
        The compiled :func:`integrate`.
    """
    from numba import njit

    namespace = dict(globals())
    namespace.update(system)
    for name in (*_SHARED, *_ORDER):
        source: Any = namespace[name]
        clone = types.FunctionType(
            source.__code__, namespace, name, source.__defaults__, source.__closure__
        )
        clone.__qualname__ = f"{source.__qualname__}_radau_{tag}"
        clone.__module__ = source.__module__
        clone.__doc__ = source.__doc__
        namespace[name] = njit(cache=cache)(clone)
    return namespace["integrate"]
