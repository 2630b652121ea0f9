r"""Contact–impact dynamics of the slider–crank: the pin moves freely in the clearance.

The massless-link model (:mod:`jointwear.mechanism.slider_crank`) assumes that the
pin never leaves the bushing wall. Here the assumption is dropped: pin and bushing
are connected only through a contact force that exists while they overlap, so the
pin can separate, fly across the clearance and hit the wall again.

Generalized coordinates
-----------------------
The crank is driven kinematically, ``phi_1 = omega t``, so the crank pin
``B = l1 (cos phi_1, sin phi_1)`` is known at every time. Without clearance the
mechanism would have no degree of freedom left; the clearance joint frees two,
taken as

* ``theta`` — rod angle (B to the rod-end joint centre C, counter-clockwise
  from +x): the rod turns about B, ``C = B + l2 (cos theta, sin theta)``;
* ``x_3`` — slider position: the slider-side joint centre is ``D = (x_3, 0)``.

The clearance vector (pin-centre offset, paper's massless link ``CD``) is then a
function of the coordinates, ``e = C - D``; ``(theta, x_3) <-> (e_x, e_y)`` is a
local change of variables, so these are exactly the "two extra degrees of
freedom" of the free pin. The mass matrix in ``(theta, x_3)`` is diagonal.

Equations of motion
-------------------
``J`` is the contact force on the slider-side body (slider), the rod feels
``-J`` at the contact point ``P = C + rho n``, with ``n`` the contact normal
(direction in which the pin presses on the bushing, along ``e`` for a circular
bushing), ``t = (-n_y, n_x)`` and ``rho = R_p`` when the bushing is in the slider
(pin on the rod) or ``rho = -R_b`` when it is in the rod end. With
``t_theta = (-sin theta, cos theta)``:

.. math::

    (I_2 + m_2 l_2^2/4)\,\ddot\theta &= -m_2 \tfrac{l_2}{2}\, \mathbf t_\theta\cdot\mathbf a_B
        - m_2 g \tfrac{l_2}{2}\cos\theta - l_2\, \mathbf t_\theta\cdot\mathbf J - \rho F_T \\
    m_3\,\ddot x_3 &= J_x + F_{spring}(x_3)

(moments about the accelerating point ``B``; ``a_B = -omega^2 B``), with
``J = F_N n + F_T t``: normal force ``F_N`` from ``dynamics.force_law``
(:mod:`jointwear.mechanism.force_laws`) and friction
``F_T = mu c_d(v_T) F_N sign(v_T)``, ``v_T = e' . t + rho theta'`` the slip of the
rod-side surface over the slider-side one. The crank torque that keeps ``omega``
constant is, as in the massless-link model,
``T = B x R_B + m_1 g B_x / 2``, ``R_B = m_2 (a_G + g y) + J``; its work
``W = int T omega dt`` is integrated with the state, so the energy balance
``E(t) - E(0) = W(t) - dissipation`` can be checked
(:meth:`SliderCrankContactSystem.energy`).

Integration
-----------
``scipy.integrate.solve_ivp`` (``dynamics.integrator``: LSODA by default,
Radau/BDF for stiff contact, RK45/DOP853 explicit) with terminal events at the
contact start (penetration rises through zero) and contact end (falls through
zero); the integration restarts at each event, so no step straddles the change of
force law, and the approach velocity ``delta'^-`` of the damping term is taken
at the contact start. A non-terminal event at ``delta' = 0`` records each
penetration maximum. ``dynamics.revolutions_settle`` revolutions are integrated
first so that the start-up transient decays; the next revolution is sampled
(dense output) at ``simulation.steps_per_revolution`` crank angles.

The initial state is the massless-link solution at ``phi_1 = 0`` (rod angle,
slider position and their rates), with the pin pushed into the wall by the
static penetration of the massless-link load.
"""

from __future__ import annotations

import functools
import math
import os
import time as _time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.laws import ContactParameters, SpringLaw
from jointwear.errors import ConfigError, ContactLossWarning, ConvergenceError, JointwearError
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.mechanism import force_laws
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.slider_crank import (
    SliderCrank,
    ideal_motion,
    inverse_dynamics,
    massless_link_load,
    slider_crank_cycle,
    solve_massless_link,
)

if TYPE_CHECKING:
    from scipy.integrate import OdeSolution

    from jointwear.config import Config, DynamicsConfig

__all__ = [
    "INTEGRATORS",
    "ContactHistory",
    "ContactImpactSettings",
    "ContactImpactSolution",
    "FreePinSystem",
    "JointContact",
    "SampledRevolution",
    "Segment",
    "SliderCrankContactSystem",
    "contact_impact_load",
    "free_pin_impact",
    "integrate_contacts",
    "integrate_revolution",
    "sampled_solution",
    "solve_contact_impact",
]

FloatArray = NDArray[np.float64]
#: the keys of :meth:`SliderCrankContactSystem.evaluate`, in the compiled tuple's order
_EVALUATE_KEYS = (
    "theta_ddot", "x3_ddot", "force_x", "force_y", "normal_force", "friction_force",
    "normal_x", "normal_y", "penetration", "slip", "crank_torque", "ex", "ey",
)  # fmt: skip


def impact_kernel() -> Any:
    """The compiled right-hand side (module), imported on first use.

    ``None`` without numba, or when ``JOINTWEAR_NO_NUMBA`` is set (the switch of the
    compiled contact kernel, :func:`jointwear.contact.kernel.compiled_available`).
    """
    if os.environ.get("JOINTWEAR_NO_NUMBA", "") not in ("", "0"):
        return None
    return _load_kernel()


@functools.cache
def _load_kernel() -> Any:
    try:
        from jointwear.mechanism import _impact_compiled
    except ImportError:
        return None
    return _impact_compiled


#: ``solve_ivp`` methods accepted by ``dynamics.integrator``
INTEGRATORS: tuple[str, ...] = ("LSODA", "Radau", "BDF", "RK45", "DOP853")


# ------------------------------------------------------------------ settings


