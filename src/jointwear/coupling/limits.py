"""Life limits: which ``[life]`` limit ends a run, and where inside an update.

:class:`LifeLimits` holds the limits set in ``[life]`` (the wall is always one). A
contour update advances the wear depth over an interval of revolutions along a known
path (linear for a fixed update interval and without contour update, the corrector's
quadratic inside an adaptive jump); the limits are checked at the end of the interval
and, if one is reached, the point where it is reached is found on that path to a
fraction of a revolution (closed form for the peak on a linear path, else Brent's
method), so the run ends *at* the limit: a wall worn through is exactly 0, never
negative (:func:`at_stop`).
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from jointwear.tribology.metrics import JointGeometry, evaluate_metrics, wear_peak

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = ["LIFE_LIMITS", "LifeLimits", "at_stop", "joint_geometry"]

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
            brentq(beyond, 0.0, interval, xtol=1e-300, rtol=4.0 * np.finfo(float).eps, maxiter=400)
        )


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


def at_stop(wear_depth: FloatArray, wall_thickness: float) -> FloatArray:
    """The wear depth where a limit ends the run [m]: never deeper than the wall.

    The stop is found to rounding, and wear-through leaves a wall of exactly 0.

    Parameters
    ----------
    wear_depth : ndarray, shape (N,)
        Wear depth on the path at the stop [m].
    wall_thickness : float
        Bushing wall thickness [m].
    """
    return np.minimum(wear_depth, wall_thickness)
