"""One settled, sampled revolution of a crank-driven contact system, and its solution.

:func:`integrate_revolution` integrates a contact system (the slider-crank's, the
four-bar's) through ``dynamics.revolutions_settle`` revolutions, so that the start-up
transient decays, and samples the next one at ``simulation.steps_per_revolution``
crank angles; :func:`sampled_solution` turns the samples and the mechanism's load
cycle into a :class:`ContactImpactSolution`, compared with the massless-link load.
"""

from __future__ import annotations

import math
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ContactLossWarning, JointwearError
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.impact.integrator import ContactHistory, integrate_contacts
from jointwear.mechanism.impact.settings import COMPILED_INTEGRATORS, ContactImpactSettings

__all__ = [
    "ContactImpactSolution",
    "SampledRevolution",
    "integrate_revolution",
    "sampled_solution",
]

FloatArray = NDArray[np.float64]


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
    peak_joint_force : float
        Largest joint force ``|J|`` (contact, friction and film), samples and
        penetration maxima [N].
    max_offset : float
        Largest pin-centre offset ``|e|``, samples and penetration maxima [m].
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
    peak_joint_force: float = math.nan
    max_offset: float = math.nan

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
        :class:`~jointwear.mechanism.slider_crank.contact_impact.SliderCrankContactSystem`).
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
        steps holding a sample, a penetration maximum or a segment's end (``keep=`` of
        :func:`~jointwear.mechanism.impact.integrator.integrate_contacts`: a third less
        time, the same samples to the bit); the history's
        :meth:`~jointwear.mechanism.impact.integrator.ContactHistory.state` then answers
        at those times only.

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
    started = time.perf_counter()
    span = (0.0, record_start + period)
    tolerances, separated = (settings.rtol, settings.atol), settings.separated_tolerances
    solved = None
    if separated != tolerances and in_contact:
        # until the pin leaves the wall the run's tolerances; where it does, all again
        solved = _integrate(system, span, y0, in_contact, settings, max_step, times, dense,
                            tolerances, stop_on_separation=True)  # fmt: skip
    if solved is None:
        solved = _integrate(system, span, y0, in_contact, settings, max_step, times, dense,
                            separated, stop_on_separation=False)  # fmt: skip
    history, states, index = solved
    runtime = time.perf_counter() - started
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
    peaks = _peaks(system, history, records, record_start, record_end)
    return SampledRevolution(
        history=history,
        times=times,
        states=states,
        records=records,
        step_lost=_free_flight_steps(history, record_start, period, steps),
        impacts=impacts,
        free_flight_fraction=free / period,
        max_penetration=peaks[0],
        peak_load=peaks[1],
        record_start=record_start,
        runtime=runtime,
        peak_joint_force=peaks[2],
        max_offset=peaks[3],
    )


def _integrate(
    system: Any,
    span: tuple[float, float],
    y0: ArrayLike,
    in_contact: bool,
    settings: ContactImpactSettings,
    max_step: float,
    times: FloatArray,
    dense: bool,
    tolerances: tuple[float, float],
    stop_on_separation: bool,
) -> tuple[ContactHistory, FloatArray, NDArray[np.int64]] | None:
    """The integration at ``tolerances``: history, states at ``times`` and their segments
    (``None``: the pin left the wall and ``stop_on_separation`` was asked)."""
    method = settings.integrator_for(system)
    if method in COMPILED_INTEGRATORS:
        # the whole integration in one compiled function (the slider-crank's)
        return system.integrate_compiled(
            span, y0, in_contact, settings, max_step, times, tolerances, stop_on_separation,
            method=method,
        )  # fmt: skip
    history = integrate_contacts(
        system,
        span,
        y0,
        in_contact=in_contact,
        method=method,
        rtol=tolerances[0],
        atol=tolerances[1],
        max_step=max_step,
        keep=None if dense else times,
        stop_after_separations=1 if stop_on_separation else None,
    )
    if stop_on_separation and history.separation_times:
        return None
    states, index = history.state(times)
    return history, states, index


