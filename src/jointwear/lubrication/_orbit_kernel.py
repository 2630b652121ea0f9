"""The pin's orbit over one load cycle, compiled by numba.

The physics of :class:`jointwear.lubrication.orbit.OrbitSolver` and
:class:`jointwear.lubrication.orbit.CycleMap` in one compiled loop: the film's force
factor (the short bearing in closed form, the long and finite bearings from the
bicubic B-spline of :func:`jointwear.lubrication.orbit.shape_table`, evaluated as
FITPACK's ``bisplev`` does), the direction of motion whose film force balances the
load (bracketed as :meth:`OrbitSolver.direction_of_motion` does, refined with the
algorithm of :func:`scipy.optimize.brentq`, which numba cannot call; for the tabulated
models first by Newton's method from the last root, with the spline's derivative, on
the wall tables along their own inner direction: some three force evaluations instead
of some eleven, the same root to 1e-13), the
Greenwood--Tripp asperity force from its cubic spline, the centre's velocity and the
right-hand side in the stretched coordinate. The cycle is integrated with the
Dormand--Prince 5(4) pair and its continuous extension (the coefficients of
:class:`scipy.integrate.RK45`, Hairer, Norsett & Wanner, *Solving Ordinary
Differential Equations I*, 1993, II.5-6), the error controlled as there.

Imported by :mod:`jointwear.lubrication.orbit` on first use only (loading numba costs
a few tenths of a second).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from scipy.integrate import RK45

from jointwear.lubrication.film import LONG_CLOSED_FORM_GAP, short_shape_scalar
from jointwear.mechanism.impact.compiled_film import long_bearing

#: ``status`` of a cycle's integration
DONE, TOO_MANY_STEPS, STEP_TOO_SMALL = 0, 1, 2
#: model codes (WALL: the finite bearing beyond its table's end, on the wall's table;
#: LONG: the long bearing, tabulated up to the table's end, on its wall table beyond
#: and in closed form where the pin leaves the wall; FINITE: the finite bearing,
#: tabulated up to the table's end, beyond it (LEAVING) on its wall table; from the
#: leaving table's start on (TABLE_LEAVING below the table's end) on its leaving table
#: where the pin leaves the wall)
SHORT, TABULATED, WALL, LONG, FINITE, LEAVING, TABLE_LEAVING = 0, 1, 2, 3, 4, 5, 6
#: the long bearing's closed form where the wall's inner direction psi lies in
#: (-pi + _LEAVING, -_LEAVING): the pin leaves the wall (orbit.LEAVING_WALL)
_LEAVING = math.atan(3.0)
_TWO_PI = 2.0 * math.pi
#: the largest eccentricity ratio the orbit reaches (h_min = 1e-12 c), as the orbit module
_LARGEST = 1.0 - 1e-12
_ROUND_OFF = 1e-12
_STEPS = 200_000
#: Newton steps of the direction of motion before the bracketing search takes over
_NEWTON_STEPS = 8
#: a Newton step below this [rad] whose successor, estimated from the quadratic
#: convergence, is below the root's tolerance ends the iteration (:func:`_newton`)
_SETTLED_STEP = 1e-7

# Dormand-Prince 5(4) (nodes, stages, weights, error weights, continuous extension):
# scipy's own RK45 tables, so that the compiled loop takes scipy's steps
_C, _A, _B, _E, _P = RK45.C, RK45.A, RK45.B, RK45.E, RK45.P


@njit(cache=True)
def _wrap(angle):
    """``angle`` wrapped to ``[-pi, pi]`` (``math.remainder(angle, 2 pi)``) [rad]."""
    return angle - _TWO_PI * np.rint(angle / _TWO_PI)


@njit(cache=True)
def _interval(breaks, x, lowest, highest):
    """``k`` with ``breaks[k] <= x < breaks[k + 1]``, clipped to ``[lowest, highest]``."""
    k = np.searchsorted(breaks, x, side="right") - 1
    return min(max(k, lowest), highest)


@njit(cache=True)
def _basis(knots, x, span):
    """The four cubic B-splines nonzero at ``x`` in ``span`` (FITPACK ``fpbspl``).

    De Boor's recursion unrolled into scalars (no array allocated per call), in
    FITPACK's order of operations.
    """
    # degree 1
    right, left = span + 1, span
    factor = 1.0 / (knots[right] - knots[left])
    b0 = 0.0 + factor * (knots[right] - x)
    b1 = factor * (x - knots[left])
    # degree 2
    s0, s1 = b0, b1
    right, left = span + 1, span - 1
    factor = s0 / (knots[right] - knots[left])
    b0 = 0.0 + factor * (knots[right] - x)
    b1 = factor * (x - knots[left])
    right, left = span + 2, span
    factor = s1 / (knots[right] - knots[left])
    b1 += factor * (knots[right] - x)
    b2 = factor * (x - knots[left])
    # degree 3
    s0, s1, s2 = b0, b1, b2
    right, left = span + 1, span - 2
    factor = s0 / (knots[right] - knots[left])
    b0 = 0.0 + factor * (knots[right] - x)
    b1 = factor * (x - knots[left])
    right, left = span + 2, span - 1
    factor = s1 / (knots[right] - knots[left])
    b1 += factor * (knots[right] - x)
    b2 = factor * (x - knots[left])
    right, left = span + 3, span
    factor = s2 / (knots[right] - knots[left])
    b2 += factor * (knots[right] - x)
    b3 = factor * (x - knots[left])
    return b0, b1, b2, b3


@njit(cache=True)
def _basis_slope(knots, x, span):
    """The derivatives of the four cubic B-splines of :func:`_basis` at ``x``.

    From the quadratic ones, ``N'_{i,3} = 3 (N_{i,2} / (t_{i+3} - t_i) - N_{i+1,2} /
    (t_{i+4} - t_{i+1}))`` (de Boor, *A Practical Guide to Splines*, 1978, X (12)).
    """
    right, left = span + 1, span
    factor = 1.0 / (knots[right] - knots[left])
    b0 = factor * (knots[right] - x)
    b1 = factor * (x - knots[left])
    s0, s1 = b0, b1
    right, left = span + 1, span - 1
    factor = s0 / (knots[right] - knots[left])
    q0 = factor * (knots[right] - x)
    q1 = factor * (x - knots[left])
    right, left = span + 2, span
    factor = s1 / (knots[right] - knots[left])
    q1 += factor * (knots[right] - x)
    q2 = factor * (x - knots[left])
    d0 = 3.0 * q0 / (knots[span + 1] - knots[span - 2])
    d1 = 3.0 * q1 / (knots[span + 2] - knots[span - 1])
    d2 = 3.0 * q2 / (knots[span + 3] - knots[span])
    return -d0, d0 - d1, d1 - d2, d2


@njit(cache=True)
def _bicubic_sum(coefficients, span_x, span_y, columns, wx, wy):
    """``sum_i wx_i sum_j wy_j c[(span_x - 3 + i) columns + span_y - 3 + j]``."""
    total = 0.0
    for i in range(4):
        row = (span_x - 3 + i) * columns + span_y - 3
        inner = 0.0
        for j in range(4):
            inner += wy[j] * coefficients[row + j]
        total += wx[i] * inner
    return total


@njit(cache=True)
def _spans(tx, ty, x, y):
    """The point clipped to the splines' domain, its knot spans and its basis values."""
    x = min(max(x, tx[3]), tx[tx.size - 4])
    y = min(max(y, ty[3]), ty[ty.size - 4])
    span_x = _interval(tx, x, 3, tx.size - 5)
    span_y = _interval(ty, y, 3, ty.size - 5)
    return span_x, span_y, _basis(tx, x, span_x), _basis(ty, y, span_y)