@dataclass(frozen=True)
class ContactImpactSettings:
    """Settings of the contact–impact model (the ``[dynamics]`` keys it uses).

    Parameters
    ----------
    force_law : str
        Normal force law, one of :data:`~jointwear.mechanism.force_laws.FORCE_LAWS`.
    restitution : float
        Coefficient of restitution ``c_e``, ``0 < c_e <= 1`` [-].
    friction_coefficient : float
        Coulomb coefficient ``mu >= 0`` [-].
    friction_velocity_tolerance : float
        ``v_0`` of the friction ramp: no friction below this slip speed [m/s].
    friction_velocity_full : float, optional
        ``v_1 > v_0``: full friction above this slip speed [m/s]; default ``2 v_0``.
    impact_velocity_floor : float
        Lower bound of the approach velocity ``delta'^-`` in the damping term
        (a contact that starts with a vanishing approach velocity would have
        unbounded damping) [m/s].
    integrator : str
        ``solve_ivp`` method, one of :data:`INTEGRATORS`.
    rtol : float
        Relative tolerance of the integrator [-].
    atol : float
        Absolute tolerance of the integrator, on every state component (SI) [-].
    revolutions_settle : int
        Revolutions integrated before the recorded one [-].
    max_step : float, optional
        Largest integrator step [s]; default one sampling step ``2 pi / (N omega)``.
    """

    force_law: str = "lankarani-nikravesh"
    restitution: float = 0.9
    friction_coefficient: float = 0.0
    friction_velocity_tolerance: float = 1e-4
    friction_velocity_full: float | None = None
    impact_velocity_floor: float = 1e-3
    integrator: str = "LSODA"
    rtol: float = 1e-8
    atol: float = 1e-10
    revolutions_settle: int = 2
    max_step: float | None = None

    def __post_init__(self) -> None:
        if self.force_law not in force_laws.FORCE_LAWS:
            raise ConfigError(
                f"dynamics.force_law: unknown force law {self.force_law!r}; choose from "
                + ", ".join(repr(name) for name in force_laws.FORCE_LAWS)
            )
        force_laws.hysteresis_factor(self.force_law, self.restitution)  # validates c_e
        if not (math.isfinite(self.friction_coefficient) and self.friction_coefficient >= 0):
            raise ConfigError(
                f"dynamics.friction_coefficient: must be >= 0, got {self.friction_coefficient!r}"
            )
        if not self.friction_velocity_tolerance > 0:
            raise ConfigError("dynamics.friction_velocity_tolerance: must be > 0")
        if (
            self.friction_velocity_full is not None
            and not self.friction_velocity_full > self.friction_velocity_tolerance
        ):
            raise ConfigError(
                "dynamics.friction_velocity_full: must be > dynamics.friction_velocity_tolerance"
            )
        if not self.impact_velocity_floor > 0:
            raise ConfigError("dynamics.impact_velocity_floor: must be > 0")
        if self.integrator not in INTEGRATORS:
            raise ConfigError(
                f"dynamics.integrator: {self.integrator!r} is not allowed; choose from "
                + ", ".join(repr(name) for name in INTEGRATORS)
            )
        if not 0 < self.rtol < 1 or not self.atol > 0:
            raise ConfigError("dynamics.rtol, dynamics.atol: need 0 < rtol < 1 and atol > 0")
        if self.revolutions_settle < 0:
            raise ConfigError("dynamics.revolutions_settle: must be >= 0")
        if self.max_step is not None and not self.max_step > 0:
            raise ConfigError("dynamics.max_step: must be > 0")

    @property
    def friction_full_speed(self) -> float:
        """``v_1`` of the friction ramp [m/s]."""
        if self.friction_velocity_full is not None:
            return self.friction_velocity_full
        return 2.0 * self.friction_velocity_tolerance

    @classmethod
    def from_config(cls, dynamics: DynamicsConfig) -> ContactImpactSettings:
        """Build from the validated ``[dynamics]`` section."""
        return cls(
            force_law=dynamics.force_law,
            restitution=dynamics.restitution,
            friction_coefficient=dynamics.friction_coefficient,
            friction_velocity_tolerance=dynamics.friction_velocity_tolerance,
            friction_velocity_full=dynamics.friction_velocity_full,
            impact_velocity_floor=dynamics.impact_velocity_floor,
            integrator=dynamics.integrator,
            rtol=dynamics.rtol,
            atol=dynamics.atol,
            revolutions_settle=dynamics.revolutions_settle,
            max_step=dynamics.max_step,
        )


# ------------------------------------------------------------------ contact force


