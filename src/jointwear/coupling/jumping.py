"""Cycle jumping: how far one contour update carries the wear, and where it ends.

The worn depth obeys ``dh/dn = w(h)``, ``w`` the wear per revolution on the contour
worn by ``h``. A fixed update interval (``simulation.update_every = k``) is the paper's
explicit scheme: the wear of one revolution on the current contour, times ``k``.
``"adaptive"`` jumps many revolutions with a trapezoid predictor-corrector in the
spirit of Mukras et al. (:func:`adaptive_step`): the jump's length is chosen by an
error estimate (:func:`jump_error`, :func:`adaptive_interval`). A wearing pin is a second
surface integrated the same way: its wear map jumps with the bushing's, predicted and
corrected alike, and the jump's error is the larger of the two surfaces'. A
:class:`WearStep` is one update before it is applied (:func:`next_step`); :func:`applied`
applies it, cut short where a ``[life]`` limit is reached inside it.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from jointwear.coupling.limits import LifeLimits, at_stop
from jointwear.geometry.update import update_contour
from jointwear.state import SimulationState, revolution_number

if TYPE_CHECKING:
    from jointwear.config import Config
    from jointwear.contact import ContactSolution
    from jointwear.geometry.contour import BushingContour

__all__ = [
    "Jumps",
    "Solved",
    "WearStep",
    "adaptive_interval",
    "adaptive_step",
    "applied",
    "grown",
    "jump_error",
    "linear_marks",
    "next_step",
]

FloatArray = NDArray[np.float64]


class Solved(NamedTuple):
    """A contact solve on a contour and the wear per revolution it gives.

    Attributes
    ----------
    rate : ndarray, shape (N,)
        Wear depth per revolution at every node [m].
    solution : ContactSolution
        The contact solve.
    contour : BushingContour
        The contour it was solved on.
    """

    rate: FloatArray
    solution: ContactSolution
    contour: BushingContour


#: ``rate_at(state, wear_depth, ahead)``: the solve on the contour worn by ``wear_depth``
#: [m], warm-started from ``state``'s last solve extrapolated ``ahead`` revolutions on
RateAt = Callable[[SimulationState, FloatArray, int], Solved]


class WearStep(NamedTuple):
    """One contour update before it is applied: where the wear depth goes over the interval.

    (A named tuple: immutable, and made once per revolution at the cost of a tuple.)

    Attributes
    ----------
    base : SimulationState
        The state the update starts from (its wear rate may have been refreshed).
    interval : int
        Revolutions the update covers.
    rate : ndarray, shape (N,)
        Wear per revolution at the start of the interval [m].
    end_rate : ndarray, shape (N,) or None
        Wear per revolution at the predicted end (adaptive jumps; ``None``: the
        explicit scheme, linear over the interval) [m].
    solution : ContactSolution
        The last contact solve of the update.
    contour : BushingContour
        The contour of that solve.
    error : float
        Error estimate of an adaptive jump [-] (0 otherwise).
    pin_rate : ndarray, shape (N,) or None
        The pin's wear per revolution in its own frame (a wearing pin) [m], at the start
        of the interval.
    end_pin_rate : ndarray, shape (N,) or None
        The pin's wear per revolution at the predicted end of an adaptive jump [m].
    """

    base: SimulationState
    interval: int
    rate: FloatArray
    end_rate: FloatArray | None
    solution: ContactSolution
    contour: BushingContour
    error: float = 0.0
    pin_rate: FloatArray | None = None
    end_pin_rate: FloatArray | None = None

    def pin_depth_at(self, revolutions: float) -> FloatArray | None:
        """The pin's wear depth ``revolutions`` (real) into the interval [m]: linear
        (explicit scheme), or the trapezoid corrector's quadratic (adaptive jumps)."""
        if self.pin_rate is None:
            return self.base.pin_wear_depth
        return _along(self.base.pin_wear_depth, self.pin_rate, self.end_pin_rate,
                      revolutions, self.interval)  # fmt: skip

    def depth_at(self, revolutions: float) -> FloatArray:
        """Wear depth ``revolutions`` (real, ``0 <= revolutions <= interval``) into the
        interval [m].

        The explicit scheme grows linearly; an adaptive jump follows the trapezoid
        corrector's quadratic, whose end value is the corrector's.
        """
        depth, rate, end = self.base.wear_depth, self.rate, self.end_rate
        if end is None:
            # (1 x is exact: a per-revolution update skips the product)
            return depth + (rate if revolutions == 1 else rate * revolutions)
        return _along(depth, rate, end, revolutions, self.interval)


