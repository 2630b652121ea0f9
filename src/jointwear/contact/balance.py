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

from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.laws import CallableSpringLaw, SpringLaw
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ContactError, ConvergenceError
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.solvers import bracketed_newton

__all__ = ["solve_contact"]

FloatArray = NDArray[np.float64]
_EPS = np.finfo(float).eps


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
        n, dtheta = contour.nodes, contour.dtheta
        self.width = width
        wrapped = np.mod(azimuth, 2 * np.pi)
        centre = np.rint(wrapped / dtheta).astype(np.int64)
        offsets = np.arange(-width, width + 1)
        shift = centre * dtheta - wrapped
        self.index = (centre[:, None] + offsets) % n
        self.phi = offsets * dtheta + shift[:, None]
        # angle addition: trig on (M,) and (2W+1,) vectors instead of the (M, 2W+1) block
        cos_o, sin_o = np.cos(offsets * dtheta), np.sin(offsets * dtheta)
        cos_s, sin_s = np.cos(shift)[:, None], np.sin(shift)[:, None]
        self.cos = cos_o * cos_s - sin_o * sin_s
        self.sin = sin_o * cos_s + cos_o * sin_s
        self.sin2 = self.sin**2
        self.centre_radius = contour.radius_at(wrapped)
        if law.symmetric:
            self.radius = np.broadcast_to(self.centre_radius[:, None], self.phi.shape)
        else:
            self.radius = contour.radius[self.index]
        # r - R_p is exact (Sterbenz); the depth is assembled from small terms
        # so a micrometre penetration is not the difference of two radii
        self.gap = self.radius - pin_radius
        if law.force_area is not None:
            self.area: Any = law.force_area
        else:
            self.area = self.radius * (dtheta * contour.axial_length)


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
        contact reaches its edge. Default: 90 degrees (always sufficient).

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
    if initial_offset is not None:
        guess = np.asarray(initial_offset, dtype=float).ravel()
        width = full if window is None else int(min(max(window, 2), full))
    elif load.size >= 64:
        # warm start from neighbours: solve every 8th load (recursively, so a long
        # batch is solved coarse-to-fine), interpolate the rest, and size the node
        # window from the widest coarse contact
        coarse = np.arange(0, load.size, 8)
        rough = solve_contact(
            contour,
            pin,
            load[coarse],
            azimuth[coarse],
            law,
            balance="paper",
            tolerance=tolerance,
            max_iterations=max_iterations,
            max_penetration=max_penetration,
            window=window,
        )
        along = np.einsum(
            "ij,ij->i",
            rough.eccentricity,
            np.stack([np.cos(azimuth[coarse]), np.sin(azimuth[coarse])], axis=1),
        )
        guess = np.interp(np.arange(load.size), coarse, along)
        widest = max(rough.half_angle_left.max(), rough.half_angle_right.max())
        width = int(min(full, np.ceil(1.25 * widest / contour.dtheta) + 3))
    else:
        guess = None
        width = full if window is None else int(min(max(window, 2), full))
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
        if not edge or width >= full:
            return solution
        width = min(2 * width, full)


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
    lower = win.gap.min(axis=1)
    limit = 0.999 * radius_pin
    if max_penetration is not None:
        limit = np.minimum(limit, win.centre_radius - radius_pin + max_penetration)
    upper = np.broadcast_to(limit, lower.shape).astype(float)
    upper = np.maximum(upper, lower)
    area = win.area
    area_is_array = isinstance(area, np.ndarray)

    everything = load.size

    def residual(s: FloatArray, rows: NDArray[np.intp]):
        if rows.size == everything:  # no gather while the whole batch is active
            cos, sin2, gap, a = win.cos, win.sin2, win.gap, area
        else:
            cos, sin2, gap = win.cos[rows], win.sin2[rows], win.gap[rows]
            a = area[rows] if area_is_array else area
        s_col = s[:, None]
        lateral2 = s_col**2 * sin2
        root = np.sqrt(r_pin2 - lateral2)
        depth = s_col * cos - gap - lateral2 / (root + radius_pin)
        penetration = np.maximum(depth, 0.0)
        force = law.pressure(penetration) * a * cos
        stiffness = law.pressure_derivative(penetration) * a * cos * (cos - s_col * sin2 / root)
        total = force.sum(axis=1)
        return total - load[rows], stiffness.sum(axis=1), np.abs(force).sum(axis=1) + load[rows]

    if guess is None:
        guess = 0.5 * (lower + upper)
    root = bracketed_newton(residual, guess, lower, upper, tolerance, max_iterations=max_iterations)
    offset = root.x
    iterations = root.iterations
    _check(root.converged, offset, upper, load, azimuth, root.residual)

    along = offset
    across = np.zeros_like(offset)
    if balance == "equilibrium":
        along, across, extra = _equilibrium(
            win, law, radius_pin, load, along, tolerance, max_iterations
        )
        iterations = iterations + extra

    # final state on the window
    a_col, b_col = along[:, None], across[:, None]
    proj = win.cos * a_col + win.sin * b_col
    cross = win.cos * b_col - win.sin * a_col
    depth = proj - win.gap - cross**2 / (np.sqrt(r_pin2 - cross**2) + radius_pin)
    penetration = np.maximum(depth, 0.0)
    pressure_w = law.pressure(penetration)
    force = pressure_w * area
    normal = (force * win.cos).sum(axis=1)
    tangential = (force * win.sin).sum(axis=1)

    m = load.size
    pressure = np.zeros((m, contour.nodes))
    pressure[np.arange(m)[:, None], win.index] = pressure_w
    contact = depth > 0
    left, right = _half_angles(win, depth, contact)
    springs_left = (contact & (win.phi > 0)).sum(axis=1)
    springs_right = (contact & (win.phi < 0)).sum(axis=1)
    edge = bool(np.any(contact[:, 0]) or np.any(contact[:, -1]))

    w = np.stack([np.cos(azimuth), np.sin(azimuth)], axis=1)
    w_perp = np.stack([-np.sin(azimuth), np.cos(azimuth)], axis=1)
    eccentricity = along[:, None] * w + across[:, None] * w_perp
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
    rows = np.arange(m)
    any_contact = contact.any(axis=1)
    last = k - 1 - np.argmax(contact[:, ::-1], axis=1)
    first = np.argmax(contact, axis=1)

    def edge(inside, outside):
        d_in, d_out = depth[rows, inside], depth[rows, outside]
        frac = np.where(d_in - d_out > 0, d_in / np.maximum(d_in - d_out, 1e-300), 0.0)
        return win.phi[rows, inside] + frac * (win.phi[rows, outside] - win.phi[rows, inside])

    left = edge(last, np.minimum(last + 1, k - 1))
    right = edge(first, np.maximum(first - 1, 0))
    left = np.where(any_contact, np.maximum(left, 0.0), 0.0)
    right = np.where(any_contact, np.maximum(-right, 0.0), 0.0)
    return left, right


def _equilibrium(
    win: _Window,
    law: SpringLaw,
    radius_pin: float,
    load: FloatArray,
    along: FloatArray,
    tolerance: float,
    max_iterations: int,
):
    """2-D Newton with backtracking on the pin position in the load frame."""
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
        scale = np.abs(force).sum(axis=1) + load[rows]
        return g_n, g_t, scale, (penetration, cos, sin, cross / root, ar)

    active = np.arange(load.size)
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
        # backtracking: accept the first fraction that reduces the residual norm
        lam = np.ones_like(a)
        pending = ~done & ~bad
        for _ in range(30):
            if not pending.any():
                break
            rows = active[pending]
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
        stalled = bad | (lam < 1e-8)
        if np.any(stalled & ~done):
            worst = np.flatnonzero(stalled & ~done)[0]
            raise ConvergenceError(
                f"contact: 2-D equilibrium stalled for load {load[active[worst]]:.6g} N "
                f"(residual {norm[worst]:.3g} N)"
            )
        active = active[~done]
    if active.size:
        raise ConvergenceError(
            f"contact: 2-D equilibrium did not converge for {active.size} load(s) in "
            f"{max_iterations} iterations"
        )
    return along, across, iterations