class JointContact:
    """Normal and friction force between pin and bushing for a relative state.

    The two bodies are the *rod side* (joint centre ``C``) and the *slider side*
    (joint centre ``D``); ``e = C - D``. Whichever carries the bushing, the force
    on the slider side is ``J = F_N n + F_T t`` with ``n`` the contact normal
    along which the pin presses on the bushing (for a circular bushing
    ``n = e / |e|``) and ``t = (-n_y, n_x)``.

    Parameters
    ----------
    force_law : str
        One of :data:`~jointwear.mechanism.force_laws.FORCE_LAWS`.
    clearance : float
        Radial clearance ``c = R_b - R_p`` [m] (point laws).
    stiffness : float
        ``K`` of the point laws [N/m^n].
    exponent : float
        ``n`` of the point laws [-].
    restitution : float
        ``c_e`` [-].
    friction_coefficient : float
        ``mu`` [-].
    friction_velocity_tolerance, friction_full_speed : float
        ``v_0``, ``v_1`` of the friction ramp [m/s].
    friction_arm : float
        ``rho``: signed distance from ``C`` to the contact point along ``n``
        (``R_p`` with the pin on the rod side, ``-R_b`` with the bushing on the
        rod side) [m].
    impact_velocity_floor : float
        Smallest ``delta'^-`` used in the damping term [m/s].
    contour : BushingContour, optional
        Bushing contour of the distributed laws (``nlcp``, ``winkler``).
    pin : Pin, optional
        The pin (distributed laws).
    spring_law : SpringLaw, optional
        Node pressure law (distributed laws).
    """

    def __init__(
        self,
        force_law: str,
        clearance: float,
        stiffness: float,
        restitution: float,
        exponent: float = 1.5,
        friction_coefficient: float = 0.0,
        friction_velocity_tolerance: float = 1e-4,
        friction_full_speed: float | None = None,
        friction_arm: float = 0.0,
        impact_velocity_floor: float = 1e-3,
        contour: BushingContour | None = None,
        pin: Pin | None = None,
        spring_law: SpringLaw | None = None,
    ) -> None:
        self.force_law = force_law
        self.hysteresis = force_laws.hysteresis_factor(force_law, restitution)
        self.restitution = restitution
        self.clearance = float(clearance)
        self.stiffness = float(stiffness)
        self.exponent = float(exponent)
        self.friction_coefficient = float(friction_coefficient)
        self.v0 = float(friction_velocity_tolerance)
        self.v1 = 2.0 * self.v0 if friction_full_speed is None else float(friction_full_speed)
        self.friction_arm = float(friction_arm)
        self.impact_velocity_floor = float(impact_velocity_floor)
        self.distributed = force_law in force_laws.DISTRIBUTED_LAWS
        # a worn bushing under a point law: the clearance grows by the wear depth in
        # the direction of the pin (periodic linear interpolation of the profile)
        self._wear: FloatArray | None = None
        if not self.distributed and contour is not None and np.any(contour.wear_depth):
            self._wear = np.append(np.asarray(contour.wear_depth, dtype=float),
                                   float(contour.wear_depth[0]))
        if self.distributed:
            if contour is None or pin is None or spring_law is None:
                raise ConfigError(
                    f"dynamics.force_law: {force_law!r} needs a bushing contour, pin and spring law"
                )
            contour.check_pin(pin)
            # node data for the fast evaluation of the springs (:meth:`_springs`)
            self._cos = np.cos(contour.theta)
            self._sin = np.sin(contour.theta)
            self._radius = np.asarray(contour.radius, dtype=float)
            self._area = np.broadcast_to(
                contour.spring_area
                if spring_law.force_area is None
                else float(spring_law.force_area),
                self._radius.shape,
            )
            self._pin_radius_sq = pin.radius**2
        self.contour = contour
        self.pin = pin
        self.spring_law = spring_law

    def _springs(self, ex: float, ey: float) -> tuple[float, float, float]:
        """Elastic resultant ``(F_x, F_y)`` [N] and signed gap [m] of the distributed law.

        Same as :func:`~jointwear.mechanism.force_laws.spring_resultant` and
        :func:`~jointwear.mechanism.force_laws.spring_gap`, evaluated only on the
        penetrated nodes (the integrator calls it at every step).
        """
        along = self._cos * ex + self._sin * ey
        across = self._cos * ey - self._sin * ex
        root = np.sqrt(self._pin_radius_sq - across * across)
        depth = along + root - self._radius
        gap = float(depth.max())
        if gap <= 0.0:
            return 0.0, 0.0, gap
        touch = depth > 0.0
        c, sn, ratio = self._cos[touch], self._sin[touch], across[touch] / root[touch]
        force = self._area[touch] * self.spring_law.pressure(depth[touch])
        fx = float(np.dot(force, c + sn * ratio))
        fy = float(np.dot(force, sn - c * ratio))
        return fx, fy, gap

    @classmethod
    def from_config(cls, config: Config, contour: BushingContour | None = None) -> JointContact:
        """Contact model of ``config``'s joint with its ``[dynamics]`` settings.

        Parameters
        ----------
        config : jointwear.config.Config
            Validated configuration.
        contour : BushingContour, optional
            Bushing contour for ``nlcp``/``winkler``; default the unworn circle
            with ``contact.nodes`` nodes.
        """
        settings = ContactImpactSettings.from_config(config.dynamics)
        params = ContactParameters.from_config(config)
        stiffness = force_laws.pin_in_hole_stiffness(
            params.pin_radius,
            params.bushing_radius,
            params.pin_youngs_modulus,
            params.pin_poisson_ratio,
            params.bushing_youngs_modulus,
            params.bushing_poisson_ratio,
        )
        arm = (
            params.pin_radius
            if config.mechanism.bushing_body == "slider"
            else (-params.bushing_radius)
        )
        extra: dict[str, Any] = {}
        if settings.force_law in force_laws.DISTRIBUTED_LAWS:
            from jointwear.contact import contact_law

            extra = {
                "contour": contour
                if contour is not None
                else BushingContour.circle(
                    params.bushing_radius, config.contact.nodes, params.axial_length
                ),
                "pin": Pin(params.pin_radius),
                "spring_law": contact_law(settings.force_law, params),
            }
        elif contour is not None:
            extra = {"contour": contour}
        return cls(
            force_law=settings.force_law,
            clearance=params.bushing_radius - params.pin_radius,
            stiffness=stiffness,
            restitution=settings.restitution,
            exponent=1.5,
            friction_coefficient=settings.friction_coefficient,
            friction_velocity_tolerance=settings.friction_velocity_tolerance,
            friction_full_speed=settings.friction_full_speed,
            friction_arm=arm,
            impact_velocity_floor=settings.impact_velocity_floor,
            **extra,
        )

    # -------------------------------------------------------------- geometry
    def clearance_at(self, ex: float, ey: float) -> float:
        """Radial clearance in the direction of ``e`` [m] (point laws; the wear adds to it)."""
        if self._wear is None:
            return self.clearance
        nodes = self._wear.size - 1
        position = (math.atan2(ey, ex) % (2.0 * math.pi)) * nodes / (2.0 * math.pi)
        index = min(int(position), nodes - 1)
        fraction = position - index
        return self.clearance + (1.0 - fraction) * self._wear[index] + fraction * self._wear[
            index + 1
        ]

    def gap(self, ex: float, ey: float) -> float:
        """Signed penetration: ``> 0`` in contact (largest penetration), ``< 0`` free [m]."""
        if self.distributed:
            return self._springs(ex, ey)[2]
        return math.hypot(ex, ey) - self.clearance_at(ex, ey)

    def gap_rate(self, ex: float, ey: float, vx: float, vy: float) -> float:
        """Rate of the gap along ``e / |e|``, ``delta' = e . e' / |e|`` [m/s]."""
        r = math.hypot(ex, ey)
        if r == 0.0:
            return 0.0
        return (ex * vx + ey * vy) / r

    def potential(self, ex: float, ey: float) -> float:
        """Elastic energy stored in the contact [J]."""
        if self.distributed:
            _, energy, _ = force_laws.spring_resultant(
                self.contour, self.pin, np.array([ex, ey]), self.spring_law
            )
            return float(energy)
        delta = math.hypot(ex, ey) - self.clearance_at(ex, ey)
        if delta <= 0.0:
            return 0.0
        return self.stiffness * delta ** (self.exponent + 1.0) / (self.exponent + 1.0)

    def static_offset(self, load: float, direction: float) -> float:
        """Length ``|e|`` at which the elastic force along ``direction`` equals ``load`` [m].

        Parameters
        ----------
        load : float
            Load magnitude [N].
        direction : float
            Direction of ``e`` (and of the load) [rad].
        """
        if load <= 0.0:
            return self._touch(direction)
        if not self.distributed:
            touch = self._touch(direction)
            return touch + (load / self.stiffness) ** (1.0 / self.exponent)
        unit = np.array([math.cos(direction), math.sin(direction)])
        lower = self._touch(direction)

        def residual(s: float) -> float:
            force, _, _ = force_laws.spring_resultant(
                self.contour, self.pin, s * unit, self.spring_law
            )
            return float(force @ unit) - load

        upper = lower + 1e-6
        while residual(upper) < 0.0:
            upper = lower + 2.0 * (upper - lower)
            if upper - lower > self.pin.radius:
                raise ConvergenceError(
                    f"load: {load:.6g} N cannot be carried by the bushing springs"
                )
        from scipy.optimize import brentq  # lazy: keeps `jointwear` quick to start

        return float(brentq(residual, lower, upper, xtol=1e-16, rtol=1e-14))

    def _touch(self, direction: float) -> float:
        """Offset ``|e|`` along ``direction`` at which the pin first touches the contour [m]."""
        if not self.distributed:
            return self.clearance_at(math.cos(direction), math.sin(direction))
        unit = np.array([math.cos(direction), math.sin(direction)])
        upper = 2.0 * (float(self.contour.radius.max()) - self.pin.radius)

        def gap(s: float) -> float:
            return float(force_laws.spring_gap(self.contour, self.pin, s * unit))

        from scipy.optimize import brentq

        return float(brentq(gap, 0.0, upper, xtol=1e-16, rtol=1e-14))

    # -------------------------------------------------------------- force
    def force(
        self, ex: float, ey: float, vx: float, vy: float, spin: float, impact_velocity: float
    ) -> tuple[float, float, float, float, float, float, float, float]:
        """Contact force on the slider side for a relative state.

        Parameters
        ----------
        ex, ey : float
            ``e = C - D`` [m].
        vx, vy : float
            ``e'`` [m/s].
        spin : float
            Angular velocity of the rod-side body (the slider side does not turn)
            [rad/s].
        impact_velocity : float
            Approach velocity ``delta'^-`` of the current contact [m/s].

        Returns
        -------
        tuple of float
            ``(J_x, J_y, F_N, F_T, n_x, n_y, penetration, slip)``: force on the
            slider side [N], normal and friction components [N], unit normal [-],
            largest penetration [m], slip velocity ``v_T`` [m/s].
        """
        r = math.hypot(ex, ey)
        nx, ny = (ex / r, ey / r) if r > 0.0 else (1.0, 0.0)
        rate = nx * vx + ny * vy
        if self.distributed:
            fx, fy, delta = self._springs(ex, ey)
            elastic = math.hypot(fx, fy)
            if elastic > 0.0:
                nx, ny = fx / elastic, fy / elastic
                rate = nx * vx + ny * vy
        else:
            delta = r - self.clearance_at(ex, ey)
            elastic = self.stiffness * delta**self.exponent if delta > 0.0 else 0.0
        slip = -ny * vx + nx * vy + self.friction_arm * spin
        if elastic <= 0.0:
            return 0.0, 0.0, 0.0, 0.0, nx, ny, delta, slip
        # a sample that the event search put just outside a contact has no approach
        # velocity (nan): the floor stands in for it
        floor = self.impact_velocity_floor
        approach = impact_velocity if impact_velocity > floor else floor
        normal = elastic * (1.0 + self.hysteresis * rate / approach)
        normal = max(normal, 0.0)
        tangential = 0.0
        if self.friction_coefficient > 0.0 and normal > 0.0:
            speed = abs(slip)
            if speed > self.v0:
                s = min((speed - self.v0) / (self.v1 - self.v0), 1.0)
                tangential = (
                    self.friction_coefficient
                    * s
                    * s
                    * (3.0 - 2.0 * s)
                    * normal
                    * math.copysign(1.0, slip)
                )
        jx = normal * nx - tangential * ny
        jy = normal * ny + tangential * nx
        return jx, jy, normal, tangential, nx, ny, delta, slip


# ------------------------------------------------------------------ systems


