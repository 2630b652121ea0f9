"""The axial balance of a revolution's loads, compiled by numba (a rigid pin).

The physics of :func:`jointwear.contact.axial.solve_axial` for a rigid pin on slices
with a power law ``p = c delta^n``: the pin centre in slice ``i`` is ``s_i = delta_0 +
gamma z_i`` along the load and ``t_i = gamma_perp z_i`` across it; node ``j`` of slice
``i`` penetrates by the ray geometry of :func:`jointwear.geometry.contour.pin_penetration`;
``sum_i F_i = W`` and, with a free tilt, ``sum_i F_i z_i = W a``. Each load is solved by
Newton's method from a warm start (the same step's balance of the last solve), with the
Jacobian of the slices' linearised stiffness ``k_i = dF_i / ds_i``; the tolerances are
the axial balance's (the force's ``max(tolerance, 8 eps sum|f|)`` or the few ulps of the
offsets that explain a residual; the moment's the same at the half-length). A load that
does not converge here is flagged (``status``) and balanced by ``solve_axial``.

What differs from ``solve_axial`` is the arithmetic: the slices share the load's
direction, so ``cos`` and ``sin`` of every node's angle from the load are computed once
per load; only a window of nodes is visited, those that the pin, a little further in
than its warm start, could touch on any slice (the smallest gap of every node over the
slices against the deepest slice's offset; the window is widened and the load solved
again where the balance goes beyond it; the scan of each side starts from the angle the
smallest gap of all bounds); arrays are repeated three times so that a window never wraps;
a Newton step within ``(eps / 64)^(1/3) R_p`` of the last full evaluation moves every
slice's depths by their second-order Taylor polynomial, without the geometry (the planar
kernel's reuse: a warm load costs one full evaluation of the slices and one move); and
the pressure of the balanced load is kept from its last evaluation, to be added to the
wear (``K_d p ds``) or written out.

The memory is laid out as the planar kernel's (:mod:`jointwear.contact._compiled`): the
slices' rows are flat arrays read at unsigned offsets (a loop over a row of a 2-D array,
or with an index that could be negative, is not vectorised), the scratch comes from the
caller (:func:`scratch`), and :func:`revolution` is compiled without reference counting
and with its arrays declared ``noalias`` (``Unaliased``): a fifth less time a revolution
of 20 slices than 2-D rows with reference counting, the same numbers to the last digit
or two.

Imported by :mod:`jointwear.contact.sliced` on first use only (loading numba costs a few
tenths of a second).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, uint64

from jointwear.contact._compiled import Unaliased

#: ``status`` of a load
CONVERGED, NOT_CONVERGED = 0, 1
_EPS = 2.220446049250313e-16
#: up to this ``(y / R_p)^2`` the pin's curvature is taken from its series (:func:`_curvature`)
_SERIES = 1e-4
#: the window holds the nodes the pin could touch this much further in than its start [-]
_REACH = 1e-2
#: steps from the last full evaluation up to ``_REUSE R_p`` in all move the depths by
#: their second-order Taylor polynomial to within ``eps s / 16`` (:func:`_moved`)
_REUSE = (_EPS / 64.0) ** (1.0 / 3.0)
#: spring laws ``p = c delta``, ``p = c delta^1.5``, ``p = c delta^n``
_LINEAR, _HERTZIAN, _POWER = 1, 2, 3
#: doubles per vector register (AVX2): a window is widened to a multiple of it (the nodes
#: added cannot touch), so the loops over it have no scalar remainder (a few per cent)
_LANES = 4
_FLAGS = {"cache": True, "error_model": "numpy", "fastmath": {"reassoc", "contract"}}


@njit(inline="always", **_FLAGS)
def _window(centre, tilt, tilt_across, z, extent, gap_min, cos_e, sin_e, cpsi, spsi, nodes,
            reach, smallest):  # fmt: skip
    """First node and width of the window of a load (indices into the padded arrays).

    A node at ``phi`` from the load can touch only if ``d cos(phi) + e |sin(phi)| >
    g_min`` (``d`` the deepest slice's offset, ``e`` the largest lateral offset);
    ``d cos(phi) + e |sin(phi)| = r cos(|phi| - alpha)`` with ``r = hypot(d, e)``,
    ``alpha = atan2(e, d)``, and ``g_min >= smallest`` (the smallest gap of all [m]),
    so none lies beyond ``|phi| = alpha + arccos(smallest / r)``: each side is scanned
    in from there (two nodes further for round-off) to its outermost node that can
    touch, the same node a scan of the whole half circle finds.
    """
    deepest = -1e300
    for i in range(z.size):
        deepest = max(deepest, centre + tilt * z[i])
    deepest = abs(deepest) * (1.0 + reach) + reach * abs(tilt_across) * extent
    side = abs(tilt_across) * extent
    centre_node = math.floor(math.atan2(spsi, cpsi) / (2 * math.pi) * nodes + 0.5) % nodes
    low, high = centre_node + nodes, centre_node + nodes
    radius = math.hypot(deepest, side)
    counter, clockwise = (nodes - 1) // 2, nodes // 2
    if smallest > 0.0:
        if radius <= smallest:
            return low, 1, deepest
        bound = math.atan2(side, deepest) + math.acos(smallest / radius)
        steps = math.floor(bound / (2 * math.pi) * nodes + 0.5) + 2
        counter, clockwise = min(counter, steps), min(clockwise, steps)
    # counter-clockwise, then clockwise: the outermost node that can touch (a window of
    # at most a turn, which a lateral tilt may need beyond the quarter circles)
    for step in range(counter, 0, -1):
        j = centre_node + nodes + step
        c = cos_e[j] * cpsi + sin_e[j] * spsi
        sn = sin_e[j] * cpsi - cos_e[j] * spsi
        if deepest * c + side * abs(sn) > gap_min[j]:
            high = j
            break
    for step in range(clockwise, 0, -1):
        j = centre_node + nodes - step
        c = cos_e[j] * cpsi + sin_e[j] * spsi
        sn = sin_e[j] * cpsi - cos_e[j] * spsi
        if deepest * c + side * abs(sn) > gap_min[j]:
            low = j
            break
    return low, high - low + 1, deepest


@njit(inline="always", **_FLAGS)
def _curvature(across, rp, series):
    """The pin's curvature term of a node's penetration ``g = y^2 / (sqrt(R^2 - y^2) +
    R)`` [m], ``g' = y / sqrt(R^2 - y^2)`` [-] and ``g'' = R^2 / (R^2 - y^2)^1.5``
    [1/m] for the pin ``y`` [m] across the node's ray
    (:func:`jointwear.geometry.contour.pin_penetration`); with ``series`` (``y^2 <= 1e-4
    R^2`` on the whole slice) from their series to ``u^2``, ``u = y^2 / R^2``, within
    ``u^3`` of each (no square root, no division)."""
    if series:
        lateral = across * across
        inverse = 1.0 / rp
        u = lateral * (inverse * inverse)
        return (
            lateral * (0.5 * inverse) * (1.0 + u * (0.25 + 0.125 * u)),
            (across * inverse) * (1.0 + u * (0.5 + 0.375 * u)),
            inverse * (1.0 + u * (1.5 + 1.875 * u)),
        )
    lateral = min(across * across, rp * rp * (1.0 - _EPS))
    root = math.sqrt(rp * rp - lateral)
    return lateral / (root + rp), across / root, rp * rp / (root * root * root)


@njit(inline="always", **_FLAGS)
def _spring(depth, exponent, law):
    """Pressure and its derivative in the depth of ``p = c delta^n`` without their
    factors common to every node, ``c`` and ``c n`` (applied to the sums: two
    multiplications a node fewer): ``delta^n`` [m^n] and ``delta^(n-1)`` [m^(n-1)]."""
    positive = max(depth, 0.0)
    if law == _LINEAR:
        return positive, 1.0 if depth > 0.0 else 0.0
    if law == _HERTZIAN:
        half = math.sqrt(positive)
        return positive * half, half
    stiffness = 0.0
    if depth > 0.0:
        stiffness = positive ** (exponent - 1.0)
    return positive**exponent, stiffness


@njit(inline="always", **_FLAGS)
def _full(row, first, s, t, c, sn, gap, area, width, rp, exponent, law, series,
          kept, depth, rate, bend):  # fmt: skip
    """One slice at offsets ``s``, ``t`` [m]: resultant along the load, ``dF/ds`` and
    ``sum |f|``, each without the law's factor (``c``, ``c n`` and ``c``: [N], [N/m],
    [N] once multiplied, :func:`_spring`); each node's pressure over ``c`` into
    ``kept``, its depth [m] and the depth's first and second derivative in ``s`` [-,
    1/m] into ``depth``, ``rate``, ``bend`` (for :func:`_moved`). The slice's window
    starts at ``row`` in the scratch and at ``first`` in ``gap`` and ``area`` (flat,
    unsigned offsets: a loop over rows of a 2-D array, or with a signed index, is not
    vectorised). Called with ``law`` and ``series`` as literals: a loop without
    branches is vectorised."""
    force, slope, magnitude = 0.0, 0.0, 0.0
    for jj in range(uint64(width)):
        across = t * c[jj] - s * sn[jj]
        curvature, extra, second = _curvature(across, rp, series)
        d = s * c[jj] + t * sn[jj] - gap[first + jj] - curvature
        r = c[jj] + sn[jj] * extra
        depth[row + jj] = d
        rate[row + jj] = r
        bend[row + jj] = -sn[jj] * sn[jj] * second
        p, stiffness = _spring(d, exponent, law)
        kept[row + jj] = p
        f = p * area[first + jj]
        force += f * c[jj]
        magnitude += f
        slope += stiffness * area[first + jj] * c[jj] * r
    return force, slope, magnitude


@njit(inline="always", **_FLAGS)
def _moved(row, first, step, c, area, width, exponent, law, kept, depth, rate,
           bend):  # fmt: skip
    """:func:`_full` after a small step ``step`` [m] of the slice from its last full
    evaluation or move: the depth moved by its Taylor polynomial, ``delta += step
    delta' + step^2 delta'' / 2``, ``delta' += step delta''`` (the neglected terms are
    below ``eps s / 16`` within ``_REUSE R_p``, as in the planar kernel), without the
    geometry or the pin's curvature."""
    force, slope, magnitude = 0.0, 0.0, 0.0
    half = 0.5 * step
    for jj in range(uint64(width)):
        d = depth[row + jj] + step * (rate[row + jj] + half * bend[row + jj])
        r = rate[row + jj] + step * bend[row + jj]
        depth[row + jj] = d
        rate[row + jj] = r
        p, stiffness = _spring(d, exponent, law)
        kept[row + jj] = p
        f = p * area[first + jj]
        force += f * c[jj]
        magnitude += f
        slope += stiffness * area[first + jj] * c[jj] * r
    return force, slope, magnitude


