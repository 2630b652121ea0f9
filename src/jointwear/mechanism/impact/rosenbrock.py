r"""A stiff integration through the contact events: the Rosenbrock method RODAS4, compiled.

The oil film of a lubricated joint (:mod:`jointwear.mechanism.impact.film`) damps the
pin's approach to the wall with a squeeze term that grows like ``(1 - eps_f^2)^{-5/2}``:
with the pin on the wall or in the transition band its damping is 1e8-1e10 N s/m,
which over the body's mass puts eigenvalues of -1e7 to -1e9 1/s into the equations of
motion. An explicit method (``RK45-compiled``) is then held by its stability, not its
accuracy, to steps of ``~3/|lambda|``: 10^6-10^8 right-hand sides per revolution where a
dry one needs 10^4. A linearly implicit method is not.

RODAS4 (Hairer & Wanner [1]_, Sec. IV.7; the coefficients of their code ``rodas.f``,
method 1) is a Rosenbrock method of order 4 with an embedded 3rd-order solution, six
stages, L-stable and stiffly accurate, with a 3rd-order dense output. With
``W = 1/(gamma h) I - J``, ``J = df/dy`` and ``f_t = df/dt`` at the step's start,
each stage solves one linear system with the same matrix:

.. math::

    W k_i = f\Big(t + \alpha_i h,\; y + \sum_{j<i} a_{ij} k_j\Big)
            + \gamma_i h f_t + \frac1h \sum_{j<i} c_{ij} k_j, \qquad
    y_1 = y + \sum_j m_j k_j, \qquad \mathrm{err} = k_6 ,

and the dense output is ``y(t + s h) = (1 - s) y_0 + s (y_1 + (1 - s)(q_3 + s q_4))``,
``q_3, q_4`` sums of the ``k_j``. ``J`` and ``f_t`` are forward differences (step
:data:`DIFFERENCE_STEP`, over the first :data:`JACOBIAN_COLUMNS` state components: the
slider-crank's right-hand side does not depend on its crank work), once per step and
kept for the retries of a rejected one. The step control is ``rodas.f``'s: the error
norm ``||err / (atol + rtol max(|y_0|, |y_1|))||_rms`` (that of ``RK45``), the new step
``h / max(1/6, min(5, err^{1/4} / 0.9))`` with Gustafsson's predictive controller [2]_
after the first accepted step, no growth after a rejection, a tenth of the step after
a rejected first one.

**Switching.** Where the equations are not stiff (a pin flying well inside the
clearance, a thin film) RODAS4's eleven right-hand sides a step (five stages, the one
at the new point, five for the Jacobian) buy nothing over the six of the explicit
Dormand-Prince pair of ``RK45`` (:mod:`jointwear.mechanism.impact.dormand_prince`, its
step control). Each integration starts with the explicit pair and watches DOPRI5's
stiffness test (Hairer, Nørsett & Wanner [3]_, Sec. II.10): ``h |lambda|``, ``|lambda|``
estimated by ``||k_7 - k_6|| / ||y_1 - y_6||`` (both stages at ``t + h``), above 3.25
on fifteen accepted steps (six in a row below it start the count again) hands over to
RODAS4; RODAS4 hands back once the step it takes is below
:data:`EXPLICIT_CHEAPER` times the explicit pair's stability limit ``3.25 / |lambda|``
on fifteen steps in a row, ``|lambda|`` the growth of ``||J^m x||`` (a few products).

The initial step and the contact events are those of ``RK45-compiled``
(:mod:`jointwear.mechanism.slider_crank._contact_impact_rk`): a gap rising or falling
through zero ends the segment at its root on the step's dense output (the explicit
pair's 4th-order one or RODAS4's, both written as a quartic in ``s``; bisection to ``4
eps |t|``), a gap rate falling through zero in contact records a penetration maximum,
and the states at the sample times are taken from the dense output as the steps pass
them.

The functions below are written once, for any contact system: they call ``rhs``,
``gap`` and ``gap_and_rate`` of the system, which :func:`bind` supplies by compiling
them in a namespace that holds the system's compiled functions (as
:mod:`jointwear.mechanism.impact.compiled_film` compiles the film force), so that the
whole integration runs compiled and is cached on disk per system. The signature of
the system functions: ``rhs(t, y, impact_velocity, p, wear) -> dy/dt``, ``gap(t, y,
p, wear)`` and ``gap_and_rate(t, y, p, wear)``, ``p`` and ``wear`` float arrays.

References
----------
.. [1] E. Hairer, G. Wanner, *Solving Ordinary Differential Equations II: Stiff and
   Differential-Algebraic Problems*, 2nd ed., Springer (1996), Sec. IV.7 (RODAS4,
   Table 7.2 and the code ``rodas.f``).
.. [2] K. Gustafsson, "Control-theoretic techniques for stepsize selection in implicit
   Runge-Kutta methods", ACM Trans. Math. Softw. 20 (1994) 496-517.
.. [3] E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary Differential Equations I:
   Nonstiff Problems*, 2nd ed., Springer (1993), Sec. II.10 (the code ``dopri5.f``).
"""

