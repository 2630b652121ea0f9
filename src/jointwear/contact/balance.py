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
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.laws import CallableSpringLaw, PowerLaw, SpringLaw
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ContactError, ConvergenceError
from jointwear.geometry.contour import BushingContour, Pin
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
#: stencils and weights of the coarse-to-fine interpolation, per (size, coarse indices)
_INTERPOLATION_CACHE: dict[tuple[int, bytes], tuple[NDArray[np.intp], FloatArray]] = {}


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
    """Nodes within +-W of each load line, gathered into (M, 2W+1) arrays."""

    def __init__(
        self,
        contour: BushingContour,
        azimuth: FloatArray,
        width: int,
        law: SpringLaw,
        pin_radius: float,
    ) -> None:
        geometry = _geometry(contour.nodes, azimuth, width)
        self.geometry = geometry
        self.width = width
        self.symmetric = bool(law.symmetric)
        self.index, self.phi = geometry.index, geometry.phi
        self.cos, self.sin, self.sin2 = geometry.cos, geometry.sin, geometry.sin2
        self.centre_radius = contour.radius_at(geometry.wrapped)
        if law.symmetric:
            radius = np.broadcast_to(self.centre_radius[:, None], self.phi.shape)
            gap = radius - pin_radius
        else:
            radius = None
            gap = np.take(contour.radius - pin_radius, self.index)
        # r - R_p is exact (Sterbenz); the depth is assembled from small terms
        # so a micrometre penetration is not the difference of two radii
        self.gap = gap
        if law.force_area is not None:
            self.area: Any = law.force_area
        else:
            if radius is None:
                radius = np.take(contour.radius, self.index)
            self.area = radius * (contour.dtheta * contour.axial_length)


