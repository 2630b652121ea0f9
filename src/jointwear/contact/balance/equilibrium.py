"""Full 2-D equilibrium of the pin (``balance="equilibrium"``).

The springs' resultant *vector* equals the load vector: the pin moves along and across
the load line. Starts from the paper balance's offsets (:mod:`.residual`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from jointwear.contact.balance.window import Window
from jointwear.contact.laws import SpringLaw
from jointwear.errors import ConvergenceError
from jointwear.geometry.contour import pin_penetration
from jointwear.solvers import bracketed_newton

__all__ = ["solve_equilibrium"]

FloatArray = NDArray[np.float64]


_EPS = np.finfo(float).eps


def solve_equilibrium(
    win: Window,
    law: SpringLaw,
    radius_pin: float,
    load: FloatArray,
    along: FloatArray,
    tolerance: float,
    max_iterations: int,
    lower: FloatArray,
    upper: FloatArray,
) -> tuple[FloatArray, FloatArray, NDArray[np.int64]]:
    """Pin positions where the springs' resultant vector equals the load vector.

    2-D Newton with backtracking on the pin position in the load frame; where it stalls
    (a single spring in contact makes the Jacobian singular), bisection on the pin's
    direction (:func:`_equilibrium_by_direction`).

    Parameters
    ----------
    win : Window
        The loads' node windows.
    law : SpringLaw
        Spring law ``p(delta)`` [m -> Pa].
    radius_pin : float
        ``R_p`` [m].
    load : ndarray, shape (M,)
        Joint loads [N].
    along : ndarray, shape (M,)
        Start: the paper balance's offsets along the load lines [m]; overwritten.
    tolerance, max_iterations : float, int
        Absolute force tolerance [N]; Newton steps allowed per load.
    lower, upper : ndarray, shape (M,)
        Bracket of the paper balance's offsets [m] (for the fallback).

    Returns
    -------
    along, across, iterations
        Pin position along and across (counter-clockwise) each load line [m], residual
        evaluations per load.
    """
    across = np.zeros_like(along)
    iterations = np.zeros(load.size, dtype=np.int64)
    active = np.arange(load.size)
    failed = []
    for _ in range(max_iterations):
        if active.size == 0:
            break
        a, b = along[active], across[active]
        g_n, g_t, scale, springs = _resultants(win, law, radius_pin, load, a, b, active)
        iterations[active] += 1
        norm = np.hypot(g_n, g_t)
        done = norm <= np.maximum(tolerance, 8 * _EPS * scale)
        step_a, step_b, bad, stiffness = _newton_step(law, g_n, g_t, *springs)
        # a residual that one ulp of the pin position explains (stiff springs; a single
        # spring makes J singular), or a Newton step below that round-off: exact to round-off
        position = _EPS * np.hypot(a, b)
        done |= norm <= position * stiffness
        step = np.hypot(step_a, step_b)
        done |= ~bad & (step <= position)
        lam = _backtrack(win, law, radius_pin, load, active, (a, b), (step_a, step_b), norm,
                         ~done & ~bad)  # fmt: skip
        along[active] = np.where(done, a, a + lam * step_a)
        across[active] = np.where(done, b, b + lam * step_b)
        stalled = (bad | (lam < 1e-8)) & ~done
        # no descent along a step of a few ulps: round-off noise, the position is exact
        noise = stalled & ~bad & (step <= 16 * position)
        done |= noise
        stalled &= ~noise
        failed.append(active[stalled])
        active = active[~done & ~stalled]
    failed.append(active)
    rows = np.concatenate(failed)
    if rows.size:
        a, b, extra = _equilibrium_by_direction(
            win, law, radius_pin, load, rows, tolerance, max_iterations, lower, upper
        )
        along[rows], across[rows] = a, b
        iterations[rows] += extra
    return along, across, iterations


def _resultants(win, law, radius_pin, load, a, b, rows):
    """Residual of the load along and across the load line [N], ``sum_j |f_j|`` [N] and
    the springs' state, for the pin at ``a`` along and ``b`` across [m] (window rows)."""
    cos, sin, gap = win.cos[rows], win.sin[rows], win.gap[rows]
    area = win.area[rows] if isinstance(win.area, np.ndarray) else win.area
    a_col, b_col = a[:, None], b[:, None]
    cross = cos * b_col - sin * a_col
    root = np.sqrt(radius_pin**2 - cross**2)
    depth = pin_penetration(cos * a_col + sin * b_col, cross, gap, radius_pin)
    penetration = np.maximum(depth, 0.0)
    force = law.pressure(penetration) * area
    g_n = (force * cos).sum(axis=1) - load[rows]
    g_t = (force * sin).sum(axis=1)
    scale = np.abs(force).sum(axis=1)  # the round-off floor is 8 eps sum|f_j|
    return g_n, g_t, scale, (penetration, cos, sin, cross / root, area)


