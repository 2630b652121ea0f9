"""Sliding distance at the pin-bushing interface per time step (stage 3a).

Archard's law needs the distance the surfaces slide over each other. Two
readings are offered:

* ``"relative-rotation"`` (default, kinematically correct): the pin turns
  relative to the bushing by ``d(phi_pin - phi_bushing)``, so a point of the
  bushing surface at radius ``R`` is slid over by ``ds = R |d(phi_pin - phi_bushing)|``.
* ``"contact-azimuth"`` (the paper's wording, §3.1): ``ds = R |d psi|``, the
  arc travelled by the contact point as the load azimuth ``psi`` changes.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.registry import Registry

__all__ = ["SLIDING_MODELS", "contact_azimuth", "relative_rotation"]

FloatArray = NDArray[np.float64]


def relative_rotation(rotation_increment: ArrayLike, radius: float) -> FloatArray:
    """Sliding distance ``R |d(phi_pin - phi_bushing)|`` per step [m].

    Parameters
    ----------
    rotation_increment : array_like, shape (M,)
        Relative rotation of pin and bushing over each step [rad].
    radius : float
        Sliding radius, the bushing radius [m].
    """
    return radius * np.abs(np.asarray(rotation_increment, dtype=float))


def contact_azimuth(azimuth: ArrayLike, radius: float) -> FloatArray:
    """Sliding distance ``R |d psi|`` per step from the load azimuth [m].

    The increment of step ``k`` is ``psi_{k+1} - psi_k`` (periodic over the
    revolution), wrapped to ``(-pi, pi]``.

    Parameters
    ----------
    azimuth : array_like, shape (M,)
        Load azimuth at each step [rad].
    radius : float
        Sliding radius [m].
    """
    psi = np.asarray(azimuth, dtype=float)
    increment = np.angle(np.exp(1j * (np.roll(psi, -1) - psi)))
    return radius * np.abs(increment)


SLIDING_MODELS: Registry = Registry("sliding model", "simulation.sliding")
SLIDING_MODELS.add(
    "relative-rotation",
    lambda joint_load, radius: relative_rotation(joint_load.relative_rotation, radius),
)
SLIDING_MODELS.add(
    "contact-azimuth", lambda joint_load, radius: contact_azimuth(joint_load.azimuth, radius)
)