@njit(inline="always", **_FLAGS)
def _slice(row, first, s, t, c, sn, gap, area, width, rp, law, kept, depth, rate, bend):
    """:func:`_full` with the law ``law`` (``R_p``, ``c``, ``n``) and the series chosen."""
    exponent = law[2]
    if (abs(s) + abs(t)) ** 2 <= _SERIES * rp * rp:
        if exponent == 1.0:
            return _full(row, first, s, t, c, sn, gap, area, width, rp, exponent,
                         _LINEAR, True, kept, depth, rate, bend)  # fmt: skip
        if exponent == 1.5:
            return _full(row, first, s, t, c, sn, gap, area, width, rp, exponent,
                         _HERTZIAN, True, kept, depth, rate, bend)  # fmt: skip
        return _full(row, first, s, t, c, sn, gap, area, width, rp, exponent,
                     _POWER, True, kept, depth, rate, bend)  # fmt: skip
    if exponent == 1.0:
        return _full(row, first, s, t, c, sn, gap, area, width, rp, exponent,
                     _LINEAR, False, kept, depth, rate, bend)  # fmt: skip
    if exponent == 1.5:
        return _full(row, first, s, t, c, sn, gap, area, width, rp, exponent,
                     _HERTZIAN, False, kept, depth, rate, bend)  # fmt: skip
    return _full(row, first, s, t, c, sn, gap, area, width, rp, exponent,
                 _POWER, False, kept, depth, rate, bend)  # fmt: skip


