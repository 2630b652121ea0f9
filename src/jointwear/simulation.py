"""The simulation orchestrator: the paper's Fig. 7 flow, one loop over revolutions.

Data flows one way through four stages, each a plain function from one small
data object to the next::

    mechanism.load_cycles(config)             -> LoadCycle       (load, azimuth, rotation per step)
    contact.solve(contour, pin, load, ...)    -> ContactSolution (pressure per step and node)
    tribology.archard.wear_depth(p, ds, K_d)  -> wear depth per revolution and node
    geometry.update.update_contour(contour,h) -> BushingContour  (worn contour)

:class:`Simulation` owns the only loop over revolutions. A contour update
applies the wear of one computed revolution times the update interval
(``simulation.update_every`` revolutions, or ``"adaptive"``: cycle jumping in
the spirit of Mukras et al., a trapezoid predictor-corrector over the jump whose
length is chosen by an error estimate, see :meth:`Simulation._adaptive_step`).
Without contour update the wear of one revolution
is simply scaled, so wear grows exactly linearly (paper Fig. 13).

The load cycle is computed once: the massless-link dynamics depend on the
clearance only through the link length ``e``, a 0.05 mm change of which moves
the load azimuth by ``e / l2 ~ 2.5e-4`` rad, far below the node spacing.

A mechanism with several clearance joints (``mechanism.clearance_joint`` a list)
wears each joint on its own contour from its own load cycle; the joints do not
interact through the (massless-link) loads, so each is its own simulation and the
results gain a ``joint`` dimension.
"""

from __future__ import annotations

import bisect
import functools
import math
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear import mechanism
from jointwear.config import Config
from jointwear.contact import (
    ContactParameters,
    ContactSolution,
    check_model_choice,
    check_paper_spring_area,
    contact_law,
)
from jointwear.contact import solve as solve_contact
from jointwear.contact.kernel import WarmRevolutions, revolution_wear
from jointwear.contact.laws import SpringLaw
from jointwear.coupling import DynamicsSchedule, LifeLimits, load_change
from jointwear.errors import WearFeedbackWarning
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.geometry.update import update_contour
from jointwear.mechanism.stage import load_cycles
from jointwear.state import Deferred, SimulationState
from jointwear.tribology.checks import warn_model_validity
from jointwear.tribology.metrics import (
    JointGeometry,
    evaluate_metrics,
    pin_metrics,
    profile_metrics,
)
from jointwear.tribology.sliding import SLIDING_MODELS
from jointwear.tribology.wear_laws import WearLaw
from jointwear.tribology.wear_laws import wear_law as wear_law_of

__all__ = ["Simulation", "SimulationState", "WearResult", "WearStep", "compiled_kernel"]

FloatArray = NDArray[np.float64]

class WearResult:
    """Outcome of a simulation.

    Parameters
    ----------
    config : Config
        The fully resolved configuration.
    dataset : xarray.Dataset, optional
        The result Dataset (given, or built from ``contents`` when first read).
    runtime : float
        Wall-clock time of the run [s].
    contents : ResultContents, optional
        The results of one clearance joint as plain arrays
        (:class:`jointwear.results.ResultContents`).

    Attributes
    ----------
    dataset : xarray.Dataset
        Profiles, per-step loads, pressure snapshots and per-update metrics,
        with ``units`` and ``long_name`` attributes (built on first access: the
        summary and :meth:`joint_data` need no xarray).
    """

    __slots__ = ("_contents", "_dataset", "config", "runtime")

    def __init__(
        self, config: Config, dataset: Any = None, runtime: float = math.nan, *,
        contents: Any = None,
    ) -> None:
        if dataset is None and contents is None:
            raise TypeError("WearResult needs a dataset or its contents")
        self.config = config
        self.runtime = runtime
        self._dataset = dataset
        self._contents = contents

    @property
    def dataset(self) -> Any:
        """The result as an xarray Dataset (built from the plain arrays on first access)."""
        if self._dataset is None:
            self._dataset = self._contents.to_dataset()
        return self._dataset

    def joint_data(self, joint: str | None = None) -> Any:
        """The results of one joint (default: the most worn one), read like a Dataset.

        A single-joint run answers with its plain arrays
        (:class:`jointwear.results.ResultContents`: ``["name"].values``, ``.attrs``,
        ``.sizes``) without importing xarray; a result of several joints with
        :meth:`joint_dataset`.

        Parameters
        ----------
        joint : str, optional
            Name of the joint.
        """
        if self._contents is None:
            return self.joint_dataset(joint)
        own = str(self._contents.attrs.get("joint", "joint"))
        if joint is not None and joint != own:
            from jointwear.errors import DataError

            raise DataError(f"result: no clearance joint {joint!r} (it has {own!r})")
        return self._contents

    @property
    def wear_depth(self) -> FloatArray:
        """Final wear-depth profile [m] (of the most worn joint if there are several)."""
        return np.asarray(self.joint_data()["wear_depth"].values[-1])

    @property
    def joints(self) -> tuple[str, ...]:
        """Names of the simulated clearance joints."""
        if self._contents is not None:
            return (str(self._contents.attrs.get("joint", "joint")),)
        if "joint" in self.dataset.dims:
            return tuple(str(j) for j in self.dataset["joint"].values)
        return (str(self.dataset.attrs.get("joint", "joint")),)

    def joint_dataset(self, joint: str | None = None) -> Any:
        """The dataset of one joint (default: the most worn one), without a joint dimension.

        Parameters
        ----------
        joint : str, optional
            Name of the joint.
        """
        from jointwear.results import select_joint

        return select_joint(self.dataset, joint)

    def summary(self) -> dict[str, Any]:
        """The ``jointwear run --json`` object (SI units in the key names).

        With several clearance joints, the top-level values are those of the most
        worn joint (``joint``), and ``joints`` holds every joint's.
        """
        from jointwear.results import summarize

        out = summarize(self.joint_data())
        if len(self.joints) > 1:
            out["joints"] = {j: summarize(self.joint_dataset(j)) for j in self.joints}
        out["runtime_s"] = self.runtime
        return out

    def __repr__(self) -> str:
        from jointwear.display import wear_result_repr

        return wear_result_repr(self)

    def _repr_html_(self) -> str:
        from jointwear.display import wear_result_html

        return wear_result_html(self)

    def plot(self, kind: str = "wear_polar", **kwargs: Any) -> Any:
        """One figure of the result, a matplotlib Figure (:func:`jointwear.plots.plot_wear_result`).

        Parameters
        ----------
        kind : str
            ``"wear_polar"``, ``"wear_profiles"``, ``"pressure"``, ``"joint_load"`` or
            ``"wear_history"``.
        **kwargs
            Passed to :func:`jointwear.plots.plot_wear_result`.
        """
        from jointwear.plots import plot_wear_result

        return plot_wear_result(self, kind, **kwargs)

    def to_netcdf(self, path) -> None:
        """Write the dataset as netCDF (h5netcdf), atomically."""
        from jointwear.results import write_netcdf

        write_netcdf(self.dataset, path)


