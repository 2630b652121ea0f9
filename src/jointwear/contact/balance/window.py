"""Node windows about the load lines: geometry, bracket, contact extent.

A load line at azimuth ``psi`` lies between nodes: :func:`nearest_nodes` gives the node
nearest to it and the angle from that node to the line, the one place the windowed
balance, the compiled kernel's set-up (:mod:`jointwear.contact.kernel`) and Hertz's
profile (:mod:`jointwear.contact.hertz`) take them from.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear.contact.laws import SpringLaw
from jointwear.geometry.angles import angle_in_turn
from jointwear.geometry.contour import BushingContour, Pin, RadiusStencil

__all__ = [
    "PIN_REACH",
    "Window",
    "WindowGeometry",
    "angle_addition",
    "bracket",
    "half_angles",
    "nearest_nodes",
    "reach_width",
    "resultant",
    "springs_in_contact",
    "upper_bound",
    "widest_half_angle",
    "window_geometry",
]

FloatArray = NDArray[np.float64]

#: the ray geometry needs the pin centre within this fraction of the pin radius of the
#: bushing centre (``|e| < R_p``): the top of every bracket of the offset [-]
PIN_REACH = 0.999

#: window geometry per (nodes, width, azimuths): a simulation solves the same loads on a new
#: contour every revolution, so the trigonometry and index arithmetic are done once
_GEOMETRY_CACHE: dict[tuple[int, int, bytes], WindowGeometry] = {}


_GEOMETRY_CACHE_SIZE = 4


#: largest window (loads x nodes) whose geometry is cached (about 10 arrays of 2 MB)
_GEOMETRY_CACHE_ELEMENTS = 2**18


def _einsum_rowdot(a: FloatArray, b: FloatArray) -> FloatArray:
    return np.einsum("...j,...j->...", a, b)


#: ``sum_j a_ij b_ij`` per row: ``np.vecdot`` (NumPy >= 2, a dot kernel per row, about
#: 1.6 times faster than the einsum on a 360 x 105 window), else the einsum
rowdot: Callable[[FloatArray, FloatArray], FloatArray] = getattr(np, "vecdot", _einsum_rowdot)


def nearest_nodes(
    nodes: int, azimuth: FloatArray
) -> tuple[FloatArray, NDArray[np.int64], FloatArray]:
    """The node nearest each load line, and the line's angle from it.

    Parameters
    ----------
    nodes : int
        Nodes ``N`` of the contour, at ``theta_j = j dtheta``, ``dtheta = 2 pi / N`` [-].
    azimuth : ndarray, shape (M,)
        Load directions [rad], any number of turns.

    Returns
    -------
    position : ndarray, shape (M,)
        The azimuths in ``[0, 2 pi)`` [rad] (:func:`~jointwear.geometry.angles.angle_in_turn`).
    centre : ndarray of int, shape (M,)
        ``rint(position / dtheta)``, the nearest node (``N`` for a line just below
        ``2 pi``: index arrays take it modulo ``N``).
    shift : ndarray, shape (M,)
        ``centre dtheta - position``, ``|shift| <= dtheta / 2`` [rad]: node ``centre + o``
        lies ``o dtheta + shift`` from the load line.
    """
    dtheta = 2 * np.pi / nodes
    position = angle_in_turn(azimuth)
    centre = np.rint(position / dtheta).astype(np.int64)
    return position, centre, centre * dtheta - position


def angle_addition(
    offsets: NDArray[np.int64], dtheta: float, shift: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """``cos`` and ``sin`` of ``o dtheta + shift`` for window offsets ``o`` and load shifts.

    By angle addition: trigonometry on the (2W+1,) offsets and the (M,) shifts instead of
    the (M, 2W+1) block.

    Parameters
    ----------
    offsets : ndarray of int, shape (K,)
        Window offsets ``o`` [nodes].
    dtheta : float
        Node spacing [rad].
    shift : ndarray, shape (M,)
        Angle of each load's centre node from its load line [rad] (:func:`nearest_nodes`).

    Returns
    -------
    cos, sin : ndarray, shape (M, K)
        Of the node angles from the load lines [-].
    """
    cos_o, sin_o = np.cos(offsets * dtheta), np.sin(offsets * dtheta)
    cos_s, sin_s = np.cos(shift)[:, None], np.sin(shift)[:, None]
    return cos_o * cos_s - sin_o * sin_s, sin_o * cos_s + cos_o * sin_s


class WindowGeometry:
    """Contour-independent part of a window: node indices and angles about each load line.

    Parameters
    ----------
    nodes : int
        Nodes ``N`` of the contour [-].
    azimuth : ndarray, shape (M,)
        Load directions [rad].
    width : int
        Window half-width ``W`` [nodes]: offsets ``-W .. W`` about each centre node.
    """

    def __init__(self, nodes: int, azimuth: FloatArray, width: int) -> None:
        dtheta = 2 * np.pi / nodes
        m = azimuth.size
        position, centre, shift = nearest_nodes(nodes, azimuth)
        offsets = np.arange(-width, width + 1)
        self.index = (centre[:, None] + offsets) % nodes
        #: flat positions of the window in an (M, N) array
        self.flat = (np.arange(m)[:, None] * nodes + self.index).ravel()
        self.phi = offsets * dtheta + shift[:, None]
        self.cos, self.sin = angle_addition(offsets, dtheta, shift)
        self.sin2 = self.sin**2
        self.left = self.phi > 0
        self.right = self.phi < 0
        self.unit = np.stack([np.cos(azimuth), np.sin(azimuth)], axis=1)
        self.unit_perp = np.stack([-self.unit[:, 1], self.unit[:, 0]], axis=1)
        for array in vars(self).values():
            array.setflags(write=False)
        #: the contour's radius on each load line, from its node radii
        self.radius_at_loads = RadiusStencil.at(nodes, position)
        self._scaled: dict[tuple[float, int], FloatArray] = {}

    def scaled_cos(self, factor: Any, power: int = 1) -> FloatArray | None:
        """``factor * cos**power`` for a scalar ``factor`` (cached), else None.

        ``factor`` is a spring area times a law's coefficient [N/m^n]; ``power`` 1 or 2.
        """
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


def window_geometry(nodes: int, azimuth: FloatArray, width: int) -> WindowGeometry:
    """The :class:`WindowGeometry` of these nodes [-], azimuths [rad] and half-width [nodes],
    cached (a run solves the same loads on a new contour every revolution)."""
    if azimuth.size * (2 * width + 1) > _GEOMETRY_CACHE_ELEMENTS:
        return WindowGeometry(nodes, azimuth, width)  # too big to keep around
    key = (nodes, width, azimuth.tobytes())
    geometry = _GEOMETRY_CACHE.get(key)
    if geometry is None:
        geometry = WindowGeometry(nodes, azimuth, width)
        while len(_GEOMETRY_CACHE) >= _GEOMETRY_CACHE_SIZE:
            _GEOMETRY_CACHE.pop(next(iter(_GEOMETRY_CACHE)), None)
        _GEOMETRY_CACHE[key] = geometry
    return geometry


class Window:
    """Nodes within +-W of each load line, gathered into (M, 2W+1) arrays.

    ``gap`` (``r_j - R_p``) [m] is an (M, 1) column where every spring of a row has the
    same gap: the symmetric law (springs on the circle through the compression centre) and
    an unworn, circular bushing; the residual then reads one number per row instead of an
    (M, 2W+1) gather. ``area`` [m^2] is a scalar where every spring has the same one.

    Parameters
    ----------
    contour : BushingContour
        The bushing contour.
    azimuth : ndarray, shape (M,)
        Load directions [rad].
    width : int
        Half-width ``W`` [nodes].
    law : SpringLaw
        The spring law (its symmetry and spring area).
    pin_radius : float
        ``R_p`` [m].
    centre_radius : ndarray, shape (M,), optional
        The contour's radius on each load line [m], if known.
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
        geometry = window_geometry(contour.nodes, azimuth, width)
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


