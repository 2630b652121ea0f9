"""The contact integrator's event watch against ``solve_ivp``'s own events.

:func:`integrate_contacts` checks the contact events itself after every step and finds
their roots afterwards; the straightforward way hands them to ``solve_ivp(events=...)``
(:func:`reference_contacts` below). Both take the same steps, so on a mechanism whose
pin separates and hits the wall again every revolution, every event time, state and
right-hand-side count is the same to the bit.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from jointwear.config import Config
from jointwear.mechanism.impact.integrator import integrate_contacts
from jointwear.mechanism.slider_crank.contact_impact import initial_state

from ..joints import slider_crank_system
from ..slider_crank.test_contact_impact import SEPARATING


def reference_contacts(system, t_end: float, y0, *, in_contact: bool, method: str):
    """Event times/states of the contact loop with ``solve_ivp``'s events (the reference)."""
    floor = system.contact.impact_velocity_floor
    t, y, v_imp = 0.0, np.asarray(y0, dtype=float), floor
    record = {"ends": [], "states": [], "peaks": [], "nfev": 0}

    def event(function, terminal, direction):
        function.terminal, function.direction = terminal, direction
        return function

    start = event(lambda t_, y_: system.gap(t_, y_), True, 1.0)
    end = event(lambda t_, y_: system.gap(t_, y_), True, -1.0)
    peak = event(lambda t_, y_: system.gap_rate(t_, y_), False, -1.0)
    while t < t_end:
        sol = solve_ivp(
            lambda t_, y_, v=v_imp: system.rhs(t_, y_, v), (t, t_end), y, method=method,
            rtol=1e-8, atol=1e-10, max_step=2 * math.pi / system.omega / 360,
            events=[end, peak] if in_contact else [start], dense_output=True,
        )  # fmt: skip
        record["nfev"] += sol.nfev
        record["ends"].append(float(sol.t[-1]))
        if in_contact:
            record["peaks"].extend(float(p) for p in sol.t_events[1])
        if sol.status != 1:
            break
        t, y = float(sol.t_events[0][-1]), np.asarray(sol.y_events[0][-1], dtype=float)
        record["states"].append(y)
        if not in_contact:
            v_imp = max(system.gap_rate(t, y), floor)
        in_contact = not in_contact
    return record


def separating(paper_config: Config):
    """The slider-crank whose pin separates twice a revolution, and its initial state."""
    config = paper_config.replace({"dynamics.model": "contact-impact", **SEPARATING})
    system = slider_crank_system(config)
    return system, initial_state(system, 360)[0]


@pytest.mark.parametrize("method", ["LSODA", "RK45"])
def test_event_watch_equals_solve_ivp_events(paper_config: Config, method: str) -> None:
    system, y0 = separating(paper_config)
    t_end = 2 * math.pi / system.omega
    history = integrate_contacts(
        system, (0.0, t_end), y0, in_contact=True, method=method,
        max_step=2 * math.pi / system.omega / 360,
    )  # fmt: skip
    reference = reference_contacts(system, t_end, y0, in_contact=True, method=method)
    assert len(history.impact_times) >= 2
    assert len(history.separation_times) >= 2
    assert [s.end for s in history.segments] == reference["ends"]
    events = sorted(history.impact_times + history.separation_times)
    assert events == reference["ends"][:-1]
    assert history.peak_times == reference["peaks"]
    assert history.evaluations == reference["nfev"]
    np.testing.assert_array_equal(
        [seg.solution(seg.end) for seg in history.segments[:-1]], reference["states"]
    )


def test_kept_steps_give_the_same_states(paper_config: Config) -> None:
    """``keep=``: the states at the kept times and the maxima are those of all steps."""
    system, y0 = separating(paper_config)
    period = 2 * math.pi / system.omega
    times = np.linspace(0.5 * period, 1.5 * period, 73)
    options = {"in_contact": True, "max_step": period / 360}
    full = integrate_contacts(system, (0.0, 1.5 * period), y0, **options)
    sparse = integrate_contacts(system, (0.0, 1.5 * period), y0, keep=times, **options)
    assert [s.end for s in sparse.segments] == [s.end for s in full.segments]
    assert sparse.peak_times == full.peak_times
    for history in (full, sparse):
        assert history.evaluations == full.evaluations
    np.testing.assert_array_equal(sparse.state(times)[0], full.state(times)[0])
    np.testing.assert_array_equal(sparse.state(full.peak_times)[0], full.state(full.peak_times)[0])
    np.testing.assert_array_equal(sparse.final_state, full.final_state)
    with pytest.raises(ValueError, match="not kept"):
        sparse.state([0.25 * period])