@njit(inline="always", **_FLAGS)
def _slice_moved(row, first, step, c, area, width, law, kept, depth, rate, bend):
    """:func:`_moved` with the law ``law`` (``R_p``, ``c``, ``n``)."""
    exponent = law[2]
    if exponent == 1.0:
        return _moved(row, first, step, c, area, width, exponent, _LINEAR, kept,
                      depth, rate, bend)  # fmt: skip
    if exponent == 1.5:
        return _moved(row, first, step, c, area, width, exponent, _HERTZIAN, kept,
                      depth, rate, bend)  # fmt: skip
    return _moved(row, first, step, c, area, width, exponent, _POWER, kept, depth,
                  rate, bend)  # fmt: skip


def scratch(count: int, nodes: int) -> tuple[np.ndarray, ...]:
    """The scratch of :func:`revolution` for ``count`` slices of ``nodes`` nodes: ``cos``
    and ``sin`` of the window's angles from the load (``nodes``), each slice's pressure,
    depth and its two derivatives in the window (``count * nodes``, slice ``i`` from ``i
    * nodes``), every slice's gaps (``count * 3 nodes``) and each node's smallest
    (``3 nodes``), :func:`_gaps`: one flat array each, as a loop over a row of a 2-D
    array is not vectorised."""
    windows = (np.empty(count * nodes) for _ in range(4))
    return (np.empty(nodes), np.empty(nodes), *windows, np.empty(3 * count * nodes),
            np.empty(3 * nodes))  # fmt: skip