def _along(
    depth: FloatArray, rate: FloatArray, end: FloatArray | None, tau: float, interval: int
) -> FloatArray:
    """Depth ``tau`` revolutions into an update [m] from ``depth`` [m] and the wear per
    revolution at its start, ``rate``, and at its predicted end, ``end`` (``None``: the
    explicit scheme's line; else the trapezoid corrector's quadratic over ``interval``)."""
    if end is None:
        return depth + rate * tau
    if tau == interval:
        return depth + 0.5 * interval * (rate + end)
    return depth + tau * rate + (0.5 * tau * tau / interval) * (end - rate)


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
    # (a wear map along the pin counts as one profile of all its slices)
    after, difference = after.ravel(), difference.ravel()
    area = float(np.dot(radius + 0.5 * after, after))
    errors = (
        float(np.max(np.abs(difference))) / peak,
        float(np.linalg.norm(difference) / np.linalg.norm(after)),
        abs(float(np.dot(radius + after, difference))) / area if area > 0 else 0.0,
    )
    return max(errors)


@dataclass(frozen=True)
class Jumps:
    """How a run's contour updates advance the wear.

    Attributes
    ----------
    every : int or "adaptive"
        ``simulation.update_every``: revolutions per update, or adaptive jumps.
    tolerance : float
        ``simulation.adaptive_tolerance`` [-].
    wall_thickness : float
        Bushing wall thickness [m].
    radius : float
        Unworn bushing radius [m].
    pin_radius : float
        Unworn pin radius [m] (a wearing pin's jump error).
    """

    every: int | str
    tolerance: float
    wall_thickness: float
    radius: float
    pin_radius: float = 0.0

    @classmethod
    def from_config(cls, config: Config) -> Jumps:
        """The updates of ``config.simulation`` on ``config.joint``."""
        sim, joint = config.simulation, config.joint
        return cls(
            sim.update_every,
            sim.adaptive_tolerance,
            joint.bushing_thickness,
            joint.bushing_radius,
            joint.pin_radius,
        )

    @property
    def adaptive(self) -> bool:
        """Whether the updates are adaptive jumps."""
        return self.every == "adaptive"


def next_step(
    base: SimulationState,
    remaining: int,
    rate_at: RateAt,
    jumps: Jumps,
    *,
    warm_start: Callable[[Solved], dict[str, Any]],
    pin_rate: Callable[[Solved], FloatArray] | None = None,
    due_in: Callable[[SimulationState], int | None] | None = None,
) -> WearStep:
    """The next contour update from ``base``: a fixed interval or an adaptive jump.

    A fixed interval is the explicit scheme: the wear of one revolution on the current
    contour (and the pin's, where it wears), times ``simulation.update_every``. An
    adaptive jump (:func:`adaptive_step`) starts from the state's wear rate; the first
    (or the first on a new load) solves the current contour for it.

    Parameters
    ----------
    base : SimulationState
        The state the update starts from.
    remaining : int
        Revolutions left in the run [-].
    rate_at : callable
        ``rate_at(state, wear_depth, ahead)``: the contact solve and wear rate on the
        contour worn by ``wear_depth`` [m], warm-started ``ahead`` revolutions on.
    jumps : Jumps
        The run's updates.
    warm_start : callable
        ``warm_start(solved)``: the state's warm-start fields after a solve.
    pin_rate : callable, optional
        ``pin_rate(solved)``: the pin's wear per revolution [m] (a wearing pin).
    due_in : callable, optional
        ``due_in(state)``: revolutions until the dynamics are due again [-] (an adaptive
        jump ends there).
    """
    if not jumps.adaptive:
        solved = rate_at(base, base.wear_depth, base.interval)
        pin = None if base.pin_wear_depth is None else pin_rate(solved)
        interval = min(int(jumps.every), remaining)
        return WearStep(
            base, interval, solved.rate, None, solved.solution, solved.contour, 0.0, pin
        )
    solved = None
    pin_unknown = base.pin_wear_depth is not None and base.pin_wear_rate is None
    if base.wear_rate is None or pin_unknown:  # the first update (or a new load): the rates
        solved = rate_at(base, base.wear_depth, 0)
        pin = {} if base.pin_wear_depth is None else {"pin_wear_rate": pin_rate(solved)}
        # (a new load keeps the step size; its jumps are error-controlled anyway)
        base = replace(
            base,
            wear_rate=solved.rate,
            next_interval=base.next_interval or 1,
            **warm_start(solved),
            **pin,
        )
    ahead = None if due_in is None else due_in(base)
    return adaptive_step(
        base, remaining, rate_at, jumps, dynamics_due_in=ahead, solved=solved, pin_rate=pin_rate
    )


