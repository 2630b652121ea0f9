"""The simulation orchestrator: the paper's Fig. 7 flow, one loop over revolutions.

Data flows one way through four stages, each a plain function from one small
data object to the next::

    mechanism.joint_load(config)              -> JointLoad       (load, azimuth, rotation per step)
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

The joint load is computed once: the massless-link dynamics depend on the
clearance only through the link length ``e``, a 0.05 mm change of which moves
the load azimuth by ``e / l2 ~ 2.5e-4`` rad, far below the node spacing.
"""

from __future__ import annotations

import functools
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear import mechanism
from jointwear.config import Config
from jointwear.contact import ContactParameters, ContactSolution, contact_law
from jointwear.contact import solve as solve_contact
from jointwear.contact.kernel import revolution_wear
from jointwear.contact.laws import SpringLaw
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.geometry.update import update_contour
from jointwear.tribology import archard, metrics
from jointwear.tribology.sliding import SLIDING_MODELS

__all__ = ["Simulation", "SimulationState", "WearResult"]

FloatArray = NDArray[np.float64]

#: the per-update summary kept for every contour update
HISTORY_FIELDS = (
    "revolution",
    "peak_wear_depth",
    "wear_width",
    "wear_area",
    "wear_volume",
    "wear_mass",
    "min_wall_thickness",
    "contact_iterations",
)


@dataclass
class SimulationState:
    """Everything the revolution loop carries from one update to the next.

    Plain arrays and numbers only, so a state can be checkpointed and resumed.

    Attributes
    ----------
    revolution : int
        Revolutions completed.
    wear_depth : ndarray, shape (N,)
        Accumulated radial wear depth [m] (the contour is the unworn circle plus
        this; kept as depth, not radius, so small depths carry full precision).
    wear_rate : ndarray, shape (N,) or None
        Wear depth per revolution on the current contour [m].
    interval : int
        Revolutions covered by the last update.
    history : dict of lists
        One entry per update (see ``HISTORY_FIELDS``), SI units.
    profiles : dict of int -> ndarray
        Saved wear-depth profiles by revolution [m].
    warm_offset : ndarray or None
        Pin displacement along each load line at the last solve [m] (warm start).
    window : int or None
        Node window of the last contact solve.
    warm_slope : ndarray or None
        Change of ``warm_offset`` per revolution between the last two solves [m]: the
        next solve starts from the linear extrapolation (one Newton step saved).
    next_interval : int or None
        Adaptive updating: the interval the step-size controller proposes next.
    """

    revolution: int
    wear_depth: FloatArray
    wear_rate: FloatArray | None = None
    interval: int = 1
    history: dict[str, list[float]] = field(
        default_factory=lambda: {name: [] for name in HISTORY_FIELDS}
    )
    profiles: dict[int, FloatArray] = field(default_factory=dict)
    warm_offset: FloatArray | None = None
    window: int | None = None
    warm_slope: FloatArray | None = None
    next_interval: int | None = None


@dataclass(frozen=True, eq=False)
class WearResult:
    """Outcome of a simulation.

    Attributes
    ----------
    config : Config
        The fully resolved configuration.
    dataset : xarray.Dataset
        Profiles, per-step loads, pressure snapshots and per-update metrics,
        with ``units`` and ``long_name`` attributes.
    runtime : float
        Wall-clock time of the run [s].
    """

    config: Config
    dataset: Any
    runtime: float

    @property
    def wear_depth(self) -> FloatArray:
        """Final wear-depth profile [m]."""
        return self.dataset["wear_depth"].isel(revolution=-1).values

    def summary(self) -> dict[str, Any]:
        """The ``jointwear run --json`` object (SI units in the key names)."""
        ds = self.dataset
        last = {
            name: float(ds[name].values[-1])
            for name in (
                "peak_wear_depth",
                "wear_width",
                "wear_mass",
                "wear_volume",
                "min_wall_thickness",
            )
        }
        return {
            "peak_wear_depth_m": last["peak_wear_depth"],
            "wear_width_deg": math.degrees(last["wear_width"]),
            "wear_mass_kg": last["wear_mass"],
            "wear_volume_m3": last["wear_volume"],
            "min_wall_thickness_m": last["min_wall_thickness"],
            "revolutions": int(ds["update_revolution"].values[-1]),
            "contour_updates": int(ds.sizes["update"]),
            "contact_model": ds.attrs["contact_model"],
            "runtime_s": self.runtime,
        }

    def to_netcdf(self, path) -> None:
        """Write the dataset as netCDF (h5netcdf), atomically."""
        from jointwear.results import write_netcdf

        write_netcdf(self.dataset, path)


