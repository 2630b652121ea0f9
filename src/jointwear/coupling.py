"""How wear and the rest of the run feed each other: life limits and dynamics updates.

Two components of :class:`~jointwear.simulation.Simulation`, each a small object
built from the config:

* :class:`LifeLimits` — the ``[life]`` limits. A contour update advances the
  wear depth over an interval of revolutions along a known path (linear for a
  fixed update interval and without contour update, the corrector's quadratic inside
  an adaptive jump); the limits are checked at the end of the interval and, if one is
  reached, the point where it is reached is found on that path to a fraction of a
  revolution (closed form for the peak on a linear path, else Brent's method), so the
  run ends *at* the limit: a wall worn through is exactly 0, never negative.
* :class:`DynamicsSchedule` — ``simulation.dynamics_update``: when the dynamics are
  solved again on the worn joint. ``"once"``: never (the load of the unworn joint
  throughout). ``K``: every ``K`` contour updates. ``"adaptive"``: when the wear
  since the last solve has grown by a depth chosen so that the load cycle moves by
  about ``simulation.dynamics_tolerance`` (RMS of the change of the load vector over
  the cycle, relative to the RMS load) from one solve to the next. The sensitivity of
  the load to the wear is measured at every solve (change of the load over growth
  of the deepest wear since the previous solve), so the solves come rarely while the
  load barely changes and often when wear starts to change the dynamics. The first
  solve on the worn joint comes after ``dynamics_tolerance`` times the clearance of
  wear.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from jointwear.tribology.metrics import JointGeometry, evaluate_metrics, wear_peak

if TYPE_CHECKING:
    from jointwear.config import Config
    from jointwear.mechanism.cycle import LoadCycle

__all__ = [
    "LIFE_LIMITS",
    "DynamicsSchedule",
    "LifeLimits",
    "joint_geometry",
    "load_change",
    "wear_signature",
]

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

    @functools.cached_property
    def _metrics(self) -> frozenset[str]:
        return frozenset(metric for _, metric, _, _ in self.limits)

    def first_reached(
        self,
        depth_at: Callable[[float], FloatArray],
        interval: float,
        linear: tuple[FloatArray, FloatArray] | None = None,
    ) -> tuple[float, str] | None:
        """Where inside an interval the first limit is reached, to a fraction of a revolution.

        Each limit reached at the end of the interval is followed back along the depth
        path to where its metric equals the limit: in closed form where the metric is a
        function of the peak and the path is linear (the first node to reach the limiting
        depth), else as the root of ``metric(depth_at(n)) - limit`` by Brent's method.
        The metrics grow monotonically along the path, so each root is the first crossing.

        Parameters
        ----------
        depth_at : callable
            ``depth_at(n)``: the wear depth ``n`` revolutions into the interval [m], ``n``
            real in ``[0, interval]``; the wear grows monotonically with ``n``.
        interval : float
            Revolutions of the interval [-].
        linear : tuple of ndarray, optional
            ``(start, rate)`` when the path is ``start + n * rate`` [m, m per revolution].

        Returns
        -------
        tuple of (float, str) or None
            Revolutions into the interval (fractional) and the limit reached there (the
            first in :data:`LIFE_LIMITS` order if several at once); ``None`` if no limit is
            reached by the end of the interval.
        """
        end = _limit_metrics(depth_at(interval), self.joint, self._metrics)
        first: tuple[float, str] | None = None
        for key, metric, limit, sense in self.limits:
            if sense * (end[metric] - limit) < 0.0:
                continue
            at = self._crossing(metric, limit, sense, depth_at, interval, linear)
            if first is None or at < first[0]:
                first = (at, key)
        return first

    def _crossing(
        self,
        metric: str,
        limit: float,
        sense: int,
        depth_at: Callable[[float], FloatArray],
        interval: float,
        linear: tuple[FloatArray, FloatArray] | None,
    ) -> float:
        """Revolutions into the interval at which ``metric`` reaches ``limit`` (reached at
        the end) [-]."""
        joint = self.joint

        def beyond(revolutions: float) -> float:
            values = _limit_metrics(depth_at(revolutions), joint, frozenset((metric,)))
            return sense * (values[metric] - limit)

        if beyond(0.0) >= 0.0:
            return 0.0
        if linear is not None and metric in _PEAK_AT_LIMIT:
            # the peak reaches the limiting depth where the first node does
            start, rate = linear
            depth = _PEAK_AT_LIMIT[metric](limit, joint)
            growing = rate > 0.0
            at = float(np.min((depth - start[growing]) / rate[growing]))
            return min(max(at, 0.0), interval)
        from scipy.optimize import brentq  # (only when a limit is reached: a run stops once)

        # (a relative tolerance: a stop early in a long interval keeps its digits)
        return float(
            brentq(beyond, 0.0, interval, xtol=1e-300, rtol=4.0 * np.finfo(float).eps,
                   maxiter=400)
        )  # fmt: skip


#: metric of the peak -> the peak wear depth at which it equals a limit [m]
_PEAK_AT_LIMIT: dict[str, Callable[[float, JointGeometry], float]] = {
    "peak_wear_depth": lambda limit, joint: limit,
    "min_wall_thickness": lambda limit, joint: joint.bushing_thickness - limit,
    "max_clearance": lambda limit, joint: limit - joint.clearance,
}


#: metrics of a profile that need its peak only, and that need its removed area
_FROM_PEAK = frozenset({"peak_wear_depth", "min_wall_thickness", "max_clearance"})


def _limit_metrics(
    wear_depth: FloatArray, joint: JointGeometry, needed: frozenset[str]
) -> dict[str, float]:
    """The metrics ``needed`` of a profile (all of :func:`evaluate_metrics` if any other).

    The limits are checked at every contour update, usually the wall alone: its peak is
    all that is computed then.
    """
    if not needed <= _FROM_PEAK:
        return evaluate_metrics(wear_depth, joint)
    peak = wear_peak(wear_depth)
    return {
        "peak_wear_depth": peak,
        "min_wall_thickness": joint.bushing_thickness - peak,
        "max_clearance": joint.clearance + peak,
    }


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
    weight = cycle.load * np.abs(cycle.relative_rotation)
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
