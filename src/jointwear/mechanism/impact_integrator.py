r"""Integration of a contact system through its contact events (``[dynamics]`` settings).

A contact system (:class:`ContactSystem`: the slider-crank or the free pin of
:mod:`jointwear.mechanism.impact_systems`, the four-bar of
:mod:`jointwear.mechanism.four_bar`) has a state ``y``, a right-hand side and a
signed gap between pin and bushing wall, positive while they overlap.

Integration
-----------
``scipy.integrate.solve_ivp`` (``dynamics.integrator``: LSODA by default,
Radau/BDF for stiff contact, RK45/DOP853 explicit) with terminal events at the
contact start (penetration rises through zero) and contact end (falls through
zero); the integration restarts at each event, so no step straddles the change of
force law, and the approach velocity ``delta'^-`` of the damping term is taken
at the contact start. A non-terminal event at ``delta' = 0`` records each
penetration maximum. ``dynamics.revolutions_settle`` revolutions are integrated
first so that the start-up transient decays; the next revolution is sampled
(dense output) at ``simulation.steps_per_revolution`` crank angles.

The events are watched by the solver after every step (:class:`_EventWatch`) and
their roots found on the step's dense output exactly as ``solve_ivp``'s own event
search finds them (Brent's method, ``xtol = rtol = 4 eps``), so the steps, events
and states are those of ``solve_ivp(..., events=...)`` to the bit, without its
per-step NumPy cost.
"""

from __future__ import annotations

import math
import time as _time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError, ConvergenceError
from jointwear.mechanism import force_laws
from jointwear.mechanism.force_laws import JointContact

if TYPE_CHECKING:
    from scipy.integrate import OdeSolution

    from jointwear.config import DynamicsConfig

__all__ = [
    "INTEGRATORS",
    "ContactHistory",
    "ContactImpactSettings",
    "ContactSystem",
    "ContactSystemBase",
    "SampledRevolution",
    "Segment",
    "integrate_contacts",
    "integrate_revolution",
]

FloatArray = NDArray[np.float64]

#: ``solve_ivp`` methods accepted by ``dynamics.integrator``
INTEGRATORS: tuple[str, ...] = ("LSODA", "Radau", "BDF", "RK45", "DOP853")


