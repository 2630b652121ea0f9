"""The paper balance's residual on a window, fused and allocation-free (NumPy).

The same equation as :func:`jointwear.contact.balance.paper.paper_residual`, evaluated on
the windows of :mod:`.window` in reused buffers.
"""

from __future__ import annotations

import threading

import numpy as np
from numpy.typing import NDArray

from jointwear.contact.balance.window import Window, rowdot
from jointwear.contact.laws import PowerLaw, SpringLaw

__all__ = ["PaperResidual"]

FloatArray = NDArray[np.float64]


_EPS = np.finfo(float).eps


#: per-thread scratch buffers of the residual (reused: no page faults per evaluation);
#: buffers larger than this many elements are not kept between solves
_SCRATCH = threading.local()


_SCRATCH_KEEP_ELEMENTS = 2**18


def _scratch(name: str, count: int, shape: tuple[int, int]) -> list[FloatArray]:
    """``count`` scratch arrays of ``shape``, reused across calls in this thread."""
    size = shape[0] * shape[1]
    if size > _SCRATCH_KEEP_ELEMENTS:  # a big problem: its own buffers, freed after the solve
        return list(np.empty((count, *shape)))
    store = getattr(_SCRATCH, name, None)
    if store is None or store.shape[0] < count or store.shape[1] < size:
        rows = max(count, 0 if store is None else store.shape[0])
        cols = max(size, 0 if store is None else store.shape[1])
        store = np.empty((rows, cols))
        setattr(_SCRATCH, name, store)
    return [store[i, :size].reshape(shape) for i in range(count)]


