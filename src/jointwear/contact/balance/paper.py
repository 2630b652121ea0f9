"""The paper's load balance, eqs. (5) and (7), stated plainly.

For a load ``F`` pressing the pin towards the azimuth ``psi``, the paper moves the pin
centre along the load line, ``e = s w`` (``w`` the unit vector of ``psi``), until the
springs' resultant along the load carries it:

.. math::
    f(s) = \\sum_j p(\\delta_j(s)) \\, A_j \\cos\\beta_j - F = 0,
    \\qquad \\beta_j = \\theta_j - \\psi,

with ``p`` the spring law (Winkler ``k delta``, eq. 5; NLCP ``K delta^n / A``, eq. 7),
``A_j`` the spring area and ``delta_j`` the penetration of node ``j`` along its ray
(:func:`jointwear.geometry.contour.pin_penetration` with ``along = s cos(beta_j)``,
``across = s sin(beta_j)``). Only nodes within 90 degrees of the load line can touch
(the pin is smaller than the bushing). ``f`` grows with ``s``; its slope is

.. math::
    f'(s) = \\sum_j p'(\\delta_j) A_j \\cos\\beta_j \\, \\delta_j'(s), \\qquad
    \\delta_j' = \\cos\\beta_j - \\frac{s \\sin^2\\beta_j}{\\sqrt{R_p^2 - s^2 \\sin^2\\beta_j}}.

This module solves exactly that, on every node, with :func:`bracketed_newton`
(:func:`paper_balance`), and gives the pressure of a pin position
(:func:`paper_pressure`): the statement the fast solvers are held to (to 1e-9 and
tighter, in the tests). :func:`jointwear.contact.balance.solve_contact` solves the same
equation on node windows with fused NumPy arithmetic and warm starts (:mod:`.window`,
:mod:`.residual`, :mod:`.guesses`), and :func:`jointwear.contact.kernel.revolution_wear`
in one compiled loop per load.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.balance.window import PIN_REACH
from jointwear.contact.laws import SpringLaw
from jointwear.geometry.angles import wrap_angle
from jointwear.geometry.contour import BushingContour, Pin, pin_penetration
from jointwear.solvers import bracketed_newton

__all__ = ["paper_balance", "paper_pressure", "paper_residual"]

FloatArray = NDArray[np.float64]


def paper_residual(
    s: FloatArray,
    beta: FloatArray,
    gap: FloatArray,
    area: FloatArray,
    law: SpringLaw,
    pin_radius: float,
    load: FloatArray,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """``f(s)``, ``f'(s)`` and ``sum_j |f_j|`` of eqs. (5)/(7) for a batch of loads.

    Parameters
    ----------
    s : ndarray, shape (M,)
        Pin displacement along each load line [m].
    beta : ndarray, shape (M, N)
        Node angles from the load line [rad].
    gap : ndarray, shape (M, N) or (N,)
        Radial gap ``r_j - R_p`` of each node [m].
    area : ndarray or float
        Spring area ``A_j`` [m^2], 0 for nodes that cannot touch.
    law : SpringLaw
        Spring law ``p(delta)`` [m -> Pa].
    pin_radius : float
        Pin radius ``R_p`` [m].
    load : ndarray, shape (M,)
        Joint load ``F`` [N].
    """
    s_col = s[:, None]
    cos, sin = np.cos(beta), np.sin(beta)
    depth = np.maximum(pin_penetration(s_col * cos, s_col * sin, gap, pin_radius), 0.0)
    force = law.pressure(depth) * area * cos
    along = cos - s_col * sin**2 / np.sqrt(pin_radius**2 - (s_col * sin) ** 2)
    slope = law.pressure_derivative(depth) * area * cos * along
    return force.sum(axis=1) - load, slope.sum(axis=1), np.abs(force).sum(axis=1)


def paper_balance(
    contour: BushingContour,
    pin: Pin,
    load: ArrayLike,
    azimuth: ArrayLike,
    law: SpringLaw,
    tolerance: float = 1e-12,
    max_iterations: int = 200,
) -> FloatArray:
    """Pin displacement along each load line that balances eqs. (5)/(7) [m].

    Every node, no windows, no start guesses (bisection from the bracket's middle):
    slow, and the reference of the fast solvers. The symmetric law's springs lie on
    the circle through the compression centre.

    Parameters
    ----------
    contour : BushingContour
        Bushing contour.
    pin : Pin
        The pin.
    load : array_like, shape (M,)
        Joint loads [N], > 0.
    azimuth : array_like, shape (M,)
        Load directions in the bushing frame [rad].
    law : SpringLaw
        Spring law.
    tolerance : float
        Force tolerance [N].
    max_iterations : int
        Residual evaluations allowed per load.
    """
    load = np.asarray(load, dtype=float).ravel()
    azimuth = np.asarray(azimuth, dtype=float).ravel()
    beta, gap, area = _nodes(contour, pin, azimuth, law)
    lower = gap.min(axis=1)
    upper = np.full(load.shape, PIN_REACH * pin.radius)

    def residual(s: FloatArray, rows: NDArray[np.intp]):
        return paper_residual(s, beta[rows], gap[rows], area[rows], law, pin.radius, load[rows])

    root = bracketed_newton(
        residual, 0.5 * (lower + upper), lower, upper, tolerance, max_iterations=max_iterations
    )
    return root.x


def paper_pressure(
    contour: BushingContour,
    pin: Pin,
    offset: ArrayLike,
    azimuth: ArrayLike,
    law: SpringLaw,
) -> FloatArray:
    """Pressure on every node with the pin displaced along each load line [Pa], (M, N).

    ``p(delta_j(s))`` on the nodes within 90 degrees of the load line, 0 elsewhere: the
    pressure whose resultant :func:`paper_balance` balances, at its offsets.

    Parameters
    ----------
    contour : BushingContour
        Bushing contour.
    pin : Pin
        The pin.
    offset : array_like, shape (M,)
        Pin displacement ``s`` along each load line [m].
    azimuth : array_like, shape (M,)
        Load directions in the bushing frame [rad].
    law : SpringLaw
        Spring law.
    """
    offset = np.asarray(offset, dtype=float).ravel()[:, None]
    beta, gap, area = _nodes(contour, pin, np.asarray(azimuth, dtype=float).ravel(), law)
    depth = pin_penetration(offset * np.cos(beta), offset * np.sin(beta), gap, pin.radius)
    return np.where(area > 0, law.pressure(np.maximum(depth, 0.0)), 0.0)


def _nodes(
    contour: BushingContour, pin: Pin, azimuth: FloatArray, law: SpringLaw
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Node angles from each load line [rad], radial gaps [m] and spring areas [m^2]
    (0 for nodes 90 degrees or more from the load line, which cannot touch), (M, N) each.
    The symmetric law's springs lie on the circle through the compression centre."""
    beta = wrap_angle(contour.theta[None, :] - azimuth[:, None])
    reach = np.abs(beta) < 0.5 * np.pi
    radius = np.broadcast_to(contour.radius, beta.shape)
    if law.symmetric:
        radius = np.broadcast_to(contour.radius_at(azimuth)[:, None], beta.shape)
    gap = radius - pin.radius
    if law.force_area is not None:
        area = np.where(reach, law.force_area, 0.0)
    else:
        area = np.where(reach, radius * contour.dtheta * contour.axial_length, 0.0)
    return beta, gap, area