class ContactSystem(Protocol):
    """What :func:`integrate_contacts` needs from a mechanical system."""

    contact: JointContact

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """Time derivative of the state."""

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        """``(e_x, e_y, e'_x, e'_y)`` [m, m/s]."""

    def gap(self, t: float, y: FloatArray) -> float:
        """Signed penetration [m]: ``> 0`` in contact."""

    def gap_rate(self, t: float, y: FloatArray) -> float:
        """Rate of the gap [m/s]."""


class ContactSystemBase:
    """The gap functions of a contact system, from its clearance state.

    A system with ``contact`` and ``clearance_state`` inherits them; the integrator
    calls them at every step (contact events).
    """

    contact: JointContact

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        """``(e_x, e_y, e'_x, e'_y)`` [m, m/s]."""
        raise NotImplementedError

    def gap(self, t: float, y: FloatArray) -> float:
        """Signed penetration of the state (:meth:`JointContact.gap`) [m]."""
        ex, ey, _, _ = self.clearance_state(t, y)
        return self.contact.gap(ex, ey)

    def gap_rate(self, t: float, y: FloatArray) -> float:
        """Rate of the gap of the state (:meth:`JointContact.gap_rate`) [m/s]."""
        return self.contact.gap_rate(*self.clearance_state(t, y))

    def gap_and_rate(self, t: float, y: FloatArray) -> tuple[float, float]:
        """:meth:`gap` and :meth:`gap_rate` together (one call per integrator step)."""
        return self.gap(t, y), self.gap_rate(t, y)

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """Time derivative of the state."""
        raise NotImplementedError

    def rhs_function(self, impact_velocity: float) -> Callable[[float, FloatArray], FloatArray]:
        """``f(t, y)`` of the integrator for a contact with approach velocity
        ``impact_velocity`` [m/s]."""
        return lambda t, y: self.rhs(t, y, impact_velocity)


