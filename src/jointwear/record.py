"""What the revolution loop records, and the plain record a run hands back.

Inside the loop every contour update adds a row to the per-update record
(:class:`MetricsRow`: the wear metrics of the profile, computed when the record is read)
and saves the profile where one is due (:class:`ProfileSchedule`). A finished run is a
:class:`RunRecord`: the final state with its records, the load cycle it wore under, the
contact pressure on the unworn and the final contour, the configuration and the warnings
it gave. :mod:`jointwear.results` builds the Dataset, the summary and the files from it.
"""

from __future__ import annotations

import bisect
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from jointwear.state import Deferred, SimulationState
from jointwear.tribology.checks import warn_model_validity
from jointwear.tribology.metrics import (
    PIN_METRICS,
    WEAR_METRICS,
    JointGeometry,
    evaluate_metrics,
    pin_metrics,
    profile_metrics,
)

if TYPE_CHECKING:
    from jointwear.config import Config, SimulationConfig
    from jointwear.contact import ContactSolution
    from jointwear.contact.lubricated import FilmRecord
    from jointwear.mechanism.cycle import LoadCycle
    from jointwear.state import Log

__all__ = [
    "UPDATE_COLUMNS",
    "WALL_CLOCK_KEYS",
    "ContactSnapshot",
    "MetricsRow",
    "ProfileSchedule",
    "RunRecord",
    "UpdateRecorder",
    "read_only_depth",
    "run_warnings",
]

#: the summary's wall-clock times [s]: ``runtime_s`` (the run), ``compile_time_s`` (of the
#: run's work, numba compiling kernels: its load cycle's dynamics and its loop; 0 when every
#: kernel came from numba's cache or ``jointwear warm-up`` compiled them) and
#: ``runtime_without_compile_s`` (``runtime_s`` less the compiling inside it). They differ
#: from run to run: the only keys two runs of one config do not share.
WALL_CLOCK_KEYS = ("runtime_s", "compile_time_s", "runtime_without_compile_s")

FloatArray = NDArray[np.float64]

#: the per-update record's columns besides ``revolution``: name -> (units, long_name)
UPDATE_COLUMNS: dict[str, tuple[str, str]] = {
    **{m.name: (m.units, m.long_name) for m in (*WEAR_METRICS, *PIN_METRICS)},
    "contact_iterations": ("1", "contact balance iterations of the revolution"),
}


class MetricsRow(Deferred):
    """A row of the per-update record: the revolution, the wear metrics of the profile
    and the contact iterations. The metrics are computed when the record is read, for
    many rows at once (each row's values as computed alone, to the bit).

    Parameters
    ----------
    revolution : int or float
        Revolutions completed [-].
    depth : ndarray, shape (N,)
        The wear profile, read-only [m].
    joint : JointGeometry
        What the metrics need of the joint.
    iterations : float
        Contact balance iterations of the update's last solve [-].
    extra : dict, optional
        Further values of the row (the pin's metrics) [SI].
    """

    __slots__ = ("depth", "extra", "iterations", "joint", "revolution")

    def __init__(
        self,
        revolution: int | float,
        depth: FloatArray,
        joint: JointGeometry,
        iterations: float,
        extra: dict[str, float] | None,
    ) -> None:
        self.revolution, self.depth, self.joint = revolution, depth, joint
        self.iterations, self.extra = iterations, extra

    @classmethod
    def resolve(cls, items: list[MetricsRow]) -> list[dict[str, Any]]:
        first = items[0]
        same = all(i.joint is first.joint and i.depth.shape == first.depth.shape for i in items)
        if not same or first.depth.ndim != 1:  # (a map along the pin: row by row)
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
                [i.revolution for i in items],
                *columns,
                [i.iterations for i in items],
                strict=True,
            )
        ]
        for row, item in zip(rows, items, strict=True):
            if item.extra:
                row.update(item.extra)
        return rows


def read_only_depth(depth: Any) -> FloatArray:
    """``depth`` as a read-only float array [m], copied only if it could change.

    Parameters
    ----------
    depth : array_like, shape (N,)
        A wear profile [m].
    """
    if type(depth) is not np.ndarray or depth.dtype != np.float64:
        depth = np.asarray(depth, dtype=float)
    if depth.flags.writeable:  # the record keeps it until it is read
        depth = depth.copy()
        depth.setflags(write=False)
    return depth