def _lower_bound(win, contour, pin_radius, load):
    """Lower end of the bracket of the pin offset: no node touches, ``f <= 0`` [m].

    The smallest radial gap of the window (where a load is zero the pin is put there,
    touching; a gap as wide as the pin is reported as out of reach). Otherwise the
    smallest gap of the whole contour, a bound as valid and without a pass over the window.
    """
    if win.symmetric:
        return win.centre_radius - pin_radius  # the gap of every spring of the row
    if np.any(load == 0) or contour.radius.max() - pin_radius >= PIN_REACH * pin_radius:
        return win.gap.min(axis=1)
    return np.full(load.shape, float(contour.radius.min()) - pin_radius)


def upper_bound(
    centre_gap: FloatArray, pin_radius: float, max_penetration: float | None, lower: FloatArray
) -> FloatArray:
    """Upper end of the bracket of the pin offset along each load line [m].

    :data:`PIN_REACH` of the pin radius (the ray geometry needs ``|e| < R_p``), or the
    wall thickness beyond the compression centre, never below ``lower``.

    Parameters
    ----------
    centre_gap : ndarray, shape (M,)
        Radial gap on each load line, ``r(psi) - R_p`` [m].
    pin_radius : float
        ``R_p`` [m].
    max_penetration : float or None
        Largest penetration at the compression centre, the wall thickness [m].
    lower : ndarray, shape (M,)
        Lower end of the bracket [m].
    """
    upper = np.full(lower.shape, PIN_REACH * pin_radius)
    if max_penetration is not None:
        upper = np.minimum(upper, centre_gap + max_penetration)
    return np.maximum(upper, lower)