class SliderCrankContactSystem(ContactSystemBase):
    """Slider–crank with a free pin in the clearance joint (module docstring).

    State ``y = (theta, x_3, theta', x_3', W)``: rod angle [rad], slider position
    [m], their rates [rad/s, m/s] and the crank work ``W = int T omega dt`` [J].

    Parameters
    ----------
    mechanism : SliderCrank
        Masses, lengths, spring and gravity.
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    contact : JointContact
        Contact force model of the joint.
    """

    def __init__(
        self,
        mechanism: SliderCrank,
        crank_speed: float,
        contact: JointContact,
        compiled: bool | None = None,
    ) -> None:
        self.mechanism = mechanism
        self.omega = float(crank_speed)
        self.contact = contact
        m = mechanism
        self._inertia_b = m.rod_inertia + 0.25 * m.rod_mass * m.rod_length**2
        if self._inertia_b <= 0.0 or m.slider_mass <= 0.0:
            raise ConfigError(
                "mechanism.rod_mass, mechanism.slider_mass: the contact-impact model needs a "
                "rod with inertia and a slider with mass (the pin's degrees of freedom)"
            )
        # the compiled right-hand side covers the point laws (the distributed laws sum
        # over the contour's nodes with NumPy)
        kernel = impact_kernel() if compiled is not False and not contact.distributed else None
        if compiled and kernel is None:
            raise ConfigError(
                "dynamics: the compiled right-hand side needs numba and a point force law"
            )
        self._kernel = kernel
        if kernel is not None:
            self._parameters = self._kernel_parameters()
            self._wear = contact._wear if contact._wear is not None else np.empty(0)

    @property
    def compiled(self) -> bool:
        """Whether :meth:`rhs` and the gap functions run compiled (numba)."""
        return self._kernel is not None

    def _kernel_parameters(self) -> FloatArray:
        """The parameter array of the compiled right-hand side (``_impact_compiled.P_*``)."""
        m, c, k = self.mechanism, self.contact, self._kernel
        values = {
            k.P_CRANK: m.crank_length,
            k.P_ROD: m.rod_length,
            k.P_OMEGA: self.omega,
            k.P_ROD_MASS: m.rod_mass,
            k.P_GRAVITY: m.gravity,
            k.P_INERTIA_B: self._inertia_b,
            k.P_SLIDER_MASS: m.slider_mass,
            k.P_CRANK_MASS: m.crank_mass,
            k.P_SPRING_PULL: 1.0 if m.spring_mode == "pull" else 0.0,
            k.P_PRELOAD: m.spring_preload,
            k.P_SPRING_STIFFNESS: m.spring_stiffness,
            k.P_CLEARANCE: c.clearance,
            k.P_STIFFNESS: c.stiffness,
            k.P_EXPONENT: c.exponent,
            k.P_HYSTERESIS: c.hysteresis,
            k.P_FRICTION: c.friction_coefficient,
            k.P_V0: c.v0,
            k.P_V1: c.v1,
            k.P_ARM: c.friction_arm,
            k.P_FLOOR: c.impact_velocity_floor,
        }
        parameters = np.empty(k.N_PARAMETERS)
        for index, value in values.items():
            parameters[index] = float(value)
        return parameters

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        theta, x3, theta_dot, x3_dot = y[0], y[1], y[2], y[3]
        m, w = self.mechanism, self.omega
        phi = w * t
        cphi, sphi = math.cos(phi), math.sin(phi)
        ct, st = math.cos(theta), math.sin(theta)
        ex = m.crank_length * cphi + m.rod_length * ct - x3
        ey = m.crank_length * sphi + m.rod_length * st
        vx = -w * m.crank_length * sphi - m.rod_length * st * theta_dot - x3_dot
        vy = w * m.crank_length * cphi + m.rod_length * ct * theta_dot
        return float(ex), float(ey), float(vx), float(vy)

    def gap(self, t: float, y: FloatArray) -> float:
        if self._kernel is not None:
            return self._kernel.gap(t, y, self._parameters, self._wear)
        return super().gap(t, y)

    def gap_rate(self, t: float, y: FloatArray) -> float:
        if self._kernel is not None:
            return self._kernel.gap_rate(t, y, self._parameters)
        return super().gap_rate(t, y)

    def gap_and_rate(self, t: float, y: FloatArray) -> tuple[float, float]:
        if self._kernel is not None:
            return self._kernel.gap_and_rate(t, y, self._parameters, self._wear)
        return super().gap_and_rate(t, y)

    def rhs_function(self, impact_velocity: float) -> Callable[[float, FloatArray], FloatArray]:
        if self._kernel is None:
            return super().rhs_function(impact_velocity)
        rhs, parameters, wear = self._kernel.rhs, self._parameters, self._wear
        return lambda t, y: rhs(t, y, impact_velocity, parameters, wear)

    def spring(self, x3: float) -> float:
        """Spring force on the slider along +x [N] (see :func:`spring_force`)."""
        m = self.mechanism
        if m.spring_mode == "pull":
            return m.spring_preload + m.spring_stiffness * (m.crank_length + m.rod_length - x3)
        return -(m.spring_preload + m.spring_stiffness * (x3 - (m.rod_length - m.crank_length)))

    def spring_energy(self, x3: float) -> float:
        """Potential of the spring force, ``F = -dV/dx_3`` [J]."""
        m = self.mechanism
        if m.spring_mode == "pull":
            u = m.crank_length + m.rod_length - x3
        else:
            u = x3 - (m.rod_length - m.crank_length)
        return m.spring_preload * u + 0.5 * m.spring_stiffness * u * u

    def evaluate(self, t: float, y: ArrayLike, impact_velocity: float) -> dict[str, float]:
        """Everything at one instant: accelerations, contact force, crank torque.

        Parameters
        ----------
        t : float
            Time [s] (crank angle ``omega t``).
        y : array_like, shape (5,)
            State.
        impact_velocity : float
            ``delta'^-`` of the current contact [m/s].

        Returns
        -------
        dict
            ``theta_ddot`` [rad/s^2], ``x3_ddot`` [m/s^2], ``force_x``/``force_y``
            (``J``) [N], ``normal_force``/``friction_force`` [N], ``normal_x``/
            ``normal_y`` [-], ``penetration`` [m], ``slip`` [m/s], ``crank_torque``
            [N m].
        """
        if self._kernel is not None:
            values = self._kernel.evaluate(
                float(t), np.asarray(y, dtype=float), impact_velocity, self._parameters, self._wear
            )
            return dict(zip(_EVALUATE_KEYS, values, strict=True))
        return self.evaluate_reference(t, y, impact_velocity)

    def evaluate_reference(
        self, t: float, y: ArrayLike, impact_velocity: float
    ) -> dict[str, float]:
        """:meth:`evaluate` in Python: the reference of the compiled one."""
        theta, x3, theta_dot, x3_dot = (float(v) for v in np.asarray(y, dtype=float)[:4])
        m, w = self.mechanism, self.omega
        l1, l2 = m.crank_length, m.rod_length
        phi = w * t
        cphi, sphi = math.cos(phi), math.sin(phi)
        bx, by = l1 * cphi, l1 * sphi
        abx, aby = -w * w * bx, -w * w * by
        ct, st = math.cos(theta), math.sin(theta)
        ex = bx + l2 * ct - x3
        ey = by + l2 * st
        vx = -w * by - l2 * st * theta_dot - x3_dot
        vy = w * bx + l2 * ct * theta_dot
        jx, jy, normal, tangential, nx, ny, delta, slip = self.contact.force(
            ex, ey, vx, vy, theta_dot, impact_velocity
        )
        half = 0.5 * l2
        # t_theta = (-st, ct)
        theta_ddot = (
            -m.rod_mass * half * (-st * abx + ct * aby)
            - m.rod_mass * m.gravity * half * ct
            - l2 * (-st * jx + ct * jy)
            - self.contact.friction_arm * tangential
        ) / self._inertia_b
        x3_ddot = (jx + self.spring(x3)) / m.slider_mass
        agx = abx + half * (-st * theta_ddot - ct * theta_dot * theta_dot)
        agy = aby + half * (ct * theta_ddot - st * theta_dot * theta_dot)
        rbx = m.rod_mass * agx + jx
        rby = m.rod_mass * (agy + m.gravity) + jy
        torque = bx * rby - by * rbx + 0.5 * m.crank_mass * m.gravity * bx
        return {
            "theta_ddot": theta_ddot,
            "x3_ddot": x3_ddot,
            "force_x": jx,
            "force_y": jy,
            "normal_force": normal,
            "friction_force": tangential,
            "normal_x": nx,
            "normal_y": ny,
            "penetration": delta,
            "slip": slip,
            "crank_torque": torque,
            "ex": ex,
            "ey": ey,
        }

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """``y' = (theta', x_3', theta'', x_3'', T omega)``."""
        if self._kernel is not None:
            return self._kernel.rhs(t, y, impact_velocity, self._parameters, self._wear)
        return self.rhs_reference(t, y, impact_velocity)

    def rhs_reference(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """:meth:`rhs` in Python: the reference of the compiled right-hand side."""
        out = self.evaluate_reference(t, y, impact_velocity)
        return np.array(
            [y[2], y[3], out["theta_ddot"], out["x3_ddot"], out["crank_torque"] * self.omega]
        )

    def energy(self, t: float, y: ArrayLike) -> float:
        """Mechanical energy: kinetic + spring + gravity + contact elastic energy [J].

        The crank's own kinetic energy is constant and left out; its potential
        energy ``m_1 g (l_1 / 2) sin(phi_1)`` is included (the crank torque pays
        for it).
        """
        theta, x3, theta_dot, x3_dot = (float(v) for v in np.asarray(y, dtype=float)[:4])
        m, w = self.mechanism, self.omega
        l1, l2 = m.crank_length, m.rod_length
        phi = w * t
        vbx, vby = -w * l1 * math.sin(phi), w * l1 * math.cos(phi)
        vgx = vbx - 0.5 * l2 * math.sin(theta) * theta_dot
        vgy = vby + 0.5 * l2 * math.cos(theta) * theta_dot
        kinetic = 0.5 * m.rod_mass * (vgx * vgx + vgy * vgy) + 0.5 * (
            m.rod_inertia * theta_dot**2 + m.slider_mass * x3_dot**2
        )
        y_g = l1 * math.sin(phi) + 0.5 * l2 * math.sin(theta)
        gravity = m.gravity * (m.rod_mass * y_g + m.crank_mass * 0.5 * l1 * math.sin(phi))
        ex, ey, _, _ = self.clearance_state(t, np.asarray(y, dtype=float))
        return kinetic + gravity + self.spring_energy(x3) + self.contact.potential(ex, ey)


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


# ------------------------------------------------------------------ integration


@dataclass(frozen=True)
class Segment:
    """One stretch of integration between two contact events.

    Attributes
    ----------
    start, end : float
        Time interval [s].
    solution : OdeSolution
        Dense output on ``[start, end]``.
    in_contact : bool
        Whether the pin penetrates the wall during the segment.
    impact_velocity : float
        ``delta'^-`` of the contact (``nan`` in free flight) [m/s].
    """

    start: float
    end: float
    solution: OdeSolution
    in_contact: bool
    impact_velocity: float


@dataclass
class ContactHistory:
    """Result of :func:`integrate_contacts`.

    Attributes
    ----------
    segments : list of Segment
        Integration segments in time order.
    impact_times, impact_velocities : list of float
        Contact starts [s] and their approach velocities ``delta'`` [m/s]
        (before the floor is applied).
    separation_times, separation_velocities : list of float
        Contact ends [s] and the normal velocity ``-delta'`` there [m/s].
    peak_times, peak_penetrations : list of float
        Local maxima of the penetration [s], [m].
    evaluations : int
        Right-hand-side evaluations.
    """

    segments: list[Segment] = field(default_factory=list)
    impact_times: list[float] = field(default_factory=list)
    impact_velocities: list[float] = field(default_factory=list)
    separation_times: list[float] = field(default_factory=list)
    separation_velocities: list[float] = field(default_factory=list)
    peak_times: list[float] = field(default_factory=list)
    peak_penetrations: list[float] = field(default_factory=list)
    evaluations: int = 0

    @property
    def end_time(self) -> float:
        """Time reached [s]."""
        return self.segments[-1].end if self.segments else math.nan

    @property
    def final_state(self) -> FloatArray:
        """State at :attr:`end_time`."""
        last = self.segments[-1]
        return np.asarray(last.solution(last.end), dtype=float)

    def locate(self, times: ArrayLike) -> NDArray[np.int64]:
        """Index of the segment holding each time."""
        starts = np.array([s.start for s in self.segments])
        index = np.searchsorted(starts, np.asarray(times, dtype=float), side="right") - 1
        return np.clip(index, 0, len(self.segments) - 1)

    def state(self, times: ArrayLike) -> tuple[FloatArray, NDArray[np.int64]]:
        """States at ``times`` (dense output) and the index of their segments.

        Returns
        -------
        states : ndarray, shape (M, n_state)
        segments : ndarray of int, shape (M,)
        """
        times = np.atleast_1d(np.asarray(times, dtype=float))
        index = self.locate(times)
        # a zero-length segment cannot interpolate: use the next one that starts there
        for k in np.unique(index):
            seg = self.segments[k]
            if seg.end <= seg.start and k + 1 < len(self.segments):
                index[index == k] = k + 1
        n_state = self.segments[0].solution(self.segments[0].start).size
        states = np.empty((times.size, n_state))
        for k in np.unique(index):
            rows = index == k
            seg = self.segments[k]
            values = np.asarray(seg.solution(np.clip(times[rows], seg.start, seg.end)))
            states[rows] = values.reshape(n_state, -1).T
        return states, index

    def free_time(self, start: float, end: float) -> float:
        """Time without penetration inside ``[start, end]`` [s]."""
        total = 0.0
        for seg in self.segments:
            if not seg.in_contact:
                total += max(0.0, min(seg.end, end) - max(seg.start, start))
        return total


@dataclass(frozen=True)
class _Part:
    """One ``solve_ivp`` run of :func:`integrate_contacts`, up to its contact event."""

    end: float
    solution: Any
    evaluations: int
    peaks: list[tuple[float, FloatArray]]
    event: FloatArray | None
    failed: str | None


class _EventWatch:
    """The contact events, checked after every step of the solver (:class:`_Watched`).

    ``solve_ivp``'s own events cost ~10 us per step in NumPy (``find_active_events``
    on two-element arrays), more than a compiled right-hand side and its step
    together. Here the same test runs on two floats: a gap that rises through zero
    (contact start, terminal), falls through zero (contact end, terminal) or a gap
    rate that falls through zero (penetration maximum); a terminal crossing ends the
    solver after the step, and the roots are found afterwards on the step's dense
    output exactly as ``solve_ivp`` finds them. The steps, roots and states are
    those of ``solve_ivp(..., events=...)``, to the bit.
    """

    def __init__(self, system: Any, in_contact: bool, t0: float, y0: FloatArray) -> None:
        self.gap, self.gap_rate = system.gap, system.gap_rate
        self.gap_and_rate = system.gap_and_rate
        self.in_contact = in_contact
        self.g = self.gap(t0, y0)
        self.rate = self.gap_rate(t0, y0) if in_contact else 0.0
        #: ``(t_old, t, dense output)`` of the steps with a penetration maximum
        self.peaks: list[tuple[float, float, Any]] = []
        self.terminal: tuple[float, float, Any] | None = None

    def check(self, solver: Any) -> None:
        t, y = solver.t, solver.y
        peak = False
        if self.in_contact:
            g, rate = self.gap_and_rate(t, y)
            peak = self.rate >= 0.0 and rate <= 0.0
            self.rate = rate
            crossed = self.g >= 0.0 and g <= 0.0
        else:
            g = self.gap(t, y)
            crossed = self.g <= 0.0 and g >= 0.0
        self.g = g
        if peak or crossed:
            step = (solver.t_old, t, solver.dense_output())
            if peak:
                self.peaks.append(step)
            if crossed:
                self.terminal = step
                solver.status = "finished"


class _Watched:
    """Mixin of a ``scipy.integrate`` solver class: :class:`_EventWatch` after each step."""

    watch: _EventWatch

    def step(self) -> str | None:
        message = super().step()  # type: ignore[misc]
        if self.status != "failed":  # type: ignore[attr-defined]
            self.watch.check(self)
        return message


def _root(function: Callable[[float, FloatArray], float], dense: Any, t0: float, t1: float):
    """Zero of ``function(t, dense(t))`` in the step ``[t0, t1]``, as ``solve_ivp`` finds it."""
    from scipy.optimize import brentq

    eps = float(np.finfo(float).eps)
    return brentq(lambda t_: function(t_, dense(t_)), t0, t1, xtol=4 * eps, rtol=4 * eps)


def _integrate_segment(
    system: Any,
    fun: Callable[[float, FloatArray], FloatArray],
    t: float,
    t_end: float,
    y: FloatArray,
    in_contact: bool,
    method: str,
    rtol: float,
    atol: float,
    max_step: float,
) -> _Part:
    """Integrate from ``t`` to the next contact event (or ``t_end``)."""
    import scipy.integrate  # lazy: keeps `jointwear` quick to start
    from scipy.integrate import OdeSolution

    base = getattr(scipy.integrate, method)
    watch = _EventWatch(system, in_contact, t, y)
    solver = type(f"Watched{method}", (_Watched, base), {"watch": watch})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        sol = scipy.integrate.solve_ivp(
            fun, (t, t_end), y, method=solver, rtol=rtol, atol=atol, max_step=max_step,
            dense_output=True,
        )  # fmt: skip
    evaluations = int(sol.nfev)
    if sol.status == -1:
        return _Part(t, None, evaluations, [], None, str(sol.message))
    roots = [(_root(watch.gap_rate, dense, t0, t1), dense) for t0, t1, dense in watch.peaks]
    ts, interpolants = list(sol.t), list(sol.sol.interpolants)
    event = None
    if watch.terminal is not None:
        t0, t1, dense = watch.terminal
        t_stop = _root(watch.gap, dense, t0, t1)
        # solve_ivp keeps the maxima of the last step found before the contact event
        roots = [(r, d) for r, d in roots if d is not dense or r < t_stop]
        event = np.asarray(dense(t_stop), dtype=float)
        ts.pop()
        if len(ts) > 1 and ts[-1] == t_stop:
            interpolants.pop()
        else:
            ts.append(t_stop)
    solution = OdeSolution(ts, interpolants, alt_segment=method in ("LSODA", "BDF"))
    peaks = [(float(r), np.asarray(d(r), dtype=float)) for r, d in roots]
    return _Part(float(ts[-1]), solution, evaluations, peaks, event, None)




def integrate_contacts(
    system: ContactSystem,
    t_span: tuple[float, float],
    y0: ArrayLike,
    *,
    in_contact: bool,
    impact_velocity: float = math.nan,
    method: str = "LSODA",
    rtol: float = 1e-8,
    atol: float = 1e-10,
    max_step: float = math.inf,
    max_events: int = 1_000_000,
    stop_after_separations: int | None = None,
) -> ContactHistory:
    """Integrate a contact system, restarting at every contact start and end.

    Parameters
    ----------
    system : ContactSystem
        :class:`SliderCrankContactSystem` or :class:`FreePinSystem`.
    t_span : tuple of float
        ``(t_0, t_end)`` [s].
    y0 : array_like
        Initial state.
    in_contact : bool
        Whether the pin penetrates the wall at ``t_0``.
    impact_velocity : float
        ``delta'^-`` of a contact already under way at ``t_0`` [m/s] (``nan``:
        the floor ``contact.impact_velocity_floor``).
    method : str
        ``solve_ivp`` method (:data:`INTEGRATORS`).
    rtol, atol : float
        Integrator tolerances.
    max_step : float
        Largest step [s].
    max_events : int
        Largest number of contact events before giving up.
    stop_after_separations : int, optional
        Stop at that many contact ends (e.g. 1 for a single impact).

    Returns
    -------
    ContactHistory

    Raises
    ------
    ConvergenceError
        If the integrator fails, or contact events pile up at one instant
        (chattering) or exceed ``max_events``.
    """
    if method not in INTEGRATORS:
        raise ConfigError(f"dynamics.integrator: {method!r} is not one of {INTEGRATORS}")
    contact = system.contact
    floor = contact.impact_velocity_floor
    t, t_end = float(t_span[0]), float(t_span[1])
    y = np.asarray(y0, dtype=float).copy()
    v_imp = floor if not math.isfinite(impact_velocity) else max(impact_velocity, floor)
    history = ContactHistory()

    gap_rate = system.gap_rate
    stalled = 0
    events = 0
    while t < t_end:
        velocity = v_imp
        fun = system.rhs_function(velocity)
        part = _integrate_segment(
            system, fun, t, t_end, y, in_contact, method, rtol, atol, max_step
        )
        history.evaluations += part.evaluations
        if part.failed is not None:
            raise ConvergenceError(
                f"dynamics.integrator: {method} failed at t = {t:.6g} s "
                f"({part.failed}); try dynamics.integrator = 'Radau' or looser "
                f"dynamics.rtol/atol"
            )
        history.segments.append(
            Segment(t, part.end, part.solution, in_contact, velocity if in_contact else math.nan)
        )
        for t_peak, y_peak in part.peaks:
            history.peak_times.append(t_peak)
            history.peak_penetrations.append(system.gap(t_peak, y_peak))
        if part.event is None:
            break
        t_event, y = part.end, part.event
        events += 1
        stalled = stalled + 1 if t_event - t <= 1e-14 * max(1.0, abs(t)) else 0
        if stalled > 100:
            raise ConvergenceError(
                f"dynamics: contact events pile up at t = {t_event:.9g} s (grazing contact or "
                f"chattering); loosen dynamics.rtol or raise dynamics.impact_velocity_floor"
            )
        if events > max_events:
            raise ConvergenceError(
                f"dynamics: more than {max_events} contact events before t = {t_event:.9g} s"
            )
        rate = gap_rate(t_event, y)
        if in_contact:
            history.separation_times.append(t_event)
            history.separation_velocities.append(-rate)
            if (
                stop_after_separations is not None
                and len(history.separation_times) >= stop_after_separations
            ):
                break
        else:
            history.impact_times.append(t_event)
            history.impact_velocities.append(rate)
            v_imp = max(rate, floor)
        in_contact = not in_contact
        t = t_event
    return history


# ------------------------------------------------------------------ solutions


@dataclass(frozen=True, eq=False)
class ContactImpactSolution:
    """Contact–impact joint load plus what the continuous-contact model cannot tell.

    Attributes
    ----------
    load : LoadCycle
        Joint load sampled over the recorded revolution (what the wear pipeline
        consumes).
    impacts : int
        Contact starts (free flight ending on the wall) in the recorded
        revolution [-].
    free_flight_fraction : float
        Share of the recorded revolution without penetration (zero contact
        force) [-].
    max_penetration : float
        Largest penetration in the recorded revolution [m].
    peak_load : float
        Largest normal contact force in the recorded revolution, impacts
        included (evaluated at the samples and at every penetration maximum) [N].
    load_difference_rms, load_difference_max : float
        RMS and maximum over the samples of ``|F_impact - F_massless|``, the
        difference of the normal-force *vectors* (magnitude and azimuth) from the
        massless-link model [N]; ``nan`` if that model fails.
    massless : LoadCycle or None
        The massless-link load it is compared with.
    massless_contact_lost : bool or None
        Whether the massless-link model reports contact loss.
    history : ContactHistory
        Full integration record (all revolutions).
    system : SliderCrankContactSystem
        The integrated system.
    settings : ContactImpactSettings
        Settings used.
    record_start : float
        Start time of the recorded revolution [s].
    runtime : float
        Wall-clock time of the integration [s].
    """

    load: LoadCycle
    impacts: int
    free_flight_fraction: float
    max_penetration: float
    peak_load: float
    load_difference_rms: float
    load_difference_max: float
    massless: LoadCycle | None
    massless_contact_lost: bool | None
    history: ContactHistory
    system: SliderCrankContactSystem
    settings: ContactImpactSettings
    record_start: float
    runtime: float

    @property
    def period(self) -> float:
        """Crank period ``2 pi / omega`` [s]."""
        return 2.0 * math.pi / self.system.omega

    def summary(self) -> dict[str, Any]:
        """Extra scalars reported by ``jointwear dynamics`` (SI, units in the keys)."""
        mean = self.massless.mean_load if self.massless is not None else math.nan
        return {
            "force_law": self.settings.force_law,
            "restitution": self.settings.restitution,
            "friction_coefficient": self.settings.friction_coefficient,
            "integrator": self.settings.integrator,
            "impacts": int(self.impacts),
            "free_flight_fraction": float(self.free_flight_fraction),
            "max_penetration_m": float(self.max_penetration),
            "peak_load_n": float(self.peak_load),
            "load_difference_rms_n": float(self.load_difference_rms),
            "load_difference_max_n": float(self.load_difference_max),
            "load_difference_rms_relative": float(self.load_difference_rms / mean),
            "massless_contact_lost": self.massless_contact_lost,
            "revolutions_settle": int(self.settings.revolutions_settle),
            "rhs_evaluations": int(self.history.evaluations),
            "integration_runtime_s": float(self.runtime),
        }


@dataclass(frozen=True, eq=False)
class SampledRevolution:
    """A contact system integrated through the settling revolutions, one sampled.

    Attributes
    ----------
    history : ContactHistory
        Full integration record.
    times : ndarray, shape (N + 1,)
        Sample times of the recorded revolution and its end [s].
    states : ndarray, shape (N + 1, n_state)
        States at ``times``.
    records : list of dict
        ``system.evaluate`` at the first ``N`` samples.
    step_lost : ndarray of bool, shape (N,)
        Steps with free flight inside them.
    impacts : int
        Contact starts in the recorded revolution [-].
    free_flight_fraction : float
        Share of the recorded revolution without penetration [-].
    max_penetration : float
        Largest penetration in the recorded revolution [m].
    peak_load : float
        Largest normal contact force, samples and penetration maxima [N].
    record_start : float
        Start of the recorded revolution [s].
    runtime : float
        Wall-clock time of the integration [s].
    """

    history: ContactHistory
    times: FloatArray
    states: FloatArray
    records: list[dict[str, Any]]
    step_lost: NDArray[np.bool_]
    impacts: int
    free_flight_fraction: float
    max_penetration: float
    peak_load: float
    record_start: float
    runtime: float

    def column(self, key: str) -> FloatArray:
        """One ``evaluate`` output over the ``N`` samples."""
        return np.array([r[key] for r in self.records])


def integrate_revolution(
    system: Any,
    y0: ArrayLike,
    settings: ContactImpactSettings,
    steps: int,
    in_contact: bool = True,
) -> SampledRevolution:
    """Integrate a crank-driven contact system and sample its last revolution.

    Parameters
    ----------
    system : ContactSystem
        A system with ``omega`` (crank speed [rad/s]) and ``evaluate(t, y,
        impact_velocity)`` returning ``normal_force`` and ``penetration`` (e.g.
        :class:`SliderCrankContactSystem`).
    y0 : array_like
        State at ``t = 0`` (crank angle 0).
    settings : ContactImpactSettings
        Integrator settings and ``revolutions_settle``.
    steps : int
        Samples ``N`` per revolution [-].
    in_contact : bool
        Whether the pin penetrates the wall at ``t = 0``.

    Returns
    -------
    SampledRevolution
    """
    omega = system.omega
    period = 2.0 * math.pi / omega
    record_start = settings.revolutions_settle * period
    max_step = settings.max_step if settings.max_step is not None else period / steps
    started = _time.perf_counter()
    history = integrate_contacts(
        system,
        (0.0, record_start + period),
        y0,
        in_contact=in_contact,
        method=settings.integrator,
        rtol=settings.rtol,
        atol=settings.atol,
        max_step=max_step,
    )
    runtime = _time.perf_counter() - started

    # samples of the recorded revolution, plus its end (for the last increment)
    phi = 2.0 * np.pi * np.arange(steps) / steps
    times = record_start + np.append(phi, 2.0 * np.pi) / omega
    states, index = history.state(times)
    records = [
        system.evaluate(float(t), y, history.segments[k].impact_velocity)
        for t, y, k in zip(times[:-1], states[:-1], index[:-1], strict=True)
    ]
    record_end = record_start + period
    free = history.free_time(record_start, record_end)
    impacts = int(
        np.sum(
            (np.array(history.impact_times) >= record_start)
            & (np.array(history.impact_times) < record_end)
        )
    )
    # free flight inside each sampling step
    step_lost = np.zeros(steps, dtype=bool)
    width = period / steps
    for seg in history.segments:
        if seg.in_contact or seg.end <= record_start or seg.start >= record_end:
            continue
        first = max(math.floor((seg.start - record_start) / width), 0)
        last = min(math.ceil((seg.end - record_start) / width), steps)
        step_lost[first:last] = True
    peak_times = [t for t in history.peak_times if record_start <= t <= record_end]
    peaks = [
        p
        for t, p in zip(history.peak_times, history.peak_penetrations, strict=True)
        if record_start <= t <= record_end
    ]
    sampled = np.array([r["penetration"] for r in records])
    max_penetration = float(max([*peaks, float(sampled.max())]))
    # the largest contact force: impacts peak between samples, near the penetration maxima
    peak_load = float(normal_max := np.max([r["normal_force"] for r in records]))
    if peak_times:
        peak_states, peak_index = history.state(peak_times)
        peak_load = max(
            normal_max,
            *(
                system.evaluate(t, y, history.segments[k].impact_velocity)["normal_force"]
                for t, y, k in zip(peak_times, peak_states, peak_index, strict=True)
            ),
        )
    return SampledRevolution(
        history=history,
        times=times,
        states=states,
        records=records,
        step_lost=step_lost,
        impacts=impacts,
        free_flight_fraction=free / period,
        max_penetration=max_penetration,
        peak_load=float(peak_load),
        record_start=record_start,
        runtime=runtime,
    )


def _initial_state(system: SliderCrankContactSystem, steps: int) -> tuple[FloatArray, float]:
    """State at ``phi_1 = 0``: massless-link motion, pin pressed in by the static load.

    Returns the state and the direction of ``e`` [rad].
    """
    m, omega = system.mechanism, system.omega
    clearance = system.contact.clearance
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            solution = solve_massless_link(m, omega, clearance, steps)
        motion, reaction = solution.motion, solution.reaction
    except JointwearError:
        motion = ideal_motion(np.array([0.0]), m.crank_length, m.rod_length, omega)
        reaction = inverse_dynamics(motion, m)
    jx, jy = float(reaction.force_x[0]), float(reaction.force_y[0])
    load = math.hypot(jx, jy)
    direction = math.atan2(jy, jx)
    offset = system.contact.static_offset(load, direction)
    ex, ey = offset * math.cos(direction), offset * math.sin(direction)
    # loop closure at phi_1 = 0: l2 sin(theta) = e_y, x_3 = l1 + l2 cos(theta) - e_x
    theta = math.asin(ey / m.rod_length)
    x3 = m.crank_length + m.rod_length * math.cos(theta) - ex
    state = np.array(
        [
            theta,
            x3,
            float(motion.rod_angular_velocity[0]),
            float(motion.slider_velocity[0]),
            0.0,
        ]
    )
    return state, direction


def solve_contact_impact(
    config: Config,
    contour: BushingContour | None = None,
    compare: bool = True,
) -> ContactImpactSolution:
    """Integrate the contact–impact slider–crank and sample one settled revolution.

    Parameters
    ----------
    config : jointwear.config.Config
        Uses ``[mechanism]``, ``[joint]``, ``[materials]``, ``contact.nodes`` (and
        the spring-law keys for ``nlcp``/``winkler``), ``[dynamics]`` and
        ``simulation.steps_per_revolution``.
    contour : BushingContour, optional
        Bushing contour for the distributed force laws (default: unworn circle).
    compare : bool
        Also run the massless-link model and report the load difference.

    Returns
    -------
    ContactImpactSolution

    Raises
    ------
    ConvergenceError
        If the integrator fails.
    ConfigError
        For inconsistent settings.
    """
    settings = ContactImpactSettings.from_config(config.dynamics)
    mechanism = SliderCrank.from_config(config.mechanism)
    omega = config.mechanism.crank_speed
    steps = config.simulation.steps_per_revolution
    contact = JointContact.from_config(config, contour)
    system = SliderCrankContactSystem(mechanism, omega, contact)
    y0, _ = _initial_state(system, max(steps, 64))
    run = integrate_revolution(system, y0, settings, steps)
    states = run.states
    theta_all = states[:, 0]
    theta = theta_all[:-1]
    force_x, force_y = run.column("force_x"), run.column("force_y")
    load = slider_crank_cycle(
        config,
        force_x,
        force_y,
        theta,
        np.diff(theta_all),
        states[:-1, 1],
        run.column("crank_torque"),
        normal_x=run.column("normal_x"),
        normal_y=run.column("normal_y"),
        load=run.column("normal_force"),
        model="contact-impact",
        lost_steps=run.step_lost,
    )
    return sampled_solution(
        load, run, system, settings, (lambda: massless_link_load(config)) if compare else None
    )


def sampled_solution(
    load: LoadCycle,
    run: SampledRevolution,
    system: Any,
    settings: ContactImpactSettings,
    massless_model: Callable[[], LoadCycle] | None = None,
) -> ContactImpactSolution:
    """The solution of a sampled revolution, compared with the massless-link load.

    Parameters
    ----------
    load : LoadCycle
        Contact-impact load of the recorded revolution.
    run : SampledRevolution
        The integration and its samples.
    system : ContactSystem
        The integrated system.
    settings : ContactImpactSettings
        Settings used.
    massless_model : callable, optional
        Computes the massless-link load of the same joint; ``None``: no comparison.
        Contact-loss warnings are silenced and a failure gives ``nan`` differences.
    """
    massless: LoadCycle | None = None
    massless_lost: bool | None = None
    rms = peak = math.nan
    if massless_model is not None:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ContactLossWarning)
                massless = massless_model()
        except JointwearError:
            massless = None
        if massless is not None:
            massless_lost = bool(massless.contact_lost)
            dx = load.load * np.cos(load.azimuth) - massless.load * np.cos(massless.azimuth)
            dy = load.load * np.sin(load.azimuth) - massless.load * np.sin(massless.azimuth)
            diff = np.hypot(dx, dy)
            rms, peak = float(np.sqrt(np.mean(diff**2))), float(diff.max())
    return ContactImpactSolution(
        load=load,
        impacts=run.impacts,
        free_flight_fraction=run.free_flight_fraction,
        max_penetration=run.max_penetration,
        peak_load=run.peak_load,
        load_difference_rms=rms,
        load_difference_max=peak,
        massless=massless,
        massless_contact_lost=massless_lost,
        history=run.history,
        system=system,
        settings=settings,
        record_start=run.record_start,
        runtime=run.runtime,
    )