@njit(cache=True)
def bicubic(tx, ty, coefficients, x, y):
    """A bicubic B-spline at one point (FITPACK ``bisplev``, ``kx = ky = 3``)."""
    span_x, span_y, wx, wy = _spans(tx, ty, x, y)
    return _bicubic_sum(coefficients, span_x, span_y, ty.size - 4, wx, wy)


#: ``G(eps, beta; L/D)`` of the short bearing in closed form [-]
short_shape = njit(cache=True)(short_shape_scalar)


@njit(cache=True)
def shape(
    eps, beta, model, ratio, log_gap_max, tx, ty, rr, tt, wtx, wty, wrr, wtt, ltx, lty, lww, laa
):
    """``G(eps, beta)`` of the film model (``orbit.OrbitSolver.scalar_shape``) [-]."""
    film = film_at(
        eps, model, ratio, log_gap_max, tx, ty, rr, tt, wtx, wty, wrr, wtt, ltx, lty, lww, laa
    )
    return shape_along(film, beta)


@njit(cache=True)
def film_at(eps, model, ratio, log_gap_max, tx, ty, rr, tt, wtx, wty, wrr, wtt, ltx, lty, lww, laa):
    """What :func:`shape_along` needs at ``eps``, evaluated once for all directions.

    The tabulated models' log-gap coordinate, their ``(1 - eps^2)^2.5`` and the knot
    span and B-spline basis along it: the direction of motion is sought at one ``eps``
    over some ten directions, and only the basis along ``beta`` changes between them
    (the same operations as :func:`bicubic` for each component, so the same values
    bit for bit). Beyond the table's end (``eps > 1 - 10^-log_gap_max``) the long
    bearing in closed form, the finite one from the wall's table (``wtx, wty, wrr,
    wtt``: ``orbit.wall_shape_table``) with ``1 - eps^2``, and the finite bearing's
    leaving table (``ltx, lty, lww, laa``: ``tx``, ``ty``, ``W`` and the angle of
    ``orbit.leaving_shape_table``) where the pin leaves the wall, from its first ``s``
    on (``TABLE_LEAVING`` below the table's end).
    """
    leaving = (ltx, lty, lww, laa)
    if model == SHORT:
        return model, eps, ratio, 1.0, 0, (0.0, 0.0, 0.0, 0.0), ty, rr, tt, leaving
    if eps > 1.0 - 10.0**-log_gap_max:
        code = LONG if model == LONG else (LEAVING if model == FINITE else WALL)
        x = min(max(-math.log10(max(1.0 - eps, 1e-300)), wtx[3]), wtx[wtx.size - 4])
        span_x = _interval(wtx, x, 3, wtx.size - 5)
        basis = _basis(wtx, x, span_x)
        return code, eps, ratio, 1.0 - eps * eps, span_x, basis, wty, wrr, wtt, leaving
    model = TABLE_LEAVING if model == FINITE and eps > 1.0 - 10.0 ** -ltx[3] else TABULATED
    log_gap = min(max(-math.log10(max(1.0 - eps, 1e-300)), 0.0), log_gap_max)
    x = min(max(log_gap, tx[3]), tx[tx.size - 4])
    span_x = _interval(tx, x, 3, tx.size - 5)
    scale = (1.0 - eps * eps) ** 2.5
    return model, eps, ratio, scale, span_x, _basis(tx, x, span_x), ty, rr, tt, leaving