@dataclass(frozen=True)
class ContactImpactSettings:
    """Settings of the contact–impact model (the ``[dynamics]`` keys it uses).

    Parameters
    ----------
    force_law : str
        Normal force law, one of :data:`~jointwear.mechanism.force_laws.FORCE_LAWS`.
    restitution : float
        Coefficient of restitution ``c_e``, ``0 < c_e <= 1`` [-].
    friction_coefficient : float
        Coulomb coefficient ``mu >= 0`` [-].
    friction_velocity_tolerance : float
        ``v_0`` of the friction ramp: no friction below this slip speed [m/s].
    friction_velocity_full : float, optional
        ``v_1 > v_0``: full friction above this slip speed [m/s]; default ``2 v_0``.
    impact_velocity_floor : float
        Lower bound of the approach velocity ``delta'^-`` in the damping term
        (a contact that starts with a vanishing approach velocity would have
        unbounded damping) [m/s].
    integrator : str
        ``solve_ivp`` method, one of :data:`INTEGRATORS`.
    rtol : float
        Relative tolerance of the integrator [-].
    atol : float
        Absolute tolerance of the integrator, on every state component (SI) [-].
    revolutions_settle : int
        Revolutions integrated before the recorded one [-].
    max_step : float, optional
        Largest integrator step [s]; default one sampling step ``2 pi / (N omega)``.
    """

    force_law: str = "lankarani-nikravesh"
    restitution: float = 0.9
    friction_coefficient: float = 0.0
    friction_velocity_tolerance: float = 1e-4
    friction_velocity_full: float | None = None
    impact_velocity_floor: float = 1e-3
    integrator: str = "LSODA"
    rtol: float = 1e-8
    atol: float = 1e-10
    revolutions_settle: int = 2
    max_step: float | None = None

    def __post_init__(self) -> None:
        if self.force_law not in force_laws.FORCE_LAWS:
            raise ConfigError(
                f"dynamics.force_law: unknown force law {self.force_law!r}; choose from "
                + ", ".join(repr(name) for name in force_laws.FORCE_LAWS)
            )
        force_laws.hysteresis_factor(self.force_law, self.restitution)  # validates c_e
        if not (math.isfinite(self.friction_coefficient) and self.friction_coefficient >= 0):
            raise ConfigError(
                f"dynamics.friction_coefficient: must be >= 0, got {self.friction_coefficient!r}"
            )
        if not self.friction_velocity_tolerance > 0:
            raise ConfigError("dynamics.friction_velocity_tolerance: must be > 0")
        if (
            self.friction_velocity_full is not None
            and not self.friction_velocity_full > self.friction_velocity_tolerance
        ):
            raise ConfigError(
                "dynamics.friction_velocity_full: must be > dynamics.friction_velocity_tolerance"
            )
        if not self.impact_velocity_floor > 0:
            raise ConfigError("dynamics.impact_velocity_floor: must be > 0")
        if self.integrator not in INTEGRATORS:
            raise ConfigError(
                f"dynamics.integrator: {self.integrator!r} is not allowed; choose from "
                + ", ".join(repr(name) for name in INTEGRATORS)
            )
        if not 0 < self.rtol < 1 or not self.atol > 0:
            raise ConfigError("dynamics.rtol, dynamics.atol: need 0 < rtol < 1 and atol > 0")
        if self.revolutions_settle < 0:
            raise ConfigError("dynamics.revolutions_settle: must be >= 0")
        if self.max_step is not None and not self.max_step > 0:
            raise ConfigError("dynamics.max_step: must be > 0")

    @property
    def friction_full_speed(self) -> float:
        """``v_1`` of the friction ramp [m/s]."""
        if self.friction_velocity_full is not None:
            return self.friction_velocity_full
        return 2.0 * self.friction_velocity_tolerance

    @classmethod
    def from_config(cls, dynamics: DynamicsConfig) -> ContactImpactSettings:
        """Build from the validated ``[dynamics]`` section."""
        return cls(
            force_law=dynamics.force_law,
            restitution=dynamics.restitution,
            friction_coefficient=dynamics.friction_coefficient,
            friction_velocity_tolerance=dynamics.friction_velocity_tolerance,
            friction_velocity_full=dynamics.friction_velocity_full,
            impact_velocity_floor=dynamics.impact_velocity_floor,
            integrator=dynamics.integrator,
            rtol=dynamics.rtol,
            atol=dynamics.atol,
            revolutions_settle=dynamics.revolutions_settle,
            max_step=dynamics.max_step,
        )


# ------------------------------------------------------------------ systems


class ContactSystem(Protocol):
    """What :func:`integrate_contacts` needs from a mechanical system."""

    contact: JointContact

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """Time derivative of the state."""

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        """``(e_x, e_y, e'_x, e'_y)`` [m, m/s]."""

    def gap(self, t: float, y: FloatArray) -> float:
        """Signed penetration [m]: ``> 0`` in contact."""

    def gap_rate(self, t: float, y: FloatArray) -> float:
        """Rate of the gap [m/s]."""


class ContactSystemBase:
    """The gap functions of a contact system, from its clearance state.

    A system with ``contact`` and ``clearance_state`` inherits them; the integrator
    calls them at every step (contact events).
    """

    contact: JointContact

    def clearance_state(self, t: float, y: FloatArray) -> tuple[float, float, float, float]:
        """``(e_x, e_y, e'_x, e'_y)`` [m, m/s]."""
        raise NotImplementedError

    def gap(self, t: float, y: FloatArray) -> float:
        """Signed penetration of the state (:meth:`JointContact.gap`) [m]."""
        ex, ey, _, _ = self.clearance_state(t, y)
        return self.contact.gap(ex, ey)

    def gap_rate(self, t: float, y: FloatArray) -> float:
        """Rate of the gap of the state (:meth:`JointContact.gap_rate`) [m/s]."""
        return self.contact.gap_rate(*self.clearance_state(t, y))

    def gap_and_rate(self, t: float, y: FloatArray) -> tuple[float, float]:
        """:meth:`gap` and :meth:`gap_rate` together (one call per integrator step)."""
        return self.gap(t, y), self.gap_rate(t, y)

    def rhs(self, t: float, y: FloatArray, impact_velocity: float) -> FloatArray:
        """Time derivative of the state."""
        raise NotImplementedError

    def rhs_function(self, impact_velocity: float) -> Callable[[float, FloatArray], FloatArray]:
        """``f(t, y)`` of the integrator for a contact with approach velocity
        ``impact_velocity`` [m/s]."""
        return lambda t, y: self.rhs(t, y, impact_velocity)


