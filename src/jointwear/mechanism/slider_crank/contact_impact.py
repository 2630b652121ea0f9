r"""Contact–impact dynamics of the slider–crank: the pin moves freely in the clearance.

The massless-link model (:mod:`jointwear.mechanism.slider_crank.massless_link`) assumes
that the pin never leaves the bushing wall. Here the assumption is dropped: pin and
bushing are connected only through a contact force that exists while they overlap
(:class:`~jointwear.mechanism.impact.joint_contact.JointContact`), so the pin can
separate, fly across the clearance and hit the wall again. The integration through
the contact events and the sampled revolution are shared with every mechanism
(:mod:`jointwear.mechanism.impact`).

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
(:mod:`jointwear.mechanism.impact.force_laws`) and friction
``F_T = mu c_d(v_T) F_N sign(v_T)``, ``v_T = e' . t + rho theta'`` the slip of the
rod-side surface over the slider-side one. The crank torque that keeps ``omega``
constant is, as in the massless-link model,
``T = B x R_B + m_1 g B_x / 2``, ``R_B = m_2 (a_G + g y) + J``; its work
``W = int T omega dt`` is integrated with the state, so the energy balance
``E(t) - E(0) = W(t) - dissipation`` can be checked
(:meth:`SliderCrankContactSystem.energy`).

The right-hand side runs compiled (numba,
:mod:`jointwear.mechanism.slider_crank._contact_impact_kernel`, imported on first use
and cached on disk) for the point force laws; without numba, with
``JOINTWEAR_NO_NUMBA=1`` or for the distributed laws, the Python methods below, which
stay the readable reference, give the same numbers to the bit.

Initial state
-------------
The massless-link solution at ``phi_1 = 0`` (rod angle, slider position and their
rates), with the pin pushed into the wall by the static penetration of the
massless-link load (:func:`initial_state`).
"""

from __future__ import annotations

import functools
import math
import os
import warnings
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError, ConvergenceError, JointwearError
from jointwear.geometry.contour import BushingContour
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.impact.bushing_frame import contact_force_in_frame, to_bushing_frame
from jointwear.mechanism.impact.integrator import ContactHistory, ContactSystemBase
from jointwear.mechanism.impact.joint_contact import JointContact
from jointwear.mechanism.impact.kept_history import kept_history
from jointwear.mechanism.impact.revolution import (
    ContactImpactSolution,
    integrate_revolution,
    sampled_solution,
)
from jointwear.mechanism.impact.settings import (
    AUTO_INTEGRATOR,
    COMPILED_INTEGRATOR,
    COMPILED_INTEGRATORS,
    RADAU_INTEGRATOR,
    STIFF_INTEGRATOR,
    ContactImpactSettings,
)
from jointwear.mechanism.inputs import MechanismInputs
from jointwear.mechanism.slider_crank.dynamics import SliderCrank, inverse_dynamics
from jointwear.mechanism.slider_crank.joint_load import slider_crank_cycle
from jointwear.mechanism.slider_crank.kinematics import ideal_motion
from jointwear.mechanism.slider_crank.massless_link import (
    massless_link_load,
    solve_massless_link,
)

