r"""The contact of a worn bushing that turns with its body: evaluated in the body's frame.

An unworn bushing is a circle and looks the same in every frame; a worn one carries
its scar with the body it sits in. The contact force laws
(:class:`~jointwear.mechanism.impact.joint_contact.JointContact`) read the pin's
offset in the bushing's own frame: the clearance vector ``e`` (first body's joint
centre minus the second's, global) is turned by ``-theta_b``, the bushing body's
angle, and reversed when the bushing sits on the first body (``e`` then points from
the pin's centre to the bushing's):

.. math::

    \mathbf e_b = s\, R(-\theta_b)\, \mathbf e, \qquad s = \pm 1 .

The force and the normal the law returns are turned back, ``J = s R(theta_b) J_b``.
Penetration rate and slip are dot products of ``e'`` with the normal and the tangent:
the same rotation of ``e'`` leaves them unchanged, and reversing ``e`` and ``e'``
together reverses ``J`` and ``n`` and keeps the slip (``t`` reverses with ``n``).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from jointwear.mechanism.impact.joint_contact import JointContact

__all__ = ["contact_force_in_frame", "to_bushing_frame"]


def to_bushing_frame(angle: float, sign: float, x: float, y: float) -> tuple[float, float]:
    """A global vector in the bushing's frame, ``s R(-theta_b) (x, y)``.

    Parameters
    ----------
    angle : float
        The bushing body's angle ``theta_b`` [rad].
    sign : float
        ``s``: ``+1`` with the bushing on the joint's second body, ``-1`` on the first [-].
    x, y : float
        The vector's global components [any unit].
    """
    c, s = math.cos(angle), math.sin(angle)
    return sign * (c * x + s * y), sign * (c * y - s * x)


def contact_force_in_frame(
    contact: JointContact,
    angle: float,
    sign: float,
    e: tuple[float, float],
    v: tuple[float, float],
    spin: float,
    approach: float,
    film_spin: float | None = None,
) -> tuple[float, float, float, float, float, float, float, float]:
    """:meth:`JointContact.force` on a bushing turned by ``angle``, returned in the global frame.

    Parameters
    ----------
    contact : JointContact
        The joint's contact model, its contour in the bushing body's frame.
    angle : float
        The bushing body's angle ``theta_b`` [rad].
    sign : float
        ``s`` of :func:`to_bushing_frame` [-].
    e, v : tuple of float
        Clearance vector [m] and its rate [m/s], global.
    spin : float
        The spin the contact multiplies by its friction arm [rad/s].
    approach : float
        ``delta'^-`` of the current contact [m/s].
    film_spin : float, optional
        Sum of the two bodies' angular velocities, for an oil film [rad/s] (a scalar: the
        frame's turn by ``s R(-theta_b)`` is a rotation and leaves it as it is).

    Returns
    -------
    tuple of float
        As :meth:`JointContact.force`, with ``J`` and ``n`` global.
    """
    ex, ey = to_bushing_frame(angle, sign, e[0], e[1])
    vx, vy = to_bushing_frame(angle, sign, v[0], v[1])
    jx, jy, normal, tangential, nx, ny, delta, slip = contact.force(
        ex, ey, vx, vy, spin, approach, film_spin
    )
    # back: s R(theta_b) is the inverse of s R(-theta_b)
    jx, jy = to_bushing_frame(-angle, sign, jx, jy)
    nx, ny = to_bushing_frame(-angle, sign, nx, ny)
    return jx, jy, normal, tangential, nx, ny, delta, slip