@dataclass(frozen=True)
class ProfileSchedule:
    """The revolutions at which a run saves its wear profile (``simulation.saved_profiles``
    evenly over the run, the last at its end).

    Attributes
    ----------
    targets : tuple of int
        The revolutions, increasing [-].
    """

    targets: tuple[int, ...]

    @classmethod
    def of(cls, simulation: SimulationConfig) -> ProfileSchedule:
        """The schedule of ``config.simulation``."""
        marks = np.linspace(
            simulation.revolutions / simulation.saved_profiles,
            simulation.revolutions,
            simulation.saved_profiles,
        )
        return cls(tuple(sorted({max(1, round(float(m))) for m in marks})))

    def due(self, profiles: Log, revolution: float) -> bool:
        """Whether a target lies in ``(last saved, revolution]``.

        Parameters
        ----------
        profiles : Log of (revolution, ndarray)
            The profiles saved so far.
        revolution : float
            Revolutions completed [-].
        """
        last = profiles.last
        after = bisect.bisect_right(self.targets, 0 if last is None else last[0])
        return after < len(self.targets) and self.targets[after] <= revolution

    def inside(self, start: float, interval: float) -> list[int]:
        """The targets strictly inside ``(start, start + interval)`` [-]."""
        return [t for t in self.targets if start < t < start + interval]

    def before(self, end: float) -> list[int]:
        """The targets before ``end`` [-]."""
        return [t for t in self.targets if t < end]


class UpdateRecorder:
    """Records every contour update of a run: its metrics row, and its profile where due.

    Parameters
    ----------
    config : Config
        The run's configuration (the saved profiles, the pin's metrics).
    joint : JointGeometry
        What the wear metrics need of the joint.
    """

    def __init__(self, config: Config, joint: JointGeometry) -> None:
        self.config, self.joint = config, joint
        self.profiles = ProfileSchedule.of(config.simulation)

    def record(
        self, base: SimulationState, iterations: float, changes: dict[str, Any]
    ) -> SimulationState:
        """``base`` with ``changes`` (field name -> value), its metrics row added to the
        record and its profile saved where one is due (or where the run stopped).

        Parameters
        ----------
        base : SimulationState
            The state the update started from.
        iterations : float
            Contact balance iterations of the update's last solve [-].
        changes : dict
            The state's new values (SI).
        """
        revolution = changes.get("revolution", base.revolution)
        depth = read_only_depth(changes.get("wear_depth", base.wear_depth))
        if "wear_depth" in changes:
            changes["wear_depth"] = depth
        pin_depth = changes.get("pin_wear_depth", base.pin_wear_depth)
        extra = None if pin_depth is None else pin_metrics(pin_depth, self.config.joint)
        row = MetricsRow(revolution, depth, self.joint, iterations, extra)
        profiles = changes.get("profiles", base.profiles)
        stopped = changes.get("stopped_by", base.stopped_by) is not None
        if stopped or self.profiles.due(profiles, revolution):
            profiles = profiles.append((revolution, depth))
        changes.update(history=base.history.append(row), profiles=profiles)
        return base.evolved(changes)


class ContactSnapshot(NamedTuple):
    """What a result keeps of a contact solve.

    Attributes
    ----------
    model : str
        The contact model that solved it.
    pressure : ndarray, shape (M, N)
        Pressure on every node at every step [Pa].
    half_angle : ndarray, shape (M,)
        Mean contact half-angle of each step [rad].
    """

    model: str
    pressure: FloatArray
    half_angle: FloatArray

    @classmethod
    def of(cls, solution: ContactSolution) -> ContactSnapshot:
        """The snapshot of ``solution``."""
        half_angle = 0.5 * (solution.half_angle_left + solution.half_angle_right)
        return cls(solution.model, solution.pressure, half_angle)


