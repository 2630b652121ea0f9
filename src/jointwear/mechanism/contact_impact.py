r"""Contact–impact dynamics of the slider–crank: the pin moves freely in the clearance.

The massless-link model (:mod:`jointwear.mechanism.slider_crank`) assumes that the
pin never leaves the bushing wall. Here the assumption is dropped: pin and bushing
are connected only through a contact force that exists while they overlap, so the
pin can separate, fly across the clearance and hit the wall again.

The model is split by topic:

* :mod:`jointwear.mechanism.force_laws` -- the contact force on the joint
  (:class:`~jointwear.mechanism.force_laws.JointContact`: force laws and friction);
* :mod:`jointwear.mechanism.impact_systems` -- the equations of motion (the
  slider-crank with a free pin, a free pin alone), compiled with numba where possible;
* :mod:`jointwear.mechanism.impact_integrator` -- the integration through the contact
  events and the sampling of a settled revolution;
* this module -- the slider-crank's solution: initial state, one settled revolution,
  its load cycle and its comparison with the massless-link model. Every name of the
  modules above is importable from here too.

The initial state is the massless-link solution at ``phi_1 = 0`` (rod angle,
slider position and their rates), with the pin pushed into the wall by the
static penetration of the massless-link load.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError, ContactLossWarning, JointwearError
from jointwear.geometry.contour import BushingContour
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.force_laws import JointContact as JointContact
from jointwear.mechanism.impact_integrator import INTEGRATORS as INTEGRATORS
from jointwear.mechanism.impact_integrator import ContactHistory as ContactHistory
from jointwear.mechanism.impact_integrator import ContactImpactSettings as ContactImpactSettings
from jointwear.mechanism.impact_integrator import ContactSystem as ContactSystem
from jointwear.mechanism.impact_integrator import ContactSystemBase as ContactSystemBase
from jointwear.mechanism.impact_integrator import SampledRevolution as SampledRevolution
from jointwear.mechanism.impact_integrator import Segment as Segment
from jointwear.mechanism.impact_integrator import integrate_contacts as integrate_contacts
from jointwear.mechanism.impact_integrator import integrate_revolution as integrate_revolution
from jointwear.mechanism.impact_systems import FreePinSystem as FreePinSystem
from jointwear.mechanism.impact_systems import SliderCrankContactSystem as SliderCrankContactSystem
from jointwear.mechanism.impact_systems import free_pin_impact as free_pin_impact
from jointwear.mechanism.impact_systems import impact_kernel as impact_kernel
from jointwear.mechanism.slider_crank import (
    SliderCrank,
    ideal_motion,
    inverse_dynamics,
    massless_link_load,
    slider_crank_cycle,
    solve_massless_link,
)

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = [
    "ContactImpactSolution",
    "compiled_dynamics",
    "contact_impact_load",
    "sampled_solution",
    "solve_contact_impact",
]

FloatArray = NDArray[np.float64]


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
        Integration record of all revolutions (:func:`solve_contact_impact` keeps the
        dense output only where it samples: the states are known at the sample times,
        the penetration maxima and the segment ends).
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
    compiled: bool | None = None,
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
    compiled : bool, optional
        Run the compiled right-hand side where it can (``True``) or the Python one
        (``False``); default: as :func:`compiled_dynamics` decides for the run. Both give
        the same bits.

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
    choice = compiled_dynamics(config) if compiled is None else (None if compiled else False)
    system = SliderCrankContactSystem(mechanism, omega, contact, choice)
    y0, _ = _initial_state(system, max(steps, 64))
    run = integrate_revolution(system, y0, settings, steps, dense=False)
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


#: integrated revolutions of a run up to which the Python right-hand side is faster
#: than loading numba and its cached machine code
COMPILED_DYNAMICS_REVOLUTIONS = 16


def compiled_dynamics(config: Config) -> bool | None:
    """Whether the run's contact-impact integrations may run compiled (``None``: where it can).

    Loading numba and its cached machine code takes ~0.5 s per process; the compiled
    right-hand side saves ~30 ms per integrated revolution of the paper's joint (35 ms
    against 67 ms). A run whose integrations cover at most
    :data:`COMPILED_DYNAMICS_REVOLUTIONS` revolutions (settling included) takes the
    Python right-hand side (``False``). Both give the same bits, so the choice never
    changes a result; it is read from the configuration alone
    (:attr:`jointwear.config.SimulationConfig.contact_solves` bounds the contour
    updates, ``simulation.dynamics_update`` how many of them re-solve the dynamics).

    Parameters
    ----------
    config : Config
        The run's configuration.
    """
    sim = config.simulation
    schedule = sim.dynamics_update
    if schedule == "adaptive":
        return None
    solves = 1
    if sim.update_contour and schedule != "once":
        solves += sim.contact_solves // schedule
    revolutions = solves * (config.dynamics.revolutions_settle + 1)
    return None if revolutions > COMPILED_DYNAMICS_REVOLUTIONS else False


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