# ------------------------------------------------------------------ integration


@dataclass(frozen=True)
class Segment:
    """One stretch of integration between two contact events.

    Attributes
    ----------
    start, end : float
        Time interval [s].
    solution : OdeSolution
        Dense output on ``[start, end]``.
    in_contact : bool
        Whether the pin penetrates the wall during the segment.
    impact_velocity : float
        ``delta'^-`` of the contact (``nan`` in free flight) [m/s].
    """

    start: float
    end: float
    solution: OdeSolution
    in_contact: bool
    impact_velocity: float


@dataclass
class ContactHistory:
    """Result of :func:`integrate_contacts`.

    Attributes
    ----------
    segments : list of Segment
        Integration segments in time order.
    impact_times, impact_velocities : list of float
        Contact starts [s] and their approach velocities ``delta'`` [m/s]
        (before the floor is applied).
    separation_times, separation_velocities : list of float
        Contact ends [s] and the normal velocity ``-delta'`` there [m/s].
    peak_times, peak_penetrations : list of float
        Local maxima of the penetration [s], [m].
    evaluations : int
        Right-hand-side evaluations.
    """

    segments: list[Segment] = field(default_factory=list)
    impact_times: list[float] = field(default_factory=list)
    impact_velocities: list[float] = field(default_factory=list)
    separation_times: list[float] = field(default_factory=list)
    separation_velocities: list[float] = field(default_factory=list)
    peak_times: list[float] = field(default_factory=list)
    peak_penetrations: list[float] = field(default_factory=list)
    evaluations: int = 0

    @property
    def end_time(self) -> float:
        """Time reached [s]."""
        return self.segments[-1].end if self.segments else math.nan

    @property
    def final_state(self) -> FloatArray:
        """State at :attr:`end_time`."""
        last = self.segments[-1]
        return np.asarray(last.solution(last.end), dtype=float)

    def locate(self, times: ArrayLike) -> NDArray[np.int64]:
        """Index of the segment holding each time."""
        starts = np.array([s.start for s in self.segments])
        index = np.searchsorted(starts, np.asarray(times, dtype=float), side="right") - 1
        return np.clip(index, 0, len(self.segments) - 1)

    def state(self, times: ArrayLike) -> tuple[FloatArray, NDArray[np.int64]]:
        """States at ``times`` (dense output) and the index of their segments.

        Returns
        -------
        states : ndarray, shape (M, n_state)
        segments : ndarray of int, shape (M,)
        """
        times = np.atleast_1d(np.asarray(times, dtype=float))
        index = self.locate(times)
        # a zero-length segment cannot interpolate: use the next one that starts there
        for k in np.unique(index):
            seg = self.segments[k]
            if seg.end <= seg.start and k + 1 < len(self.segments):
                index[index == k] = k + 1
        n_state = self.final_state.size
        states = np.empty((times.size, n_state))
        for k in np.unique(index):
            rows = index == k
            seg = self.segments[k]
            values = np.asarray(seg.solution(np.clip(times[rows], seg.start, seg.end)))
            states[rows] = values.reshape(n_state, -1).T
        return states, index

    def free_time(self, start: float, end: float) -> float:
        """Time without penetration inside ``[start, end]`` [s]."""
        total = 0.0
        for seg in self.segments:
            if not seg.in_contact:
                total += max(0.0, min(seg.end, end) - max(seg.start, start))
        return total