def run_warnings(
    config: Config,
    law: Any,
    wear_depth: FloatArray,
    solutions: tuple[ContactSolution | None, ...],
    joint: str | None,
    feedback: tuple[str, ...],
) -> tuple[str, ...]:
    """The warnings a run's record keeps: the wear's ``feedback``, then the contact
    model's range (:func:`~jointwear.tribology.checks.warn_model_validity`, which warns).

    Parameters
    ----------
    config : Config
        The run's configuration.
    law : str or law
        The run's contact model.
    wear_depth : ndarray
        The final wear profile [m].
    solutions : tuple of ContactSolution or None
        The contact on the unworn and the final contour (``None``: not solved).
    joint : str or None
        The clearance joint, named in the model's messages where there are several.
    feedback : tuple of str
        The messages of the wear's feedback on the load (already warned).
    """
    where = f"joint {joint!r}: " if len(config.joints) > 1 else ""
    said = warn_model_validity(config, law, wear_depth, solutions, where)
    return (*feedback, *(where + message for message in said.values()))


@dataclass(frozen=True, eq=False)
class RunRecord:
    """The plain record of one clearance joint's run (SI units).

    Attributes
    ----------
    config : Config
        The configuration the run ran with (the steps of a load history its own).
    state : SimulationState
        The final state: wear profile and rate, the per-update record, the saved
        profiles, the dynamics record and the limit that ended the run.
    cycle : LoadCycle
        The load cycle the run ended with (its diagnostics beside it).
    sliding_distance : ndarray, shape (M,)
        Sliding distance of each step of ``cycle`` [m].
    contact_model : str
        Name of the contact model.
    initial, final : ContactSnapshot or None
        Contact on the unworn and on the final contour (``None``: not solved, as a
        sweep case needs only the wear).
    runtime : float
        Wall-clock time of the run [s].
    compile_time : float
        Of this run's work (its load cycle's dynamics and its loop), the seconds numba
        spent compiling kernels [s] (0: none compiled, e.g. loaded from numba's cache).
    compile_in_runtime : float
        Of ``compile_time``, the part inside ``runtime`` [s].
    warnings : tuple of str
        The warnings the run gave about its models' range and the wear's feedback.
    film : FilmRecord or None
        A lubricated run's film thickness, film parameter, asperity load fraction and
        dry-fallback steps over ``cycle`` (``None``: a dry run).
    """

    config: Config
    state: SimulationState
    cycle: LoadCycle
    sliding_distance: FloatArray
    contact_model: str
    initial: ContactSnapshot | None = None
    final: ContactSnapshot | None = None
    runtime: float = math.nan
    compile_time: float = 0.0
    compile_in_runtime: float = 0.0
    warnings: tuple[str, ...] = ()
    film: FilmRecord | None = None

    @classmethod
    def finished(
        cls,
        config: Config,
        state: SimulationState,
        cycle: LoadCycle,
        sliding_distance: FloatArray,
        law: Any,
        solutions: tuple[ContactSolution | None, ContactSolution | None],
        *,
        joint: str | None,
        feedback: tuple[str, ...],
        film: FilmRecord | None,
        times: dict[str, float],
    ) -> RunRecord:
        """The record of a finished run: the snapshots of its contact on the unworn and the
        final contour (``solutions``, ``None``: not solved), the contact model's name and
        the warnings (:func:`run_warnings`, which warns of the model's range).

        Parameters
        ----------
        config, state, cycle, sliding_distance, film
            As the attributes [SI units].
        law : str or law
            The run's contact model (its ``name`` is kept where nothing was solved).
        solutions : (ContactSolution or None, ContactSolution or None)
            The contact on the unworn and on the final contour.
        joint, feedback
            As :func:`run_warnings`.
        times : dict
            ``runtime``, ``compile_time`` and ``compile_in_runtime`` [s]
            (:meth:`jointwear.compile_time.Clock.times`).
        """
        initial, final = solutions
        said = run_warnings(config, law, state.wear_depth, solutions, joint, feedback)
        return cls(
            config,
            state,
            cycle,
            sliding_distance,
            contact_model=law.name if final is None else final.model,
            initial=None if initial is None else ContactSnapshot.of(initial),
            final=None if final is None else ContactSnapshot.of(final),
            warnings=said,
            film=film,
            **times,
        )