@dataclass(frozen=True, eq=False)
class WearStep:
    """One contour update before it is applied: where the wear depth goes over the interval.

    Attributes
    ----------
    base : SimulationState
        The state the update starts from (its wear rate may have been refreshed).
    interval : int
        Revolutions the update covers.
    rate : ndarray, shape (N,)
        Wear per revolution at the start of the interval [m].
    end_rate : ndarray, shape (N,) or None
        Wear per revolution at the predicted end (adaptive jumps; ``None``: the
        explicit scheme, linear over the interval) [m].
    solution : ContactSolution
        The last contact solve of the update.
    contour : BushingContour
        The contour of that solve.
    error : float
        Error estimate of an adaptive jump [-] (0 otherwise).
    """

    base: SimulationState
    interval: int
    rate: FloatArray
    end_rate: FloatArray | None
    solution: ContactSolution
    contour: BushingContour
    error: float = 0.0
    pin_rate: FloatArray | None = None

    @classmethod
    def _explicit(
        cls, base: SimulationState, interval: int, rate: FloatArray, solution: ContactSolution,
        contour: BushingContour, pin_rate: FloatArray | None,
    ) -> WearStep:  # fmt: skip
        """A step of the explicit scheme, without the frozen dataclass's ``__init__`` (its
        ``object.__setattr__`` per field: a step per revolution)."""
        step = object.__new__(cls)
        step.__dict__.update(
            base=base, interval=interval, rate=rate, end_rate=None, solution=solution,
            contour=contour, error=0.0, pin_rate=pin_rate,
        )  # fmt: skip
        return step

    def pin_depth_at(self, revolutions: float) -> FloatArray | None:
        """The pin's wear depth ``revolutions`` (real) into the interval [m] (explicit scheme)."""
        if self.pin_rate is None:
            return self.base.pin_wear_depth
        return self.base.pin_wear_depth + self.pin_rate * revolutions

    def depth_at(self, revolutions: float) -> FloatArray:
        """Wear depth ``revolutions`` (real, ``0 <= revolutions <= interval``) into the
        interval [m].

        The explicit scheme grows linearly; an adaptive jump follows the trapezoid
        corrector's quadratic, whose end value is the corrector's.
        """
        depth, rate, end = self.base.wear_depth, self.rate, self.end_rate
        if end is None:
            # (1 x is exact: a per-revolution update skips the product)
            return depth + (rate if revolutions == 1 else rate * revolutions)
        if revolutions == self.interval:
            return depth + 0.5 * self.interval * (rate + end)
        tau = revolutions
        return depth + tau * rate + (0.5 * tau * tau / self.interval) * (end - rate)