def _free_flight_steps(
    history: ContactHistory, record_start: float, period: float, steps: int
) -> NDArray[np.bool_]:
    """Sampling steps of the recorded revolution with free flight inside them."""
    record_end = record_start + period
    step_lost = np.zeros(steps, dtype=bool)
    width = period / steps
    for seg in history.segments:
        if seg.in_contact or seg.end <= record_start or seg.start >= record_end:
            continue
        first = max(math.floor((seg.start - record_start) / width), 0)
        last = min(math.ceil((seg.end - record_start) / width), steps)
        step_lost[first:last] = True
    return step_lost


def _peaks(
    system: Any,
    history: ContactHistory,
    records: list[dict[str, Any]],
    record_start: float,
    record_end: float,
) -> tuple[float, float, float, float]:
    """Largest penetration [m], normal force [N], joint force ``|J|`` [N] and offset
    ``|e|`` [m] of the recorded revolution.

    Impacts peak between the samples, near the penetration maxima: all are taken over
    the samples and the maxima.
    """
    peak_times = [t for t in history.peak_times if record_start <= t <= record_end]
    peaks = [
        p
        for t, p in zip(history.peak_times, history.peak_penetrations, strict=True)
        if record_start <= t <= record_end
    ]
    sampled = np.array([r["penetration"] for r in records])
    max_penetration = float(max([*peaks, float(sampled.max())]))
    at_peaks: list[dict[str, Any]] = []
    if peak_times:
        peak_states, peak_index = history.state(peak_times)
        at_peaks = [
            system.evaluate(t, y, history.segments[k].impact_velocity)
            for t, y, k in zip(peak_times, peak_states, peak_index, strict=True)
        ]
    every = [*records, *at_peaks]
    peak_load = max(r["normal_force"] for r in every)
    joint_force = max(math.hypot(r["force_x"], r["force_y"]) for r in every)
    offset = max(math.hypot(r["ex"], r["ey"]) for r in every)
    return max_penetration, float(peak_load), float(joint_force), float(offset)


