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

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import GeometryError
from jointwear.geometry.contour import BushingContour

__all__ = ["SlicedContour"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class SlicedContour:
    """The bushing's slices, each a contour worn by its row of the wear map.

    Parameters
    ----------
    contours : tuple of BushingContour
        One contour per slice, equal node counts, the slice width as axial length [m].
    """

    contours: tuple[BushingContour, ...]

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
            return cls(tuple(BushingContour._of_depth(radius, row, width) for row in wear))
        wear = wear.copy()
        wear.setflags(write=False)
        radii.setflags(write=False)
        rows = zip(radii, wear, strict=True)
        return cls(tuple(BushingContour._of_valid(r, width, float(radius), w) for r, w in rows))

    @property
    def count(self) -> int:
        """Number of slices ``N``."""
        return len(self.contours)

    @property
    def nodes(self) -> int:
        """Nodes of each slice's contour."""
        return self.contours[0].nodes

    @property
    def theta(self) -> FloatArray:
        """Node angles [rad]."""
        return self.contours[0].theta

    @property
    def dtheta(self) -> float:
        """Node spacing [rad]."""
        return self.contours[0].dtheta

    @property
    def axial_length(self) -> float:
        """Length of the whole bushing [m]."""
        return self.contours[0].axial_length * self.count

    @property
    def original_radius(self) -> float:
        """Radius of the unworn bushing [m]."""
        return self.contours[0].original_radius

    @property
    def radius(self) -> FloatArray:
        """Inner radius of every slice at every node [m], shape ``(N, nodes)``."""
        return np.stack([c.radius for c in self.contours])

    @property
    def wear_depth(self) -> FloatArray:
        """The wear map [m], shape ``(N, nodes)``."""
        return np.stack([c.wear_depth for c in self.contours])

    def worn(self, wear_depth: ArrayLike) -> SlicedContour:
        """The slices grown radially by the map ``wear_depth`` [m], shape ``(N, nodes)``."""
        increment = np.asarray(wear_depth, dtype=float)
        if increment.shape != (self.count, self.nodes):
            raise GeometryError(
                f"axial slices: a wear increment of shape {increment.shape} for "
                f"{self.count} slices of {self.nodes} nodes"
            )
        rows = zip(self.contours, increment, strict=True)
        return SlicedContour(tuple(contour.worn(row) for contour, row in rows))
