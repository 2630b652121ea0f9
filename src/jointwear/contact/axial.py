"""Along the pin: a joint cut into axial slices that share one pin.

A planar contact (:func:`jointwear.contact.solve`) is one cross-section of the joint.
Here the bushing of length ``L`` is cut into ``N`` slices of width ``h = L / N`` (the
slicing method of misaligned roller contacts [1]_) centred at

.. math:: z_i = \\left(i + \\tfrac12\\right) h - \\tfrac{L}{2}, \\qquad i = 0, \\dots, N - 1,

(``z = 0`` at the mid-plane), each slice a planar contact on its own contour (a worn
bushing wears differently along its length) with the slice's width as its axial
length. The slices share the pin, whose centre line is straight, tilted and possibly
bent: the pin centre in slice ``i``, along and across the load direction ``psi``, is

.. math::
    s_i = \\delta_0 + \\gamma z_i + w_i, \\qquad t_i = \\gamma_\\perp z_i,

with ``delta_0`` the offset at the mid-plane, ``gamma`` the tilt in the load plane,
``gamma_perp`` an imposed out-of-plane tilt and ``w_i`` the pin's bending
(:mod:`jointwear.contact.pin_beam`). Slice ``i`` carries the resultant of its springs
along the load, ``F_i = sum_j p(delta_ij) A_ij cos(theta_j - psi)``, the planar law of
that slice at that pin position (Winkler [2]_, NLCP [3]_; the penetration ``delta_ij``
along the node's ray, :func:`jointwear.geometry.contour.pin_penetration`). A load ``W`` whose line
of action crosses the axis at ``z = a`` (the load offset) is balanced by

.. math::
    \\sum_i F_i = W, \\qquad \\sum_i F_i z_i = W a,

for ``delta_0`` and ``gamma`` (a pin free to tilt), or for ``delta_0`` alone with
``gamma`` imposed (a misalignment: the supports take the moment
``sum_i F_i z_i - W a``). A slice the pin leaves carries nothing, so the contact
length shortens; a pin tilted further than the clearance allows presses on the
opposite wall at the far end (negative ``F_i``). The balance is the paper's: along the
load; the sideways resultant and its moment are reported, not balanced.

The pressure law is local, so a slice has the joint's pressure law and a force area
in proportion to its width (:func:`slice_law`): ``N`` equal slices under an aligned
pin each carry ``W / N`` with the planar solution's pressure, and one slice is the
planar solve.

Solvers: ``scipy.optimize.brentq`` for ``delta_0`` (the resultant grows with it),
``scipy.optimize.root`` (Powell's hybrid method with the analytic Jacobian, the
slices' linearised stiffness ``k_i = dF_i / ds_i``) for the tilt and the bending,
nested ``brentq`` on the tilt where that fails. A bent pin starts from the rigid pin's
balance and, where ``root`` does not converge at once, follows its flexibility up from
zero (continuation). The force balance is met to the planar balance's tolerance,
``max(tolerance, 8 eps sum|f|)`` (or the few ulps of the offsets that explain a
residual, as in the planar balance); the moment to the same force tolerance at the
half-length.

References
----------
.. [1] Harris, T. A., Kotzalas, M. N.: Advanced Concepts of Bearing Technology, 5th ed.
   CRC Press (2006), ch. 1 (misaligned and crowned rollers: the slicing method).
.. [2] Johnson, K. L.: Contact Mechanics. Cambridge University Press (1985), §5.9.
.. [3] The NLCP paper, eqs. (5)-(7) (the planar balance of one slice).
"""

from __future__ import annotations

import copy
import dataclasses
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.balance.window import PIN_REACH
from jointwear.contact.laws import CallableSpringLaw, SpringLaw
from jointwear.errors import ConfigError, ContactError, ConvergenceError, GeometryError
from jointwear.geometry.contour import BushingContour, Pin, pin_penetration

__all__ = [
    "AxialSlices",
    "AxialSolution",
    "Misalignment",
    "SliceContact",
    "slice_law",
    "solve_axial",
    "spring_law_of",
]

FloatArray = NDArray[np.float64]

_EPS = float(np.finfo(float).eps)

#: relative mismatch between a slice contour's axial length and the slice width accepted
WIDTH_TOLERANCE = 1e-12