class PaperResidual:
    """Residual of the paper balance for :func:`bracketed_newton`, fused and allocation-free.

    For pin displacement ``s`` along the load the depth of window node ``j`` is
    ``s cos(phi_j) - g_j - s^2 sin^2(phi_j) / (sqrt(R_p^2 - s^2 sin^2(phi_j)) + R_p)``
    (``g_j = r_j - R_p``); the residual is ``sum_j p(depth_j) A_j cos(phi_j) - F`` and
    its derivative ``sum_j p'(depth_j) A_j cos(phi_j) (cos(phi_j) - s sin^2(phi_j) / root)``.

    With ``order`` 2 or 3 (power law 1.5 only) the slope comes with the second (and
    third) derivative (:meth:`_curvatures`), for the third- (fourth-) order step of
    :func:`bracketed_newton`: a cold start, whose guesses are ~1e-5 of the load off,
    then lands within round-off in one step (two evaluations instead of three). The
    call returns ``(residual, slope, scale)`` followed by the higher derivatives;
    NaN where a derivative was not computed.

    Speed: every array operation writes into per-thread scratch buffers of at most
    ``_BLOCK`` elements (rows are processed in blocks: fresh temporaries of a few
    hundred kB cost page faults, the ``sys`` time seen in profiles, and blocks stay
    in cache); power laws with exponent 1 or 1.5 (Winkler, NLCP) take a fused path
    (one ``sqrt`` serves force and stiffness); the sums are row-wise dot products
    (:data:`~jointwear.contact.balance.window.rowdot`). The derivative is computed only
    for loads that the residual shows are not converged yet (the last evaluation of a
    warm-started load is just the check). The depth and ``pressure / coefficient`` of
    every load's last evaluation are kept, so the final state is read off instead of
    recomputed. A call for most of the batch evaluates the whole batch (loads already
    converged are re-evaluated at their root, bit for bit) rather than gathering rows.

    Parameters
    ----------
    win : Window
        The loads' node windows.
    law : SpringLaw
        Spring law ``p(delta)`` [m -> Pa].
    pin_radius : float
        ``R_p`` [m].
    load : ndarray, shape (M,)
        Joint loads ``F`` [N].
    tolerance : float
        Absolute force tolerance [N].
    rtol : float
        Round-off floor of the convergence test, relative to ``sum_j |f_j|`` [-].
    order : int
        Highest derivative formed with the slope (power law 1.5): 1, 2 or 3.
    """

    _BLOCK = 2**16

    def __init__(
        self,
        win: Window,
        law: SpringLaw,
        pin_radius: float,
        load: FloatArray,
        tolerance: float,
        rtol: float = 8 * _EPS,
        order: int = 1,
    ):
        m, k = win.cos.shape
        self.m = m
        self.block = max(1, min(m, self._BLOCK // k))
        self.law = law
        self.radius_pin, self.r_pin2 = pin_radius, pin_radius**2
        self.cos, self.sin2, self.gap = win.cos, win.sin2, win.gap
        self.load = load
        self.atol, self.rtol = tolerance, rtol
        fast = isinstance(law, PowerLaw) and law.exponent in (1.0, 1.5)
        self.exponent = law.exponent if fast else None
        self.coefficient = law.coefficient if fast else 1.0
        #: block buffers: 4 for the arithmetic, 8 for gathered rows
        self.work = _scratch("block", 12, (self.block, k))
        #: depth and pressure / coefficient of every load's last evaluation
        self.depth, self.power = _scratch("batch", 2, (m, k))
        #: coefficient * A_j * cos(phi_j): the pressure law's constant folded in
        factor = self.coefficient * win.area
        weight = win.geometry.scaled_cos(factor)
        self.weight = weight if weight is not None else factor * win.cos
        #: coefficient * A_j * cos(phi_j)^2 (the stiffness along the load)
        weight_cos = win.geometry.scaled_cos(factor, power=2)
        self.weight_cos = weight_cos if weight_cos is not None else self.weight * win.cos
        #: highest derivative formed with the slope: 1, 2 (f'') or 3 (f'''); power law 1.5
        self.order = order if self.exponent == 1.5 else 1
        self.total = np.zeros(m)
        self.offset = np.zeros(m)
        #: loads whose slope has not been computed yet
        self.fresh = np.ones(m, dtype=bool)
        #: a residual above this fraction of the force gets a new slope (else a chord step)
        self.refresh = 1e-10

    def __call__(self, s: FloatArray, rows: NDArray[np.intp]):
        n = rows.size
        self.offset[rows] = s
        if 2 * n >= self.m:
            # (most of) the whole batch: evaluate all of it, no gather
            wanted = None
            if n < self.m:
                wanted = np.zeros(self.m, dtype=bool)
                wanted[rows] = True
            total, derivatives = self._blocks(self.offset, None, wanted)
            self.total[:] = total
            if n < self.m:
                total, derivatives = total[rows], derivatives[:, rows]
        else:
            total, derivatives = self._blocks(s, rows, None)
            self.total[rows] = total
        # every force term is >= 0 (|phi| <= 90 deg in the window): sum|f_j| = total, the
        # scale of the round-off floor 8 eps sum|f_j| of the convergence test
        return total - self.load[rows], derivatives[0], total, *derivatives[1:]

    def _blocks(self, s, rows, wanted):
        """Evaluate rows ``rows`` (all if None) block by block: totals, derivatives."""
        n = s.size
        total = np.empty(n)
        derivatives = np.empty((self.order, n))
        for start in range(0, n, self.block):
            stop = min(n, start + self.block)
            if rows is None:
                part = slice(start, stop)
                arrays = (
                    self.cos[part],
                    self.sin2[part],
                    self.gap[part],
                    self.weight[part],
                    self.weight_cos[part],
                    self.depth[part],
                    self.power[part],
                )
                load = self.load[part]
                keep = None if wanted is None else wanted[part]
                fresh = self.fresh[part]
            else:
                index = rows[start:stop]
                size = index.size
                arrays = tuple(buffer[:size] for buffer in self.work[4:11])
                for source, target in zip(
                    (self.cos, self.sin2, self.gap, self.weight, self.weight_cos),
                    arrays,
                    strict=False,
                ):
                    if source.shape != self.cos.shape:  # a column or a broadcast view
                        source = np.broadcast_to(source, self.cos.shape)
                    # mode="clip": the default "raise" buffers the output (4x slower)
                    np.take(source, index, axis=0, out=target, mode="clip")
                load = self.load[index]
                keep = None
                fresh = self.fresh[index]
            total[start:stop], derivatives[:, start:stop], computed = self._evaluate(
                s[start:stop], load, *arrays, keep, fresh
            )
            if rows is None:
                if computed is not None:
                    self.fresh[part][computed] = False
            else:
                self.depth[index] = arrays[5]
                self.power[index] = arrays[6]
                if computed is not None:
                    self.fresh[index[computed]] = False
        return total, derivatives

    def _evaluate(self, s, load, cos, sin2, gap, weight, weight_cos, depth, power, keep, fresh):
        """Totals of a block; slopes (and higher derivatives) of the rows that need one.

        The derivatives are rows of one array: the slope, and up to ``order`` the
        higher ones.

        A row needs its slope while it is not converged and it has none yet or its residual
        is above ``refresh`` of its force (``keep``: only rows asked for); otherwise the
        solver reuses the last slope (a chord step: its error factor ``kappa (f'/F) |s -
        s_slope|`` is ~1e-5 there, so one chord step from a residual of 1e-10 F reaches
        round-off). The higher derivatives (up to ``order``) come with the slope.
        """
        n = s.size
        lat, root, tmp, pen = (w[:n] for w in self.work[:4])
        s_col = s[:, None]
        np.multiply(sin2, (s * s)[:, None], out=lat)  # s^2 sin^2
        np.subtract(self.r_pin2, lat, out=root)
        np.sqrt(root, out=root)
        np.add(root, self.radius_pin, out=tmp)
        np.divide(lat, tmp, out=tmp)  # pin curvature term
        np.multiply(cos, s_col, out=depth)
        depth -= gap
        depth -= tmp
        np.maximum(depth, 0.0, out=pen)
        if self.exponent == 1.5:
            np.sqrt(pen, out=tmp)  # kept for the stiffness 1.5 sqrt(pen)
            np.multiply(tmp, pen, out=power)
            total = rowdot(power, weight)
        elif self.exponent == 1.0:
            power[...] = pen
            total = rowdot(power, weight)
        else:
            total = rowdot(self.law.pressure(pen), weight)
        derivatives = np.full((self.order, n), np.nan)
        slope = derivatives[0]
        # the derivative only where the residual is not yet within tolerance and the last
        # one (if any) is not good enough for a chord step
        error = np.abs(total - load)
        need = (error > np.maximum(self.atol, self.rtol * total)) & (
            fresh | (error > self.refresh * total)
        )
        if keep is not None:
            need &= keep
        count = np.count_nonzero(need)
        if not count:
            return total, derivatives, None
        if 2 * count >= n:
            # most rows: the slope of the whole block, kept where needed (gathering the rows
            # into fresh arrays costs more than the extra arithmetic, and page faults)
            sel, s_sel, pick = need, np.where(need, s, 1.0), need
        else:
            sel = np.flatnonzero(need)
            s_sel, pick = s[sel], slice(None)
            lat, root, pen, tmp = lat[sel], root[sel], pen[sel], tmp[sel]
            weight, weight_cos = weight[sel], weight_cos[sel]
            if self.order > 1:
                cos, sin2 = cos[sel], sin2[sel]
        # d depth / ds = cos - s sin^2 / root: sum_j k_j cos_j^2 - sum_j k_j (lat_j / root_j) / s,
        # k_j = p'(depth_j) A_j (weight = A cos), the first sum without a pass of its own
        np.divide(lat, root, out=lat)
        np.multiply(lat, weight, out=lat)
        if self.exponent == 1.5:
            along = rowdot(tmp, weight_cos)
            across = rowdot(tmp, lat)
            slope[sel] = (1.5 * (along - across / s_sel))[pick]
            if self.order > 1:
                higher = self._curvatures(s_sel, cos, sin2, weight, pen, tmp, across, lat, root)
                for row, values in enumerate(higher, start=1):
                    derivatives[row, sel] = values[pick]
        elif self.exponent == 1.0:
            np.greater(pen, 0.0, out=root)  # 1.0 where in contact
            along = rowdot(root, weight_cos)
            across = rowdot(root, lat)
            slope[sel] = (along - across / s_sel)[pick]
        else:
            derivative = self.law.pressure_derivative(pen)
            along = rowdot(derivative, weight_cos)
            across = rowdot(derivative, lat)
            slope[sel] = (along - across / s_sel)[pick]
        return total, derivatives, need

    def _curvatures(
        self, s, cos, sin2, weight, pen, root_pen, across, work, out
    ) -> tuple[FloatArray, ...]:
        """Second (and with ``order`` 3 third) derivative of the residual, ``p = k delta^1.5``.

        ``f'' = sum_j A_j cos_j (p''(delta_j) delta_j'^2 + p'(delta_j) delta_j'')`` with
        ``delta' = cos - s sin^2 / root`` and ``delta'' = -(sin^2 / root) (1 + s^2 sin^2 /
        root^2)``, ``root = sqrt(R_p^2 - s^2 sin^2)``. ``delta'`` is taken with ``root ~
        R_p``, and the ``p' delta''`` sum is the slope's ``across`` sum over ``s^2`` (its
        factor ``1 + s^2 sin^2 / root^2`` dropped): both are relative errors of ``(s /
        R_p)^2 ~ 1e-4`` on small parts of ``f''``, which comes out to ~1e-7. ``f'''`` is its
        leading term ``sum_j A_j cos_j p'''(delta_j) delta_j'^3`` (``p''' ~ delta^-1.5``;
        the next one is ~1 % of it): it is large where a node barely touches, which is
        where a third-order step falls short. Only the step uses them, never the
        convergence test. ``pen`` (the depths in contact), ``work`` and ``out`` are
        overwritten.
        """
        np.multiply(sin2, (s / self.radius_pin)[:, None], out=out)
        np.subtract(cos, out, out=out)  # delta'
        # 1 / sqrt(delta) in contact, 0 elsewhere (sqrt(0) / tiny): a depth in contact is
        # never below 1e-300 m
        np.add(pen, 1e-300, out=work)
        np.divide(root_pen, work, out=work)
        np.multiply(out, work, out=out)  # delta' / sqrt(delta)
        np.multiply(out, out, out=pen)  # delta'^2 / delta
        np.multiply(pen, root_pen, out=work)  # delta'^2 / sqrt(delta)
        second = 0.75 * rowdot(work, weight) - 1.5 * across / (s * s)
        if self.order < 3:
            return (second,)
        pen *= out  # (delta' / sqrt(delta))^3
        return second, -0.375 * rowdot(pen, weight)

    def pressure(self) -> FloatArray:
        """Pressure on the window at every load's last evaluation [Pa]."""
        if self.exponent is None:
            return self.law.pressure(np.maximum(self.depth, 0.0))
        return np.multiply(self.power, self.coefficient, out=self.power)
