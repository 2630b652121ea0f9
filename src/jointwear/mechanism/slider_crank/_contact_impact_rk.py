r"""The slider-crank's contact-impact revolution integrated in one compiled function.

``dynamics.integrator = "RK45-compiled"``: the Dormand–Prince 5(4) pair with its
4th-order dense output [1]_, step control and initial step exactly as
``scipy.integrate.RK45`` takes them (error norm ``||K^T E h / (atol + rtol max(|y|,
|y_new|))||_rms``, safety 0.9, factors in ``[0.2, 10]``, exponent ``-1/5``), and the
contact events of :func:`jointwear.mechanism.impact.integrator.integrate_contacts`:
after every step a gap rising through zero (contact start) or falling through zero
(contact end) ends the segment at the root on the step's dense output, and the
integration restarts there with a fresh initial step (the approach velocity of the
damping term taken at the contact start); a gap rate falling through zero in contact
records a penetration maximum. The whole loop runs compiled: a step costs its six
right-hand sides and no interpreter work, where LSODA through ``solve_ivp`` pays
~20 us of Python per right-hand side.

The roots are bracketed by bisection on the dense output to ``4 eps |t|`` (the
tolerance of ``solve_ivp``'s Brent search); ``scipy.optimize`` cannot be called from
compiled code.

References
----------
.. [1] J. R. Dormand, P. J. Prince, "A family of embedded Runge-Kutta formulae",
   J. Comput. Appl. Math. 6 (1980) 19-26.
"""

from __future__ import annotations

import hashlib
import math
from pathlib import Path

import numpy as np
from numba import njit

from jointwear.mechanism.impact import dormand_prince
from jointwear.mechanism.impact.compiled_film import SOURCE_DIGEST
from jointwear.mechanism.slider_crank import _contact_impact_kernel as kernel
from jointwear.mechanism.slider_crank._contact_impact_kernel import gap, gap_and_rate, rhs

#: numba reloads a cached function while its own file is unchanged: the name of the
#: cache entry carries the right-hand side's and the film force's sources
_DIGEST = hashlib.sha1(Path(kernel.__file__).read_bytes()).hexdigest()[:12] + SOURCE_DIGEST

#: status codes of :func:`integrate_revolution_rk`
OK, STEP_TOO_SMALL, TOO_MANY_EVENTS, CHATTER, SEPARATED = 0, 1, 2, 3, 4

# Dormand-Prince 5(4) with scipy's dense output (the same floats as scipy's: the loop takes
# scipy's steps, tested)
_C, _A, _B, _E, _P = (
    dormand_prince.C, dormand_prince.A, dormand_prince.B, dormand_prince.E, dormand_prince.P
)  # fmt: skip


def _named(function):
    """Name the disk-cache entry of ``function`` by :data:`_DIGEST` (before ``njit``)."""
    function.__qualname__ = f"{function.__qualname__}_rhs_{_DIGEST}"
    return function


@njit(cache=True)
@_named
def _rms(values, scale):
    total = 0.0
    for i in range(values.size):
        ratio = values[i] / scale[i]
        total += ratio * ratio
    return math.sqrt(total / values.size)


@njit(cache=True)
@_named
def _initial_step(t0, y0, f0, t_bound, max_step, v_imp, p, wear, rtol, atol):
    """``scipy.integrate._ivp.common.select_initial_step`` (order 4); one right-hand side."""
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
        h1 = (0.01 / max(d1, d2)) ** (1.0 / 5.0)
    return min(100 * h0, h1, interval, max_step)


@njit(cache=True, fastmath={"contract"})
@_named
def _interpolant(k, q):
    """``q = K^T P`` (the step's dense-output coefficients) into ``q``: each sum in the order
    of BLAS's kernel, fused multiply-adds from ``k = 0`` up, without its call per step."""
    for i in range(q.shape[0]):
        for c in range(q.shape[1]):
            total = 0.0
            for j in range(k.shape[0]):
                total += k[j, i] * _P[j, c]
            q[i, c] = total