@dataclass(frozen=True)
class _Part:
    """One ``solve_ivp`` run of :func:`integrate_contacts`, up to its contact event."""

    end: float
    solution: Any
    evaluations: int
    peaks: list[tuple[float, FloatArray]]
    event: FloatArray | None
    failed: str | None


class _EventWatch:
    """The contact events, checked after every step of the solver (:class:`_Watched`).

    ``solve_ivp``'s own events cost ~10 us per step in NumPy (``find_active_events``
    on two-element arrays), more than a compiled right-hand side and its step
    together. Here the same test runs on two floats: a gap that rises through zero
    (contact start, terminal), falls through zero (contact end, terminal) or a gap
    rate that falls through zero (penetration maximum); a terminal crossing ends the
    solver after the step, and the roots are found afterwards on the step's dense
    output exactly as ``solve_ivp`` finds them. The steps, roots and states are
    those of ``solve_ivp(..., events=...)``, to the bit.
    """

    def __init__(
        self, system: Any, in_contact: bool, t0: float, y0: FloatArray, keep: list[float] | None
    ) -> None:
        self.gap, self.gap_rate = system.gap, system.gap_rate
        self.gap_and_rate = system.gap_and_rate
        self.in_contact = in_contact
        self.g = self.gap(t0, y0)
        self.rate = self.gap_rate(t0, y0) if in_contact else 0.0
        #: ``(t_old, t, dense output)`` of the steps with a penetration maximum
        self.peaks: list[tuple[float, float, Any]] = []
        self.terminal: tuple[float, float, Any] | None = None
        #: sorted times whose steps keep their dense output (None: ``solve_ivp`` keeps all)
        self.keep = keep
        self.next_kept = 0
        #: the kept steps, in time order
        self.kept: list[tuple[float, float, Any]] = []

    def check(self, solver: Any) -> None:
        t, y = solver.t, solver.y
        peak = False
        if self.in_contact:
            g, rate = self.gap_and_rate(t, y)
            peak = self.rate >= 0.0 and rate <= 0.0
            self.rate = rate
            crossed = self.g >= 0.0 and g <= 0.0
        else:
            g = self.gap(t, y)
            crossed = self.g <= 0.0 and g >= 0.0
        self.g = g
        kept = False
        if self.keep is not None:
            # a kept time on a step boundary keeps both steps: whichever OdeSolution picks
            keep, i, t_old = self.keep, self.next_kept, solver.t_old
            while i < len(keep) and keep[i] < t_old:
                i += 1
            self.next_kept = i
            kept = peak or crossed or solver.status == "finished"
            kept = kept or (i < len(keep) and keep[i] <= t)
        if peak or crossed or kept:
            step = (solver.t_old, t, solver.dense_output())
            if peak:
                self.peaks.append(step)
            if kept:
                self.kept.append(step)
            if crossed:
                self.terminal = step
                solver.status = "finished"

    def kept_solution(self, t0: float) -> tuple[list[float], list[Any]]:
        """Times and interpolants of the kept steps, an :class:`_Unkept` between runs."""
        from scipy.integrate import DenseOutput

        class _Unkept(DenseOutput):
            def _call_impl(self, t: Any) -> FloatArray:
                raise ValueError(
                    f"integrate_contacts: the states in [{self.t_old:.9g}, {self.t:.9g}] s "
                    "were not kept (the keep= times)"
                )

        ts, interpolants = [t0], []
        for start, end, dense in self.kept:
            if start != ts[-1]:
                interpolants.append(_Unkept(ts[-1], start))
                ts.append(start)
            interpolants.append(dense)
            ts.append(end)
        return ts, interpolants


class _Watched:
    """Mixin of a ``scipy.integrate`` solver class: :class:`_EventWatch` after each step."""

    watch: _EventWatch

    def step(self) -> str | None:
        message = super().step()  # type: ignore[misc]
        if self.status != "failed":  # type: ignore[attr-defined]
            self.watch.check(self)
        return message