def adaptive_step(
    base: SimulationState,
    remaining: int,
    rate_at: RateAt,
    jumps: Jumps,
    *,
    dynamics_due_in: int | None = None,
    solved: Solved | None = None,
    pin_rate: Callable[[Solved], FloatArray] | None = None,
) -> WearStep:
    """One adaptive contour update: a jump of many revolutions, error-controlled.

    A jump of ``J`` revolutions predicts ``h* = h + J w(h)`` (Euler), solves the contact
    on ``h*`` and corrects with the trapezoid rule, ``h_new = h + J (w(h) + w(h*)) / 2``
    (a second-order predictor-corrector; the rate ``w(h*)`` serves as the rate of the
    next jump). ``J (w(h*) - w(h)) / 2``, the difference of the two, estimates the error
    of the Euler jump (:func:`jump_error`); above the tolerance the jump is rejected and
    retried shorter. The predicted contour stays inside the wall: the last jumps before
    wear-through shrink to single revolutions, and the revolution in which the wall goes
    is explicit (there is no contour to predict beyond it). A wearing pin's map jumps
    alike from ``base.pin_wear_rate``: the prediction solves the contact with the pin
    worn by ``h_p + J w_p`` too, and the jump's error is the larger of the bushing's and
    the pin's.

    Parameters
    ----------
    base : SimulationState
        The state the jump starts from, with its wear rate ``w(h)`` [m].
    remaining : int
        Revolutions left in the run [-].
    rate_at : callable
        ``rate_at(state, wear_depth, ahead)``: the contact solve and wear rate on the
        contour worn by ``wear_depth`` [m], warm-started ``ahead`` revolutions on.
    jumps : Jumps
        The tolerance, the wall and the radius.
    dynamics_due_in : int, optional
        Revolutions until the dynamics are due again (a jump ends there, so that they
        see the wear) [-].
    solved : Solved, optional
        The solve that gave ``base``'s wear rate, when it was just made.
    pin_rate : callable, optional
        ``pin_rate(solved)``: the pin's wear per revolution [m] (a wearing pin, whose
        rate at ``base`` is ``base.pin_wear_rate``).
    """
    rate0, tolerance = base.wear_rate, jumps.tolerance
    pin0 = None if base.pin_wear_depth is None else base.pin_wear_rate
    interval = min(max(1, base.next_interval or base.interval), remaining)
    wearing = rate0 > 0
    if np.any(wearing):
        room = float(np.min((jumps.wall_thickness - base.wear_depth[wearing]) / rate0[wearing]))
        if room < 1.0:
            # the wall goes within this revolution: explicit from the current contour's
            # rate, and the wall limit ends the run inside it
            if solved is None:
                solved = rate_at(base, base.wear_depth, base.interval)
                pin0 = None if pin0 is None else pin_rate(solved)
            return WearStep(base, 1, solved.rate, None, solved.solution, solved.contour, 0.0, pin0)
        interval = max(1, min(interval, math.floor(room)))
    if dynamics_due_in is not None:
        interval = max(1, min(interval, dynamics_due_in))
    end_pin = None
    while True:
        ahead = base
        if pin0 is not None:  # (the pin predicted too: its wear faces the bushing's)
            ahead = replace(base, pin_wear_depth=base.pin_wear_depth + interval * pin0)
        solved = rate_at(ahead, base.wear_depth + interval * rate0, interval)
        error = jump_error(base.wear_depth, rate0, solved.rate, interval, jumps.radius)
        if pin0 is not None:
            end_pin = pin_rate(solved)
            # (the worn pin's area, ``(R_p - h/2) h``, taken as the bushing's to first order)
            pin_error = jump_error(base.pin_wear_depth, pin0, end_pin, interval, jumps.pin_radius)
            error = max(error, pin_error)
        if error <= tolerance or interval == 1:
            break
        interval = max(1, min(interval - 1, adaptive_interval(error, interval, tolerance)))
    return WearStep(
        base, interval, rate0, solved.rate, solved.solution, solved.contour, error, pin0, end_pin
    )


def grown(contour: BushingContour, increment: FloatArray) -> FloatArray:
    """The wear depth of ``update_contour(contour, increment)`` [m], without building the
    contour unless it would be refused (it then raises as the update does).

    Parameters
    ----------
    contour : BushingContour
        The contour before the increment.
    increment : ndarray, shape (N,)
        Wear depth added at every node [m].
    """
    # the contour's radii are valid, and so are they grown by a finite increment that is
    # nowhere negative (a NaN fails both comparisons): else the update decides
    if not (increment.min() >= 0.0 and increment.max() < np.inf):
        return update_contour(contour, increment).wear_depth
    return contour.wear_depth + increment