@njit(cache=True)
@_named
def _dense(t, t_old, h, y_old, q):
    """The step's 4th-order interpolant at ``t`` (``RkDenseOutput``)."""
    x = (t - t_old) / h
    out = y_old.copy()
    for i in range(y_old.size):
        out[i] += h * (q[i, 0] * x + q[i, 1] * x * x + q[i, 2] * x**3 + q[i, 3] * x**4)
    return out


@njit(cache=True)
@_named
def _event_value(kind, t, t_old, h, y_old, q, p, wear):
    y = _dense(t, t_old, h, y_old, q)
    if kind == 0:
        return gap(t, y, p, wear)
    return gap_and_rate(t, y, p, wear)[1]


@njit(cache=True)
@_named
def _root(kind, t0, t1, h, y_old, q, p, wear):
    """Zero of the gap (``kind`` 0) or its rate (1) on the step's dense output."""
    f0 = _event_value(kind, t0, t0, h, y_old, q, p, wear)
    f1 = _event_value(kind, t1, t0, h, y_old, q, p, wear)
    if f0 == 0.0:
        return t0
    if f1 == 0.0:
        return t1
    if (f0 > 0.0) == (f1 > 0.0):
        # the step started on the zero: no sign change to bracket (as integrate_contacts)
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


@njit(cache=True)
@_named
def _take_samples(samples, next_sample, upto, closed, t_old, h, y_old, q, out, seg, segment):
    """Dense-output states at the samples ``< upto`` (``<= upto`` if ``closed``)."""
    while next_sample < samples.size and (
        samples[next_sample] < upto or (closed and samples[next_sample] == upto)
    ):
        out[next_sample] = _dense(samples[next_sample], t_old, h, y_old, q)
        seg[next_sample] = segment
        next_sample += 1
    return next_sample


