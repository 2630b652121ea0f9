"""Compile (or load from numba's cache) every compiled kernel once: ``jointwear warm-up``.

numba compiles a kernel the first time a process calls it and keeps the machine code
in its on-disk cache (``cache=True``), once per machine and source version: the first
long run after an install pays ~15 s for the contact kernel and ~2 s for the
contact–impact right-hand side, every later run ~0.3–0.5 s to load them.
:func:`warm_up` pays that up front, on a small case of the paper's joint that reaches
every compiled entry point (the contact kernel's cold, warm and contact-field calls;
the slider-crank's compiled right-hand side, gap and ``evaluate``), and reports the
seconds of each, so that a run's own time is its run's.
"""

from __future__ import annotations

import time
from typing import Any

__all__ = ["WARM_UP_CASE", "warm_up"]

#: the case that reaches every compiled entry point: the paper's slider-crank (Table 1)
#: with the default parameter set's joint; 501 adaptive revolutions take the compiled
#: contact kernel (:func:`jointwear.contact.solver.compiled_kernel`)
WARM_UP_CASE: dict[str, Any] = {
    "parameter_set": "nlcp-paper",
    "mechanism": {
        "crank_length": "70 mm",
        "rod_length": "200 mm",
        "crank_mass": "0.46 kg",
        "rod_mass": "1.09 kg",
        "slider_mass": "5 kg",
        "spring_stiffness": "1800 N/m",
        "spring_mode": "pull",
        "spring_preload": "120 N",
        "crank_speed": "120 rpm",
    },
    "simulation": {
        "steps_per_revolution": 360,
        "revolutions": 501,
        "update_contour": True,
        "update_every": "adaptive",
    },
}


def warm_up() -> dict[str, Any]:
    """Compile or load every compiled kernel; the seconds each took.

    Returns
    -------
    dict
        ``compiled`` (whether numba is there and not switched off by
        ``JOINTWEAR_NO_NUMBA``), ``contact_kernel_s`` and ``dynamics_kernel_s`` (wall
        seconds of the small case that reaches each, compile or cache load included),
        ``compile_s`` (of them, numba compiling: 0 when the cache was warm) and
        ``total_s``. Without numba nothing is compiled and the times are those of
        the NumPy and Python paths.
    """
    import warnings

    from jointwear.compile_time import compile_seconds
    from jointwear.config import config_from_dict
    from jointwear.contact.kernel import compiled_available, revolution_wear
    from jointwear.mechanism.slider_crank.contact_impact import (
        impact_kernel,
        solve_contact_impact,
    )
    from jointwear.mechanism.stage import mechanism_inputs
    from jointwear.simulation import Simulation

    started, compiled_before = time.perf_counter(), compile_seconds()
    config = config_from_dict(WARM_UP_CASE)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = Simulation(config)
        run.run()
        # the contact fields a revolution evaluates when read (snapshots, checks)
        cycle = run.load_cycle
        revolution = revolution_wear(
            run.initial_contour(),
            run.pin,
            cycle.load,
            cycle.azimuth,
            run.sliding_distance,
            run.law,
            config.materials.bushing.wear_coefficient,
            compiled=None if compiled_available() else False,
        )
        revolution.peak_pressure  # noqa: B018 (read: evaluates the balanced state)
    contact = time.perf_counter() - started
    dynamics_started = time.perf_counter()
    impact = config.replace({"dynamics.model": "contact-impact", "dynamics.revolutions_settle": 0})
    compiled = compiled_available() and impact_kernel() is not None
    solve_contact_impact(mechanism_inputs(impact), compare=False, compiled=compiled)
    dynamics = time.perf_counter() - dynamics_started
    return {
        "compiled": compiled,
        "contact_kernel_s": contact,
        "dynamics_kernel_s": dynamics,
        # (this call's share: the process may have compiled before it)
        "compile_s": compile_seconds() - compiled_before,
        "total_s": time.perf_counter() - started,
    }