class Simulation:
    """Wear of a clearance joint over revolutions (paper Fig. 7).

    Parameters
    ----------
    config : Config
        Validated configuration (:func:`jointwear.load_config`).
    contact_model : str or callable, optional
        Contact model name, a spring law, or ``pressure(penetration)``
        [m -> Pa]; default ``config.contact.model``.
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
        load_cycle: mechanism.LoadCycle | None = None,
        joint: str | None = None,
        wear_law: str | WearLaw | None = None,
    ) -> None:
        self.config = config
        self.wear_law = wear_law_of(config.wear, config.materials.bushing, wear_law)
        # the fused kernel accumulates Archard's wear inside the contact solve
        self._fused = wear_law in (None, "archard") and config.wear.law == "archard"
        self._compiled = compiled_kernel(config)
        self.parameters = ContactParameters.from_sections(
            config.joint, config.materials, config.contact
        )
        self.contact_model = config.contact.model if contact_model is None else contact_model
        self.law = contact_law(self.contact_model, self.parameters)
        # (a model given here, not by the config, is refused as the config would be)
        check_model_choice(self.law, config.simulation.update_contour)
        if getattr(self.law, "force_area", None) is not None:
            node_area = self.initial_contour().spring_area[0]
            check_paper_spring_area(self.law.force_area, node_area, config.contact.nodes)
        self.pin = Pin(config.joint.pin_radius)
        if joint is not None and joint not in config.joints:
            from jointwear.errors import ConfigError
            from jointwear.registry import suggest

            raise ConfigError(f"joint: no clearance joint {joint!r}{suggest(joint, config.joints)}")
        self._cycles: dict[str, mechanism.LoadCycle] | None = None
        self._given_cycle = load_cycle is not None
        if load_cycle is not None:
            self._cycles = {joint or load_cycle.joint: load_cycle}
            joint = joint or load_cycle.joint
        self.joint = joint
        self.pin_wear_coefficient = config.materials.pin.wear_coefficient
        if self.pin_wear_coefficient is not None and config.simulation.update_every == "adaptive":
            from jointwear.errors import ConfigError

            raise ConfigError(
                "materials.pin.wear_coefficient: a wearing pin is updated with a fixed "
                "simulation.update_every (adaptive updating integrates the bushing only)"
            )
        self.life = LifeLimits.from_config(config)
        self.schedule = DynamicsSchedule.from_config(config)
        self._warned: set[str] = set()
        self._sliding: tuple[mechanism.LoadCycle, FloatArray] | None = None
        self._warm_kernel: tuple[mechanism.LoadCycle, WarmRevolutions | None] | None = None
        #: the load cycle whose smallest and largest load are known, and those loads [N]
        self._load_range_of: tuple[mechanism.LoadCycle, float, float] | None = None

    # ---------------------------------------------------------------- stages
    @property
    def load_cycles(self) -> dict[str, mechanism.LoadCycle]:
        """Stage 1: the load cycle of every simulated clearance joint (unworn joint)."""
        if self._cycles is None:
            cycles = load_cycles(self.config)
            self._cycles = cycles if self.joint is None else {self.joint: cycles[self.joint]}
        return self._cycles

    @property
    def load_cycle(self) -> mechanism.LoadCycle:
        """Stage 1: load, azimuth and relative rotation per step (the current cycle)."""
        return next(iter(self.load_cycles.values()))

    @property
    def sliding_distance(self) -> FloatArray:
        """Stage 3a: sliding distance per step of the current cycle [m]."""
        cycle = self.load_cycle
        # computed once per load cycle: every contour update asks for it
        if self._sliding is None or self._sliding[0] is not cycle:
            slide = SLIDING_MODELS.get(self.config.simulation.sliding)
            self._sliding = (cycle, slide(cycle, self.config.joint.bushing_radius))
        return self._sliding[1]

    def initial_contour(self) -> BushingContour:
        """The unworn bushing."""
        joint = self.config.joint
        return BushingContour.circle(
            joint.bushing_radius, self.config.contact.nodes, joint.axial_length
        )

    def initial_state(self) -> SimulationState:
        """State before the first revolution."""
        nodes = self.config.contact.nodes
        pin = None if self.pin_wear_coefficient is None else np.zeros(nodes)
        return SimulationState(revolution=0, wear_depth=np.zeros(nodes), pin_wear_depth=pin)

    @property
    def pin_rotation(self) -> FloatArray:
        """Rotation of the pin against the bushing at the start of each step [rad].

        Raises
        ------
        ConfigError
            If the pin wears and turns by other than whole turns per cycle (its scar
            would then be smeared over the cycles of an update interval).
        """
        rotation = self.load_cycle.rotation
        turns = rotation[-1] / (2.0 * np.pi)
        if abs(turns - round(turns)) > 1e-9:
            from jointwear.errors import ConfigError

            raise ConfigError(
                f"materials.pin.wear_coefficient: the pin turns {turns:.6g} times per cycle; "
                f"a wearing pin needs whole turns (its scar must come back to the same place)"
            )
        return rotation[:-1]

    def pin_wear_per_revolution(self, solution: ContactSolution, contour: BushingContour):
        """Stage 3b on the pin: its wear depth per revolution in its own frame [m]."""
        from jointwear.tribology.pin_wear import pin_wear_depth

        return pin_wear_depth(
            solution.pressure,
            self.sliding_distance,
            self.pin_wear_coefficient,
            contour.radius,
            self.config.joint.pin_radius,
            self.pin_rotation,
        )

    def contact(
        self, contour: BushingContour, state: SimulationState | None = None
    ) -> ContactSolution:
        """Stage 2: pressure on every node at every step on ``contour``.

        With ``state``, the solve is warm-started from the state's last solve,
        extrapolated over ``state.interval`` revolutions.
        """
        return self._solve(contour, state, 0 if state is None else state.interval)

    def _solve(
        self, contour: BushingContour, state: SimulationState | None, ahead: int
    ) -> ContactSolution:
        """Contact solve warm-started from ``state``'s last solve, ``ahead`` revolutions on.

        Inside the revolution loop (``state`` given), paper balance with a spring law:
        :func:`jointwear.contact.kernel.revolution_wear`, which also accumulates the
        revolution's wear (the solution carries it; its dense pressure is assembled only
        when read). Without ``state`` the full NumPy solve.
        """
        cfg = self.config.contact
        warm = {}
        if state is not None and state.warm_offset is not None:
            guess = state.warm_offset
            if state.warm_slope is not None and ahead:
                # (one revolution ahead: the slope itself, 1 x is exact)
                slope = state.warm_slope if ahead == 1 else ahead * state.warm_slope
                guess = guess + slope
            warm = {"initial_offset": guess, "window": state.window}
        pin = None if state is None else state.pin_wear_depth
        if pin is not None and pin.any():
            options = {"balance": cfg.balance, "tolerance": cfg.tolerance,
                       "max_iterations": cfg.max_iterations}
            return self._solve_worn_pin(contour, pin, options)
        cycle = self.load_cycle
        if state is not None and self._fused and cfg.balance == "paper" and isinstance(
            self.law, SpringLaw
        ):
            if warm:
                revolutions = self._warm_revolutions(cycle)
                solved = None if revolutions is None else revolutions(contour, guess)
                if solved is not None:
                    return solved.solution()
            # (a cold start, or inputs the warm revolutions refuse: the general path,
            # which raises where they were wrong)
            return revolution_wear(
                contour,
                self.pin,
                cycle.load,
                cycle.azimuth,
                self.sliding_distance,
                self.law,
                self.config.materials.bushing.wear_coefficient,
                max_penetration=self.parameters.bushing_thickness,
                tolerance=cfg.tolerance,
                max_iterations=cfg.max_iterations,
                compiled=self._compiled,
                **warm,
            ).solution()
        return solve_contact(
            contour,
            self.pin,
            cycle.load,
            cycle.azimuth,
            self.law,
            self.parameters,
            balance=cfg.balance,
            tolerance=cfg.tolerance,
            max_iterations=cfg.max_iterations,
            **warm,
        )

    def _warm_revolutions(self, cycle: mechanism.LoadCycle) -> WarmRevolutions | None:
        """The compiled kernel's warm revolutions of ``cycle``, set up once per cycle
        (None without the kernel: :func:`revolution_wear` takes the NumPy path)."""
        kept = self._warm_kernel
        if kept is None or kept[0] is not cycle:
            cfg = self.config.contact
            revolutions = WarmRevolutions.of(
                self.pin, cycle.load, cycle.azimuth, self.sliding_distance, self.law,
                self.config.materials.bushing.wear_coefficient, nodes=cfg.nodes,
                axial_length=self.config.joint.axial_length,
                max_penetration=self.parameters.bushing_thickness, tolerance=cfg.tolerance,
                max_iterations=cfg.max_iterations, compiled=self._compiled,
            )  # fmt: skip
            kept = self._warm_kernel = (cycle, revolutions)
        return kept[1]

    def _solve_worn_pin(
        self, contour: BushingContour, pin_depth: FloatArray, options: dict[str, Any]
    ) -> ContactSolution:
        """Each step on its own contour: the bushing plus the pin's wear facing it."""
        from jointwear.tribology.pin_wear import pin_on_bushing

        cycle = self.load_cycle
        facing = pin_on_bushing(pin_depth, self.pin_rotation)
        joint = self.config.joint
        parts = [
            solve_contact(
                BushingContour.from_wear_profile(
                    joint.bushing_radius, contour.wear_depth + facing[k], joint.axial_length
                ),
                self.pin,
                cycle.load[k : k + 1],
                cycle.azimuth[k : k + 1],
                self.law,
                self.parameters,
                **options,
            )
            for k in range(cycle.steps)
        ]
        fields = {
            name: np.concatenate([getattr(part, name) for part in parts])
            for name in ("pressure", "eccentricity", "penetration", "normal_force",
                         "tangential_force", "half_angle_left", "half_angle_right",
                         "springs_left", "springs_right", "iterations")
        }
        return ContactSolution(**fields, model=parts[0].model)

    def wear_per_revolution(self, solution: ContactSolution) -> FloatArray:
        """Stage 3b: wear depth of one revolution at every node, by the wear law [m]."""
        revolution = getattr(solution, "revolution", None)
        if revolution is not None:  # Archard, accumulated by the fused solve from each window
            return revolution.wear
        return self.wear_law(solution.pressure, self.sliding_distance)

    # ---------------------------------------------------------------- loop
    def run(
        self,
        progress: Callable[[int, int], None] | None = None,
        state: SimulationState | None = None,
        on_step: Callable[[SimulationState], None] | None = None,
        pressures: bool = True,
    ) -> WearResult:
        """Run all revolutions, or up to the first ``[life]`` limit reached.

        Parameters
        ----------
        progress : callable, optional
            Called as ``progress(revolutions_done, revolutions_total)`` after every contour
            update, and with ``done == total`` once the run is complete: ``(total,
            total)`` at its end, ``(stop, stop)`` where a ``[life]`` limit ended it at
            revolution ``stop`` (fractional).
        state : SimulationState, optional
            Resume from this state (e.g. a checkpoint).
        on_step : callable, optional
            Called with the state after every contour update (checkpointing).
        pressures : bool
            Solve the contact on the unworn and the final contour once more for the
            result's pressure snapshots and contact half-angle (``False``: the result
            has neither, as a sweep case needs only the wear; the wear is the same).
        """
        if self.joint is None and len(self.config.joints) > 1:
            return self._run_joints(progress, state, on_step, pressures)
        start = time.perf_counter()
        state = self.initial_state() if state is None else state
        self._use_load_of(state)
        steps = self.load_cycle.steps
        if steps != self.config.simulation.steps_per_revolution:
            # a load history brings its own steps: the config says what really ran
            self.config = self.config.replace({"simulation.steps_per_revolution": steps})
        total = self.config.simulation.revolutions
        first_solution = None
        if state.revolution == 0 and not len(state.dynamics_updates):
            state = self._record_dynamics(state, None)
        if not self.config.simulation.update_contour and state.revolution == 0:
            # without update one revolution is computed and scaled (exactly linear)
            state, first_solution = self._linear(state)
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
        initial_solution = final_solution = None
        if pressures:
            final_solution = (
                self.contact(self._contour(state.wear_depth))
                if first_solution is None
                else first_solution
            )
            initial_solution = first_solution or self._unworn_solution(state)
        where = f"joint {self.joint!r}: " if len(self.config.joints) > 1 else ""
        warn_model_validity(
            self.config, self.law, state.wear_depth, (initial_solution, final_solution), where
        )
        runtime = time.perf_counter() - start
        from jointwear.results import build_contents

        contents = build_contents(self, state, initial_solution, final_solution, runtime)
        return WearResult(config=self.config, runtime=runtime, contents=contents)

    def step(self, state: SimulationState) -> SimulationState:
        """One contour update, and the dynamics solved again on the worn joint when due.

        A fixed interval (``update_every = k``) is the paper's explicit scheme: the wear
        of one revolution on the current contour, times ``k``. ``"adaptive"`` integrates
        the wear with error control, see :meth:`_adaptive_step`. A ``[life]`` limit
        reached inside the interval ends it at the first revolution that reaches it.
        """
        if self.schedule.coupled:  # (the growth is a reduction over the profile)
            threshold = state.dynamics_threshold or self.schedule.first_threshold(
                self.config.joint.clearance
            )
            if self.schedule.due(state.updates_since_dynamics, state.wear_growth, threshold):
                state = self._resolve_dynamics(state)
        remaining = self.config.simulation.revolutions - state.revolution
        if self.config.simulation.update_every == "adaptive":
            wear_step = self._adaptive_step(state, remaining)
        else:
            wear_step = self._fixed_step(state, remaining)
        return self._apply(wear_step)

    def _fixed_step(self, state: SimulationState, remaining: int) -> WearStep:
        contour = self._contour(state.wear_depth)
        solution = self.contact(contour, state)
        rate = self.wear_per_revolution(solution)
        interval = min(int(self.config.simulation.update_every), remaining)
        pin_rate = (
            None if state.pin_wear_depth is None
            else self.pin_wear_per_revolution(solution, contour)
        )
        return WearStep._explicit(state, interval, rate, solution, contour, pin_rate)

    def _adaptive_step(self, state: SimulationState, remaining: int) -> WearStep:
        """One adaptive contour update: a jump of many revolutions, error-controlled.

        The worn depth obeys ``dh/dn = w(h)``, ``w`` the wear per revolution on the
        contour worn by ``h``; updating every revolution is explicit Euler with step 1.
        A jump of ``J`` revolutions predicts ``h* = h + J w(h)`` (Euler), solves the
        contact on ``h*`` and corrects with the trapezoid rule,
        ``h_new = h + J (w(h) + w(h*)) / 2`` (a second-order predictor-corrector; the rate
        ``w(h*)`` serves as the rate of the next jump). ``J (w(h*) - w(h)) / 2``, the
        difference of the two, estimates the error of the Euler jump: it is measured
        relative to the new depth in the peak (max norm), the profile (L2) and the worn
        mass, and must stay below ``simulation.adaptive_tolerance``; otherwise the jump is
        rejected and retried shorter. The next jump follows from
        :func:`adaptive_interval`. Saved profiles that fall inside a jump are the
        quadratic (dense) output of the corrector, at their exact revolutions. After the
        dynamics were solved again the rate is that of the new load, and the jumps
        start again from one revolution.
        """
        sim = self.config.simulation
        thickness = self.config.joint.bushing_thickness
        base = state
        solved = None
        if base.wear_rate is None:  # the first update (or a new load): the current rate
            contour = self._contour(base.wear_depth)
            solution = self._solve(contour, base, 0)
            solved = (solution, contour)
            base = replace(
                base,
                wear_rate=self.wear_per_revolution(solution),
                # a new load keeps the step size; its jumps are error-controlled anyway
                next_interval=base.next_interval or 1,
                **self._warm_start(solution, contour),
            )
        rate0 = base.wear_rate
        interval = min(max(1, base.next_interval or base.interval), remaining)
        # the predicted contour stays inside the wall; the last jumps before wear-through
        # shrink to single revolutions, where the wall limit ends the run
        wearing = rate0 > 0
        if np.any(wearing):
            room = float(np.min((thickness - base.wear_depth[wearing]) / rate0[wearing]))
            if room < 1.0:
                # the wall goes within this revolution: there is no contour to predict
                # beyond it. The revolution is explicit (linear from the current contour's
                # rate), and the wall limit ends the run inside it
                if solved is None:
                    contour = self._contour(base.wear_depth)
                    solved = (self.contact(contour, base), contour)
                solution, contour = solved
                rate = self.wear_per_revolution(solution)
                return WearStep._explicit(base, 1, rate, solution, contour, None)
            interval = max(1, min(interval, math.floor(room)))
        if self.schedule.setting == "adaptive" and not self._given_cycle:
            # a jump ends where the dynamics are due again, so that they see the wear
            threshold = base.dynamics_threshold or self.schedule.first_threshold(
                self.config.joint.clearance
            )
            peak_rate = float(rate0.max())
            if peak_rate > 0.0:
                ahead = math.ceil((threshold - base.wear_growth) / peak_rate)
                interval = max(1, min(interval, ahead))
        while True:
            contour = self._contour(base.wear_depth + interval * rate0)
            solution = self._solve(contour, base, interval)
            rate = self.wear_per_revolution(solution)
            error = jump_error(
                base.wear_depth, rate0, rate, interval, self.config.joint.bushing_radius
            )
            if error <= sim.adaptive_tolerance or interval == 1:
                break
            interval = max(
                1, min(interval - 1, adaptive_interval(error, interval, sim.adaptive_tolerance))
            )
        return WearStep(base, interval, rate0, rate, solution, contour, error)

    def _apply(self, step: WearStep) -> SimulationState:
        """The state after a contour update, cut short where a ``[life]`` limit is reached."""
        base, interval = step.base, step.interval
        end = step.depth_at(interval)
        adaptive = step.end_rate is not None
        # (the end of the interval is the limits' first question, and usually the answer)
        stop = self.life.first_reached(
            lambda revolutions: end if revolutions == interval else step.depth_at(revolutions),
            interval,
            None if adaptive else (base.wear_depth, step.rate),
        )
        stopped_by = None
        if stop is None:
            depth = end
        else:
            from jointwear.results import revolution_number

            # the run ends inside the interval, at the limit (a fractional revolution)
            at, stopped_by = stop
            interval = revolution_number(at)
            depth = self._at_stop(step.depth_at(at))
        if stopped_by is None:
            # the contour must stay inside the wall (a run without a wall limit cannot
            # get here with wear beyond it: the wall is always a limit); a fixed step's
            # contour is the one of ``base``
            if adaptive:
                depth = update_contour(
                    self._contour(base.wear_depth), depth - base.wear_depth
                ).wear_depth
            else:
                depth = _grown(step.contour, depth - base.wear_depth)
                depth.setflags(write=False)  # its own array: the state keeps it uncopied
        profiles = base.profiles
        if adaptive:
            # saved profiles inside the jump: the corrector's quadratic in the revolution
            for target in self._profile_targets:
                if base.revolution < target < base.revolution + interval:
                    profiles = profiles.append((target, step.depth_at(target - base.revolution)))
        return self._record(
            base,
            step.solution,
            revolution=base.revolution + interval,
            wear_depth=depth,
            wear_rate=step.end_rate if adaptive else step.rate,
            interval=interval,
            profiles=profiles,
            next_interval=(
                adaptive_interval(step.error, interval, self.config.simulation.adaptive_tolerance)
                if adaptive
                else base.next_interval
            ),
            stopped_by=stopped_by,
            updates_since_dynamics=base.updates_since_dynamics + 1,
            pin_wear_depth=step.pin_depth_at(interval),
            pin_wear_rate=step.pin_rate,
            **self._warm_start(step.solution, step.contour, base.warm_offset, interval),
        )

    def _at_stop(self, depth: FloatArray) -> FloatArray:
        """The wear depth where a limit ends the run [m]: never deeper than the wall (the
        stop is found to rounding, and wear-through leaves a wall of exactly 0)."""
        return np.minimum(depth, self.config.joint.bushing_thickness)

    def _warm_start(
        self,
        solution: ContactSolution,
        contour: BushingContour,
        previous_offset: FloatArray | None = None,
        interval: int = 1,
    ) -> dict[str, Any]:
        """State fields that warm-start the next contact solve from ``solution``.

        ``previous_offset`` is the offset of the solve ``interval`` revolutions before
        (None: no trend to extrapolate).
        """
        revolution = getattr(solution, "revolution", None)
        if revolution is not None:
            offset = revolution.offset
        else:
            offset = _along_load(solution, self.load_cycle.azimuth)
        slope = _slope(previous_offset, offset, interval)
        # arrays of this solve alone, never written again: the state keeps them uncopied
        offset.setflags(write=False)
        if slope is not None:
            slope.setflags(write=False)
        window = _window_nodes(solution, contour)
        return {"warm_offset": offset, "warm_slope": slope, "window": window}

    # ---------------------------------------------------------------- coupling
    def _use_load_of(self, state: SimulationState) -> None:
        """Make the load cycle the one ``state`` was running with (resume)."""
        if state.load_depth is not None and not self._given_cycle:
            self._set_cycle(self._worn_cycle(state.load_depth))

    def _set_cycle(self, cycle: mechanism.LoadCycle) -> None:
        self._cycles = {self.joint or cycle.joint: cycle}

    def _worn_cycle(self, wear_depth: FloatArray) -> mechanism.LoadCycle:
        """The load cycle of the joint worn by ``wear_depth`` (stage 1 on the worn joint)."""
        cycles = load_cycles(self.config, wear_depth=wear_depth)
        return cycles[self.joint] if self.joint is not None else next(iter(cycles.values()))

    def _resolve_dynamics(self, state: SimulationState) -> SimulationState:
        """Solve the dynamics again on the worn joint; the wear rate follows the new load."""
        if self._given_cycle or not self.schedule.coupled:
            return replace(state, updates_since_dynamics=0)
        old = self.load_cycle
        self._set_cycle(self._worn_cycle(state.wear_depth))
        change = load_change(old, self.load_cycle)
        state = replace(
            state,
            load_depth=state.wear_depth,
            updates_since_dynamics=0,
            dynamics_threshold=self.schedule.next_threshold(
                state.wear_growth, change, self.config.joint.clearance + state.wear_depth.max()
            ),
            # the rate and the warm start belonged to the old load
            wear_rate=None,
            warm_offset=None,
            warm_slope=None,
            window=None,
        )
        return self._record_dynamics(state, change)

    def _record_dynamics(self, state: SimulationState, change: float | None) -> SimulationState:
        """Add the current load cycle's scalars to the record, and say what they imply."""
        cycle = self.load_cycle
        extras = cycle.extras
        row = {
            "revolution": float(state.revolution),
            "load_max": float(cycle.load.max()),
            "load_mean": cycle.mean_load,
            "peak_load": float(extras.get("peak_load_n", cycle.load.max())),
            "impacts": float(extras.get("impacts", 0)),
            "free_flight_fraction": float(extras.get("free_flight_fraction", 0.0)),
            "load_change": math.nan if change is None else float(change),
            "max_clearance": self.config.joint.clearance + float(state.wear_depth.max()),
        }
        if row["impacts"] > 0 or row["free_flight_fraction"] > 0:
            self._warn_once(
                "separation",
                f"dynamics: the pin separates from the bushing ({int(row['impacts'])} impacts, "
                f"{row['free_flight_fraction']:.3g} of the cycle in free flight at revolution "
                f"{state.revolution:.10g}); the wear follows the contact-impact load",
            )
        return replace(state, dynamics_updates=state.dynamics_updates.append(row))

    def _warn_once(self, key: str, message: str) -> None:
        if key not in self._warned:
            self._warned.add(key)
            warnings.warn(message, WearFeedbackWarning, stacklevel=3)

    def _check_assumptions(self, revolution: int, wear_depth: FloatArray) -> None:
        """Say once when the continuous-contact assumption of the load is in doubt.

        ``wear_depth``: the wear profile [m] at ``revolution``.
        """
        warned = self._warned
        cycle = self.load_cycle
        # (nothing left to say: both said, or the clearance said and this cycle's load
        # range seen; a run checks at every update)
        seen = self._load_range_of is not None and self._load_range_of[0] is cycle
        if cycle.model != "massless-link" or (
            "clearance" in warned and ("load" in warned or seen)
        ):
            return
        clearance = self.config.joint.clearance
        # (the peak only until its warning was given: a run checks at every update)
        peak = clearance if "clearance" in warned else float(wear_depth.max())
        if peak >= clearance:
            self._warn_once(
                "clearance",
                f"simulation: the wear ({peak * 1e3:.3g} mm) has grown past the clearance "
                f"({clearance * 1e3:.3g} mm) by revolution {revolution:.10g}, but the massless-"
                f"link load assumes the pin stays on the wall; set dynamics.model = "
                f"'contact-impact' and simulation.dynamics_update = 'adaptive' to let the "
                f"worn joint's dynamics feed back",
            )
        if "load" not in warned:
            low, high = self._load_range(cycle)
            if low < 1e-3 * high:
                self._warn_once(
                    "load",
                    f"dynamics: the joint load falls to {low:.3g} N "
                    f"(peak {high:.3g} N), where the pin may leave the wall; "
                    f"dynamics.model = 'contact-impact' models the separation",
                )

    def _load_range(self, cycle: mechanism.LoadCycle) -> tuple[float, float]:
        """Smallest and largest load of ``cycle`` [N], computed once per cycle."""
        cached = self._load_range_of
        if cached is None or cached[0] is not cycle:
            cached = (cycle, float(cycle.load.min()), float(cycle.load.max()))
            self._load_range_of = cached
        return cached[1], cached[2]

    # ---------------------------------------------------------------- helpers
    def _unworn_solution(self, state: SimulationState) -> ContactSolution:
        """Contact on the unworn bushing under the load of the unworn joint."""
        if state.load_depth is None or self._given_cycle:
            return self.contact(self.initial_contour())
        current = self.load_cycle
        self._set_cycle(self._worn_cycle(np.zeros_like(state.wear_depth)))
        try:
            return self.contact(self.initial_contour())
        finally:
            self._set_cycle(current)

    def _run_joints(self, progress, state, on_step, pressures: bool = True) -> WearResult:
        """Each clearance joint on its own contour from its own load cycle."""
        if state is not None or on_step is not None:
            from jointwear.errors import ConfigError

            raise ConfigError(
                "simulation.checkpoint_every: checkpoints hold one clearance joint; give "
                "mechanism.clearance_joint a single joint to checkpoint"
            )
        from jointwear.results import combine_joints

        start = time.perf_counter()
        results = [
            Simulation(
                self.config, self.contact_model, load_cycle=cycle, joint=joint,
                wear_law=self.wear_law,
            ).run(progress, pressures=pressures)
            for joint, cycle in self.load_cycles.items()
        ]
        runtime = time.perf_counter() - start
        dataset = combine_joints([r.dataset for r in results])
        return WearResult(config=self.config, dataset=dataset, runtime=runtime)

    def _linear(self, state: SimulationState) -> tuple[SimulationState, ContactSolution]:
        """Without contour update: one revolution's wear, scaled (exactly linear)."""
        total = self.config.simulation.revolutions
        contour = self._contour(state.wear_depth)
        solution = self.contact(contour)
        rate = self.wear_per_revolution(solution)
        pin_rate = (
            None if state.pin_wear_depth is None
            else self.pin_wear_per_revolution(solution, contour)
        )
        stop = self.life.first_reached(lambda n: rate * n, total, (np.zeros_like(rate), rate))
        end, stopped_by = total, None
        if stop is not None:
            from jointwear.results import revolution_number

            end, stopped_by = revolution_number(stop[0]), stop[1]
        # the saved profiles before the end, and the end (the last mark without a stop)
        for revolution in [t for t in self._profile_targets if t < end] + [end]:
            depth = contour.worn(rate * revolution).wear_depth
            if stopped_by is not None and revolution == end:
                depth = self._at_stop(depth)
            state = self._record(
                state,
                solution,
                revolution=revolution,
                wear_rate=rate,
                interval=revolution,
                wear_depth=depth,
                stopped_by=stopped_by if revolution == end else None,
                pin_wear_depth=None if pin_rate is None else pin_rate * revolution,
                pin_wear_rate=pin_rate,
            )
        return state, solution

    def _contour(self, wear_depth: FloatArray) -> BushingContour:
        joint = self.config.joint
        # built anew from the depth at every update (as a resumed run rebuilds it), never
        # carried over: ``R + (h + dh)`` and ``(R + h) + dh`` differ in the last bits
        return BushingContour._of_depth(
            joint.bushing_radius, np.asarray(wear_depth, dtype=float), joint.axial_length
        )

    @functools.cached_property
    def _profile_targets(self) -> tuple[int, ...]:
        # computed once: _record asks at every contour update
        sim = self.config.simulation
        marks = np.linspace(
            sim.revolutions / sim.saved_profiles, sim.revolutions, sim.saved_profiles
        )
        return tuple(sorted({max(1, round(float(m))) for m in marks}))

    def _record(
        self, base: SimulationState, solution: ContactSolution, **changes: Any
    ) -> SimulationState:
        """``base`` with ``changes``, its metrics added to the record and its profile saved
        where one is due: one new state."""
        revolution = changes.get("revolution", base.revolution)
        depth = changes.get("wear_depth", base.wear_depth)
        pin_depth = changes.get("pin_wear_depth", base.pin_wear_depth)
        stopped_by = changes.get("stopped_by", base.stopped_by)
        profiles = changes.get("profiles", base.profiles)
        if type(depth) is not np.ndarray or depth.dtype != np.float64:
            depth = np.asarray(depth, dtype=float)
        if depth.flags.writeable:  # the row keeps it until it is read
            depth = depth.copy()
            depth.setflags(write=False)
        if "wear_depth" in changes:
            changes["wear_depth"] = depth
        row = _MetricsRow(
            revolution,
            depth,
            self.life.joint,
            float(solution.iterations.sum()),
            None if pin_depth is None else pin_metrics(pin_depth, self.config.joint),
        )
        last = profiles.last
        last_saved = 0 if last is None else last[0]
        targets = self._profile_targets
        # a target in (last_saved, revolution]
        due = bisect.bisect_right(targets, last_saved)
        if stopped_by is not None or (due < len(targets) and targets[due] <= revolution):
            profiles = profiles.append((revolution, depth))
        self._check_assumptions(revolution, depth)
        changes.update(history=base.history.append(row), profiles=profiles)
        return base._evolved(changes)


