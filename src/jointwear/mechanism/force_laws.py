r"""The contact force of the clearance joint: force laws (``dynamics.force_law``) and friction.

The contact–impact dynamics (:mod:`jointwear.mechanism.contact_impact`) lets the pin
move freely inside the bushing; while it penetrates the wall, the normal force
comes from one of the laws below, and Coulomb friction acts along the wall.
:class:`JointContact` applies them to the joint: for a relative state of the two
bodies (pin-centre offset ``e``, its rate and the spin) it gives the force on each.

**Point laws** (the pin-in-hole as one Hertz contact, penetration
``delta = |e| - c`` of the pin-centre offset ``e`` beyond the radial clearance
``c = R_b - R_p``). All are Hertz's elastic force with a hysteresis damping term,

.. math::

    F_N = K \delta^n \left(1 + \chi \frac{\dot\delta}{\dot\delta^{(-)}}\right),
    \qquad F_N \leftarrow \max(F_N, 0),

with ``delta_dot^(-)`` the normal approach velocity at the start of the contact
(recorded at the contact-start event) and ``chi`` the hysteresis factor
(:func:`hysteresis_factor`):

=======================  ===============================  ============================
``lankarani-nikravesh``  ``chi = 3 (1 - c_e^2) / 4``      derived for ``c_e -> 1``
``hunt-crossley``        ``chi = 3 (1 - c_e) / 2``        derived for ``c_e -> 1``
``flores``               ``chi = 8 (1 - c_e) / (5 c_e)``  any ``c_e`` (soft materials)
=======================  ===============================  ============================

(Lankarani and Nikravesh [1]_, Hunt and Crossley [2]_ with Marhefka and Orin [3]_,
Flores et al. [4]_.)

``K`` is eq. (2) of the NLCP paper with ``R_i = R_p`` (pin) and ``R_j = R_b``
(bushing, internal contact, :func:`pin_in_hole_stiffness`), ``n = 1.5``.
The clip ``max(F_N, 0)`` removes the small tensile force the damping term gives
near the end of the restitution phase when ``chi delta_dot^(+)/delta_dot^(-) > 1``
(low ``c_e``); the contact then ends with ``delta > 0`` still (the wall recovers
after the pin has left).

**Distributed laws** ``nlcp`` and ``winkler``: the pressure model of the wear
pipeline (:mod:`jointwear.contact`) integrated over the current bushing contour
for the displaced pin (:func:`spring_resultant`). Each node ``j`` of the contour
is a radial spring with the exact penetration ``delta_j(e) = max(t_j(e) - r_j, 0)``
(:meth:`jointwear.geometry.BushingContour.penetration`), pressure ``p(delta_j)``
from the spring law and area ``A_j``; the elastic force on the bushing is the
gradient of the stored energy

.. math::

    V(\mathbf e) = \sum_j A_j \int_0^{\delta_j} p(s)\,ds, \qquad
    \mathbf F_{el} = \nabla_{\mathbf e} V = \sum_j A_j\, p(\delta_j)\, \nabla t_j ,

which is the radial-spring resultant ``sum_j A_j p_j u_j`` up to terms of order
``|e| / R_p`` (about 1 % of each spring's force, mostly cancelling between the two
sides), and is exactly conservative. The same hysteresis damping as
Lankarani–Nikravesh multiplies it.

**Friction** (:func:`friction_force`): Coulomb with Ambrósio's dynamic correction
coefficient [5]_, ``F_T = -mu c_d(v_T) F_N sign(v_T)``, ``c_d`` rising from 0 at
``|v_T| <= v_0`` to 1 at ``|v_T| >= v_1`` (here a C1 cubic ramp instead of the
original linear one, so the right-hand side of the equations of motion stays
differentiable).

References
----------
.. [1] Lankarani, H. M., Nikravesh, P. E.: A contact force model with hysteresis
   damping for impact analysis of multibody systems. J. Mech. Des. 112, 369-376
   (1990).
.. [2] Hunt, K. H., Crossley, F. R. E.: Coefficient of restitution interpreted as
   damping in vibroimpact. J. Appl. Mech. 42, 440-445 (1975).
.. [3] Marhefka, D. W., Orin, D. E.: A compliant contact model with nonlinear
   damping for simulation of robotic systems. IEEE Trans. SMC A 29, 566-572 (1999).
.. [4] Flores, P., Machado, M., Silva, M. T., Martins, J. M.: On the continuous
   contact force models for soft materials in multibody dynamics. Multibody
   Syst. Dyn. 25, 357-375 (2011).
.. [5] Ambrósio, J. A. C.: Impact of rigid and flexible multibody systems:
   deformation description and contact models. In: Virtual Nonlinear Multibody
   Systems, NATO Sci. Ser. 103, 57-81 (2003).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact import hertz
from jointwear.contact.laws import ContactParameters, PowerLaw, SpringLaw
from jointwear.errors import ConfigError, ConvergenceError
from jointwear.geometry.contour import (
    BushingContour,
    Pin,
    pin_penetration,
    ray_distance_derivative,
)

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = [
    "DISTRIBUTED_LAWS",
    "FORCE_LAWS",
    "POINT_LAWS",
    "ForceLaw",
    "JointContact",
    "dissipative_force",
    "elastic_force",
    "elastic_potential",
    "friction_force",
    "friction_ramp",
    "hysteresis_factor",
    "hysteresis_restitution",
    "pin_in_hole_stiffness",
    "spring_gap",
    "spring_resultant",
]

FloatArray = NDArray[np.float64]
ForceLaw = Literal["lankarani-nikravesh", "hunt-crossley", "flores", "nlcp", "winkler"]

#: laws with one Hertz contact ``F = K delta^n (...)``
POINT_LAWS: tuple[str, ...] = ("lankarani-nikravesh", "hunt-crossley", "flores")
#: laws integrated over the bushing contour with a :mod:`jointwear.contact` spring law
DISTRIBUTED_LAWS: tuple[str, ...] = ("nlcp", "winkler")
#: every name accepted by ``dynamics.force_law``
FORCE_LAWS: tuple[str, ...] = POINT_LAWS + DISTRIBUTED_LAWS


def hysteresis_factor(law: str, restitution: float) -> float:
    """Hysteresis factor ``chi`` of a dissipative contact law [-].

    Parameters
    ----------
    law : str
        One of :data:`FORCE_LAWS`; ``"nlcp"`` and ``"winkler"`` use the
        Lankarani–Nikravesh factor.
    restitution : float
        Coefficient of restitution ``c_e``, ``0 < c_e <= 1`` [-].

    Returns
    -------
    float
        ``3 (1 - c_e^2) / 4`` (Lankarani–Nikravesh, nlcp, winkler),
        ``3 (1 - c_e) / 2`` (Hunt–Crossley) or ``8 (1 - c_e) / (5 c_e)`` (Flores)
        [-]; zero for ``c_e = 1`` (elastic contact).

    Raises
    ------
    ConfigError
        For an unknown law or ``c_e`` outside ``(0, 1]``.
    """
    if not 0.0 < restitution <= 1.0:
        raise ConfigError(f"dynamics.restitution: must be in (0, 1], got {restitution!r}")
    if law in ("lankarani-nikravesh", "nlcp", "winkler"):
        return 0.75 * (1.0 - restitution**2)
    if law == "hunt-crossley":
        return 1.5 * (1.0 - restitution)
    if law == "flores":
        return 1.6 * (1.0 - restitution) / restitution
    raise ConfigError(
        f"dynamics.force_law: unknown force law {law!r}; choose from "
        + ", ".join(repr(name) for name in FORCE_LAWS)
    )


def hysteresis_restitution(hysteresis: float) -> float:
    r"""Coefficient of restitution that a hysteresis factor actually produces [-].

    For every force of the form ``F = f(delta) (1 + chi delta'/delta'^-)`` (any
    elastic law ``f``: Hertz, NLCP or Winkler resultants) a single impact of a
    free body ends with the normal velocity ``-e delta'^-``, where ``e`` depends on
    ``chi`` only. With ``u = delta' / delta'^-``, ``m delta'' = -F`` gives
    ``m delta'^-^2 u du / (1 + chi u) = -f(delta) d delta``; over the compression
    (``u: 1 -> 0``) and restitution (``u: 0 -> -e``) the right side integrates to
    zero, so

    .. math:: \int_1^{-e} \frac{u\,du}{1 + \chi u} = 0
              \iff \chi (1 + e) = \ln\frac{1 + \chi}{1 - \chi e},

    independent of the mass, the impact velocity, ``K`` and ``n``. Since
    ``e < 1/chi``, the damped force never turns tensile during a free impact.

    Parameters
    ----------
    hysteresis : float
        ``chi >= 0`` [-] (:func:`hysteresis_factor`).

    Returns
    -------
    float
        Effective coefficient of restitution ``e`` in ``(0, 1]`` [-].
    """
    chi = float(hysteresis)
    if chi < 0.0 or not math.isfinite(chi):
        raise ConfigError(f"hysteresis factor must be finite and >= 0, got {hysteresis!r}")
    if chi == 0.0:
        return 1.0

    def balance(e: float) -> float:
        if chi < 0.5:
            # the integral as a power series in chi: well conditioned for small chi
            total, power, k = 0.0, 1.0, 0
            while True:
                term = power * ((-e) ** (k + 2) - 1.0) / (k + 2)
                total += term
                k += 1
                power *= -chi
                if abs(power) < 1e-18 or k > 200:
                    return total
        return chi * (1.0 + e) - math.log1p(chi) + math.log1p(-chi * e)

    upper = min(1.0, (1.0 - 1e-15) / chi)
    from scipy.optimize import brentq  # lazy: keeps `jointwear` quick to start

    return float(brentq(balance, 0.0, upper, xtol=1e-15, rtol=1e-14))


def pin_in_hole_stiffness(
    pin_radius: float,
    bushing_radius: float,
    pin_youngs_modulus: float,
    pin_poisson_ratio: float,
    bushing_youngs_modulus: float,
    bushing_poisson_ratio: float,
) -> float:
    """Hertz stiffness ``K`` of a pin in a hole, eq. (2) with ``R_i = R_p``, ``R_j = R_b``.

    .. math:: K = \\frac{4}{3\\pi(\\sigma_p + \\sigma_b)}
              \\left[\\frac{R_p R_b}{R_b - R_p}\\right]^{1/2}

    Parameters
    ----------
    pin_radius : float
        Pin radius ``R_p`` [m].
    bushing_radius : float
        Bushing inner radius ``R_b > R_p`` [m].
    pin_youngs_modulus, bushing_youngs_modulus : float
        Young's moduli [Pa].
    pin_poisson_ratio, bushing_poisson_ratio : float
        Poisson's ratios [-].

    Returns
    -------
    float
        ``K`` [N/m^1.5].
    """
    return float(
        hertz.stiffness(
            pin_radius,
            bushing_radius,
            pin_youngs_modulus,
            pin_poisson_ratio,
            bushing_youngs_modulus,
            bushing_poisson_ratio,
        )
    )


def elastic_force(penetration: ArrayLike, stiffness: float, exponent: float = 1.5) -> FloatArray:
    """Hertz's elastic force ``K delta^n`` (eq. 1), zero without penetration [N].

    Parameters
    ----------
    penetration : array_like
        Penetration ``delta`` [m]; ``<= 0`` means no contact.
    stiffness : float
        ``K`` [N/m^n].
    exponent : float
        ``n`` [-].
    """
    delta = np.maximum(np.asarray(penetration, dtype=float), 0.0)
    return stiffness * delta**exponent


def elastic_potential(
    penetration: ArrayLike, stiffness: float, exponent: float = 1.5
) -> FloatArray:
    """Energy stored by the elastic force ``K delta^(n+1) / (n+1)`` [J].

    Parameters
    ----------
    penetration : array_like
        Penetration ``delta`` [m]; ``<= 0`` means no contact.
    stiffness : float
        ``K`` [N/m^n].
    exponent : float
        ``n`` [-].
    """
    delta = np.maximum(np.asarray(penetration, dtype=float), 0.0)
    return stiffness * delta ** (exponent + 1.0) / (exponent + 1.0)


def dissipative_force(
    penetration: ArrayLike,
    penetration_rate: ArrayLike,
    impact_velocity: ArrayLike,
    stiffness: float,
    hysteresis: float,
    exponent: float = 1.5,
) -> FloatArray:
    """Hertz force with hysteresis damping, ``max(K delta^n (1 + chi delta'/delta'^-), 0)`` [N].

    Parameters
    ----------
    penetration : array_like
        Penetration ``delta`` [m]; ``<= 0`` gives zero force.
    penetration_rate : array_like
        ``d delta / dt`` [m/s], positive while the pin moves into the wall.
    impact_velocity : array_like
        Approach velocity ``delta'^-`` at the start of the contact [m/s], > 0.
    stiffness : float
        ``K`` [N/m^n].
    hysteresis : float
        ``chi`` [-] (:func:`hysteresis_factor`).
    exponent : float
        ``n`` [-].

    Returns
    -------
    ndarray
        Normal contact force, never negative [N].
    """
    elastic = elastic_force(penetration, stiffness, exponent)
    rate = np.asarray(penetration_rate, dtype=float) / np.asarray(impact_velocity, dtype=float)
    return np.maximum(elastic * (1.0 + hysteresis * rate), 0.0)


def friction_ramp(
    slip_speed: ArrayLike, tolerance: float, full_speed: float | None = None
) -> FloatArray:
    """Ambrósio's dynamic correction coefficient ``c_d(|v_T|)`` as a C1 ramp [-].

    ``c_d = 0`` for ``|v_T| <= v_0``, ``c_d = 1`` for ``|v_T| >= v_1`` and the
    cubic ``3 s^2 - 2 s^3``, ``s = (|v_T| - v_0) / (v_1 - v_0)``, in between.

    Parameters
    ----------
    slip_speed : array_like
        Tangential slip speed ``|v_T|`` [m/s].
    tolerance : float
        ``v_0`` [m/s], > 0.
    full_speed : float, optional
        ``v_1 > v_0`` [m/s]; default ``2 v_0``.
    """
    v1 = 2.0 * tolerance if full_speed is None else full_speed
    s = np.clip(
        (np.abs(np.asarray(slip_speed, dtype=float)) - tolerance) / (v1 - tolerance), 0.0, 1.0
    )
    return s * s * (3.0 - 2.0 * s)


def friction_force(
    slip_velocity: ArrayLike,
    normal_force: ArrayLike,
    coefficient: float,
    tolerance: float,
    full_speed: float | None = None,
) -> FloatArray:
    """Regularised Coulomb friction ``-mu c_d(v_T) F_N sign(v_T)`` [N].

    Parameters
    ----------
    slip_velocity : array_like
        Signed tangential velocity ``v_T`` of the surface the force acts on,
        relative to the other surface [m/s].
    normal_force : array_like
        Normal contact force ``F_N >= 0`` [N].
    coefficient : float
        Coulomb friction coefficient ``mu`` [-].
    tolerance : float
        ``v_0`` of :func:`friction_ramp` [m/s].
    full_speed : float, optional
        ``v_1`` of :func:`friction_ramp` [m/s].

    Returns
    -------
    ndarray
        Tangential force on that surface, opposing ``v_T`` [N].
    """
    v = np.asarray(slip_velocity, dtype=float)
    ramp = friction_ramp(v, tolerance, full_speed)
    return -coefficient * ramp * np.asarray(normal_force, dtype=float) * np.sign(v)


# ------------------------------------------------------------------ distributed laws


def _force_area(contour: BushingContour, law: SpringLaw) -> FloatArray | float:
    """Area that turns each node's pressure into force [m^2]."""
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
    law: SpringLaw,
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
    law : SpringLaw
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
        :class:`~jointwear.contact.laws.PowerLaw`, trapezoidal (4 panels per
        node) for other laws.
    max_penetration : ndarray, shape (...)
        Largest node penetration [m].
    """
    e = np.asarray(eccentricity, dtype=float)
    ex, ey = e[..., 0:1], e[..., 1:2]
    theta = contour.theta
    delta = contour.penetration(pin, e)
    pressure = np.asarray(law.pressure(delta), dtype=float)
    area = _force_area(contour, law)
    node_force = area * pressure
    d_ex, d_ey = ray_distance_derivative(theta, ex, ey, pin.radius)
    force = np.stack(
        [np.sum(node_force * d_ex, axis=-1), np.sum(node_force * d_ey, axis=-1)], axis=-1
    )
    if isinstance(law, PowerLaw):
        energy = law.coefficient * delta ** (law.exponent + 1.0) / (law.exponent + 1.0)
    else:
        fractions = np.linspace(0.0, 1.0, 5)
        samples = np.stack([law.pressure(f * delta) for f in fractions], axis=0)
        energy = np.trapezoid(samples, dx=0.25, axis=0) * delta
    potential = np.sum(area * energy, axis=-1)
    return force, potential, np.max(delta, axis=-1)


# ------------------------------------------------------------------ the joint's contact force


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
            self._area = np.broadcast_to(
                contour.spring_area
                if spring_law.force_area is None
                else float(spring_law.force_area),
                self._radius.shape,
            )
            self._pin_radius = pin.radius
            self._gap = self._radius - pin.radius
        self.contour = contour
        self.pin = pin
        self.spring_law = spring_law

    def _springs(self, ex: float, ey: float) -> tuple[float, float, float]:
        """Elastic resultant ``(F_x, F_y)`` [N] and signed gap [m] of the distributed law.

        Same as :func:`~jointwear.mechanism.spring_resultant` and
        :func:`~jointwear.mechanism.spring_gap`, evaluated only on the
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
        settings = config.dynamics
        params = ContactParameters.from_config(config)
        stiffness = pin_in_hole_stiffness(
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
        if settings.force_law in DISTRIBUTED_LAWS:
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
            friction_full_speed=settings.friction_velocity_full,
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
            return self._touch(direction)
        if not self.distributed:
            touch = self._touch(direction)
            return touch + (load / self.stiffness) ** (1.0 / self.exponent)
        unit = np.array([math.cos(direction), math.sin(direction)])
        lower = self._touch(direction)

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

    def _touch(self, direction: float) -> float:
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
