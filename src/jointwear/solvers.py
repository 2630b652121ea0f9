"""Batched root finding.

``scipy.optimize.newton`` accepts arrays but has no bracket, so a step can leave
the region where the contact force is defined (or where it is flat: zero force
before contact, zero derivative) and the batch fails. The load balance needs a
*bracketed* Newton over thousands of independent scalar problems at once, which
scipy does not offer; :func:`bracketed_newton` is that solver: a Newton step
where it stays inside the current bracket, bisection otherwise, the bracket
shrunk by the sign of every residual. It is tested against ``scipy.optimize.brentq``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["RootResult", "bracketed_newton"]

FloatArray = NDArray[np.float64]

#: ``func(x, index) -> (residual, derivative, scale[, second[, third derivative]])`` for
#: the problems ``index``. ``scale`` is the size of the terms summed into the residual;
#: it sets the round-off floor of the tolerance.
Residual = Callable[[FloatArray, NDArray[np.intp]], tuple[FloatArray, ...]]


@dataclass(frozen=True)
class RootResult:
    """Result of :func:`bracketed_newton`.

    Attributes
    ----------
    x : ndarray
        Roots (same unit as the unknown).
    residual : ndarray
        Residual at ``x`` (same unit as the residual).
    iterations : ndarray of int
        Function evaluations used by each problem.
    converged : ndarray of bool
        ``|residual| <= tolerance`` reached, or the root located to round-off:
        the bracket collapsed to a few ulps of ``x`` with
        ``|residual| <= 2 |f'(x)| * bracket width`` (a stiff equation where one
        ulp of ``x`` moves ``f`` by more than the tolerance), or a residual that a few
        ulps of ``x`` explain (see ``ulps`` of :func:`bracketed_newton`).
    """

    x: FloatArray
    residual: FloatArray
    iterations: NDArray[np.int64]
    converged: NDArray[np.bool_]


def bracketed_newton(
    func: Residual,
    x0: FloatArray,
    lower: FloatArray,
    upper: FloatArray,
    atol: float,
    rtol: float = 8 * np.finfo(float).eps,
    max_iterations: int = 100,
    curvature: float = 0.0,
    polish: bool = False,
    ulps: float = 4.0,
) -> RootResult:
    """Solve many increasing scalar equations ``f_i(x_i) = 0`` at once.

    Each ``f_i`` must be non-decreasing with ``f_i(lower_i) <= 0 <= f_i(upper_i)``.
    Problems leave the batch as they converge, so late iterations cost little.

    Parameters
    ----------
    func : callable
        ``func(x, index)`` returns ``(f, df/dx, scale)`` for problems ``index``,
        optionally followed by ``d2f/dx2`` and ``d3f/dx3``. A NaN derivative means "not
        computed": the last first derivative ``func`` gave for that problem is reused (a
        chord step); with none yet, the step is a bisection. A second derivative makes
        the step Chebyshev's, ``h = -f/f' (1 + f f'' / (2 f'^2))`` (third order); where it
        is NaN (or not returned) ``curvature`` stands in for it. A third derivative adds
        one Newton step on the cubic Taylor polynomial ``f + f' h + f'' h^2 / 2 + f''' h^3
        / 6`` from there (fourth order; not where it is NaN, nor where it would change
        the step by half of itself or more).
    x0 : ndarray
        Initial guesses (clipped into the bracket).
    lower, upper : ndarray
        Bracket.
    atol : float
        Absolute tolerance on the residual (unit of ``f``).
    rtol : float
        Relative round-off floor: the tolerance is ``max(atol, rtol * scale)``.
    max_iterations : int
        Evaluations allowed per problem.
    curvature : float
        ``kappa`` of a second-order (Chebyshev) correction of the Newton step for
        residuals ``f = g - c`` with ``g ~ scale ~ C u^m`` locally (``kappa = (m - 1) / m``,
        ``f'' / f' = kappa f' / g``): the step ``-f/f'`` becomes
        ``-f/f' (1 + kappa f / (2 scale))``, which removes most of Newton's quadratic
        error term. 0: plain Newton. Only the step changes, never the convergence test.
    polish : bool
        Let a problem that converges take the step its last evaluation gives, too (where
        that step stays inside the bracket). ``x`` is then not the point whose residual
        is reported, but usually far closer to the root: for starting points from a loose
        tolerance, not for roots.

    ulps : float
        Round-off of the unknown [ulp]: a residual that ``ulps`` units in the last place
        of ``x`` explain (``|f| <= ulps eps |x| |f'|``) is accepted where Newton's step
        is below one ulp, or when it is so for the second evaluation in a row. Where
        one ulp of ``x`` moves ``f`` by more than the tolerance, nothing is left to
        bisect (which would otherwise go on until the bracket collapses).

    Returns
    -------
    RootResult
    """
    lo = np.array(lower, dtype=float, copy=True)
    hi = np.array(upper, dtype=float, copy=True)
    x = np.clip(np.asarray(x0, dtype=float), lo, hi)
    size = x.size
    residual = np.full(size, np.nan)
    slope = np.full(size, np.nan)  # last derivative func computed, per problem
    iterations = np.zeros(size, dtype=np.int64)
    converged = np.zeros(size, dtype=bool)
    explained_before = np.zeros(size, dtype=bool)
    active = np.arange(size)
    eps = float(np.finfo(float).eps)
    half_curvature = 0.5 * curvature
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for _ in range(max_iterations):
            if active.size == 0:
                break
            # while every problem is active (the costly first iterations) no gathers
            whole = active.size == size
            xa = x.copy() if whole else x[active]
            f, df, scale, *second = func(xa, active)
            if whole:
                iterations += 1
                residual[:] = f
                lo_old, hi_old, slope_old = lo, hi, slope
            else:
                iterations[active] += 1
                residual[active] = f
                lo_old, hi_old, slope_old = lo[active], hi[active], slope[active]
            df = np.where(np.isnan(df), slope_old, df)
            size_f = np.abs(f)
            done = size_f <= np.maximum(rtol * scale, atol)
            # round-off: a residual that ``ulps`` units in the last place of x explain is
            # accepted where Newton's step is below one ulp (it would round to x, and a
            # step the bracket rejects would bisect it), or for the second time in a row
            ulp_x = eps * np.abs(xa)
            explained = ~done & (size_f <= ulps * ulp_x * np.abs(df))
            if explained.any():
                before = explained_before if whole else explained_before[active]
                done = done | (explained & ((size_f <= ulp_x * np.abs(df)) | before))
            if whole:
                explained_before = explained
            else:
                explained_before[active] = explained
            # shrink the bracket with the sign of the residual
            below = f < 0
            lo_a = np.where(below, xa, lo_old)
            hi_a = np.where(below, hi_old, xa)
            if second:
                # f'' / (2 f'^2) where func gave f'', else kappa / (2 scale)
                half = 0.5 * second[0] / (df * df)
                if half_curvature:
                    half = np.where(np.isnan(half), half_curvature / scale, half)
                else:
                    half = np.where(np.isnan(half), 0.0, half)
                change = -f / df * (1.0 + half * f)
                if len(second) > 1:
                    # one Newton step on the cubic Taylor polynomial from the Chebyshev step;
                    # a refinement only: where it would move the step by half of itself or
                    # more, the expansion is not to be trusted (keep the Chebyshev step)
                    d2, d3 = second
                    have = ~np.isnan(d3)
                    if have.any():
                        h = change[have]
                        a, b, c = df[have], d2[have], d3[have]
                        value = f[have] + h * (a + h * (0.5 * b + h * c / 6.0))
                        correction = value / (a + h * (b + 0.5 * h * c))
                        change[have] = np.where(
                            np.abs(correction) <= 0.5 * np.abs(h), h - correction, h
                        )
                step = xa + change
            elif half_curvature:
                step = xa - f / df * (1.0 + half_curvature * f / scale)
            else:
                step = xa - f / df
            # (a NaN or infinite step compares False: bisection)
            inside = (step > lo_a) & (step < hi_a)
            new_x = np.where(inside, step, 0.5 * (lo_a + hi_a))
            # a bracket that has collapsed to round-off cannot improve any further
            bracket = hi_a - lo_a
            ulp = eps * np.abs(xa)
            stalled = bracket <= 4 * np.maximum(ulp, eps * 1e-300)
            keep = ~(done | stalled)
            if stalled.any():
                # ... and if the residual is what a step of that size explains, x is the root
                # to machine precision though |f| > tolerance (stiff f: f' * ulp(x) > atol)
                resolved = stalled & ~done & (size_f <= 2 * np.abs(df) * np.maximum(bracket, ulp))
                done = done | resolved
            converged[active[done]] = True
            move = keep | (done & inside) if polish else keep
            if whole:
                lo, hi, slope = lo_a, hi_a, df
                x[move] = new_x[move]
                active = active[keep]
            else:
                lo[active], hi[active], slope[active] = lo_a, hi_a, df
                x[active[move]] = new_x[move]
                active = active[keep]
    return RootResult(x=x, residual=residual, iterations=iterations, converged=converged)