@dataclass(frozen=True)
class AxialSlices:
    """``N`` equal slices of a bushing of length ``L``, the mid-plane at ``z = 0``.

    Parameters
    ----------
    length : float
        Axial length ``L`` of the bushing [m].
    count : int
        Number of slices ``N`` [-].
    """

    length: float
    count: int

    def __post_init__(self) -> None:
        if isinstance(self.count, bool) or not isinstance(self.count, int | np.integer):
            raise ConfigError(f"joint.axial_slices: must be a whole number, got {self.count!r}")
        if self.count < 1:
            raise ConfigError(f"joint.axial_slices: must be >= 1, got {self.count}")
        if not (math.isfinite(self.length) and self.length > 0):
            raise GeometryError(
                f"joint.axial_length: must be a positive finite length, got {self.length!r}"
            )

    @property
    def width(self) -> float:
        """Slice width ``h = L / N`` [m]."""
        return self.length / self.count

    @property
    def widths(self) -> FloatArray:
        """Width of every slice [m], shape (N,)."""
        return np.full(self.count, self.width)

    @property
    def centres(self) -> FloatArray:
        """Slice centres ``z_i = (2 i + 1 - N) L / (2 N)`` [m], symmetric about 0 exactly."""
        return (2.0 * np.arange(self.count) + 1.0 - self.count) * (self.length / (2 * self.count))

    @property
    def edges(self) -> FloatArray:
        """Slice boundaries from ``-L/2`` to ``L/2`` [m], shape (N + 1,)."""
        return (2.0 * np.arange(self.count + 1) - self.count) * (self.length / (2 * self.count))

    def contours(self, contour: BushingContour) -> tuple[BushingContour, ...]:
        """The contour of every slice: ``contour``'s radii, the slice's width as axial length.

        Parameters
        ----------
        contour : BushingContour
            Contour of the whole bushing (its axial length is not used) [m].
        """
        return tuple(
            BushingContour(contour.radius, self.width, contour.original_radius, contour.wear)
            for _ in range(self.count)
        )

    def worn_contours(self, radius: float, wear_depth: ArrayLike) -> tuple[BushingContour, ...]:
        """One contour per slice from a circle worn by a depth per slice and node.

        Parameters
        ----------
        radius : float
            Unworn bushing radius ``R_b`` [m].
        wear_depth : array_like, shape (N, nodes)
            Wear depth of every slice at the node angles [m].
        """
        wear = np.asarray(wear_depth, dtype=float)
        if wear.ndim != 2 or wear.shape[0] != self.count:
            raise GeometryError(
                f"axial slices: wear depth must have shape ({self.count}, nodes), got {wear.shape}"
            )
        return tuple(BushingContour.from_wear_profile(radius, row, self.width) for row in wear)


@dataclass(frozen=True)
class Misalignment:
    """An imposed tilt of the pin axis relative to the bushing axis.

    The pin centre line is displaced by ``angle * z`` towards the azimuth ``plane``
    (bushing frame) at the axial position ``z``; for a load at azimuth ``psi`` that is
    ``angle cos(plane - psi)`` along the load and ``angle sin(plane - psi)`` across it.

    Parameters
    ----------
    angle : float
        Misalignment angle ``theta_m >= 0`` [rad].
    plane : float
        Azimuth of the plane of the tilt in the bushing frame [rad].
    play : float
        Tilt the pin may take freely about the imposed one in the load plane, e.g.
        ``2 c_f / span`` of a clevis whose fork bores have the radial clearance ``c_f``
        (:attr:`jointwear.contact.pin_beam.Clevis.tilt_play`) [rad].
    """

    angle: float
    plane: float = 0.0
    play: float = 0.0

    def __post_init__(self) -> None:
        for name in ("angle", "plane", "play"):
            value = getattr(self, name)
            if not math.isfinite(value):
                raise ConfigError(f"joint.misalignment: {name} must be finite, got {value!r}")
        if self.angle < 0 or self.play < 0:
            raise ConfigError(
                f"joint.misalignment: angle and play must be >= 0 (the plane gives the "
                f"direction), got {self.angle!r} and {self.play!r}"
            )

    def components(self, azimuth: float) -> tuple[float, float]:
        """Tilt along and across (counter-clockwise) the load at ``azimuth`` [rad], in [rad]."""
        return (
            self.angle * math.cos(self.plane - azimuth),
            self.angle * math.sin(self.plane - azimuth),
        )


def spring_law_of(law: SpringLaw | Callable[..., Any]) -> SpringLaw:
    """The spring law of ``law``; refuse a model that solves itself.

    Slices need a pressure law on the contour (``asymmetric-winkler``, ``nlcp``,
    ``winkler`` or a callable ``pressure(penetration)`` [m -> Pa]); Hertz and the exact
    and finite-element references solve a whole cross-section and cannot be sliced.

    Parameters
    ----------
    law : SpringLaw or callable
        A resolved contact law (:func:`jointwear.contact.contact_law`).
    """
    if isinstance(law, SpringLaw):
        return law
    if hasattr(law, "solve"):
        name = getattr(law, "name", type(law).__name__)
        raise ContactError(
            f"contact.model: {name!r} solves a whole cross-section and cannot be cut into "
            f"axial slices; use 'asymmetric-winkler', 'nlcp', 'winkler' or a pressure law"
        )
    if hasattr(law, "pressure") and hasattr(law, "pressure_derivative"):
        return law  # type: ignore[return-value]
    return CallableSpringLaw(law)