class _PaperResidual:
    """Residual of the paper balance for :func:`bracketed_newton`, fused and allocation-free.

    For pin displacement ``s`` along the load the depth of window node ``j`` is
    ``s cos(phi_j) - g_j - s^2 sin^2(phi_j) / (sqrt(R_p^2 - s^2 sin^2(phi_j)) + R_p)``
    (``g_j = r_j - R_p``); the residual is ``sum_j p(depth_j) A_j cos(phi_j) - F`` and
    its derivative ``sum_j p'(depth_j) A_j cos(phi_j) (cos(phi_j) - s sin^2(phi_j) / root)``.

    Speed: every array operation writes into per-thread scratch buffers of at most
    ``_BLOCK`` elements (rows are processed in blocks: fresh temporaries of a few
    hundred kB cost page faults, the ``sys`` time seen in profiles, and blocks stay
    in cache); power laws with exponent 1 or 1.5 (Winkler, NLCP) take a fused path
    (one ``sqrt`` serves force and stiffness); the sums are ``einsum`` contractions
    (no BLAS). The derivative is computed only for loads that the residual shows are
    not converged yet (the last evaluation of a warm-started load is just the
    check). The depth and ``pressure / coefficient`` of every load's last evaluation
    are kept, so the final state is read off instead of recomputed. A call for most
    of the batch evaluates the whole batch (loads already converged are re-evaluated
    at their root, bit for bit) rather than gathering rows.
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
            total, slope = self._blocks(self.offset, None, wanted)
            self.total[:] = total
            if n < self.m:
                total, slope = total[rows], slope[rows]
        else:
            total, slope = self._blocks(s, rows, None)
            self.total[rows] = total
        # every force term is >= 0 (|phi| <= 90 deg in the window): sum|f_j| = total, the
        # scale of the round-off floor 8 eps sum|f_j| of the convergence test
        return total - self.load[rows], slope, total

    def _blocks(self, s, rows, wanted):
        """Evaluate rows ``rows`` (all if None) block by block."""
        n = s.size
        total = np.empty(n)
        slope = np.empty(n)
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
                    np.take(np.broadcast_to(source, self.cos.shape), index, axis=0, out=target)
                load = self.load[index]
                keep = None
                fresh = self.fresh[index]
            total[start:stop], slope[start:stop], computed = self._evaluate(
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
        return total, slope

    def _evaluate(self, s, load, cos, sin2, gap, weight, weight_cos, depth, power, keep, fresh):
        """Totals of a block, and slopes of the rows (``keep``: those asked for) that need one.

        A row needs its slope while it is not converged and it has none yet or its residual
        is above ``refresh`` of its force; otherwise the solver reuses the last slope (a
        chord step: its error factor ``kappa (f'/F) |s - s_slope|`` is ~1e-5 there, so one chord
        step from a residual of 1e-10 F reaches round-off; a cold fine solve thus spends three
        evaluations but computes the slope once).
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
            total = np.einsum("ij,ij->i", power, weight)
        elif self.exponent == 1.0:
            power[...] = pen
            total = np.einsum("ij,ij->i", power, weight)
        else:
            total = np.einsum("ij,ij->i", self.law.pressure(pen), weight)
        slope = np.full(n, np.nan)
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
            return total, slope, None
        if 2 * count >= n:
            # most rows: the slope of the whole block, kept where needed (gathering the rows
            # into fresh arrays costs more than the extra arithmetic, and page faults)
            sel, s_sel, pick = need, np.where(need, s, 1.0), need
        else:
            sel = np.flatnonzero(need)
            s_sel, pick = s[sel], slice(None)
            lat, root, pen, tmp = lat[sel], root[sel], pen[sel], tmp[sel]
            weight, weight_cos = weight[sel], weight_cos[sel]
        # d depth / ds = cos - s sin^2 / root: sum_j k_j cos_j^2 - sum_j k_j (lat_j / root_j) / s,
        # k_j = p'(depth_j) A_j (weight = A cos), the first sum without a pass of its own
        np.divide(lat, root, out=lat)
        np.multiply(lat, weight, out=lat)
        if self.exponent == 1.5:
            along = np.einsum("ij,ij->i", tmp, weight_cos)
            across = np.einsum("ij,ij->i", tmp, lat)
            slope[sel] = (1.5 * (along - across / s_sel))[pick]
        elif self.exponent == 1.0:
            np.greater(pen, 0.0, out=root)  # 1.0 where in contact
            along = np.einsum("ij,ij->i", root, weight_cos)
            across = np.einsum("ij,ij->i", root, lat)
            slope[sel] = (along - across / s_sel)[pick]
        else:
            derivative = self.law.pressure_derivative(pen)
            along = np.einsum("ij,ij->i", derivative, weight_cos)
            across = np.einsum("ij,ij->i", derivative, lat)
            slope[sel] = (along - across / s_sel)[pick]
        return total, slope, need

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
        contact on worn contours). Default: 90 degrees (always sufficient in paper
        mode; 2-D equilibrium may widen it up to 180 degrees).

    Returns
    -------
    ContactSolution
    """
    law = _law_from(law)
    load = np.asarray(load, dtype=float).ravel()
    azimuth = np.broadcast_to(np.asarray(azimuth, dtype=float).ravel(), load.shape).copy()
    if not (np.all(np.isfinite(load)) and np.all(np.isfinite(azimuth))):
        raise ContactError("load: loads and azimuths must be finite")
    if np.any(load < 0):
        raise ContactError("load: must be >= 0 (the azimuth gives the direction)")
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
        solution, edge = _solve_window(
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
        )
        if width >= limit:
            return solution
        # contact need not be contiguous (worn contours): a node beyond a gap in the contact
        # may touch although the window's edge nodes do not; the reach bound finds it
        needed = _reach_width(contour, pin, law, azimuth, solution.eccentricity)
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


def _coarse_guess(contour, pin, law, load, azimuth, tolerance, max_iterations, max_penetration,
                  window):
    """Pin offsets of every load from a coarse pass, and the widest contact half-angle [rad].

    Every 8th load (and the last) is balanced to ``|F_total - F| <= 1e-8 F`` (offsets to
    ~1e-9, far below the ~1e-6 error of interpolating them), the others are interpolated
    (local cubic Lagrange in the load index). Lighter than a full solve: no contact
    solution is assembled, and the window is sized from the conformal-contact estimate of
    the half-angle (widened to 90 degrees if the contact reaches its edge). A long batch
    starts its coarse pass from a coarser one (recursively).
    """
    full = contour.nodes // 4
    coarse = np.unique(np.append(np.arange(0, load.size, 8), load.size - 1))
    c_load, c_azimuth = load[coarse], azimuth[coarse]
    if coarse.size >= 64:
        start, widest = _coarse_guess(
            contour, pin, law, c_load, c_azimuth, tolerance, max_iterations, max_penetration,
            window,
        )
        width = int(np.ceil(1.05 * widest / contour.dtheta) + 3)
    else:
        start = None
        if window is not None:
            width = window
        else:
            alpha = _conformal_half_angle(contour, pin.radius, law, c_load, c_azimuth)
            width = full if alpha is None else int(np.ceil(1.2 * alpha / contour.dtheta) + 3)
    width = int(min(max(width, 2), full))
    width = min(-(-width // 4) * 4, full)
    while True:
        win = _Window(contour, c_azimuth, width, law, pin.radius)
        lower = _lower_bound(win, contour, pin.radius, c_load)
        upper = np.full(lower.shape, 0.999 * pin.radius)
        if max_penetration is not None:
            upper = np.minimum(upper, win.centre_radius - pin.radius + max_penetration)
        upper = np.maximum(upper, lower)
        guess = start
        if guess is None:
            guess = _initial_guess(win, law, contour, pin.radius, c_load, lower, upper)
        guess = np.where(c_load > 0, guess, lower)
        residual = _PaperResidual(win, law, pin.radius, c_load, tolerance, rtol=1e-8)
        root = bracketed_newton(
            residual,
            guess,
            lower,
            upper,
            tolerance,
            rtol=1e-8,
            max_iterations=max_iterations,
            curvature=_curvature(law),
        )
        depth = residual.depth
        contact = depth > 0
        if width >= full or not (contact[:, 0].any() or contact[:, -1].any()):
            break
        width = full
    left, right = _half_angles(win, depth, contact)
    widest = float(max(left.max(), right.max()))
    return _cubic_interpolation(coarse, root.x, load.size), widest


def _conformal_half_angle(contour, pin_radius, law, load, azimuth):
    """Largest contact half-angle of the conformal-contact estimate [rad] (power laws)."""
    if not isinstance(law, PowerLaw):
        return None
    clearance = np.maximum(contour.radius_at(np.mod(azimuth, 2 * np.pi)) - pin_radius,
                           1e-12 * pin_radius)
    delta = _conformal_depth(contour, pin_radius, law, load, clearance)
    return float(np.sqrt(2 * delta / (clearance + delta)).max())


def _reach_width(contour, pin, law, azimuth, eccentricity) -> int:
    """Window half-width [nodes] holding every node that can touch the pin at ``eccentricity``.

    The penetration of node ``j`` is at most ``u_j . e - (r_j - R_p)``, so only nodes
    within ``arccos(g_min / |e|)`` of the pin's direction can touch, ``g_min`` the
    smallest radial gap. A window of half-width ``W`` holds every node within
    ``(W - 1/2) dtheta`` of the load line.
    """
    if law.symmetric:  # springs on the circle through the compression centre
        gap = contour.radius_at(np.mod(azimuth, 2 * np.pi)) - pin.radius
    else:
        gap = contour.radius.min() - pin.radius
    size = np.hypot(eccentricity[:, 0], eccentricity[:, 1])
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = np.arccos(np.clip(gap / size, -1.0, 1.0))
    reach = np.where(size > gap, reach, 0.0)
    direction = np.arctan2(eccentricity[:, 1], eccentricity[:, 0])
    off = np.abs(np.angle(np.exp(1j * (direction - azimuth))))
    return int(np.ceil(np.max(off + reach) / contour.dtheta + 0.5)) + 1


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
):
    radius_pin = pin.radius
    r_pin2 = radius_pin**2
    lower = _lower_bound(win, contour, radius_pin, load)
    upper = np.full(lower.shape, 0.999 * radius_pin)
    if max_penetration is not None:
        upper = np.minimum(upper, win.centre_radius - radius_pin + max_penetration)
    # the ray geometry needs |e| < R_p: a radial gap as wide as the pin is out of its reach
    out_of_reach = (lower >= 0.999 * radius_pin) & (load > 0)
    if np.any(out_of_reach):
        i = int(np.flatnonzero(out_of_reach)[0])
        raise ContactError(
            f"load: {load[i]:.6g} N at {np.degrees(azimuth[i]):.4g} deg: the bushing is out of "
            f"the pin's reach (radial gap {lower[i]:.3g} m >= pin radius {radius_pin:.3g} m)"
        )
    upper = np.maximum(upper, lower)
    area = win.area
    geometry = win.geometry

    residual = _PaperResidual(win, law, radius_pin, load, tolerance)
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
    across = np.zeros_like(offset)
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
    left, right = _half_angles(win, depth, contact)
    springs_left, springs_right = _springs(win, contact)
    edge = bool(contact[:, 0].any() or contact[:, -1].any())

    eccentricity = along[:, None] * geometry.unit + across[:, None] * geometry.unit_perp
    centre_penetration = (
        along
        - (win.centre_radius - radius_pin)
        - across**2 / (np.sqrt(r_pin2 - across**2) + radius_pin)
    )
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
    return solution, edge


def _resultant(pressure: FloatArray, area: Any, direction: FloatArray) -> FloatArray:
    """``sum_j p_j A_j direction_j`` per load (an einsum: one pass, no BLAS)."""
    if isinstance(area, np.ndarray):
        return np.einsum("ij,ij,ij->i", pressure, area, direction)
    return area * np.einsum("ij,ij->i", pressure, direction)


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


def _half_angles(win: _Window, depth: FloatArray, contact: NDArray[np.bool_]):
    """Contact extent each side of the load line, edges interpolated between nodes [rad]."""
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
    phi_in, phi_out = win.phi.take(inside), win.phi.take(outside)
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

        root = bracketed_newton(residual, guess, lower[rows][idx], upper[rows][idx], tolerance,
                                max_iterations=max_iterations)
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
