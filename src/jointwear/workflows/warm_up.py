"""Compile (or load from numba's cache) every compiled kernel once: ``jointwear warm-up``.

numba compiles a kernel the first time a process calls it and keeps the machine code
in its on-disk cache (``cache=True``), once per machine and source version: the first
long run after an install pays ~15 s for the contact kernel and ~2 s for the
contact–impact right-hand side, every later run ~0.3–0.5 s to load them.
:func:`warm_up` pays that up front, on small cases of the paper's joint run through the
same code as any run (so that the compiled signatures are a run's), one per kernel
group (:data:`KERNEL_GROUPS`, :data:`DYNAMICS_GROUPS`): the contact kernel's cold, warm
and contact-field calls; the slices along the pin; the oiled pin's orbit; the
slider-crank's contact-impact dynamics, LSODA's compiled right-hand side and the
compiled RK45, each dry and with the film's force. It reports the seconds of each
group, so that a run's own time is its run's.
"""

from __future__ import annotations

import time
from typing import Any

__all__ = ["DYNAMICS_GROUPS", "KERNEL_GROUPS", "WARM_UP_CASE", "warm_up"]

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


#: the kernel groups after the contact kernel and the runs through their real code paths
#: that compile them (overrides of :data:`WARM_UP_CASE`; a few revolutions each)
KERNEL_GROUPS: dict[str, dict[str, Any]] = {
    # the axial balance of the slices along the pin (jointwear.contact._sliced_kernel)
    "slices": {"joint.axial_slices": 3, "simulation.steps_per_revolution": 36},
    # the oiled pin's orbit over the cycle (jointwear.lubrication._orbit_kernel)
    "orbit": {
        "lubrication.model": "short-bearing",
        "lubrication.viscosity": "0.1 Pa*s",
        "simulation.revolutions": 1,
        "simulation.update_contour": False,
        "simulation.steps_per_revolution": 36,
    },
    # a tabulated film's orbit: its first guess by the compiled steady force factor
    "orbit_tabulated": {
        "lubrication.model": "long-bearing",
        "lubrication.viscosity": "0.05 Pa*s",
        "simulation.revolutions": 1,
        "simulation.update_contour": False,
        "simulation.steps_per_revolution": 36,
    },
}

#: the contact-impact integrations: ``(integrator, oiled)`` -> the name of their group
DYNAMICS_GROUPS: dict[tuple[str, bool], str] = {
    ("LSODA", False): "dynamics",  # the compiled right-hand side
    ("LSODA", True): "dynamics_film",  # with the film's force (mechanism.impact.compiled_film)
    ("RK45-compiled", False): "dynamics_rk45",  # the whole integration compiled
    ("RK45-compiled", True): "dynamics_rk45_film",
    ("Rodas4-compiled", True): "dynamics_rodas4_film",  # RODAS4, named
    ("Radau-compiled", True): "dynamics_radau_film",  # auto's with a film: RADAU5
}


def warm_up() -> dict[str, Any]:
    """Compile or load every compiled kernel; the seconds each group took.

    Returns
    -------
    dict
        ``compiled`` (whether numba is there and not switched off by
        ``JOINTWEAR_NO_NUMBA``), ``groups`` (kernel group -> wall seconds of the small
        case that reaches it, compile or cache load included: ``contact``, ``slices``,
        ``orbit``, ``orbit_tabulated``, ``dynamics``, ``dynamics_film``, ``dynamics_rk45``,
        ``dynamics_rk45_film``, ``dynamics_rodas4_film``, ``dynamics_radau_film``),
        ``contact_kernel_s`` and
        ``dynamics_kernel_s`` (the contact group's and the dynamics groups' together),
        ``compile_s`` (of them, numba compiling: 0 when the cache was warm) and
        ``total_s``. Without numba
        nothing is compiled and the times are those of the NumPy and Python paths.
    """
    from jointwear.compile_time import compile_seconds, watch_compiles
    from jointwear.config import config_from_dict
    from jointwear.contact.kernel import compiled_available
    from jointwear.mechanism.slider_crank.contact_impact import impact_kernel

    compiled = compiled_available() and impact_kernel() is not None
    if compiled:
        watch_compiles()
    started, compiled_before = time.perf_counter(), compile_seconds()
    config = config_from_dict(WARM_UP_CASE)
    groups = {"contact": _timed(_contact_group, config)}
    for name, overrides in KERNEL_GROUPS.items():
        groups[name] = _timed(_run, config.replace(overrides))
    for (integrator, oiled), name in DYNAMICS_GROUPS.items():
        groups[name] = _timed(_dynamics, config, integrator, oiled, compiled)
    return {
        "compiled": compiled,
        "groups": groups,
        "contact_kernel_s": groups["contact"],
        "dynamics_kernel_s": sum(groups[name] for name in DYNAMICS_GROUPS.values()),
        # (this call's share: the process may have compiled before it)
        "compile_s": compile_seconds() - compiled_before,
        "total_s": time.perf_counter() - started,
    }


def _timed(work: Any, *args: Any) -> float:
    """Wall seconds of ``work(*args)`` [s], its warnings (a tiny case's range) silenced."""
    import warnings

    started = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        work(*args)
    return time.perf_counter() - started


def _run(config: Any) -> Any:
    """A run of ``config`` (its compiled paths taken as in any run)."""
    from jointwear.simulation import Simulation

    run = Simulation(config)
    run.run()
    return run


def _contact_group(config: Any) -> None:
    """The contact kernel: a run's cold and warm calls and the contact fields."""
    from jointwear.contact.kernel import compiled_available, revolution_wear

    run = _run(config)
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


def _dynamics(config: Any, integrator: str, oiled: bool, compiled: bool) -> None:
    """One contact-impact load cycle with ``integrator``, the film's force if ``oiled``."""
    from jointwear.mechanism.slider_crank.contact_impact import solve_contact_impact
    from jointwear.mechanism.stage import mechanism_inputs

    overrides: dict[str, Any] = {
        "dynamics.model": "contact-impact",
        "dynamics.revolutions_settle": 0,
        "dynamics.integrator": integrator,
    }
    if oiled:
        # a thin oil: the same compiled functions, a short explicit integration (a thick
        # one makes the film stiff for RK45: ~14 s against 0.2 s)
        overrides |= {"lubrication.model": "short-bearing", "lubrication.viscosity": "1 mPa*s"}
    impact = config.replace(overrides)
    solve_contact_impact(mechanism_inputs(impact), compare=False, compiled=compiled)