def slice_law(law: SpringLaw | Callable[..., Any], fraction: float) -> SpringLaw:
    """The spring law of a slice that is ``fraction`` of the joint's length.

    The pressure ``p(delta)`` is a local law and stays; a law that turns pressure into
    force with a fixed area (NLCP's paper form, ``force = p A``) gets the slice's share
    ``fraction * A``, so that equal slices under an aligned pin add up to the joint. A
    law on the nodes' own areas (``force_area = None``) takes the width from the slice's
    contour.

    Parameters
    ----------
    law : SpringLaw or callable
        Spring law of the whole joint.
    fraction : float
        Slice width over joint length ``h / L`` [-], in (0, 1].
    """
    law = spring_law_of(law)
    if not 0.0 < fraction <= 1.0:
        raise ConfigError(f"joint.axial_slices: a slice fraction must be in (0, 1], got {fraction}")
    if law.force_area is None or fraction == 1.0:
        return law
    area = law.force_area * fraction
    if dataclasses.is_dataclass(law):
        return dataclasses.replace(law, force_area=area)
    sliced = copy.copy(law)
    sliced.force_area = area
    return sliced


@dataclass(frozen=True, eq=False)
class AxialSolution:
    """The contact of every slice under one load.

    Attributes
    ----------
    pressure : ndarray, shape (N, nodes)
        Pressure on every node of every slice [Pa].
    force : ndarray, shape (N,)
        Resultant of each slice along the load ``F_i`` [N].
    lateral_force : ndarray, shape (N,)
        Resultant of each slice across the load, counter-clockwise [N].
    offset : ndarray, shape (N,)
        Pin centre along the load at the slice centres ``s_i`` [m].
    lateral_offset : ndarray, shape (N,)
        Pin centre across the load ``t_i`` [m].
    deflection : ndarray, shape (N,)
        Bending ``w_i`` of the pin in ``s_i`` (zeros for a rigid pin) [m].
    stiffness : ndarray, shape (N,)
        Linearised contact stiffness of each slice ``k_i = dF_i / ds_i`` [N/m].
    penetration : ndarray, shape (N,)
        Deepest penetration of each slice [m].
    centres, widths : ndarray, shape (N,)
        Slice centres ``z_i`` and widths [m].
    centre_offset : float
        ``delta_0``, the pin centre along the load at the mid-plane [m].
    tilt, lateral_tilt : float
        ``gamma`` and ``gamma_perp`` [rad].
    load : float
        ``W`` [N].
    azimuth : float
        Load direction in the bushing frame [rad].
    load_offset : float
        Axial position ``a`` of the load's line of action [m].
    evaluations : int
        Evaluations of all slices' resultants.
    model : str
        Name of the spring law.
    """

    pressure: FloatArray
    force: FloatArray
    lateral_force: FloatArray
    offset: FloatArray
    lateral_offset: FloatArray
    deflection: FloatArray
    stiffness: FloatArray
    penetration: FloatArray
    centres: FloatArray
    widths: FloatArray
    centre_offset: float
    tilt: float
    lateral_tilt: float
    load: float
    azimuth: float
    load_offset: float
    evaluations: int
    model: str

    def __repr__(self) -> str:
        return (
            f"<AxialSolution {self.model}: {self.force.size} slices, {self.load:.6g} N, "
            f"{int(self.loaded.sum())} loaded, tilt {self.tilt:.3g} rad>"
        )

    @property
    def loaded(self) -> NDArray[np.bool_]:
        """Slices in contact on the loaded side (``F_i > 0``)."""
        return self.force > 0

    @property
    def contact_length(self) -> float:
        """Total width of the loaded slices [m]."""
        return float(self.widths[self.loaded].sum())

    @property
    def line_load(self) -> FloatArray:
        """Force per unit length ``F_i / h_i`` [N/m]."""
        return self.force / self.widths

    @property
    def foundation_stiffness(self) -> FloatArray:
        """Linearised contact stiffness per unit length ``k_i / h_i`` [N/m^2]."""
        return self.stiffness / self.widths

    @property
    def force_residual(self) -> float:
        """``sum_i F_i - W`` [N]."""
        return float(self.force.sum() - self.load)

    @property
    def moment(self) -> float:
        """``sum_i F_i z_i`` about the mid-plane [N m]."""
        return float(self.force @ self.centres)

    @property
    def moment_reaction(self) -> float:
        """``sum_i F_i z_i - W a``: what the supports carry under an imposed tilt [N m]."""
        return self.moment - self.load * self.load_offset

    @property
    def lateral_moment(self) -> float:
        """Moment of the sideways resultants about the mid-plane [N m]."""
        return float(self.lateral_force @ self.centres)


