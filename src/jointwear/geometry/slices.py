"""The worn bushing of a joint cut into axial slices: one contour per slice.

A run with ``joint.axial_slices = N > 1`` wears every slice on its own contour; its wear
depth is a map of shape ``(N, nodes)``, row ``i`` the slice centred at
``z_i = (i + 1/2) L / N - L / 2`` (:class:`jointwear.contact.axial.AxialSlices`).
:class:`SlicedContour` is that map as the loop's contour: it grows by a map
(:meth:`SlicedContour.worn`, as :func:`jointwear.geometry.update.update_contour` asks
of a contour) and hands each slice's :class:`~jointwear.geometry.contour.BushingContour`
(the slice width as its axial length) to the contact stage.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import GeometryError
from jointwear.geometry.contour import BushingContour, node_angles

__all__ = ["SlicedContour"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class SlicedContour:
    """The bushing's slices, each a contour worn by its row of the wear map.

    The map and the radii are kept whole, as two read-only ``(N, nodes)`` arrays: the
    loop builds a sliced contour every contour update and its contact solve reads the
    radii of all slices at once; each slice's
    :class:`~jointwear.geometry.contour.BushingContour` (:attr:`contours`) is built
    only when asked for, from rows of the two arrays (no copy).

    Parameters
    ----------
    radius : ndarray, shape (N, nodes)
        Inner radius of every slice at every node [m], read-only.
    wear_depth : ndarray, shape (N, nodes)
        The wear map that made ``radius`` from ``original_radius`` [m], read-only.
    width : float
        Width of a slice, the axial length of its contour [m].
    original_radius : float
        Radius of the unworn bushing [m].
    """

    radius: FloatArray = field(repr=False)
    wear_depth: FloatArray = field(repr=False)
    width: float
    original_radius: float

    @classmethod
    def of_depth(cls, radius: float, wear_depth: ArrayLike, axial_length: float) -> SlicedContour:
        """The slices of a bushing of ``axial_length`` [m] and unworn ``radius`` [m] worn
        by ``wear_depth`` [m], shape ``(N, nodes)``, each slice ``axial_length / N`` wide."""
        wear = np.asarray(wear_depth, dtype=float)
        if wear.ndim != 2 or wear.shape[0] < 1:
            raise GeometryError(
                f"axial slices: the wear map must have shape (slices, nodes), got {wear.shape}"
            )
        width = axial_length / wear.shape[0]
        radii = radius + wear
        if not (
            wear.dtype == np.float64
            and wear.shape[1] >= 16
            and 0.0 < width < np.inf
            and radii.min() > 0.0
            and radii.max() < np.inf
        ):  # (the checks of every row at once; a map they refuse goes through each row's)
            return cls.of_contours([BushingContour._of_depth(radius, row, width) for row in wear])
        if wear.flags.writeable:
            wear = wear.copy()
            wear.setflags(write=False)
        radii.setflags(write=False)
        return cls(radii, wear, width, float(radius))

    @classmethod
    def of_contours(cls, contours: Sequence[BushingContour]) -> SlicedContour:
        """The slices of ``contours`` (equal node counts, the slice width as each one's
        axial length, one unworn radius)."""
        radius = np.stack([c.radius for c in contours])
        wear = np.stack([c.wear_depth for c in contours])
        radius.setflags(write=False)
        wear.setflags(write=False)
        first = contours[0]
        return cls(radius, wear, first.axial_length, first.original_radius)

    @cached_property
    def contours(self) -> tuple[BushingContour, ...]:
        """One contour per slice, the slice width as its axial length."""
        rows = zip(self.radius, self.wear_depth, strict=True)
        build = BushingContour._of_valid
        return tuple(build(r, self.width, self.original_radius, w) for r, w in rows)

    @property
    def count(self) -> int:
        """Number of slices ``N``."""
        return self.radius.shape[0]

    @property
    def nodes(self) -> int:
        """Nodes of each slice's contour."""
        return self.radius.shape[1]

    @property
    def theta(self) -> FloatArray:
        """Node angles [rad]."""
        return node_angles(self.nodes)

    @property
    def dtheta(self) -> float:
        """Node spacing [rad]."""
        return 2.0 * np.pi / self.nodes

    @property
    def axial_length(self) -> float:
        """Length of the whole bushing [m]."""
        return self.width * self.count

    def worn(self, wear_depth: ArrayLike) -> SlicedContour:
        """The slices grown radially by the map ``wear_depth`` [m], shape ``(N, nodes)``."""
        increment = np.asarray(wear_depth, dtype=float)
        if increment.shape != (self.count, self.nodes):
            raise GeometryError(
                f"axial slices: a wear increment of shape {increment.shape} for "
                f"{self.count} slices of {self.nodes} nodes"
            )
        radii = self.radius + increment
        if not (radii.min() > 0.0 and radii.max() < np.inf):  # (each row's checks raise)
            rows = zip(self.contours, increment, strict=True)
            return SlicedContour.of_contours([contour.worn(row) for contour, row in rows])
        wear = self.wear_depth + increment
        radii.setflags(write=False)
        wear.setflags(write=False)
        return SlicedContour(radii, wear, self.width, self.original_radius)
