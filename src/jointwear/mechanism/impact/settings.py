"""Settings of the contact–impact model: the ``[dynamics]`` keys it reads, checked.

:class:`ContactImpactSettings` is what the force laws, the integrator and the sampled
revolution of every contact system take from the ``[dynamics]`` section.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from jointwear.errors import ConfigError
from jointwear.mechanism.impact.force_laws import FORCE_LAWS, hysteresis_factor

if TYPE_CHECKING:
    from jointwear.config import DynamicsConfig

__all__ = [
    "AUTO_INTEGRATOR",
    "COMPILED_FALLBACK",
    "COMPILED_INTEGRATOR",
    "COMPILED_INTEGRATORS",
    "FALLBACK_INTEGRATOR",
    "INTEGRATORS",
    "RADAU_INTEGRATOR",
    "SEPARATION_RTOL",
    "STIFF_FALLBACK",
    "STIFF_INTEGRATOR",
    "ContactImpactSettings",
]

#: the Dormand-Prince 5(4) pair of ``RK45`` with the contact events, the whole
#: integration compiled (the slider-crank's compiled right-hand side; ``RK45`` of
#: ``solve_ivp`` for the other systems, :data:`COMPILED_FALLBACK`)
COMPILED_INTEGRATOR = "RK45-compiled"
#: what :data:`COMPILED_INTEGRATOR` runs as where the system has no compiled integration
COMPILED_FALLBACK = "RK45"
#: the L-stable Rosenbrock method RODAS4 with the contact events, the whole integration
#: compiled (:mod:`jointwear.mechanism.impact.rosenbrock`): the squeeze film of a
#: lubricated joint makes the equations of motion stiff, and an explicit method crawls
STIFF_INTEGRATOR = "Rodas4-compiled"
#: what :data:`STIFF_INTEGRATOR` runs as where the system has no compiled integration
STIFF_FALLBACK = "Radau"
#: the fully implicit Radau IIA method RADAU5 with the contact events, the whole
#: integration compiled (:mod:`jointwear.mechanism.impact.radau`); ``Radau`` of
#: ``solve_ivp`` (:data:`STIFF_FALLBACK`) where the system has no compiled integration
RADAU_INTEGRATOR = "Radau-compiled"
#: the integrators that run as the system's compiled integration where it has one
COMPILED_INTEGRATORS = (COMPILED_INTEGRATOR, STIFF_INTEGRATOR, RADAU_INTEGRATOR)
#: the compiled integrator where the system has it (RADAU5 with an oil film), LSODA
#: elsewhere: on the slider-crank
#: as accurate as LSODA against a converged solution or more, 10-57 times less CPU
#: (``docs/dynamics.md``), LSODA being the stiff-safe choice for every other system
AUTO_INTEGRATOR = "auto"
#: the integrator ``auto`` falls back to where no compiled integration exists
FALLBACK_INTEGRATOR = "LSODA"
#: ``solve_ivp`` methods accepted by ``dynamics.integrator``, the compiled one and ``auto``
INTEGRATORS: tuple[str, ...] = (
    "LSODA",
    "Radau",
    "BDF",
    "RK45",
    "DOP853",
    COMPILED_INTEGRATOR,
    STIFF_INTEGRATOR,
    RADAU_INTEGRATOR,
    AUTO_INTEGRATOR,
)


#: ``dynamics.separation_rtol`` of a solve of its own (``jointwear dynamics``, the load of
#: an uncoupled run) unless given: a separating solve's wear per revolution within
#: 1.5e-4-4e-4 of a converged one (:attr:`ContactImpactSettings.separated_tolerances`);
#: the solves of a coupled run keep the run's ``rtol`` (``docs/wear-feedback.md``)
SEPARATION_RTOL = 1e-10


@dataclass(frozen=True)
class ContactImpactSettings:
    """Settings of the contact–impact model (the ``[dynamics]`` keys it uses).

    Parameters
    ----------
    force_law : str
        Normal force law, one of :data:`~jointwear.mechanism.impact.force_laws.FORCE_LAWS`.
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
        ``solve_ivp`` method, one of :data:`INTEGRATORS`; ``"auto"`` (the default, as
        ``dynamics.integrator``'s): the system's compiled integration where it has one,
        else LSODA (:meth:`integrator_for`).
    rtol : float
        Relative tolerance of the integrator [-].
    atol : float
        Absolute tolerance of the integrator, on every state component (SI) [-].
    separation_rtol : float
        Relative tolerance of a solve in which the pin leaves the wall (all of it, from
        ``t = 0``), if tighter than ``rtol``; ``atol`` is scaled alike [-]
        (:attr:`separated_tolerances`).
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
    integrator: str = AUTO_INTEGRATOR
    rtol: float = 1e-8
    atol: float = 1e-10
    separation_rtol: float = SEPARATION_RTOL
    revolutions_settle: int = 2
    max_step: float | None = None

    def __post_init__(self) -> None:
        if self.force_law not in FORCE_LAWS:
            raise ConfigError(
                f"dynamics.force_law: unknown force law {self.force_law!r}; choose from "
                + ", ".join(repr(name) for name in FORCE_LAWS)
            )
        hysteresis_factor(self.force_law, self.restitution)  # validates c_e
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
        if not 0 < self.separation_rtol < 1:
            raise ConfigError("dynamics.separation_rtol: need 0 < separation_rtol < 1")
        if self.revolutions_settle < 0:
            raise ConfigError("dynamics.revolutions_settle: must be >= 0")
        if self.max_step is not None and not self.max_step > 0:
            raise ConfigError("dynamics.max_step: must be > 0")

    def integrator_for(self, system: object) -> str:
        """The integrator that runs for ``system``: ``auto`` and the compiled ones resolved [-].

        The system integrates compiled where it has ``integrate_compiled`` and a compiled
        right-hand side (the slider-crank's point force laws with numba). There ``auto``
        is :data:`RADAU_INTEGRATOR` for a joint with an oil film of some viscosity (its
        squeeze term makes the equations stiff) and :data:`COMPILED_INTEGRATOR` for a
        dry one, and an explicit compiled choice runs as named. For every other system,
        law or without numba ``auto`` is LSODA, :data:`COMPILED_INTEGRATOR` is ``RK45``
        of ``solve_ivp`` (:data:`COMPILED_FALLBACK`: the same pair and step control, the
        right-hand side in Python) and :data:`STIFF_INTEGRATOR` is ``Radau``
        (:data:`STIFF_FALLBACK`, an L-stable implicit method too), as is
        :data:`RADAU_INTEGRATOR`.
        """
        if self.integrator not in (AUTO_INTEGRATOR, *COMPILED_INTEGRATORS):
            return self.integrator
        if getattr(system, "compiled", False) and hasattr(system, "integrate_compiled"):
            if self.integrator != AUTO_INTEGRATOR:
                return self.integrator
            film = getattr(getattr(system, "contact", None), "film", None)
            # a film of zero viscosity exerts no force: the dry integration, bit for bit
            oiled = film is not None and film.viscosity > 0.0
            # RADAU5 over RODAS4: on the oiled paper joint 3-6.5x a dry revolution against
            # 45-233x, and its peak joint force within 1e-6 where RODAS4's is 1.4 % high
            # at the default rtol (docs/dynamics.md)
            return RADAU_INTEGRATOR if oiled else COMPILED_INTEGRATOR
        if self.integrator == COMPILED_INTEGRATOR:
            return COMPILED_FALLBACK
        if self.integrator in (STIFF_INTEGRATOR, RADAU_INTEGRATOR):
            return STIFF_FALLBACK
        return FALLBACK_INTEGRATOR

    @property
    def friction_full_speed(self) -> float:
        """``v_1`` of the friction ramp [m/s]."""
        if self.friction_velocity_full is not None:
            return self.friction_velocity_full
        return 2.0 * self.friction_velocity_tolerance

    @property
    def separated_tolerances(self) -> tuple[float, float]:
        """``(rtol, atol)`` once the pin has left the wall [-].

        A pin in persistent contact converges at ``rtol`` = 1e-8 (the paper's joint: its
        wear per revolution within 2e-6 of a solution at 1e-12); a flying pin does not:
        where it lands after a free flight moves with the tolerance and the next flights
        with it. On the separating slider-crank of ``docs/dynamics.md`` (a 30 um scar, 7
        impacts a revolution) rtol = 1e-8 throughout puts the peak wear depth per
        revolution 2-4 % and the peak contact force 3 % off the converged values, 1e-10
        within 0.05 %. A solve in which the pin leaves the wall is therefore integrated
        again from its start at the tighter of ``rtol`` and ``separation_rtol``, ``atol``
        scaled by the same factor (tightening from the first separation on is not
        enough: the state the pin leaves the wall with, from the loose contact phase,
        carries its error into every later flight).
        """
        rtol = min(self.rtol, self.separation_rtol)
        return rtol, self.atol * rtol / self.rtol

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
            separation_rtol=(
                SEPARATION_RTOL if dynamics.separation_rtol is None else dynamics.separation_rtol
            ),
            revolutions_settle=dynamics.revolutions_settle,
            max_step=dynamics.max_step,
        )
