"""A free pin inside a fixed bushing: one impact of the contact force law in isolation.

:func:`free_pin_impact` flies a pin from the bushing centre into the wall and integrates
it (:func:`~jointwear.mechanism.impact.integrator.integrate_contacts`) until it leaves
the wall again: the effective coefficient of restitution of a force law, checked
against :func:`~jointwear.mechanism.impact.force_laws.hysteresis_restitution`.
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConvergenceError
from jointwear.mechanism.impact.integrator import (
    ContactHistory,
    ContactSystemBase,
    integrate_contacts,
)
from jointwear.mechanism.impact.joint_contact import JointContact

__all__ = ["FreePinSystem", "free_pin_impact"]

FloatArray = NDArray[np.float64]


class FreePinSystem(ContactSystemBase):
    """A free pin of mass ``m`` inside a fixed bushing (to test one impact in isolation).

    State ``y = (e_x, e_y, e'_x, e'_y, W)`` with ``W`` the work of the constant
    external force [J]. The bushing does not move and the pin does not spin.

    Parameters
    ----------
    mass : float
        Pin mass [kg].
    contact : JointContact
        Contact force model.
    external_force : tuple of float
        Constant force on the pin, e.g. its weight [N].
    """

    def __init__(
        self, mass: float, contact: JointContact, external_force: tuple[float, float] = (0.0, 0.0)
    ) -> None:
        self.mass = float(mass)
        self.contact = contact
        self.external_force = (float(external_force[0]), float(external_force[1]))

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        return float(y[0]), float(y[1]), float(y[2]), float(y[3])

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        ex, ey, vx, vy = (float(v) for v in y[:4])
        jx, jy, *_ = self.contact.force(ex, ey, vx, vy, 0.0, impact_velocity)
        fx, fy = self.external_force
        return np.array([vx, vy, (fx - jx) / self.mass, (fy - jy) / self.mass, fx * vx + fy * vy])

    def energy(self, t: float, y: ArrayLike) -> float:
        """Kinetic + contact elastic energy [J]."""
        ex, ey, vx, vy = (float(v) for v in np.asarray(y, dtype=float)[:4])
        return 0.5 * self.mass * (vx * vx + vy * vy) + self.contact.potential(ex, ey)


def free_pin_impact(
    contact: JointContact,
    mass: float,
    impact_velocity: float,
    direction: float = 0.0,
    method: str = "LSODA",
    rtol: float = 1e-10,
    atol: float = 1e-14,
) -> tuple[float, ContactHistory]:
    """One impact of a free pin on the bushing wall; effective restitution.

    The pin starts at the bushing centre moving along ``direction`` at
    ``impact_velocity`` and is integrated until it leaves the wall again.

    Parameters
    ----------
    contact : JointContact
        Contact force model (its clearance and law).
    mass : float
        Pin mass [kg].
    impact_velocity : float
        Approach velocity [m/s], > 0.
    direction : float
        Direction of flight [rad].
    method : str
        ``solve_ivp`` method.
    rtol, atol : float
        Integrator tolerances.

    Returns
    -------
    restitution : float
        ``-delta'^+ / delta'^-``: normal separation velocity over approach
        velocity [-].
    history : ContactHistory
        The integration record.
    """
    system = FreePinSystem(mass, contact)
    u = (math.cos(direction), math.sin(direction))
    y0 = np.array([0.0, 0.0, impact_velocity * u[0], impact_velocity * u[1], 0.0])
    gap = contact.clearance if not contact.distributed else contact.touch_offset(direction)
    flight = gap / impact_velocity
    # generous bound on the contact duration (Hertz: 2.94 (m^2 / (K^2 v))^(1/5))
    duration = 50.0 * (mass**2 / (contact.stiffness**2 * impact_velocity)) ** 0.2
    history = integrate_contacts(
        system,
        (0.0, 2.0 * flight + duration),
        y0,
        in_contact=False,
        method=method,
        rtol=rtol,
        atol=atol,
        stop_after_separations=1,
    )
    if not history.separation_times:
        raise ConvergenceError("free pin: no separation within the integration window")
    return history.separation_velocities[0] / history.impact_velocities[0], history
