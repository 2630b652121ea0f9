"""Bushing contour and pin: the geometry of the clearance joint.

The bushing's inner surface is stored as radii ``r_j`` at ``N`` equally spaced
angles ``theta_j = 2 pi j / N`` about the (fixed) bushing centre; a worn
contour is not a circle. The pin is a circle of radius ``R_p`` whose centre
sits at eccentricity vector ``e`` from the bushing centre.

The penetration at node ``j`` is measured along the node's ray: the distance
from the bushing centre to the far side of the pin along ``theta_j``, minus
``r_j``, clipped at zero. It is exact (no small-clearance expansion):

.. math::

    t_j = \\mathbf{u}_j \\cdot \\mathbf{e} + \\sqrt{R_p^2 - |\\mathbf{u}_j \\times \\mathbf{e}|^2},
    \\qquad \\delta_j = \\max(t_j - r_j, 0)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import GeometryError

__all__ = [
    "BushingContour",
    "Pin",
    "RadiusStencil",
    "node_angles",
    "pin_penetration",
    "ray_distance",
    "ray_distance_derivative",
]

FloatArray = NDArray[np.float64]


def node_angles(nodes: int) -> FloatArray:
    """Equally spaced node angles ``2 pi j / N`` [rad], ``j = 0, 1, ..., N-1``."""
    return 2.0 * np.pi * np.arange(nodes) / nodes


@dataclass(frozen=True, eq=False)
class Pin:
    """The pin: a rigid circle.

    Parameters
    ----------
    radius : float
        Pin radius [m].
    """

    radius: float

    def __post_init__(self) -> None:
        if not (np.isfinite(self.radius) and self.radius > 0):
            raise GeometryError(
                f"joint.pin_radius: must be a positive finite length, got {self.radius!r}"
            )


@dataclass(frozen=True, eq=False)
class RadiusStencil:
    """Periodic linear interpolation of node radii at fixed angles.

    Kept apart from :meth:`BushingContour.radius_at` so that a solver that reads the
    radius at the same angles on many contours computes the stencil once.

    Attributes
    ----------
    lower, upper : ndarray of int
        Nodes either side of each angle.
    weight : ndarray
        Weight of ``upper`` (``lower`` gets ``1 - weight``) [-].
    """

    lower: NDArray[np.intp]
    upper: NDArray[np.intp]
    weight: FloatArray

    @classmethod
    def at(cls, nodes: int, angle: ArrayLike) -> RadiusStencil:
        """The stencil of ``angle`` [rad] on ``nodes`` equally spaced nodes."""
        position = np.mod(np.asarray(angle, float), 2 * np.pi) / (2 * np.pi / nodes)
        floor = np.floor(position)
        lower = floor.astype(int) % nodes
        return cls(lower, (lower + 1) % nodes, position - floor)

    def __call__(self, radius: FloatArray) -> FloatArray:
        """Interpolated radius [m] from the node radii ``radius`` [m]."""
        return (1 - self.weight) * radius[self.lower] + self.weight * radius[self.upper]


@dataclass(frozen=True, eq=False)
class BushingContour:
    """Inner contour of the bushing, radii at equally spaced angles.

    Parameters
    ----------
    radius : array_like, shape (N,)
        Inner radius at ``theta_j = 2 pi j / N`` [m].
    axial_length : float
        Axial length ``b`` of the joint [m].
    original_radius : float, optional
        Radius of the unworn bushing [m]; default the mean of ``radius``.
    wear : array_like, shape (N,), optional
        Wear depth that made ``radius`` from ``original_radius`` [m]. Kept
        alongside the radius because ``radius - original_radius`` loses the
        digits of a micrometre depth on a millimetre radius.
    """

    radius: FloatArray
    axial_length: float
    original_radius: float = field(default=np.nan)
    wear: FloatArray | None = field(default=None, repr=False)

    def __post_init__(self) -> None:
        radius = np.asarray(self.radius, dtype=float)
        if radius.ndim != 1 or radius.size < 16:
            raise GeometryError("bushing contour: need a 1-D array of at least 16 radii")
        if not np.all(np.isfinite(radius)) or np.any(radius <= 0):
            raise GeometryError("bushing contour: radii must be positive and finite")
        if not (np.isfinite(self.axial_length) and self.axial_length > 0):
            raise GeometryError(
                f"joint.axial_length: must be a positive finite length, got {self.axial_length!r}"
            )
        radius.setflags(write=False)
        object.__setattr__(self, "radius", radius)
        if not np.isfinite(self.original_radius):
            object.__setattr__(self, "original_radius", float(radius.mean()))
        if self.wear is not None:
            wear = np.array(self.wear, dtype=float)
            if wear.shape != radius.shape:
                raise GeometryError("bushing contour: wear must have one value per node")
            wear.setflags(write=False)
            object.__setattr__(self, "wear", wear)

    def __repr__(self) -> str:
        peak = 0.0 if self.wear is None or not self.wear.size else float(self.wear.max())
        return (
            f"<BushingContour {self.radius.size} nodes, R0 {self.original_radius * 1e3:.6g} mm, "
            f"b {self.axial_length * 1e3:.4g} mm, peak wear {peak * 1e6:.4g} µm>"
        )

    # ---------------------------------------------------------------- builders
    @classmethod
    def circle(cls, radius: float, nodes: int, axial_length: float) -> BushingContour:
        """An unworn circular bushing.

        Parameters
        ----------
        radius : float
            Inner radius [m].
        nodes : int
            Number of nodes ``N``.
        axial_length : float
            Axial length of the joint [m].
        """
        return cls(np.full(nodes, float(radius)), axial_length, float(radius))

    @classmethod
    def from_wear_profile(
        cls, radius: float, wear_depth: ArrayLike, axial_length: float
    ) -> BushingContour:
        """A circle of ``radius`` worn by ``wear_depth`` [m] at the node angles."""
        wear = np.asarray(wear_depth, dtype=float)
        return cls(radius + wear, axial_length, float(radius), wear)

    @classmethod
    def _of_depth(cls, radius: float, wear: FloatArray, axial_length: float) -> BushingContour:
        """:meth:`from_wear_profile` of a float array, without building what is known valid.

        The revolution loop builds one contour per update from the state's wear depth;
        a profile the checks would refuse goes through them (and raises).
        """
        radii = radius + wear
        if not (
            wear.dtype == np.float64
            and wear.ndim == 1
            and wear.size >= 16
            and 0.0 < axial_length < np.inf
            and radii.min() > 0.0
            and radii.max() < np.inf
        ):
            return cls.from_wear_profile(radius, wear, axial_length)
        if wear.flags.writeable:
            wear = wear.copy()
            wear.setflags(write=False)
        radii.setflags(write=False)
        return cls._of_valid(radii, axial_length, float(radius), wear)

    @classmethod
    def _of_valid(
        cls, radii: FloatArray, axial_length: float, radius: float, wear: FloatArray
    ) -> BushingContour:
        """The contour of read-only ``radii`` [m] and ``wear`` [m] that the checks of
        ``__post_init__`` would pass (the caller checked them), built as it leaves them."""
        contour = object.__new__(cls)
        contour.__dict__.update(
            radius=radii, axial_length=axial_length, original_radius=radius, wear=wear
        )
        return contour

    @classmethod
    def from_points(
        cls,
        x: ArrayLike,
        y: ArrayLike,
        nodes: int,
        axial_length: float,
        center: tuple[float, float] = (0.0, 0.0),
        original_radius: float | None = None,
    ) -> BushingContour:
        """Resample measured surface points onto ``nodes`` equally spaced angles.

        Parameters
        ----------
        x, y : array_like
            Coordinates of points on the inner surface [m].
        nodes : int
            Number of nodes of the contour.
        axial_length : float
            Axial length of the joint [m].
        center : tuple of float
            Bushing centre in the points' frame [m].
        original_radius : float, optional
            Unworn radius [m].
        """
        x = np.asarray(x, float) - center[0]
        y = np.asarray(y, float) - center[1]
        angle = np.mod(np.arctan2(y, x), 2 * np.pi)
        order = np.argsort(angle)
        angle, r = angle[order], np.hypot(x, y)[order]
        # periodic linear interpolation
        angle_ext = np.concatenate([angle[-1:] - 2 * np.pi, angle, angle[:1] + 2 * np.pi])
        r_ext = np.concatenate([r[-1:], r, r[:1]])
        radius = np.interp(node_angles(nodes), angle_ext, r_ext)
        return cls(radius, axial_length, np.nan if original_radius is None else original_radius)

    # ---------------------------------------------------------------- properties
    @property
    def nodes(self) -> int:
        """Number of nodes ``N``."""
        return self.radius.size

    @property
    def theta(self) -> FloatArray:
        """Node angles [rad]."""
        return node_angles(self.nodes)

    @property
    def dtheta(self) -> float:
        """Node spacing [rad]."""
        return 2.0 * np.pi / self.nodes

    @property
    def spring_area(self) -> FloatArray:
        """Area of each node's spring ``A_j = r_j dtheta b`` [m^2]."""
        return self.radius * self.dtheta * self.axial_length

    @property
    def wear_depth(self) -> FloatArray:
        """Radial wear depth relative to the unworn circle [m]."""
        if self.wear is not None:
            return self.wear
        return self.radius - self.original_radius

    @property
    def area(self) -> float:
        """Area enclosed by the contour ``1/2 sum r_j^2 dtheta`` [m^2]."""
        return 0.5 * float(np.sum(self.radius**2)) * self.dtheta

    def worn(self, wear_depth: ArrayLike) -> BushingContour:
        """A new contour grown radially by ``wear_depth`` [m] at every node."""
        increment = np.asarray(wear_depth, float)
        return BushingContour(
            self.radius + increment,
            self.axial_length,
            self.original_radius,
            self.wear_depth + increment,
        )

    def radius_at(self, angle: ArrayLike) -> FloatArray:
        """Periodic linear interpolation of the radius at ``angle`` [rad]."""
        return RadiusStencil.at(self.nodes, angle)(self.radius)

    def rotated(self, shift: int) -> BushingContour:
        """The contour rotated by ``shift`` nodes (``shift * dtheta`` [rad])."""
        wear = None if self.wear is None else np.roll(self.wear, shift)
        return BushingContour(
            np.roll(self.radius, shift), self.axial_length, self.original_radius, wear
        )

    def check_pin(self, pin: Pin) -> None:
        """Raise :class:`GeometryError` unless the pin fits inside the contour."""
        if pin.radius >= self.radius.min():
            raise GeometryError(
                f"joint.pin_radius: pin radius {pin.radius:g} m is not smaller than the "
                f"bushing radius {self.radius.min():g} m (clearance must be > 0)"
            )

    def penetration(self, pin: Pin, eccentricity: ArrayLike, signed: bool = False) -> FloatArray:
        """Penetration of the pin at every node for pin-centre positions (:func:`pin_penetration`).

        Parameters
        ----------
        pin : Pin
            The pin.
        eccentricity : array_like, shape (..., 2)
            Pin-centre position relative to the bushing centre [m].
        signed : bool
            Keep the negative values (the gap of the nodes the pin does not reach).

        Returns
        -------
        ndarray, shape (..., N)
            Penetration ``delta_j >= 0`` [m] (``signed``: ``t_j - r_j``, negative for a gap).
        """
        e = np.asarray(eccentricity, float)
        c, s = np.cos(self.theta), np.sin(self.theta)
        along = c * e[..., 0:1] + s * e[..., 1:2]
        across = c * e[..., 1:2] - s * e[..., 0:1]
        depth = pin_penetration(along, across, self.radius - pin.radius, pin.radius)
        return depth if signed else np.maximum(depth, 0.0)