@njit(cache=True)
def _long_shape(eps, beta, ratio):
    """The long bearing's ``G`` in closed form [-]: ``film.long_shape_near_wall``.

    Its operations, with the compiled force (a compiled function passed as an argument
    would keep numba from caching the kernel).
    """
    if 1.0 - eps >= LONG_CLOSED_FORM_GAP:
        return long_bearing(
            1.0, 2.0 * ratio, 1.0, 1.0 / 6.0, eps, 0.5 * math.sin(beta), math.cos(beta) / eps
        )
    held = 1.0 - LONG_CLOSED_FORM_GAP
    one_minus, held_minus = 1.0 - eps * eps, 1.0 - held * held
    root, held_root = math.sqrt(one_minus), math.sqrt(held_minus)
    direction = math.atan2(held_root * math.sin(beta), root * math.cos(beta))
    size = math.hypot(root * math.cos(beta), math.sin(beta))
    held_size = math.hypot(held_root * math.cos(direction), math.sin(direction))
    radial, tangential = long_bearing(
        1.0,
        2.0 * ratio,
        1.0,
        1.0 / 6.0,
        held,
        0.5 * math.sin(direction),
        math.cos(direction) / held,
    )
    scale = size / held_size
    return (
        scale * radial * (held_minus / one_minus) ** 1.5,
        scale * tangential * (held_minus / one_minus),
    )


@njit(cache=True)
def shape_along(film, beta):
    """``G(eps, beta)`` at the ``eps`` of ``film`` (:func:`film_at`) [-].

    On the wall's table (``orbit.wall_shape_scalar``): at the inner direction
    ``psi = atan2(sin beta, sqrt(1 - eps^2) cos beta)``,
    ``G = m' (V_r / (1 - eps^2)^1.5, V_t / (1 - eps^2))``
    (``mobility.to_wall``).
    """
    model, eps, ratio, scale, span_x, wx, ty, radial, tangential, leaving = film
    if model == SHORT:
        return short_shape(eps, beta, ratio)
    if model == TABLE_LEAVING:
        root = math.sqrt(1.0 - eps * eps)
        squeeze = math.sin(beta)
        inner = math.atan2(squeeze, root * math.cos(beta))
        if -math.pi + _LEAVING < inner < -_LEAVING:
            return _leaving_shape(eps, beta, root, squeeze, leaving)
    elif model != TABULATED:  # WALL, LONG or LEAVING
        root = math.sqrt(scale)
        wedge, squeeze = root * math.cos(beta), math.sin(beta)
        inner = math.atan2(squeeze, wedge)
        if -math.pi + _LEAVING < inner < -_LEAVING:
            if model == LONG:
                return _long_shape(eps, beta, ratio)
            if model == LEAVING:
                return _leaving_shape(eps, beta, root, squeeze, leaving)
        y = min(max(inner, ty[3]), ty[ty.size - 4])
        size = math.hypot(wedge, squeeze)
        span_y = _interval(ty, y, 3, ty.size - 5)
        wy = _basis(ty, y, span_y)
        columns = ty.size - 4
        g_r = _bicubic_sum(radial, span_x, span_y, columns, wx, wy)
        g_t = _bicubic_sum(tangential, span_x, span_y, columns, wx, wy)
        return size * g_r / (scale * root), size * g_t / scale
    y = min(max(_wrap(beta), ty[3]), ty[ty.size - 4])
    span_y = _interval(ty, y, 3, ty.size - 5)
    wy = _basis(ty, y, span_y)
    columns = ty.size - 4
    g_r = _bicubic_sum(radial, span_x, span_y, columns, wx, wy)
    g_t = _bicubic_sum(tangential, span_x, span_y, columns, wx, wy)
    return g_r / scale, g_t / scale


