"""Starting points of the balance: conformal estimate, node-free circle, coarse pass."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.polynomial import chebyshev
from numpy.typing import NDArray

from jointwear.contact.balance.residual import PaperResidual
from jointwear.contact.balance.window import Window, bracket, widest_half_angle
from jointwear.contact.laws import PowerLaw, SpringLaw
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.solvers import bracketed_newton

__all__ = ["circle_guess", "coarse_guess", "conformal_depth", "conformal_guess", "step_curvature"]

FloatArray = NDArray[np.float64]


#: the coarse pass solves every 8th load, to |F_total - F| <= 1e-3 F (then one more,
#: unevaluated step: see coarse_guess)
_COARSE_STRIDE = 8


_COARSE_RTOL = 1e-3


#: stencils and weights of the coarse-to-fine interpolation, per (size, coarse indices)
_INTERPOLATION_CACHE: dict[tuple[int, bytes], tuple[NDArray[np.intp], FloatArray]] = {}


def conformal_guess(
    win: Window,
    law: SpringLaw,
    contour: BushingContour,
    pin_radius: float,
    load: FloatArray,
    lower: FloatArray,
    upper: FloatArray,
) -> FloatArray:
    """Pin displacement along each load line estimated from conformal contact [m].

    A cold start's guess (:func:`conformal_depth` beyond the clearance), within the
    bracket; the bracket's middle for a law that is not a power law.

    Parameters
    ----------
    win : Window
        The loads' windows (their radius on the load lines).
    law : SpringLaw
        Spring law.
    contour : BushingContour
        The contour.
    pin_radius : float
        ``R_p`` [m].
    load : ndarray, shape (M,)
        Joint loads [N].
    lower, upper : ndarray, shape (M,)
        Bracket of the offset [m].
    """
    if not isinstance(law, PowerLaw):
        return 0.5 * (lower + upper)
    clearance = np.maximum(win.centre_radius - pin_radius, 1e-12 * pin_radius)
    delta = conformal_depth(contour, pin_radius, law, load, clearance)
    return np.clip(clearance + delta, lower, upper)


def conformal_depth(
    contour: BushingContour, pin_radius: float, law: PowerLaw, load: Any, clearance: Any
) -> Any:
    """Penetration at the compression centre from a conformal-contact model [m].

    A power law ``p = k delta^n`` on a circle of clearance ``c``, small angles: the
    depth is ``delta_0 (1 - phi^2 / alpha^2)`` with ``alpha^2 = 2 delta_0 / (c + delta_0)``,
    so ``F = (A k / dtheta) B(n) delta_0^n alpha``, ``B(n) = sqrt(pi) Gamma(n+1) /
    Gamma(n+3/2)``. Two fixed-point passes for ``delta_0``; only a starting point for Newton
    (the half-angle ``alpha`` came out 3 % below the solved one for the paper's NLCP case).

    ``load`` [N] and ``clearance`` [m] are floats or arrays of one shape; ``pin_radius``
    is ``R_p`` [m].
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


def step_curvature(law: SpringLaw) -> float:
    """``kappa = (m - 1) / m`` [-] of the total force ``F ~ u^m`` for the Chebyshev step.

    A power law ``p ~ delta^n`` in conformal contact (small angles) carries
    ``F ~ delta_0^n alpha`` with the half-angle ``alpha ~ sqrt(delta_0)``: ``m = n + 1/2``.
    Wider contacts and worn contours deviate (kappa 0.4-0.6 measured for the paper's
    NLCP case against 0.5 here); the correction only needs to be roughly right, as it
    shrinks Newton's quadratic error term by the relative error of kappa.
    """
    if isinstance(law, PowerLaw) and law.exponent > 0.5:
        return (law.exponent - 0.5) / (law.exponent + 0.5)
    return 0.0


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


def circle_guess(
    contour: BushingContour,
    pin: Pin,
    law: SpringLaw,
    load: FloatArray,
    azimuth: FloatArray,
) -> tuple[FloatArray, float] | None:
    """Pin offsets [m] from the node-free contact of a circle, and the widest half-angle [rad].

    ``load`` [N] and ``azimuth`` [rad] are the loads' magnitudes and directions.

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
        r = contour.radius_at(azimuth)  # (it takes the azimuths modulo 2 pi)
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
    start = delta = conformal_depth(contour, rp, law, load, clearance)
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


def _coarse_indices(size: int) -> NDArray[np.intp]:
    """Every ``_COARSE_STRIDE``-th of ``size`` loads, and the last one."""
    coarse = np.arange(0, size, _COARSE_STRIDE)
    if coarse[-1] != size - 1:
        coarse = np.append(coarse, size - 1)
    return coarse


def coarse_guess(
    contour: BushingContour,
    pin: Pin,
    law: SpringLaw,
    load: FloatArray,
    azimuth: FloatArray,
    tolerance: float,
    max_iterations: int,
    max_penetration: float | None,
    window: int | None,
) -> tuple[FloatArray, float]:
    """Pin offsets of every load from a coarse pass [m], and the widest half-angle [rad].

    Used for a cold start where the springs do not lie on a circle (a worn contour; see
    :func:`circle_guess` for the others). Every 8th load (and the last) is balanced,
    the others are interpolated (local cubic Lagrange in the load index: ~1e-5 of the
    load on the paper case, an error of the node grid's ripple rather than of the
    interpolation). The coarse loads are solved to ``|F_total - F| <= 1e-3 F`` with
    third-order steps (power law 1.5), and take the step their last evaluation gives as
    well (``polish``): two evaluations leave their penetration ~3e-13 off at most (worn
    paper case), far below the interpolation error. Lighter than a full solve: no
    contact solution is assembled, and the window is sized from the conformal-contact
    estimate of the half-angle (widened to 90 degrees if the contact reaches its edge).
    A long batch starts its coarse pass from a coarser one (recursively).

    ``load`` [N], ``azimuth`` [rad], ``tolerance`` [N], ``max_iterations``,
    ``max_penetration`` [m] and ``window`` [nodes] are those of
    :func:`jointwear.contact.balance.solve_contact`.
    """
    full = contour.nodes // 4
    coarse = _coarse_indices(load.size)
    c_load, c_azimuth = load[coarse], azimuth[coarse]
    centre = contour.radius_at(c_azimuth)
    clearance = np.maximum(centre - pin.radius, 1e-12 * pin.radius)
    start = depth0 = None
    if coarse.size >= 64:
        start, widest = coarse_guess(
            contour, pin, law, c_load, c_azimuth, tolerance, max_iterations,
            max_penetration, window,
        )  # fmt: skip
        width = int(np.ceil(1.05 * widest / contour.dtheta) + 3)
    elif isinstance(law, PowerLaw):
        # conformal contact: a starting point, and the half-angle for the window
        depth0 = conformal_depth(contour, pin.radius, law, c_load, clearance)
        alpha = float(np.sqrt(2 * depth0 / (clearance + depth0)).max())
        width = window if window is not None else int(np.ceil(1.2 * alpha / contour.dtheta) + 3)
    else:
        width = window if window is not None else full
    width = int(min(max(width, 2), full))
    width = min(-(-width // 4) * 4, full)
    while True:
        win = Window(contour, c_azimuth, width, law, pin.radius, centre_radius=centre)
        lower, upper = bracket(win, contour, pin.radius, c_load, max_penetration)
        if start is not None:
            guess = start
        elif depth0 is not None:
            guess = np.clip(clearance + depth0, lower, upper)
        else:
            guess = 0.5 * (lower + upper)
        offset, depth = _coarse_balance(win, law, pin, c_load, guess, lower, upper, tolerance,
                                        max_iterations)  # fmt: skip
        contact = depth > 0
        if width >= full or not (contact[:, 0].any() or contact[:, -1].any()):
            break
        width = full
    widest = widest_half_angle(win.phi, depth, contact)
    return _cubic_interpolation(coarse, offset, load.size), widest


def _coarse_balance(win, law, pin, load, guess, lower, upper, tolerance, max_iterations):
    """The coarse loads balanced to :data:`_COARSE_RTOL`: offsets [m] and window depths [m]."""
    guess = np.where(load > 0, guess, lower)
    # (third-order steps: from the conformal estimate, up to 2x off on a worn contour,
    # a fourth-order one is no better and sometimes worse)
    residual = PaperResidual(win, law, pin.radius, load, tolerance, order=2)
    root = bracketed_newton(
        residual,
        guess,
        lower,
        upper,
        tolerance,
        rtol=_COARSE_RTOL,
        max_iterations=max_iterations,
        curvature=step_curvature(law),
        polish=True,
    )
    return root.x, residual.depth


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