class _MetricsRow(Deferred):
    """A row of the per-update record: the revolution, the wear metrics of the profile
    and the contact iterations. The metrics are computed when the record is read, for
    many rows at once (each row's values as computed alone, to the bit)."""

    __slots__ = ("depth", "extra", "iterations", "joint", "revolution")

    def __init__(
        self, revolution: int, depth: FloatArray, joint: JointGeometry, iterations: float,
        extra: dict[str, float] | None,
    ) -> None:
        self.revolution, self.depth, self.joint = revolution, depth, joint
        self.iterations, self.extra = iterations, extra

    @classmethod
    def resolve(cls, items: list[_MetricsRow]) -> list[dict[str, Any]]:
        first = items[0]
        if not all(i.joint is first.joint and i.depth.shape == first.depth.shape for i in items):
            rows = [evaluate_metrics(i.depth, i.joint) for i in items]
            names = ("revolution", *rows[0], "contact_iterations")
            columns = [[row[name] for row in rows] for name in names[1:-1]]
        else:
            stacked = profile_metrics(np.stack([i.depth for i in items]), first.joint)
            names = ("revolution", *stacked, "contact_iterations")
            columns = [values.tolist() for values in stacked.values()]
        # a dict per row by zip of the columns (a run has a row per revolution)
        rows = [
            dict(zip(names, row, strict=True))
            for row in zip(
                [i.revolution for i in items], *columns, [i.iterations for i in items],
                strict=True,
            )
        ]
        for row, item in zip(rows, items, strict=True):
            if item.extra:
                row.update(item.extra)
        return rows