@njit(cache=True)
def _leaving_shape(eps, beta, root, squeeze, leaving):
    """``G`` of the finite bearing's leaving table (``orbit.leaving_shape_scalar``) [-].

    At ``s = -log10(1 - eps)`` held at the table's ends and
    ``u = asinh(cot beta) / asinh(1 / (3 sqrt(1 - eps^2)))``,
    ``G = exp(W) (cos T / sin^2 beta, sin T / |sin beta|)`` (``mobility.from_leaving``).
    """
    tx, ty, scaled, angle = leaving
    x = min(max(-math.log10(max(1.0 - eps, 1e-300)), tx[3]), tx[tx.size - 4])
    span_x = _interval(tx, x, 3, tx.size - 5)
    wx = _basis(tx, x, span_x)
    motion = math.asinh(math.cos(beta) / squeeze) / math.asinh(1.0 / (3.0 * root))
    y = min(max(motion, ty[3]), ty[ty.size - 4])
    span_y = _interval(ty, y, 3, ty.size - 5)
    wy = _basis(ty, y, span_y)
    columns = ty.size - 4
    size = math.exp(_bicubic_sum(scaled, span_x, span_y, columns, wx, wy)) / (squeeze * squeeze)
    direction = _bicubic_sum(angle, span_x, span_y, columns, wx, wy)
    return size * math.cos(direction), -size * squeeze * math.sin(direction)


@njit(cache=True)
def _mismatch(direction, target, film):
    g_r, g_t = shape_along(film, direction)
    return _wrap(math.atan2(g_t, g_r) - target)


@njit(cache=True)
def _brent(low, high, f_low, f_high, target, film):
    """The root of the mismatch in ``[low, high]``: scipy's ``brentq`` (xtol 1e-13, rtol 1e-15)."""
    xtol, rtol = 1e-13, 1e-15
    xpre, xcur, fpre, fcur = low, high, f_low, f_high
    xblk = fblk = spre = scur = 0.0
    if fpre == 0.0:
        return xpre
    if fcur == 0.0:
        return xcur
    for _ in range(100):
        if fpre != 0.0 and fcur != 0.0 and (fpre < 0.0) != (fcur < 0.0):
            xblk, fblk = xpre, fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre, xcur, xblk = xcur, xblk, xcur
            fpre, fcur, fblk = fcur, fblk, fcur
        delta = 0.5 * (xtol + rtol * abs(xcur))
        sbis = 0.5 * (xblk - xcur)
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            if 2.0 * abs(stry) < min(abs(spre), 3.0 * abs(sbis) - delta):
                spre, scur = scur, stry
            else:
                spre = scur = sbis
        else:
            spre = scur = sbis
        xpre, fpre = xcur, fcur
        if abs(scur) > delta:
            xcur += scur
        else:
            xcur += delta if sbis > 0.0 else -delta
        fcur = _mismatch(xcur, target, film)
    return xcur


@njit(cache=True)
def _newton(start, target, film):
    """The rising root of the mismatch of a tabulated model by Newton's method [rad].

    From ``start`` (the last root: the state moves little between calls), with the
    mismatch's slope ``(G_r G_t' - G_t G_r') / |G|^2`` from the splines' derivatives
    along ``beta`` (on a wall table: :func:`_wall_newton`); done when a step is below
    the tolerance of :func:`_brent`, or when it is below ``_SETTLED_STEP`` and the next
    one, ``|s_k|^3 / |s_{k-1}|^2`` by the quadratic convergence, is (one iteration of
    some four saved). Returns the root and ``G`` at the iterate before the last step
    (it moved less than 1e-13 rad), or there moved along its tangent to the root
    (``G - s_k G'``: an error of order ``s_k^2``); NaN where the slope is not positive,
    the iterate strays a radian from the start, the long or finite bearing's iterate
    leaves the wall (its closed form or leaving table there) or it does not settle: the
    bracketing search takes over.
    """
    model, eps, _, scale, span_x, wx, ty, radial, tangential, _ = film
    if model not in (TABULATED, TABLE_LEAVING):
        return _wall_newton(start, target, film)
    columns = ty.size - 4
    beta, last = start, 0.0
    root = math.sqrt(1.0 - eps * eps)
    for _ in range(_NEWTON_STEPS):
        y = min(max(_wrap(beta), ty[3]), ty[ty.size - 4])
        span_y = _interval(ty, y, 3, ty.size - 5)
        wy = _basis(ty, y, span_y)
        dy = _basis_slope(ty, y, span_y)
        g_r = _bicubic_sum(radial, span_x, span_y, columns, wx, wy)
        g_t = _bicubic_sum(tangential, span_x, span_y, columns, wx, wy)
        d_r = _bicubic_sum(radial, span_x, span_y, columns, wx, dy)
        d_t = _bicubic_sum(tangential, span_x, span_y, columns, wx, dy)
        slope = (g_r * d_t - g_t * d_r) / (g_r * g_r + g_t * g_t)
        if not slope > 0.0:
            return math.nan, 0.0, 0.0
        g_r, g_t = g_r / scale, g_t / scale
        step = _wrap(math.atan2(g_t, g_r) - target) / slope
        beta -= step
        if abs(beta - start) > 1.0:
            return math.nan, 0.0, 0.0
        # an iterate on the leaving table: the bracketing search takes over
        if (
            model == TABLE_LEAVING
            and -math.pi + _LEAVING < math.atan2(math.sin(beta), root * math.cos(beta)) < -_LEAVING
        ):
            return math.nan, 0.0, 0.0
        tolerance = 0.5 * (1e-13 + 1e-15 * abs(beta))
        if abs(step) <= tolerance:
            return beta, g_r, g_t
        # quadratic convergence: the next step ~ (step / last step^2) step^2; where it
        # is below the tolerance, G moved along the tangent to beta (an error ~ step^2)
        # instead of one more iteration for a step of round-off
        if abs(step) <= _SETTLED_STEP and abs(step) ** 3 <= tolerance * last * last:
            return beta, g_r - step * d_r / scale, g_t - step * d_t / scale
        last = abs(step)
    return math.nan, 0.0, 0.0


