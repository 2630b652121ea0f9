"""A :class:`~jointwear.mechanism.impact.integrator.ContactHistory` from a compiled run.

A compiled integration (``dynamics.integrator = "RK45-compiled"``,
:mod:`jointwear.mechanism.slider_crank._contact_impact_rk`) returns its segments,
contact events, penetration maxima and the states at the sample times as arrays;
:func:`kept_history` turns them into the history :func:`integrate_contacts` returns
with ``keep=`` the sample times: the states are known at the samples, the
penetration maxima and the segment ends.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from jointwear.mechanism.impact.integrator import ContactHistory, Segment

__all__ = ["KeptStates", "kept_history"]

FloatArray = NDArray[np.float64]


class KeptStates:
    """States at a few times, answered like an ``OdeSolution`` at exactly those times.

    Parameters
    ----------
    times : ndarray, shape (M,)
        Times [s].
    states : ndarray, shape (M, n_state)
        States at ``times``.
    """

    def __init__(self, times: FloatArray, states: FloatArray) -> None:
        order = np.argsort(times, kind="stable")
        self.times, self.states = times[order], states[order]

    def __call__(self, t: Any) -> FloatArray:
        scalar = np.ndim(t) == 0
        wanted = np.atleast_1d(np.asarray(t, dtype=float))
        index = np.clip(np.searchsorted(self.times, wanted), 0, self.times.size - 1)
        if not np.all(self.times[index] == wanted):
            raise ValueError(
                "RK45-compiled: the states are kept at the samples, the penetration "
                "maxima and the segment ends only"
            )
        values = self.states[index].T
        return values[:, 0] if scalar else values


def kept_history(
    run: tuple[Any, ...], samples: FloatArray, gap: Any, evaluations_offset: int = 0
) -> tuple[ContactHistory, FloatArray]:
    """The history of a compiled run and its states at ``samples``.

    Parameters
    ----------
    run : tuple
        What the compiled integrator returns (status checked by the caller).
    samples : ndarray, shape (M,)
        The sample times it integrated through [s].
    gap : callable
        ``gap(t, y)`` of the system: the penetration of a maximum [m].
    evaluations_offset : int
        Right-hand sides spent before the run [-].

    Returns
    -------
    history : ContactHistory
    states : ndarray, shape (M, n_state)
    """
    _, nfev, states, _, starts, ends, contact, velocity, rate, n_seg, pt, py, _, n_peaks = run
    peak_times, peak_states = pt[:n_peaks], py[:n_peaks]
    history = ContactHistory(evaluations=int(nfev) + evaluations_offset)
    for i in range(n_peaks):
        history.peak_times.append(float(peak_times[i]))
        history.peak_penetrations.append(float(gap(float(peak_times[i]), peak_states[i])))
    times = np.concatenate([samples, peak_times])
    kept = np.concatenate([states, peak_states])
    solution = KeptStates(times, kept)
    for i in range(n_seg):
        in_contact = bool(contact[i])
        history.segments.append(
            Segment(
                float(starts[i]), float(ends[i]), solution, in_contact,
                float(velocity[i]) if in_contact else math.nan,
            )
        )  # fmt: skip
        if math.isnan(rate[i]):
            continue
        if in_contact:
            history.separation_times.append(float(ends[i]))
            history.separation_velocities.append(-float(rate[i]))
        else:
            history.impact_times.append(float(ends[i]))
            history.impact_velocities.append(float(rate[i]))
    return history, states