#: contact solves a run may need, above which the compiled kernel pays for loading numba
COMPILED_KERNEL_SOLVES = 500


def compiled_kernel(config: Config) -> bool | None:
    """Whether the run's contact solves may use the compiled kernel (``None``: where it can).

    Loading numba and its cached machine code takes ~0.7 s; the NumPy path solves a
    warm-started revolution of the paper's joint (360 steps, 360 nodes) in 0.5-1.7 ms, the
    compiled one in ~0.2 ms. A run that may need at most :data:`COMPILED_KERNEL_SOLVES`
    solves is about as fast or faster on the NumPy path (``False``). The
    bound is read from the configuration alone, so a run resumed from its checkpoint
    takes the same path and gives the same bits
    (:attr:`jointwear.config.SimulationConfig.contact_solves`).

    Parameters
    ----------
    config : Config
        The run's configuration.
    """
    return None if config.simulation.contact_solves > COMPILED_KERNEL_SOLVES else False


#: step-size control of adaptive updating: safety factor, largest growth and shrink
_SAFETY, _GROW, _SHRINK = 0.9, 4.0, 0.2


def adaptive_interval(error: float, interval: int, tolerance: float) -> int:
    """Revolutions of the next adaptive jump, from the error estimate of the last one.

    The estimate is the local error of an Euler jump, which grows as ``interval^2
    |dw/dn|``; the next interval is the one whose error would be ``0.9 * tolerance``,
    growing at most 4-fold and shrinking at most 5-fold (standard step-size control
    of an ODE integrator).

    Parameters
    ----------
    error : float
        Relative error estimate of the last jump (:func:`jump_error`) [-].
    interval : int
        Revolutions of the last jump [-].
    tolerance : float
        ``simulation.adaptive_tolerance`` [-].
    """
    if not error > 0.0:
        factor = _GROW
    else:
        factor = min(_GROW, max(_SHRINK, _SAFETY * math.sqrt(tolerance / error)))
    return max(1, int(interval * factor))


