"""Load balance: where the pin sits so that the springs carry the joint load.

For every load ``F`` at azimuth ``psi`` (the direction in which the pin presses
on the bushing) find the pin-centre position ``e`` such that the springs'
resultant equals the load:

* ``balance="paper"``: the pin moves along the load line only, ``e = s w``,
  and ``s`` is iterated until the component along the load balances it
  (paper eqs. 5 and 7, with ``cos beta``): ``sum_j p_j A_j cos(beta_j) = F``.
  On an asymmetric (worn) contour the resultant then has a sideways component,
  reported as ``tangential_force``.
* ``balance="equilibrium"``: full 2-D equilibrium, the resultant *vector*
  equals the load vector (no sideways residue).

All loads are solved together (no Python loop over loads): nodes are gathered
into a window around each load line, where the only nodes that can touch lie
(a node more than 90 degrees from the load can never touch because the pin is
smaller than the bushing), and a bracketed Newton iteration
(:func:`jointwear.solvers.bracketed_newton`) runs on the whole batch.

Starting points: a warm start takes the caller's offsets (the previous revolution).
A cold start on a circle (an unworn bushing, or the symmetric law) takes the
node-free contact of a pin in a circle (:func:`_circle_guess`, ~1e-5 of the load
off); on a worn contour a batch of >= 64 loads solves every 8th load first and
interpolates (:func:`_coarse_guess`), a small batch starts from a conformal-contact
estimate. The balance of a cold start then takes fourth-order steps (power law
1.5: the residual gives its second and third derivatives), which bring a ~1e-5
start to round-off in one step: two evaluations per load, the step and the check.

Convergence: ``|F_total - F| <= max(tolerance, 8 eps * sum|f_j|)``: the
paper's 1e-12 N, with a round-off floor for loads where 1e-12 N is below what
double precision can resolve in a sum of spring forces.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.polynomial import chebyshev
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.laws import CallableSpringLaw, PowerLaw, SpringLaw
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ContactError, ConvergenceError
from jointwear.geometry.contour import BushingContour, Pin, RadiusStencil
from jointwear.solvers import bracketed_newton

__all__ = ["solve_contact"]

FloatArray = NDArray[np.float64]
_EPS = np.finfo(float).eps


#: window geometry per (nodes, width, azimuths): a simulation solves the same loads on a new
#: contour every revolution, so the trigonometry and index arithmetic are done once
_GEOMETRY_CACHE: dict[tuple[int, int, bytes], _Geometry] = {}
_GEOMETRY_CACHE_SIZE = 4
#: largest window (loads x nodes) whose geometry is cached (about 10 arrays of 2 MB)
_GEOMETRY_CACHE_ELEMENTS = 2**18
#: per-thread scratch buffers of the residual (reused: no page faults per evaluation);
#: buffers larger than this many elements are not kept between solves
_SCRATCH = threading.local()
_SCRATCH_KEEP_ELEMENTS = 2**18
#: the coarse pass solves every 8th load, to |F_total - F| <= 1e-3 F (then one more,
#: unevaluated step: see _coarse_guess)
_COARSE_STRIDE = 8
_COARSE_RTOL = 1e-3
#: stencils and weights of the coarse-to-fine interpolation, per (size, coarse indices)
_INTERPOLATION_CACHE: dict[tuple[int, bytes], tuple[NDArray[np.intp], FloatArray]] = {}


def _einsum_rowdot(a: FloatArray, b: FloatArray) -> FloatArray:
    return np.einsum("...j,...j->...", a, b)


#: ``sum_j a_ij b_ij`` per row: ``np.vecdot`` (NumPy >= 2, a dot kernel per row, about
#: 1.6 times faster than the einsum on a 360 x 105 window), else the einsum
_rowdot: Callable[[FloatArray, FloatArray], FloatArray] = getattr(np, "vecdot", _einsum_rowdot)


class _Geometry:
    """Contour-independent part of a window: node indices and angles about each load line."""

    def __init__(self, nodes: int, azimuth: FloatArray, width: int) -> None:
        dtheta = 2 * np.pi / nodes
        m = azimuth.size
        wrapped = np.mod(azimuth, 2 * np.pi)
        centre = np.rint(wrapped / dtheta).astype(np.int64)
        offsets = np.arange(-width, width + 1)
        shift = centre * dtheta - wrapped
        self.wrapped = wrapped
        self.index = (centre[:, None] + offsets) % nodes
        #: flat positions of the window in an (M, N) array
        self.flat = (np.arange(m)[:, None] * nodes + self.index).ravel()
        self.phi = offsets * dtheta + shift[:, None]
        # angle addition: trig on (M,) and (2W+1,) vectors instead of the (M, 2W+1) block
        cos_o, sin_o = np.cos(offsets * dtheta), np.sin(offsets * dtheta)
        cos_s, sin_s = np.cos(shift)[:, None], np.sin(shift)[:, None]
        self.cos = cos_o * cos_s - sin_o * sin_s
        self.sin = sin_o * cos_s + cos_o * sin_s
        self.sin2 = self.sin**2
        self.left = self.phi > 0
        self.right = self.phi < 0
        self.unit = np.stack([np.cos(azimuth), np.sin(azimuth)], axis=1)
        self.unit_perp = np.stack([-self.unit[:, 1], self.unit[:, 0]], axis=1)
        for array in vars(self).values():
            array.setflags(write=False)
        #: the contour's radius on each load line, from its node radii
        self.radius_at_loads = RadiusStencil.at(nodes, wrapped)
        self._scaled: dict[tuple[float, int], FloatArray] = {}

    def scaled_cos(self, factor: Any, power: int = 1) -> FloatArray | None:
        """``factor * cos**power`` for a scalar factor (cached), else None."""
        if isinstance(factor, np.ndarray):
            return None
        key = (float(factor), power)
        scaled = self._scaled.get(key)
        if scaled is None:
            if len(self._scaled) >= 8:
                self._scaled.clear()
            scaled = key[0] * self.cos if power == 1 else key[0] * self.cos**power
            scaled.setflags(write=False)
            self._scaled[key] = scaled
        return scaled


def _geometry(nodes: int, azimuth: FloatArray, width: int) -> _Geometry:
    if azimuth.size * (2 * width + 1) > _GEOMETRY_CACHE_ELEMENTS:
        return _Geometry(nodes, azimuth, width)  # too big to keep around
    key = (nodes, width, azimuth.tobytes())
    geometry = _GEOMETRY_CACHE.get(key)
    if geometry is None:
        geometry = _Geometry(nodes, azimuth, width)
        while len(_GEOMETRY_CACHE) >= _GEOMETRY_CACHE_SIZE:
            _GEOMETRY_CACHE.pop(next(iter(_GEOMETRY_CACHE)), None)
        _GEOMETRY_CACHE[key] = geometry
    return geometry


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


class _Window:
    """Nodes within +-W of each load line, gathered into (M, 2W+1) arrays.

    ``gap`` (``r_j - R_p``) is an (M, 1) column where every spring of a row has the same
    gap: the symmetric law (springs on the circle through the compression centre) and an
    unworn, circular bushing; the residual then reads one number per row instead of an
    (M, 2W+1) gather. ``area`` is a scalar where every spring has the same one.
    """

    def __init__(
        self,
        contour: BushingContour,
        azimuth: FloatArray,
        width: int,
        law: SpringLaw,
        pin_radius: float,
        centre_radius: FloatArray | None = None,
    ) -> None:
        geometry = _geometry(contour.nodes, azimuth, width)
        self.geometry = geometry
        self.width = width
        self.symmetric = bool(law.symmetric)
        self.index, self.phi = geometry.index, geometry.phi
        self.cos, self.sin, self.sin2 = geometry.cos, geometry.sin, geometry.sin2
        radius = contour.radius
        if centre_radius is None:
            centre_radius = geometry.radius_at_loads(radius)
        self.centre_radius = centre_radius
        circle = bool(radius.min() == radius.max())
        # r - R_p is exact (Sterbenz); the depth is assembled from small terms
        # so a micrometre penetration is not the difference of two radii
        if law.symmetric:
            self.gap = (centre_radius - pin_radius)[:, None]
        elif circle:
            self.gap = np.full((azimuth.size, 1), radius[0] - pin_radius)
        else:
            self.gap = np.take(radius - pin_radius, self.index)
        spring = contour.dtheta * contour.axial_length
        if law.force_area is not None:
            self.area: Any = law.force_area
        elif law.symmetric:
            self.area = np.broadcast_to(centre_radius[:, None], self.phi.shape) * spring
        elif circle:
            self.area = float(radius[0]) * spring
        else:
            self.area = np.take(radius, self.index) * spring


class _PaperResidual:
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
    (:data:`_rowdot`). The derivative is computed only for loads that the residual
    shows are not converged yet (the last evaluation of a warm-started load is just
    the check). The depth and ``pressure / coefficient`` of every load's last
    evaluation are kept, so the final state is read off instead of recomputed. A call
    for most of the batch evaluates the whole batch (loads already converged are
    re-evaluated at their root, bit for bit) rather than gathering rows.
    """

    _BLOCK = 2**16

    def __init__(
        self,
        win: _Window,
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
            total = _rowdot(power, weight)
        elif self.exponent == 1.0:
            power[...] = pen
            total = _rowdot(power, weight)
        else:
            total = _rowdot(self.law.pressure(pen), weight)
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
            along = _rowdot(tmp, weight_cos)
            across = _rowdot(tmp, lat)
            slope[sel] = (1.5 * (along - across / s_sel))[pick]
            if self.order > 1:
                higher = self._curvatures(s_sel, cos, sin2, weight, pen, tmp, across, lat, root)
                for row, values in enumerate(higher, start=1):
                    derivatives[row, sel] = values[pick]
        elif self.exponent == 1.0:
            np.greater(pen, 0.0, out=root)  # 1.0 where in contact
            along = _rowdot(root, weight_cos)
            across = _rowdot(root, lat)
            slope[sel] = (along - across / s_sel)[pick]
        else:
            derivative = self.law.pressure_derivative(pen)
            along = _rowdot(derivative, weight_cos)
            across = _rowdot(derivative, lat)
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
        second = 0.75 * _rowdot(work, weight) - 1.5 * across / (s * s)
        if self.order < 3:
            return (second,)
        pen *= out  # (delta' / sqrt(delta))^3
        return second, -0.375 * _rowdot(pen, weight)

    def pressure(self) -> FloatArray:
        """Pressure on the window at every load's last evaluation [Pa]."""
        if self.exponent is None:
            return self.law.pressure(np.maximum(self.depth, 0.0))
        return np.multiply(self.power, self.coefficient, out=self.power)


def _initial_guess(
    win: _Window,
    law: SpringLaw,
    contour: BushingContour,
    pin_radius: float,
    load: FloatArray,
    lower: FloatArray,
    upper: FloatArray,
) -> FloatArray:
    """Pin displacement estimated from a conformal-contact model, for a cold start."""
    if not isinstance(law, PowerLaw):
        return 0.5 * (lower + upper)
    clearance = np.maximum(win.centre_radius - pin_radius, 1e-12 * pin_radius)
    delta = _conformal_depth(contour, pin_radius, law, load, clearance)
    return np.clip(clearance + delta, lower, upper)


def _conformal_depth(contour, pin_radius, law, load, clearance):
    """Penetration at the compression centre from a conformal-contact model [m].

    A power law ``p = k delta^n`` on a circle of clearance ``c``, small angles: the
    depth is ``delta_0 (1 - phi^2 / alpha^2)`` with ``alpha^2 = 2 delta_0 / (c + delta_0)``,
    so ``F = (A k / dtheta) B(n) delta_0^n alpha``, ``B(n) = sqrt(pi) Gamma(n+1) /
    Gamma(n+3/2)``. Two fixed-point passes for ``delta_0``; only a starting point for Newton
    (the half-angle ``alpha`` came out 3 % below the solved one for the paper's NLCP case).
    """
    n = law.exponent
    if law.force_area is not None:
        per_radian = law.force_area / contour.dtheta
    else:
        per_radian = (clearance + pin_radius) * contour.axial_length
    shape = math.sqrt(math.pi) * math.gamma(n + 1) / math.gamma(n + 1.5)
    scale = load / (law.coefficient * per_radian * shape)
    delta = (scale * np.sqrt(0.5 * clearance)) ** (1 / (n + 0.5))
    for _ in range(2):
        delta = (scale * np.sqrt(0.5 * (clearance + delta))) ** (1 / (n + 0.5))
    return delta


def _curvature(law: SpringLaw) -> float:
    """``kappa = (m - 1) / m`` of the total force ``F ~ u^m`` for the Chebyshev step.

    A power law ``p ~ delta^n`` in conformal contact (small angles) carries
    ``F ~ delta_0^n alpha`` with the half-angle ``alpha ~ sqrt(delta_0)``: ``m = n + 1/2``.
    Wider contacts and worn contours deviate (kappa 0.4-0.6 measured for the paper's
    NLCP case against 0.5 here); the correction only needs to be roughly right, as it
    shrinks Newton's quadratic error term by the relative error of kappa.
    """
    if isinstance(law, PowerLaw) and law.exponent > 0.5:
        return (law.exponent - 0.5) / (law.exponent + 0.5)
    return 0.0


def checked_loads(load: ArrayLike, azimuth: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Loads [N] and azimuths [rad] as flat float arrays of one length, checked.

    Raises :class:`ContactError` for a load or azimuth that is not finite or a negative
    load (the azimuth gives the direction).
    """
    load = np.asarray(load, dtype=float).ravel()
    azimuth = np.asarray(azimuth, dtype=float).ravel()
    if azimuth.shape == load.shape:
        azimuth = azimuth.copy()
    else:
        azimuth = np.broadcast_to(azimuth, load.shape).copy()
    if not (np.isfinite(load).all() and np.isfinite(azimuth).all()):
        raise ContactError("load: loads and azimuths must be finite")
    if (load < 0).any():
        raise ContactError("load: must be >= 0 (the azimuth gives the direction)")
    return load, azimuth


def _law_from(model: SpringLaw | Callable[..., Any]) -> SpringLaw:
    if isinstance(model, SpringLaw):
        return model
    if hasattr(model, "pressure") and hasattr(model, "pressure_derivative"):
        return model  # type: ignore[return-value]
    return CallableSpringLaw(model)


def solve_contact(
    contour: BushingContour,
    pin: Pin,
    load: ArrayLike,
    azimuth: ArrayLike,
    law: SpringLaw | Callable[..., Any],
    *,
    balance: str = "paper",
    tolerance: float = 1e-12,
    max_iterations: int = 100,
    max_penetration: float | None = None,
    initial_offset: ArrayLike | None = None,
    window: int | None = None,
) -> ContactSolution:
    """Pressure on every bushing node for many loads on one contour.

    Parameters
    ----------
    contour : BushingContour
        Current bushing contour.
    pin : Pin
        The pin.
    load : array_like, shape (M,)
        Joint load magnitudes ``F_N`` [N], >= 0.
    azimuth : array_like, shape (M,)
        Direction in which the pin presses on the bushing, in the bushing frame [rad].
    law : SpringLaw or callable
        Spring law (e.g. from :func:`jointwear.contact.spring_law`) or a
        callable ``pressure(penetration)`` [m -> Pa]. Hertz is solved by
        :func:`jointwear.contact.hertz.solve` instead.
    balance : {"paper", "equilibrium"}
        Balance along the load line only, or full 2-D equilibrium.
    tolerance : float
        Absolute force tolerance [N].
    max_iterations : int
        Residual evaluations allowed per load.
    max_penetration : float, optional
        Largest admissible penetration at the compression centre, normally the
        bushing wall thickness [m]; a load needing more raises :class:`ContactError`.
    initial_offset : array_like, shape (M,), optional
        Initial guesses of the pin displacement along the load line [m]
        (a previous solution), for warm starts.
    window : int, optional
        Half-width of the node window in nodes; widened automatically if the
        contact reaches its edge or a node beyond it could touch (non-contiguous
        contact on worn contours). Default: with ``initial_offset`` 90 degrees (always
        sufficient in paper mode; 2-D equilibrium may widen it up to 180 degrees),
        else sized from the cold start's estimate of the contact.

    Returns
    -------
    ContactSolution
    """
    law = _law_from(law)
    load, azimuth = checked_loads(load, azimuth)
    if balance not in ("paper", "equilibrium"):
        raise ContactError(
            f"contact.balance: unknown mode {balance!r}; choose 'paper' or 'equilibrium'"
        )
    contour.check_pin(pin)
    full = contour.nodes // 4
    # paper mode: the pin moves along the load, nodes > 90 deg away never touch; in 2-D
    # equilibrium the pin moves sideways too, so the window may have to grow further
    limit = full if balance == "paper" else max(full, (contour.nodes - 1) // 2)
    if initial_offset is not None:
        guess = np.asarray(initial_offset, dtype=float).ravel()
        width = full if window is None else int(min(max(window, 2), full))
    elif (circle := _circle_guess(contour, pin, law, load, azimuth)) is not None:
        # every spring of a load on one circle (an unworn bushing, or the symmetric law):
        # the node-free contact gives every load's offset to ~1e-5 of its force, and the
        # contact's half-angle
        guess, widest = circle
        if window is None:
            width = int(min(full, np.ceil(1.05 * widest / contour.dtheta) + 3))
        else:
            width = int(min(max(window, 2), full))
    elif load.size >= 64:
        # warm start from neighbours: solve every 8th load (recursively, so a long
        # batch is solved coarse-to-fine), interpolate the rest, and size the node
        # window from the widest coarse contact
        guess, widest = _coarse_guess(
            contour, pin, law, load, azimuth, tolerance, max_iterations, max_penetration, window
        )
        width = int(min(full, np.ceil(1.05 * widest / contour.dtheta) + 3))
    else:
        guess = None
        width = full if window is None else int(min(max(window, 2), full))
    # whole multiples of 4 nodes: the cached window geometry is reused while the contact
    # width drifts from one solve to the next
    width = min(-(-width // 4) * 4, full)
    while True:
        win = _Window(contour, azimuth, width, law, pin.radius)
        solution, edge, along, across = _solve_window(
            win,
            contour,
            pin,
            load,
            azimuth,
            law,
            balance,
            tolerance,
            max_iterations,
            max_penetration,
            guess,
            order=1 if initial_offset is not None else 3,
        )
        if width >= limit:
            return solution
        # contact need not be contiguous (worn contours): a node beyond a gap in the contact
        # may touch although the window's edge nodes do not; the reach bound finds it
        needed = _reach_width(contour, pin, law, win.centre_radius, along, across)
        if not edge and needed <= width:
            return solution
        width = int(min(max(needed, width + 1), limit))


def _lower_bound(win, contour, pin_radius, load):
    """Lower end of the bracket of the pin offset: no node touches, ``f <= 0`` [m].

    The smallest radial gap of the window (where a load is zero the pin is put there,
    touching; a gap as wide as the pin is reported as out of reach). Otherwise the
    smallest gap of the whole contour, a bound as valid and without a pass over the window.
    """
    if win.symmetric:
        return win.centre_radius - pin_radius  # the gap of every spring of the row
    if np.any(load == 0) or contour.radius.max() - pin_radius >= 0.999 * pin_radius:
        return win.gap.min(axis=1)
    return np.full(load.shape, float(contour.radius.min()) - pin_radius)


def _circle_rule(points: int) -> tuple[FloatArray, FloatArray]:
    """Squared nodes ``u^2 = sin(t)^2`` and weights ``cos(t) w_t`` of Gauss-Legendre in ``t``.

    For ``int_{-1}^{1} g(u) du`` with ``g ~ (1 - u^2)^n`` at the ends (the force of springs
    whose depth falls to zero at the contact edges): ``u = sin t`` makes the integrand
    ``~ cos^(2n+1) t``, smooth enough that 10 points give the penetration of
    :func:`_circle_offsets` to ~4e-8 (against 48 points, paper case), far below the ripple
    of the nodes that it cannot know about.
    """
    x, w = np.polynomial.legendre.leggauss(points)
    angle = 0.5 * np.pi * x
    return np.sin(angle) ** 2, 0.5 * np.pi * w * np.cos(angle)


_CIRCLE_RULE = _circle_rule(10)
#: Chebyshev points in ln F at which the offsets on an unworn bushing are solved
_CHEBYSHEV_POINTS = 12


def _circle_guess(contour, pin, law, load, azimuth):
    """Pin offsets from the node-free contact of a circle, and the widest half-angle [rad].

    Applies where every spring of a load lies on one circle (an unworn bushing, or the
    symmetric law's circle through the compression centre) and the law is a power law
    ``p = k delta^n``; else None. The nodes' sum of spring forces differs from the
    integral of :func:`_circle_offsets` by a ripple of where the contact edges fall
    between the nodes, ~1e-5 of the force and without bias (~3e-6 median, 9e-6 at most
    on the paper case): as good a start as the coarse pass, at a fraction of its cost.
    On an unworn bushing the offset depends on the load's magnitude only (not on its
    direction), so a long batch is solved at 12 Chebyshev points of ``ln F`` and the
    smooth ``ln(s - c)`` interpolated (6e-14 off the load-by-load solve, paper case).
    """
    if not isinstance(law, PowerLaw) or law.exponent <= 0:
        return None
    radius = contour.radius
    rp = pin.radius
    if law.symmetric:
        r = contour.radius_at(np.mod(azimuth, 2 * np.pi))
    elif radius.min() == radius.max():
        r = np.full(load.shape, radius[0])
    else:
        return None
    # no load: touching (the balance puts the pin at its lower bound anyway)
    guess = r - rp
    positive = load > 0
    if positive.all():
        force, r_loaded = load, r
    elif positive.any():
        force, r_loaded = load[positive], r[positive]
    else:
        return guess, 0.0
    if law.symmetric or force.size <= 2 * _CHEBYSHEV_POINTS:
        delta = _circle_offsets(contour, rp, law, force, r_loaded)
        s = r_loaded - rp + delta
        # the contact half-angle alpha: cos(alpha) = (r^2 + s^2 - R_p^2) / (2 r s)
        cos_alpha = float(np.min(((r_loaded - rp) * (r_loaded + rp) + s * s) / (2 * r_loaded * s)))
    else:
        # the offset depends on |F| only: solve at Chebyshev points of ln F, interpolate
        x = np.log(force)
        low, high = x.min(), x.max()
        r0 = float(radius[0])
        centre, half = 0.5 * (low + high), 0.5 * (high - low)

        def log_depth(t: FloatArray) -> FloatArray:  # t in [-1, 1] maps onto [low, high]
            at = np.exp(centre + half * t)
            return np.log(_circle_offsets(contour, rp, law, at, np.full(t.size, r0)))

        coefficients = chebyshev.chebinterpolate(log_depth, _CHEBYSHEV_POINTS - 1)
        t = (x - centre) / half if half > 0 else np.zeros_like(x)
        s = (r0 - rp) + np.exp(chebyshev.chebval(t, coefficients))
        # alpha grows with s on one circle
        widest = float(s.max())
        cos_alpha = ((r0 - rp) * (r0 + rp) + widest * widest) / (2 * r0 * widest)
    if force is load:
        guess = s
    else:
        guess[positive] = s
    return guess, math.acos(min(max(cos_alpha, 0.0), 1.0))


def _circle_offsets(contour, pin_radius, law, load, radius, steps: int = 2) -> FloatArray:
    """Penetration ``s - c`` of a pin in a circle, node-free (continuous springs) [m].

    On a circle of radius ``r`` (clearance ``c = r - R_p``) the depth at ``v = sin(phi)``
    is ``s sqrt(1 - v^2) - r + sqrt(R_p^2 - s^2 v^2)`` and the springs carry
    ``F = (A / dtheta) k int depth^n dv`` over the contact ``|v| < sin(alpha)``,
    ``cos(alpha) = (r^2 + s^2 - R_p^2) / (2 r s)`` (the circles' intersection), as ``v``
    times the projection ``cos(phi)`` is the force along the load. Contact beyond 90
    degrees is cut off, as in the window. Newton's method on ``ln(s - c)`` (``ln F`` is
    nearly linear in it) from the conformal estimate (2 % off on the paper case): one
    step leaves ~3e-5, a second one with the first slope (a chord) ~1e-9.
    """
    rp = pin_radius
    n = law.exponent
    clearance = np.maximum(radius - rp, 1e-12 * rp)
    start = delta = _conformal_depth(contour, rp, law, load, clearance)
    if law.force_area is not None:
        per_radian = law.force_area / contour.dtheta
    else:
        per_radian = radius * contour.axial_length
    target = load / (law.coefficient * per_radian)
    u2, w = _CIRCLE_RULE
    # r^2 - R_p^2 = (r - R_p)(r + R_p): no cancellation
    chord = clearance * (radius + rp)
    twice_r = 2.0 * radius
    r_col = radius[:, None]
    elasticity = None
    # (a load too large for the pin's reach makes the model invalid: NaN, handled below)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for step in range(steps):
            s = clearance + delta
            s_col = s[:, None]
            cos_alpha = (chord + s * s) / (twice_r * s)
            # sin^2(alpha), or 1 where the contact would reach beyond 90 degrees (cut off
            # there, as the window is)
            sin2_alpha = np.maximum(cos_alpha, 0.0)
            sin2_alpha *= sin2_alpha
            np.subtract(1.0, sin2_alpha, out=sin2_alpha)
            v2 = sin2_alpha[:, None] * u2
            along = np.sqrt(1.0 - v2)  # cos(phi)
            root = np.sqrt(rp * rp - (s * s)[:, None] * v2)
            depth = s_col * along
            depth -= r_col
            depth += root
            np.maximum(depth, 0.0, out=depth)
            root_depth = np.sqrt(depth) if n == 1.5 else None
            force = (depth * root_depth if n == 1.5 else depth**n) @ w
            if step == 0:
                # d ln F / d ln delta = delta F' / F (F carries the factor sin(alpha) of
                # v = sin(alpha) sin(t), the ratio does not)
                np.divide(v2, root, out=root)
                root *= s_col
                np.subtract(along, root, out=along)  # d depth / ds = cos(phi) - s v^2 / root
                along *= root_depth if n == 1.5 else depth ** (n - 1)
                elasticity = n * delta * (along @ w) / force
            change = np.log(target / (np.sqrt(sin2_alpha) * force)) / elasticity
            # at most a factor e^2 per step: no wild step leaves the model's range
            delta = delta * np.exp(np.minimum(np.maximum(change, -2.0), 2.0))
    if not np.isfinite(delta).all():  # keep the conformal estimate there
        delta = np.where(np.isfinite(delta), delta, start)
    return delta


def _bracket(win, contour, pin_radius, load, max_penetration):
    """Bracket ``[lower, upper]`` of the pin offset along each load line [m].

    ``upper``: 0.999 of the pin radius (the ray geometry needs ``|e| < R_p``), or the
    wall thickness beyond the compression centre, never below ``lower``.
    """
    lower = _lower_bound(win, contour, pin_radius, load)
    upper = np.full(lower.shape, 0.999 * pin_radius)
    if max_penetration is not None:
        upper = np.minimum(upper, win.centre_radius - pin_radius + max_penetration)
    return lower, np.maximum(upper, lower)


def _coarse_indices(size: int) -> NDArray[np.intp]:
    """Every ``_COARSE_STRIDE``-th of ``size`` loads, and the last one."""
    coarse = np.arange(0, size, _COARSE_STRIDE)
    if coarse[-1] != size - 1:
        coarse = np.append(coarse, size - 1)
    return coarse


def _coarse_guess(
    contour, pin, law, load, azimuth, tolerance, max_iterations, max_penetration, window
):
    """Pin offsets of every load from a coarse pass, and the widest contact half-angle [rad].

    Used for a cold start where the springs do not lie on a circle (a worn contour; see
    :func:`_circle_guess` for the others). Every 8th load (and the last) is balanced,
    the others are interpolated (local cubic Lagrange in the load index: ~1e-5 of the
    load on the paper case, an error of the node grid's ripple rather than of the
    interpolation). The coarse loads are solved to ``|F_total - F| <= 1e-3 F`` with
    third-order steps (power law 1.5), and take the step their last evaluation gives as
    well (``polish``): two evaluations leave their penetration ~3e-13 off at most (worn
    paper case), far below the interpolation error. Lighter than a full solve: no
    contact solution is assembled, and the window is sized from the conformal-contact
    estimate of the half-angle (widened to 90 degrees if the contact reaches its edge).
    A long batch starts its coarse pass from a coarser one (recursively).
    """
    full = contour.nodes // 4
    coarse = _coarse_indices(load.size)
    c_load, c_azimuth = load[coarse], azimuth[coarse]
    centre = contour.radius_at(c_azimuth)
    clearance = np.maximum(centre - pin.radius, 1e-12 * pin.radius)
    start = depth0 = None
    if coarse.size >= 64:
        start, widest = _coarse_guess(
            contour,
            pin,
            law,
            c_load,
            c_azimuth,
            tolerance,
            max_iterations,
            max_penetration,
            window,
        )
        width = int(np.ceil(1.05 * widest / contour.dtheta) + 3)
    elif isinstance(law, PowerLaw):
        # conformal contact: a starting point, and the half-angle for the window
        depth0 = _conformal_depth(contour, pin.radius, law, c_load, clearance)
        alpha = float(np.sqrt(2 * depth0 / (clearance + depth0)).max())
        width = window if window is not None else int(np.ceil(1.2 * alpha / contour.dtheta) + 3)
    else:
        width = window if window is not None else full
    width = int(min(max(width, 2), full))
    width = min(-(-width // 4) * 4, full)
    while True:
        win = _Window(contour, c_azimuth, width, law, pin.radius, centre_radius=centre)
        lower, upper = _bracket(win, contour, pin.radius, c_load, max_penetration)
        if start is not None:
            guess = start
        elif depth0 is not None:
            guess = np.clip(clearance + depth0, lower, upper)
        else:
            guess = 0.5 * (lower + upper)
        guess = np.where(c_load > 0, guess, lower)
        # (third-order steps: from the conformal estimate, up to 2x off on a worn contour,
        # a fourth-order one is no better and sometimes worse)
        residual = _PaperResidual(win, law, pin.radius, c_load, tolerance, order=2)
        root = bracketed_newton(
            residual,
            guess,
            lower,
            upper,
            tolerance,
            rtol=_COARSE_RTOL,
            max_iterations=max_iterations,
            curvature=_curvature(law),
            polish=True,
        )
        depth = residual.depth
        contact = depth > 0
        if width >= full or not (contact[:, 0].any() or contact[:, -1].any()):
            break
        width = full
    return _cubic_interpolation(coarse, root.x, load.size), _widest(win.phi, depth, contact)


def _widest(phi: FloatArray, depth: FloatArray, contact: NDArray[np.bool_]) -> float:
    """Largest contact half-angle of all rows [rad], from the few rows that can hold it.

    A row's half-angle lies within a node beyond its outermost node in contact, and the
    rows' node grids are shifted by at most half a node against each other: only rows in
    contact in the two outermost columns on either side can hold the widest contact.
    """
    columns = contact.any(axis=0)
    if not columns.any():
        return 0.0
    k = columns.size
    first = int(np.argmax(columns))
    last = k - 1 - int(np.argmax(columns[::-1]))
    rows = np.flatnonzero(
        contact[:, first]
        | contact[:, min(first + 1, k - 1)]
        | contact[:, last]
        | contact[:, max(last - 1, 0)]
    )
    left, right = _half_angles(phi[rows], depth[rows], contact[rows])
    return float(max(left.max(), right.max()))


def _reach_width(contour, pin, law, centre_radius, along, across) -> int:
    """Window half-width [nodes] holding every node that can touch the pin.

    The pin centre is ``along`` the load line and ``across`` it (None: on the line). The
    penetration of node ``j`` is at most ``u_j . e - (r_j - R_p)``, so only nodes within
    ``arccos(g_min / |e|)`` of the pin's direction can touch, ``g_min`` the smallest
    radial gap. A window of half-width ``W`` holds every node within ``(W - 1/2) dtheta``
    of the load line.
    """
    # the symmetric law's springs lie on the circle through the compression centre
    gap = centre_radius - pin.radius if law.symmetric else contour.radius.min() - pin.radius
    if across is None:
        # on the load line: the widest reach is that of the smallest gap / |e|
        with np.errstate(divide="ignore"):
            ratio = float(np.min(gap / np.abs(along)))
        widest = math.acos(ratio) if ratio < 1.0 else 0.0
    else:
        size = np.hypot(along, across)
        with np.errstate(divide="ignore", invalid="ignore"):
            reach = np.arccos(np.clip(gap / size, -1.0, 1.0))
        reach = np.where(size > gap, reach, 0.0)
        widest = float(np.max(np.abs(np.arctan2(across, along)) + reach))
    return int(np.ceil(widest / contour.dtheta + 0.5)) + 1


def _solve_window(
    win,
    contour,
    pin,
    load,
    azimuth,
    law,
    balance,
    tolerance,
    max_iterations,
    max_penetration,
    guess,
    order=1,
):
    radius_pin = pin.radius
    r_pin2 = radius_pin**2
    lower, upper = _bracket(win, contour, radius_pin, load, max_penetration)
    check_reach(lower, load, azimuth, radius_pin)
    area = win.area
    geometry = win.geometry

    # a cold start (guesses good to ~1e-5 of the load) takes a fourth-order first step,
    # which lands within round-off for (almost) every load: two evaluations, not three
    residual = _PaperResidual(win, law, radius_pin, load, tolerance, order=order)
    if guess is None:
        guess = _initial_guess(win, law, contour, radius_pin, load, lower, upper)
    # no load: the pin just touches (a tolerance-sized contact would be arbitrary)
    guess = np.where(load > 0, guess, lower)
    root = bracketed_newton(
        residual,
        guess,
        lower,
        upper,
        tolerance,
        max_iterations=max_iterations,
        curvature=_curvature(law),
    )
    offset = root.x
    iterations = root.iterations
    _check(root.converged, offset, upper, load, azimuth, root.residual)

    along = offset
    across = None  # paper mode: the pin moves along the load only
    if balance == "equilibrium":
        along, across, extra = _equilibrium(
            win, law, radius_pin, load, along, tolerance, max_iterations, lower, upper
        )
        iterations = iterations + extra
        # final state on the window
        a_col, b_col = along[:, None], across[:, None]
        proj = win.cos * a_col + win.sin * b_col
        cross = win.cos * b_col - win.sin * a_col
        depth = proj - win.gap - cross**2 / (np.sqrt(r_pin2 - cross**2) + radius_pin)
        pressure_w = law.pressure(np.maximum(depth, 0.0))
        normal = _resultant(pressure_w, area, win.cos)
    else:
        # every load's last residual evaluation was at its root: reuse its depth and sum
        depth = residual.depth
        pressure_w = residual.pressure()
        normal = residual.total.copy()
    tangential = _resultant(pressure_w, area, win.sin)

    m = load.size
    pressure = np.zeros((m, contour.nodes))
    pressure.reshape(-1)[geometry.flat] = pressure_w.reshape(-1)
    contact = depth > 0
    left, right = _half_angles(win.phi, depth, contact)
    springs_left, springs_right = _springs(win, contact)
    edge = bool(contact[:, 0].any() or contact[:, -1].any())

    centre_penetration = along - (win.centre_radius - radius_pin)
    eccentricity = along[:, None] * geometry.unit
    if across is not None:
        centre_penetration -= across**2 / (np.sqrt(r_pin2 - across**2) + radius_pin)
        eccentricity += across[:, None] * geometry.unit_perp
    solution = ContactSolution(
        pressure=pressure,
        eccentricity=eccentricity,
        penetration=np.maximum(centre_penetration, 0.0),
        normal_force=normal,
        tangential_force=tangential,
        half_angle_left=left,
        half_angle_right=right,
        springs_left=springs_left,
        springs_right=springs_right,
        iterations=iterations,
        model=law.name,
    )
    return solution, edge, along, across


def _resultant(pressure: FloatArray, area: Any, direction: FloatArray) -> FloatArray:
    """``sum_j p_j A_j direction_j`` per load (one pass)."""
    if isinstance(area, np.ndarray):
        return np.einsum("ij,ij,ij->i", pressure, area, direction)
    return area * _rowdot(pressure, direction)


def _cubic_interpolation(known: NDArray[np.intp], values: FloatArray, size: int) -> FloatArray:
    """Local 4-point Lagrange interpolation of ``values`` given at indices ``known``.

    Evaluated at ``0 .. size-1``; exact at the known indices. Warm starts for the loads
    between solved ones: the error is O(h^4) on a smooth load history, against O(h^2)
    for linear interpolation, which saves Newton steps. The stencils and weights depend
    only on the indices and are cached.
    """
    if known.size < 4:
        return np.interp(np.arange(size), known, values)
    key = (size, known.tobytes())
    cached = _INTERPOLATION_CACHE.get(key)
    if cached is None:
        x = np.arange(size, dtype=float)
        start = np.clip(np.searchsorted(known, x) - 2, 0, known.size - 4)
        stencil = start[:, None] + np.arange(4)
        nodes = known[stencil].astype(float)
        weights = np.ones((size, 4))
        for i in range(4):
            for j in range(4):
                if j != i:
                    weights[:, i] *= (x - nodes[:, j]) / (nodes[:, i] - nodes[:, j])
        cached = (stencil, weights)
        if len(_INTERPOLATION_CACHE) >= 8:
            _INTERPOLATION_CACHE.clear()
        _INTERPOLATION_CACHE[key] = cached
    stencil, weights = cached
    return np.einsum("ij,ij->i", weights, values[stencil])


def check_reach(lower: FloatArray, load: FloatArray, azimuth: FloatArray, pin_radius: float):
    """Raise :class:`ContactError` where a loaded pin cannot reach the bushing.

    The ray geometry needs ``|e| < R_p``: a radial gap ``lower`` [m] as wide as the pin
    (radius ``pin_radius`` [m]) is out of its reach; ``load`` [N], ``azimuth`` [rad].
    """
    out_of_reach = (lower >= 0.999 * pin_radius) & (load > 0)
    if np.any(out_of_reach):
        i = int(np.flatnonzero(out_of_reach)[0])
        raise ContactError(
            f"load: {load[i]:.6g} N at {np.degrees(azimuth[i]):.4g} deg: the bushing is out of "
            f"the pin's reach (radial gap {lower[i]:.3g} m >= pin radius {pin_radius:.3g} m)"
        )


def _check(converged, offset, upper, load, azimuth, residual) -> None:
    if np.all(converged):
        return
    bad = np.flatnonzero(~converged)
    at_wall = bad[np.abs(offset[bad] - upper[bad]) <= 1e-9 * np.abs(upper[bad]) + 1e-15]
    if at_wall.size:
        i = at_wall[0]
        raise ContactError(
            f"load: {load[i]:.6g} N at {np.degrees(azimuth[i]):.4g} deg would push the pin "
            f"through the bushing wall (no balance within the wall thickness)"
        )
    i = bad[0]
    raise ConvergenceError(
        f"contact: load balance did not converge for {bad.size} load(s), e.g. "
        f"{load[i]:.6g} N (residual {residual[i]:.3g} N); raise contact.max_iterations "
        f"or contact.tolerance"
    )


def _half_angles(phi: FloatArray, depth: FloatArray, contact: NDArray[np.bool_]):
    """Contact extent each side of the load line, edges interpolated between nodes [rad].

    ``phi``, ``depth`` and ``contact`` are window arrays (M, 2W+1): node angles from the
    load line, depths, and ``depth > 0``.
    """
    m, k = depth.shape
    first = np.argmax(contact, axis=1)
    last = (k - 1) - np.argmax(contact[:, ::-1], axis=1)
    # flat positions of the last node in contact and the next one out, each side
    base = np.arange(0, m * k, k)
    inside = np.concatenate((last, first))
    outside = np.concatenate((np.minimum(last + 1, k - 1), np.maximum(first - 1, 0)))
    base2 = np.concatenate((base, base))
    inside += base2
    outside += base2
    d_in, d_out = depth.take(inside), depth.take(outside)
    phi_in, phi_out = phi.take(inside), phi.take(outside)
    drop = d_in - d_out
    frac = np.where(drop > 0, d_in / np.maximum(drop, 1e-300), 0.0)
    angle = phi_in + frac * (phi_out - phi_in)
    angle[m:] *= -1.0
    np.maximum(angle, 0.0, out=angle)
    # argmax is 0 in a row without contact, where contact[0] is False
    angle[np.concatenate((~contact.take(inside[m:]),) * 2)] = 0.0
    return angle[:m], angle[m:]


def _springs(win: _Window, contact: NDArray[np.bool_]):
    """Springs in contact counter-clockwise (phi > 0) and clockwise (phi < 0) of the load line.

    Only the centre column can have either sign (``|shift| <= dtheta / 2``); the others
    are counted as bytes (a sum of ``uint8``, exact while a half-window has < 256 nodes).
    """
    w = win.width
    centre = contact[:, w]
    left_centre = centre & win.geometry.left[:, w]
    right_centre = centre & win.geometry.right[:, w]
    if w < 256:
        count = contact.view(np.uint8)
        left = np.einsum("ij->i", count[:, w + 1 :]).astype(np.int64)
        right = np.einsum("ij->i", count[:, :w]).astype(np.int64)
    else:
        left = np.count_nonzero(contact[:, w + 1 :], axis=1).astype(np.int64)
        right = np.count_nonzero(contact[:, :w], axis=1).astype(np.int64)
    return left + left_centre, right + right_centre


def _equilibrium(
    win: _Window,
    law: SpringLaw,
    radius_pin: float,
    load: FloatArray,
    along: FloatArray,
    tolerance: float,
    max_iterations: int,
    lower: FloatArray,
    upper: FloatArray,
):
    """2-D Newton with backtracking on the pin position in the load frame.

    Where the Newton iteration stalls (a singular Jacobian: a single spring in contact
    can only push along its own ray), :func:`_equilibrium_by_direction` takes over.
    """
    r_pin2 = radius_pin**2
    area = win.area
    area_is_array = isinstance(area, np.ndarray)
    across = np.zeros_like(along)
    iterations = np.zeros(load.size, dtype=np.int64)

    def state(a, b, rows):
        cos, sin, gap = win.cos[rows], win.sin[rows], win.gap[rows]
        ar = area[rows] if area_is_array else area
        a_col, b_col = a[:, None], b[:, None]
        cross = cos * b_col - sin * a_col
        root = np.sqrt(r_pin2 - cross**2)
        depth = cos * a_col + sin * b_col - gap - cross**2 / (root + radius_pin)
        penetration = np.maximum(depth, 0.0)
        force = law.pressure(penetration) * ar
        g_n = (force * cos).sum(axis=1) - load[rows]
        g_t = (force * sin).sum(axis=1)
        scale = np.abs(force).sum(axis=1)  # the round-off floor is 8 eps sum|f_j|
        return g_n, g_t, scale, (penetration, cos, sin, cross / root, ar)

    active = np.arange(load.size)
    failed = []
    for _ in range(max_iterations):
        if active.size == 0:
            break
        a, b = along[active], across[active]
        g_n, g_t, scale, (penetration, cos, sin, ratio, ar) = state(a, b, active)
        iterations[active] += 1
        norm = np.hypot(g_n, g_t)
        done = norm <= np.maximum(tolerance, 8 * _EPS * scale)
        k = law.pressure_derivative(penetration) * ar
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
        # a residual that one ulp of the pin position explains (stiff springs; a single
        # spring makes J singular), or a Newton step below that round-off: exact to round-off
        position = _EPS * np.hypot(a, b)
        done |= norm <= position * (np.abs(j11) + np.abs(j12) + np.abs(j21) + np.abs(j22))
        step = np.hypot(step_a, step_b)
        done |= ~bad & (step <= position)
        # backtracking: accept the first fraction that reduces the residual norm
        lam = np.ones_like(a)
        pending = ~done & ~bad
        for _ in range(30):
            if not pending.any():
                break
            rows = active[pending]
            with np.errstate(invalid="ignore", over="ignore"):  # a wild step may leave the pin
                gn2, gt2, _, _ = state(
                    a[pending] + lam[pending] * step_a[pending],
                    b[pending] + lam[pending] * step_b[pending],
                    rows,
                )
            better = np.hypot(gn2, gt2) < norm[pending]
            idx = np.flatnonzero(pending)
            pending[idx[better]] = False
            lam[idx[~better]] *= 0.5
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


def _equilibrium_by_direction(
    win: _Window,
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
    r_pin2 = radius_pin**2
    cos, sin, gap = win.cos[rows], win.sin[rows], win.gap[rows]
    area = win.area[rows] if isinstance(win.area, np.ndarray) else win.area
    target = load[rows]
    m = rows.size
    iterations = np.zeros(m, dtype=np.int64)

    def springs(s, chi, idx):
        c, si = np.cos(chi)[:, None], np.sin(chi)[:, None]
        cs, sn = cos[idx], sin[idx]
        s_col = s[:, None]
        mu = cs * c + sn * si  # cos(theta_j - chi)
        cross = s_col * (cs * si - sn * c)
        root = np.sqrt(r_pin2 - cross**2)
        depth = s_col * mu - gap[idx] - cross**2 / (root + radius_pin)
        penetration = np.maximum(depth, 0.0)
        a = area[idx] if isinstance(area, np.ndarray) else area
        force = law.pressure(penetration) * a
        slope = law.pressure_derivative(penetration) * a * (mu - cross * cross / (s_col * root))
        return force, slope, cs, sn

    def distance(chi, idx, guess):
        """Paper-mode balance along the load for pin direction chi (rows idx)."""

        def residual(s, sub):
            force, slope, cs, _ = springs(s, chi[sub], idx[sub])
            normal = force * cs
            total = target[idx[sub]]
            return normal.sum(1) - total, (slope * cs).sum(1), np.abs(normal).sum(1)

        root = bracketed_newton(
            residual,
            guess,
            lower[rows][idx],
            upper[rows][idx],
            tolerance,
            max_iterations=max_iterations,
        )
        iterations[idx] += root.iterations
        force, _, _, sn = springs(root.x, chi, idx)
        scale = np.abs(force).sum(1)
        return root.x, (force * sn).sum(1), root.converged, scale

    everything = np.arange(m)
    half = np.full(m, np.pi / 3)
    s_lo, t_lo, _, _ = distance(-half, everything, upper[rows].copy())
    s_hi, t_hi, _, _ = distance(half, everything, upper[rows].copy())
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
        s_mid, t_mid, balanced, scale = distance(mid, active, s[active])
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
    return s * np.cos(chi), s * np.sin(chi), iterations
