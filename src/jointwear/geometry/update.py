"""Contour update (stage 4): the worn bushing after wear has removed material."""

from __future__ import annotations

from numpy.typing import ArrayLike

from jointwear.errors import WearThroughError
from jointwear.geometry.contour import BushingContour

__all__ = ["update_contour"]


def update_contour(
    contour: BushingContour, wear_depth: ArrayLike, wall_thickness: float | None = None
) -> BushingContour:
    """Grow the bushing radius by the wear depth at every node.

    Parameters
    ----------
    contour : BushingContour
        Contour before the wear increment.
    wear_depth : array_like, shape (N,)
        Wear depth to remove [m].
    wall_thickness : float, optional
        Bushing wall thickness ``L`` [m]; wear deeper than the wall raises
        :class:`~jointwear.errors.WearThroughError`.
    """
    worn = contour.worn(wear_depth)
    if wall_thickness is not None:
        deepest = float(worn.wear_depth.max())
        if deepest >= wall_thickness:
            raise WearThroughError(
                f"joint.bushing_thickness: wear ({deepest * 1e3:.4g} mm) has gone through the "
                f"{wall_thickness * 1e3:.4g} mm bushing wall"
            )
    return worn