def jump_error(
    depth: FloatArray, rate: FloatArray, new_rate: FloatArray, interval: int, radius: float
) -> float:
    """Relative error estimate of an adaptive jump [-].

    ``d = interval (new_rate - rate) / 2`` is the difference between the trapezoid and
    the Euler increment. Measured against the depth after the jump ``h``: in the peak
    ``max|d| / max h``, in the profile ``||d||_2 / ||h||_2`` and in the worn mass
    ``|sum (R + h) d| / sum (R + h/2) h`` (the removed area to first order in ``d``);
    the largest of the three.

    Parameters
    ----------
    depth : ndarray
        Wear depth before the jump [m].
    rate, new_rate : ndarray
        Wear per revolution before the jump and at the predicted contour [m].
    interval : int
        Revolutions of the jump.
    radius : float
        Unworn bushing radius ``R`` [m].
    """
    difference = 0.5 * interval * (new_rate - rate)
    after = depth + 0.5 * interval * (rate + new_rate)
    peak = float(np.max(np.abs(after)))
    if not peak > 0.0:
        return 0.0
    area = float(np.dot(radius + 0.5 * after, after))
    errors = (
        float(np.max(np.abs(difference))) / peak,
        float(np.linalg.norm(difference) / np.linalg.norm(after)),
        abs(float(np.dot(radius + after, difference))) / area if area > 0 else 0.0,
    )
    return max(errors)


