"""How wear and the rest of the run feed each other: life limits and dynamics updates.

Two components of :class:`~jointwear.simulation.Simulation`, each a small object
built from the config:

* :class:`LifeLimits` — the ``[life]`` limits. A contour update advances the
  wear depth over an interval of revolutions along a known path (linear for a
  fixed update interval, the corrector's quadratic inside an adaptive jump); the
  limits are checked at the end of the interval and, if one is reached, the first
  revolution at which it is reached is found by bisection on that path, so the run
  stops within one revolution of the limit wherever it falls.
* :class:`DynamicsSchedule` — ``simulation.dynamics_update``: when the dynamics are
  solved again on the worn joint. ``"once"``: never (the load of the unworn joint
  throughout). ``K``: every ``K`` contour updates. ``"adaptive"``: the interval
  between solves is chosen so that the load cycle moves by about
  ``simulation.dynamics_tolerance`` (RMS of the change of the load vector over the
  cycle, relative to the RMS load) from one solve to the next — longer while the
  load barely changes, shorter when wear starts to change the dynamics.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from jointwear.tribology.metrics import JointGeometry, evaluate_metrics

if TYPE_CHECKING:
    from jointwear.config import Config
    from jointwear.mechanism.cycle import LoadCycle

__all__ = ["LIFE_LIMITS", "DynamicsSchedule", "LifeLimits", "joint_geometry", "load_change"]

FloatArray = NDArray[np.float64]

#: ``[life]`` key -> (metric of the wear profile, +1: reached at or above the limit,
#: -1: at or below)
LIFE_LIMITS: dict[str, tuple[str, int]] = {
    "peak_wear_depth": ("peak_wear_depth", 1),
    "wear_mass": ("wear_mass", 1),
    "wear_volume": ("wear_volume", 1),
    "clearance": ("max_clearance", 1),
    "wall_thickness": ("min_wall_thickness", -1),
}


def joint_geometry(config: Config) -> JointGeometry:
    """What the wear metrics need of a configured joint."""
    joint = config.joint
    return JointGeometry(
        bushing_radius=joint.bushing_radius,
        clearance=joint.clearance,
        axial_length=joint.axial_length,
        bushing_thickness=joint.bushing_thickness,
        density=config.materials.bushing.density,
        width_threshold=config.simulation.width_threshold,
    )


@dataclass(frozen=True)
class LifeLimits:
    """The ``[life]`` limits of a run.

    Attributes
    ----------
    limits : tuple of (str, str, float, int)
        ``(life key, metric, limit [SI], sense)`` of each limit that is set.
    joint : JointGeometry
        The joint the metrics are evaluated for.
    """

    limits: tuple[tuple[str, str, float, int], ...]
    joint: JointGeometry

    @classmethod
    def from_config(cls, config: Config) -> LifeLimits:
        """The limits set in ``config.life`` (the wall is always one)."""
        limits = []
        for key, (metric, sense) in LIFE_LIMITS.items():
            value = getattr(config.life, key)
            if value is not None:
                limits.append((key, metric, float(value), sense))
        return cls(tuple(limits), joint_geometry(config))

    def reached(self, wear_depth: FloatArray) -> str | None:
        """The first limit (in :data:`LIFE_LIMITS` order) a profile reaches, if any.

        Parameters
        ----------
        wear_depth : ndarray, shape (N,)
            Wear-depth profile [m].
        """
        values = evaluate_metrics(wear_depth, self.joint)
        for key, metric, limit, sense in self.limits:
            if sense * (values[metric] - limit) >= 0.0:
                return key
        return None

    def first_reached(
        self, depth_at: Callable[[int], FloatArray], interval: int
    ) -> tuple[int, str] | None:
        """The first revolution of an interval at which a limit is reached.

        Parameters
        ----------
        depth_at : callable
            ``depth_at(n)``: the wear depth ``n`` revolutions into the interval [m];
            the wear grows monotonically with ``n``.
        interval : int
            Revolutions of the interval.

        Returns
        -------
        tuple of (int, str) or None
            Revolutions into the interval and the limit reached there; ``None`` if no
            limit is reached by the end of the interval.
        """
        if self.reached(depth_at(interval)) is None:
            return None
        low, high = 0, interval  # not reached at ``low`` (the state before), reached at ``high``
        while high - low > 1:
            middle = (low + high) // 2
            if self.reached(depth_at(middle)) is None:
                low = middle
            else:
                high = middle
        return high, str(self.reached(depth_at(high)))


def load_change(old: LoadCycle, new: LoadCycle) -> float:
    """How far a load cycle has moved: RMS of the change of the load vector over RMS load [-].

    Parameters
    ----------
    old, new : LoadCycle
        Two load cycles of the same joint with the same steps.
    """
    if old.steps != new.steps:
        return math.inf
    difference = np.hypot(new.force_x - old.force_x, new.force_y - old.force_y)
    scale = float(np.sqrt(np.mean(old.load**2)))
    if not scale > 0.0:
        return 0.0 if not np.any(difference) else math.inf
    return float(np.sqrt(np.mean(difference**2)) / scale)


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

    def due(self, updates_since: int, every: int) -> bool:
        """Whether the dynamics are due after ``updates_since`` contour updates.

        Parameters
        ----------
        updates_since : int
            Contour updates since the last solve.
        every : int
            The current adaptive interval (contour updates).
        """
        if self.setting == "once":
            return False
        interval = every if self.setting == "adaptive" else int(self.setting)
        return updates_since >= interval

    def next_every(self, every: int, change: float) -> int:
        """Contour updates until the next solve, from the change the last solve showed.

        Parameters
        ----------
        every : int
            The interval that led to the last solve.
        change : float
            :func:`load_change` between the last two load cycles [-].
        """
        if self.setting != "adaptive":
            return every
        if not change > 0.0:
            factor = _GROW
        else:
            factor = min(_GROW, max(_SHRINK, _SAFETY * self.tolerance / change))
        return max(1, int(every * factor))