from __future__ import annotations

import math
import types
from collections.abc import Callable
from typing import Any

import numpy as np

from jointwear.mechanism.impact import dormand_prince

__all__ = [
    "ALPHA",
    "DENSE",
    "GAMMA",
    "GAMMA_SUM",
    "STATUS",
    "A",
    "B",
    "C",
    "bind",
]

#: status codes of the bound ``integrate`` (as ``_contact_impact_rk``'s)
OK, STEP_TOO_SMALL, TOO_MANY_EVENTS, CHATTER, SEPARATED = 0, 1, 2, 3, 4
STATUS = {
    STEP_TOO_SMALL: "the step fell below the resolution of the time",
    CHATTER: "contact events pile up at one instant (grazing or chattering)",
    TOO_MANY_EVENTS: "more than 10^6 contact events",
}

# RODAS4 of Hairer & Wanner (rodas.f, METH = 1): gamma, the stage times alpha_i, the sums
# gamma_i of the gamma_ij (the f_t terms), a_ij, c_ij, the solution's weights m_j and the
# dense output's d_ij
GAMMA = 0.25
ALPHA = np.array([0.0, 0.386, 0.21, 0.63, 1.0, 1.0])
GAMMA_SUM = np.array([0.25, -0.1043, 0.1035, -0.3620000000000023e-01, 0.0, 0.0])
_A51, _A52, _A53, _A54 = (
    0.1221224509226641e01,
    0.6019134481288629e01,
    0.1253708332932087e02,
    -0.6878860361058950e00,
)
A = np.array(
    [
        [0.0, 0.0, 0.0, 0.0, 0.0],
        [0.1544000000000000e01, 0.0, 0.0, 0.0, 0.0],
        [0.9466785280815826e00, 0.2557011698983284e00, 0.0, 0.0, 0.0],
        [0.3314825187068521e01, 0.2896124015972201e01, 0.9986419139977817e00, 0.0, 0.0],
        [_A51, _A52, _A53, _A54, 0.0],
        [_A51, _A52, _A53, _A54, 1.0],
    ]
)
C = np.array(
    [
        [0.0, 0.0, 0.0, 0.0, 0.0],
        [-0.5668800000000000e01, 0.0, 0.0, 0.0, 0.0],
        [-0.2430093356833875e01, -0.2063599157091915e00, 0.0, 0.0, 0.0],
        [-0.1073529058151375e00, -0.9594562251023355e01, -0.2047028614809616e02, 0.0, 0.0],
        [
            0.7496443313967647e01,
            -0.1024680431464352e02,
            -0.3399990352819905e02,
            0.1170890893206160e02,
            0.0,
        ],
        [
            0.8083246795921522e01,
            -0.7981132988064893e01,
            -0.3152159432874371e02,
            0.1631930543123136e02,
            -0.6058818238834054e01,
        ],
    ]
)
#: the solution: the last stage's point plus its own ``k`` (stiffly accurate)
B = np.array([_A51, _A52, _A53, _A54, 1.0, 1.0])
DENSE = np.array(
    [
        [
            0.1012623508344586e02,
            -0.7487995877610167e01,
            -0.3480091861555747e02,
            -0.7992771707568823e01,
            0.1025137723295662e01,
        ],
        [
            -0.6762803392801253e00,
            0.6087714651680015e01,
            0.1643084320892478e02,
            0.2476722511418386e02,
            -0.6594389125716872e01,
        ],
    ]
)
_STAGES = 6
_DP_C, _DP_A, _DP_B, _DP_E, _DP_P = (
    dormand_prince.C, dormand_prince.A, dormand_prince.B, dormand_prince.E, dormand_prince.P
)  # fmt: skip
#: ``h |lambda|`` above which a step is held by the explicit pair's stability (DOPRI5's)
STIFF_STEP = 3.25
#: steps that decide a switch between the explicit pair and RODAS4 (DOPRI5's 15 and 6)
SWITCH_VOTES = 15
CALM_STEPS = 6
#: RODAS4's right-hand sides a step over the explicit pair's, with the Jacobian (4 + 1)
EXPLICIT_CHEAPER = 11.0 / 6.0
#: matrix-vector products of the estimate of the Jacobian's spectral radius
POWER_STEPS = 8
#: switch between the two methods (bound; ``False``: RODAS4 throughout)
SWITCHING = True
#: how many leading state components the right-hand side depends on (-1: all); bound
JACOBIAN_COLUMNS = -1
#: the forward differences' step over ``max(|y_j|, 1)`` (and ``max(|t|, 1)``), SI states;
#: bound: ``sqrt(eps)`` by default, a system's own where its scales ask for another
#: (the slider-crank's: :mod:`jointwear.mechanism.slider_crank._contact_impact_rosenbrock`)
DIFFERENCE_STEP = 1.4901161193847656e-08