def _newton_step(law, g_n, g_t, penetration, cos, sin, ratio, area):
    """Newton's step in the pin position [m] (zero where the Jacobian is singular), where
    it is, and the sum of the Jacobian's entries' magnitudes [N/m]."""
    k = law.pressure_derivative(penetration) * area
    dt_da = cos + sin * ratio
    dt_db = sin - cos * ratio
    j11 = (k * cos * dt_da).sum(axis=1)
    j12 = (k * cos * dt_db).sum(axis=1)
    j21 = (k * sin * dt_da).sum(axis=1)
    j22 = (k * sin * dt_db).sum(axis=1)
    det = j11 * j22 - j12 * j21
    with np.errstate(divide="ignore", invalid="ignore"):
        step_a = -(j22 * g_n - j12 * g_t) / det
        step_b = -(-j21 * g_n + j11 * g_t) / det
    bad = ~np.isfinite(step_a) | ~np.isfinite(step_b)
    step_a[bad] = 0.0
    step_b[bad] = 0.0
    return step_a, step_b, bad, np.abs(j11) + np.abs(j12) + np.abs(j21) + np.abs(j22)


def _backtrack(win, law, radius_pin, load, active, position, step, norm, pending):
    """Fraction of each Newton step that reduces the residual norm (halved up to 30 times;
    1 where ``pending`` is False)."""
    a, b = position
    step_a, step_b = step
    lam = np.ones_like(a)
    for _ in range(30):
        if not pending.any():
            break
        rows = active[pending]
        with np.errstate(invalid="ignore", over="ignore"):  # a wild step may leave the pin
            gn2, gt2, _, _ = _resultants(
                win,
                law,
                radius_pin,
                load,
                a[pending] + lam[pending] * step_a[pending],
                b[pending] + lam[pending] * step_b[pending],
                rows,
            )
        better = np.hypot(gn2, gt2) < norm[pending]
        idx = np.flatnonzero(pending)
        pending[idx[better]] = False
        lam[idx[~better]] *= 0.5
    return lam


class _DirectionBalance:
    """The paper balance along the load for a pin turned by ``chi`` from it, on the
    window rows ``rows`` (the fallback of :func:`solve_equilibrium`)."""

    def __init__(self, win, law, radius_pin, load, rows, tolerance, max_iterations, lower, upper):
        self.law, self.radius_pin = law, radius_pin
        self.cos, self.sin, self.gap = win.cos[rows], win.sin[rows], win.gap[rows]
        self.area = win.area[rows] if isinstance(win.area, np.ndarray) else win.area
        self.target = load[rows]
        self.lower, self.upper = lower[rows], upper[rows]
        self.tolerance, self.max_iterations = tolerance, max_iterations
        #: residual evaluations per row
        self.iterations = np.zeros(rows.size, dtype=np.int64)

    def springs(self, s, chi, idx):
        """Spring forces [N] and their slopes in ``s`` [N/m] at distance ``s`` [m] in the
        direction ``chi`` [rad] from the load, with the nodes' ``cos`` and ``sin``."""
        rp = self.radius_pin
        c, si = np.cos(chi)[:, None], np.sin(chi)[:, None]
        cs, sn = self.cos[idx], self.sin[idx]
        s_col = s[:, None]
        mu = cs * c + sn * si  # cos(theta_j - chi)
        cross = s_col * (cs * si - sn * c)
        root = np.sqrt(rp**2 - cross**2)
        depth = pin_penetration(s_col * mu, cross, self.gap[idx], rp)
        penetration = np.maximum(depth, 0.0)
        a = self.area[idx] if isinstance(self.area, np.ndarray) else self.area
        force = self.law.pressure(penetration) * a
        slope = (
            self.law.pressure_derivative(penetration) * a * (mu - cross * cross / (s_col * root))
        )
        return force, slope, cs, sn

    def distance(self, chi, idx, guess):
        """Paper-mode balance along the load for pin direction ``chi`` (rows ``idx``): the
        distance [m], the sideways resultant [N], convergence and ``sum_j |f_j|`` [N]."""

        def residual(s, sub):
            force, slope, cs, _ = self.springs(s, chi[sub], idx[sub])
            normal = force * cs
            total = self.target[idx[sub]]
            return normal.sum(1) - total, (slope * cs).sum(1), np.abs(normal).sum(1)

        root = bracketed_newton(
            residual,
            guess,
            self.lower[idx],
            self.upper[idx],
            self.tolerance,
            max_iterations=self.max_iterations,
        )
        self.iterations[idx] += root.iterations
        force, _, _, sn = self.springs(root.x, chi, idx)
        scale = np.abs(force).sum(1)
        return root.x, (force * sn).sum(1), root.converged, scale