def bracket(
    win: Window,
    contour: BushingContour,
    pin_radius: float,
    load: FloatArray,
    max_penetration: float | None,
) -> tuple[FloatArray, FloatArray]:
    """Bracket ``[lower, upper]`` of the pin offset along each load line [m].

    ``lower``: no node of the window touches; ``upper``: :func:`upper_bound`.

    Parameters
    ----------
    win : Window
        The loads' windows.
    contour : BushingContour
        The contour of the windows.
    pin_radius : float
        ``R_p`` [m].
    load : ndarray, shape (M,)
        Joint loads [N].
    max_penetration : float or None
        Largest penetration at the compression centre [m].
    """
    lower = _lower_bound(win, contour, pin_radius, load)
    return lower, upper_bound(win.centre_radius - pin_radius, pin_radius, max_penetration, lower)


def resultant(pressure: FloatArray, area: Any, direction: FloatArray) -> FloatArray:
    """``sum_j p_j A_j direction_j`` per load (one pass) [N].

    Parameters
    ----------
    pressure : ndarray, shape (M, K)
        Window pressures [Pa].
    area : ndarray, shape (M, K), or float
        Spring areas [m^2].
    direction : ndarray, shape (M, K)
        ``cos`` or ``sin`` of the node angles from the load lines [-].
    """
    if isinstance(area, np.ndarray):
        return np.einsum("ij,ij,ij->i", pressure, area, direction)
    return area * rowdot(pressure, direction)


def half_angles(
    phi: FloatArray, depth: FloatArray, contact: NDArray[np.bool_]
) -> tuple[FloatArray, FloatArray]:
    """Contact extent each side of the load line, edges interpolated between nodes [rad].

    Parameters
    ----------
    phi : ndarray, shape (M, K)
        Node angles from the load lines [rad], growing along a row.
    depth : ndarray, shape (M, K)
        Node depths [m].
    contact : ndarray of bool, shape (M, K)
        ``depth > 0``.

    Returns
    -------
    left, right : ndarray, shape (M,)
        Counter-clockwise and clockwise of the load line [rad].
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


def springs_in_contact(
    win: Window, contact: NDArray[np.bool_]
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Springs in contact counter-clockwise (phi > 0) and clockwise (phi < 0) of the load line.

    ``contact`` (bool, (M, 2W+1)) marks the window's nodes in contact. Only the centre
    column can have either sign (``|shift| <= dtheta / 2``); the others are counted as
    bytes (a sum of ``uint8``, exact while a half-window has < 256 nodes).
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


def widest_half_angle(phi: FloatArray, depth: FloatArray, contact: NDArray[np.bool_]) -> float:
    """Largest contact half-angle of all rows [rad], from the few rows that can hold it.

    The arguments are those of :func:`half_angles` (angles [rad], depths [m]).

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
    left, right = half_angles(phi[rows], depth[rows], contact[rows])
    return float(max(left.max(), right.max()))


def reach_width(
    contour: BushingContour,
    pin: Pin,
    law: SpringLaw,
    centre_radius: FloatArray,
    along: FloatArray,
    across: FloatArray | None,
) -> int:
    """Window half-width [nodes] holding every node that can touch the pin.

    The pin centre is ``along`` the load line and ``across`` it [m] (None: on the line);
    ``centre_radius`` is the contour's radius on each load line [m]. The
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