def rhs(t, y, impact_velocity, p, wear):  # type: ignore[no-untyped-def]
    """The system's right-hand side (supplied by :func:`bind`)."""
    raise NotImplementedError("rosenbrock.rhs: compile the integrator with bind()")


def gap(t, y, p, wear):  # type: ignore[no-untyped-def]
    """The system's signed penetration (supplied by :func:`bind`)."""
    raise NotImplementedError("rosenbrock.gap: compile the integrator with bind()")


def gap_and_rate(t, y, p, wear):  # type: ignore[no-untyped-def]
    """The system's penetration and its rate (supplied by :func:`bind`)."""
    raise NotImplementedError("rosenbrock.gap_and_rate: compile the integrator with bind()")


def _rms(values, scale):  # type: ignore[no-untyped-def]
    total = 0.0
    for i in range(values.size):
        ratio = values[i] / scale[i]
        total += ratio * ratio
    return math.sqrt(total / values.size)


def _lu_factor(a, pivots):  # type: ignore[no-untyped-def]
    """LU with partial pivoting of the small matrix ``a``, in place; False if singular.

    (LAPACK's ``getrf`` for a 5x5 matrix, without a call into it: compiled code cannot
    call ``scipy.linalg.lu_factor``, and ``np.linalg.solve`` would factor the matrix
    again for each of the six stages.)
    """
    n = a.shape[0]
    for col in range(n):
        best, row = abs(a[col, col]), col
        for i in range(col + 1, n):
            if abs(a[i, col]) > best:
                best, row = abs(a[i, col]), i
        pivots[col] = row
        if best == 0.0 or not math.isfinite(best):
            return False
        if row != col:
            for j in range(n):
                a[col, j], a[row, j] = a[row, j], a[col, j]
        for i in range(col + 1, n):
            factor = a[i, col] / a[col, col]
            a[i, col] = factor
            for j in range(col + 1, n):
                a[i, j] -= factor * a[col, j]
    return True


def _lu_solve(a, pivots, b):  # type: ignore[no-untyped-def]
    """Solve ``A x = b`` with the factors of :func:`_lu_factor`, ``b`` overwritten by ``x``."""
    n = a.shape[0]
    for i in range(n):
        j = pivots[i]
        if j != i:
            b[i], b[j] = b[j], b[i]
    for i in range(n):
        for j in range(i):
            b[i] -= a[i, j] * b[j]
    for i in range(n - 1, -1, -1):
        for j in range(i + 1, n):
            b[i] -= a[i, j] * b[j]
        b[i] /= a[i, i]


def _jacobian(t, y, f, v_imp, p, wear, jac, f_t, work):  # type: ignore[no-untyped-def]
    """Forward-difference ``df/dy`` into ``jac`` and ``df/dt`` into ``f_t``; the count of
    right-hand sides spent [-]."""
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
    step = DIFFERENCE_STEP * max(abs(t), 1.0)
    shifted = rhs(t + step, y, v_imp, p, wear)
    step = (t + step) - t
    for i in range(n):
        f_t[i] = (shifted[i] - f[i]) / step
    return columns + 1


