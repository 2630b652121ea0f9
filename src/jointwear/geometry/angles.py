"""Angles on the bushing: the one place an angle is wrapped.

Two conventions are used across the package: a *difference* of angles (a rotation
increment, an offset between two azimuths) lives in (-pi, pi]; a *position* on the
bushing (an azimuth that indexes the contour) lives in [0, 2 pi).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["angle_in_turn", "wrap_angle"]

FloatArray = NDArray[np.float64]

TWO_PI = 2.0 * np.pi


def wrap_angle(angle: ArrayLike) -> FloatArray:
    """Wrap angle differences to the interval (-pi, pi] [rad].

    Parameters
    ----------
    angle : array_like
        Angles [rad].

    Returns
    -------
    ndarray
        The same angles modulo 2 pi, in (-pi, pi] [rad].
    """
    wrapped = np.mod(np.asarray(angle, dtype=float) + np.pi, TWO_PI) - np.pi
    # mod maps +pi to -pi; the interval is closed on the right
    return np.where(wrapped == -np.pi, np.pi, wrapped)


def angle_in_turn(angle: ArrayLike) -> FloatArray:
    """Positions on the bushing in [0, 2 pi) [rad].

    Parameters
    ----------
    angle : array_like
        Azimuths [rad], any number of turns.

    Returns
    -------
    ndarray
        The same azimuths modulo 2 pi, in [0, 2 pi) [rad].
    """
    turned = np.mod(np.asarray(angle, dtype=float), TWO_PI)
    # mod of a tiny negative angle rounds to exactly 2 pi
    return np.where(turned >= TWO_PI, 0.0, turned)
