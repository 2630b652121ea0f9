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

Imported by :mod:`jointwear.contact.sliced` on first use only (loading numba costs a few
tenths of a second).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: ``status`` of a load
CONVERGED, NOT_CONVERGED = 0, 1
_EPS = 2.220446049250313e-16
_FLAGS = {"cache": True, "error_model": "numpy"}


@njit(inline="always", **_FLAGS)
def _pressure(depth, coefficient, exponent):
    if exponent == 1.0:
        return coefficient * depth
    if exponent == 1.5:
        return coefficient * depth * math.sqrt(depth)
    return coefficient * depth**exponent


@njit(inline="always", **_FLAGS)
def _derivative(depth, coefficient, exponent):
    if exponent == 1.0:
        return coefficient
    if exponent == 1.5:
        return 1.5 * coefficient * math.sqrt(depth)
    return coefficient * exponent * depth ** (exponent - 1.0)


@njit(inline="always", **_FLAGS)
def _depth(s, t, c, sn, gap, rp):
    """Penetration of a node [m] and the pin across its ray [m] (``pin_penetration``)."""
    across = t * c - s * sn
    lateral = min(across * across, rp * rp)
    return s * c + t * sn - gap - lateral / (math.sqrt(rp * rp - lateral) + rp), across


@njit(**_FLAGS)
def _evaluate(centre, tilt, tilt_across, z, gap, area, cos_t, sin_t, cpsi, spsi, law, sums):
    """``sums`` = (sum F, sum F z, sum k, sum k z, sum k z^2, sum |f|, sum |k|, sum |k z|)."""
    rp, coefficient, exponent = law[0], law[1], law[2]
    sums[:] = 0.0
    for i in range(z.size):
        s, t = centre + tilt * z[i], tilt_across * z[i]
        force, slope, total = 0.0, 0.0, 0.0
        for j in range(cos_t.size):
            c = cos_t[j] * cpsi + sin_t[j] * spsi
            sn = sin_t[j] * cpsi - cos_t[j] * spsi
            if s * c + t * sn <= gap[i, j]:  # (the pin's curvature only deepens the gap)
                continue
            depth, across = _depth(s, t, c, sn, gap[i, j], rp)
            if depth <= 0.0:
                continue
            f = _pressure(depth, coefficient, exponent) * area[i, j]
            lateral = min(across * across, rp * rp * (1.0 - _EPS))
            ray = c + sn * across / math.sqrt(rp * rp - lateral)
            force += f * c
            total += abs(f)
            slope += _derivative(depth, coefficient, exponent) * area[i, j] * c * ray
        sums[0] += force
        sums[1] += force * z[i]
        sums[2] += slope
        sums[3] += slope * z[i]
        sums[4] += slope * z[i] * z[i]
        sums[5] += total
        sums[6] += abs(slope)
        sums[7] += abs(slope * z[i])


@njit(**_FLAGS)
def balance(load, azimuth, tilt_along, tilt_across, free, load_offset, z, gap, area, cos_t,
            sin_t, law, tolerance, max_iterations, state, status, evaluations):  # fmt: skip
    """Balance every load of a revolution; ``state[k] = (delta_0, gamma)`` holds the warm
    start on entry and the balance on return [m, rad]."""
    sums = np.zeros(8)
    half = 0.5 * (z[-1] - z[0]) * z.size / max(z.size - 1, 1)
    extent = np.abs(z).max()
    for k in range(load.size):
        cpsi, spsi = math.cos(azimuth[k]), math.sin(azimuth[k])
        centre = state[k, 0]
        tilt = state[k, 1] if free else tilt_along[k]
        status[k] = NOT_CONVERGED
        for iteration in range(max_iterations):
            _evaluate(centre, tilt, tilt_across[k], z, gap, area, cos_t, sin_t, cpsi, spsi,
                      law, sums)  # fmt: skip
            evaluations[k] = iteration + 1
            size = max(abs(centre), abs(tilt) * extent)
            floor = max(tolerance, 8.0 * _EPS * sums[5])
            residual = sums[0] - load[k]
            moment = sums[1] - load[k] * load_offset
            force_ok = abs(residual) <= floor + 4.0 * _EPS * sums[6] * size
            moment_ok = abs(moment) <= floor * half + 4.0 * _EPS * sums[7] * size
            if force_ok and (not free or moment_ok):
                status[k] = CONVERGED
                break
            if free:
                det = sums[2] * sums[4] - sums[3] * sums[3]
                if not det > 0.0:
                    break
                centre -= (sums[4] * residual - sums[3] * moment) / det
                tilt -= (sums[2] * moment - sums[3] * residual) / det
            else:
                if not sums[2] > 0.0:
                    break
                centre -= residual / sums[2]
            if not (math.isfinite(centre) and math.isfinite(tilt)):
                break
        state[k, 0], state[k, 1] = centre, tilt


@njit(**_FLAGS)
def settle(load, azimuth, tilt_along, tilt_across, z, gap, area, cos_t, sin_t, law, state,
           sliding, wear_coefficient, wear, pressure):  # fmt: skip
    """From balanced ``state``: Archard's wear ``K_d p ds`` added to ``wear`` (N, nodes)
    where ``wear_coefficient > 0``, else every pressure into ``pressure`` (N, M, nodes)."""
    rp, coefficient, exponent = law[0], law[1], law[2]
    for k in range(load.size):
        cpsi, spsi = math.cos(azimuth[k]), math.sin(azimuth[k])
        factor = wear_coefficient * sliding[k]
        for i in range(z.size):
            s, t = state[k, 0] + state[k, 1] * z[i], tilt_across[k] * z[i]
            for j in range(cos_t.size):
                c = cos_t[j] * cpsi + sin_t[j] * spsi
                sn = sin_t[j] * cpsi - cos_t[j] * spsi
                if s * c + t * sn <= gap[i, j]:
                    continue
                depth, _ = _depth(s, t, c, sn, gap[i, j], rp)
                if depth <= 0.0:
                    continue
                p = _pressure(depth, coefficient, exponent)
                if wear_coefficient > 0.0:
                    wear[i, j] += factor * p
                else:
                    pressure[i, k, j] = p
