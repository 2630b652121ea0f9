"""Wear metrics as the paper reports them: peak, width, area, mass.

All functions take a wear-depth profile on the equally spaced node grid
``theta_j = 2 pi j / N`` (radial growth of the bushing radius, [m]).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

__all__ = ["removed_area", "wear_mass", "wear_peak", "wear_volume", "wear_width", "worn_area"]


def wear_peak(wear_depth: ArrayLike) -> float:
    """Largest wear depth [m].

    Parameters
    ----------
    wear_depth : array_like, shape (N,)
        Radial wear depth at the nodes [m].
    """
    return float(np.max(wear_depth))


def wear_width(wear_depth: ArrayLike, threshold: float = 0.01) -> float:
    """Angular extent of the worn zone [rad].

    The measure of the angles where the profile, linearly interpolated between
    nodes (periodically), exceeds ``threshold * peak``: whole node intervals
    above the threshold count fully, intervals that cross it count up to the
    interpolated crossing. Unlike a node count this is continuous in the
    model's parameters (so calibration can use it) and exact for the
    interpolated profile. For the single scar a revolute joint wears it is the
    scar's width; for several scars, their summed width.

    Parameters
    ----------
    wear_depth : array_like, shape (N,)
        Radial wear depth at the nodes [m].
    threshold : float
        Fraction of the peak that counts as worn [-], default 1 %.
    """
    depth = np.asarray(wear_depth, dtype=float)
    peak = depth.max()
    if not peak > 0:
        return 0.0
    above = depth - threshold * peak
    after = np.roll(above, -1)
    both = (above > 0) & (after > 0)
    crossing = (above > 0) != (after > 0)
    positive = np.where(above > 0, above, after)
    with np.errstate(divide="ignore", invalid="ignore"):
        fraction = np.where(crossing, positive / np.abs(above - after), 0.0)
    width = (np.count_nonzero(both) + fraction.sum()) * 2 * np.pi / depth.size
    return float(min(width, 2 * np.pi))  # all worn: exactly 2 pi, not one ulp more


def removed_area(original_radius: float | ArrayLike, radius: ArrayLike) -> float:
    """Area of bushing removed by wear, exact for a polar contour [m^2].

    .. math:: A = \\tfrac12 \\sum_j (r_j^2 - r_{0,j}^2) \\, \\Delta\\theta

    the area between two star-shaped contours sampled at the same angles (the
    trapezoid rule on a periodic grid, spectrally accurate for smooth contours).

    Parameters
    ----------
    original_radius : float or array_like, shape (N,)
        Radius before wear [m].
    radius : array_like, shape (N,)
        Radius after wear [m].
    """
    radius = np.asarray(radius, dtype=float)
    return worn_area(original_radius, radius - original_radius)


def worn_area(original_radius: float | ArrayLike, wear_depth: ArrayLike) -> float:
    """Area removed by a wear-depth profile, exact for a polar contour [m^2].

    :func:`removed_area` in terms of ``h = r - r_0``: ``1/2 sum h_j (2 r_0 + h_j) dtheta``,
    so that micrometre depths on a millimetre radius keep full precision.

    Parameters
    ----------
    original_radius : float or array_like, shape (N,)
        Radius before wear [m].
    wear_depth : array_like, shape (N,)
        Radial wear depth [m].
    """
    depth = np.asarray(wear_depth, dtype=float)
    original = np.broadcast_to(np.asarray(original_radius, dtype=float), depth.shape)
    return float(0.5 * np.sum(depth * (2 * original + depth)) * 2 * np.pi / depth.size)


def wear_volume(removed_area: float, axial_length: float) -> float:
    """Worn volume ``b * A`` [m^3].

    Parameters
    ----------
    removed_area : float
        Removed cross-section area [m^2].
    axial_length : float
        Axial length of the joint ``b`` [m].
    """
    return removed_area * axial_length


def wear_mass(removed_area: float, axial_length: float, density: float) -> float:
    """Worn mass ``rho * b * A`` [kg].

    Parameters
    ----------
    removed_area : float
        Removed cross-section area [m^2].
    axial_length : float
        Axial length of the joint ``b`` [m].
    density : float
        Density of the bushing material [kg/m^3].
    """
    return density * axial_length * removed_area
