r"""Contact force laws of the contact–impact dynamics (``dynamics.force_law``) and friction.

The contact–impact dynamics let the pin move freely inside the bushing; while it
penetrates the wall, the normal force comes from one of the laws below, and Coulomb
friction acts along the wall (:class:`~jointwear.mechanism.impact.joint_contact.JointContact`
applies them to a joint).

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
(bushing, internal contact), ``n = 1.5``. The clip ``max(F_N, 0)`` removes the small
tensile force the damping term gives near the end of the restitution phase when
``chi delta_dot^(+)/delta_dot^(-) > 1`` (low ``c_e``); the contact then ends with
``delta > 0`` still (the wall recovers after the pin has left).

**Distributed laws** ``nlcp`` and ``winkler``: the pressure model of the wear
pipeline integrated over the bushing contour
(:mod:`jointwear.mechanism.impact.distributed`), with the same hysteresis damping as
Lankarani–Nikravesh.

**Friction** (:func:`friction_force`): Coulomb with Ambrósio's dynamic correction
coefficient [5]_, ``F_T = -mu c_d(v_T) F_N sign(v_T)``, ``c_d`` rising from 0 at
``|v_T| <= v_0`` to 1 at ``|v_T| >= v_1`` (here a C1 cubic ramp instead of the
original linear one, so the right-hand side of the equations of motion stays
differentiable).

**Where the elastic law comes from.** The mechanism layer lies below the contact
layer (the joint's load cycle is the contact stage's input), so these laws import
nothing from :mod:`jointwear.contact`: they take the elastic part as a number (``K``)
or as an object, the distributed laws any pressure law with ``pressure(delta)`` and
``force_area`` (:class:`~jointwear.mechanism.impact.distributed.PressureLaw`). Both
are built once, above the contact layer, from the contact stage's own implementation
(Hertz's eq. (2) in :func:`jointwear.contact.hertz.stiffness`, the spring laws of
:data:`jointwear.contact.CONTACT_MODELS`) and travel in an
:class:`~jointwear.mechanism.inputs.ElasticLaw`
(:func:`jointwear.mechanism.stage.elastic_law`). Moving those formulas down here
instead would either copy them (two implementations of eq. (2)) or make the contact
stage import the mechanism's impact module for its own pressure laws; passing them in
keeps one implementation of each and the one-way flow.

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
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError

__all__ = [
    "DISTRIBUTED_LAWS",
    "FORCE_LAWS",
    "POINT_LAWS",
    "ForceLaw",
    "dissipative_force",
    "elastic_force",
    "elastic_potential",
    "friction_force",
    "friction_ramp",
    "hysteresis_factor",
    "hysteresis_restitution",
]

FloatArray = NDArray[np.float64]
ForceLaw = Literal["lankarani-nikravesh", "hunt-crossley", "flores", "nlcp", "winkler"]

#: laws with one Hertz contact ``F = K delta^n (...)``
POINT_LAWS: tuple[str, ...] = ("lankarani-nikravesh", "hunt-crossley", "flores")
#: laws integrated over the bushing contour with the contact stage's spring law
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