@njit(cache=True)
@_named
def integrate_revolution_rk(
    t0, t_end, y0, in_contact, v_imp, floor, p, wear, rtol, atol, max_step, samples, capacity,
    stop_on_separation,
):  # fmt: skip
    """Integrate through the contact events; states at ``samples``.

    With ``stop_on_separation`` the integration ends at the first contact end, status
    :data:`SEPARATED` (the caller integrates again at tighter tolerances).
    Returns ``(status, nfev, sample_states, sample_segment, seg_start, seg_end,
    seg_contact, seg_velocity, seg_event_rate, n_segments, peak_t, peak_y, peak_segment,
    n_peaks)``; a segment's event rate is the gap rate at its end event (``nan`` at
    ``t_end``).
    """
    n = y0.size
    sample_states = np.full((samples.size, n), np.nan)
    sample_segment = np.zeros(samples.size, dtype=np.int64)
    seg_start, seg_end = np.empty(capacity), np.empty(capacity)
    seg_contact = np.zeros(capacity, dtype=np.bool_)
    seg_velocity, seg_rate = np.empty(capacity), np.empty(capacity)
    peak_t, peak_y = np.empty(capacity), np.empty((capacity, n))
    peak_segment = np.zeros(capacity, dtype=np.int64)
    n_seg = n_peaks = nfev = next_sample = stalled = 0
    status = OK
    k = np.empty((7, n))
    stage, q = np.empty(n), np.empty((n, 4))
    t, y = t0, y0.copy()
    while True:
        if n_seg >= capacity:
            status = TOO_MANY_EVENTS
            break
        seg_start[n_seg], seg_contact[n_seg], seg_velocity[n_seg] = t, in_contact, v_imp
        seg_rate[n_seg] = np.nan
        f = rhs(t, y, v_imp, p, wear)
        h_abs = _initial_step(t, y, f, t_end, max_step, v_imp, p, wear, rtol, atol)
        nfev += 2
        g, rate = gap_and_rate(t, y, p, wear)
        if not in_contact:
            rate = 0.0
        rejected = False
        event = False
        while t < t_end:
            min_step = 10.0 * abs(np.nextafter(t, np.inf) - t)
            if h_abs > max_step:
                h_abs = max_step
            elif h_abs < min_step:
                h_abs = min_step
            while True:
                if h_abs < min_step:
                    status = STEP_TOO_SMALL
                    break
                t_new = min(t + h_abs, t_end)
                h = t_new - t
                h_abs = abs(h)
                k[0] = f
                for s in range(1, 6):
                    for i in range(n):
                        dy = 0.0
                        for j in range(s):
                            dy += _A[s, j] * k[j, i]
                        stage[i] = y[i] + dy * h
                    k[s] = rhs(t + _C[s] * h, stage, v_imp, p, wear)
                y_new = np.empty(n)
                for i in range(n):
                    dy = 0.0
                    for j in range(6):
                        dy += _B[j] * k[j, i]
                    y_new[i] = y[i] + h * dy
                f_new = rhs(t + h, y_new, v_imp, p, wear)
                k[6] = f_new
                nfev += 6
                total = 0.0
                for i in range(n):
                    err = 0.0
                    for j in range(7):
                        err += _E[j] * k[j, i]
                    ratio = err * h / (atol + max(abs(y[i]), abs(y_new[i])) * rtol)
                    total += ratio * ratio
                norm = math.sqrt(total / n)
                if norm < 1.0:
                    factor = 10.0 if norm == 0.0 else min(10.0, 0.9 * norm**-0.2)
                    if rejected:
                        factor = min(1.0, factor)
                    h_abs *= factor
                    rejected = False
                    break
                h_abs *= max(0.2, 0.9 * norm**-0.2)
                rejected = True
            if status != OK:
                break
            _interpolant(k, q)
            g_new, rate_new = gap_and_rate(t_new, y_new, p, wear)
            peak = in_contact and rate >= 0.0 and rate_new <= 0.0
            crossed = (g >= 0.0 and g_new <= 0.0) if in_contact else (g <= 0.0 and g_new >= 0.0)
            t_stop = t_end
            if crossed:
                t_stop = _root(0, t, t_new, h, y, q, p, wear)
            if peak:
                t_peak = _root(1, t, t_new, h, y, q, p, wear)
                if (not crossed or t_peak < t_stop) and n_peaks < capacity:
                    peak_t[n_peaks] = t_peak
                    peak_y[n_peaks] = _dense(t_peak, t, h, y, q)
                    peak_segment[n_peaks] = n_seg
                    n_peaks += 1
            if crossed:
                y_stop = _dense(t_stop, t, h, y, q)
                next_sample = _take_samples(
                    samples, next_sample, t_stop, False, t, h, y, q, sample_states,
                    sample_segment, n_seg,
                )  # fmt: skip
                t, y, event = t_stop, y_stop, True
                break
            next_sample = _take_samples(
                samples, next_sample, t_new, t_new >= t_end, t, h, y, q, sample_states,
                sample_segment, n_seg,
            )  # fmt: skip
            t, y, f, g = t_new, y_new, f_new, g_new
            if in_contact:
                rate = rate_new
        if status != OK:
            break
        seg_end[n_seg] = t
        n_seg += 1
        if not event:
            break
        if in_contact and stop_on_separation:
            status = SEPARATED
            break
        stalled = stalled + 1 if t - seg_start[n_seg - 1] <= 1e-14 * max(1.0, abs(t)) else 0
        if stalled > 100:
            status = CHATTER
            break
        event_rate = gap_and_rate(t, y, p, wear)[1]
        seg_rate[n_seg - 1] = event_rate
        if not in_contact:
            v_imp = max(event_rate, floor)
        in_contact = not in_contact
    return (
        status, nfev, sample_states, sample_segment, seg_start, seg_end, seg_contact,
        seg_velocity, seg_rate, n_seg, peak_t, peak_y, peak_segment, n_peaks,
    )  # fmt: skip
