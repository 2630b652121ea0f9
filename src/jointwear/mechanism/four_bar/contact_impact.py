r"""Contact–impact dynamics of the four-bar: the pin free in one joint's clearance.

**Contact-impact model** (:class:`FourBarContactSystem`). One joint has
clearance; the crank stays kinematically driven, and the coupler and rocker
angles ``q = (theta_2, theta_3)`` become free. Every point of the coupler and the
rocker is ``P = base(t) + L2 e2 + L3 e3`` with ``base`` = B or D; the clearance
vector (pin-centre offset, first body's joint centre minus the second's) is, for
every choice of joint, the loop-closure residual::

    e = B + l2 e2 - D - l3 e3

and the equations of motion follow from virtual power,
``M(q) q'' = sum_b J_b^T m_b (g - a_b^0) + (0, M_r) + Q_contact`` with
``M = sum_b m_b J_b^T J_b + diag(I2, I3)``, ``J_b`` the Jacobian of the centre of
mass of body b with respect to ``q'`` and ``a_b^0`` its acceleration at ``q'' = 0``.
The contact force (:class:`~jointwear.mechanism.impact.joint_contact.JointContact`) acts
on the second body with ``J`` and on the first with ``-J``, both at the contact
point ``P = C_1 + rho n``.

The force laws, the integration through the contact events and the sampled
revolution are the ones every mechanism shares (:mod:`jointwear.mechanism.impact`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError
from jointwear.geometry.contour import BushingContour
from jointwear.mechanism.four_bar.dynamics import (
    cross,
    inverse_dynamics,
    joint_force,
    rocker_load_torque,
)
from jointwear.mechanism.four_bar.geometry import JOINT_BODIES, FourBar
from jointwear.mechanism.four_bar.joint_load import joint_cycle
from jointwear.mechanism.four_bar.kinematics import four_bar_motion, ideal_motion
from jointwear.mechanism.four_bar.massless_link import massless_link_cycles
from jointwear.mechanism.impact.bushing_frame import contact_force_in_frame, to_bushing_frame
from jointwear.mechanism.impact.integrator import ContactSystemBase
from jointwear.mechanism.impact.joint_contact import JointContact
from jointwear.mechanism.impact.revolution import (
    ContactImpactSolution,
    integrate_revolution,
    sampled_solution,
)
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.inputs import MechanismInputs

__all__ = [
    "FourBarContactSystem",
    "four_bar_contact",
    "four_bar_contact_impact",
    "worn_bushing",
]

FloatArray = NDArray[np.float64]


#: per joint: (base, L2, L3) of the centres of mass of coupler and rocker and of the
#: joint centres on the first and second body; base "B" is the crank pin, "D" the
#: rocker's ground pivot; the chain closes everywhere except at the clearance joint
_CHAINS: dict[str, dict[str, tuple[str, float, float]]] = {
    "crank-coupler": {
        "coupler": ("D", -0.5, 1.0),
        "rocker": ("D", 0.0, 0.5),
        "first": ("B", 0.0, 0.0),
        "second": ("D", -1.0, 1.0),
    },
    "coupler-rocker": {
        "coupler": ("B", 0.5, 0.0),
        "rocker": ("D", 0.0, 0.5),
        "first": ("B", 1.0, 0.0),
        "second": ("D", 0.0, 1.0),
    },
    "rocker-ground": {
        "coupler": ("B", 0.5, 0.0),
        "rocker": ("B", 1.0, -0.5),
        "first": ("B", 1.0, -1.0),
        "second": ("D", 0.0, 0.0),
    },
}
#: index of the free coordinate that is each body's angle (None: driven or fixed)
_ANGLE_INDEX = {"crank": None, "coupler": 0, "rocker": 1, "ground": None}


class FourBarContactSystem(ContactSystemBase):
    """Four-bar with a free pin in one joint (module docstring), a ``ContactSystem``.

    State ``y = (theta_2, theta_3, theta_2', theta_3', W)``: coupler and rocker
    angles [rad], their rates [rad/s] and the work ``W`` of the crank torque and
    the constant rocker torque [J].

    Parameters
    ----------
    linkage : FourBar
        Lengths, masses, gravity and rocker load.
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    contact : JointContact
        Contact force model; its ``friction_arm`` ``rho`` is measured from the first
        body's joint centre (``R_p`` if the pin is on the first body, ``-R_b`` if
        the bushing is).
    joint : {"crank-coupler", "coupler-rocker", "rocker-ground"}
        The clearance joint.
    bushing_body : str, optional
        The body that carries the bushing (default: the joint's second body). A worn
        bushing (``contact`` with a worn contour) turns with it: the contact is then
        evaluated in that body's frame (:meth:`bushing_offset`).
    """

    def __init__(
        self,
        linkage: FourBar,
        crank_speed: float,
        contact: JointContact,
        joint: str,
        bushing_body: str | None = None,
    ) -> None:
        if joint not in _CHAINS:
            raise ConfigError(f"mechanism.clearance_joint: unknown four-bar joint {joint!r}")
        self.linkage = linkage
        self.omega = float(crank_speed)
        self.contact = contact
        self.joint = joint
        chain = _CHAINS[joint]
        _, _, l2, l3 = linkage.lengths
        self._points = {name: (base, s2 * l2, s3 * l3) for name, (base, s2, s3) in chain.items()}
        first, second = JOINT_BODIES[joint]
        self._first, self._second = _ANGLE_INDEX[first], _ANGLE_INDEX[second]
        body = second if bushing_body is None else bushing_body
        # e points from the bushing's centre to the pin's when the bushing is on the
        # second body, the other way when it is on the first
        self._bushing_sign = 1.0 if body == second else -1.0
        self._bushing_body = body
        # only a worn bushing has a direction of its own (an unworn one is a circle,
        # evaluated in the global frame as before)
        worn = contact.contour is not None and bool(np.any(contact.contour.wear_depth))
        self._worn_frame = worn
        inertia = np.diag([linkage.coupler_inertia, linkage.rocker_inertia])
        self._constant_mass = inertia
        self._masses = {"coupler": linkage.coupler_mass, "rocker": linkage.rocker_mass}
        if linkage.coupler_inertia + linkage.coupler_mass * l2 * l2 <= 0.0 or (
            linkage.rocker_inertia + linkage.rocker_mass * l3 * l3 <= 0.0
        ):
            raise ConfigError(
                "mechanism.coupler_mass, mechanism.rocker_mass: the contact-impact model "
                "needs a coupler and a rocker with inertia (the pin's degrees of freedom)"
            )

    # -------------------------------------------------------------- kinematics
    def _base(self, base: str, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        if base == "D":
            zero = np.zeros(2)
            return np.array([self.linkage.ground_length, 0.0]), zero, zero
        phi, w, l1 = self.omega * t, self.omega, self.linkage.crank_length
        p = l1 * np.array([math.cos(phi), math.sin(phi)])
        return p, w * np.array([-p[1], p[0]]), -w * w * p

    def _point(
        self, name: str, t: float, q: np.ndarray, qd: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Position, velocity, Jacobian (2x2) and ``q'' = 0`` acceleration of a point."""
        base, a2, a3 = self._points[name]
        p0, v0, acc0 = self._base(base, t)
        e2 = np.array([math.cos(q[0]), math.sin(q[0])])
        e3 = np.array([math.cos(q[1]), math.sin(q[1])])
        n2, n3 = np.array([-e2[1], e2[0]]), np.array([-e3[1], e3[0]])
        jac = np.column_stack((a2 * n2, a3 * n3))
        pos = p0 + a2 * e2 + a3 * e3
        vel = v0 + jac @ qd
        drift = acc0 - a2 * qd[0] ** 2 * e2 - a3 * qd[1] ** 2 * e3
        return pos, vel, jac, drift

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        q, qd = np.asarray(y[:2], dtype=float), np.asarray(y[2:4], dtype=float)
        p1, v1, _, _ = self._point("first", t, q, qd)
        p2, v2, _, _ = self._point("second", t, q, qd)
        e, v = p1 - p2, v1 - v2
        return float(e[0]), float(e[1]), float(v[0]), float(v[1])

    # -------------------------------------------------------------- dynamics
    def evaluate(self, t: float, y: ArrayLike, impact_velocity: float) -> dict[str, float]:
        """Accelerations, contact force and crank torque at one instant.

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
            ``q_ddot`` (2,) [rad/s^2], ``force_x``/``force_y`` (``J`` on the second
            body) [N], ``normal_force``/``friction_force`` [N], ``normal_x``/``normal_y``
            [-], ``penetration`` [m], ``slip`` [m/s], ``crank_torque`` [N m].
        """
        y = np.asarray(y, dtype=float)
        q, qd = y[:2], y[2:4]
        p1, v1, jac1, _ = self._point("first", t, q, qd)
        p2, v2, jac2, _ = self._point("second", t, q, qd)
        e, v = p1 - p2, v1 - v2
        jx, jy, normal, tangential, nx, ny, delta, slip = self.contact_force(
            t, q, e, v, self._spin(qd, e), impact_velocity, self._film_spin(qd)
        )
        force = np.array([jx, jy])
        contact_point = p1 + self.contact.friction_arm * np.array([nx, ny])
        mass, gen, drifts = self._mass_and_forces(t, q, qd)
        # contact: -J on the first body, +J on the second, both at the contact point
        for sign, point_jac, centre, index in (
            (-1.0, jac1, p1, self._first),
            (1.0, jac2, p2, self._second),
        ):
            gen += sign * point_jac.T @ force
            if index is not None:
                gen[index] += sign * cross(contact_point - centre, force)
        q_ddot = np.linalg.solve(mass, gen)
        torque = self._crank_torque(t, q_ddot, drifts, force, contact_point)
        return {
            "q_ddot": q_ddot,
            "force_x": jx,
            "force_y": jy,
            "normal_force": normal,
            "friction_force": tangential,
            "normal_x": nx,
            "normal_y": ny,
            "penetration": delta,
            "slip": slip,
            "crank_torque": float(torque),
            "ex": float(e[0]),
            "ey": float(e[1]),
        }

    def bushing_angle(self, t: float, q: FloatArray) -> float:
        """Angle of the body that carries the bushing [rad] (crank ``omega t``, ground 0)."""
        body = self._bushing_body
        if body == "crank":
            return self.omega * t
        index = _ANGLE_INDEX[body]
        return 0.0 if index is None else float(q[index])

    def bushing_offset(self, t: float, q: FloatArray, ex: float, ey: float) -> tuple[float, float]:
        """The pin centre's offset from the bushing centre in the bushing body's frame [m].

        ``s R(-theta_b) e`` with ``theta_b`` the bushing body's angle and ``s = +1``
        when the bushing is on the joint's second body (``e`` then points from the
        bushing's centre to the pin's), ``-1`` on the first. The identity for an unworn
        bushing (a circle looks the same in every frame).

        Parameters
        ----------
        t : float
            Time [s].
        q : ndarray, shape (2,)
            Coupler and rocker angles [rad].
        ex, ey : float
            Clearance vector ``e`` in the global frame [m].
        """
        if not self._worn_frame:
            return ex, ey
        return to_bushing_frame(self.bushing_angle(t, q), self._bushing_sign, ex, ey)

    def contact_force(
        self,
        t: float,
        q: FloatArray,
        e: FloatArray,
        v: FloatArray,
        spin: float,
        approach: float,
        film_spin: float | None = None,
    ) -> tuple[float, float, float, float, float, float, float, float]:
        """:meth:`JointContact.force` for the clearance state, in the global frame.

        On a worn bushing the contact is evaluated in the bushing body's frame, its
        contour turning with it
        (:func:`~jointwear.mechanism.impact.bushing_frame.contact_force_in_frame`).

        Parameters
        ----------
        t : float
            Time [s].
        q : ndarray, shape (2,)
            Coupler and rocker angles [rad].
        e, v : ndarray, shape (2,)
            Clearance vector [m] and its rate [m/s], global.
        spin : float
            :meth:`_spin` [rad/s].
        approach : float
            ``delta'^-`` of the current contact [m/s].
        film_spin : float, optional
            Sum of the two bodies' angular velocities, for an oil film [rad/s].
        """
        if not self._worn_frame:
            return self.contact.force(e[0], e[1], v[0], v[1], spin, approach, film_spin)
        angle = self.bushing_angle(t, q)
        return contact_force_in_frame(
            self.contact, angle, self._bushing_sign, (e[0], e[1]), (v[0], v[1]), spin, approach,
            film_spin,
        )  # fmt: skip

    def gap(self, t: float, y: FloatArray) -> float:
        """Signed penetration of the state, on the bushing's own contour [m]."""
        ex, ey, _, _ = self.clearance_state(t, y)
        return self.contact.gap(*self.bushing_offset(t, np.asarray(y[:2]), ex, ey))

    def gap_and_rate(self, t: float, y: FloatArray) -> tuple[float, float]:
        ex, ey, vx, vy = self.clearance_state(t, y)
        gap = self.contact.gap(*self.bushing_offset(t, np.asarray(y[:2]), ex, ey))
        return gap, self.contact.gap_rate(ex, ey, vx, vy)

    def _spin(self, qd: FloatArray, e: FloatArray) -> float:
        """The spin :meth:`JointContact.force` multiplies by ``rho`` for the slip [rad/s].

        The slip of the first body's surface over the second's at the contact point is
        ``e'.t + rho (w1 - w2) - w2 |e|``; the contact adds ``rho * spin`` to ``e'.t``.
        """
        # angular velocities of the two bodies (crank: omega; ground: 0)
        first, second = JOINT_BODIES[self.joint]
        omega1 = self.omega if first == "crank" else float(qd[_ANGLE_INDEX[first]])
        omega2 = 0.0 if second == "ground" else float(qd[_ANGLE_INDEX[second]])
        rho = self.contact.friction_arm
        return (omega1 - omega2) - omega2 * math.hypot(e[0], e[1]) / rho if rho else 0.0

    def _film_spin(self, qd: FloatArray) -> float:
        """The sum of the two bodies' angular velocities, the film's wedge [rad/s]."""
        first, second = JOINT_BODIES[self.joint]
        omega1 = self.omega if first == "crank" else float(qd[_ANGLE_INDEX[first]])
        omega2 = 0.0 if second == "ground" else float(qd[_ANGLE_INDEX[second]])
        return omega1 + omega2

    def _mass_and_forces(
        self, t: float, q: FloatArray, qd: FloatArray
    ) -> tuple[FloatArray, FloatArray, dict[str, tuple[FloatArray, FloatArray]]]:
        """Mass matrix ``M(q)`` and generalized forces without the contact, and each
        moving body's centre-of-mass Jacobian and ``q'' = 0`` acceleration."""
        lk = self.linkage
        gravity = np.array([0.0, -lk.gravity])
        mass = self._constant_mass.copy()
        gen = np.array([0.0, float(rocker_load_torque(q[1], lk))])
        drifts = {}
        for body, m in self._masses.items():
            _, _, jac, drift = self._point(body, t, q, qd)
            drifts[body] = (jac, drift)
            mass += m * jac.T @ jac
            gen += m * jac.T @ (gravity - drift)
        return mass, gen, drifts

    def _crank_torque(
        self,
        t: float,
        q_ddot: FloatArray,
        drifts: dict[str, tuple[FloatArray, FloatArray]],
        force: FloatArray,
        contact_point: FloatArray,
    ) -> float:
        """Crank torque about A at constant omega, ``T = B x F_B + m1 g (l1 / 2) cos(phi)``."""
        lk = self.linkage
        gravity = np.array([0.0, -lk.gravity])
        phi = self.omega * t
        b = lk.crank_length * np.array([math.cos(phi), math.sin(phi)])

        def inertial(body: str) -> np.ndarray:
            jac, drift = drifts[body]
            return self._masses[body] * (jac @ q_ddot + drift - gravity)

        if self.joint == "crank-coupler":
            torque_arm, f_b = contact_point, force
        elif self.joint == "coupler-rocker":
            torque_arm, f_b = b, inertial("coupler") + force
        else:
            torque_arm, f_b = b, inertial("coupler") + inertial("rocker") + force
        return cross(torque_arm, f_b) + 0.5 * lk.crank_mass * lk.gravity * b[0]

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """``y' = (theta_2', theta_3', theta_2'', theta_3'', T omega + tau theta_3')``."""
        out = self.evaluate(t, y, impact_velocity)
        q_ddot = out["q_ddot"]
        power = out["crank_torque"] * self.omega + self.linkage.rocker_torque * y[3]
        return np.array([y[2], y[3], q_ddot[0], q_ddot[1], power])

    def energy(self, t: float, y: ArrayLike) -> float:
        """Kinetic + gravity + rocker spring + contact elastic energy [J].

        The crank's kinetic energy is constant and left out; its potential energy
        is included (the crank torque pays for it).
        """
        y = np.asarray(y, dtype=float)
        q, qd = y[:2], y[2:4]
        lk = self.linkage
        phi = self.omega * t
        energy = 0.5 * (lk.coupler_inertia * qd[0] ** 2 + lk.rocker_inertia * qd[1] ** 2)
        energy += lk.gravity * lk.crank_mass * 0.5 * lk.crank_length * math.sin(phi)
        for body, m in (("coupler", lk.coupler_mass), ("rocker", lk.rocker_mass)):
            pos, vel, _, _ = self._point(body, t, q, qd)
            energy += 0.5 * m * float(vel @ vel) + m * lk.gravity * float(pos[1])
        energy += 0.5 * lk.rocker_spring_stiffness * (q[1] - lk.rocker_spring_angle) ** 2
        ex, ey, _, _ = self.clearance_state(t, y)
        return float(energy + self.contact.potential(*self.bushing_offset(t, q, ex, ey)))

    # -------------------------------------------------------------- start
    def initial_state(self, load: ArrayLike, steps: int = 64) -> FloatArray:
        """State at ``phi = 0``: ideal motion, pin pressed into the wall along ``load``.

        Parameters
        ----------
        load : array_like, shape (2,)
            ``J`` of the ideal linkage at ``phi = 0`` [N].
        steps : int
            Newton iterations allowed for the offset geometry [-].
        """
        lk = self.linkage
        motion = four_bar_motion(np.zeros(1), *lk.lengths, self.omega, lk.assembly)
        q = np.array([motion.coupler_angle[0], motion.rocker_angle[0]])
        qd = np.array([motion.coupler_angular_velocity[0], motion.rocker_angular_velocity[0]])
        jx, jy = (float(v) for v in np.asarray(load, dtype=float))
        direction = math.atan2(jy, jx)
        seen = direction
        if self._worn_frame:
            # the same direction seen from the worn bushing, in its own frame
            along = self.bushing_offset(0.0, q, math.cos(direction), math.sin(direction))
            seen = math.atan2(along[1], along[0])
        offset = self.contact.static_offset(math.hypot(jx, jy), seen)
        target = offset * np.array([math.cos(direction), math.sin(direction)])
        # Newton on the loop residual e(q) = target (a 2x2 system, well conditioned
        # away from the toggle positions a crank-rocker never reaches)
        for _ in range(steps):
            p1, _, jac1, _ = self._point("first", 0.0, q, qd)
            p2, _, jac2, _ = self._point("second", 0.0, q, qd)
            residual = p1 - p2 - target
            if np.max(np.abs(residual)) <= 1e-15 * lk.coupler_length:
                break
            q = q - np.linalg.solve(jac1 - jac2, residual)
        # velocities: keep e' = 0 (the ideal rates solve it up to O(c))
        _, v1, jac1, _ = self._point("first", 0.0, q, np.zeros(2))
        _, v2, jac2, _ = self._point("second", 0.0, q, np.zeros(2))
        qd = np.linalg.solve(jac1 - jac2, -(v1 - v2))
        return np.array([q[0], q[1], qd[0], qd[1], 0.0])


def worn_bushing(inputs: MechanismInputs, wear_depth: FloatArray | None) -> BushingContour | None:
    """The worn bushing contour in its body's frame, or ``None`` for an unworn one.

    Parameters
    ----------
    inputs : MechanismInputs
        The joint's geometry.
    wear_depth : ndarray, shape (N,) or None
        Wear depth on the ``joint.nodes`` grid [m].
    """
    if wear_depth is None or not np.any(wear_depth):
        return None
    joint = inputs.joint
    return BushingContour.from_wear_profile(joint.bushing_radius, wear_depth, joint.axial_length)


def four_bar_contact(
    inputs: MechanismInputs,
    settings: ContactImpactSettings,
    joint: str,
    bushing_body: str,
    contour: BushingContour | None = None,
) -> JointContact:
    """The contact force model of a four-bar joint.

    Parameters
    ----------
    inputs : MechanismInputs
        The joint, its elastic law and its oil film.
    settings : ContactImpactSettings
        The ``[dynamics]`` settings of the contact–impact model.
    joint : str
        The clearance joint.
    bushing_body : str
        The body that carries its bushing.
    contour : BushingContour, optional
        The worn bushing in its body's frame (distributed laws: also an unworn one).

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
    geometry = inputs.joint
    # rho is measured from the first body's joint centre: R_p with the pin there,
    # -R_b with the bushing there (the slider-crank's rule keys on its own bodies)
    first = JOINT_BODIES[joint][0]
    arm = -geometry.bushing_radius if bushing_body == first else geometry.pin_radius
    return JointContact.for_joint(
        settings, inputs.elastic, geometry, arm, contour, film=inputs.film
    )


def four_bar_contact_impact(
    inputs: MechanismInputs,
    compare: bool = True,
    wear_depth: FloatArray | None = None,
) -> ContactImpactSolution:
    """Integrate the four-bar with a free pin in its clearance joint; one settled revolution.

    Parameters
    ----------
    inputs : MechanismInputs
        A four-bar with one clearance joint: its ``[mechanism]`` section, the joint and
        its elastic law, the ``[dynamics]`` settings and the steps per revolution.
    compare : bool
        Also compute the massless-link load and report the difference.
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing on the ``joint.nodes`` grid, in the frame of the body
        that carries it [m]: the pin meets the worn contour, which turns with that
        body. ``None``: the unworn bushing.

    Returns
    -------
    ContactImpactSolution
        ``load`` is the normal contact force (zero in free flight) with the contact
        normal's azimuth in the bushing body's frame.

    Raises
    ------
    ConfigError
        If more than one clearance joint is configured.
    ConvergenceError
        If the integrator fails.
    """
    mech = inputs.mechanism
    if len(mech.joints) != 1:
        raise ConfigError("mechanism.clearance_joint: contact-impact models one clearance joint")
    joint, bushing = mech.joints[0], mech.bushing_bodies[0]
    settings = ContactImpactSettings.from_config(inputs.dynamics)
    steps = inputs.steps
    linkage = FourBar.from_config(mech)
    motion = ideal_motion(linkage, mech.crank_speed, steps)
    ideal = joint_force(inverse_dynamics(motion, linkage), joint)
    contact = four_bar_contact(inputs, settings, joint, bushing, worn_bushing(inputs, wear_depth))
    system = FourBarContactSystem(linkage, mech.crank_speed, contact, joint, bushing)
    run = integrate_revolution(system, system.initial_state(ideal[0]), settings, steps)

    states = run.states
    angles = {
        "crank": motion.crank_angle,
        "coupler": states[:-1, 0],
        "rocker": states[:-1, 1],
        "ground": np.zeros(steps),
    }
    # increments up to the sampled end of the revolution: the settled motion is
    # periodic only to the integration tolerance, so step N-1 does not end at step 0
    increments = {
        "crank": np.full(steps, 2.0 * math.pi / steps),
        "coupler": np.diff(states[:, 0]),
        "rocker": np.diff(states[:, 1]),
        "ground": np.zeros(steps),
    }
    load = joint_cycle(
        mech,
        joint,
        bushing,
        np.column_stack((run.column("force_x"), run.column("force_y"))),
        angles,
        increments,
        run.column("crank_torque"),
        normal=np.column_stack((run.column("normal_x"), run.column("normal_y"))),
        load=run.column("normal_force"),
        model="contact-impact",
        lost_steps=run.step_lost,
    )
    return sampled_solution(
        load,
        run,
        system,
        settings,
        (lambda: massless_link_cycles(inputs)[joint]) if compare else None,
    )
