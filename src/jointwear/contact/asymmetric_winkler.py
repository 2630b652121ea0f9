"""Asymmetric Winkler model (paper eq. 6).

The Winkler spring law of eq. (4) evaluated on the *real* bushing contour: on
a worn, non-circular contour the springs in contact are not symmetric about
the load, and their numbers on each side, ``N = N_L + N_R``, follow from the
discrete geometry of pin and bushing (penetration along every node's ray).
This is the model the paper calls "Winkler" in its Tables 3-5, after Li et al. [1]_.

References
----------
.. [1] Li, P., Chen, W., Zhu, A.: An improved practical model for wear prediction
   of revolute clearance joints in crank slider mechanisms. Sci. China Technol.
   Sci. 56, 2953-2963 (2013).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact import winkler
from jointwear.contact.laws import ContactParameters, PowerLaw

__all__ = ["spring_counts", "spring_law"]


def spring_counts(
    penetration: ArrayLike, relative_angle: ArrayLike
) -> tuple[NDArray[np.int64], NDArray[np.int64]]:
    """Springs in contact on each side of the compression centre (eq. 6).

    Parameters
    ----------
    penetration : array_like, shape (..., N)
        Node penetrations [m].
    relative_angle : array_like, shape (..., N)
        Node angle minus load azimuth, wrapped to (-pi, pi] [rad].

    Returns
    -------
    left, right : ndarray of int
        ``N_L`` (angle > 0, counter-clockwise of the load) and ``N_R`` (angle < 0).
        A node exactly on the load line is counted in neither.
    """
    contact = np.asarray(penetration) > 0
    angle = np.asarray(relative_angle)
    return (contact & (angle > 0)).sum(axis=-1), (contact & (angle < 0)).sum(axis=-1)


def spring_law(parameters: ContactParameters) -> PowerLaw:
    """Winkler spring law on the real contour."""
    symmetric = winkler.spring_law(parameters)
    return PowerLaw(symmetric.coefficient, 1.0, name="asymmetric-winkler", symmetric=False)