def _slope(previous: FloatArray | None, offset: FloatArray, interval: int) -> FloatArray | None:
    """Change of the pin offset per revolution between two solves [m]."""
    if previous is None or previous.shape != offset.shape or interval <= 0:
        return None
    change = offset - previous
    # (x / 1 is exact: a per-revolution update skips the division)
    return change if interval == 1 else change / interval


def _along_load(solution: ContactSolution, azimuth: FloatArray) -> FloatArray:
    return solution.eccentricity[:, 0] * np.cos(azimuth) + solution.eccentricity[:, 1] * np.sin(
        azimuth
    )


def _grown(contour: BushingContour, increment: FloatArray) -> FloatArray:
    """The wear depth of ``update_contour(contour, increment)`` [m], without building the
    contour unless it would be refused (it then raises as the update does)."""
    # the contour's radii are valid, and so are they grown by a finite increment that is
    # nowhere negative (a NaN fails both comparisons): else the update decides
    if not (increment.min() >= 0.0 and increment.max() < np.inf):
        return update_contour(contour, increment).wear_depth
    return contour.wear_depth + increment


def _window_nodes(solution: ContactSolution, contour: BushingContour) -> int:
    revolution = getattr(solution, "revolution", None)
    if revolution is not None:
        return revolution.window
    widest = max(float(solution.half_angle_left.max()), float(solution.half_angle_right.max()))
    return int(np.ceil(widest / contour.dtheta) + 3)
