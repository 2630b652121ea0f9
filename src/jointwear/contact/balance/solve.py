"""The batched load balance: windows, start, bracketed Newton, the contact solution."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.balance.equilibrium import solve_equilibrium
from jointwear.contact.balance.guesses import (
    circle_guess,
    coarse_guess,
    conformal_guess,
    step_curvature,
)
from jointwear.contact.balance.residual import PaperResidual
from jointwear.contact.balance.window import (
    PIN_REACH,
    Window,
    bracket,
    half_angles,
    reach_width,
    resultant,
    springs_in_contact,
)
from jointwear.contact.laws import CallableSpringLaw, SpringLaw
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ContactError, ConvergenceError
from jointwear.geometry.contour import BushingContour, Pin, pin_penetration
from jointwear.solvers import bracketed_newton

__all__ = ["check_converged", "check_reach", "checked_loads", "solve_contact"]

FloatArray = NDArray[np.float64]


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
    if load.size:
        # NaN propagates into the extremes: two reductions check every load
        low, high = float(load.min()), float(load.max())
        finite = math.isfinite(low) and math.isfinite(high)
        if not (finite and np.isfinite(azimuth).all()):
            raise ContactError("load: loads and azimuths must be finite")
        if low < 0:
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
    """Pressure on every bushing node for many loads on one contour (a
    :class:`ContactSolution`).

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
        Spring law (:func:`jointwear.contact.contact_law`) or a callable
        ``pressure(penetration)`` [m -> Pa]; Hertz is :func:`jointwear.contact.hertz.solve`.
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
        Guesses of the pin displacement along the load line [m] (warm start).
    window : int, optional
        Half-width of the node window in nodes; widened automatically if the
        contact reaches its edge or a node beyond it could touch (non-contiguous
        contact on worn contours). Default: with ``initial_offset`` 90 degrees (always
        sufficient in paper mode; 2-D equilibrium may widen it up to 180 degrees),
        else sized from the cold start's estimate of the contact.
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
    guess, width = _start(
        contour, pin, law, load, azimuth, tolerance, max_iterations, max_penetration,
        initial_offset, window,
    )  # fmt: skip
    while True:
        win = Window(contour, azimuth, width, law, pin.radius)
        solution, edge, along, across = _solve_window(
            win, contour, pin, load, azimuth, law, balance, tolerance, max_iterations,
            max_penetration, guess, order=1 if initial_offset is not None else 3,
        )  # fmt: skip
        if width >= limit:
            return solution
        # contact need not be contiguous (worn contours): a node beyond a gap in the contact
        # may touch although the window's edge nodes do not; the reach bound finds it
        needed = reach_width(contour, pin, law, win.centre_radius, along, across)
        if not edge and needed <= width:
            return solution
        width = int(min(max(needed, width + 1), limit))