def _step(t, y, f, jac, f_t, h, v_imp, p, wear, lu, pivots, k, point, y_new, scale_rtol, atol):  # type: ignore[no-untyped-def]
    """One RODAS4 step of ``h`` from ``(t, y)``: ``y_new``, the stages ``k``; the error
    norm (``inf`` if ``W`` is singular)."""
    n = y.size
    for i in range(n):
        for j in range(n):
            lu[i, j] = -jac[i, j]
        lu[i, i] += 1.0 / (GAMMA * h)
    if not _lu_factor(lu, pivots):
        return math.inf
    for s in range(_STAGES):
        if s == 0:
            fs = f
        else:
            for i in range(n):
                total = 0.0
                for j in range(s):
                    total += A[s, j] * k[j, i]
                point[i] = y[i] + total
            fs = rhs(t + ALPHA[s] * h, point, v_imp, p, wear)
        for i in range(n):
            coupling = 0.0
            for j in range(s):
                coupling += C[s, j] * k[j, i]
            k[s, i] = fs[i] + GAMMA_SUM[s] * h * f_t[i] + coupling / h
        _lu_solve(lu, pivots, k[s])
    total = 0.0
    for i in range(n):
        step = 0.0
        for j in range(_STAGES):
            step += B[j] * k[j, i]
        y_new[i] = y[i] + step
        ratio = k[_STAGES - 1, i] / (atol + max(abs(y[i]), abs(y_new[i])) * scale_rtol)
        total += ratio * ratio
    norm = math.sqrt(total / n)
    return norm if math.isfinite(norm) else math.inf


def _rodas_interpolant(y_old, y_new, h, k, q):  # type: ignore[no-untyped-def]
    """The RODAS4 step's dense output as ``q`` of :func:`_dense`: ``(1 - s) y_0 + s (y_1 +
    (1 - s)(q_3 + s q_4))`` expanded in powers of ``s``, ``q_3, q_4`` sums of the ``k``."""
    for i in range(y_old.size):
        q3 = q4 = 0.0
        for j in range(_STAGES - 1):
            q3 += DENSE[0, j] * k[j, i]
            q4 += DENSE[1, j] * k[j, i]
        q[i, 0] = (y_new[i] - y_old[i] + q3) / h
        q[i, 1] = (q4 - q3) / h
        q[i, 2] = -q4 / h
        q[i, 3] = 0.0


def _explicit_interpolant(kk, q):  # type: ignore[no-untyped-def]
    """The Dormand-Prince step's 4th-order dense output, ``q = K^T P``."""
    for i in range(q.shape[0]):
        for c in range(q.shape[1]):
            total = 0.0
            for j in range(kk.shape[0]):
                total += kk[j, i] * _DP_P[j, c]
            q[i, c] = total


def _dense(t, t_old, h, y_old, q):  # type: ignore[no-untyped-def]
    """The step's interpolant at ``t``: ``y_old + h (q_1 x + q_2 x^2 + q_3 x^3 + q_4 x^4)``."""
    x = (t - t_old) / h
    out = y_old.copy()
    for i in range(y_old.size):
        out[i] += h * (q[i, 0] * x + q[i, 1] * x * x + q[i, 2] * x**3 + q[i, 3] * x**4)
    return out


def _event_value(kind, t, t_old, h, y_old, q, p, wear):  # type: ignore[no-untyped-def]
    state = _dense(t, t_old, h, y_old, q)
    if kind == 0:
        return gap(t, state, p, wear)
    return gap_and_rate(t, state, p, wear)[1]


