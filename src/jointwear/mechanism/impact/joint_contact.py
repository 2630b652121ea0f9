r"""The contact force between pin and bushing for a relative state of the two bodies.

:class:`JointContact` applies a force law of :mod:`jointwear.mechanism.impact.force_laws`
(point laws) or :mod:`jointwear.mechanism.impact.distributed` (``nlcp``, ``winkler``)
and Coulomb friction to a clearance joint: for the pin-centre offset ``e``, its rate
and the spin it gives the normal and friction force on each body. Every contact
system (the slider-crank's, the four-bar's, the free pin's) evaluates it at every
right-hand side call. A lubricated joint adds the oil film's force
(:mod:`jointwear.mechanism.impact.film`) to the contact force, in free flight and in
contact.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError, ConvergenceError
from jointwear.geometry.contour import BushingContour, Pin, pin_penetration
from jointwear.mechanism.impact.distributed import (
    PressureLaw,
    force_area,
    spring_gap,
    spring_resultant,
)
from jointwear.mechanism.impact.film import FilmParameters, joint_film_force
from jointwear.mechanism.impact.force_laws import DISTRIBUTED_LAWS, hysteresis_factor

if TYPE_CHECKING:
    from jointwear.mechanism.impact.settings import ContactImpactSettings
    from jointwear.mechanism.inputs import ElasticLaw, JointGeometry

__all__ = ["JointContact"]

FloatArray = NDArray[np.float64]


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
        One of :data:`FORCE_LAWS`.
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
    spring_law : PressureLaw, optional
        Node pressure law (distributed laws).
    film : FilmParameters, optional
        The oil film of a lubricated joint; ``None`` or ``"dry"``: none.
    pin_radius : float, optional
        Pin radius ``R`` of the film force [m] (needed with a film).
    axial_length : float, optional
        The joint's axial length [m]: the film's length unless ``film.length`` is given.
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
        spring_law: PressureLaw | None = None,
        film: FilmParameters | None = None,
        pin_radius: float | None = None,
        axial_length: float | None = None,
    ) -> None:
        self.force_law = force_law
        self.hysteresis = hysteresis_factor(force_law, restitution)
        self.restitution = restitution
        self.clearance = float(clearance)
        self.stiffness = float(stiffness)
        self.exponent = float(exponent)
        self.friction_coefficient = float(friction_coefficient)
        self.v0 = float(friction_velocity_tolerance)
        self.v1 = 2.0 * self.v0 if friction_full_speed is None else float(friction_full_speed)
        self.friction_arm = float(friction_arm)
        self.impact_velocity_floor = float(impact_velocity_floor)
        self.distributed = force_law in DISTRIBUTED_LAWS
        # a worn bushing under a point law: the clearance grows by the wear depth in
        # the direction of the pin (periodic linear interpolation of the profile)
        self._wear: FloatArray | None = None
        if not self.distributed and contour is not None and np.any(contour.wear_depth):
            self._wear = np.append(
                np.asarray(contour.wear_depth, dtype=float), float(contour.wear_depth[0])
            )
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
            self._area = np.broadcast_to(force_area(contour, spring_law), self._radius.shape)
            self._pin_radius = pin.radius
            self._gap = self._radius - pin.radius
        self.contour = contour
        self.pin = pin
        self.spring_law = spring_law
        self.film = film if film is not None and film.active else None
        #: ``(model code, R, L, c, mu, delta_1 / c)`` of :func:`joint_film_force`
        self.film_arguments = (0.0, 0.0, 0.0, self.clearance, 0.0, 0.0)
        if self.film is not None:
            length = self.film.length if self.film.length is not None else axial_length
            if pin_radius is None or length is None:
                raise ConfigError(
                    "lubrication.model: a lubricated joint needs the pin radius and the film length"
                )
            self.film_arguments = (
                float(self.film.code),
                float(pin_radius),
                float(length),
                self.clearance,
                float(self.film.viscosity),
                self.film.band(self.clearance) / self.clearance,
            )

    def _springs(self, ex: float, ey: float) -> tuple[float, float, float]:
        """Elastic resultant ``(F_x, F_y)`` [N] and signed gap [m] of the distributed law.

        Same as :func:`~jointwear.mechanism.impact.distributed.spring_resultant` and
        :func:`~jointwear.mechanism.impact.distributed.spring_gap`, evaluated only on the
        penetrated nodes (the integrator calls it at every step).
        """
        along = self._cos * ex + self._sin * ey
        across = self._cos * ey - self._sin * ex
        depth = pin_penetration(along, across, self._gap, self._pin_radius)
        gap = float(depth.max())
        if gap <= 0.0:
            return 0.0, 0.0, gap
        touch = depth > 0.0
        c, sn, lateral = self._cos[touch], self._sin[touch], across[touch]
        ratio = lateral / np.sqrt(self._pin_radius**2 - lateral * lateral)
        force = self._area[touch] * self.spring_law.pressure(depth[touch])
        fx = float(np.dot(force, c + sn * ratio))
        fy = float(np.dot(force, sn - c * ratio))
        return fx, fy, gap

    @classmethod
    def for_joint(
        cls,
        settings: ContactImpactSettings,
        elastic: ElasticLaw,
        joint: JointGeometry,
        friction_arm: float,
        contour: BushingContour | None = None,
        film: FilmParameters | None = None,
    ) -> JointContact:
        """Contact model of a joint with the ``[dynamics]`` settings.

        Parameters
        ----------
        settings : ContactImpactSettings
            Force law, restitution, friction and the approach-velocity floor.
        elastic : ElasticLaw
            Hertz stiffness ``K`` of the point laws and, for ``nlcp``/``winkler``, the
            bushing's spring law.
        joint : JointGeometry
            Pin radius, clearance, axial length and contour nodes.
        friction_arm : float
            ``rho`` (class docstring): ``R_p`` or ``-R_b`` [m].
        contour : BushingContour, optional
            Bushing contour for ``nlcp``/``winkler`` (default: the unworn circle with
            ``joint.nodes`` nodes), or the worn bushing of a point law.
        film : FilmParameters, optional
            The oil film of a lubricated joint (its force acts with the contact's).
        """
        extra: dict[str, Any] = {}
        if settings.force_law in DISTRIBUTED_LAWS:
            if contour is None:
                contour = BushingContour.circle(
                    joint.bushing_radius, joint.nodes, joint.axial_length
                )
            extra = {
                "contour": contour,
                "pin": Pin(joint.pin_radius),
                "spring_law": elastic.spring_law,
            }
        elif contour is not None:
            extra = {"contour": contour}
        return cls(
            force_law=settings.force_law,
            clearance=joint.bushing_radius - joint.pin_radius,
            stiffness=elastic.stiffness,
            restitution=settings.restitution,
            exponent=1.5,
            friction_coefficient=settings.friction_coefficient,
            friction_velocity_tolerance=settings.friction_velocity_tolerance,
            friction_full_speed=settings.friction_velocity_full,
            friction_arm=friction_arm,
            impact_velocity_floor=settings.impact_velocity_floor,
            film=film,
            pin_radius=joint.pin_radius,
            axial_length=joint.axial_length,
            **extra,
        )

    # -------------------------------------------------------------- geometry
    @property
    def wear_profile(self) -> FloatArray | None:
        """Wear depth of the bushing that a point law adds to the clearance, closed
        (the first node repeated at the end) [m]; ``None`` for an unworn bushing or a
        distributed law."""
        return self._wear

    def clearance_at(self, ex: float, ey: float) -> float:
        """Radial clearance in the direction of ``e`` [m] (point laws; the wear adds to it)."""
        if self._wear is None:
            return self.clearance
        nodes = self._wear.size - 1
        position = (math.atan2(ey, ex) % (2.0 * math.pi)) * nodes / (2.0 * math.pi)
        index = min(int(position), nodes - 1)
        fraction = position - index
        return (
            self.clearance + (1.0 - fraction) * self._wear[index] + fraction * self._wear[index + 1]
        )

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
            _, energy, _ = spring_resultant(
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
            return self.touch_offset(direction)
        if not self.distributed:
            touch = self.touch_offset(direction)
            return touch + (load / self.stiffness) ** (1.0 / self.exponent)
        unit = np.array([math.cos(direction), math.sin(direction)])
        lower = self.touch_offset(direction)

        def residual(s: float) -> float:
            force, _, _ = spring_resultant(self.contour, self.pin, s * unit, self.spring_law)
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

    def touch_offset(self, direction: float) -> float:
        """Offset ``|e|`` along ``direction`` at which the pin first touches the contour [m]."""
        if not self.distributed:
            return self.clearance_at(math.cos(direction), math.sin(direction))
        unit = np.array([math.cos(direction), math.sin(direction)])
        upper = 2.0 * (float(self.contour.radius.max()) - self.pin.radius)

        def gap(s: float) -> float:
            return float(spring_gap(self.contour, self.pin, s * unit))

        from scipy.optimize import brentq

        return float(brentq(gap, 0.0, upper, xtol=1e-16, rtol=1e-14))

    # -------------------------------------------------------------- force
    def film_force(
        self, ex: float, ey: float, vx: float, vy: float, spin: float
    ) -> tuple[float, float]:
        """The oil film's force on the slider side (``D``), zero for a dry joint [N].

        Parameters
        ----------
        ex, ey : float
            ``e = C - D`` [m].
        vx, vy : float
            ``e'`` [m/s].
        spin : float
            Sum of the angular velocities of the two bodies [rad/s].
        """
        if self.film is None:
            return 0.0, 0.0
        return joint_film_force(ex, ey, vx, vy, spin, *self.film_arguments)

    def force(
        self,
        ex: float,
        ey: float,
        vx: float,
        vy: float,
        spin: float,
        impact_velocity: float,
        film_spin: float | None = None,
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
        film_spin : float, optional
            Sum of the angular velocities of the two bodies, for the film's wedge
            [rad/s]; default ``spin`` (the slider side does not turn).

        Returns
        -------
        tuple of float
            ``(J_x, J_y, F_N, F_T, n_x, n_y, penetration, slip)``: force on the
            slider side, the film's included [N], normal and friction components of
            the contact [N], unit normal [-], largest penetration [m], slip velocity
            ``v_T`` [m/s].
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
        film_x = film_y = 0.0
        if self.film is not None:
            film_x, film_y = joint_film_force(
                ex, ey, vx, vy, spin if film_spin is None else film_spin, *self.film_arguments
            )
        if elastic <= 0.0:
            if self.film is not None:
                return film_x, film_y, 0.0, 0.0, nx, ny, delta, slip
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
        if self.film is not None:
            jx, jy = jx + film_x, jy + film_y
        return jx, jy, normal, tangential, nx, ny, delta, slip
