"""The load cycle: the one object between the mechanism and the wear model.

Every mechanism type (``mechanism.type``) and dynamics model hands the rest of the
pipeline a :class:`LoadCycle`: per time step of one period of the joint's motion,
the time, the magnitude of the force between pin and bushing, its direction in the
bushing's frame and the increment of the relative rotation pin - bushing (from
which :mod:`jointwear.tribology.sliding` computes the sliding distance of the Archard
step, at a radius it states). Nothing downstream of stage 1
knows which mechanism produced it; mechanism-specific series (crank torque,
slider position, ...) travel beside it as :attr:`LoadCycle.diagnostics`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.geometry.angles import wrap_angle

__all__ = ["Diagnostic", "DutyModes", "LoadCycle", "bushing_azimuth", "crank_extras"]

FloatArray = NDArray[np.float64]


def bushing_azimuth(
    force_x: ArrayLike, force_y: ArrayLike, bushing_angle: ArrayLike | float = 0.0
) -> FloatArray:
    """Direction of the force on the bushing, in the bushing's frame [rad].

    Unwrapped (continuous from step to step) and shifted by whole turns so that its
    mean lies in (-pi, pi].

    Parameters
    ----------
    force_x, force_y : array_like
        Global components of the force the pin exerts on the bushing [N].
    bushing_angle : array_like or float
        Angle of the bushing body's x axis from the global x axis [rad].

    Returns
    -------
    ndarray
        Azimuth of the force, counter-clockwise from the bushing's x axis [rad].
    """
    azimuth = np.unwrap(
        np.arctan2(np.asarray(force_y, dtype=float), np.asarray(force_x, dtype=float))
        - np.asarray(bushing_angle, dtype=float)
    )
    mean = float(azimuth.mean())
    return azimuth + (wrap_angle(mean) - mean)


def crank_extras(
    crank_speed: float, crank_torque: ArrayLike, lost_steps: ArrayLike
) -> dict[str, Any]:
    """Summary scalars of a mechanism driven by a crank at constant speed.

    Parameters
    ----------
    crank_speed : float
        Crank angular velocity [rad/s].
    crank_torque : array_like, shape (N,)
        Driving torque at each step [N m].
    lost_steps : array_like of bool, shape (N,)
        Steps where the continuous-contact assumption fails.
    """
    torque = np.asarray(crank_torque, dtype=float)
    lost = np.asarray(lost_steps, dtype=bool)
    return {
        "crank_speed_rad_s": float(crank_speed),
        "crank_speed_rpm": float(crank_speed) * 60.0 / (2.0 * math.pi),
        # the crank angle of step k is 2 pi k / N (rounded so that it prints as 15.0)
        "contact_lost_crank_angles_deg": [
            float(a) for a in np.round(360.0 * np.flatnonzero(lost) / lost.size, 9)
        ],
        "crank_torque_rms_nm": float(np.sqrt(np.mean(torque**2))),
        "crank_torque_max_abs_nm": float(np.max(np.abs(torque))),
    }


@dataclass(frozen=True, eq=False)
class Diagnostic:
    """A mechanism-specific per-step series that travels beside the cycle.

    Attributes
    ----------
    values : ndarray, shape (N,)
        One value per step, SI [units].
    units : str
        Unit of ``values`` (UDUNITS spelling, e.g. ``"N m"``).
    long_name : str
        What the series is.
    """

    values: FloatArray
    units: str
    long_name: str


@dataclass(frozen=True)
class DutyModes:
    """The operating modes of a duty cycle, laid one after the other in one load cycle.

    Mode ``i`` runs in a fraction ``shares[i]`` of the cycles; its steps are
    ``starts[i]`` to ``starts[i + 1] - 1`` of the cycle, its own period ``periods[i]``.
    The wear of a cycle is the share-weighted sum of the modes' wear: each step's
    sliding distance is weighted by its mode's share (:meth:`LoadCycle.parts`).

    Attributes
    ----------
    names : tuple of str
        Name of each mode (its ``mechanism.type`` and index, ``"1:oscillating"``).
    shares : tuple of float
        Fraction of the cycles in which each mode runs [-]; they sum to one.
    starts : tuple of int
        First step of each mode in the cycle [-].
    periods : tuple of float
        Duration of each mode's own cycle [s].
    """

    names: tuple[str, ...]
    shares: tuple[float, ...]
    starts: tuple[int, ...]
    periods: tuple[float, ...]

    @property
    def mean_period(self) -> float:
        """Mean duration of a cycle, ``sum_i share_i T_i`` [s]."""
        return float(sum(s * t for s, t in zip(self.shares, self.periods, strict=True)))


@dataclass(frozen=True, eq=False)
class LoadCycle:
    """Load on a clearance joint over one period of its motion.

    Step ``k`` (``k = 0, 1, ..., N-1``) starts at ``time[k]`` and ends at ``time[k+1]``
    (``period`` for the last step). Forces and directions are sampled at the start
    of the step; ``relative_rotation`` is the increment over the step. Steps need
    not be equally long.

    Attributes
    ----------
    time : ndarray, shape (N,)
        Start of each step, ``time[0] = 0`` [s].
    load : ndarray, shape (N,)
        Magnitude of the force between pin and bushing [N]; never negative.
    azimuth : ndarray, shape (N,)
        Direction in which the pin presses on the bushing, counter-clockwise from
        the x axis of the body that carries the bushing [rad]. Unwrapped and shifted
        by whole turns so that its mean lies in (-pi, pi].
    relative_rotation : ndarray, shape (N,)
        Signed increment of ``phi_pin - phi_bushing`` over each step [rad]; a surface
        at radius ``R`` slides ``R |relative_rotation|`` over the step
        (:mod:`jointwear.tribology.sliding`).
    period : float
        Duration of one cycle [s].
    mechanism : str
        Mechanism type that produced the cycle (``mechanism.type``).
    model : str
        Dynamics model (``"massless-link"``, ``"contact-impact"``, ``"prescribed"``).
    joint : str
        Name of the clearance joint within the mechanism.
    lost_steps : ndarray of bool, shape (N,)
        Steps where the model's continuous-contact assumption fails.
    iterations : int
        Fixed-point iterations of the dynamics model (0 if none).
    converged : bool
        False if the dynamics model reports a one-pass fallback.
    diagnostics : mapping of str to Diagnostic
        Mechanism-specific per-step series (crank torque, slider position, ...).
    extras : mapping of str to scalar
        Mechanism-specific scalars for the ``dynamics`` summary (units in the keys).
    duty : DutyModes, optional
        The modes of a duty cycle laid one after the other (``None``: one mode).
    """

    time: FloatArray
    load: FloatArray
    azimuth: FloatArray
    relative_rotation: FloatArray
    period: float
    mechanism: str = "load-history"
    model: str = "prescribed"
    joint: str = "joint"
    lost_steps: NDArray[np.bool_] | None = None
    iterations: int = 0
    converged: bool = True
    diagnostics: Mapping[str, Diagnostic] = field(default_factory=dict)
    extras: Mapping[str, Any] = field(default_factory=dict)
    duty: DutyModes | None = None

    def __post_init__(self) -> None:
        from jointwear.errors import DataError

        arrays = {}
        for name in ("time", "load", "azimuth", "relative_rotation"):
            value = np.asarray(getattr(self, name), dtype=float).ravel()
            arrays[name] = value
            object.__setattr__(self, name, value)
        steps = arrays["load"].size
        if steps < 2 or any(v.size != steps for v in arrays.values()):
            raise DataError(
                "load cycle: time, load, azimuth and relative_rotation need one value per "
                "step (at least 2 steps)"
            )
        if not all(np.all(np.isfinite(v)) for v in arrays.values()):
            raise DataError("load cycle: values must be finite")
        if np.any(arrays["load"] < 0):
            raise DataError("load cycle: load magnitudes must be >= 0")
        period = float(self.period)
        ends = np.append(arrays["time"], period)
        if not (math.isfinite(period) and np.all(np.diff(ends) > 0)):
            raise DataError("load cycle: times must increase and end before the period")
        object.__setattr__(self, "period", period)
        lost = np.zeros(steps, bool) if self.lost_steps is None else self.lost_steps
        object.__setattr__(self, "lost_steps", np.asarray(lost, dtype=bool).ravel())
        object.__setattr__(self, "diagnostics", MappingProxyType(dict(self.diagnostics)))
        object.__setattr__(self, "extras", MappingProxyType(dict(self.extras)))

    # ------------------------------------------------------------ construction
    @classmethod
    def from_arrays(
        cls,
        load: ArrayLike,
        azimuth: ArrayLike,
        relative_rotation: ArrayLike,
        period: float = 1.0,
        time: ArrayLike | None = None,
        **kwargs: Any,
    ) -> LoadCycle:
        """A load cycle from arrays, e.g. exported by another multibody code.

        Parameters
        ----------
        load : array_like, shape (N,)
            Load magnitude at each step [N].
        azimuth : array_like, shape (N,)
            Direction in which the pin presses on the bushing, bushing frame [rad].
        relative_rotation : array_like, shape (N,)
            Rotation of the pin relative to the bushing over each step [rad].
        period : float
            Duration of the cycle [s].
        time : array_like, shape (N,), optional
            Start of each step [s]; default equally spaced over the period.
        **kwargs
            Further :class:`LoadCycle` fields (``mechanism``, ``joint``, ...).
        """
        load = np.asarray(load, dtype=float).ravel()
        if time is None:
            time = period * np.arange(load.size) / max(load.size, 1)
        azimuth = np.asarray(azimuth, dtype=float).ravel()
        if azimuth.size == load.size and np.all(np.isfinite(azimuth)):
            azimuth = np.unwrap(azimuth)
            azimuth = azimuth + (wrap_angle(azimuth.mean()) - azimuth.mean())
        return cls(
            time=time,
            load=load,
            azimuth=azimuth,
            relative_rotation=relative_rotation,
            period=period,
            **kwargs,
        )

    def with_load(self, load: ArrayLike) -> LoadCycle:
        """The same cycle with another load magnitude per step [N]."""
        return replace(self, load=np.asarray(load, dtype=float))

    # ------------------------------------------------------------ derived
    def parts(self) -> list[tuple[float, LoadCycle]]:
        """The cycle's modes: ``(share [-], that mode's own load cycle)`` each.

        A cycle of one mode is ``[(1.0, self)]``. A per-step quantity of a duty cycle
        (a sliding distance) is computed on each mode's own cycle (a change of the load
        azimuth closes over the mode's period, not into the next mode) and weighted by
        the mode's share.
        """
        duty = self.duty
        if duty is None:
            return [(1.0, self)]
        ends = (*duty.starts[1:], self.steps)
        return [
            (share, self._mode(start, end, period))
            for share, start, end, period in zip(
                duty.shares, duty.starts, ends, duty.periods, strict=True
            )
        ]

    def _mode(self, start: int, end: int, period: float) -> LoadCycle:
        """Steps ``start`` to ``end - 1`` as a cycle of their own, of ``period`` [s]."""
        part = slice(start, end)
        return LoadCycle(
            time=self.time[part] - self.time[start],
            load=self.load[part],
            azimuth=self.azimuth[part],
            relative_rotation=self.relative_rotation[part],
            period=period,
            mechanism=self.mechanism,
            model=self.model,
            joint=self.joint,
            lost_steps=self.lost_steps[part],
        )

    @property
    def step_share(self) -> FloatArray:
        """Fraction of the cycles in which each step runs [-] (ones for one mode)."""
        if self.duty is None:
            return np.ones(self.steps)
        return np.concatenate([np.full(part.steps, share) for share, part in self.parts()])

    @property
    def steps(self) -> int:
        """Number of steps ``N`` per cycle."""
        return int(self.load.size)

    @property
    def step_duration(self) -> FloatArray:
        """Duration of each step [s]."""
        return np.diff(np.append(self.time, self.period))

    @property
    def phase(self) -> FloatArray:
        """Phase ``2 pi t / period`` at the start of each step [rad] (crank angle of a crank)."""
        return 2.0 * np.pi * self.time / self.period

    @property
    def frequency(self) -> float:
        """Cycles per second [Hz]."""
        return 1.0 / self.period

    @property
    def contact_lost(self) -> bool:
        """True if the continuous-contact assumption fails at some step."""
        return bool(np.any(self.lost_steps))

    @property
    def force_x(self) -> FloatArray:
        """Force of the pin on the bushing along the bushing's x axis [N]."""
        return self.load * np.cos(self.azimuth)

    @property
    def force_y(self) -> FloatArray:
        """Force of the pin on the bushing along the bushing's y axis [N]."""
        return self.load * np.sin(self.azimuth)

    @property
    def rotation(self) -> FloatArray:
        """Cumulative relative rotation at the start of each step and at the end [rad]."""
        return np.concatenate(([0.0], np.cumsum(self.relative_rotation)))

    @property
    def total_relative_rotation(self) -> float:
        """Sum of the absolute relative-rotation increments over the cycle [rad] (of a
        duty cycle: weighted by the modes' shares, the mean over its cycles)."""
        if self.duty is not None:
            return float(np.sum(np.abs(self.relative_rotation) * self.step_share))
        return float(np.sum(np.abs(self.relative_rotation)))

    @property
    def mean_load(self) -> float:
        """Time mean of the load magnitude [N] (of a duty cycle: over its modes' time)."""
        if self.duty is not None:
            parts = self.parts()
            time = sum(share * part.period for share, part in parts)
            return sum(share * part.period * part.mean_load for share, part in parts) / time
        duration = self.step_duration
        if np.ptp(duration) <= 1e-12 * duration.mean():
            return float(np.mean(self.load))
        return float(np.dot(self.load, duration) / self.period)

    @property
    def sliding_mean_load(self) -> float:
        """Sliding-weighted mean load ``sum F |d phi| / sum |d phi|`` [N].

        Archard wear over a cycle is proportional to ``sum F ds``, so this is the
        load that, applied over the total sliding distance, wears as much. Falls
        back to the time mean if pin and bushing do not rotate relatively.
        """
        weight = np.abs(self.relative_rotation) * self.step_share
        total = weight.sum()
        if total == 0.0:
            return self.mean_load
        return float(np.sum(self.load * weight) / total)

    # ------------------------------------------------------------ reporting
    def summary(self) -> dict[str, Any]:
        """Scalar results (SI, units in the keys), keyed as ``jointwear dynamics --json``."""
        azimuth_deg = np.degrees(self.azimuth)
        lost_phase = np.round(np.degrees(self.phase[self.lost_steps]), 9)
        out: dict[str, Any] = {
            "mechanism": self.mechanism,
            "dynamics_model": self.model,
            "joint": self.joint,
            "steps": self.steps,
            "period_s": self.period,
            "load_min_n": float(self.load.min()),
            "load_max_n": float(self.load.max()),
            "load_mean_n": self.mean_load,
            "load_sliding_mean_n": self.sliding_mean_load,
            "azimuth_min_deg": float(azimuth_deg.min()),
            "azimuth_max_deg": float(azimuth_deg.max()),
            "azimuth_range_deg": float(azimuth_deg.max() - azimuth_deg.min()),
            "total_relative_rotation_rad": self.total_relative_rotation,
            "contact_lost": self.contact_lost,
            # rounded so that 2 pi k / N prints as 15.0, not 14.999999999999998
            "contact_lost_phases_deg": [float(a) for a in lost_phase],
            "iterations": int(self.iterations),
            "fixed_point_converged": bool(self.converged),
        }
        out.update(self.extras)
        return out

    def columns(self) -> dict[str, FloatArray]:
        """Per-step arrays keyed by unit-bearing headers, one closing row appended.

        The first four columns are the ``load-history`` file format (force of the pin
        on the bushing in the bushing frame, cumulative relative rotation), so the
        table reads back as the same cycle; the closing row (time = period) repeats
        the first row's forces and carries the rotation at the end of the cycle.
        """

        def closed(values: FloatArray) -> FloatArray:
            return np.append(values, values[0])

        cols = {
            "time [s]": np.append(self.time, self.period),
            "force_x [N]": closed(self.force_x),
            "force_y [N]": closed(self.force_y),
            "rotation [rad]": self.rotation,
            "phase [deg]": np.append(np.round(np.degrees(self.phase), 9), 360.0),
            "load [N]": closed(self.load),
            "azimuth [deg]": closed(np.degrees(self.azimuth)),
            "relative_rotation [rad]": closed(self.relative_rotation),
        }
        for name, diagnostic in self.diagnostics.items():
            cols[f"{name} [{diagnostic.units}]"] = closed(diagnostic.values)
        return cols

    def __repr__(self) -> str:
        return (
            f"LoadCycle(mechanism={self.mechanism!r}, model={self.model!r}, "
            f"joint={self.joint!r}, steps={self.steps}, period={self.period:.6g} s, "
            f"load={self.load.min():.4g}..{self.load.max():.4g} N, "
            f"rotation={self.total_relative_rotation:.4g} rad)"
        )