def _root(function: Callable[[float, FloatArray], float], dense: Any, t0: float, t1: float):
    """Zero of ``function(t, dense(t))`` in the step ``[t0, t1]``, as ``solve_ivp`` finds it."""
    from scipy.optimize import brentq

    eps = float(np.finfo(float).eps)
    return brentq(lambda t_: function(t_, dense(t_)), t0, t1, xtol=4 * eps, rtol=4 * eps)


def _integrate_segment(
    system: Any,
    fun: Callable[[float, FloatArray], FloatArray],
    t: float,
    t_end: float,
    y: FloatArray,
    in_contact: bool,
    method: str,
    rtol: float,
    atol: float,
    max_step: float,
    keep: list[float] | None,
) -> _Part:
    """Integrate from ``t`` to the next contact event (or ``t_end``)."""
    import scipy.integrate  # lazy: keeps `jointwear` quick to start
    from scipy.integrate import OdeSolution

    base = getattr(scipy.integrate, method)
    watch = _EventWatch(system, in_contact, t, y, keep)
    solver = type(f"Watched{method}", (_Watched, base), {"watch": watch})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        sol = scipy.integrate.solve_ivp(
            fun, (t, t_end), y, method=solver, rtol=rtol, atol=atol, max_step=max_step,
            dense_output=keep is None,
        )  # fmt: skip
    evaluations = int(sol.nfev)
    if sol.status == -1:
        return _Part(t, None, evaluations, [], None, str(sol.message))
    roots = [(_root(watch.gap_rate, dense, t0, t1), dense) for t0, t1, dense in watch.peaks]
    if keep is None:
        ts, interpolants = list(sol.t), list(sol.sol.interpolants)
    else:
        ts, interpolants = watch.kept_solution(t)
    event = None
    if watch.terminal is not None:
        t0, t1, dense = watch.terminal
        t_stop = _root(watch.gap, dense, t0, t1)
        # solve_ivp keeps the maxima of the last step found before the contact event
        roots = [(r, d) for r, d in roots if d is not dense or r < t_stop]
        event = np.asarray(dense(t_stop), dtype=float)
        ts.pop()
        if len(ts) > 1 and ts[-1] == t_stop and keep is None:
            interpolants.pop()
        else:
            ts.append(t_stop)
    solution = OdeSolution(ts, interpolants, alt_segment=method in ("LSODA", "BDF"))
    peaks = [(float(r), np.asarray(d(r), dtype=float)) for r, d in roots]
    return _Part(float(ts[-1]), solution, evaluations, peaks, event, None)


