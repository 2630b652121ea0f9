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
BoolArray = NDArray[np.bool_]

_EPS = float(np.finfo(float).eps)

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
    batch = _Batch.start(x0, lower, upper)
    half_curvature = 0.5 * curvature
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for _ in range(max_iterations):
            if batch.active.size == 0:
                break
            # while every problem is active (the costly first iterations) no gathers
            whole = batch.active.size == batch.x.size
            xa = batch.x.copy() if whole else batch.x[batch.active]
            f, df, scale, *derivatives = func(xa, batch.active)
            lo, hi, slope = batch.record(f, whole)
            df = np.where(np.isnan(df), slope, df)
            size_f = np.abs(f)
            done = size_f <= np.maximum(rtol * scale, atol)
            done = batch.accept_round_off(done, size_f, df, xa, ulps, whole)
            # shrink the bracket with the sign of the residual
            below = f < 0
            lo = np.where(below, xa, lo)
            hi = np.where(below, hi, xa)
            step = xa + _newton_change(f, df, scale, derivatives, half_curvature)
            # (a NaN or infinite step compares False: bisection)
            inside = (step > lo) & (step < hi)
            new_x = np.where(inside, step, 0.5 * (lo + hi))
            stalled, resolved = _collapsed(lo, hi, xa, size_f, df, done)
            keep = ~(done | stalled)
            done = done | resolved
            move = keep | (done & inside) if polish else keep
            batch.advance(lo, hi, df, new_x, done, keep, move, whole)
    return RootResult(
        x=batch.x, residual=batch.residual, iterations=batch.iterations, converged=batch.converged
    )