def _root(kind, t0, t1, h, y_old, q, p, wear):  # type: ignore[no-untyped-def]
    """Zero of the gap (``kind`` 0) or its rate (1) on the step's dense output, by
    bisection to ``4 eps |t|`` (``scipy.optimize`` cannot be called from compiled code)."""
    f0 = _event_value(kind, t0, t0, h, y_old, q, p, wear)
    f1 = _event_value(kind, t1, t0, h, y_old, q, p, wear)
    if f0 == 0.0:
        return t0
    if f1 == 0.0:
        return t1
    if (f0 > 0.0) == (f1 > 0.0):
        return t0
    a, b, fa = t0, t1, f0
    tol = 4.0 * 2.220446049250313e-16
    while b - a > tol * max(abs(a), abs(b)) + tol:
        m = 0.5 * (a + b)
        fm = _event_value(kind, m, t0, h, y_old, q, p, wear)
        if fm == 0.0:
            return m
        if (fm > 0.0) == (fa > 0.0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


def _take_samples(samples, next_sample, upto, closed, t_old, h, y_old, q, out, seg, segment):  # type: ignore[no-untyped-def]
    """Dense-output states at the samples ``< upto`` (``<= upto`` if ``closed``)."""
    while next_sample < samples.size and (
        samples[next_sample] < upto or (closed and samples[next_sample] == upto)
    ):
        out[next_sample] = _dense(samples[next_sample], t_old, h, y_old, q)
        seg[next_sample] = segment
        next_sample += 1
    return next_sample


def _explicit_step(t, y, f, h, v_imp, p, wear, kk, point, y_new, rtol, atol):  # type: ignore[no-untyped-def]
    """One Dormand-Prince step (``RK45``'s): ``y_new``, the stages ``kk`` (the last one
    ``f(t + h, y_new)``); ``(error norm, |lambda| estimate)``.

    The estimate of the dominant eigenvalue is DOPRI5's: the last two stages are both
    taken at ``t + h``, so ``||k_7 - k_6|| / ||y_new - y_6||`` [1/s].
    """
    n = y.size
    kk[0] = f
    for s in range(1, 6):
        for i in range(n):
            dy = 0.0
            for j in range(s):
                dy += _DP_A[s, j] * kk[j, i]
            point[i] = y[i] + dy * h
        kk[s] = rhs(t + _DP_C[s] * h, point, v_imp, p, wear)
    for i in range(n):
        dy = 0.0
        for j in range(6):
            dy += _DP_B[j] * kk[j, i]
        y_new[i] = y[i] + h * dy
    kk[6] = rhs(t + h, y_new, v_imp, p, wear)
    total = num = den = 0.0
    for i in range(n):
        err = 0.0
        for j in range(7):
            err += _DP_E[j] * kk[j, i]
        ratio = err * h / (atol + max(abs(y[i]), abs(y_new[i])) * rtol)
        total += ratio * ratio
        num += (kk[6, i] - kk[5, i]) ** 2
        den += (y_new[i] - point[i]) ** 2
    norm = math.sqrt(total / n)
    return (norm if math.isfinite(norm) else math.inf), (math.sqrt(num / den) if den > 0.0 else 0.0)


def _initial_step(t0, y0, f0, t_bound, max_step, v_imp, p, wear, rtol, atol):  # type: ignore[no-untyped-def]
    """``scipy.integrate._ivp.common.select_initial_step`` for the 3rd-order error
    estimate; one right-hand side."""
    interval = abs(t_bound - t0)
    if interval == 0.0:
        return 0.0
    scale = atol + np.abs(y0) * rtol
    d0, d1 = _rms(y0, scale), _rms(f0, scale)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, interval)
    f1 = rhs(t0 + h0, y0 + h0 * f0, v_imp, p, wear)
    d2 = _rms(f1 - f0, scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 4.0)
    return min(100 * h0, h1, interval, max_step)


def _next_step(h, err, accepted_before, h_acc, err_acc):  # type: ignore[no-untyped-def]
    """``rodas.f``'s new step after an error ``err`` on ``h``: ``(h_new, predicted)``,
    Gustafsson's prediction once a step was accepted (``h_acc``, ``err_acc``)."""
    fac = max(1.0 / 6.0, min(5.0, err**0.25 / 0.9))
    if accepted_before and err <= 1.0:
        gus = (h_acc / h) * (err * err / err_acc) ** 0.25 / 0.9
        fac = max(fac, max(1.0 / 6.0, min(5.0, gus)))
    return h / fac


def _explicit_factor(err, rejected):  # type: ignore[no-untyped-def]
    """``RK45``'s step factor after an error norm ``err`` (accepted if ``err < 1``)."""
    if err < 1.0:
        factor = 10.0 if err == 0.0 else min(10.0, 0.9 * err**-0.2)
        return min(1.0, factor) if rejected else factor
    return max(0.2, 0.9 * err**-0.2)


def _spectral_radius(jac, x, z):  # type: ignore[no-untyped-def]
    """The largest ``|lambda|`` of the Jacobian, roughly: the growth of ``||J^m x||`` over
    :data:`POWER_STEPS` products from ``x = 1`` (a complex pair grows alike) [1/s]."""
    n = jac.shape[0]
    for i in range(n):
        x[i] = 1.0
    growth = 0.0
    for _ in range(POWER_STEPS):
        norm = 0.0
        for i in range(n):
            total = 0.0
            for j in range(n):
                total += jac[i, j] * x[j]
            z[i] = total
            norm = max(norm, abs(total))
        if norm == 0.0 or not math.isfinite(norm):
            return 0.0 if norm == 0.0 else math.inf
        for i in range(n):
            x[i] = z[i] / norm
        growth += math.log(norm)
    return math.exp(growth / POWER_STEPS)