def contact_impact_load(config: Config, wear_depth: FloatArray | None = None) -> LoadCycle:
    """Joint load over one settled revolution from the contact–impact model.

    Registered as ``dynamics.model = "contact-impact"`` of the slider-crank.

    Parameters
    ----------
    config : jointwear.config.Config
        Validated configuration.
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing on the ``contact.nodes`` grid [m]: the pin meets
        the worn contour. ``None``: the unworn bushing.

    Returns
    -------
    LoadCycle
        ``load`` is the normal contact force ``F_N`` (zero in free flight),
        ``azimuth`` the contact normal in the bushing body's frame; the extras hold
        the impacts, the free-flight fraction and the difference from the
        massless-link load (:meth:`ContactImpactSolution.summary`).
    """
    from dataclasses import replace

    contour = None
    if wear_depth is not None and np.any(wear_depth):
        if config.mechanism.bushing_body != "slider":
            raise ConfigError(
                "simulation.dynamics_update: contact-impact on a worn bushing needs the bushing "
                "on a body that does not turn (mechanism.bushing_body = 'slider')"
            )
        joint = config.joint
        contour = BushingContour.from_wear_profile(
            joint.bushing_radius, wear_depth, joint.axial_length
        )
    solution = solve_contact_impact(config, contour)
    return replace(solution.load, extras={**solution.load.extras, **solution.summary()})


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
    gap = contact.clearance if not contact.distributed else contact._touch(direction)
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