def integrate_contacts(
    system: ContactSystem,
    t_span: tuple[float, float],
    y0: ArrayLike,
    *,
    in_contact: bool,
    impact_velocity: float = math.nan,
    method: str = "LSODA",
    rtol: float = 1e-8,
    atol: float = 1e-10,
    max_step: float = math.inf,
    max_events: int = 1_000_000,
    stop_after_separations: int | None = None,
    keep: ArrayLike | None = None,
) -> ContactHistory:
    """Integrate a contact system, restarting at every contact start and end.

    Parameters
    ----------
    system : ContactSystem
        :class:`SliderCrankContactSystem` or :class:`FreePinSystem`.
    t_span : tuple of float
        ``(t_0, t_end)`` [s].
    y0 : array_like
        Initial state.
    in_contact : bool
        Whether the pin penetrates the wall at ``t_0``.
    impact_velocity : float
        ``delta'^-`` of a contact already under way at ``t_0`` [m/s] (``nan``:
        the floor ``contact.impact_velocity_floor``).
    method : str
        ``solve_ivp`` method (:data:`INTEGRATORS`).
    rtol, atol : float
        Integrator tolerances.
    max_step : float
        Largest step [s].
    max_events : int
        Largest number of contact events before giving up.
    stop_after_separations : int, optional
        Stop at that many contact ends (e.g. 1 for a single impact).
    keep : array_like, optional
        The only times at which :meth:`ContactHistory.state` will be asked for states
        [s]: the dense output is kept just for the steps holding them, the penetration
        maxima and each segment's last step (a step's dense output costs about as much
        as the step). Default: every step's.

    Returns
    -------
    ContactHistory

    Raises
    ------
    ConvergenceError
        If the integrator fails, or contact events pile up at one instant
        (chattering) or exceed ``max_events``.
    """
    if method not in INTEGRATORS:
        raise ConfigError(f"dynamics.integrator: {method!r} is not one of {INTEGRATORS}")
    contact = system.contact
    floor = contact.impact_velocity_floor
    t, t_end = float(t_span[0]), float(t_span[1])
    y = np.asarray(y0, dtype=float).copy()
    v_imp = floor if not math.isfinite(impact_velocity) else max(impact_velocity, floor)
    history = ContactHistory()

    gap_rate = system.gap_rate
    kept = None if keep is None else sorted(float(v) for v in np.ravel(keep))
    stalled = 0
    events = 0
    while t < t_end:
        velocity = v_imp
        fun = system.rhs_function(velocity)
        part = _integrate_segment(
            system, fun, t, t_end, y, in_contact, method, rtol, atol, max_step, kept
        )
        history.evaluations += part.evaluations
        if part.failed is not None:
            raise ConvergenceError(
                f"dynamics.integrator: {method} failed at t = {t:.6g} s "
                f"({part.failed}); try dynamics.integrator = 'Radau' or looser "
                f"dynamics.rtol/atol"
            )
        history.segments.append(
            Segment(t, part.end, part.solution, in_contact, velocity if in_contact else math.nan)
        )
        for t_peak, y_peak in part.peaks:
            history.peak_times.append(t_peak)
            history.peak_penetrations.append(system.gap(t_peak, y_peak))
        if part.event is None:
            break
        t_event, y = part.end, part.event
        events += 1
        stalled = stalled + 1 if t_event - t <= 1e-14 * max(1.0, abs(t)) else 0
        if stalled > 100:
            raise ConvergenceError(
                f"dynamics: contact events pile up at t = {t_event:.9g} s (grazing contact or "
                f"chattering); loosen dynamics.rtol or raise dynamics.impact_velocity_floor"
            )
        if events > max_events:
            raise ConvergenceError(
                f"dynamics: more than {max_events} contact events before t = {t_event:.9g} s"
            )
        rate = gap_rate(t_event, y)
        if in_contact:
            history.separation_times.append(t_event)
            history.separation_velocities.append(-rate)
            if (
                stop_after_separations is not None
                and len(history.separation_times) >= stop_after_separations
            ):
                break
        else:
            history.impact_times.append(t_event)
            history.impact_velocities.append(rate)
            v_imp = max(rate, floor)
        in_contact = not in_contact
        t = t_event
    return history


# ------------------------------------------------------------------ sampling


@dataclass(frozen=True, eq=False)
class SampledRevolution:
    """A contact system integrated through the settling revolutions, one sampled.

    Attributes
    ----------
    history : ContactHistory
        Full integration record.
    times : ndarray, shape (N + 1,)
        Sample times of the recorded revolution and its end [s].
    states : ndarray, shape (N + 1, n_state)
        States at ``times``.
    records : list of dict
        ``system.evaluate`` at the first ``N`` samples.
    step_lost : ndarray of bool, shape (N,)
        Steps with free flight inside them.
    impacts : int
        Contact starts in the recorded revolution [-].
    free_flight_fraction : float
        Share of the recorded revolution without penetration [-].
    max_penetration : float
        Largest penetration in the recorded revolution [m].
    peak_load : float
        Largest normal contact force, samples and penetration maxima [N].
    record_start : float
        Start of the recorded revolution [s].
    runtime : float
        Wall-clock time of the integration [s].
    """

    history: ContactHistory
    times: FloatArray
    states: FloatArray
    records: list[dict[str, Any]]
    step_lost: NDArray[np.bool_]
    impacts: int
    free_flight_fraction: float
    max_penetration: float
    peak_load: float
    record_start: float
    runtime: float

    def column(self, key: str) -> FloatArray:
        """One ``evaluate`` output over the ``N`` samples."""
        return np.array([r[key] for r in self.records])