@njit(cache=True)
def _wall_newton(start, target, film):
    """:func:`_newton` on a wall table, iterating on the inner direction ``psi`` [rad].

    The table's own coordinate: ``G = m' (V_r / q^1.5, V_t / q)`` points along
    ``(V_r(psi) / sqrt(q), V_t(psi))`` (``q = 1 - eps^2``; ``m'`` cancels in the
    angle), so the mismatch's slope along ``psi`` is the splines' derivative alone,
    and a root that ``beta = atan2(sqrt(q) sin psi, cos psi)`` moves by radians where
    ``q`` is small (the pin squeezing the film: ``psi`` near ``pi / 2`` for most
    ``beta``) moves little along ``psi``. Done when the step of ``beta`` is below the
    tolerance of :func:`_brent`, or below ``_SETTLED_STEP`` with the next one, by the
    quadratic convergence, below it (``V`` moved along its tangent to the root). NaN
    where the slope is not positive, ``psi`` strays a radian from the start's, the long
    or finite bearing's iterate leaves the wall (its closed form or leaving table
    there) or it does not settle.
    """
    model, _, _, scale, span_x, wx, ty, radial, tangential, _ = film
    columns = ty.size - 4
    root = math.sqrt(scale)
    inner = math.atan2(math.sin(start), root * math.cos(start))
    first, beta, last = inner, start, 0.0
    for _ in range(_NEWTON_STEPS):
        if model in (LONG, LEAVING) and -math.pi + _LEAVING < inner < -_LEAVING:
            return math.nan, 0.0, 0.0
        y = min(max(inner, ty[3]), ty[ty.size - 4])
        span_y = _interval(ty, y, 3, ty.size - 5)
        wy = _basis(ty, y, span_y)
        dy = _basis_slope(ty, y, span_y)
        v_r = _bicubic_sum(radial, span_x, span_y, columns, wx, wy) / root
        v_t = _bicubic_sum(tangential, span_x, span_y, columns, wx, wy)
        d_r = _bicubic_sum(radial, span_x, span_y, columns, wx, dy) / root
        d_t = _bicubic_sum(tangential, span_x, span_y, columns, wx, dy)
        slope = (v_r * d_t - v_t * d_r) / (v_r * v_r + v_t * v_t)
        if not slope > 0.0:
            return math.nan, 0.0, 0.0
        step = _wrap(math.atan2(v_t, v_r) - target) / slope
        inner = _wrap(inner - step)
        if abs(_wrap(inner - first)) > 1.0:
            return math.nan, 0.0, 0.0
        moved = beta
        beta = start + _wrap(math.atan2(root * math.sin(inner), math.cos(inner)) - start)
        moved = abs(beta - moved)
        tolerance = 0.5 * (1e-13 + 1e-15 * abs(beta))
        settled = moved <= tolerance
        if not settled and moved <= _SETTLED_STEP and last > 0.0:
            settled = moved * (step / last) ** 2 <= tolerance
            v_r, v_t = v_r - step * d_r, v_t - step * d_t
        if settled:
            size = math.hypot(root * math.cos(beta), math.sin(beta))
            return beta, size * v_r / scale, size * v_t / scale
        last = abs(step)
    return math.nan, 0.0, 0.0


@njit(cache=True)
def direction_of_motion(
    eps,
    target,
    memory,
    model,
    ratio,
    log_gap_max,
    tx,
    ty,
    rr,
    tt,
    wtx,
    wty,
    wrr,
    wtt,
    ltx,
    lty,
    lww,
    laa,
    nodes,
):
    """``beta`` whose film force points at ``target`` (``OrbitSolver.direction_of_motion``).

    ``memory[0]`` holds the last root (NaN: none); returns NaN where none is found.
    """
    film = film_at(
        eps, model, ratio, log_gap_max, tx, ty, rr, tt, wtx, wty, wrr, wtt, ltx, lty, lww, laa
    )
    return direction_along(film, target, memory, nodes)[0]


