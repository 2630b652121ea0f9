"""The simulation orchestrator: the paper's Fig. 7 flow, one loop over revolutions.

Data flows one way through four stages, each a plain function from one small
data object to the next::

    mechanism.joint_load(config)              -> JointLoad       (load, azimuth, rotation per step)
    contact.solve(contour, pin, load, ...)    -> ContactSolution (pressure per step and node)
    tribology.archard.wear_depth(p, ds, K_d)  -> wear depth per revolution and node
    geometry.update.update_contour(contour,h) -> BushingContour  (worn contour)

:class:`Simulation` owns the only loop over revolutions. A contour update
applies the wear of one computed revolution times the update interval
(``simulation.update_every`` revolutions, or ``"adaptive"``: the interval
follows from how fast the wear-rate profile changes, cycle jumping in the
spirit of Mukras et al.). Without contour update the wear of one revolution
is simply scaled, so wear grows exactly linearly (paper Fig. 13).

The joint load is computed once: the massless-link dynamics depend on the
clearance only through the link length ``e``, a 0.05 mm change of which moves
the load azimuth by ``e / l2 ~ 2.5e-4`` rad, far below the node spacing.
"""

from __future__ import annotations

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
        """Stage 2: pressure on every node at every step on ``contour``."""
        cfg = self.config.contact
        warm = {}
        if state is not None and state.warm_offset is not None:
            warm = {"initial_offset": state.warm_offset, "window": state.window}
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
        return archard.wear_depth(
            solution.pressure, self.sliding_distance, self.config.materials.bushing.wear_coefficient
        )

    # ---------------------------------------------------------------- loop
    def step(self, state: SimulationState) -> SimulationState:
        """One contour update: solve a revolution, apply its wear over the next interval."""
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
            warm_offset=_along_load(solution, self.joint_load.azimuth),
            window=_window_nodes(solution, contour),
        )
        self._record(new, new.wear_depth, solution)
        return new

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

    def _profile_revolutions(self) -> list[int]:
        sim = self.config.simulation
        marks = np.linspace(
            sim.revolutions / sim.saved_profiles, sim.revolutions, sim.saved_profiles
        )
        return sorted({max(1, round(float(m))) for m in marks})

    def _interval(self, state: SimulationState, rate: FloatArray, remaining: int) -> int:
        sim = self.config.simulation
        if sim.update_every != "adaptive":
            return min(int(sim.update_every), remaining)
        return min(
            adaptive_interval(state.wear_rate, rate, state.interval, sim.adaptive_tolerance),
            remaining,
        )

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
        targets = self._profile_revolutions()
        last_saved = max(state.profiles) if state.profiles else 0
        if any(last_saved < t <= state.revolution for t in targets):
            state.profiles[state.revolution] = depth.copy()


def adaptive_interval(
    previous_rate: FloatArray | None, rate: FloatArray, previous_interval: int, tolerance: float
) -> int:
    """Revolutions until the next contour update, from the change of the wear rate.

    The wear-rate profile changed by ``max|r_new - r_old| / max|r_new|`` over the
    last interval; assuming the change is steady, the next interval is the one
    over which it changes by ``tolerance``, at most doubling each time.

    Parameters
    ----------
    previous_rate : ndarray or None
        Wear depth per revolution at the previous update [m].
    rate : ndarray
        Wear depth per revolution now [m].
    previous_interval : int
        Revolutions between the two [-].
    tolerance : float
        Allowed relative change of the wear-rate profile per update [-].
    """
    if previous_rate is None:
        return 1
    scale = float(np.max(np.abs(rate)))
    if scale == 0.0:
        return 2 * previous_interval
    change = float(np.max(np.abs(rate - previous_rate))) / scale / previous_interval
    if change == 0.0:
        return 2 * previous_interval
    return int(max(1, min(2 * previous_interval, math.floor(tolerance / change))))


def _along_load(solution: ContactSolution, azimuth: FloatArray) -> FloatArray:
    return solution.eccentricity[:, 0] * np.cos(azimuth) + solution.eccentricity[:, 1] * np.sin(
        azimuth
    )


def _window_nodes(solution: ContactSolution, contour: BushingContour) -> int:
    widest = max(float(solution.half_angle_left.max()), float(solution.half_angle_right.max()))
    return int(np.ceil(1.25 * widest / contour.dtheta) + 3)