def _attempt(
    explicit,
    t,
    t_end,
    y,
    f,
    h_abs,
    min_step,
    v_imp,
    p,
    wear,
    jac,
    f_t,
    lu,
    pivots,
    k,
    kk,
    point,
    y_new,
    rtol,
    atol,
    control,
):  # type: ignore[no-untyped-def]
    """Steps from ``(t, y)`` until one is accepted, into ``y_new``: ``(accepted, t_new, h,
    h_abs, stiffness, right-hand sides)``, ``h_abs`` the next step's size, ``stiffness`` the
    explicit pair's ``|lambda|``. ``control`` holds ``(rejected, accepted before, h_acc,
    err_acc)`` of the step control, updated."""
    nfev = 0
    while True:
        if h_abs < min_step:
            return False, t, 0.0, h_abs, 0.0, nfev
        t_new = min(t + h_abs, t_end)
        h = t_new - t
        if explicit:
            err, stiffness = _explicit_step(t, y, f, h, v_imp, p, wear, kk, point, y_new,
                                            rtol, atol)  # fmt: skip
            nfev += 6
            h_abs = h * _explicit_factor(err, control[0] != 0.0)
            control[0] = 1.0 if err >= 1.0 else 0.0
            if err < 1.0:
                return True, t_new, h, h_abs, stiffness, nfev
            continue
        err = _step(t, y, f, jac, f_t, h, v_imp, p, wear, lu, pivots, k, point, y_new,
                    rtol, atol)  # fmt: skip
        nfev += _STAGES - 1
        if err <= 1.0:
            h_abs = _next_step(h, err, control[1] != 0.0, control[2], control[3])
            if control[0] != 0.0:
                h_abs = min(h_abs, h)
            control[0], control[1], control[2], control[3] = 0.0, 1.0, h, max(0.01, err)
            return True, t_new, h, h_abs, 0.0, nfev
        if not math.isfinite(err):
            h_abs = 0.5 * h
        elif control[1] == 0.0:
            h_abs = 0.1 * h
        else:
            h_abs = _next_step(h, err, False, control[2], control[3])
        control[0] = 1.0


def _switch(explicit, h, h_abs, stiffness, jac, x, z, votes, calm):  # type: ignore[no-untyped-def]
    """Whether the next step is explicit, and the switch's counts ``(explicit, votes, calm)``.

    The explicit pair hands over on DOPRI5's test: steps held by stability, ``h |lambda| >
    3.25``, fifteen times (six steps in a row below it start the count again). RODAS4 hands
    back once its six right-hand sides fewer a step would buy more than its longer steps:
    its step below :data:`EXPLICIT_CHEAPER` times the explicit pair's stability limit,
    fifteen steps in a row.
    """
    if not SWITCHING:
        return False, 0, 0
    if explicit:
        if h * stiffness > STIFF_STEP:
            votes, calm = votes + 1, 0
        else:
            calm += 1
            if calm >= CALM_STEPS:
                votes = 0
        if votes >= SWITCH_VOTES:
            return False, 0, 0
        return True, votes, calm
    if h_abs * _spectral_radius(jac, x, z) < EXPLICIT_CHEAPER * STIFF_STEP:
        votes += 1
    else:
        votes = 0
    if votes >= SWITCH_VOTES:
        return True, 0, 0
    return False, votes, calm


def _step_events(
    in_contact,
    g,
    rate,
    g_new,
    rate_new,
    t,
    t_new,
    h,
    t_end,
    y,
    q,
    p,
    wear,
    samples,
    next_sample,
    sample_states,
    sample_segment,
    n_seg,
    peak_t,
    peak_y,
    peak_segment,
    n_peaks,
):  # type: ignore[no-untyped-def]
    """The step's contact event, penetration maximum and samples: ``(crossed, t_stop,
    next_sample, n_peaks)``, ``t_stop`` the event's time (``t_end`` without one)."""
    peak = in_contact and rate >= 0.0 and rate_new <= 0.0
    crossed = (g >= 0.0 and g_new <= 0.0) if in_contact else (g <= 0.0 and g_new >= 0.0)
    t_stop = t_end
    if crossed:
        t_stop = _root(0, t, t_new, h, y, q, p, wear)
    if peak:
        t_peak = _root(1, t, t_new, h, y, q, p, wear)
        if (not crossed or t_peak < t_stop) and n_peaks < peak_t.size:
            peak_t[n_peaks] = t_peak
            peak_y[n_peaks] = _dense(t_peak, t, h, y, q)
            peak_segment[n_peaks] = n_seg
            n_peaks += 1
    upto = t_stop if crossed else t_new
    closed = not crossed and t_new >= t_end
    next_sample = _take_samples(
        samples, next_sample, upto, closed, t, h, y, q, sample_states, sample_segment, n_seg
    )
    return crossed, t_stop, next_sample, n_peaks


