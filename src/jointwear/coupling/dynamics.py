"""Dynamics solved again on the worn joint: when, and what each solve records.

:class:`DynamicsSchedule` is ``simulation.dynamics_update``: when the dynamics are
solved again on the worn joint. ``"once"``: never (the load of the unworn joint
throughout). ``K``: every ``K`` contour updates. ``"adaptive"``: when the wear since the
last solve has grown by a depth chosen so that the load cycle moves by about
``simulation.dynamics_tolerance`` (:func:`load_change`) from one solve to the next. The
sensitivity of the load to the wear is measured at every solve (change of the load over
growth of the deepest wear since the previous solve), so the solves come rarely while
the load barely changes and often when wear starts to change the dynamics. The first
solve on the worn joint comes after ``dynamics_tolerance`` times the clearance of wear.

:class:`JointLoad` is the load a joint wears under: the unworn joint's cycle, replaced
when the dynamics are solved again (:meth:`JointLoad.resolve`). Each solve adds a row to
the run's dynamics record (:func:`dynamics_row`, :data:`DYNAMICS_COLUMNS`); the
mechanism-specific scalars it reads travel beside the load cycle (``LoadCycle.extras``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ConfigError
from jointwear.mechanism.stage import load_cycles
from jointwear.registry import suggest
from jointwear.tribology.pin_wear import pin_on_bushing
from jointwear.tribology.sliding import SLIDING_MODELS

if TYPE_CHECKING:
    from jointwear.config import Config
    from jointwear.coupling.feedback import FeedbackWarnings
    from jointwear.mechanism.cycle import LoadCycle
    from jointwear.state import SimulationState

__all__ = [
    "DYNAMICS_COLUMNS",
    "DynamicsSchedule",
    "JointLoad",
    "coupled_dynamics",
    "dynamics_row",
    "load_change",
    "wear_signature",
    "worn_cycle",
]

FloatArray = NDArray[np.float64]

#: bins of the wear signature of a load cycle over the bushing's circumference
SIGNATURE_BINS = 72


def wear_signature(cycle: LoadCycle, bins: int = SIGNATURE_BINS) -> FloatArray:
    """Where on the bushing a load cycle does its wear: ``sum F |d phi|`` per azimuth bin [N rad].

    Archard's wear of a cycle is ``K_d sum_k N_k ds_k``, laid down around the load's
    azimuth; the signature spreads each step's ``F_k |d phi_k|`` linearly onto the
    two bins next to its azimuth. Unlike the load sampled step by step, it does not
    jump when an impact moves by a step, so it measures what matters for the wear.

    Parameters
    ----------
    cycle : LoadCycle
        The load cycle.
    bins : int
        Bins over the circumference [-].
    """
    weight = cycle.load * np.abs(cycle.relative_rotation) * cycle.step_share
    position = np.mod(cycle.azimuth, 2.0 * np.pi) * bins / (2.0 * np.pi)
    lower = np.floor(position).astype(int) % bins
    fraction = position - np.floor(position)
    signature = np.bincount(lower, weight * (1.0 - fraction), minlength=bins)
    signature += np.bincount((lower + 1) % bins, weight * fraction, minlength=bins)
    return signature


def load_change(old: LoadCycle, new: LoadCycle) -> float:
    """How far a load cycle has moved, as the wear sees it [-].

    The L2 norm of the change of the :func:`wear_signature` over its norm.

    Parameters
    ----------
    old, new : LoadCycle
        Two load cycles of the same joint.
    """
    before, after = wear_signature(old), wear_signature(new)
    scale = float(np.linalg.norm(before))
    difference = float(np.linalg.norm(after - before))
    if not scale > 0.0:
        return 0.0 if difference == 0.0 else math.inf
    return difference / scale


#: step-size control of the adaptive coupling: safety factor, largest growth and shrink
_SAFETY, _GROW, _SHRINK = 0.9, 4.0, 0.25


@dataclass(frozen=True)
class DynamicsSchedule:
    """When the dynamics are solved again on the worn joint.

    Attributes
    ----------
    setting : int or {"once", "adaptive"}
        ``simulation.dynamics_update``.
    tolerance : float
        ``simulation.dynamics_tolerance`` [-].
    """

    setting: int | str
    tolerance: float

    @classmethod
    def from_config(cls, config: Config) -> DynamicsSchedule:
        """The schedule of ``config.simulation``."""
        sim = config.simulation
        return cls(sim.dynamics_update, sim.dynamics_tolerance)

    @property
    def coupled(self) -> bool:
        """Whether the dynamics are ever solved again."""
        return self.setting != "once"

    def due(self, updates_since: int, growth: float, threshold: float) -> bool:
        """Whether the dynamics are due.

        Parameters
        ----------
        updates_since : int
            Contour updates since the last solve.
        growth : float
            Growth of the deepest wear since the last solve [m].
        threshold : float
            Growth at which the adaptive schedule solves again [m].
        """
        if self.setting == "once":
            return False
        if self.setting == "adaptive":
            return growth >= threshold
        return updates_since >= int(self.setting)

    def first_threshold(self, clearance: float) -> float:
        """Wear growth before the first solve on the worn joint [m].

        Parameters
        ----------
        clearance : float
            Radial clearance of the unworn joint [m].
        """
        return self.tolerance * clearance

    def next_threshold(self, growth: float, change: float, clearance: float) -> float:
        """Wear growth until the next solve, from what the last solve showed [m].

        Never below ``tolerance`` times the current clearance: an impacting joint's
        load scatters from one solve to the next even without wear, and chasing that
        scatter with ever shorter intervals would not make the wear more accurate.

        Parameters
        ----------
        growth : float
            Growth of the deepest wear between the last two solves [m].
        change : float
            :func:`load_change` between the last two load cycles [-].
        clearance : float
            Largest radial play of the pin now (clearance plus wear) [m].
        """
        floor = self.tolerance * clearance
        if not growth > 0.0:
            return floor
        if not change > 0.0:
            return max(floor, _GROW * growth)
        # the load moves about in proportion to the wear: aim at the tolerance
        target = _SAFETY * self.tolerance * growth / change
        return max(floor, min(_GROW * growth, max(_SHRINK * growth, target)))

    def threshold(self, state: SimulationState, clearance: float) -> float:
        """Growth of the deepest wear since the last solve at which the next is due [m].

        Parameters
        ----------
        state : SimulationState
            The run's state.
        clearance : float
            Radial clearance of the unworn joint [m].
        """
        return state.dynamics_threshold or self.first_threshold(clearance)

    def due_now(self, state: SimulationState, clearance: float) -> bool:
        """Whether the dynamics are to be solved again before the next contour update.

        Parameters
        ----------
        state : SimulationState
            The run's state.
        clearance : float
            Radial clearance of the unworn joint [m].
        """
        # (the growth is a reduction over the profile: not asked of an uncoupled run)
        if not self.coupled:
            return False
        threshold = self.threshold(state, clearance)
        return self.due(state.updates_since_dynamics, state.wear_growth, threshold)

    def due_in(self, state: SimulationState, clearance: float) -> int | None:
        """Revolutions until the adaptive schedule is due at the state's wear rate [-]
        (``None``: not adaptive, or no wear).

        Parameters
        ----------
        state : SimulationState
            The run's state, with its wear rate.
        clearance : float
            Radial clearance of the unworn joint [m].
        """
        if self.setting != "adaptive":
            return None
        peak_rate = float(state.wear_rate.max())
        if not peak_rate > 0.0:
            return None
        return math.ceil((self.threshold(state, clearance) - state.wear_growth) / peak_rate)

    def solved(self, state: SimulationState, change: float, clearance: float) -> SimulationState:
        """The state after the dynamics were solved on its wear.

        The load is that of the state's wear; the next solve's threshold follows from
        the load's ``change``; the wear rate and the warm start belonged to the old load.

        Parameters
        ----------
        state : SimulationState
            The state the dynamics were solved on.
        change : float
            :func:`load_change` from the previous load cycle [-].
        clearance : float
            Radial clearance of the unworn joint [m].
        """
        return replace(
            state,
            load_depth=state.wear_depth,
            updates_since_dynamics=0,
            dynamics_threshold=self.next_threshold(
                state.wear_growth, change, clearance + state.wear_depth.max()
            ),
            wear_rate=None,
            warm_offset=None,
            warm_slope=None,
            window=None,
        )


def coupled_dynamics(config: Config) -> Config:
    """The configuration a coupled run solves its dynamics with.

    A solve in which the pin leaves the wall is integrated again at the tighter
    ``dynamics.separation_rtol`` (1e-10 unless given,
    :data:`~jointwear.mechanism.impact.settings.SEPARATION_RTOL`): a single solve's
    wear per revolution needs it. A coupled run's accumulated wear does not: its
    separating trajectory is not periodic, and what moves it by a rounding error (the
    tolerance 1.1e-12 instead of 1e-12, a third settling revolution) moves the peak wear
    of the separation-prone slider-crank's 10^5 revolutions by up to 2.6e-3 at any
    tolerance. At the run's ``rtol`` (1e-8, one pass per solve) the peak wear lies 9.5e-4
    from that of rtol 1e-12, inside that scatter, at 0.6 of the run's CPU
    (``docs/wear-feedback.md``, *How well a separating run is defined*). So, unless
    ``dynamics.separation_rtol`` is given, a coupled run's solves keep its ``rtol``; a run
    whose pin stays on the wall integrates the same either way. (Each solve's recorded
    peak contact force is then that of its ``rtol``: give 1e-10 where those matter.)

    Parameters
    ----------
    config : Config
        The run's configuration.
    """
    dynamics = config.dynamics
    if dynamics.separation_rtol is not None or config.simulation.dynamics_update == "once":
        return config
    return config.replace({"dynamics.separation_rtol": dynamics.rtol})


def worn_cycle(config: Config, joint: str | None, wear_depth: FloatArray) -> LoadCycle:
    """The load cycle of the joint worn by ``wear_depth`` (the dynamics on the worn joint).

    Parameters
    ----------
    config : Config
        The run's configuration.
    joint : str or None
        The clearance joint (``None``: the mechanism's first).
    wear_depth : ndarray, shape (N,) or (slices, N)
        Wear depth of the bushing [m]; a map along the pin is averaged over its slices
        (the mechanism sees the joint's mean contour and gives its total load).
    """
    if wear_depth.ndim == 2:
        wear_depth = wear_depth.mean(axis=0)
    cycles = load_cycles(config, wear_depth=wear_depth)
    return cycles[joint] if joint is not None else next(iter(cycles.values()))


#: the dynamics record's columns: name -> (units, long_name)
DYNAMICS_COLUMNS: dict[str, tuple[str, str]] = {
    "revolution": ("1", "revolutions completed when the dynamics were solved"),
    "load_max": ("N", "largest joint load of the cycle (sampled steps)"),
    "load_mean": ("N", "time mean of the joint load"),
    "peak_load": ("N", "largest contact force of the cycle, impacts included"),
    "impacts": ("1", "impacts per cycle"),
    "free_flight_fraction": ("1", "fraction of the cycle in free flight"),
    "load_change": ("1", "RMS change of the load vector since the last solve over RMS load"),
    "max_clearance": ("m", "largest radial play of the pin when the dynamics were solved"),
    # an oil film in the contact-impact dynamics (its rows only): the film the solve met
    "max_eccentricity_ratio": ("1", "largest eccentricity ratio |e| / c of the pin"),
    "min_film_thickness": ("m", "least film thickness c - max |e| (negative: solids touched)"),
    "peak_joint_force": ("N", "largest joint force, film and contact, impacts included"),
}
#: the film's columns: :data:`DYNAMICS_COLUMNS` name -> its key in ``LoadCycle.extras``
FILM_EXTRAS: dict[str, str] = {
    "max_eccentricity_ratio": "max_eccentricity_ratio",
    "min_film_thickness": "min_film_thickness_m",
    "peak_joint_force": "peak_joint_force_n",
}


def dynamics_row(
    cycle: LoadCycle,
    revolution: float,
    wear_depth: FloatArray,
    clearance: float,
    change: float | None,
) -> dict[str, float]:
    """A row of the dynamics record (:data:`DYNAMICS_COLUMNS`) for a solve of the dynamics.

    The peak contact force, the impacts and the free flight are the dynamics model's
    scalars (``cycle.extras``) where it has them; a model whose pin stays on the wall
    has no impacts and its largest load for the peak. A cycle whose dynamics carried
    an oil film (``film_model`` in its extras) adds the film's columns
    (:data:`FILM_EXTRAS`).

    Parameters
    ----------
    cycle : LoadCycle
        The load cycle the solve gave.
    revolution : float
        Revolutions completed at the solve [-].
    wear_depth : ndarray, shape (N,)
        The wear the dynamics were solved on [m].
    clearance : float
        Radial clearance of the unworn joint [m].
    change : float or None
        :func:`load_change` from the previous cycle [-] (``None``: the first solve).
    """
    extras = cycle.extras
    film = {}
    if "film_model" in extras:
        film = {name: float(extras[key]) for name, key in FILM_EXTRAS.items()}
    return {
        "revolution": float(revolution),
        "load_max": float(cycle.load.max()),
        "load_mean": cycle.mean_load,
        "peak_load": float(extras.get("peak_load_n", cycle.load.max())),
        "impacts": float(extras.get("impacts", 0)),
        "free_flight_fraction": float(extras.get("free_flight_fraction", 0.0)),
        "load_change": math.nan if change is None else float(change),
        "max_clearance": clearance + float(wear_depth.max()),
        **film,
    }


class JointLoad:
    """The load a clearance joint wears under: the unworn joint's load cycle, replaced when
    the dynamics are solved again on the worn joint (:attr:`schedule`).

    The sliding distance of the current cycle is computed once per cycle.

    Parameters
    ----------
    config : Config
        The run's configuration (:attr:`config`: replaced where the run's is).
    joint : str or None
        The clearance joint (``None``: every joint of the mechanism).
    given : LoadCycle, optional
        A precomputed load cycle, never solved again.

    Raises
    ------
    ConfigError
        If ``joint`` names no clearance joint of the mechanism.
    """

    def __init__(self, config: Config, joint: str | None, given: LoadCycle | None = None) -> None:
        if joint is not None and joint not in config.joints:
            raise ConfigError(f"joint: no clearance joint {joint!r}{suggest(joint, config.joints)}")
        self.config = config
        self.joint = joint or (None if given is None else given.joint)
        self.given = given is not None
        self.schedule = DynamicsSchedule.from_config(config)
        self._cycles = None if given is None else {self.joint: given}
        self._sliding: tuple[LoadCycle, FloatArray] | None = None
        self._solving: tuple[Config, Config] | None = None

    @property
    def solving(self) -> Config:
        """The configuration the dynamics are solved with (:func:`coupled_dynamics`)."""
        if self._solving is None or self._solving[0] is not self.config:
            self._solving = (self.config, coupled_dynamics(self.config))
        return self._solving[1]

    @property
    def cycles(self) -> dict[str, LoadCycle]:
        """The load cycle of every clearance joint (of the unworn joints until replaced)."""
        if self._cycles is None:
            cycles = load_cycles(self.solving)
            self._cycles = cycles if self.joint is None else {self.joint: cycles[self.joint]}
        return self._cycles

    @property
    def cycle(self) -> LoadCycle:
        """The current load cycle (of the first joint)."""
        return next(iter(self.cycles.values()))

    @property
    def sliding_distance(self) -> FloatArray:
        """Sliding distance per step of the current cycle [m] (``simulation.sliding``)."""
        cycle = self.cycle
        # computed once per load cycle: every contour update asks for it
        if self._sliding is None or self._sliding[0] is not cycle:
            slide = SLIDING_MODELS.get(self.config.simulation.sliding)
            radius = self.config.joint.bushing_radius
            # a duty cycle's modes each on their own cycle, weighted by their share
            parts = [share * slide(part, radius) for share, part in cycle.parts()]
            self._sliding = (cycle, parts[0] if len(parts) == 1 else np.concatenate(parts))
        return self._sliding[1]

    @property
    def pin_rotation(self) -> FloatArray:
        """Rotation of the pin against the bushing at the start of each step [rad].

        Raises
        ------
        ConfigError
            If the pin wears and turns by other than whole turns per cycle (its scar
            would then be smeared over the cycles of an update interval).
        """
        rotation = self.cycle.rotation
        turns = rotation[-1] / (2.0 * np.pi)
        if abs(turns - round(turns)) > 1e-9:
            raise ConfigError(
                f"materials.pin.wear_coefficient: the pin turns {turns:.6g} times per cycle; "
                f"a wearing pin needs whole turns (its scar must come back to the same place)"
            )
        return rotation[:-1]

    def facing(self, pin_wear_depth: FloatArray | None) -> FloatArray | None:
        """The pin's wear facing each bushing node at each step [m] (``None``: an unworn
        or rigid pin; :func:`jointwear.tribology.pin_wear.pin_on_bushing`).

        Parameters
        ----------
        pin_wear_depth : ndarray, shape (N,) or (S, N), or None
            Wear depth of the pin in its own frame [m] (a map over the slices along the
            pin: then shape (S, M, N)).
        """
        if pin_wear_depth is None or not pin_wear_depth.any():
            return None
        return pin_on_bushing(pin_wear_depth, self.pin_rotation)

    def use(self, cycle: LoadCycle) -> None:
        """Wear under ``cycle`` from now on."""
        self._cycles = {self.joint or cycle.joint: cycle}

    def resume(self, state: SimulationState) -> Config:
        """Wear under the load ``state`` was running with (a resumed run); the run's
        configuration with the steps the cycle really has."""
        if state.load_depth is not None and not self.given:
            self.use(worn_cycle(self.solving, self.joint, state.load_depth))
        steps = self.cycle.steps
        if steps != self.config.simulation.steps_per_revolution and not self.cycle.duty:
            # a load history brings its own steps: the config says what really ran
            self.config = self.config.replace({"simulation.steps_per_revolution": steps})
        return self.config

    def unworn(self, state: SimulationState) -> LoadCycle:
        """The load cycle of the unworn joint (``state``'s own if never solved again)."""
        if state.load_depth is None or self.given:
            return self.cycle
        return worn_cycle(self.solving, self.joint, np.zeros_like(state.wear_depth))

    def due_in(self, state: SimulationState) -> int | None:
        """Revolutions until the dynamics are due again at the state's wear rate [-]
        (``None``: not on an adaptive schedule, or a given cycle, never solved again)."""
        if self.given:
            return None
        return self.schedule.due_in(state, self.config.joint.clearance)

    def resolved(self, state: SimulationState, feedback: FeedbackWarnings) -> SimulationState:
        """``state``, with the dynamics solved again on its wear where they are due (the
        wear rate then follows the new load).

        Parameters
        ----------
        state : SimulationState
            The state before a contour update.
        feedback : FeedbackWarnings
            Where the new load's separation is said.
        """
        schedule, clearance = self.schedule, self.config.joint.clearance
        if not schedule.due_now(state, clearance):
            return state
        if self.given:
            return replace(state, updates_since_dynamics=0)
        old = self.cycle
        self.use(worn_cycle(self.solving, self.joint, state.wear_depth))
        change = load_change(old, self.cycle)
        return self.record(schedule.solved(state, change, clearance), change, feedback)

    def record(
        self, state: SimulationState, change: float | None, feedback: FeedbackWarnings
    ) -> SimulationState:
        """``state`` with the current cycle's row added to the dynamics record.

        Parameters
        ----------
        state : SimulationState
            The state the cycle was solved on.
        change : float or None
            :func:`load_change` from the previous cycle [-] (``None``: the first solve).
        feedback : FeedbackWarnings
            Where the pin's separation is said.
        """
        row = dynamics_row(
            self.cycle, state.revolution, state.wear_depth, self.config.joint.clearance, change
        )
        feedback.check_separation(row, state.revolution)
        return replace(state, dynamics_updates=state.dynamics_updates.append(row))
