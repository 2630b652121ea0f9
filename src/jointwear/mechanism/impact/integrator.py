r"""Integration of a contact system through its contact events.

A contact system (:class:`ContactSystem`: the slider-crank's
:class:`~jointwear.mechanism.slider_crank.contact_impact.SliderCrankContactSystem`, the
four-bar's :class:`~jointwear.mechanism.four_bar.contact_impact.FourBarContactSystem`,
the free pin of :mod:`jointwear.mechanism.impact.free_pin`) has a state ``y``, a
right-hand side and a signed gap between pin and bushing wall, positive while they
overlap.

``scipy.integrate.solve_ivp`` (``dynamics.integrator``: LSODA by default,
Radau/BDF for stiff contact, RK45/DOP853 explicit) with terminal events at the
contact start (penetration rises through zero) and contact end (falls through
zero); the integration restarts at each event, so no step straddles the change of
force law, and the approach velocity ``delta'^-`` of the damping term is taken
at the contact start. A non-terminal event at ``delta' = 0`` records each
penetration maximum. (:mod:`jointwear.mechanism.impact.revolution` integrates the
settling revolutions and samples the next one.)

The events are watched by the solver after every step (:class:`_EventWatch`) and
their roots found on the step's dense output exactly as ``solve_ivp``'s own event
search finds them (Brent's method, ``xtol = rtol = 4 eps``), so the steps, events
and states are those of ``solve_ivp(..., events=...)`` to the bit, without its
per-step NumPy cost.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError, ConvergenceError
from jointwear.mechanism.impact.settings import AUTO_INTEGRATOR, FALLBACK_INTEGRATOR, INTEGRATORS

if TYPE_CHECKING:
    from scipy.integrate import OdeSolution

    from jointwear.mechanism.impact.joint_contact import JointContact

__all__ = [
    "ContactHistory",
    "ContactSystem",
    "ContactSystemBase",
    "Segment",
    "integrate_contacts",
]

FloatArray = NDArray[np.float64]


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

    def gap_and_rate(self, t: float, y: FloatArray) -> tuple[float, float]:
        """:meth:`gap` and :meth:`gap_rate` together."""

    def rhs_function(self, impact_velocity: float) -> Callable[[float, FloatArray], FloatArray]:
        """``f(t, y)`` of the integrator for a contact with approach velocity [m/s]."""


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
    try:
        return brentq(lambda t_: function(t_, dense(t_)), t0, t1, xtol=4 * eps, rtol=4 * eps)
    except ValueError:
        # the step started on the zero (a state at rest on the wall): the dense output
        # rounds its start to the far side, so there is no sign change to bracket
        return t0


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

    # the compiled Dormand-Prince integrator runs as RK45 where it cannot run compiled
    base = getattr(scipy.integrate, method.removesuffix("-compiled"))
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


def _append_part(
    history: ContactHistory,
    system: ContactSystem,
    part: _Part,
    start: float,
    in_contact: bool,
    impact_velocity: float,
    method: str,
) -> None:
    """Add one integrated segment, its right-hand-side count and its penetration maxima."""
    history.evaluations += part.evaluations
    if part.failed is not None:
        raise ConvergenceError(
            f"dynamics.integrator: {method} failed at t = {start:.6g} s "
            f"({part.failed}); try dynamics.integrator = 'Radau' or looser "
            f"dynamics.rtol/atol"
        )
    history.segments.append(
        Segment(
            start, part.end, part.solution, in_contact,
            impact_velocity if in_contact else math.nan,
        )
    )  # fmt: skip
    for t_peak, y_peak in part.peaks:
        history.peak_times.append(t_peak)
        history.peak_penetrations.append(system.gap(t_peak, y_peak))


class _EventCount:
    """Contact events so far; refuses chattering (events piling up at one instant)."""

    def __init__(self, max_events: int) -> None:
        self.max_events = max_events
        self.events = 0
        self.stalled = 0

    def count(self, start: float, t_event: float) -> None:
        """Count the event at ``t_event`` that ends a segment begun at ``start`` [s]."""
        self.events += 1
        stalled = t_event - start <= 1e-14 * max(1.0, abs(start))
        self.stalled = self.stalled + 1 if stalled else 0
        if self.stalled > 100:
            raise ConvergenceError(
                f"dynamics: contact events pile up at t = {t_event:.9g} s (grazing contact or "
                f"chattering); loosen dynamics.rtol or raise dynamics.impact_velocity_floor"
            )
        if self.events > self.max_events:
            raise ConvergenceError(
                f"dynamics: more than {self.max_events} contact events before t = {t_event:.9g} s"
            )


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
        E.g. :class:`~jointwear.mechanism.slider_crank.contact_impact.SliderCrankContactSystem`
        or :class:`~jointwear.mechanism.impact.free_pin.FreePinSystem`.
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
    if method == AUTO_INTEGRATOR:  # no compiled integration on this path
        method = FALLBACK_INTEGRATOR
    floor = system.contact.impact_velocity_floor
    t, t_end = float(t_span[0]), float(t_span[1])
    y = np.asarray(y0, dtype=float).copy()
    v_imp = floor if not math.isfinite(impact_velocity) else max(impact_velocity, floor)
    history = ContactHistory()
    kept = None if keep is None else sorted(float(v) for v in np.ravel(keep))
    events = _EventCount(max_events)
    while t < t_end:
        fun = system.rhs_function(v_imp)
        part = _integrate_segment(
            system, fun, t, t_end, y, in_contact, method, rtol, atol, max_step, kept
        )
        _append_part(history, system, part, t, in_contact, v_imp, method)
        if part.event is None:
            break
        t_event, y = part.end, part.event
        events.count(t, t_event)
        rate = system.gap_rate(t_event, y)
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
