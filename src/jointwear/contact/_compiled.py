"""The fused contact balance + Archard step, compiled by numba.

Imported by :mod:`jointwear.contact.kernel` on first use only (``import numba`` and
loading the cached machine code cost a few tenths of a second, which a run that never
solves a revolution should not pay). The physics is that of
:mod:`jointwear.contact.balance` (paper eqs. (5)/(7): the pin moves along the load
line by ``s``, node ``j`` penetrates by ``s cos(phi_j) - g_j - (R_p - sqrt(R_p^2 - s^2
sin^2(phi_j)))`` and the springs' force along the load balances the load); what differs
is the arithmetic: one loop per load over the nodes the pin can reach, no temporaries,
and the wear of a load added to the nodes as soon as it is balanced.

The window of load ``k`` is read from arrays padded by a quarter circle each side
(``ext[c + o + pad]`` is node ``(c + o) mod N``), so the inner loop has no modulo and
LLVM vectorises it (``fastmath`` only reassociates the sums and contracts to FMA: no
approximate division or square root). Arguments travel in tuples:

* ``nodes``: ``(gap_ext, area_ext, cos_o, sin_o)``, the padded node gaps ``r_j - R_p``
  [m] and spring areas [m^2], and ``cos``/``sin`` of the window offsets ``o dtheta``;
* ``grid``: ``(pad, quarter, dtheta, rp, exponent, coefficient)``;
* ``lines``: per load ``(centre, cos_shift, sin_shift, load_gap, load_area, gap_min,
  lower, upper)``, the node nearest the load line, the load line's angle from it, a
  gap and area factor per load (the symmetric law's circle), the smallest gap the pin
  can meet, and the bracket of the offset [m];
* ``line``: one load's ``(base, cos_shift, sin_shift, load_gap, load_area)``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: results per load (``status``)
CONVERGED, NOT_CONVERGED = 0, 1
#: below this ``(s / R_p)^2`` the pin-curvature term is taken from its series (exact
#: to ~1e-20 relative there), which needs neither a square root nor a division
_SERIES_LIMIT = 1e-3
_EPS = 2.220446049250313e-16
_FLAGS = {"cache": True, "error_model": "numpy", "fastmath": {"reassoc", "contract"}}


@njit(**_FLAGS)
def _evaluate(s, nodes, grid, line, width, higher, press, depth):
    """Springs of one load at offset ``s`` [m]: (force, slope, second, third derivative).

    ``press`` receives ``p / coefficient`` and ``depth`` the depth [m] of each window node
    (index ``o + quarter``); ``higher`` asks for the second and third derivatives of a
    power law 1.5 (linear springs always give the second; NaN where not computed). Each
    combination of exponent (1 or 1.5) and curvature form is a loop of its own whose
    constants LLVM folds: a branch (or an untaken ``pow``) inside the loop keeps it from
    being vectorised (up to 10x slower).
    """
    rp, exponent = grid[3], grid[4]
    series = s * s <= _SERIES_LIMIT * rp * rp
    if exponent == 1.5:
        if series:
            total, slope, second = _springs(s, nodes, grid, line, width, press, depth, True, True)
        else:
            total, slope, second = _springs(s, nodes, grid, line, width, press, depth, True, False)
        if higher:
            second, third = _curvatures(s, nodes, grid, line, width, depth)
            return total, slope, second, third
    elif series:
        total, slope, second = _springs(s, nodes, grid, line, width, press, depth, False, True)
    else:
        total, slope, second = _springs(s, nodes, grid, line, width, press, depth, False, False)
    return total, slope, second, np.nan


@njit(inline="always", **_FLAGS)
def _angle(cos_offset, sin_offset, cos_shift, sin_shift):
    """``cos(phi)`` and ``sin^2(phi)`` of ``phi = o dtheta + shift`` by angle addition."""
    sin_phi = sin_offset * cos_shift + cos_offset * sin_shift
    return cos_offset * cos_shift - sin_offset * sin_shift, sin_phi * sin_phi


@njit(inline="always", **_FLAGS)
def _pin_curvature(x, rp, inv_rp, series):
    """``R_p - sqrt(R_p^2 - x)`` and ``1 / sqrt(R_p^2 - x)`` for ``x = s^2 sin^2(phi)``.

    With ``series`` (``x / R_p^2 <= 1e-3``) from their Taylor series in ``y = x / R_p^2``,
    exact to ~1e-20 relative there, without a square root or a division (``inv_rp`` is
    ``1 / R_p``: a division in the loop would not be turned into a product).
    """
    if series:
        y = x * inv_rp * inv_rp
        poly = 0.0390625 + y * (0.02734375 + y * 0.0205078125)
        curv = rp * y * (0.5 + y * (0.125 + y * (0.0625 + y * poly)))
        poly = 0.3125 + y * (0.2734375 + y * 0.24609375)
        return curv, (1.0 + y * (0.5 + y * (0.375 + y * poly))) * inv_rp
    root = math.sqrt(rp * rp - x)
    return x / (root + rp), 1.0 / root


@njit(inline="always", **_FLAGS)
def _springs(s, nodes, grid, line, width, press, depth, power15, series):
    """``sum_j p_j A_j cos(phi_j)``, its slope in ``s`` and (linear springs) its curvature.

    Linear springs: between two nodes coming into contact the force is linear in ``s``
    but for the pin's curvature, ``f'' = sum_j k A_j cos(phi_j) delta_j''`` over the nodes
    in contact, a few flops more; with it the step is Chebyshev's (power law 1.5: NaN).
    """
    gap_ext, area_ext, cos_o, sin_o = nodes
    quarter, rp, coefficient = grid[1], grid[3], grid[5]
    base, cs, ss, load_gap, load_area = line
    total = 0.0
    slope = 0.0
    second = 0.0
    s2 = s * s
    inv_rp = 1.0 / rp
    for o in range(-width, width + 1):
        i = o + quarter
        c, sin2 = _angle(cos_o[i], sin_o[i], cs, ss)
        curv, inv_root = _pin_curvature(s2 * sin2, rp, inv_rp, series)
        d = s * c - (gap_ext[base + o] + load_gap) - curv
        pen = max(d, 0.0)
        weight = coefficient * (area_ext[base + o] * load_area) * c
        along = c - s * sin2 * inv_root  # d depth / ds
        if power15:
            r = math.sqrt(pen)
            p = pen * r
            slope += weight * 1.5 * r * along
        else:
            p = pen
            touching = 1.0 if pen > 0.0 else 0.0
            slope += weight * along * touching
            second -= weight * touching * sin2 * inv_root * (1.0 + s2 * sin2 * inv_root * inv_root)
        total += weight * p
        press[i] = p
        depth[i] = d
    if power15:
        second = np.nan
    return total, slope, second


@njit(**_FLAGS)
def _curvatures(s, nodes, grid, line, width, depth):
    """Second and (leading term of the) third derivative of the force, ``p = k delta^1.5``.

    ``f'' = sum_j w_j (p''(delta_j) delta_j'^2 + p'(delta_j) delta_j'')`` and
    ``f''' ~ sum_j w_j p'''(delta_j) delta_j'^3`` (``p''' ~ delta^-1.5`` dominates where a
    node barely touches), ``w_j = A_j cos(phi_j)``, from the depths of the evaluation.
    """
    _, area_ext, cos_o, sin_o = nodes
    quarter, rp, coefficient = grid[1], grid[3], grid[5]
    base, cs, ss, _, load_area = line
    second = 0.0
    third = 0.0
    s2 = s * s
    series = s2 <= _SERIES_LIMIT * rp * rp
    inv_rp = 1.0 / rp
    for o in range(-width, width + 1):
        i = o + quarter
        c, sin2 = _angle(cos_o[i], sin_o[i], cs, ss)
        x = s2 * sin2
        _, inv_root = _pin_curvature(x, rp, inv_rp, series)
        pen = max(depth[i], 0.0)
        weight = coefficient * (area_ext[base + o] * load_area) * c
        along = c - s * sin2 * inv_root
        bend = -sin2 * inv_root * (1.0 + x * inv_root * inv_root)  # d2 depth / ds2
        r = math.sqrt(pen)
        inv_r = r / (pen + 1e-300)  # 1 / sqrt(depth) in contact, 0 elsewhere
        second += weight * (0.75 * inv_r * along * along + 1.5 * r * bend)
        third -= weight * 0.375 * inv_r * inv_r * inv_r * along * along * along
    return second, third


@njit(**_FLAGS)
def _reach(s, gap_min, dtheta, quarter):
    """Window half-width [nodes] holding every node that can touch at offset ``s`` [m].

    A node's depth is at most ``s cos(phi) - g_min``: none beyond ``arccos(g_min / s)``
    (a window of half-width ``W`` holds the nodes within ``(W - 1/2) dtheta``).
    """
    if s <= gap_min:
        return 1
    width = math.ceil(math.acos(gap_min / s) / dtheta + 0.5) + 1
    return min(max(width, 1), quarter)


@njit(**_FLAGS)
def _step(s, f, slope, total, second, third, curvature):
    """Newton's step, Chebyshev's where a curvature is known, plus a cubic refinement.

    Without ``second`` the Chebyshev term comes from ``kappa`` (``curvature``) of a
    force ``~ u^m`` (:func:`jointwear.contact.balance._curvature`).
    """
    newton = -f / slope
    if not math.isnan(second):
        change = newton * (1.0 + 0.5 * second / (slope * slope) * f)
        if not math.isnan(third):
            value = f + change * (slope + change * (0.5 * second + change * third / 6.0))
            correction = value / (slope + change * (second + 0.5 * change * third))
            if abs(correction) <= 0.5 * abs(change):
                change -= correction
        return s + change
    return s + newton * (1.0 + 0.5 * curvature * f / total)


@njit(**_FLAGS)
def _balance(load, s, lower, upper, gap_min, nodes, grid, line, solver, higher, press, depth):
    """Bracketed Newton for one load from ``s`` [m]: (offset, force, slope, width, its, ok).

    Accepted: ``|f| <= max(atol, 8 eps sum|f_j|)`` (the paper's 1e-12 N with a round-off
    floor); or, twice in a row, a residual that ``ulps`` units in the last place of ``s``
    explain (where one ulp of ``s`` moves the sum by more than its own round-off there
    is nothing left to bisect); or a bracket collapsed to round-off around a residual
    its slope explains. The state returned is the last one evaluated.
    """
    atol, ulps, max_iterations, curvature = solver
    dtheta, quarter = grid[2], grid[1]
    lo, hi = lower, upper
    s = min(max(s, lo), hi)
    hits = 0
    width = 1
    total = 0.0
    slope = 0.0
    for it in range(1, max_iterations + 1):
        width = _reach(s, gap_min, dtheta, quarter)
        total, slope, second, third = _evaluate(s, nodes, grid, line, width, higher, press, depth)
        f = total - load
        error = abs(f)
        # far off (a cold start's first steps): keep taking fourth-order steps
        higher = higher and error > 1e-6 * load
        if error <= max(atol, 8.0 * _EPS * total):
            return s, total, slope, width, it, True
        if slope > 0.0 and error <= ulps * _EPS * abs(s) * slope:
            hits += 1
            if hits >= 2:
                return s, total, slope, width, it, True
        if f < 0.0:
            lo = s
        else:
            hi = s
        new = _step(s, f, slope, total, second, third, curvature)
        if not (lo < new < hi):
            new = 0.5 * (lo + hi)
        bracket = hi - lo
        ulp = _EPS * abs(s)
        if bracket <= 4.0 * max(ulp, 1e-300):
            return s, total, slope, width, it, error <= 2.0 * slope * max(bracket, ulp)
        s = new
    return s, total, slope, width, max_iterations, False


@njit(**_FLAGS)
def revolution(
    load,
    sliding,
    guess,
    have_guess,
    conformal,
    nodes,
    grid,
    lines,
    solver,
    floats,
    counts,
    wear_ext,
):
    """Balance every load of a revolution and add its wear ``p ds / coefficient`` per node.

    Loads are solved in order. With ``have_guess`` each starts from ``guess`` [m];
    otherwise from its predecessor's balance moved by the change of load (a Chebyshev
    step) plus the predecessor's own miss (on a worn contour the force curve moves with
    the azimuth, smoothly from load to load), the first one from the conformal estimate
    ``conformal`` [m], and takes fourth-order steps while far off. Out: ``floats`` rows
    offset [m], force [N], tangential force [N], left and right half-angle [rad], peak
    pressure [Pa]; ``counts`` rows iterations, springs left and right, status.
    """
    centre, cos_shift, sin_shift, load_gap, load_area, gap_min, lower, upper = lines
    gap_ext = nodes[0]
    pad, quarter, dtheta, coefficient = grid[0], grid[1], grid[2], grid[5]
    press = np.empty(2 * quarter + 1)
    depth = np.empty(2 * quarter + 1)
    previous_s = np.nan
    previous_total = 0.0
    previous_slope = 0.0
    drift = 0.0
    for k in range(load.size):
        base = centre[k] + pad
        line = (base, cos_shift[k], sin_shift[k], load_gap[k], load_area[k])
        if load[k] <= 0.0:
            # no load: the pin just touches the nearest node of the quarter window
            touch = np.inf
            for o in range(-quarter, quarter + 1):
                touch = min(touch, gap_ext[base + o] + load_gap[k])
            floats[0, k] = touch
            counts[3, k] = CONVERGED
            previous_s = np.nan
            continue
        predicted = np.nan
        if have_guess:
            s = guess[k]
        elif previous_s == previous_s and previous_slope > 0.0:
            change = previous_total - load[k]
            predicted = previous_s - change / previous_slope * (
                1.0 + 0.5 * solver[3] * change / previous_total
            )
            s = predicted + drift
        else:
            s = conformal[k]
        s, total, slope, width, its, ok = _balance(
            load[k], s, lower[k], upper[k], gap_min[k], nodes, grid, line, solver,
            not have_guess, press, depth,
        )  # fmt: skip
        floats[0, k] = s
        floats[1, k] = total
        counts[0, k] = its
        counts[3, k] = CONVERGED if ok else NOT_CONVERGED
        previous_s, previous_total, previous_slope = s, total, slope
        drift = s - predicted if predicted == predicted else 0.0
        # the balanced state is the last evaluation: its wear, resultants and extent
        floats[2, k], floats[5, k] = _settle(sliding[k], nodes, grid, line, width, press, wear_ext)
        shift = math.atan2(sin_shift[k], cos_shift[k])
        floats[3, k], floats[4, k], counts[1, k], counts[2, k] = _extent(
            depth, quarter, width, dtheta, shift
        )
    floats[2] *= coefficient
    floats[5] *= coefficient


@njit(**_FLAGS)
def _settle(ds, nodes, grid, line, width, press, wear_ext):
    """Add ``p ds / coefficient`` of one load to the nodes; its tangential force and peak.

    Every node of the window is added (``p`` is 0 out of contact): no branch, one
    vectorised loop. Both results are still to be multiplied by the coefficient.
    """
    _, area_ext, cos_o, sin_o = nodes
    quarter = grid[1]
    base, cs, ss, _, load_area = line
    sideways = 0.0
    top = 0.0
    for o in range(-width, width + 1):
        i = o + quarter
        p = press[i]
        wear_ext[base + o] += ds * p
        sideways += area_ext[base + o] * (sin_o[i] * cs + cos_o[i] * ss) * p
        top = max(top, p)
    return load_area * sideways, top


@njit(**_FLAGS)
def _extent(depth, quarter, width, dtheta, shift):
    """Contact half-angles left and right of the load line [rad], and springs in contact.

    The outermost node in contact each side is found by scanning in from the window's
    edges (a few nodes: the window is the pin's reach); the edge lies between it and
    the next node out, interpolated linearly in depth.
    """
    last = width
    while last >= -width and not depth[last + quarter] > 0.0:
        last -= 1
    if last < -width:
        return 0.0, 0.0, 0, 0
    first = -width
    while not depth[first + quarter] > 0.0:
        first += 1
    n_left = 0
    n_right = 0
    for o in range(first, last + 1):
        touching = depth[o + quarter] > 0.0
        n_left += touching and o > 0
        n_right += touching and o < 0
    if depth[quarter] > 0.0:
        n_left += shift > 0.0
        n_right += shift < 0.0
    left = _edge(last, min(last + 1, width), depth, quarter, dtheta, shift)
    right = -_edge(first, max(first - 1, -width), depth, quarter, dtheta, shift)
    return max(left, 0.0), max(right, 0.0), n_left, n_right


@njit(**_FLAGS)
def _edge(inside, outside, depth, quarter, dtheta, shift):
    """Angle of a contact edge [rad], between the last node in and the next one out."""
    d_in = depth[inside + quarter]
    d_out = depth[outside + quarter]
    drop = d_in - d_out
    frac = d_in / drop if drop > 0.0 else 0.0
    phi_in = inside * dtheta + shift
    phi_out = outside * dtheta + shift
    return phi_in + frac * (phi_out - phi_in)


@njit(**_FLAGS)
def dense_pressure(offset, load, nodes, grid, lines, out):
    """Pressure of every load at its balanced offset on all nodes [Pa] (rows of ``out``).

    The same evaluation as the balance's last one, so the same numbers bit for bit.
    """
    centre, cos_shift, sin_shift, load_gap, load_area, gap_min = lines[:6]
    pad, quarter, dtheta, coefficient = grid[0], grid[1], grid[2], grid[5]
    nodes_count = out.shape[1]
    press = np.empty(2 * quarter + 1)
    depth = np.empty(2 * quarter + 1)
    for k in range(offset.size):
        if load[k] <= 0.0:
            continue
        line = (centre[k] + pad, cos_shift[k], sin_shift[k], load_gap[k], load_area[k])
        width = _reach(offset[k], gap_min[k], dtheta, quarter)
        _evaluate(offset[k], nodes, grid, line, width, False, press, depth)
        for o in range(-width, width + 1):
            if depth[o + quarter] > 0.0:
                out[k, (centre[k] + o) % nodes_count] = coefficient * press[o + quarter]