@njit(cache=True)
def direction_along(film, target, memory, nodes):
    """:func:`direction_of_motion` at the ``eps`` of ``film`` (:func:`film_at`) [rad],
    and ``G`` there (:func:`shape_along`; NaN where no root is found) [-]."""
    for search in range(2):
        found = False
        if search == 0:
            centre = memory[0]
            if math.isnan(centre):
                continue
            if film[0] != SHORT:
                # the root turns with the load: start from the last root turned as far
                # as the target has turned since (memory[1], NaN: not at all)
                turn = _wrap(target - memory[1]) if memory.size > 1 else math.nan
                root, g_r, g_t = _newton(centre + (0.0 if math.isnan(turn) else turn), target, film)
                if not math.isnan(root):
                    memory[0] = root
                    if memory.size > 1:
                        memory[1] = target
                    return root, g_r, g_t
            width = 0.05
            low, high = centre - width, centre + width
            below, above = _mismatch(low, target, film), _mismatch(high, target, film)
            while width < 1.0:
                if below <= 0.0 < above and above - below < math.pi:
                    found = True
                    break
                width *= 3.0
                if below > 0.0:
                    low = centre - width
                    below = _mismatch(low, target, film)
                else:
                    high = centre + width
                    above = _mismatch(high, target, film)
            if not found:
                continue
        else:
            step = _TWO_PI / nodes
            previous = _wrap(_mismatch(-math.pi, target, film))
            cell = 0
            for k in range(1, nodes + 1):
                current = _mismatch(-math.pi + step * k, target, film)
                if previous <= 0.0 < current and current - previous < math.pi:
                    cell = k - 1
                    break
                previous = current
            low = -math.pi + step * cell
            high = low + step
            if cell + 1 == nodes:
                high = math.pi
            below, above = _mismatch(low, target, film), _mismatch(high, target, film)
        if min(abs(below), abs(above)) <= _ROUND_OFF:
            root = low if abs(below) <= abs(above) else high
        elif below < 0.0 < above and above - below < math.pi:
            root = _brent(low, high, below, above, target, film)
        else:
            continue
        memory[0] = root
        if memory.size > 1:
            memory[1] = target
        g_r, g_t = shape_along(film, root)
        return root, g_r, g_t
    return math.nan, math.nan, math.nan


@njit(cache=True)
def _tridiagonal(lower, diagonal, upper, rhs):
    """``rhs`` overwritten by the solution of a diagonally dominant tridiagonal system.

    ``lower[i] = a[i + 1, i]``, ``upper[i] = a[i, i + 1]``; the elimination of LAPACK's
    ``gtsv`` (what :func:`scipy.linalg.solve_banded` calls) where no row is swapped, as
    none is in a diagonally dominant system; ``rhs`` has one column per channel.
    """
    d = diagonal.copy()
    n = d.size
    for i in range(n - 1):
        factor = lower[i] / d[i]
        d[i + 1] -= factor * upper[i]
        for j in range(rhs.shape[1]):
            rhs[i + 1, j] -= factor * rhs[i, j]
    for j in range(rhs.shape[1]):
        rhs[n - 1, j] /= d[n - 1]
        for i in range(n - 2, -1, -1):
            rhs[i, j] = (rhs[i, j] - upper[i] * rhs[i + 1, j]) / d[i]