def integrate_revolution(
    system: Any,
    y0: ArrayLike,
    settings: ContactImpactSettings,
    steps: int,
    in_contact: bool = True,
    dense: bool = True,
) -> SampledRevolution:
    """Integrate a crank-driven contact system and sample its last revolution.

    Parameters
    ----------
    system : ContactSystem
        A system with ``omega`` (crank speed [rad/s]) and ``evaluate(t, y,
        impact_velocity)`` returning ``normal_force`` and ``penetration`` (e.g.
        :class:`SliderCrankContactSystem`).
    y0 : array_like
        State at ``t = 0`` (crank angle 0).
    settings : ContactImpactSettings
        Integrator settings and ``revolutions_settle``.
    steps : int
        Samples ``N`` per revolution [-].
    in_contact : bool
        Whether the pin penetrates the wall at ``t = 0``.
    dense : bool
        Keep the dense output of every step in the history. ``False``: only of the
        steps holding a sample, a penetration maximum or a segment's end (``keep=``
        of :func:`integrate_contacts`: a third less time, the same samples to the
        bit); the history's :meth:`~ContactHistory.state` then answers at those
        times only.

    Returns
    -------
    SampledRevolution
    """
    omega = system.omega
    period = 2.0 * math.pi / omega
    record_start = settings.revolutions_settle * period
    max_step = settings.max_step if settings.max_step is not None else period / steps
    # samples of the recorded revolution, plus its end (for the last increment)
    phi = 2.0 * np.pi * np.arange(steps) / steps
    times = record_start + np.append(phi, 2.0 * np.pi) / omega
    started = _time.perf_counter()
    history = integrate_contacts(
        system,
        (0.0, record_start + period),
        y0,
        in_contact=in_contact,
        method=settings.integrator,
        rtol=settings.rtol,
        atol=settings.atol,
        max_step=max_step,
        keep=None if dense else times,
    )
    runtime = _time.perf_counter() - started
    states, index = history.state(times)
    records = [
        system.evaluate(float(t), y, history.segments[k].impact_velocity)
        for t, y, k in zip(times[:-1], states[:-1], index[:-1], strict=True)
    ]
    record_end = record_start + period
    free = history.free_time(record_start, record_end)
    impacts = int(
        np.sum(
            (np.array(history.impact_times) >= record_start)
            & (np.array(history.impact_times) < record_end)
        )
    )
    # free flight inside each sampling step
    step_lost = np.zeros(steps, dtype=bool)
    width = period / steps
    for seg in history.segments:
        if seg.in_contact or seg.end <= record_start or seg.start >= record_end:
            continue
        first = max(math.floor((seg.start - record_start) / width), 0)
        last = min(math.ceil((seg.end - record_start) / width), steps)
        step_lost[first:last] = True
    peak_times = [t for t in history.peak_times if record_start <= t <= record_end]
    peaks = [
        p
        for t, p in zip(history.peak_times, history.peak_penetrations, strict=True)
        if record_start <= t <= record_end
    ]
    sampled = np.array([r["penetration"] for r in records])
    max_penetration = float(max([*peaks, float(sampled.max())]))
    # the largest contact force: impacts peak between samples, near the penetration maxima
    peak_load = float(normal_max := np.max([r["normal_force"] for r in records]))
    if peak_times:
        peak_states, peak_index = history.state(peak_times)
        peak_load = max(
            normal_max,
            *(
                system.evaluate(t, y, history.segments[k].impact_velocity)["normal_force"]
                for t, y, k in zip(peak_times, peak_states, peak_index, strict=True)
            ),
        )
    return SampledRevolution(
        history=history,
        times=times,
        states=states,
        records=records,
        step_lost=step_lost,
        impacts=impacts,
        free_flight_fraction=free / period,
        max_penetration=max_penetration,
        peak_load=float(peak_load),
        record_start=record_start,
        runtime=runtime,
    )