def pin_penetration(along: ArrayLike, across: ArrayLike, gap: ArrayLike, pin_radius: float):
    """Penetration of a circular pin into the bushing along a node's ray [m] (< 0: a gap).

    The pin centre lies ``along`` the node's ray and ``across`` it; the pin's far side
    on the ray is ``t = along + sqrt(R_p^2 - across^2)`` from the bushing centre, so a
    node at radius ``r = R_p + gap`` is penetrated by ``t - r = along - gap - across^2 /
    (sqrt(R_p^2 - across^2) + R_p)``, written so that a micrometre penetration is not
    the difference of two millimetre radii. The one statement of the ray geometry for
    the load balance, the finite-element reference, :meth:`BushingContour.penetration`
    and the distributed force laws of the contact-impact dynamics
    (:mod:`jointwear.mechanism.impact.distributed`). Two copies remain, for speed: the compiled
    contact kernel takes the same formula from its series, and the balance's residual
    (:mod:`jointwear.contact.balance.residual`) evaluates it in place in reused buffers.

    Parameters
    ----------
    along, across : array_like
        Pin-centre position along and across the node's ray [m], ``|across| < R_p``.
    gap : array_like
        Radial gap of the node, ``r - R_p`` [m].
    pin_radius : float
        Pin radius ``R_p`` [m].
    """
    lateral = np.minimum(np.square(across), pin_radius**2)
    return along - gap - lateral / (np.sqrt(pin_radius**2 - lateral) + pin_radius)


def ray_distance(theta: ArrayLike, ex: ArrayLike, ey: ArrayLike, pin_radius: float) -> FloatArray:
    """Distance from the bushing centre to the far side of the pin along ``theta``.

    Parameters
    ----------
    theta : array_like
        Ray angles [rad].
    ex, ey : array_like
        Pin-centre position [m], broadcast against ``theta``.
    pin_radius : float
        Pin radius [m].

    Returns
    -------
    ndarray
        ``t = u.e + sqrt(R_p^2 - (u x e)^2)`` [m]; requires ``|e| < R_p``.
    """
    c, s = np.cos(theta), np.sin(theta)
    along = c * ex + s * ey
    across = c * ey - s * ex
    return along + np.sqrt(pin_radius**2 - across**2)


def ray_distance_derivative(
    theta: ArrayLike, ex: ArrayLike, ey: ArrayLike, pin_radius: float
) -> tuple[FloatArray, FloatArray]:
    """Partial derivatives ``(dt/dex, dt/dey)`` of :func:`ray_distance` [-]."""
    c, s = np.cos(theta), np.sin(theta)
    across = c * ey - s * ex
    root = np.sqrt(pin_radius**2 - across**2)
    ratio = across / root
    return c + s * ratio, s - c * ratio