@njit(cache=True)
def periodic_spline(breaks, values):
    """``c[power, interval, channel]`` of the periodic cubic spline through ``values``.

    :class:`scipy.interpolate.CubicSpline` with ``bc_type="periodic"`` (``values`` of
    shape ``(channels, n)``, ``values[:, -1] == values[:, 0]``, at least four
    breaks), its cyclic tridiagonal system for the slopes ``s`` solved as scipy solves
    it: the system without its last row and column twice (:func:`_tridiagonal`), then
    that row,

    .. math:: \\Delta x_i s_{i-1} + 2(\\Delta x_{i-1} + \\Delta x_i) s_i
        + \\Delta x_{i-1} s_{i+1} = 3(\\Delta x_i m_{i-1} + \\Delta x_{i-1} m_i),

    ``m_i`` the slope of interval ``i``, and the Hermite cubic of each interval. The
    same coefficients to round-off, without scipy's checks of the input (some
    0.6 ms a cycle's load of 360 samples).
    """
    n = breaks.size
    channels = values.shape[0]
    dx = np.diff(breaks)
    slope = np.empty((n - 1, channels))
    for j in range(channels):
        for i in range(n - 1):
            slope[i, j] = (values[j, i + 1] - values[j, i]) / dx[i]
    m = n - 2
    diagonal = np.empty(m)
    upper = np.empty(m - 1)
    lower = np.empty(m - 1)
    diagonal[0] = 2.0 * (dx[-1] + dx[0])
    upper[0] = dx[-1]
    for i in range(1, m):
        diagonal[i] = 2.0 * (dx[i - 1] + dx[i])
        lower[i - 1] = dx[i]
        if i < m - 1:
            upper[i] = dx[i - 1]
    first = np.empty((m, channels))
    for j in range(channels):
        first[0, j] = 3.0 * (dx[0] * slope[-1, j] + dx[-1] * slope[0, j])
        for i in range(1, m):
            first[i, j] = 3.0 * (dx[i] * slope[i - 1, j] + dx[i - 1] * slope[i, j])
    second = np.zeros((m, 1))
    second[0, 0] = -dx[0]
    second[-1, 0] = -dx[-3]
    _tridiagonal(lower, diagonal, upper, first)
    _tridiagonal(lower, diagonal, upper, second)
    slopes = np.empty((n, channels))
    corner = 2.0 * (dx[-1] + dx[-2]) + dx[-2] * second[0, 0] + dx[-1] * second[-1, 0]
    for j in range(channels):
        last = 3.0 * (dx[-1] * slope[-2, j] + dx[-2] * slope[-1, j])
        s_last = (last - dx[-2] * first[0, j] - dx[-1] * first[-1, j]) / corner
        for i in range(m):
            slopes[i, j] = first[i, j] + s_last * second[i, 0]
        slopes[m, j] = s_last
        slopes[n - 1, j] = slopes[0, j]
    c = np.empty((4, n - 1, channels))
    for j in range(channels):
        for i in range(n - 1):
            t = (slopes[i, j] + slopes[i + 1, j] - 2.0 * slope[i, j]) / dx[i]
            c[0, i, j] = t / dx[i]
            c[1, i, j] = (slope[i, j] - slopes[i, j]) / dx[i] - t
            c[2, i, j] = slopes[i, j]
            c[3, i, j] = values[j, i]
    return c


@njit(cache=True)
def _spline(breaks, coefficients, x, channel):
    """A cubic spline (``c[power, interval, channel]``) at ``x``, its ends extended."""
    k = _interval(breaks, x, 0, breaks.size - 2)
    dx = x - breaks[k]
    c = coefficients
    return ((c[0, k, channel] * dx + c[1, k, channel]) * dx + c[2, k, channel]) * dx + c[
        3, k, channel
    ]


@njit(cache=True)
def velocity(x, y, load_x, load_y, mean_speed, joint, asperity, memory, tables, nodes):
    """``de/dt / c`` at ``e / c = (x, y)`` (``OrbitSolver.velocity``) [1/s].

    ``joint = (clearance, roughness, cutoff, mobility_scale, ratio, model, log_gap_max)``,
    ``asperity = (breaks, coefficients)`` of the force's spline over the gap,
    ``tables = (tx, ty, radial, tangential)`` of the tabulated models, the same of
    their wall tables and the finite bearing's leaving table ``(tx, ty, W, angle)``
    (``orbit.OrbitSolver.kernel_arguments``). Returns NaN where no direction of motion
    is found.
    """
    clearance, roughness, cutoff, scale, ratio, model_code, log_gap_max = joint
    model = int(model_code)
    tx, ty, rr, tt, wtx, wty, wrr, wtt, ltx, lty, lww, laa = tables
    eps, phi = math.hypot(x, y), math.atan2(y, x)
    eps = min(max(eps, 1e-6), _LARGEST)
    cos_phi, sin_phi = math.cos(phi), math.sin(phi)
    gap = (1.0 - eps) * clearance / roughness
    force = _spline(asperity[0], asperity[1], gap, 0) if gap < cutoff else 0.0
    film_x, film_y = load_x + force * cos_phi, load_y + force * sin_phi
    carried = math.hypot(film_x, film_y)
    radial = tangential = 0.0
    if carried > 0.0:
        target = math.atan2(film_y, film_x) - phi + math.pi
        film = film_at(
            eps, model, ratio, log_gap_max, tx, ty, rr, tt, wtx, wty, wrr, wtt, ltx, lty, lww, laa
        )
        beta, g_r, g_t = direction_along(film, target, memory, nodes)
        if math.isnan(beta):
            return math.nan, math.nan
        size = ratio / (3.0 * math.hypot(g_r, g_t))
        rate = carried * scale * size
        radial, tangential = rate * math.sin(beta), -rate * math.cos(beta)
    tangential += mean_speed * eps
    return radial * cos_phi - tangential * sin_phi, radial * sin_phi + tangential * cos_phi


