r"""Distributed force laws of the contact–impact dynamics: the bushing's springs on the pin.

The ``nlcp`` and ``winkler`` force laws (``dynamics.force_law``) integrate the
pressure model of the wear pipeline over the current bushing contour for the
displaced pin (:func:`spring_resultant`). Each node ``j`` of the contour is a radial
spring with the exact penetration ``delta_j(e) = max(t_j(e) - r_j, 0)``
(:meth:`jointwear.geometry.BushingContour.penetration`), pressure ``p(delta_j)``
from the spring law and area ``A_j``; the elastic force on the bushing is the
gradient of the stored energy

.. math::

    V(\mathbf e) = \sum_j A_j \int_0^{\delta_j} p(s)\,ds, \qquad
    \mathbf F_{el} = \nabla_{\mathbf e} V = \sum_j A_j\, p(\delta_j)\, \nabla t_j ,

which is the radial-spring resultant ``sum_j A_j p_j u_j`` up to terms of order
``|e| / R_p`` (about 1 % of each spring's force, mostly cancelling between the two
sides), and is exactly conservative.

The spring law is the contact stage's (e.g. ``jointwear.contact.contact_law("nlcp",
...)``), passed in: anything with ``pressure(delta)`` and ``force_area``
(:class:`PressureLaw`) will do, so this module imports nothing from the contact
layer above it (see :mod:`jointwear.mechanism.impact.force_laws`).
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.geometry.contour import BushingContour, Pin, ray_distance_derivative

__all__ = [
    "PowerPressureLaw",
    "PressureLaw",
    "force_area",
    "spring_gap",
    "spring_resultant",
]

FloatArray = NDArray[np.float64]


class PressureLaw(Protocol):
    """Pressure on a bushing node as a function of its penetration.

    :class:`jointwear.contact.SpringLaw` and its subclasses are such laws.

    Attributes
    ----------
    force_area : float or None
        Area that turns a node's pressure into its force [m^2]; ``None``: the node's
        own area ``r_j dtheta b``.
    """

    force_area: float | None

    def pressure(self, penetration: FloatArray) -> FloatArray:
        """Pressure [Pa] for penetration [m] (>= 0)."""
        ...


@runtime_checkable
class PowerPressureLaw(Protocol):
    """A power law ``p = coefficient delta^exponent``: its stored energy is closed-form.

    :class:`jointwear.contact.PowerLaw` (the ``nlcp`` and ``winkler`` laws) is one.

    Attributes
    ----------
    coefficient : float
        Pressure coefficient [Pa / m^exponent].
    exponent : float
        Exponent [-].
    force_area : float or None
        See :class:`PressureLaw` [m^2].
    """

    coefficient: float
    exponent: float
    force_area: float | None

    def pressure(self, penetration: FloatArray) -> FloatArray:
        """Pressure [Pa] for penetration [m] (>= 0)."""
        ...


def force_area(contour: BushingContour, law: PressureLaw) -> FloatArray | float:
    """Area that turns each node's pressure into force [m^2].

    Parameters
    ----------
    contour : BushingContour
        Bushing contour (its node areas ``r_j dtheta b``).
    law : PressureLaw
        The spring law; its ``force_area``, if set, replaces the node areas.
    """
    return contour.spring_area if law.force_area is None else float(law.force_area)


def spring_gap(contour: BushingContour, pin: Pin, eccentricity: ArrayLike) -> FloatArray:
    """Signed gap function of the displaced pin, ``max_j (t_j - r_j)`` [m].

    Positive where some node is penetrated (the largest penetration), negative
    (minus the smallest gap) while the pin is free; zero at contact start/end.

    Parameters
    ----------
    contour : BushingContour
        Bushing contour.
    pin : Pin
        The pin.
    eccentricity : array_like, shape (..., 2)
        Pin-centre position relative to the bushing centre [m].
    """
    return np.max(contour.penetration(pin, eccentricity, signed=True), axis=-1)


def spring_resultant(
    contour: BushingContour,
    pin: Pin,
    eccentricity: ArrayLike,
    law: PressureLaw,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Elastic force of the bushing springs on the displaced pin's wall, and its energy.

    Parameters
    ----------
    contour : BushingContour
        Current bushing contour (circular or worn).
    pin : Pin
        The pin.
    eccentricity : array_like, shape (..., 2)
        Pin-centre position relative to the bushing centre [m].
    law : PressureLaw
        Pressure law of the nodes (:func:`jointwear.contact.contact_law`), e.g. the
        ``nlcp`` or ``winkler`` law. ``law.force_area`` (the paper's NLCP spring
        area) or the node areas ``r_j dtheta b`` turn pressure into force.

    Returns
    -------
    force : ndarray, shape (..., 2)
        ``F_el = sum_j A_j p(delta_j) grad t_j``: the force with which the pin
        presses on the bushing (the bushing pushes the pin with ``-F_el``) [N].
    potential : ndarray, shape (...)
        Stored energy ``sum_j A_j int_0^delta_j p`` [J]; exact for a
        :class:`PowerPressureLaw`, trapezoidal (4 panels per
        node) for other laws.
    max_penetration : ndarray, shape (...)
        Largest node penetration [m].
    """
    e = np.asarray(eccentricity, dtype=float)
    ex, ey = e[..., 0:1], e[..., 1:2]
    theta = contour.theta
    delta = contour.penetration(pin, e)
    pressure = np.asarray(law.pressure(delta), dtype=float)
    area = force_area(contour, law)
    node_force = area * pressure
    d_ex, d_ey = ray_distance_derivative(theta, ex, ey, pin.radius)
    force = np.stack(
        [np.sum(node_force * d_ex, axis=-1), np.sum(node_force * d_ey, axis=-1)], axis=-1
    )
    if isinstance(law, PowerPressureLaw):
        energy = law.coefficient * delta ** (law.exponent + 1.0) / (law.exponent + 1.0)
    else:
        fractions = np.linspace(0.0, 1.0, 5)
        samples = np.stack([law.pressure(f * delta) for f in fractions], axis=0)
        energy = np.trapezoid(samples, dx=0.25, axis=0) * delta
    potential = np.sum(area * energy, axis=-1)
    return force, potential, np.max(delta, axis=-1)