def _start(
    contour, pin, law, load, azimuth, tolerance, max_iterations, max_penetration,
    initial_offset, window,
):  # fmt: skip
    """Starting offsets [m] (None: :func:`conformal_guess`'s) and the window half-width
    [nodes], a whole multiple of 4 (the cached window geometry is reused while the contact
    width drifts from one solve to the next)."""
    full = contour.nodes // 4
    if initial_offset is not None:
        guess = np.asarray(initial_offset, dtype=float).ravel()
        width = full if window is None else int(min(max(window, 2), full))
    elif (circle := circle_guess(contour, pin, law, load, azimuth)) is not None:
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
        guess, widest = coarse_guess(
            contour, pin, law, load, azimuth, tolerance, max_iterations, max_penetration, window
        )
        width = int(min(full, np.ceil(1.05 * widest / contour.dtheta) + 3))
    else:
        guess = None
        width = full if window is None else int(min(max(window, 2), full))
    return guess, min(-(-width // 4) * 4, full)


def _solve_window(
    win, contour, pin, load, azimuth, law, balance, tolerance, max_iterations,
    max_penetration, guess, order=1,
):  # fmt: skip
    """The balance on windows of half-width ``win.width``: the solution, whether contact
    reaches a window's edge, and the pin position along and across the load lines [m]."""
    radius_pin = pin.radius
    lower, upper = bracket(win, contour, radius_pin, load, max_penetration)
    check_reach(lower, load, azimuth, radius_pin)
    # a cold start (guesses good to ~1e-5 of the load) takes a fourth-order first step,
    # which lands within round-off for (almost) every load: two evaluations, not three
    residual = PaperResidual(win, law, radius_pin, load, tolerance, order=order)
    if guess is None:
        guess = conformal_guess(win, law, contour, radius_pin, load, lower, upper)
    # no load: the pin just touches (a tolerance-sized contact would be arbitrary)
    guess = np.where(load > 0, guess, lower)
    root = bracketed_newton(
        residual,
        guess,
        lower,
        upper,
        tolerance,
        max_iterations=max_iterations,
        curvature=step_curvature(law),
    )
    check_converged(root.converged, root.x, upper, load, azimuth, root.residual)
    along, across, iterations = root.x, None, root.iterations  # paper: along the load only
    if balance == "equilibrium":
        along, across, extra = solve_equilibrium(
            win, law, radius_pin, load, along, tolerance, max_iterations, lower, upper
        )
        iterations = iterations + extra
        # final state on the window
        a_col, b_col = along[:, None], across[:, None]
        proj = win.cos * a_col + win.sin * b_col
        cross = win.cos * b_col - win.sin * a_col
        depth = pin_penetration(proj, cross, win.gap, radius_pin)
        pressure_w = law.pressure(np.maximum(depth, 0.0))
        normal = resultant(pressure_w, win.area, win.cos)
    else:
        # every load's last residual evaluation was at its root: reuse its depth and sum
        depth = residual.depth
        pressure_w = residual.pressure()
        normal = residual.total.copy()
    solution, edge = _solution(win, contour, radius_pin, law, depth, pressure_w, normal,
                               (along, across), iterations)  # fmt: skip
    return solution, edge, along, across


def _solution(win, contour, radius_pin, law, depth, pressure_w, normal, position, iterations):
    """The :class:`ContactSolution` of a balanced window state (depths [m], pressures [Pa],
    normal resultants [N], pin position along and across [m]), and whether contact reaches
    a window's edge."""
    along, across = position
    geometry = win.geometry
    tangential = resultant(pressure_w, win.area, win.sin)
    pressure = np.zeros((along.size, contour.nodes))
    pressure.reshape(-1)[geometry.flat] = pressure_w.reshape(-1)
    contact = depth > 0
    left, right = half_angles(win.phi, depth, contact)
    springs_left, springs_right = springs_in_contact(win, contact)
    edge = bool(contact[:, 0].any() or contact[:, -1].any())
    lateral = 0.0 if across is None else across
    centre_penetration = pin_penetration(along, lateral, win.centre_radius - radius_pin, radius_pin)
    eccentricity = along[:, None] * geometry.unit
    if across is not None:
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
    return solution, edge


def check_reach(lower: FloatArray, load: FloatArray, azimuth: FloatArray, pin_radius: float):
    """Raise :class:`ContactError` where a loaded pin cannot reach the bushing.

    The ray geometry needs ``|e| < R_p``: a radial gap ``lower`` [m] as wide as the pin
    (:data:`PIN_REACH` of its radius ``pin_radius`` [m]) is out of its reach; ``load`` [N],
    ``azimuth`` [rad].
    """
    if not np.any(lower >= PIN_REACH * pin_radius):
        return
    out_of_reach = (lower >= PIN_REACH * pin_radius) & (load > 0)
    if np.any(out_of_reach):
        i = int(np.flatnonzero(out_of_reach)[0])
        raise ContactError(
            f"load: {load[i]:.6g} N at {np.degrees(azimuth[i]):.4g} deg: the bushing is out of "
            f"the pin's reach (radial gap {lower[i]:.3g} m >= pin radius {pin_radius:.3g} m)"
        )


def check_converged(
    converged: NDArray[np.bool_],
    offset: FloatArray,
    upper: FloatArray,
    load: FloatArray,
    azimuth: FloatArray,
    residual: FloatArray,
) -> None:
    """Raise where a load's balance did not converge.

    :class:`ContactError` where the offset [m] stopped at the bracket's ``upper`` end [m]
    (the load [N] at azimuth [rad] would push the pin through the wall), else
    :class:`ConvergenceError` naming the residual [N] and the settings to raise.
    """
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