@njit(inline="always", **_FLAGS)
def _gaps(radius, rp, gap, gap_min):
    """Every slice's gaps ``r - R_p`` [m] of its radii ``radius`` (N, nodes) [m] into
    ``gap``, three turns a slice (slice ``i`` from ``3 i nodes``), and each node's smallest
    over the slices into ``gap_min``, three turns."""
    count, nodes = radius.shape
    for j in range(nodes):
        gap_min[j] = math.inf
    for i in range(count):
        row = i * 3 * nodes
        for j in range(nodes):
            g = radius[i, j] - rp
            gap[row + j] = g
            gap[row + nodes + j] = g
            gap[row + 2 * nodes + j] = g
            gap_min[j] = min(gap_min[j], g)
    for j in range(nodes):
        gap_min[nodes + j] = gap_min[j]
        gap_min[2 * nodes + j] = gap_min[j]


@njit(_nrt=False, pipeline_class=Unaliased, **_FLAGS)
def revolution(load, azimuth, tilt_along, tilt_across, free, load_offset, z, radius, area,
               cos_e, sin_e, law, tolerance, max_iterations, state, status,
               evaluations, sliding, wear_coefficient, wear, pressure, cold, work):  # fmt: skip
    """Balance every load of a revolution and settle it.

    ``state[k] = (delta_0, gamma)`` holds the warm start on entry and the balance on
    return [m, rad]; ``radius`` [m] holds the slices' radii (N, nodes), ``area`` [m^2]
    their spring areas flat, slice ``i``'s three turns of nodes from ``3 i nodes``, and
    ``cos_e``, ``sin_e`` (3 nodes,) three turns likewise. Where ``wear_coefficient > 0``
    Archard's ``K_d p ds`` of every balanced load is added to ``wear`` (N, nodes), else
    its pressure is written to ``pressure`` (N, M, nodes). ``cold``: no warm start; each
    load starts from the last one's approach (the first from a touch), doubled until the
    slices carry the load, then Newton's method from that side (the resultant grows and
    is convex in the offset). ``work``: the scratch (:func:`scratch`), the gaps written
    into it first (:func:`_gaps`).

    Compiled without reference counting and with its arrays declared ``noalias``
    (:class:`jointwear.contact._compiled.Unaliased`): every array passed is a buffer of
    its own, and nothing is allocated here.
    """
    rp = law[0]
    count, nodes = z.size, cos_e.size // 3
    turns = uint64(3 * nodes)
    half = 0.5 * (z[-1] - z[0]) * count / max(count - 1, 1)
    extent = 0.0
    for i in range(count):
        extent = max(extent, abs(z[i]))
    c, sn, kept, depth, rate, bend, gap, gap_min = work
    _gaps(radius, rp, gap, gap_min)
    smallest = math.inf
    for j in range(nodes):
        smallest = min(smallest, gap_min[j])
    scale, rise = law[1], law[1] * law[2]  # (the laws' factors common to every node)
    for i in range(count):
        for j in range(nodes):
            wear[i, j] = 0.0
    approach = 1e-9 * rp
    for k in range(load.size):
        cpsi, spsi = math.cos(azimuth[k]), math.sin(azimuth[k])
        base = gap_min[math.floor(math.atan2(spsi, cpsi) / (2 * math.pi) * nodes + 0.5) % nodes]
        if cold:
            state[k, 0] = base + approach
            state[k, 1] = state[k - 1, 1] if k > 0 and free else 0.0
        pushing = cold
        centre = state[k, 0]
        tilt = state[k, 1] if free else tilt_along[k]
        across_tilt = tilt_across[k]
        status[k] = NOT_CONVERGED
        reach = _REACH
        start, width, covered = _window(centre, tilt, across_tilt, z, extent, gap_min, cos_e,
                                        sin_e, cpsi, spsi, nodes, reach, smallest)  # fmt: skip
        width = min(width + (-width) % _LANES, nodes)
        for jj in range(width):
            c[jj] = cos_e[start + jj] * cpsi + sin_e[start + jj] * spsi
            sn[jj] = sin_e[start + jj] * cpsi - cos_e[start + jj] * spsi
        used = 0
        travel = math.inf  # how far the slices moved since the last full evaluation [m]
        small = 0.0
        last_centre, last_tilt = centre, tilt
        while used < max_iterations:
            used += 1
            force_sum, moment_sum, k0, k1, k2, total, k_abs, kz_abs = (0.0,) * 8
            move = abs(centre - last_centre) + abs(tilt - last_tilt) * extent
            reuse = travel + move <= small
            if reuse:
                travel += move
                deepest = -1e300
                for i in range(count):
                    deepest = max(deepest, centre + tilt * z[i])
                reuse = deepest <= covered
            if not reuse:
                travel = 0.0
                small = _REUSE * rp
            for i in range(count):
                row, first = uint64(i) * uint64(nodes), uint64(i) * turns + uint64(start)
                s, t = centre + tilt * z[i], across_tilt * z[i]
                if reuse:
                    step = (centre - last_centre) + (tilt - last_tilt) * z[i]
                    sums = _slice_moved(row, first, step, c, area, width, law, kept, depth,
                                        rate, bend)  # fmt: skip
                else:
                    if abs(s) + abs(t) > 0.5 * rp:
                        small = 0.0  # (the curvature's third derivative bounded up to R_p / 2)
                    sums = _slice(row, first, s, t, c, sn, gap, area, width, rp, law, kept,
                                  depth, rate, bend)  # fmt: skip
                force, slope, magnitude = sums
                force, slope, magnitude = scale * force, rise * slope, scale * magnitude
                force_sum += force
                moment_sum += force * z[i]
                k0 += slope
                k1 += slope * z[i]
                k2 += slope * z[i] * z[i]
                total += magnitude
                k_abs += abs(slope)
                kz_abs += abs(slope * z[i])
            last_centre, last_tilt = centre, tilt
            size = max(abs(centre), abs(tilt) * extent)
            floor = max(tolerance, 8.0 * _EPS * total)
            residual = force_sum - load[k]
            moment = moment_sum - load[k] * load_offset
            force_ok = abs(residual) <= floor + 4.0 * _EPS * k_abs * size
            moment_ok = abs(moment) <= floor * half + 4.0 * _EPS * kz_abs * size
            if residual < 0.0 and (pushing or not k0 > 0.0):
                # short of the load (or out of contact): twice as far in
                centre = base + 2.0 * max(centre - base, 1e-9 * rp)
                continue
            pushing = False
            if force_ok and (not free or moment_ok):
                deepest = -1e300
                for i in range(count):
                    deepest = max(deepest, centre + tilt * z[i])
                if deepest <= covered:
                    status[k] = CONVERGED
                    break
                # beyond the window: widen it about the balance found and go on
                reach *= 4.0
                start, width, covered = _window(centre, tilt, across_tilt, z, extent, gap_min,
                                                cos_e, sin_e, cpsi, spsi, nodes, reach,
                                                smallest)  # fmt: skip
                width = min(width + (-width) % _LANES, nodes)
                for jj in range(width):
                    c[jj] = cos_e[start + jj] * cpsi + sin_e[start + jj] * spsi
                    sn[jj] = sin_e[start + jj] * cpsi - cos_e[start + jj] * spsi
                travel = math.inf
                continue
            if free:
                det = k0 * k2 - k1 * k1
                if not det > 0.0:
                    break
                centre -= (k2 * residual - k1 * moment) / det
                tilt -= (k0 * moment - k1 * residual) / det
            else:
                if not k0 > 0.0:
                    break
                centre -= residual / k0
            if not (math.isfinite(centre) and math.isfinite(tilt)):
                break
        evaluations[k] = used
        state[k, 0], state[k, 1] = centre, tilt
        approach = max(centre - base, 1e-9 * rp)
        if status[k] != CONVERGED:
            continue
        if wear_coefficient > 0.0:
            _settle(wear_coefficient * sliding[k] * scale, kept, wear, start, width, nodes)
        else:
            for i in range(count):
                for jj in range(width):
                    pressure[i, k, (start + jj) % nodes] = scale * kept[i * nodes + jj]


@njit(inline="always", **_FLAGS)
def _settle(factor, kept, wear, start, width, nodes):
    """Add ``factor`` times every slice's pressure in the window from padded position
    ``start`` to the nodes' wear (``wear``, (N, nodes)): the window's part in each of
    the three turns, without a modulo per node."""
    count = wear.shape[0]
    for turn in range(3):
        low = max(start, turn * nodes)
        high = min(start + width, (turn + 1) * nodes)
        if high <= low:
            continue
        shift = uint64(low - start)
        first = uint64(low - turn * nodes)
        for i in range(count):
            row = uint64(i) * uint64(nodes)
            line = wear[i]
            for jj in range(uint64(high - low)):
                line[first + jj] += factor * kept[row + shift + jj]
