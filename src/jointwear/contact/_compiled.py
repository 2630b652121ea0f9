"""The fused contact balance + Archard step, compiled by numba.

Imported by :mod:`jointwear.contact.kernel` on first use only (``import numba`` and
loading the cached machine code cost a few tenths of a second, which a run that never
solves a revolution should not pay). The physics is that of
:mod:`jointwear.contact.balance` (paper eqs. (5)/(7): the pin moves along the load
line by ``s``, node ``j`` penetrates by ``s cos(phi_j) - g_j - (R_p - sqrt(R_p^2 - s^2
sin^2(phi_j)))`` and the springs' force along the load balances the load); what differs
is the arithmetic: one loop per load over the nodes that can touch, no temporaries,
and the wear of a load added to the nodes as soon as it is balanced.

The window of a load is not symmetric about its load line: the pin's reach from the
smallest gap of the contour (:func:`_reach`) bounds it, and each side is then trimmed to
the outermost node whose depth ``s cos(phi) - g`` could be positive (:func:`_trim`). On
a worn contour the contact lies to one side of the load line (the worn groove lags the
load), and the gaps beside the groove exceed the contour's smallest: late in a long run
the reach's symmetric window held ~140 nodes for ~92 in contact, the trimmed one ~94.
The trimmed window is then widened to whole vectors of 8 nodes (:func:`_whole_vectors`).

The window of load ``k`` is read from arrays padded by a quarter circle each side
(``ext[c + o + pad]`` is node ``(c + o) mod N``), so no loop has a modulo; loops index
them by unsigned offsets (``uint64``), because an index that could be negative is
wrapped around by numba, which turns the loads into gathers (3x slower), and a window
view per evaluation would cost its reference counting. ``fastmath``
only reassociates the sums and contracts to FMA: no approximate division or square
root. Arguments travel in tuples:

* ``nodes``: ``(gap_ext, area_ext, cos_o, sin_o, half_cos)``, the padded node gaps
  ``r_j - R_p`` [m] and spring areas [m^2], ``cos``/``sin`` of the window offsets
  ``o dtheta`` and ``cos((n - 1/2) dtheta)`` (:func:`_reach`);
* ``grid``: ``(pad, quarter, dtheta, rp, exponent, coefficient)``;
* ``lines``: per load ``(centre, cos_shift, sin_shift, load_gap, load_area, gap_min,
  lower, upper, shift)``, the node nearest the load line, the load line's angle from
  it, a gap and area factor per load (the symmetric law's circle), the smallest gap
  the pin can meet, the bracket of the offset [m] and the angle [rad];
* ``line``: one load's ``(base, cos_shift, sin_shift, load_gap, load_area)``;
* ``work``: the window scratch of one load, one array per row ``_DEPTH`` .. ``_PRESS``
  (:func:`scratch`), by offset from the window's start (node ``-right`` of the load's
  centre node).

Every helper is inlined into :func:`revolution` (``inline="always"``): a call that
passes arrays costs reference counting of each, which made a revolution twice as slow;
and :func:`revolution` itself is compiled without reference counting (``_nrt=False``),
whose atomic operations on the arrays passed between the inlined helpers still took a
fifth of a revolution, and with its array arguments declared ``noalias`` to LLVM
(:class:`Unaliased`), whose run-time overlap checks before each vectorised loop took a
tenth.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, uint64
from numba.core.compiler import CompilerBase, DefaultPassBuilder

#: results per load (``status``)
CONVERGED, NOT_CONVERGED = 0, 1
#: up to these ``(s / R_p)^2`` the pin-curvature term is taken from its series to ``y^4``
#: and ``y^6`` (exact to ~1e-17 relative there), which need neither a square root nor a
#: division; beyond, the closed form. The second is where a worn joint's offset goes
#: (the paper's joint passes 1e-4 within its first thousand revolutions); a third tier
#: to ``y^8`` (up to 1e-2) was dropped: each tier is a loop per law to compile (~8 s)
_SHORT_SERIES, _LONG_SERIES = 1e-4, 2e-3
_EPS = 2.220446049250313e-16
#: doubles per vector register (AVX-512); windows are whole multiples of it
_LANES = 8
#: steps from the last full evaluation up to ``_REUSE R_p`` in all move the depths by
#: their second-order Taylor polynomial to within ``eps s / 16`` (see :func:`_balance`)
_REUSE = (_EPS / 64.0) ** (1.0 / 3.0)
_FLAGS = {"cache": True, "error_model": "numpy", "fastmath": {"reassoc", "contract"}}
#: spring laws of :func:`_springs`: ``p = k delta``, ``p = k delta^1.5`` and the latter
#: with its curvature
_LINEAR, _HERTZIAN, _CURVED = 1, 2, 3
#: rows of ``work``: per node of the window, depth [m], its first and second derivative
#: in the offset, ``A_j cos(phi_j)``, ``A_j sin(phi_j)`` and ``p / k`` (not written for
#: linear springs, whose ``p / k`` is the depth's positive part)
_DEPTH, _ALONG, _CURVE, _WEIGHT, _SIDE, _PRESS = range(6)


class Unaliased(CompilerBase):
    """numba's pipeline, with every array argument declared ``noalias`` to LLVM.

    Without it each vectorised loop first compares the address ranges of every array it
    writes with those of every other array it touches (the rows of ``work``, the padded
    node arrays, the tables, the wear): a tenth of a warm revolution. The arrays of
    :func:`revolution` are distinct buffers (the caller's scratch, its outputs and the
    contour's arrays, read only).
    """

    def define_pipelines(self):
        self.state.flags.noalias = True
        return [DefaultPassBuilder.define_nopython_pipeline(self.state)]


def scratch(quarter: int) -> tuple[np.ndarray, ...]:
    """The window scratch of :func:`revolution`: one array per row of ``work`` (rows of one
    2-D array are not vectorised), ``2 quarter + 1`` long."""
    size = 2 * quarter + 1
    return tuple(np.zeros(size) for _ in range(6))


@njit(inline="always", **_FLAGS)
def _evaluate(s, rp, exponent, nodes, grid, line, right, left, work, curved):
    """Springs of one load at offset ``s`` [m]: (force [N], slope [N/m], curvature [N/m^2]).

    The window holds the nodes ``-right .. left`` of the load's centre node.

    The window geometry and the springs in one pass (:func:`_springs`); the curvature
    for linear springs, and for ``delta^1.5`` where ``curved`` (NaN otherwise). Each
    combination of exponent (1 or 1.5) and
    curvature form is a loop of its own whose constants LLVM folds: a branch (or an
    untaken ``pow``) inside the loop keeps it from being vectorised (up to 10x slower).
    """
    terms = _series_terms(s, rp)
    # (literal arguments: each call below is a loop of its own)
    if exponent == 1.0:
        if terms == 4:
            return _springs(s, nodes, grid, line, right, left, work, _LINEAR, 4)
        if terms == 6:
            return _springs(s, nodes, grid, line, right, left, work, _LINEAR, 6)
        return _springs(s, nodes, grid, line, right, left, work, _LINEAR, 0)
    if curved:
        if terms == 4:
            return _springs(s, nodes, grid, line, right, left, work, _CURVED, 4)
        if terms == 6:
            return _springs(s, nodes, grid, line, right, left, work, _CURVED, 6)
        return _springs(s, nodes, grid, line, right, left, work, _CURVED, 0)
    if terms == 4:
        return _springs(s, nodes, grid, line, right, left, work, _HERTZIAN, 4)
    if terms == 6:
        return _springs(s, nodes, grid, line, right, left, work, _HERTZIAN, 6)
    return _springs(s, nodes, grid, line, right, left, work, _HERTZIAN, 0)


@njit(inline="always", **_FLAGS)
def _series_terms(s, rp):
    """Terms of the pin-curvature series that are exact at offset ``s`` (0: closed form)."""
    ratio = s * s / (rp * rp)
    if ratio <= _SHORT_SERIES:
        return 4
    return 6 if ratio <= _LONG_SERIES else 0


@njit(inline="always", **_FLAGS)
def _pin_curvature(y, rp, terms):
    """``R_p - sqrt(R_p^2 - x)`` [m] and ``q = R_p / sqrt(R_p^2 - x)`` for ``x = s^2
    sin^2(phi) = y R_p^2``.

    With ``terms`` 4 or 6 (``y`` up to 1e-4 or 2e-3) from their Taylor series in ``y``
    (``R_p (y/2 + y^2/8 + y^3/16 + 5 y^4/128 + ...)`` and ``1 + y/2 + 3 y^2/8 + ...``; the
    first term left out is below ~3e-17 of the sum there), without a square root or a
    division (the products of ``R_p`` and the coefficients are loop constants).
    """
    if terms == 4:
        curv = y * (rp * 0.5 + y * (rp * 0.125 + y * (rp * 0.0625 + y * (rp * 0.0390625))))
        return curv, 1.0 + y * (0.5 + y * (0.375 + y * 0.3125))
    if terms == 6:
        tail = rp * 0.0390625 + y * (rp * 0.02734375 + y * (rp * 0.0205078125))
        curv = y * (rp * 0.5 + y * (rp * 0.125 + y * (rp * 0.0625 + y * tail)))
        return curv, 1.0 + y * (0.5 + y * (0.375 + y * (0.3125 + y * (0.2734375 + y * 0.24609375))))
    x = y * rp * rp
    root = math.sqrt(rp * rp - x)
    return x / (root + rp), rp / root


@njit(inline="always", **_FLAGS)
def _spring(depth, law):
    """``p / k`` of one spring at ``depth`` [m] (0 out of contact) and ``p' / k``, but for
    ``delta^1.5`` ``sqrt(delta)``: its factor 1.5 is applied to the sums."""
    pen = max(depth, 0.0)
    if law == _LINEAR:
        return pen, 1.0 if pen > 0.0 else 0.0
    root = math.sqrt(pen)
    return pen * root, root


@njit(inline="always", **_FLAGS)
def _springs(s, nodes, grid, line, right, left, work, law, terms):
    """``sum_j p_j A_j cos(phi_j)``, its slope in ``s`` and (linear springs) its curvature.

    ``law`` is ``_LINEAR`` (``p = k delta``), ``_HERTZIAN`` (``p = k delta^1.5``) or
    ``_CURVED`` (the same with its curvature, for a cold start). The
    window's geometry comes with it: ``cos(phi_j)`` and ``sin(phi_j)`` by angle addition
    from the tables, the gap and the spring area of each node; every row of ``work`` is
    written (what a later :func:`_springs_moved` and the wear read).
    Linear springs: between two nodes coming into contact the force is linear in ``s``
    but for the pin's curvature, ``f'' = sum_j k A_j cos(phi_j) delta_j''`` over the nodes
    in contact, a few flops more; with it the step is Chebyshev's. For ``delta^1.5`` the
    curvature costs a division per node (``p'' = 3 / (4 sqrt(delta))``): taken where a
    start is cold (it saves the third evaluation), else NaN (the step uses ``kappa``).

    Every factor common to the nodes is left out of the loop and applied to the sums
    (fewer multiplications, the loop's bound for linear springs): the load's
    ``k A`` factor (rows ``_WEIGHT`` and ``_SIDE`` hold ``A_j cos(phi_j)`` and ``A_j
    sin(phi_j)``), the ``1.5`` of ``delta^1.5``'s slope and the ``-1 / R_p`` of the
    second derivative (row ``_CURVE`` holds ``-R_p delta_j''``); the pin curvature is a
    series in ``y = (s / R_p)^2 sin^2(phi_j)`` with ``R_p`` folded into its coefficients,
    and ``delta_j' = cos(phi_j) - (s / R_p) sin^2(phi_j) q_j``, ``-R_p delta_j'' = sin^2
    (phi_j) q_j^3`` with ``q_j = R_p / sqrt(R_p^2 - x_j)``: ~28 vector operations per
    8 nodes instead of 34 (a few per cent of a warm Winkler revolution; none for
    ``delta^1.5``, whose loop waits on its square roots).
    """
    gap, area, co, so = nodes[0], nodes[1], nodes[2], nodes[3]
    quarter, rp, coefficient = grid[1], grid[3], grid[5]
    base, cs, ss, load_gap, load_area = line
    # unsigned offsets: numba wraps a possibly negative index (a gather), and a slice per
    # array would cost its reference counting per evaluation
    start, first = uint64(base - right), uint64(quarter - right)
    depth, slopes, bends, weights, sides, press = work
    total = 0.0
    slope = 0.0
    second = 0.0
    inv_rp = 1.0 / rp
    ratio = s * inv_rp
    square = ratio * ratio
    for j in range(uint64(right + left + 1)):
        c = co[first + j] * cs - so[first + j] * ss
        sn = so[first + j] * cs + co[first + j] * ss
        sin2 = sn * sn
        curv, q = _pin_curvature(square * sin2, rp, terms)
        d = s * c - (gap[start + j] + load_gap) - curv
        bent = sin2 * q
        along = c - ratio * bent  # d depth / ds
        bend = bent * q * q  # -R_p d2 depth / ds2
        weight = area[start + j] * c
        p, stiffness = _spring(d, law)
        total += weight * p
        slope += weight * stiffness * along
        if law == _LINEAR:  # where in contact
            second += weight * stiffness * bend
        if law == _CURVED:  # p'' = 1.125 / p' in contact
            curl = 0.75 / stiffness if stiffness > 0.0 else 0.0
            second += weight * (curl * along * along - 1.5 * inv_rp * stiffness * bend)
        depth[j] = d
        slopes[j] = along
        bends[j] = bend
        weights[j] = weight
        sides[j] = area[start + j] * sn
        if law != _LINEAR:  # (linear springs: p / k is the depth's positive part)
            press[j] = p
    factor = coefficient * load_area
    if law == _LINEAR:
        return factor * total, factor * slope, -factor * inv_rp * second
    if law == _HERTZIAN:
        return factor * total, 1.5 * factor * slope, np.nan
    return factor * total, 1.5 * factor * slope, factor * second


@njit(inline="always", **_FLAGS)
def _springs_moved(step, size, work, law, factor, inv_rp):
    """:func:`_springs` after a small step [m] from the last evaluation, without geometry or
    pin curvature: ``delta_j += step delta_j' + step^2 delta_j'' / 2`` and ``delta_j' +=
    step delta_j''``, with ``delta_j''`` of the last full evaluation (the neglected terms
    are below ``eps s / 16`` within ``_REUSE R_p`` of it, see :func:`_balance`).
    ``factor``: the load's ``k A`` factor [N/m^3]; ``inv_rp``: ``1 / R_p`` [1/m]."""
    depth, slopes, bends, weights, _, press = work
    total = 0.0
    slope = 0.0
    second = 0.0
    # row _CURVE holds -R_p delta''
    half = -0.5 * step * inv_rp
    turn = -step * inv_rp
    for j in range(uint64(size)):
        weight, along, bend = weights[j], slopes[j], bends[j]
        d = depth[j] + step * (along + half * bend)
        along += turn * bend
        p, stiffness = _spring(d, law)
        total += weight * p
        slope += weight * stiffness * along
        if law == _LINEAR:
            second += weight * stiffness * bend
        depth[j] = d
        slopes[j] = along
        if law != _LINEAR:
            press[j] = p
    if law == _LINEAR:
        return factor * total, factor * slope, -factor * inv_rp * second
    return factor * total, 1.5 * factor * slope, np.nan


@njit(inline="always", **_FLAGS)
def _reach(s, gap_min, half_cos, quarter, hint):
    """Window half-width [nodes] holding every node that can touch at offset ``s`` [m].

    A node's depth is at most ``s cos(phi) - g_min``: none beyond ``arccos(g_min / s)``;
    a window of half-width ``W`` holds the nodes within ``(W - 1/2) dtheta``, so ``W`` is
    one more than the first ``n`` with ``cos((n - 1/2) dtheta) <= g_min / s``
    (``half_cos[n]``, ``half_cos[0] = 1``), searched from ``hint``.
    """
    ratio = gap_min / s if s > 0.0 else 1.0
    n = min(max(hint, 0), quarter)
    while n > 0 and half_cos[n - 1] <= ratio:
        n -= 1
    while n <= quarter and half_cos[n] > ratio:
        n += 1
    return min(n + 1, quarter)


@njit(inline="always", **_FLAGS)
def _trim(top, nodes, quarter, line, reach):
    """Nodes right and left of the centre node [nodes] a window needs to hold every node
    that can touch up to offset ``top`` [m], within the reach ``reach`` (:func:`_reach`).

    Node ``o`` is at most ``s cos(phi_o) - g_o`` deep at offset ``s`` (the pin-curvature
    term only lowers it), so for ``s <= top`` it touches only if ``top cos(phi_o) >
    g_o``. The reach bounds the window from the global smallest gap ``g_min``; on a worn
    contour the gaps near the load line are larger, and the worn groove lags the load
    line, so the contact lies to one side of it: late in a run the reach's symmetric
    window is half as wide again as the contact. Each side is scanned in from the
    reach's edge to its outermost node that can touch, plus one node (the contact edge
    is interpolated towards the next node out, :func:`_extent`).
    """
    gap, co, so = nodes[0], nodes[2], nodes[3]
    base, cs, ss, load_gap = line[0], line[1], line[2], line[3]
    right = reach
    while right > 1:
        o = uint64(quarter - right)
        if top * (co[o] * cs - so[o] * ss) > gap[uint64(base - right)] + load_gap:
            break
        right -= 1
    left = reach
    while left > 1:
        o = uint64(quarter + left)
        if top * (co[o] * cs - so[o] * ss) > gap[uint64(base + left)] + load_gap:
            break
        left -= 1
    return min(right + 1, reach), min(left + 1, reach)


@njit(inline="always", **_FLAGS)
def _whole_vectors(right, left, quarter):
    """The window ``-right .. left`` widened to a multiple of ``_LANES`` nodes (left first,
    within a quarter circle each side): the nodes added cannot touch (their springs add
    zeros), and the loops over the window then run without a scalar remainder (a few
    per cent of a warm revolution)."""
    add = -(right + left + 1) % _LANES
    grow = min(add, quarter - left)
    return min(right + add - grow, quarter), left + grow


@njit(inline="always", **_FLAGS)
def _step(s, f, slope, total, second, curvature):
    """Chebyshev's step: with the curvature ``second`` where known, else from ``kappa``.

    ``kappa`` (``curvature``) is that of a force ``~ u^m``
    (:func:`jointwear.contact.balance.guesses._curvature`).
    """
    newton = -f / slope
    if not math.isnan(second):
        return s + newton * (1.0 + 0.5 * second / (slope * slope) * f)
    return s + newton * (1.0 + 0.5 * curvature * f / total)


@njit(inline="always", **_FLAGS)
def _moves(law, step, size, work, factor, inv_rp):
    """:func:`_springs_moved` over ``size`` nodes with the law as a literal."""
    if law == _LINEAR:
        return _springs_moved(step, size, work, _LINEAR, factor, inv_rp)
    return _springs_moved(step, size, work, _HERTZIAN, factor, inv_rp)


@njit(inline="always", **_FLAGS)
def _balance(load, s, lower, upper, gap_min, nodes, grid, line, solver, work, hint, cold):
    """Bracketed Newton for one load from ``s`` [m]: (offset, force, slope, window's nodes
    right and left of the centre node, reach, its, ok).

    Accepted: ``|f| <= max(atol, 8 eps sum|f_j|)`` (the paper's 1e-12 N with a round-off
    floor); or a residual that ``ulps`` units in the last place of ``s`` explain, where
    Newton's step is below one ulp or for the second time in a row (where one ulp of
    ``s`` moves the sum by more than its own round-off there is nothing left to
    bisect); or a bracket collapsed to round-off around a residual its slope explains.
    The state returned is the last one evaluated (``work``).

    Steps that stay within ``_REUSE R_p`` in all of the last full evaluation (and within
    its window) move the depths by their Taylor polynomial (:func:`_springs_moved`): the
    pin-curvature term's third derivative is at most ``6.2 s / R_p^3`` for ``s <= R_p /
    2``, so the neglected cubic terms stay below ``eps s / 16``. A full evaluation at
    ``s`` trims its window to the nodes that can touch up to ``s + _REUSE R_p``
    (:func:`_trim`), so every such step finds its nodes in it; ``limit`` (the largest
    offset the window holds) is that, or the reach's own bound where it is smaller.
    ``hint``: the last reach [nodes], where this one's is looked for.
    """
    atol, ulps, max_iterations, curvature = solver
    quarter, rp, exponent = grid[1], grid[3], grid[4]
    half_cos = nodes[4]
    lo, hi = lower, upper
    s = min(max(s, lo), hi)
    hits = 0
    right = 1
    left = 1
    reach = hint + 1
    limit = -np.inf  # largest offset the window of the last full evaluation holds
    travel = np.inf
    total = 0.0
    slope = 0.0
    small = _REUSE * rp if s <= 0.5 * rp else 0.0
    factor = grid[5] * line[4]
    inv_rp = 1.0 / rp
    law = _LINEAR if exponent == 1.0 else _HERTZIAN
    previous = np.nan
    for it in range(1, max_iterations + 1):
        step = s - previous
        if travel + abs(step) <= small and s <= limit:
            travel += abs(step)
            total, slope, second = _moves(law, step, right + left + 1, work, factor, inv_rp)
        else:
            reach = _reach(s, gap_min, half_cos, quarter, hint)
            hint = reach - 1
            # Taylor steps stay within ``small`` of s: the window holds every node that
            # can touch up to ``s + small``, the reach up to its own bound
            top = s + small
            right, left = _trim(top, nodes, quarter, line, reach)
            right, left = _whole_vectors(right, left, quarter)
            limit = top if reach >= quarter else min(top, gap_min / half_cos[reach - 1])
            travel = 0.0
            total, slope, second = _evaluate(
                s, rp, exponent, nodes, grid, line, right, left, work, cold
            )
        previous = s
        f = total - load
        error = abs(f)
        if error <= max(atol, 8.0 * _EPS * total):
            return s, total, slope, right, left, reach, it, True
        if slope > 0.0 and error <= ulps * _EPS * abs(s) * slope:
            # a residual a few ulp of s explain: accept it if Newton's step is below one
            # ulp (it would round to s, and a step rejected by the bracket would bisect
            # a wide one), else after one more step
            hits += 1
            if hits >= 2 or error <= _EPS * abs(s) * slope:
                return s, total, slope, right, left, reach, it, True
        if f < 0.0:
            lo = s
        else:
            hi = s
        new = _step(s, f, slope, total, second, curvature)
        if not (lo < new < hi):
            new = 0.5 * (lo + hi)
        bracket = hi - lo
        ulp = _EPS * abs(s)
        if bracket <= 4.0 * max(ulp, 1e-300):
            return s, total, slope, right, left, reach, it, error <= 2.0 * slope * max(bracket, ulp)
        s = new
    return s, total, slope, right, left, reach, max_iterations, False


@njit(_nrt=False, pipeline_class=Unaliased, **_FLAGS)
def revolution(load, sliding, guess, have_guess, conformal, nodes, grid, lines, solver,
               floats, counts, wear_ext, scale, wear, work):  # fmt: skip
    """Balance every load of a revolution and add its wear ``p ds / k`` per node.

    Loads are solved in order. With ``have_guess`` each starts from ``guess`` [m];
    otherwise from its predecessor's balance moved by the change of load (a Chebyshev
    step) plus the predecessor's own miss (on a worn contour the force curve moves with
    the azimuth, smoothly from load to load), the first one from the conformal estimate
    ``conformal`` [m] (three evaluations a load, against two warm). Out: ``floats`` rows
    offset [m] and force [N]; ``counts`` rows iterations and status. The wear of the
    padded window positions (``wear_ext``, zeroed here) is folded onto the nodes and
    scaled by ``scale`` into ``wear`` [m]. Every entry of the outputs is written: the
    caller need not zero them. What a run does not read every revolution (the contact
    extent, the tangential force, the peak pressure, the springs in contact) is not
    computed here: :func:`balanced_state` evaluates it when it is asked for (a tenth of
    a warm revolution).

    Compiled without reference counting (``_nrt=False``: an array passed between the
    inlined helpers cost two atomic operations, a fifth of a revolution): the scratch
    ``work`` (:func:`scratch`) comes from the caller. Every array written here must be a
    buffer of its own, distinct from every other argument (``noalias``,
    :class:`Unaliased`).

    Returns the number of loads not balanced and the widest window [nodes] either side
    of a load's centre node (it holds every node in contact).
    """
    centre, cos_shift, sin_shift, load_gap, load_area, gap_min, lower, upper = lines[:8]
    gap_ext = nodes[0]
    pad, quarter = grid[0], grid[1]
    linear = grid[4] == 1.0
    widest = 0
    previous_s = np.nan
    previous_total = 0.0
    previous_slope = 0.0
    drift = 0.0
    reach = 2  # the last load's reach: where the next one's is looked for
    for i in range(wear_ext.size):
        wear_ext[i] = 0.0
    for k in range(load.size):
        base = centre[k] + pad
        line = (base, cos_shift[k], sin_shift[k], load_gap[k], load_area[k])
        if load[k] <= 0.0:
            # no load: the pin just touches the nearest node of the quarter window
            touch = np.inf
            for o in range(-quarter, quarter + 1):
                touch = min(touch, gap_ext[base + o] + load_gap[k])
            floats[0, k] = touch
            for row in range(1, floats.shape[0]):
                floats[row, k] = 0.0
            for row in range(counts.shape[0]):
                counts[row, k] = 0
            counts[1, k] = CONVERGED
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
        s, total, slope, right, left, reach, its, ok = _balance(
            load[k], s, lower[k], upper[k], gap_min[k], nodes, grid, line, solver,
            work, reach - 1, not have_guess,
        )  # fmt: skip
        floats[0, k] = s
        floats[1, k] = total
        counts[0, k] = its
        counts[1, k] = CONVERGED if ok else NOT_CONVERGED
        previous_s, previous_total, previous_slope = s, total, slope
        drift = s - predicted if predicted == predicted else 0.0
        widest = max(widest, right, left)
        # the balanced state is the last evaluation: its wear
        if linear:
            _settle(sliding[k], work, wear_ext, base - right, right, left, _LINEAR)
        else:
            _settle(sliding[k], work, wear_ext, base - right, right, left, _HERTZIAN)
    failed = 0
    for k in range(load.size):
        failed += counts[1, k] != CONVERGED
    # padded position i is node (i - pad) mod N: the nodes, then the left and the right
    # padding added (no modulo: an integer division each; no node gets both paddings,
    # and a sum of two is the same either way round)
    nodes_count = wear.size
    middle = wear_ext[pad : pad + nodes_count]
    for j in range(nodes_count):
        wear[j] = middle[j]
    left = wear[nodes_count - pad :]
    for i in range(pad):
        left[i] += wear_ext[i]
    right = wear_ext[pad + nodes_count :]
    for i in range(right.size):
        wear[i] += right[i]
    for j in range(nodes_count):
        wear[j] *= scale
    return failed, widest


@njit(inline="always", **_FLAGS)
def _settle(ds, work, wear, start, right, left, law):
    """Add ``p ds / k`` of one load to its nodes (``wear``).

    ``p / k`` is the row ``_PRESS``, but for linear springs (``law``) the positive part
    of the depth, which the evaluations then need not store (a store per node and
    evaluation). The window holds ``right`` nodes right of the centre column and
    ``left`` left of it (offsets from ``start``). Every node of the window is added
    (``p`` is 0 out of contact): no branch.
    """
    depth, press = work[_DEPTH], work[_PRESS]
    offset = uint64(start)
    for j in range(uint64(right + left + 1)):
        p = max(depth[j], 0.0) if law == _LINEAR else press[j]
        wear[offset + j] += ds * p


@njit(inline="always", **_FLAGS)
def _extent(depth, right, left, dtheta, shift):
    """Contact half-angles left and right of the load line [rad].

    ``depth`` holds the window (offsets ``-right .. left``) first. The outermost node in
    contact each side is found by scanning in from the window's edges (a node or two:
    the window is trimmed to the nodes that can touch); the edge lies between it and the
    next node out, interpolated linearly in depth.
    """
    size = right + left + 1
    last = size - 1
    while last >= 0 and not depth[last] > 0.0:
        last -= 1
    if last < 0:
        return 0.0, 0.0
    first = 0
    while not depth[first] > 0.0:
        first += 1
    half_left = _edge(last, min(last + 1, size - 1), depth, right, dtheta, shift)
    half_right = -_edge(first, max(first - 1, 0), depth, right, dtheta, shift)
    return max(half_left, 0.0), max(half_right, 0.0)


@njit(inline="always", **_FLAGS)
def _edge(inside, outside, depth, right, dtheta, shift):
    """Angle of a contact edge [rad], between the last node in and the next one out
    (window positions; the centre column is position ``right``)."""
    d_in = depth[inside]
    d_out = depth[outside]
    drop = d_in - d_out
    frac = d_in / drop if drop > 0.0 else 0.0
    phi_in = (inside - right) * dtheta + shift
    phi_out = (outside - right) * dtheta + shift
    return phi_in + frac * (phi_out - phi_in)


@njit(**_FLAGS)
def balanced_state(offset, load, nodes, grid, lines, pressure, floats, springs, work):
    """What :func:`revolution` leaves out, from one full evaluation of every load at its
    balanced offset ``offset`` [m]: the pressure on all nodes [Pa] (rows of
    ``pressure``, zeros; none written where it has no rows); ``floats`` rows tangential
    force [N], contact half-angles left and right of the load line [rad] and peak
    pressure [Pa]; ``springs`` rows springs in contact left and right (the centre
    column's side is the sign of its angle from the load line).

    The evaluation is the balance's last one, or within ``eps s / 16`` of it in depth
    where that one was a Taylor step.
    """
    centre, cos_shift, sin_shift, load_gap, load_area, gap_min = lines[:6]
    shifts = lines[8]
    pad, quarter, dtheta, rp, exponent, coefficient = grid
    nodes_count = pressure.shape[1]
    fill = pressure.shape[0] > 0
    depth, sides, press = work[_DEPTH], work[_SIDE], work[_PRESS]
    reach = 2
    for k in range(offset.size):
        for row in range(floats.shape[0]):
            floats[row, k] = 0.0
        springs[0, k] = 0
        springs[1, k] = 0
        if load[k] <= 0.0:
            continue
        base = centre[k] + pad
        line = (base, cos_shift[k], sin_shift[k], load_gap[k], load_area[k])
        reach = _reach(offset[k], gap_min[k], nodes[4], quarter, reach - 1)
        right, left = _trim(offset[k], nodes, quarter, line, reach)
        _evaluate(offset[k], rp, exponent, nodes, grid, line, right, left, work, False)
        sideways = 0.0
        top = 0.0
        for o in range(-right, left + 1):
            d = depth[o + right]
            if d > 0.0:
                p = d if exponent == 1.0 else press[o + right]
                sideways += sides[o + right] * p
                top = max(top, p)
                springs[0, k] += o > 0 or (o == 0 and shifts[k] > 0.0)
                springs[1, k] += o < 0 or (o == 0 and shifts[k] < 0.0)
                if fill:
                    pressure[k, (centre[k] + o) % nodes_count] = coefficient * p
        floats[0, k] = coefficient * load_area[k] * sideways
        floats[1, k], floats[2, k] = _extent(depth, right, left, dtheta, shifts[k])
        floats[3, k] = coefficient * top


@njit(_nrt=False, **_FLAGS)
def prepare(load, radius, rp, built, out):
    """Build the contour's arguments of :func:`revolution` in place, for a warm revolution:
    False for an input the caller must check (a load not finite or negative, a pin that
    does not fit, a load line out of the pin's reach).

    A function of its own: inlined into :func:`revolution` it slowed its loops down (a
    cold revolution by a few per cent), for a microsecond it saves there.
    ``radius``: the node radii [m]; ``rp``: the pin's [m]. ``built``: ``(mode, area,
    below, above, weight, rest, padded, spring, reach)``, ``mode`` 1 (springs on the circle
    through each compression centre) or 2 (springs on the contour); ``area``: the spring
    areas follow the radius (no fixed force area); the radius stencil of each load line
    (``rest`` is ``1 - weight``); the padded positions' nodes; the spring area per unit
    radius [m] and the largest penetration [m]. ``out``: ``(centre_gap, gap_ext,
    area_ext, load_gap, load_area, gap_min, upper)``, the arrays of :func:`revolution`'s
    ``nodes`` and ``lines`` it fills (as the NumPy expressions of
    :func:`jointwear.contact.kernel._arguments`; those a law keeps constant are not
    written). Plain arrays, not those tuples: a smaller signature compiles faster.
    """
    mode, area, below, above, weight, rest, padded, spring, reach = built
    centre_gap, gap_ext, area_ext, load_gap, load_area, gap_min, upper = out
    wall = 0.999 * rp
    smallest = np.inf
    for j in range(radius.size):
        smallest = min(smallest, radius[j])
    if not rp < smallest:
        return False
    bad = 0
    for k in range(load.size):
        force = load[k]
        bad += not (0.0 <= force < np.inf)
        centre = rest[k] * radius[below[k]] + weight[k] * radius[above[k]]
        gap = centre - rp
        centre_gap[k] = gap
        if mode == 1:
            load_gap[k] = gap
            gap_min[k] = gap
            if area:
                load_area[k] = centre
            bad += gap >= wall and force > 0.0
        else:
            gap_min[k] = smallest - rp
        upper[k] = max(min(gap + reach, wall), gap_min[k])
    if mode == 2:
        if smallest - rp >= wall:
            return False
        for i in range(padded.size):
            r = radius[padded[i]]
            gap_ext[i] = r - rp
            if area:
                area_ext[i] = r * spring
    return bad == 0