class Simulation:
    """Wear of a clearance joint over revolutions (paper Fig. 7).

    Parameters
    ----------
    config : Config
        Validated configuration (:func:`jointwear.load_config`).
    contact_model : str or callable, optional
        Contact model name, a spring law, or ``pressure(penetration)``
        [m -> Pa]; default ``config.contact.model``.
    joint_load : JointLoad, optional
        Precomputed joint load per step (default: from ``config`` by
        :func:`jointwear.mechanism.joint_load`).

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
        joint_load: mechanism.JointLoad | None = None,
    ) -> None:
        self.config = config
        self.parameters = ContactParameters.from_config(config)
        self.contact_model = config.contact.model if contact_model is None else contact_model
        self.law = contact_law(self.contact_model, self.parameters)
        self.pin = Pin(config.joint.pin_radius)
        self._joint_load = joint_load

    # ---------------------------------------------------------------- stages
    @property
    def joint_load(self) -> mechanism.JointLoad:
        """Stage 1: joint load, azimuth and relative rotation per step."""
        if self._joint_load is None:
            self._joint_load = mechanism.joint_load(self.config)
        return self._joint_load

    @property
    def sliding_distance(self) -> FloatArray:
        """Stage 3a: sliding distance per step [m]."""
        slide = SLIDING_MODELS.get(self.config.simulation.sliding)
        return slide(self.joint_load, self.config.joint.bushing_radius)

    def initial_contour(self) -> BushingContour:
        """The unworn bushing."""
        joint = self.config.joint
        return BushingContour.circle(
            joint.bushing_radius, self.config.contact.nodes, joint.axial_length
        )

    def initial_state(self) -> SimulationState:
        """State before the first revolution."""
        return SimulationState(revolution=0, wear_depth=np.zeros(self.config.contact.nodes))

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
                guess = guess + ahead * state.warm_slope
            warm = {"initial_offset": guess, "window": state.window}
        if state is not None and cfg.balance == "paper" and isinstance(self.law, SpringLaw):
            return revolution_wear(
                contour,
                self.pin,
                self.joint_load.load,
                self.joint_load.azimuth,
                self.sliding_distance,
                self.law,
                self.config.materials.bushing.wear_coefficient,
                max_penetration=self.parameters.bushing_thickness,
                tolerance=cfg.tolerance,
                max_iterations=cfg.max_iterations,
                **warm,
            ).solution()
        return solve_contact(
            contour,
            self.pin,
            self.joint_load.load,
            self.joint_load.azimuth,
            self.law,
            self.parameters,
            balance=cfg.balance,
            tolerance=cfg.tolerance,
            max_iterations=cfg.max_iterations,
            **warm,
        )

    def wear_per_revolution(self, solution: ContactSolution) -> FloatArray:
        """Stage 3b: Archard wear depth of one revolution at every node [m]."""
        revolution = getattr(solution, "revolution", None)
        if revolution is not None:  # accumulated by the solve, from each step's window
            return revolution.wear
        return archard.wear_depth(
            solution.pressure, self.sliding_distance, self.config.materials.bushing.wear_coefficient
        )

    # ---------------------------------------------------------------- loop
    def step(self, state: SimulationState) -> SimulationState:
        """One contour update: solve a revolution, apply its wear over the next interval.

        A fixed interval (``update_every = k``) is the paper's explicit scheme: the wear
        of one revolution on the current contour, times ``k``. ``"adaptive"`` integrates
        the wear with error control, see :meth:`_adaptive_step`.
        """
        if self.config.simulation.update_every == "adaptive":
            return self._adaptive_step(state)
        contour = self._contour(state.wear_depth)
        solution = self.contact(contour, state)
        rate = self.wear_per_revolution(solution)
        interval = self._interval(
            state, rate, self.config.simulation.revolutions - state.revolution
        )
        worn = update_contour(contour, rate * interval, self.config.joint.bushing_thickness)
        new = replace(
            state,
            revolution=state.revolution + interval,
            wear_depth=worn.wear_depth,
            wear_rate=rate,
            interval=interval,
            **self._warm_start(solution, contour, state.warm_offset, state.interval),
        )
        self._record(new, new.wear_depth, solution)
        return new

    def _adaptive_step(self, state: SimulationState) -> SimulationState:
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
        quadratic (dense) output of the corrector, at their exact revolutions.
        """
        sim = self.config.simulation
        thickness = self.config.joint.bushing_thickness
        base = state
        if base.wear_rate is None:  # the first update: the rate of the current contour
            contour = self._contour(base.wear_depth)
            solution = self._solve(contour, base, 0)
            base = replace(
                base,
                wear_rate=self.wear_per_revolution(solution),
                next_interval=1,
                **self._warm_start(solution, contour),
            )
        remaining = sim.revolutions - base.revolution
        rate0 = base.wear_rate
        interval = min(max(1, base.next_interval or base.interval), remaining)
        # the predicted contour must stay inside the wall (the last jumps before wear-through
        # shrink to single revolutions, which then raise as per-revolution updating does)
        wearing = rate0 > 0
        if np.any(wearing):
            room = float(np.min((thickness - base.wear_depth[wearing]) / rate0[wearing]))
            if room < 1.0:  # the next revolution wears through: raises WearThroughError
                update_contour(self._contour(base.wear_depth), rate0, thickness)
            interval = max(1, min(interval, math.floor(room)))
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
        increment = 0.5 * interval * (rate0 + rate)
        worn = update_contour(self._contour(base.wear_depth), increment, thickness)
        new = replace(
            base,
            revolution=base.revolution + interval,
            wear_depth=worn.wear_depth,
            wear_rate=rate,
            interval=interval,
            next_interval=adaptive_interval(error, interval, sim.adaptive_tolerance),
            **self._warm_start(solution, contour, base.warm_offset, interval),
        )
        # saved profiles inside the jump: the corrector's quadratic in the revolution
        for target in self._profile_revolutions():
            if base.revolution < target < new.revolution:
                tau = target - base.revolution
                new.profiles[target] = (
                    base.wear_depth + tau * rate0 + (0.5 * tau * tau / interval) * (rate - rate0)
                )
        self._record(new, new.wear_depth, solution)
        return new

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
            offset = _along_load(solution, self.joint_load.azimuth)
        return {
            "warm_offset": offset,
            "warm_slope": _slope(previous_offset, offset, interval),
            "window": _window_nodes(solution, contour),
        }

    def run(
        self,
        progress: Callable[[int, int], None] | None = None,
        state: SimulationState | None = None,
        on_step: Callable[[SimulationState], None] | None = None,
    ) -> WearResult:
        """Run all revolutions.

        Parameters
        ----------
        progress : callable, optional
            Called as ``progress(revolutions_done, revolutions_total)``.
        state : SimulationState, optional
            Resume from this state (e.g. a checkpoint).
        on_step : callable, optional
            Called with the state after every contour update (checkpointing).
        """
        start = time.perf_counter()
        total = self.config.simulation.revolutions
        state = self.initial_state() if state is None else state
        first_solution = None
        if not self.config.simulation.update_contour and state.revolution == 0:
            # without update one revolution is computed and scaled (exactly linear)
            state, first_solution = self._linear(state)
        while state.revolution < total:
            state = self.step(state)
            if on_step is not None:
                on_step(state)
            if progress is not None:
                progress(state.revolution, total)
        if progress is not None:
            progress(total, total)
        final_solution = (
            self.contact(self._contour(state.wear_depth))
            if first_solution is None
            else first_solution
        )
        initial_solution = first_solution or self.contact(self.initial_contour())
        runtime = time.perf_counter() - start
        from jointwear.results import build_dataset

        dataset = build_dataset(self, state, initial_solution, final_solution, runtime)
        return WearResult(config=self.config, dataset=dataset, runtime=runtime)

    # ---------------------------------------------------------------- helpers
    def _linear(self, state: SimulationState) -> tuple[SimulationState, ContactSolution]:
        total = self.config.simulation.revolutions
        contour = self._contour(state.wear_depth)
        solution = self.contact(contour)
        rate = self.wear_per_revolution(solution)
        for revolution in self._profile_revolutions():
            worn = update_contour(contour, rate * revolution, self.config.joint.bushing_thickness)
            state = replace(
                state,
                revolution=revolution,
                wear_rate=rate,
                interval=revolution,
                wear_depth=worn.wear_depth,
            )
            self._record(state, state.wear_depth, solution)
        state.revolution = total
        return state, solution

    def _contour(self, wear_depth: FloatArray) -> BushingContour:
        joint = self.config.joint
        return BushingContour.from_wear_profile(
            joint.bushing_radius, wear_depth, joint.axial_length
        )

    @functools.cached_property
    def _profile_targets(self) -> tuple[int, ...]:
        # computed once: _record asks at every contour update
        sim = self.config.simulation
        marks = np.linspace(
            sim.revolutions / sim.saved_profiles, sim.revolutions, sim.saved_profiles
        )
        return tuple(sorted({max(1, round(float(m))) for m in marks}))

    def _profile_revolutions(self) -> tuple[int, ...]:
        return self._profile_targets

    def _interval(self, state: SimulationState, rate: FloatArray, remaining: int) -> int:
        sim = self.config.simulation
        if sim.update_every != "adaptive":
            return min(int(sim.update_every), remaining)
        return min(state.next_interval or 1, remaining)

    def _record(self, state: SimulationState, depth: FloatArray, solution: ContactSolution) -> None:
        joint = self.config.joint
        area = metrics.worn_area(joint.bushing_radius, depth)
        row = {
            "revolution": state.revolution,
            "peak_wear_depth": metrics.wear_peak(depth),
            "wear_width": metrics.wear_width(depth, self.config.simulation.width_threshold),
            "wear_area": area,
            "wear_volume": metrics.wear_volume(area, joint.axial_length),
            "wear_mass": metrics.wear_mass(
                area, joint.axial_length, self.config.materials.bushing.density
            ),
            "min_wall_thickness": joint.bushing_thickness - float(depth.max()),
            "contact_iterations": float(solution.iterations.sum()),
        }
        for name, value in row.items():
            state.history[name].append(value)
        last_saved = max(state.profiles) if state.profiles else 0
        if any(last_saved < t <= state.revolution for t in self._profile_targets):
            state.profiles[state.revolution] = depth.copy()


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
    return (offset - previous) / interval


def _along_load(solution: ContactSolution, azimuth: FloatArray) -> FloatArray:
    return solution.eccentricity[:, 0] * np.cos(azimuth) + solution.eccentricity[:, 1] * np.sin(
        azimuth
    )


def _window_nodes(solution: ContactSolution, contour: BushingContour) -> int:
    widest = max(float(solution.half_angle_left.max()), float(solution.half_angle_right.max()))
    return int(np.ceil(widest / contour.dtheta) + 3)