def _equilibrium_by_direction(
    win: Window,
    law: SpringLaw,
    radius_pin: float,
    load: FloatArray,
    rows: NDArray[np.intp],
    tolerance: float,
    max_iterations: int,
    lower: FloatArray,
    upper: FloatArray,
):
    """Robust 2-D equilibrium: bisection on the pin's direction, Newton on its distance.

    For a direction ``chi`` of the pin (relative to the load) the distance ``s`` is found
    as in paper mode, so that the resultant along the load equals the load; the sideways
    resultant ``T(chi)`` then grows with ``chi`` (turning the pin towards a side loads
    that side) and its root is bracketed within +-60 degrees and bisected. Slower than
    Newton, but it cannot stall where a single spring touches.
    """
    balance = _DirectionBalance(
        win, law, radius_pin, load, rows, tolerance, max_iterations, lower, upper
    )
    target = balance.target
    m = rows.size
    everything = np.arange(m)
    half = np.full(m, np.pi / 3)
    s_lo, t_lo, _, _ = balance.distance(-half, everything, upper[rows].copy())
    s_hi, t_hi, _, _ = balance.distance(half, everything, upper[rows].copy())
    if np.any(t_lo > 0) or np.any(t_hi < 0):
        i = int(np.flatnonzero((t_lo > 0) | (t_hi < 0))[0])
        raise ConvergenceError(
            f"contact: 2-D equilibrium not found for load {target[i]:.6g} N "
            f"(no pin direction within 60 deg of the load balances it)"
        )
    chi_lo, chi_hi = -half, half.copy()
    chi = np.zeros(m)
    s = 0.5 * (s_lo + s_hi)
    ok = np.zeros(m, dtype=bool)
    active = everything
    for _ in range(200):
        if active.size == 0:
            break
        mid = 0.5 * (chi_lo[active] + chi_hi[active])
        s_mid, t_mid, balanced, scale = balance.distance(mid, active, s[active])
        chi[active], s[active], ok[active] = mid, s_mid, balanced
        done = balanced & (np.abs(t_mid) <= np.maximum(tolerance, 8 * _EPS * scale))
        # T is continuous in chi: a collapsed bracket holds its root to round-off
        done |= (chi_hi[active] - chi_lo[active]) <= 4 * _EPS * np.maximum(np.abs(mid), 1.0)
        chi_lo[active] = np.where(t_mid < 0, mid, chi_lo[active])
        chi_hi[active] = np.where(t_mid < 0, chi_hi[active], mid)
        active = active[~done]
    if active.size:
        raise ConvergenceError(
            f"contact: 2-D equilibrium did not converge for {active.size} load(s)"
        )
    if not ok.all():  # the sideways force jumps where the load cannot be carried at all
        i = int(np.flatnonzero(~ok)[0])
        raise ConvergenceError(
            f"contact: 2-D equilibrium not found for load {target[i]:.6g} N: the pin would "
            f"have to travel further than the wall or its own radius allows"
        )
    return s * np.cos(chi), s * np.sin(chi), balance.iterations
