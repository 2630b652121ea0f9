"""Sliding distance at the pin-bushing interface per time step (stage 3a).

The one place a sliding distance is computed: :func:`sliding_distance`,

.. math:: \\Delta s = R_b \\, |\\Delta\\varphi| ,

``R_b`` the bushing radius and ``Delta phi`` an angle the contact turns through over the
step. Archard's wear of the bushing (:mod:`jointwear.tribology.archard`, and the fused
kernel of :mod:`jointwear.contact.kernel`, which is handed these distances) and the
sliding speed of the material checks (:func:`sliding_speed`) take it from here.

Which radius
------------
In the bushing's frame the pin turns by ``dphi`` relative to the bushing about its own
centre, which sits at ``e = c + delta`` from the bushing centre (clearance ``c`` plus
the elastic approach ``delta``) in the direction ``psi`` of the load. The pin's material
at the contact moves along the bushing surface by ``R_p dphi`` (its surface turning past
the bushing) plus ``e dpsi`` (its centre swinging round with the load), so the slip at
the contact is exactly

.. math:: \\Delta s = |R_p \\, \\Delta\\varphi + e \\, \\Delta\\psi| .

* A load that turns with the pin (``dpsi = dphi``: a two-force link carrying the pin, as
  the connecting rod of the paper's slider-crank, whose pin runs in the slider's
  bushing) slides ``(R_p + e) |dphi| = R_b |dphi| + delta |dphi|``: ``R_b`` is exact but
  for the elastic approach, ``delta / R_b ~ 1e-3``.
* A load fixed in the bushing (``dpsi = 0``) slides ``R_p |dphi|``, ``c / R_b`` less:
  0.67 % for the paper's joint (``c = 0.05 mm``, ``R_b = 7.5 mm``), 0.1-1 % for
  ordinary plain bearings.

The wear takes ``R_b``: exact for the paper's joint, within ``c / R_b`` of the slip
otherwise. The material checks (:func:`sliding_speed`) take ``R_p``, because the limits
they are compared with are stated that way: a datasheet's sliding speed and PV use the
shaft's surface speed ``R_p |dphi/dt|``. Each caller states its radius; the formula is
this module's one.

Two readings of the angle are offered (``simulation.sliding``):

* ``"relative-rotation"`` (default, kinematically correct): the rotation of the pin
  relative to the bushing, ``Delta phi = Delta(phi_pin - phi_bushing)``
  (:func:`relative_rotation`);
* ``"contact-azimuth"`` (the paper's wording, §3.1): the change of the load azimuth,
  ``Delta psi`` (:func:`contact_azimuth`).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.geometry.angles import wrap_angle
from jointwear.registry import Registry

__all__ = [
    "SLIDING_MODELS",
    "contact_azimuth",
    "relative_rotation",
    "sliding_distance",
    "sliding_speed",
]

FloatArray = NDArray[np.float64]


def sliding_distance(angle_increment: ArrayLike, bushing_radius: float) -> FloatArray:
    """Sliding distance ``R_b |d angle|`` of each step [m].

    Parameters
    ----------
    angle_increment : array_like, shape (M,)
        Angle the contact turns through over each step [rad] (a relative rotation or a
        change of the load azimuth).
    bushing_radius : float
        Bushing radius ``R_b`` [m], the sliding radius (module notes).
    """
    return bushing_radius * np.abs(np.asarray(angle_increment, dtype=float))


def relative_rotation(rotation_increment: ArrayLike, radius: float) -> FloatArray:
    """Sliding distance ``R_b |d(phi_pin - phi_bushing)|`` per step [m].

    Parameters
    ----------
    rotation_increment : array_like, shape (M,)
        Relative rotation of pin and bushing over each step [rad].
    radius : float
        Bushing radius ``R_b`` [m] (:func:`sliding_distance`).
    """
    return sliding_distance(rotation_increment, radius)


def contact_azimuth(azimuth: ArrayLike, radius: float) -> FloatArray:
    """Sliding distance ``R_b |d psi|`` per step from the load azimuth [m].

    The increment of step ``k`` is ``psi_{k+1} - psi_k`` (periodic over the
    revolution), wrapped to ``(-pi, pi]``.

    Parameters
    ----------
    azimuth : array_like, shape (M,)
        Load azimuth at each step [rad].
    radius : float
        Bushing radius ``R_b`` [m] (:func:`sliding_distance`).
    """
    psi = np.asarray(azimuth, dtype=float)
    return sliding_distance(wrap_angle(np.roll(psi, -1) - psi), radius)


def sliding_speed(
    rotation_increment: ArrayLike, step_duration: ArrayLike, radius: float
) -> FloatArray:
    """Sliding speed ``R |d(phi_pin - phi_bushing)| / dt`` of each step [m/s].

    The sliding distance of :func:`sliding_distance` over the step's duration. The
    material checks call it with the pin radius ``R_p``, the radius of a datasheet's
    sliding speed and PV limits.

    Parameters
    ----------
    rotation_increment : array_like, shape (M,)
        Relative rotation of pin and bushing over each step [rad].
    step_duration : array_like, shape (M,)
        Duration of each step [s].
    radius : float
        Radius of the surface whose speed is meant [m]: ``R_p`` for a datasheet's limits.
    """
    duration = np.asarray(step_duration, dtype=float)
    return sliding_distance(rotation_increment, radius) / duration


SLIDING_MODELS: Registry = Registry("sliding model", "simulation.sliding")
SLIDING_MODELS.add(
    "relative-rotation",
    lambda joint_load, radius: relative_rotation(joint_load.relative_rotation, radius),
)
SLIDING_MODELS.add(
    "contact-azimuth", lambda joint_load, radius: contact_azimuth(joint_load.azimuth, radius)
)