@dataclass(frozen=True, eq=False)
class ContactImpactSolution:
    """Contact–impact joint load plus what the continuous-contact model cannot tell.

    Attributes
    ----------
    load : LoadCycle
        Joint load sampled over the recorded revolution (what the wear pipeline
        consumes).
    impacts : int
        Contact starts (free flight ending on the wall) in the recorded
        revolution [-].
    free_flight_fraction : float
        Share of the recorded revolution without penetration (zero contact
        force) [-].
    max_penetration : float
        Largest penetration in the recorded revolution [m].
    peak_load : float
        Largest normal contact force in the recorded revolution, impacts
        included (evaluated at the samples and at every penetration maximum) [N].
    load_difference_rms, load_difference_max : float
        RMS and maximum over the samples of ``|F_impact - F_massless|``, the
        difference of the normal-force *vectors* (magnitude and azimuth) from the
        massless-link model [N]; ``nan`` if that model fails.
    massless : LoadCycle or None
        The massless-link load it is compared with.
    massless_contact_lost : bool or None
        Whether the massless-link model reports contact loss.
    history : ContactHistory
        Integration record of all revolutions (:func:`solve_contact_impact` keeps the
        dense output only where it samples: the states are known at the sample times,
        the penetration maxima and the segment ends).
    system : ContactSystem
        The integrated system (the slider-crank's, the four-bar's).
    settings : ContactImpactSettings
        Settings used.
    record_start : float
        Start time of the recorded revolution [s].
    runtime : float
        Wall-clock time of the integration [s].
    peak_joint_force : float
        Largest joint force ``|J|`` in the recorded revolution (contact, friction and
        the film of a lubricated joint) [N].
    max_offset : float
        Largest pin-centre offset ``|e|`` in the recorded revolution [m].
    """

    load: LoadCycle
    impacts: int
    free_flight_fraction: float
    max_penetration: float
    peak_load: float
    load_difference_rms: float
    load_difference_max: float
    massless: LoadCycle | None
    massless_contact_lost: bool | None
    history: ContactHistory
    system: Any
    settings: ContactImpactSettings
    record_start: float
    runtime: float
    peak_joint_force: float = math.nan
    max_offset: float = math.nan

    @property
    def period(self) -> float:
        """Crank period ``2 pi / omega`` [s]."""
        return 2.0 * math.pi / self.system.omega

    def summary(self) -> dict[str, Any]:
        """Extra scalars reported by ``jointwear dynamics`` (SI, units in the keys).

        A lubricated joint adds its film model, the largest eccentricity ratio
        ``max |e| / c``, the smallest film thickness ``c - max |e|`` (negative: the
        solids touched) and the largest joint force, the film's included.
        """
        mean = self.massless.mean_load if self.massless is not None else math.nan
        film = getattr(self.system.contact, "film", None)
        lubricated = {}
        if film is not None:
            clearance = self.system.contact.clearance
            lubricated = {
                "film_model": film.model,
                "max_eccentricity_ratio": float(self.max_offset / clearance),
                "min_film_thickness_m": float(clearance - self.max_offset),
                "peak_joint_force_n": float(self.peak_joint_force),
            }
        return {
            "force_law": self.settings.force_law,
            "restitution": self.settings.restitution,
            "friction_coefficient": self.settings.friction_coefficient,
            "integrator": self.settings.integrator_for(self.system),
            "impacts": int(self.impacts),
            "free_flight_fraction": float(self.free_flight_fraction),
            "max_penetration_m": float(self.max_penetration),
            "peak_load_n": float(self.peak_load),
            "load_difference_rms_n": float(self.load_difference_rms),
            "load_difference_max_n": float(self.load_difference_max),
            "load_difference_rms_relative": float(self.load_difference_rms / mean),
            "massless_contact_lost": self.massless_contact_lost,
            "revolutions_settle": int(self.settings.revolutions_settle),
            "rhs_evaluations": int(self.history.evaluations),
            "integration_runtime_s": float(self.runtime),
            **lubricated,
        }

    def load_cycle(self) -> LoadCycle:
        """:attr:`load` with :meth:`summary` in its extras: what the dynamics model reports."""
        return replace(self.load, extras={**self.load.extras, **self.summary()})


def sampled_solution(
    load: LoadCycle,
    run: SampledRevolution,
    system: Any,
    settings: ContactImpactSettings,
    massless_model: Callable[[], LoadCycle] | None = None,
) -> ContactImpactSolution:
    """The solution of a sampled revolution, compared with the massless-link load.

    Parameters
    ----------
    load : LoadCycle
        Contact-impact load of the recorded revolution.
    run : SampledRevolution
        The integration and its samples.
    system : ContactSystem
        The integrated system.
    settings : ContactImpactSettings
        Settings used.
    massless_model : callable, optional
        Computes the massless-link load of the same joint; ``None``: no comparison.
        Contact-loss warnings are silenced and a failure gives ``nan`` differences.
    """
    massless: LoadCycle | None = None
    massless_lost: bool | None = None
    rms = peak = math.nan
    if massless_model is not None:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", ContactLossWarning)
                massless = massless_model()
        except JointwearError:
            massless = None
        if massless is not None:
            massless_lost = bool(massless.contact_lost)
            dx = load.load * np.cos(load.azimuth) - massless.load * np.cos(massless.azimuth)
            dy = load.load * np.sin(load.azimuth) - massless.load * np.sin(massless.azimuth)
            diff = np.hypot(dx, dy)
            rms, peak = float(np.sqrt(np.mean(diff**2))), float(diff.max())
    return ContactImpactSolution(
        load=load,
        impacts=run.impacts,
        free_flight_fraction=run.free_flight_fraction,
        max_penetration=run.max_penetration,
        peak_load=run.peak_load,
        load_difference_rms=rms,
        load_difference_max=peak,
        massless=massless,
        massless_contact_lost=massless_lost,
        history=run.history,
        system=system,
        settings=settings,
        record_start=run.record_start,
        runtime=run.runtime,
        peak_joint_force=run.peak_joint_force,
        max_offset=run.max_offset,
    )