__all__ = [
    "SliderCrankContactSystem",
    "contact_impact_load",
    "impact_kernel",
    "initial_state",
    "slider_crank_contact",
    "solve_contact_impact",
    "worn_contour",
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
        from jointwear.compile_time import watch_compiles

        watch_compiles()
        from jointwear.mechanism.slider_crank import _contact_impact_kernel
    except ImportError:
        return None
    return _contact_impact_kernel


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
    compiled : bool, optional
        Run the compiled right-hand side where it can (``None``), never (``False``) or
        insist on it (``True``).
    rod_bushing : bool
        The bushing is in the rod end. Worn, it turns with the rod: the contact is
        then evaluated in the rod's frame
        (:mod:`jointwear.mechanism.impact.bushing_frame`), by the Python right-hand side.
    """

    def __init__(
        self,
        mechanism: SliderCrank,
        crank_speed: float,
        contact: JointContact,
        compiled: bool | None = None,
        rod_bushing: bool = False,
    ) -> None:
        self.mechanism = mechanism
        self.omega = float(crank_speed)
        self.contact = contact
        # a worn bushing in the rod end turns with the rod (an unworn one is a circle)
        worn = contact.contour is not None and bool(np.any(contact.contour.wear_depth))
        self._rod_frame = rod_bushing and worn
        m = mechanism
        self._inertia_b = m.rod_inertia + 0.25 * m.rod_mass * m.rod_length**2
        if self._inertia_b <= 0.0 or m.slider_mass <= 0.0:
            raise ConfigError(
                "mechanism.rod_mass, mechanism.slider_mass: the contact-impact model needs a "
                "rod with inertia and a slider with mass (the pin's degrees of freedom)"
            )
        # the compiled right-hand side covers the point laws (the distributed laws sum
        # over the contour's nodes with NumPy)
        plain = not contact.distributed and not self._rod_frame
        kernel = impact_kernel() if compiled is not False and plain else None
        if compiled and kernel is None:
            raise ConfigError(
                "dynamics: the compiled right-hand side needs numba and a point force law"
            )
        self._kernel = kernel
        if kernel is not None:
            self._parameters = self._kernel_parameters()
            wear = contact.wear_profile
            self._wear = wear if wear is not None else np.empty(0)

    @property
    def compiled(self) -> bool:
        """Whether :meth:`rhs` and the gap functions run compiled (numba)."""
        return self._kernel is not None

    def _kernel_parameters(self) -> FloatArray:
        """The parameter array of the compiled right-hand side (``_contact_impact_kernel.P_*``)."""
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
            k.P_FILM: c.film_arguments[0],
            k.P_PIN_RADIUS: c.film_arguments[1],
            k.P_FILM_LENGTH: c.film_arguments[2],
            k.P_VISCOSITY: c.film_arguments[4],
            k.P_FILM_BAND: c.film_arguments[5],
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

    def bushing_offset(self, y: FloatArray, ex: float, ey: float) -> tuple[float, float]:
        """The pin centre's offset from the bushing centre in the bushing's frame [m]
        (``e`` itself but for a worn bushing in the rod end: ``-R(-theta) e``)."""
        if not self._rod_frame:
            return ex, ey
        return to_bushing_frame(float(y[0]), -1.0, ex, ey)

    def gap(self, t: float, y: FloatArray) -> float:
        if self._kernel is not None:
            return self._kernel.gap(t, y, self._parameters, self._wear)
        if self._rod_frame:
            ex, ey, _, _ = self.clearance_state(t, y)
            return self.contact.gap(*self.bushing_offset(y, ex, ey))
        return super().gap(t, y)

    def gap_rate(self, t: float, y: FloatArray) -> float:
        if self._kernel is not None:
            return self._kernel.gap_rate(t, y, self._parameters)
        return super().gap_rate(t, y)

    def gap_and_rate(self, t: float, y: FloatArray) -> tuple[float, float]:
        if self._kernel is not None:
            return self._kernel.gap_and_rate(t, y, self._parameters, self._wear)
        if self._rod_frame:
            return self.gap(t, y), self.gap_rate(t, y)
        return super().gap_and_rate(t, y)

    def rhs_function(self, impact_velocity: float) -> Callable[[float, FloatArray], FloatArray]:
        if self._kernel is None:
            return super().rhs_function(impact_velocity)
        rhs, parameters, wear = self._kernel.rhs, self._parameters, self._wear
        return lambda t, y: rhs(t, y, impact_velocity, parameters, wear)

    def integrate_compiled(
        self,
        t_span: tuple[float, float],
        y0: ArrayLike,
        in_contact: bool,
        settings: ContactImpactSettings,
        max_step: float,
        samples: FloatArray,
        tolerances: tuple[float, float] | None = None,
        stop_on_separation: bool = False,
        method: str = COMPILED_INTEGRATOR,
    ) -> tuple[ContactHistory, FloatArray, NDArray[np.int64]] | None:
        """Integrate through the contact events in one compiled function.

        Parameters
        ----------
        t_span : tuple of float
            ``(t_0, t_end)`` [s].
        y0 : array_like
            State at ``t_0``.
        in_contact : bool
            Whether the pin penetrates the wall at ``t_0``.
        settings : ContactImpactSettings
            ``rtol`` and ``atol`` [-].
        max_step : float
            Largest step [s].
        samples : ndarray, shape (M,)
            Sorted times of the states wanted, inside ``t_span`` [s].
        tolerances : tuple of float, optional
            ``(rtol, atol)`` instead of the settings' [-].
        stop_on_separation : bool
            Give up at the first contact end (and return ``None``).
        method : str
            ``RK45-compiled`` (Dormand-Prince,
            :mod:`~jointwear.mechanism.slider_crank._contact_impact_rk`) or
            ``Rodas4-compiled`` (the stiff RODAS4,
            :mod:`~jointwear.mechanism.impact.rosenbrock`) or ``Radau-compiled`` (the
            fully implicit RADAU5, :mod:`~jointwear.mechanism.impact.radau`).

        Returns
        -------
        history : ContactHistory
            As :func:`~jointwear.mechanism.impact.integrator.integrate_contacts` with
            ``keep=samples``.
        states : ndarray, shape (M, 5)
            States at ``samples``.
        segments : ndarray of int, shape (M,)
            Index of the segment of each sample.

        Raises
        ------
        ConvergenceError
            If the step falls below the resolution of the time, or contact events pile
            up at one instant.
        """
        from jointwear.mechanism.slider_crank import _contact_impact_rk as rk

        if method == STIFF_INTEGRATOR:
            from jointwear.mechanism.slider_crank._contact_impact_rosenbrock import (
                integrate_revolution_rosenbrock as integrate,
            )
        elif method == RADAU_INTEGRATOR:
            from jointwear.mechanism.slider_crank._contact_impact_radau import (
                integrate_revolution_radau as integrate,
            )
        else:
            integrate = rk.integrate_revolution_rk
        floor = self.contact.impact_velocity_floor
        capacity = 4096
        rtol, atol = (settings.rtol, settings.atol) if tolerances is None else tolerances
        while True:
            run = integrate(
                float(t_span[0]), float(t_span[1]), np.asarray(y0, dtype=float), in_contact,
                floor, floor, self._parameters, self._wear, rtol, atol, float(max_step),
                np.asarray(samples, dtype=float), capacity, stop_on_separation,
            )  # fmt: skip
            if run[0] != rk.TOO_MANY_EVENTS or capacity > 1_000_000:
                break
            capacity *= 8
        if run[0] == rk.SEPARATED:
            return None
        if run[0] != rk.OK:
            reason = {
                rk.STEP_TOO_SMALL: "the step fell below the resolution of the time",
                rk.CHATTER: "contact events pile up at one instant (grazing or chattering)",
                rk.TOO_MANY_EVENTS: "more than 10^6 contact events",
            }[run[0]]
            raise ConvergenceError(
                f"dynamics.integrator: {method} failed ({reason}); try "
                "dynamics.integrator = 'LSODA' or looser dynamics.rtol/atol"
            )
        history, states = kept_history(run, np.asarray(samples, dtype=float), self.gap)
        return history, states, run[3]

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
        if self._rod_frame:
            # the bushing in the rod end, e from its centre to the pin's reversed
            jx, jy, normal, tangential, nx, ny, delta, slip = contact_force_in_frame(
                self.contact, theta, -1.0, (ex, ey), (vx, vy), theta_dot, impact_velocity
            )
        else:
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
        state = np.asarray(y, dtype=float)
        ex, ey, _, _ = self.clearance_state(t, state)
        contact = self.contact.potential(*self.bushing_offset(state, ex, ey))
        return kinetic + gravity + self.spring_energy(x3) + contact


def slider_crank_contact(
    inputs: MechanismInputs,
    settings: ContactImpactSettings,
    contour: BushingContour | None = None,
) -> JointContact:
    """The contact force model of the slider-crank's joint.

    Parameters
    ----------
    inputs : MechanismInputs
        Uses ``mechanism.bushing_body``, the joint, its elastic law and its film.
    settings : ContactImpactSettings
        The ``[dynamics]`` settings of the contact–impact model.
    contour : BushingContour, optional
        Bushing contour (distributed laws, a worn bushing).

    Raises
    ------
    ConfigError
        If ``inputs`` carries no elastic law.
    """
    if inputs.elastic is None:
        raise ConfigError(
            "dynamics.model: the contact-impact model needs the joint's elastic law "
            "(jointwear.mechanism.stage.mechanism_inputs builds it)"
        )
    joint = inputs.joint
    # rho: from the rod-side joint centre C to the contact point
    arm = joint.pin_radius if inputs.mechanism.bushing_body == "slider" else (-joint.bushing_radius)
    return JointContact.for_joint(settings, inputs.elastic, joint, arm, contour, inputs.film)


def initial_state(system: SliderCrankContactSystem, steps: int) -> tuple[FloatArray, float]:
    """State at ``phi_1 = 0``: massless-link motion, pin pressed in by the static load.

    Parameters
    ----------
    system : SliderCrankContactSystem
        The system to start.
    steps : int
        Steps per revolution of the massless-link solution it starts from [-].

    Returns
    -------
    state : ndarray, shape (5,)
        ``(theta, x_3, theta', x_3', 0)``.
    direction : float
        Direction of ``e`` [rad].
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
    seen = direction
    if system._rod_frame:
        # the load's direction seen from the worn bushing in the rod end
        rod = np.array([float(motion.rod_angle[0]), 0.0])
        along = system.bushing_offset(rod, math.cos(direction), math.sin(direction))
        seen = math.atan2(along[1], along[0])
    offset = system.contact.static_offset(load, seen)
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
    inputs: MechanismInputs,
    contour: BushingContour | None = None,
    compare: bool = True,
    compiled: bool | None = None,
) -> ContactImpactSolution:
    """Integrate the contact–impact slider–crank and sample one settled revolution.

    Parameters
    ----------
    inputs : MechanismInputs
        The slider-crank's ``[mechanism]`` section, the joint and its elastic law, the
        ``[dynamics]`` settings, the steps per revolution and whether the right-hand
        side may run compiled.
    contour : BushingContour, optional
        Bushing contour for the distributed force laws (default: unworn circle).
    compare : bool
        Also run the massless-link model and report the load difference.
    compiled : bool, optional
        Run the compiled right-hand side where it can (``True``) or the Python one
        (``False``); default: as ``inputs.compiled`` says
        (:func:`jointwear.mechanism.stage.compiled_dynamics`), and compiled wherever it
        can for a lubricated joint. Both give the same bits for a dry joint.

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
    settings = ContactImpactSettings.from_config(inputs.dynamics)
    mechanism = SliderCrank.from_config(inputs.mechanism)
    omega = inputs.mechanism.crank_speed
    steps = inputs.steps
    contact = slider_crank_contact(inputs, settings, contour)
    choice = inputs.compiled if compiled is None else (None if compiled else False)
    if compiled is None and (
        contact.film is not None or settings.integrator in (*COMPILED_INTEGRATORS, AUTO_INTEGRATOR)
    ):
        # the film's force in Python costs far more than loading the compiled kernel; the
        # compiled integrator (and ``auto``, which picks it where it runs) asks for it
        choice = None
    rod = inputs.mechanism.bushing_body == "rod"
    system = SliderCrankContactSystem(mechanism, omega, contact, choice, rod_bushing=rod)
    y0, _ = initial_state(system, max(steps, 64))
    run = integrate_revolution(system, y0, settings, steps, dense=False)
    states = run.states
    theta_all = states[:, 0]
    theta = theta_all[:-1]
    force_x, force_y = run.column("force_x"), run.column("force_y")
    load = slider_crank_cycle(
        inputs.mechanism,
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
        load, run, system, settings, (lambda: massless_link_load(inputs)) if compare else None
    )


def worn_contour(inputs: MechanismInputs, wear_depth: FloatArray | None) -> BushingContour | None:
    """The worn bushing the pin meets, or ``None`` for an unworn one.

    Parameters
    ----------
    inputs : MechanismInputs
        The joint and ``mechanism.bushing_body``.
    wear_depth : ndarray, shape (N,) or None
        Wear depth of the bushing on the ``joint.nodes`` grid [m].

    The contour is in the frame of the body that carries the bushing (the rod's for a
    bushing in the rod end).
    """
    if wear_depth is None or not np.any(wear_depth):
        return None
    joint = inputs.joint
    return BushingContour.from_wear_profile(joint.bushing_radius, wear_depth, joint.axial_length)


def contact_impact_load(inputs: MechanismInputs, wear_depth: FloatArray | None = None) -> LoadCycle:
    """Joint load over one settled revolution from the contact–impact model.

    Parameters
    ----------
    inputs : MechanismInputs
        As for :func:`solve_contact_impact`.
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing on the ``joint.nodes`` grid [m]: the pin meets
        the worn contour. ``None``: the unworn bushing.

    Returns
    -------
    LoadCycle
        ``load`` is the normal contact force ``F_N`` (zero in free flight),
        ``azimuth`` the contact normal in the bushing body's frame; the extras hold
        the impacts, the free-flight fraction and the difference from the
        massless-link load
        (:meth:`~jointwear.mechanism.impact.revolution.ContactImpactSolution.summary`).
    """
    return solve_contact_impact(inputs, worn_contour(inputs, wear_depth)).load_cycle()
