r"""Contact–impact dynamics of the oscillating bearing: the loaded pin free in the clearance.

The prescribed model (:mod:`jointwear.mechanism.oscillating`) presses the pin on the wall
along the load at every instant. Here the pin, with the mass ``m`` that moves with it
(``mechanism.pin_mass``: pin and loading arm), is free in the clearance of the fixed
bushing. Its rotation ``varphi(t) = A sin(2 pi t / T)`` is driven; the load
``F(t) u(t)`` of the rig (``u`` at ``load_angle``, turning with the pin for
``load_frame = "pin"``) pushes it, and the bushing's contact force
(:class:`~jointwear.mechanism.impact.joint_contact.JointContact`) holds it:

.. math::

    m \ddot{\mathbf e} = F(t)\, \mathbf u(t) - \mathbf J(\mathbf e, \dot{\mathbf e},
        \dot\varphi), \qquad \mathbf J = F_N \mathbf n + F_T \mathbf t ,

``e`` the pin centre's offset from the bushing centre (bushing frame = global frame),
``J`` the force of the pin on the bushing. Friction ``F_T = mu c_d(v_T) F_N sign(v_T)``
acts on the slip ``v_T = e' . t + R_p varphi'`` of the pin's surface over the
bushing's: it drives the contact up the wall against the sliding, by ``atan(mu)`` in
the steady state (the friction circle), and back at each reversal, so the scar is
wider than the load line's. State ``(e_x, e_y, e'_x, e'_y, W)``, ``W`` the work of the
load [J]; one oscillation is the period the shared machinery calls a revolution
(:func:`~jointwear.mechanism.impact.revolution.integrate_revolution`).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError
from jointwear.geometry.contour import BushingContour
from jointwear.mechanism.cycle import Diagnostic, LoadCycle, bushing_azimuth
from jointwear.mechanism.impact.integrator import ContactSystemBase
from jointwear.mechanism.impact.joint_contact import JointContact
from jointwear.mechanism.impact.revolution import (
    ContactImpactSolution,
    integrate_revolution,
    sampled_solution,
)
from jointwear.mechanism.impact.settings import ContactImpactSettings
from jointwear.mechanism.inputs import MechanismInputs

__all__ = ["OscillatingContactSystem", "oscillating_contact_impact"]

FloatArray = NDArray[np.float64]


class OscillatingContactSystem(ContactSystemBase):
    """The oscillating bearing's loaded pin free in the clearance (module docstring).

    Parameters
    ----------
    mechanism : jointwear.config.OscillatingConfig
        Load, its frame and harmonic, amplitude, frequency and ``pin_mass``.
    contact : JointContact
        Contact force model (friction arm ``R_p``: the pin is the turning body).
    """

    def __init__(self, mechanism, contact: JointContact) -> None:
        self.mechanism = mechanism
        self.contact = contact
        self.mass = float(mechanism.pin_mass)
        #: angular frequency of the oscillation: one oscillation is one "revolution"
        self.omega = 2.0 * math.pi * float(mechanism.frequency)

    def pin_angle(self, t: float) -> tuple[float, float]:
        """Pin rotation ``varphi`` [rad] and its rate [rad/s] at time ``t`` [s]."""
        amplitude, phase = self.mechanism.amplitude, self.omega * t
        return amplitude * math.sin(phase), amplitude * self.omega * math.cos(phase)

    def load(self, t: float) -> tuple[float, float]:
        """The rig's force on the pin, ``F(t) u(t)`` [N], global (= bushing) frame."""
        mech, phase = self.mechanism, self.omega * t
        magnitude = mech.load + mech.load_amplitude * math.cos(
            mech.load_harmonic * phase + mech.load_phase
        )
        direction = mech.load_angle
        if mech.load_frame == "pin":
            direction += self.pin_angle(t)[0]
        return magnitude * math.cos(direction), magnitude * math.sin(direction)

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        return float(y[0]), float(y[1]), float(y[2]), float(y[3])

    def evaluate(self, t: float, y: ArrayLike, impact_velocity: float) -> dict[str, float]:
        """Acceleration of the pin and the contact force at one instant.

        Parameters
        ----------
        t : float
            Time [s].
        y : array_like, shape (5,)
            State.
        impact_velocity : float
            ``delta'^-`` of the current contact [m/s].

        Returns
        -------
        dict
            ``ax``/``ay`` [m/s^2], ``force_x``/``force_y`` (``J``, on the bushing) [N],
            ``normal_force``/``friction_force`` [N], ``normal_x``/``normal_y`` [-],
            ``penetration`` [m], ``slip`` [m/s], ``load_x``/``load_y`` [N], the pin's
            offset ``ex``/``ey`` [m].
        """
        ex, ey, vx, vy = (float(v) for v in np.asarray(y, dtype=float)[:4])
        spin = self.pin_angle(t)[1]
        jx, jy, normal, tangential, nx, ny, delta, slip = self.contact.force(
            ex, ey, vx, vy, spin, impact_velocity
        )
        fx, fy = self.load(t)
        return {
            "ax": (fx - jx) / self.mass,
            "ay": (fy - jy) / self.mass,
            "force_x": jx,
            "force_y": jy,
            "normal_force": normal,
            "friction_force": tangential,
            "normal_x": nx,
            "normal_y": ny,
            "penetration": delta,
            "slip": slip,
            "load_x": fx,
            "load_y": fy,
            "ex": ex,
            "ey": ey,
        }

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """``y' = (e', e'', F u . e')``."""
        out = self.evaluate(t, y, impact_velocity)
        power = out["load_x"] * y[2] + out["load_y"] * y[3]
        return np.array([y[2], y[3], out["ax"], out["ay"], power])

    def energy(self, t: float, y: ArrayLike) -> float:
        """Kinetic + contact elastic energy [J] (the load's work is the state's ``W``)."""
        ex, ey, vx, vy = (float(v) for v in np.asarray(y, dtype=float)[:4])
        return 0.5 * self.mass * (vx * vx + vy * vy) + self.contact.potential(ex, ey)

    def initial_state(self) -> FloatArray:
        """State at ``t = 0``: the pin at rest, pressed into the wall by the load [m]."""
        fx, fy = self.load(0.0)
        direction = math.atan2(fy, fx)
        offset = self.contact.static_offset(math.hypot(fx, fy), direction)
        return np.array([offset * math.cos(direction), offset * math.sin(direction), 0, 0, 0.0])