def _segment_end(
    t,
    y,
    p,
    wear,
    in_contact,
    stop_on_separation,
    seg_start,
    seg_rate,
    segment,
    stalled,
    v_imp,
    floor,
):  # type: ignore[no-untyped-def]
    """After a contact event at ``t``: ``(status, stalled, v_imp)``, the segment's event rate
    recorded, the approach velocity of a contact that starts."""
    if in_contact and stop_on_separation:
        return SEPARATED, stalled, v_imp
    stalled = stalled + 1 if t - seg_start[segment] <= 1e-14 * max(1.0, abs(t)) else 0
    if stalled > 100:
        return CHATTER, stalled, v_imp
    event_rate = gap_and_rate(t, y, p, wear)[1]
    seg_rate[segment] = event_rate
    return OK, stalled, (v_imp if in_contact else max(event_rate, floor))


def _open_segment(t, y, t_end, in_contact, v_imp, p, wear, rtol, atol, max_step, n_seg,
                  capacity, seg_start, seg_contact, seg_velocity, seg_rate):  # type: ignore[no-untyped-def]  # fmt: skip
    """A segment's start recorded: ``(full, f, h_abs, g, rate)``, ``full`` if the records
    are (then nothing else is done), ``f`` the right-hand side, ``h_abs`` the initial step
    (two right-hand sides in all), the gap and, in contact, its rate."""
    if n_seg >= capacity:
        return True, y, 0.0, 0.0, 0.0
    seg_start[n_seg], seg_contact[n_seg], seg_velocity[n_seg] = t, in_contact, v_imp
    seg_rate[n_seg] = np.nan
    f = rhs(t, y, v_imp, p, wear)
    h_abs = _initial_step(t, y, f, t_end, max_step, v_imp, p, wear, rtol, atol)
    g, rate = gap_and_rate(t, y, p, wear)
    return False, f, h_abs, g, (rate if in_contact else 0.0)


def _close_segment(t, y, p, wear, in_contact, event, stop_on_separation, seg_start, seg_end,
                   seg_rate, n_seg, stalled, v_imp, floor):  # type: ignore[no-untyped-def]  # fmt: skip
    """A segment's end at ``t`` recorded: ``(status, done, n_seg, stalled, v_imp,
    in_contact)``, ``done`` without a contact event (the end of the integration)."""
    seg_end[n_seg] = t
    n_seg += 1
    if not event:
        return OK, True, n_seg, stalled, v_imp, in_contact
    status, stalled, v_imp = _segment_end(
        t, y, p, wear, in_contact, stop_on_separation, seg_start, seg_rate, n_seg - 1,
        stalled, v_imp, floor,
    )  # fmt: skip
    return status, False, n_seg, stalled, v_imp, not in_contact


def _records(samples, capacity, n):  # type: ignore[no-untyped-def]
    """The states at the samples, their segments, and the segments' starts, ends, contact
    flags, approach velocities and event rates."""
    return (
        np.full((samples, n), np.nan), np.zeros(samples, dtype=np.int64), np.empty(capacity),
        np.empty(capacity), np.zeros(capacity, dtype=np.bool_), np.empty(capacity),
        np.empty(capacity),
    )  # fmt: skip


def _work_arrays(n):  # type: ignore[no-untyped-def]
    """The Jacobian, ``f_t``, a state, the LU and its pivots, the step control, RODAS4's and
    the explicit pair's stages, a stage point and the dense output's coefficients."""
    return (
        np.zeros((n, n)), np.empty(n), np.empty(n), np.empty((n, n)), np.zeros(n, dtype=np.int64),
        np.zeros(4), np.empty((_STAGES, n)), np.empty((7, n)), np.empty(n), np.empty((n, 4)),
    )  # fmt: skip