class SliceContact:
    """The resultants of all slices at once, for pin positions along and across the load.

    Parameters
    ----------
    contours : sequence of BushingContour
        One contour per slice, equal node counts, axial length the slice width.
    pin : Pin
        The pin.
    azimuth : float
        Load direction [rad].
    law : SpringLaw
        Spring law of the whole joint (its force area is shared by width).
    widths : ndarray, shape (N,)
        Slice widths [m].
    """

    def __init__(
        self,
        contours: Sequence[BushingContour],
        pin: Pin,
        azimuth: float,
        law: SpringLaw,
        widths: FloatArray,
    ) -> None:
        first = contours[0]
        self.cos = np.cos(first.theta - azimuth)
        self.sin = np.sin(first.theta - azimuth)
        radius = np.stack([c.radius for c in contours])
        if law.symmetric:  # springs on the circle through the compression centre
            radius = np.stack([np.full(c.nodes, float(c.radius_at(azimuth))) for c in contours])
        self.gap = radius - pin.radius
        if law.force_area is None:
            self.area = radius * first.dtheta * widths[:, None]
        else:
            share = widths / widths.sum()
            self.area = np.broadcast_to((law.force_area * share)[:, None], radius.shape)
        self.law = law
        self.pin_radius = pin.radius
        #: evaluations of all slices
        self.evaluations = 0

    def depth(self, along: FloatArray, across: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Penetration of every node [m] (< 0: a gap), and the pin position across each
        node's ray [m], for the pin at ``along``/``across`` the load per slice [m]."""
        s, t = along[:, None], across[:, None]
        ray_across = t * self.cos - s * self.sin
        depth = pin_penetration(s * self.cos + t * self.sin, ray_across, self.gap, self.pin_radius)
        return depth, ray_across

    def __call__(self, along: FloatArray, across: FloatArray):
        """Per slice: resultant along and across the load [N], ``dF/ds`` [N/m] and
        ``sum_j |f_j|`` [N]."""
        self.evaluations += 1
        depth, ray_across = self.depth(along, across)
        penetration = np.maximum(depth, 0.0)
        force = self.law.pressure(penetration) * self.area
        lateral = np.minimum(ray_across**2, self.pin_radius**2 * (1 - _EPS))
        # d(depth)/ds of the exact ray geometry (the planar balance's slope)
        ray_slope = self.cos + self.sin * ray_across / np.sqrt(self.pin_radius**2 - lateral)
        slope = self.law.pressure_derivative(penetration) * self.area * self.cos * ray_slope
        slope = np.where(depth > 0, slope, 0.0).sum(axis=1)
        return force @ self.cos, force @ self.sin, slope, np.abs(force).sum(axis=1)

    def resultant(self, along: FloatArray, across: FloatArray) -> float:
        """Sum of all slices' resultants along the load [N] (what ``brentq`` needs)."""
        self.evaluations += 1
        depth, _ = self.depth(along, across)
        return float((self.law.pressure(np.maximum(depth, 0.0)) * self.area).sum(axis=0) @ self.cos)

    def pressure(self, along: FloatArray, across: FloatArray) -> FloatArray:
        """Pressure on every node of every slice [Pa], shape (N, nodes)."""
        depth, _ = self.depth(along, across)
        return self.law.pressure(np.maximum(depth, 0.0))


def solve_axial(
    contours: Sequence[BushingContour],
    slices: AxialSlices,
    pin: Pin,
    load: float,
    azimuth: float,
    law: SpringLaw | Callable[..., Any],
    *,
    load_offset: float = 0.0,
    misalignment: Misalignment | None = None,
    compliance: ArrayLike | None = None,
    tolerance: float = 1e-12,
    max_penetration: float | None = None,
    method: str = "hybr",
) -> AxialSolution:
    """Balance one load on a joint cut into axial slices (force and moment).

    Finds ``delta_0`` and, for a pin free to tilt, ``gamma`` (and with ``compliance``
    the bending ``w``) such that

    .. math::
        \\sum_i F_i(s_i) = W, \\qquad \\sum_i F_i(s_i) z_i = W a, \\qquad
        w = -C F, \\qquad s_i = \\delta_0 + \\gamma z_i + w_i,

    each ``F_i`` the planar law of slice ``i`` on its own contour (module notes).

    Parameters
    ----------
    contours : sequence of BushingContour
        One contour per slice (:meth:`AxialSlices.contours`), the slice's width as its
        axial length, equal node counts.
    slices : AxialSlices
        The slices.
    pin : Pin
        The pin.
    load : float
        Load magnitude ``W >= 0`` [N].
    azimuth : float
        Direction in which the pin presses on the bushing, bushing frame [rad].
    law : SpringLaw or callable
        Spring law of the whole joint (:func:`jointwear.contact.contact_law`), or a
        callable ``pressure(penetration)`` [m -> Pa].
    load_offset : float
        Axial position ``a`` of the load's line of action, 0 at the mid-plane [m].
    misalignment : Misalignment, optional
        Imposed tilt; ``None`` (default): the pin tilts freely (moment balance).
    compliance : array_like, shape (N, N), optional
        The pin's flexibility at the slice centres relative to its supports [m/N]
        (:func:`jointwear.contact.pin_beam.compliance`); ``None``: a rigid pin.
    tolerance : float
        Force tolerance [N], with the planar balance's round-off floor ``8 eps sum|f|``;
        the moment's is the same at the half-length, times ``L / 2`` [N m].
    max_penetration : float, optional
        Largest admissible penetration, normally the wall thickness [m].
    method : {"hybr", "nested"}
        A free tilt by ``scipy.optimize.root`` (falling back on nested ``brentq``), or
        by nested ``brentq`` only.

    Returns
    -------
    AxialSolution

    Raises
    ------
    ContactError
        The load cannot be carried (through the wall, out of the pin's reach, a load
        offset on a single slice, a misalignment the bore cannot hold).
    ConvergenceError
        The balance did not meet its tolerance.
    """
    law = spring_law_of(law)
    contours = _checked_contours(contours, slices, pin)
    load, azimuth, load_offset = _checked_load(load, azimuth, load_offset, slices)
    if method not in ("hybr", "nested"):
        raise ConfigError(f"axial balance: unknown method {method!r}; choose 'hybr' or 'nested'")
    matrix = _checked_compliance(compliance, slices.count)
    contact = SliceContact(contours, pin, azimuth, law, slices.widths)
    imposed = (0.0, 0.0) if misalignment is None else misalignment.components(azimuth)
    balance = _Balance(contact, slices, load, load_offset, imposed[1], tolerance, matrix)
    free = misalignment is None or misalignment.play > 0
    if slices.count == 1 or load == 0:
        free = False  # one slice has no moment stiffness; no load, no moment to balance
    centre, tilt, bending = balance.solve(free, imposed[0], method)
    if free and misalignment is not None and abs(tilt - imposed[0]) > misalignment.play:
        # the play is used up: the pin bears on the supports at its limit tilt
        limit = imposed[0] + math.copysign(misalignment.play, tilt - imposed[0])
        centre, tilt, bending = balance.solve(False, limit, method)
    solution = balance.solution(centre, tilt, bending, azimuth, law.name)
    _check_wall(solution, max_penetration)
    return solution


class _Balance:
    """The balance of one load on the slices: unknowns, residuals, scipy's solvers."""

    def __init__(self, contact, slices, load, load_offset, lateral_tilt, tolerance, compliance):
        self.contact = contact
        self.z = slices.centres
        self.half_length = 0.5 * slices.length
        self.load, self.load_offset = load, load_offset
        self.lateral = lateral_tilt * self.z
        self.lateral_tilt = lateral_tilt
        self.tolerance = tolerance
        self.compliance = compliance
        reach = PIN_REACH * contact.pin_radius
        if np.any(np.abs(self.lateral) >= reach):
            raise ContactError(
                f"joint.misalignment: a tilt of {abs(lateral_tilt):.4g} rad across the load "
                f"puts the pin's ends out of the bushing"
            )
        #: how far the pin centre may move along the load in each slice [m]
        self.reach = np.sqrt(reach**2 - self.lateral**2)

    def forces(self, along: FloatArray):
        """Resultants, slopes and ``sum |f|`` of every slice (:class:`SliceContact`)."""
        return self.contact(along, self.lateral)

    def force_floor(self, total: FloatArray) -> float:
        """Tolerance of the force balance [N] for the slices' ``sum_j |f_j|`` [N]."""
        return max(self.tolerance, 8 * _EPS * float(total.sum()))

    def moment_floor(self, total: FloatArray, slope: FloatArray, size: float) -> float:
        """Tolerance of the moment balance [N m]: the force's at the half-length, or the
        moment a few ulps of the offsets explain (slopes ``dF_i/ds_i`` [N/m], the largest
        term of the offsets ``size`` [m], :func:`_round_off`)."""
        return self.force_floor(total) * self.half_length + _round_off(slope * self.z, size)

    def solve(self, free: bool, tilt: float, method: str) -> tuple[float, float, FloatArray]:
        """``delta_0`` [m], ``gamma`` [rad] and the bending [m] that balance the load;
        ``free``: the tilt from the moment balance, else ``tilt`` [rad] imposed. A bent
        pin starts from the rigid pin's balance."""
        bending = np.zeros(self.z.size)
        centre = self.centre_offset(tilt * self.z)
        if free:
            found = self.free_tilt(centre) if method == "hybr" else None
            if found is None:
                tilt = self.nested_tilt(centre)
                found = self.centre_offset(tilt * self.z), tilt
            centre, tilt = found
        if self.compliance is not None and self.load > 0:
            return self.bent(free, (centre, tilt, bending))
        return centre, tilt, bending

    def centre_offset(self, base: FloatArray, guess: float | None = None) -> float:
        """``delta_0`` [m] with ``sum_i F_i(delta_0 + base_i) = W`` (``base`` [m]), by
        ``brentq`` to round-off (the resultant grows with ``delta_0``)."""
        low, high = float(np.max(-self.reach - base)), float(np.min(self.reach - base))
        if not low < high:
            raise ContactError("joint.misalignment: the tilted pin does not fit in the bushing")

        def excess(centre: float) -> float:
            return self.contact.resultant(centre + base, self.lateral) - self.load

        if guess is None:
            # the pin just touching the slice nearest to the wall, then steps of a gap
            guess = float(np.clip(np.min(self.contact.gap.min(axis=1) - base), low, high))
            step = max(float(self.contact.gap.min()), 1e-9 * self.contact.pin_radius)
        else:
            step = 1e-9 * max(abs(guess), float(np.abs(base).max()), 1e-9)
        lower, upper = _bracket(excess, guess, step, low, high, "the pin centre")
        if lower == upper:
            return lower
        # to round-off: a few ulps of the offsets (rtol alone fails where delta_0 ~ 0)
        ulps = 2 * _EPS * max(abs(lower), abs(upper), float(np.abs(base).max()))
        from scipy.optimize import brentq  # (a run of one slice never loads scipy.optimize)

        return brentq(excess, lower, upper, xtol=ulps, rtol=4 * _EPS, maxiter=500)

    def free_tilt(self, centre: float) -> tuple[float, float] | None:
        """``(delta_0, gamma)`` of the force and moment balance by ``scipy.optimize.root``
        (hybrid method, analytic Jacobian), ``delta_0`` polished by ``brentq``; ``None``
        where it does not meet the tolerances."""
        z, load = self.z, self.load
        scale = np.array([1.0 / load, 1.0 / (load * self.half_length)])

        def residual(x: FloatArray):
            force, _, slope, _ = self.forces(x[0] + x[1] * z)
            f = np.array([force.sum() - load, force @ z - load * self.load_offset])
            k, kz = slope.sum(), slope @ z
            jac = np.array([[k, kz], [kz, slope @ z**2]])
            return f * scale, jac * scale[:, None]

        from scipy.optimize import root

        found = root(residual, [centre, 0.0], jac=True, method="hybr", options={"xtol": 1e-15})
        if not np.all(np.isfinite(found.x)):
            return None
        tilt = float(found.x[1])
        try:
            centre = self.centre_offset(tilt * z, guess=float(found.x[0]))
        except ContactError:
            return None
        force, _, slope, total = self.forces(centre + tilt * z)
        floor = self.moment_floor(total, slope, _size(centre, tilt * z))
        if abs(force @ z - load * self.load_offset) > floor:
            return None
        return centre, tilt

    def nested_tilt(self, centre: float) -> float:
        """``gamma`` [rad] of the moment balance by ``brentq``, ``delta_0`` by ``brentq``
        for every trial tilt (the moment grows with the tilt)."""
        z = self.z

        def moment(tilt: float) -> float:
            offset = self.centre_offset(tilt * z) + tilt * z
            return float(self.forces(offset)[0] @ z) - self.load * self.load_offset

        force, _, slope, _ = self.forces(centre + 0.0 * z)
        # a first step from the linearised moment stiffness sum k_i z_i^2
        stiffness = max(float(slope @ z**2), _EPS)
        guess = (self.load * self.load_offset - float(force @ z)) / stiffness
        limit = 0.999 * float(np.max(self.reach) / np.abs(z).max())
        step = max(abs(guess), 1e-9 * limit)
        lower, upper = _bracket(moment, guess, step, -limit, limit, "the tilt")
        if lower == upper:
            return lower
        # to round-off: a tilt moving the end slices by a few ulps of the pin's offset
        ulps = 2 * _EPS * max(abs(centre), float(np.abs(z).max() * max(abs(lower), abs(upper))))
        ulps /= float(np.abs(z).max())
        from scipy.optimize import brentq

        return brentq(moment, lower, upper, xtol=ulps, rtol=4 * _EPS, maxiter=500)

    def bent(self, free: bool, rigid: tuple[float, float, FloatArray]):
        """``(delta_0, gamma, w)`` of the bent pin from the rigid pin's balance ``rigid``;
        where ``scipy.optimize.root`` does not converge at once, by continuation in the
        pin's flexibility (``s C`` for ``s`` rising from 0 to 1 in steps halved on failure)."""
        state, done, step = rigid, 0.0, 1.0
        while done < 1.0:
            share = min(1.0, done + step)
            trial = self.coupled(free, state, share * self.compliance)
            if trial is not None:
                state, done, step = trial, share, 2 * step
                continue
            step /= 2
            if step < 1 / 64:
                raise ConvergenceError(
                    f"axial balance: the bent pin's balance did not converge for "
                    f"{self.load:.6g} N (at {done:.3g} of the pin's flexibility; a pin that "
                    f"bends by much of the clearance is beyond this model)"
                )
        return state

    def coupled(self, free: bool, start, matrix: FloatArray):
        """``(delta_0, gamma, w)`` of the pin of compliance ``matrix`` [m/N] from ``start``:
        ``scipy.optimize.root`` on the offset, the tilt (``free``) and the bending, whose
        Jacobian is the beam on the slices' linearised foundation; ``delta_0`` polished by
        ``brentq``. ``None`` where it misses the tolerances (:meth:`converged`)."""
        z, load = self.z, self.load
        n, extra, tilt = z.size, 2 if free else 1, start[1]
        deflection_scale = load * max(float(np.abs(matrix).max()), 1e-300)
        scale = np.concatenate(
            [[1.0 / load], [1.0 / (load * self.half_length)] if free else [],
             np.full(n, 1.0 / deflection_scale)]
        )  # fmt: skip
        shape = np.zeros((n, extra + n))  # d(offset)/d(unknowns)
        shape[:, 0] = 1.0
        if free:
            shape[:, 1] = z
        shape[:, extra:] = np.eye(n)
        rows = np.vstack([np.ones(n), *([z] if free else []), *matrix])
        target = np.zeros(extra + n)
        target[:extra] = [load, load * self.load_offset][:extra]

        def residual(x: FloatArray):
            offset = shape @ x + (0.0 if free else tilt * z)
            force, _, slope, _ = self.forces(offset)
            f = rows @ force - target
            f[extra:] += x[extra:]
            jac = rows @ (slope[:, None] * shape)
            jac[extra:, extra:] += np.eye(n)
            return f * scale, jac * scale[:, None]

        x0 = np.concatenate([[start[0]], [tilt] if free else [], start[2]])
        from scipy.optimize import root

        found = root(residual, x0, jac=True, method="hybr", options={"xtol": 1e-15})
        if not np.all(np.isfinite(found.x)):
            return None
        tilt = float(found.x[1]) if free else tilt
        bending = found.x[extra:]
        try:
            centre = self.centre_offset(tilt * z + bending, guess=float(found.x[0]))
        except ContactError:
            return None
        return (
            (centre, tilt, bending) if self.converged(centre, tilt, bending, free, matrix) else None
        )

    def converged(self, centre, tilt, bending, free, matrix) -> bool:
        """Whether the bent pin's balance meets its tolerances: the moment (``free``) and
        the bending's consistency with the forces, ``|w + C F| <= 1e-9 |w|``."""
        force, _, slope, total = self.forces(centre + tilt * self.z + bending)
        moment = abs(force @ self.z - self.load * self.load_offset)
        consistency = np.abs(bending + matrix @ force).max()
        size = np.abs(bending).max() + 1e-9 * np.abs(matrix).max() * self.load
        floor = self.moment_floor(total, slope, _size(centre, tilt * self.z, bending))
        return (not free or moment <= floor) and consistency <= 1e-9 * size

    def solution(self, centre, tilt, bending, azimuth, model) -> AxialSolution:
        """The :class:`AxialSolution` at ``delta_0`` [m], ``gamma`` [rad], bending [m]."""
        offset = centre + tilt * self.z + bending
        force, lateral_force, slope, total = self.forces(offset)
        size = _size(centre, tilt * self.z, bending)
        if abs(force.sum() - self.load) > self.force_floor(total) + _round_off(slope, size):
            raise ConvergenceError(
                f"axial balance: force residual {force.sum() - self.load:.3g} N for "
                f"{self.load:.6g} N"
            )
        depth, _ = self.contact.depth(offset, self.lateral)
        return AxialSolution(
            pressure=self.contact.pressure(offset, self.lateral),
            force=force,
            lateral_force=lateral_force,
            offset=offset,
            lateral_offset=self.lateral.copy(),
            deflection=np.asarray(bending, dtype=float).copy(),
            stiffness=slope,
            penetration=np.maximum(depth.max(axis=1), 0.0),
            centres=self.z.copy(),
            widths=np.full(self.z.size, 2 * self.half_length / self.z.size),
            centre_offset=float(centre),
            tilt=float(tilt),
            lateral_tilt=float(self.lateral_tilt),
            load=self.load,
            azimuth=azimuth,
            load_offset=self.load_offset,
            evaluations=self.contact.evaluations,
            model=model,
        )


def _size(*terms: ArrayLike) -> float:
    """The largest magnitude among the terms summed into the pin's offsets [m]: what their
    round-off is in proportion to."""
    return max(float(np.max(np.abs(term))) for term in terms)


def _round_off(slope: FloatArray, size: float) -> float:
    """Force [N] (moment [N m], for ``slope`` ``dF_i/ds_i z_i``) that a few ulps of the
    pin's offsets explain, offsets summed from terms up to ``size`` [m]: where one ulp
    moves the resultant by more than the tolerance (the planar balance's round-off
    criterion)."""
    return 4 * _EPS * float(np.abs(slope).sum()) * size


def _bracket(
    function: Callable[[float], float],
    guess: float,
    step: float,
    low: float,
    high: float,
    what: str,
) -> tuple[float, float]:
    """An interval ``(a, b)`` within ``[low, high]`` where the increasing ``function``
    changes sign, from ``guess`` in steps doubling from ``step`` (units of the unknown);
    ``(x, x)`` where ``function(x) = 0``."""
    value = function(guess)
    if value == 0:
        return guess, guess
    direction = 1.0 if value < 0 else -1.0
    edge = high if direction > 0 else low
    near = guess
    while True:
        far = guess + direction * step
        far = min(far, high) if direction > 0 else max(far, low)
        far_value = function(far)
        if far_value == 0:
            return far, far
        if (far_value > 0) == (direction > 0):
            return (near, far) if direction > 0 else (far, near)
        if far == edge:
            raise ContactError(
                f"load: no balance within the pin's reach ({what} would leave the bushing)"
            )
        near, guess, step = far, far, 2 * step


def _checked_contours(
    contours: Sequence[BushingContour], slices: AxialSlices, pin: Pin
) -> tuple[BushingContour, ...]:
    """The slices' contours, checked: one per slice, equal node counts, the slice width."""
    contours = tuple(contours)
    if len(contours) != slices.count:
        raise GeometryError(
            f"axial slices: {len(contours)} contours for {slices.count} slices (one per slice)"
        )
    nodes = contours[0].nodes
    for index, contour in enumerate(contours):
        if contour.nodes != nodes:
            raise GeometryError(
                f"axial slices: slice {index} has {contour.nodes} nodes, slice 0 has {nodes}"
            )
        if abs(contour.axial_length / slices.width - 1.0) > WIDTH_TOLERANCE:
            raise GeometryError(
                f"axial slices: slice {index}'s contour is {contour.axial_length:.6g} m long, "
                f"the slice {slices.width:.6g} m wide; build them with AxialSlices.contours"
            )
        contour.check_pin(pin)
    return contours


def _checked_load(load, azimuth, load_offset, slices: AxialSlices) -> tuple[float, float, float]:
    """Load [N], azimuth [rad] and load offset [m] as floats, checked."""
    load, azimuth, load_offset = float(load), float(azimuth), float(load_offset)
    if not (math.isfinite(load) and math.isfinite(azimuth)):
        raise ContactError("load: loads and azimuths must be finite")
    if load < 0:
        raise ContactError("load: must be >= 0 (the azimuth gives the direction)")
    if not math.isfinite(load_offset):
        raise ConfigError(f"joint.load_offset: must be finite, got {load_offset!r}")
    if slices.count == 1 and load_offset != 0 and load > 0:
        raise ConfigError(
            "joint.load_offset: a load off the mid-plane needs joint.axial_slices >= 2 "
            "(one slice has no moment stiffness)"
        )
    return load, azimuth, load_offset


def _checked_compliance(compliance: ArrayLike | None, count: int) -> FloatArray | None:
    """The pin's compliance matrix [m/N], shape (N, N), or ``None`` (rigid)."""
    if compliance is None:
        return None
    matrix = np.asarray(compliance, dtype=float)
    if matrix.shape != (count, count) or not np.all(np.isfinite(matrix)):
        raise GeometryError(
            f"pin.model: the compliance must be a finite ({count}, {count}) matrix, got "
            f"shape {matrix.shape}"
        )
    return matrix


def _check_wall(solution: AxialSolution, max_penetration: float | None) -> None:
    """Raise :class:`ContactError` where a slice's penetration exceeds ``max_penetration``
    [m] (the load pushes the pin through the wall there)."""
    if max_penetration is None:
        return
    deepest = int(np.argmax(solution.penetration))
    if solution.penetration[deepest] > max_penetration:
        raise ContactError(
            f"load: {solution.load:.6g} N at {math.degrees(solution.azimuth):.4g} deg would "
            f"push the pin through the bushing wall in slice {deepest} "
            f"(z = {solution.centres[deepest] * 1e3:.4g} mm)"
        )