@njit(cache=True)
def right_hand_side(t, qx, qy, inputs, joint, asperity, memory, tables, nodes):
    """``dq/dt`` in the stretched coordinate (``CycleMap.right_hand_side``) [1/s]."""
    breaks, c = inputs
    # the three inputs share their breaks: one interval for all (as _spline finds it)
    k = _interval(breaks, t, 0, breaks.size - 2)
    dx = t - breaks[k]
    load_x = ((c[0, k, 0] * dx + c[1, k, 0]) * dx + c[2, k, 0]) * dx + c[3, k, 0]
    load_y = ((c[0, k, 1] * dx + c[1, k, 1]) * dx + c[2, k, 1]) * dx + c[3, k, 1]
    speed = ((c[0, k, 2] * dx + c[1, k, 2]) * dx + c[2, k, 2]) * dx + c[3, k, 2]
    norm = 1.0 + math.hypot(qx, qy)
    x, y = qx / norm, qy / norm
    vx, vy = velocity(x, y, load_x, load_y, speed, joint, asperity, memory, tables, nodes)
    gap = 1.0 - math.hypot(x, y)
    if not gap > 0.0:
        # a trial stage so far out that the gap rounds to nil: NaN rejects the step, as
        # the Python path's inf does (a pin leaving the wall fast can overshoot so)
        return math.nan, math.nan
    radial = (x * vx + y * vy) / gap**2
    return vx / gap + radial * x, vy / gap + radial * y


@njit(cache=True)
def _rms(a, b):
    """``sqrt(mean([a, b]^2))``, as ``np.mean`` sums."""
    return math.sqrt((0.0 + a**2 + b**2) / 2.0)


@njit(cache=True)
def cycle(q0, ends, rtol, atol, inputs, joint, asperity, memory, tables, nodes, path):
    """``q`` over one cycle from ``q0`` at ``ends[0]``, written to ``path[:, k]`` at ``ends``.

    Dormand--Prince 5(4) with its continuous extension and the step control of
    :class:`scipy.integrate.RK45`. Returns ``(status, evaluations)``. The two
    components are carried as scalars: no array is allocated per step.
    """
    k = np.empty((7, 2))
    y0, y1 = q0[0], q0[1]
    t, t_end = ends[0], ends[-1]
    args = (inputs, joint, asperity, memory, tables, nodes)
    k[0, 0], k[0, 1] = right_hand_side(t, y0, y1, *args)
    evaluations = 1
    path[0, 0], path[1, 0] = y0, y1
    sample = 1
    # the first step as scipy's select_initial_step, order 4, simplified: 1e-2 of the
    # scaled ratio of state and rate, at most the whole cycle
    scale0, scale1 = atol + abs(y0) * rtol, atol + abs(y1) * rtol
    d0 = _rms(y0 / scale0, y1 / scale1)
    d1 = _rms(k[0, 0] / scale0, k[0, 1] / scale1)
    h = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h = min(h, t_end - t)
    for _ in range(_STEPS):
        if sample >= ends.size:
            return DONE, evaluations
        if h < 10.0 * abs(np.nextafter(t, math.inf) - t):
            return STEP_TOO_SMALL, evaluations
        last = h >= t_end - t
        if last:
            h = t_end - t
        for s in range(1, 6):
            stage0, stage1 = y0, y1
            for j in range(s):
                weight = h * _A[s, j]
                stage0 += weight * k[j, 0]
                stage1 += weight * k[j, 1]
            k[s, 0], k[s, 1] = right_hand_side(t + _C[s] * h, stage0, stage1, *args)
        new0, new1 = y0, y1
        for j in range(6):
            weight = h * _B[j]
            new0 += weight * k[j, 0]
            new1 += weight * k[j, 1]
        k[6, 0], k[6, 1] = right_hand_side(t + h, new0, new1, *args)
        evaluations += 6
        error0 = error1 = 0.0
        for j in range(7):
            weight = h * _E[j]
            error0 += weight * k[j, 0]
            error1 += weight * k[j, 1]
        scale0 = atol + max(abs(y0), abs(new0)) * rtol
        scale1 = atol + max(abs(y1), abs(new1)) * rtol
        norm = _rms(error0 / scale0, error1 / scale1)
        if not np.isfinite(norm):
            h *= 0.2
            continue
        if norm < 1.0:
            t_new = t_end if last else t + h
            # the samples within the step from the continuous extension
            while sample < ends.size and ends[sample] <= t_new:
                theta = (ends[sample] - t) / h
                powers = (theta, theta**2, theta**3, theta**4)
                for c in range(2):
                    increment = 0.0
                    for j in range(7):
                        increment += k[j, c] * (
                            _P[j, 0] * powers[0]
                            + _P[j, 1] * powers[1]
                            + _P[j, 2] * powers[2]
                            + _P[j, 3] * powers[3]
                        )
                    path[c, sample] = (y0 if c == 0 else y1) + h * increment
                sample += 1
            factor = 10.0 if norm == 0.0 else min(10.0, 0.9 * norm**-0.2)
            t = t_new
            y0, y1 = new0, new1
            k[0, 0], k[0, 1] = k[6, 0], k[6, 1]
            h *= factor
        else:
            h *= max(0.2, 0.9 * norm**-0.2)
    return TOO_MANY_STEPS, evaluations
