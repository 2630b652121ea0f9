"""The one loop over revolutions: the paper's Fig. 7 flow.

:class:`Simulation` builds the stages and runs the loop; every contour update is a
:class:`~jointwear.coupling.WearStep`, applied up to the first ``[life]`` limit and recorded,
and the run ends in a plain :class:`~jointwear.record.RunRecord`, which
:class:`jointwear.results.WearResult` presents.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from jointwear import coupling
from jointwear.compile_time import Clock
from jointwear.config import Config
from jointwear.contact import ContactSolution
from jointwear.contact.solver import ContactSolver, WarmStart
from jointwear.coupling.joints import joint_records
from jointwear.geometry.contour import BushingContour
from jointwear.record import RunRecord, UpdateRecorder
from jointwear.state import SimulationState
from jointwear.tribology.pin_wear import pin_wear_depth
from jointwear.tribology.wear_laws import WearLaw
from jointwear.tribology.wear_laws import wear_law as wear_law_of

if TYPE_CHECKING:
    from jointwear.mechanism import LoadCycle
    from jointwear.results import WearResult

__all__ = ["Simulation"]

FloatArray = NDArray[np.float64]
Progress = Callable[[float, float], None]
OnStep = Callable[[SimulationState], None]


class Simulation:
    """Wear of a clearance joint over revolutions (paper Fig. 7).

    Parameters
    ----------
    config : Config
        Validated configuration (:func:`jointwear.load_config`).
    contact_model : str or callable, optional
        Contact model name, a spring law, or ``pressure(penetration)`` [m -> Pa]; default
        ``config.contact.model``.
    load_cycle : LoadCycle, optional
        Precomputed load cycle of the joint (default: from ``config`` by
        :func:`jointwear.mechanism.stage.load_cycles`; a given cycle is never re-solved).
    joint : str, optional
        The clearance joint to simulate; default all of ``config.joints``.
    wear_law : str or callable, optional
        Wear law name (:data:`~jointwear.tribology.wear_laws.WEAR_LAWS`) or
        ``law(pressure, sliding_distance) -> wear depth`` [Pa, m -> m]; default
        ``config.wear.law``.

    Examples
    --------
    >>> from jointwear import Simulation, load_config
    >>> result = Simulation(load_config(overrides={"contact.model": "nlcp"})).run()
    >>> result.summary()["peak_wear_depth_m"] > 0
    True
    """

    def __init__(
        self,
        config: Config,
        contact_model: str | Callable[..., Any] | None = None,
        load_cycle: LoadCycle | None = None,
        joint: str | None = None,
        wear_law: str | WearLaw | None = None,
    ) -> None:
        setup = Clock()
        self.config = config
        self.wear_law = wear_law_of(config.wear, config.wearing_bushing, wear_law)
        self.contact_model = config.contact.model if contact_model is None else contact_model
        # the fused kernel accumulates Archard's wear inside the contact solve
        archard = wear_law in (None, "archard") and config.wear.law == "archard"
        self.solver = ContactSolver.from_config(config, self.contact_model, fused_archard=archard)
        if config.joint.axial_slices > 1:  # (a planar run never loads the slices' modules)
            from jointwear.contact.sliced import SlicedSolver

            self.solver = SlicedSolver.from_config(config, self.solver)
        self.law, self.pin = self.solver.law, self.solver.pin
        self.parameters = self.solver.parameters
        self.load = coupling.JointLoad(config, joint, load_cycle)
        self.joint = self.load.joint
        self.pin_wear_coefficient = config.materials.pin.wear_coefficient
        self.jumps = coupling.Jumps.from_config(config)
        self.life = coupling.LifeLimits.from_config(config)
        self.recorder = UpdateRecorder(config, self.life.joint)
        self.feedback = coupling.FeedbackWarnings(config.joint.clearance)
        #: numba's compile seconds while setting up (the load cycle's dynamics) [s]
        self.setup_compile_time = setup.compiling()

    @property
    def load_cycle(self) -> LoadCycle:
        """Stage 1: load, azimuth and relative rotation per step (the current cycle)."""
        return self.load.cycle

    @property
    def sliding_distance(self) -> FloatArray:
        """Stage 3a: sliding distance per step of the current cycle [m]."""
        return self.load.sliding_distance

    def initial_contour(self) -> BushingContour:
        """The unworn bushing (its slices along the pin, ``joint.axial_slices > 1``)."""
        return self.solver.initial_contour()

    def initial_state(self) -> SimulationState:
        """State before the first revolution."""
        shape = self.solver.depth_shape  # (nodes,), or (slices, nodes) along the pin
        pin = None if self.pin_wear_coefficient is None else np.zeros(shape)
        return SimulationState(revolution=0, wear_depth=np.zeros(shape), pin_wear_depth=pin)

    def contact(
        self,
        contour: BushingContour,
        state: SimulationState | None = None,
        ahead: int | None = None,
    ) -> ContactSolution:
        """Stage 2: pressure on every node at every step on ``contour``; with ``state``, a
        solve of the loop, warm-started from the state's last solve extrapolated ``ahead``
        revolutions, or ``state.interval`` (:mod:`jointwear.contact.solver` picks the path)."""
        if state is None:
            return self.solver.solve(contour, self.load_cycle)
        facing, warm = self.load.facing(state.pin_wear_depth), WarmStart.of_state(state)
        return self.solver.solve(
            contour, self.load_cycle, sliding=self.sliding_distance, warm=warm,
            ahead=state.interval if ahead is None else ahead, facing=facing,
        )  # fmt: skip

    def wear_per_revolution(self, solution: ContactSolution, revolution: float = 0) -> FloatArray:
        """Stage 3b: wear depth of one revolution at every node, by the wear law [m] (after
        ``revolution`` revolutions, for a law that reads how the joint runs)."""
        law = coupling.wear_law_at(self.wear_law, self.load, revolution)
        return self.solver.wear_per_revolution(solution, law, self.sliding_distance)

    def pin_wear_per_revolution(self, solved: coupling.Solved) -> FloatArray:
        """Stage 3b on the pin: its wear depth per revolution in its own frame [m] (a map
        over the slices along the pin)."""
        joint, contour = self.config.joint, solved.contour
        return pin_wear_depth(
            self.solver.node_pressure(solved.solution),
            self.sliding_distance,
            self.pin_wear_coefficient,
            contour.radius,
            joint.pin_radius,
            self.load.pin_rotation,
        )

    def run(
        self,
        progress: Progress | None = None,
        state: SimulationState | None = None,
        on_step: OnStep | None = None,
        pressures: bool = True,
    ) -> WearResult:
        """Run all revolutions, or up to the first ``[life]`` limit reached.

        Parameters
        ----------
        progress : callable, optional
            Called as ``progress(revolutions_done, revolutions_total)`` after every contour
            update, and once the run is complete as ``(total, total)``, or ``(stop, stop)``
            where a ``[life]`` limit ended it at revolution ``stop`` (fractional).
        state : SimulationState, optional
            Resume from this state (e.g. a checkpoint).
        on_step : callable, optional
            Called with the state after every contour update (checkpointing).
        pressures : bool
            Solve the contact on the unworn and the final contour again for the result's
            pressure snapshots and contact half-angle (``False``: neither, the same wear).
        """
        from jointwear.results import WearResult  # (the record, presented)

        if self.joint is not None or len(self.config.joints) == 1:
            return WearResult.of_record(self.record(progress, state, on_step, pressures))
        resumed = state is not None or on_step is not None
        clock = Clock()
        records = joint_records(self, progress, resumed, pressures)
        return WearResult.of_joints(self.config, records, **clock.times(self.setup_compile_time))

    def record(
        self,
        progress: Progress | None = None,
        state: SimulationState | None = None,
        on_step: OnStep | None = None,
        pressures: bool = True,
    ) -> RunRecord:
        """The loop over the revolutions of one clearance joint, as a plain record
        (the parameters of :meth:`run`)."""
        clock = Clock()
        state = self.initial_state() if state is None else state
        self.config = self.load.resume(state)
        total = self.config.simulation.revolutions
        first = None
        if state.revolution == 0 and not len(state.dynamics_updates):
            state = self.load.record(state, None, self.feedback)
        if not self.config.simulation.update_contour and state.revolution == 0:
            state, first = self._linear(state)
        while state.revolution < total and state.stopped_by is None:
            state = self.step(state)
            if on_step is not None:
                on_step(state)
            # (a run a limit has ended is complete: said by the last call)
            if progress is not None and state.stopped_by is None:
                progress(state.revolution, total)
        if progress is not None:
            end = total if state.stopped_by is None else state.revolution
            progress(end, end)
        return self._finish(state, first, pressures, clock)

    def step(self, state: SimulationState) -> SimulationState:
        """One contour update (:func:`~jointwear.coupling.next_step`), and the dynamics
        solved again on the worn joint when due."""
        state = self.load.resolved(state, self.feedback)
        remaining = self.config.simulation.revolutions - state.revolution
        step = coupling.next_step(
            state,
            remaining,
            self._rate_at,
            self.jumps,
            warm_start=self._warm_start,
            pin_rate=self.pin_wear_per_revolution,
            due_in=self.load.due_in,
        )
        saved = self.recorder.profiles.targets
        changes = coupling.applied(step, self.life, self.jumps, self.solver.contour, saved)
        warm = self._warm_start(step, step.base.warm_offset, changes["interval"])
        return self._record(step.base, step.solution, **changes, **warm)

    def _record(self, base: SimulationState, solution: ContactSolution, **changes: Any):
        """``base`` with ``changes``, recorded (:class:`~jointwear.record.UpdateRecorder`)."""
        state = self.recorder.record(base, float(solution.iterations.sum()), changes)
        self.feedback.check_contact(self.load_cycle, state.revolution, state.wear_depth)
        return state

    def _linear(self, state: SimulationState) -> tuple[SimulationState, ContactSolution]:
        """Without contour update: one revolution's wear, scaled (exactly linear)."""
        solved = self._rate_at(None, state.wear_depth, 0)
        pin_rate = None if state.pin_wear_depth is None else self.pin_wear_per_revolution(solved)
        total, wall = self.config.simulation.revolutions, self.config.joint.bushing_thickness
        saved = self.recorder.profiles.targets
        for changes in coupling.linear_marks(solved, pin_rate, total, self.life, saved, wall):
            state = self._record(state, solved.solution, **changes)
        return state, solved.solution

    def _finish(
        self, state: SimulationState, first: ContactSolution | None, pressures: bool, clock: Clock
    ) -> RunRecord:
        """The record of the run: the contact on the unworn and the final contour (unless
        ``pressures`` is false), said to stay in the model's range; ``clock`` started with
        the loop."""
        initial = final = None
        if pressures:
            initial = final = first
            if first is None:
                final = self.contact(self.solver.contour(state.wear_depth))
                initial = self.solver.solve(self.initial_contour(), self.load.unworn(state))
        return RunRecord.finished(
            self.config, state, self.load_cycle, self.sliding_distance, self.law, (initial, final),
            joint=self.joint, feedback=self.feedback.messages,
            film=self.solver.film_record(self.load_cycle),
            times=clock.times(self.setup_compile_time),
        )  # fmt: skip

    def _rate_at(
        self, state: SimulationState | None, wear_depth: FloatArray, ahead: int
    ) -> coupling.Solved:
        """The solve on the contour worn by ``wear_depth`` [m] and its wear rate; with a
        state, a solve of the loop warm from the state's, ``ahead`` revolutions on."""
        contour = self.solver.contour(wear_depth)
        solution = self.contact(contour, state, ahead)
        revolution = coupling.revolution_of(state, wear_depth, ahead)
        return coupling.Solved(self.wear_per_revolution(solution, revolution), solution, contour)

    def _warm_start(
        self, solved: coupling.Solved | coupling.WearStep, previous=None, interval=1
    ) -> dict[str, Any]:
        """The state's warm start of the next solve (:class:`~jointwear.contact.solver.WarmStart`,
        the trend from the ``previous`` offsets [m] ``interval`` revolutions before)."""
        azimuth = self.load_cycle.azimuth
        warm = self.solver.warm_start(solved.solution, solved.contour, azimuth, previous, interval)
        return warm._asdict()