def applied(
    step: WearStep,
    life: LifeLimits,
    jumps: Jumps,
    contour: Callable[[FloatArray], BushingContour],
    saved: Sequence[int],
) -> dict[str, Any]:
    """The state's new values after a contour update (its warm start aside), the update
    cut short where a ``[life]`` limit is reached inside it.

    A limit reached inside the interval ends it where it is reached, a fraction of a
    revolution included (:meth:`LifeLimits.first_reached` on the step's path). Otherwise
    the depth is that of the contour update, which refuses wear through the wall. Saved
    profiles inside an adaptive jump are the corrector's quadratic at their revolutions.

    Parameters
    ----------
    step : WearStep
        The update.
    life : LifeLimits
        The run's limits.
    jumps : Jumps
        The run's updates.
    contour : callable
        ``contour(wear_depth)``: the bushing contour worn by ``wear_depth`` [m] (an
        adaptive jump's update starts from the contour of its base).
    saved : sequence of int
        The revolutions of the saved profiles [-].
    """
    base, interval = step.base, step.interval
    end = step.depth_at(interval)
    adaptive = step.end_rate is not None
    # (the end of the interval is the limits' first question, and usually the answer)
    stop = life.first_reached(
        lambda revolutions: end if revolutions == interval else step.depth_at(revolutions),
        interval,
        None if adaptive else (base.wear_depth, step.rate),
    )
    stopped_by = None
    if stop is not None:
        # the run ends inside the interval, at the limit (a fractional revolution)
        at, stopped_by = stop
        interval = revolution_number(at)
        depth = at_stop(step.depth_at(at), jumps.wall_thickness)
    elif adaptive:
        # the contour must stay inside the wall (a run without a wall limit cannot get
        # here with wear beyond it: the wall is always a limit)
        depth = update_contour(contour(base.wear_depth), end - base.wear_depth).wear_depth
    else:  # (a fixed step's contour is the one of ``base``)
        depth = grown(step.contour, end - base.wear_depth)
        depth.setflags(write=False)  # its own array: the state keeps it uncopied
    profiles = base.profiles
    if adaptive:
        for target in saved:
            if base.revolution < target < base.revolution + interval:
                profiles = profiles.append((target, step.depth_at(target - base.revolution)))
    return {
        "revolution": base.revolution + interval,
        "wear_depth": depth,
        "wear_rate": step.end_rate if adaptive else step.rate,
        "interval": interval,
        "profiles": profiles,
        "next_interval": (
            adaptive_interval(step.error, interval, jumps.tolerance)
            if adaptive
            else base.next_interval
        ),
        "stopped_by": stopped_by,
        "updates_since_dynamics": base.updates_since_dynamics + 1,
        "pin_wear_depth": step.pin_depth_at(interval),
        # (an adaptive jump's next starts from the pin's rate at its end, as the bushing's)
        "pin_wear_rate": step.end_pin_rate
        if adaptive and step.end_pin_rate is not None
        else step.pin_rate,
    }


def linear_marks(
    solved: Solved,
    pin_rate: FloatArray | None,
    revolutions: int,
    life: LifeLimits,
    saved: Sequence[int],
    wall_thickness: float,
) -> list[dict[str, Any]]:
    """The record of a run without contour update, whose wear grows exactly linearly: the
    state's new values at each saved profile's revolution before the end, and at the end.

    The end is the last revolution, or where the first ``[life]`` limit is reached on
    the linear path (a fraction of a revolution included).

    Parameters
    ----------
    solved : Solved
        The solve of the unworn contour and its wear per revolution [m].
    pin_rate : ndarray, shape (N,) or None
        The pin's wear per revolution [m] (a wearing pin).
    revolutions : int
        ``simulation.revolutions`` [-].
    life : LifeLimits
        The run's limits.
    saved : sequence of int
        The revolutions of the saved profiles [-].
    wall_thickness : float
        Bushing wall thickness [m].
    """
    rate = solved.rate
    stop = life.first_reached(lambda n: rate * n, revolutions, (np.zeros_like(rate), rate))
    end, stopped_by = (revolutions, None) if stop is None else (revolution_number(stop[0]), stop[1])
    marks = []
    for revolution in [*(t for t in saved if t < end), end]:
        depth = solved.contour.worn(rate * revolution).wear_depth
        if stopped_by is not None and revolution == end:
            depth = at_stop(depth, wall_thickness)
        marks.append(
            {
                "revolution": revolution,
                "wear_rate": rate,
                "interval": revolution,
                "wear_depth": depth,
                "stopped_by": stopped_by if revolution == end else None,
                "pin_wear_depth": None if pin_rate is None else pin_rate * revolution,
                "pin_wear_rate": pin_rate,
            }
        )
    return marks