def integrate(
    t0, t_end, y0, in_contact, v_imp, floor, p, wear, rtol, atol, max_step, samples, capacity,
    stop_on_separation,
):  # type: ignore[no-untyped-def]  # fmt: skip
    """Integrate through the contact events, RODAS4 where stiff; states at ``samples``.

    The arguments and the returned tuple are those of
    :func:`jointwear.mechanism.slider_crank._contact_impact_rk.integrate_revolution_rk`:
    ``(status, nfev, sample_states, sample_segment, seg_start, seg_end, seg_contact,
    seg_velocity, seg_event_rate, n_segments, peak_t, peak_y, peak_segment, n_peaks)``.
    """
    n = y0.size
    sample_states, sample_segment, seg_start, seg_end, seg_contact, seg_velocity, seg_rate = (
        _records(samples.size, capacity, n)
    )
    peak_t, peak_y = np.empty(capacity), np.empty((capacity, n))
    peak_segment = np.zeros(capacity, dtype=np.int64)
    n_seg = n_peaks = nfev = next_sample = stalled = votes = calm = 0
    status = OK
    jac, f_t, work, lu, pivots, control, k, kk, point, q = _work_arrays(n)
    explicit = SWITCHING
    t, y = t0, y0.copy()
    while status == OK:
        full, f, h_abs, g, rate = _open_segment(
            t, y, t_end, in_contact, v_imp, p, wear, rtol, atol, max_step, n_seg, capacity,
            seg_start, seg_contact, seg_velocity, seg_rate,
        )  # fmt: skip
        if full:
            status = TOO_MANY_EVENTS
            break
        nfev += 2
        control[:] = 0.0
        event = False
        while t < t_end:
            min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
            h_abs = min(max(h_abs, min_step), max_step)
            if not explicit:
                nfev += _jacobian(t, y, f, v_imp, p, wear, jac, f_t, work)
            y_new = np.empty(n)
            ok, t_new, h, h_abs, stiffness, spent = _attempt(
                explicit, t, t_end, y, f, h_abs, min_step, v_imp, p, wear, jac, f_t, lu, pivots,
                k, kk, point, y_new, rtol, atol, control,
            )  # fmt: skip
            nfev += spent
            if not ok:
                status = STEP_TOO_SMALL
                break
            if explicit:
                _explicit_interpolant(kk, q)
                f_new = kk[6].copy()
            else:
                _rodas_interpolant(y, y_new, h, k, q)
                f_new = rhs(t_new, y_new, v_imp, p, wear)
                nfev += 1
            was_explicit = explicit
            explicit, votes, calm = _switch(explicit, h, h_abs, stiffness, jac, work, point,
                                            votes, calm)  # fmt: skip
            if was_explicit and not explicit:
                control[:] = 0.0  # RODAS4's step control starts afresh
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


#: the functions compiled by :func:`bind`, callees before their callers
_ORDER = (
    "_rms",
    "_lu_factor",
    "_lu_solve",
    "_jacobian",
    "_step",
    "_rodas_interpolant",
    "_explicit_interpolant",
    "_dense",
    "_event_value",
    "_root",
    "_take_samples",
    "_explicit_step",
    "_initial_step",
    "_next_step",
    "_explicit_factor",
    "_spectral_radius",
    "_attempt",
    "_switch",
    "_step_events",
    "_segment_end",
    "_open_segment",
    "_close_segment",
    "_records",
    "_work_arrays",
    "integrate",
)


def bind(system: dict[str, Any], tag: str, cache: bool = True) -> Callable[..., tuple[Any, ...]]:
    """:func:`integrate` compiled for one contact system.

    Parameters
    ----------
    system : dict
        The system's compiled ``rhs``, ``gap`` and ``gap_and_rate`` (numba functions of
        the signatures in the module docstring) and optionally ``JACOBIAN_COLUMNS`` (the
        leading state components the right-hand side depends on) [-].
    tag : str
        Names the compiled functions' disk-cache entries: it must change whenever the
        system's functions do (e.g. a digest of their sources) [-].
    cache : bool
        Cache the machine code on disk, next to this module.

    Returns
    -------
    callable
        The compiled :func:`integrate`.
    """
    from numba import njit

    namespace = dict(globals())
    namespace.update(system)
    for name in _ORDER:
        source: Any = namespace[name]
        clone = types.FunctionType(
            source.__code__, namespace, name, source.__defaults__, source.__closure__
        )
        clone.__qualname__ = f"{source.__qualname__}_{tag}"
        clone.__module__ = source.__module__
        clone.__doc__ = source.__doc__
        namespace[name] = njit(cache=cache)(clone)
    return namespace["integrate"]