@dataclass
class _Batch:
    """Iteration state of every problem; the ``active`` ones are still being solved.

    Attributes
    ----------
    x : ndarray
        Current iterates (same unit as the unknown).
    lo, hi : ndarray
        Current brackets (same unit as the unknown).
    residual : ndarray
        Last residual of each problem (unit of ``f``).
    slope : ndarray
        Last first derivative ``func`` computed for each problem (NaN: none yet).
    iterations : ndarray of int
        Evaluations per problem.
    converged : ndarray of bool
        Problems that met the tolerance or were located to round-off.
    explained_before : ndarray of bool
        The last residual was one that ``ulps`` units in the last place of ``x`` explain.
    active : ndarray of int
        Indices of the problems still iterating.
    """

    x: FloatArray
    lo: FloatArray
    hi: FloatArray
    residual: FloatArray
    slope: FloatArray
    iterations: NDArray[np.int64]
    converged: BoolArray
    explained_before: BoolArray
    active: NDArray[np.intp]

    @classmethod
    def start(cls, x0: FloatArray, lower: FloatArray, upper: FloatArray) -> _Batch:
        """Every problem active, at its guess clipped into its bracket."""
        lo = np.array(lower, dtype=float, copy=True)
        hi = np.array(upper, dtype=float, copy=True)
        x = np.clip(np.asarray(x0, dtype=float), lo, hi)
        size = x.size
        return cls(
            x=x,
            lo=lo,
            hi=hi,
            residual=np.full(size, np.nan),
            slope=np.full(size, np.nan),
            iterations=np.zeros(size, dtype=np.int64),
            converged=np.zeros(size, dtype=bool),
            explained_before=np.zeros(size, dtype=bool),
            active=np.arange(size),
        )

    def record(self, f: FloatArray, whole: bool) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Count an evaluation of the active problems; return their bracket and last slope.

        ``whole``: every problem is active, so nothing is gathered.
        """
        if whole:
            self.iterations += 1
            self.residual[:] = f
            return self.lo, self.hi, self.slope
        active = self.active
        self.iterations[active] += 1
        self.residual[active] = f
        return self.lo[active], self.hi[active], self.slope[active]

    def accept_round_off(
        self,
        done: BoolArray,
        size_f: FloatArray,
        df: FloatArray,
        xa: FloatArray,
        ulps: float,
        whole: bool,
    ) -> BoolArray:
        """``done``, plus residuals that ``ulps`` units in the last place of ``x`` explain.

        Such a residual is accepted where Newton's step is below one ulp (it would round
        to ``x``, and a step the bracket rejects would bisect it), or for the second
        evaluation in a row (remembered here).
        """
        ulp_x = _EPS * np.abs(xa)
        explained = ~done & (size_f <= ulps * ulp_x * np.abs(df))
        if explained.any():
            before = self.explained_before if whole else self.explained_before[self.active]
            done = done | (explained & ((size_f <= ulp_x * np.abs(df)) | before))
        if whole:
            self.explained_before = explained
        else:
            self.explained_before[self.active] = explained
        return done

    def advance(
        self,
        lo: FloatArray,
        hi: FloatArray,
        df: FloatArray,
        new_x: FloatArray,
        done: BoolArray,
        keep: BoolArray,
        move: BoolArray,
        whole: bool,
    ) -> None:
        """Store the active problems' brackets, slopes and iterates; retire the finished.

        ``done``: converged; ``keep``: still active; ``move``: take ``new_x``.
        """
        active = self.active
        self.converged[active[done]] = True
        if whole:
            self.lo, self.hi, self.slope = lo, hi, df
            self.x[move] = new_x[move]
        else:
            self.lo[active], self.hi[active], self.slope[active] = lo, hi, df
            self.x[active[move]] = new_x[move]
        self.active = active[keep]


def _newton_change(
    f: FloatArray,
    df: FloatArray,
    scale: FloatArray,
    derivatives: list[FloatArray],
    half_curvature: float,
) -> FloatArray:
    """The step of :func:`bracketed_newton`, before the bracket judges it.

    Newton's ``-f/f'``; Chebyshev's ``-f/f' (1 + f f'' / (2 f'^2))`` where ``func`` gave
    ``f''`` or ``curvature`` stands in for it (``f'' / (2 f'^2) = kappa / (2 scale)``);
    refined on the cubic Taylor polynomial where ``func`` gave the third derivative.
    """
    if derivatives:
        half = 0.5 * derivatives[0] / (df * df)
        if half_curvature:
            half = np.where(np.isnan(half), half_curvature / scale, half)
        else:
            half = np.where(np.isnan(half), 0.0, half)
        change = -f / df * (1.0 + half * f)
        if len(derivatives) > 1:
            d2, d3 = derivatives
            _refine_on_cubic(change, f, df, d2, d3)
        return change
    if half_curvature:
        return -f / df * (1.0 + half_curvature * f / scale)
    return -f / df


def _refine_on_cubic(
    change: FloatArray, f: FloatArray, df: FloatArray, d2: FloatArray, d3: FloatArray
) -> None:
    """One Newton step on ``f + f' h + f'' h^2 / 2 + f''' h^3 / 6`` from ``h = change``.

    In place, where the third derivative is known. A refinement only: where it would
    move the step by half of itself or more the expansion is not to be trusted, and the
    step stays.
    """
    have = ~np.isnan(d3)
    if have.any():
        h = change[have]
        a, b, c = df[have], d2[have], d3[have]
        value = f[have] + h * (a + h * (0.5 * b + h * c / 6.0))
        correction = value / (a + h * (b + 0.5 * h * c))
        change[have] = np.where(np.abs(correction) <= 0.5 * np.abs(h), h - correction, h)


def _collapsed(
    lo: FloatArray,
    hi: FloatArray,
    xa: FloatArray,
    size_f: FloatArray,
    df: FloatArray,
    done: BoolArray,
) -> tuple[BoolArray, BoolArray]:
    """Brackets collapsed to round-off (no further improvement), and which hold a root.

    A collapsed bracket whose residual is what a step of its size explains has its root
    to machine precision though ``|f|`` exceeds the tolerance (a stiff ``f``:
    ``f' ulp(x) > atol``).
    """
    bracket = hi - lo
    ulp = _EPS * np.abs(xa)
    stalled = bracket <= 4 * np.maximum(ulp, _EPS * 1e-300)
    if not stalled.any():
        return stalled, stalled
    resolved = stalled & ~done & (size_f <= 2 * np.abs(df) * np.maximum(bracket, ulp))
    return stalled, resolved