def oscillating_contact_impact(
    inputs: MechanismInputs,
    prescribed: LoadCycle,
    wear_depth: FloatArray | None = None,
    compare: bool = True,
) -> ContactImpactSolution:
    """Integrate the oscillating bearing with a free pin; one settled oscillation.

    Parameters
    ----------
    inputs : MechanismInputs
        The ``[mechanism]`` section (type ``"oscillating"``), the joint and its elastic
        law, the ``[dynamics]`` settings and the steps per oscillation.
    prescribed : LoadCycle
        The prescribed load cycle of the same bearing
        (:func:`jointwear.mechanism.oscillating.oscillating_cycle`): its times and
        rotation, and the load the free pin's is compared with.
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the (fixed) bushing on the ``joint.nodes`` grid [m]: the pin meets
        the worn contour. ``None``: the unworn bushing.
    compare : bool
        Also compute the prescribed load (the pin on the wall along the load) and
        report the difference.

    Returns
    -------
    ContactImpactSolution
        ``load`` is the normal contact force (zero in free flight), its azimuth the
        contact normal's in the bushing frame.

    Raises
    ------
    ConfigError
        If ``inputs`` carries no elastic law.
    ConvergenceError
        If the integrator fails.
    """
    if inputs.elastic is None:
        raise ConfigError(
            "dynamics.model: the contact-impact model needs the joint's elastic law "
            "(jointwear.mechanism.stage.mechanism_inputs builds it)"
        )
    mech, joint, steps = inputs.mechanism, inputs.joint, inputs.steps
    settings = ContactImpactSettings.from_config(inputs.dynamics)
    contour = None
    if wear_depth is not None and np.any(wear_depth):
        contour = BushingContour.from_wear_profile(
            joint.bushing_radius, wear_depth, joint.axial_length
        )
    # rho = R_p: the pin is the turning body, the bushing does not move
    contact = JointContact.for_joint(settings, inputs.elastic, joint, joint.pin_radius, contour)
    system = OscillatingContactSystem(mech, contact)
    run = integrate_revolution(system, system.initial_state(), settings, steps, dense=False)
    normal = run.column("normal_force")
    load = LoadCycle.from_arrays(
        load=normal,
        azimuth=bushing_azimuth(run.column("normal_x"), run.column("normal_y")),
        relative_rotation=prescribed.relative_rotation,
        period=mech.period,
        time=prescribed.time,
        mechanism="oscillating",
        joint="bearing",
        model="contact-impact",
        lost_steps=run.step_lost,
        diagnostics={
            **prescribed.diagnostics,
            "pin_offset_x": Diagnostic(run.states[:-1, 0], "m", "pin centre offset, x"),
            "pin_offset_y": Diagnostic(run.states[:-1, 1], "m", "pin centre offset, y"),
        },
        extras=dict(prescribed.extras),
    )
    return sampled_solution(load, run, system, settings, (lambda: prescribed) if compare else None)
