"""``jointwear warm-up``: every compiled entry point is compiled (or loaded) by it."""

from __future__ import annotations

import pytest

from jointwear.contact.kernel import compiled_available
from jointwear.workflows.warm_up import warm_up


def entry_points(module, caller) -> dict[str, object]:
    """The module's compiled functions that ``caller`` calls from Python (as
    ``module.name`` or ``self._kernel.name``)."""
    import inspect
    import re

    from numba.core.registry import CPUDispatcher

    source = inspect.getsource(caller)
    return {
        name: value
        for name, value in vars(module).items()
        if isinstance(value, CPUDispatcher) and re.search(rf"(module|_kernel)\.{name}\b", source)
    }


@pytest.mark.skipif(not compiled_available(), reason="needs numba")
def test_warm_up_reaches_every_compiled_entry_point() -> None:
    from jointwear.contact import _compiled, kernel
    from jointwear.mechanism.slider_crank import _contact_impact_kernel, contact_impact

    times = warm_up()
    assert times["compiled"] is True
    assert times["total_s"] >= times["contact_kernel_s"] + times["dynamics_kernel_s"]
    assert 0.0 <= times["compile_s"] <= times["total_s"]
    for module, caller in ((_compiled, kernel), (_contact_impact_kernel, contact_impact)):
        entries = entry_points(module, caller)
        assert entries
        missing = [name for name, dispatcher in entries.items() if not dispatcher.signatures]
        assert not missing, f"{module.__name__}: not compiled by the warm-up: {missing}"


#: the compiled modules a run may load (the film's functions: compiled_film's namespace)
COMPILED_MODULES = (
    "jointwear.contact._compiled",
    "jointwear.contact._sliced_kernel",
    "jointwear.lubrication._orbit_kernel",
    "jointwear.mechanism.impact.compiled_film",
    "jointwear.mechanism.slider_crank._contact_impact_kernel",
    "jointwear.mechanism.slider_crank._contact_impact_rk",
)


def specialisations() -> dict[str, int]:
    """Every compiled function's number of compiled (or loaded) signatures."""
    import importlib

    from numba.core.registry import CPUDispatcher

    out = {}
    for name in COMPILED_MODULES:
        module = importlib.import_module(name)
        namespace = getattr(module, "_COMPILED", vars(module))
        for key, value in namespace.items():
            if isinstance(value, CPUDispatcher):
                out[f"{name}.{key}"] = len(value.signatures)
    return out


#: a run of each kind that takes a compiled path, on the warm-up's joint
RUNS = {
    "slices": {"joint.axial_slices": 4, "simulation.steps_per_revolution": 48},
    "lubricated": {
        "lubrication.model": "long-bearing",
        "lubrication.viscosity": "0.05 Pa*s",
        "simulation.revolutions": 2,
        "simulation.update_contour": False,
    },
    "contact-impact, oiled": {
        "dynamics.model": "contact-impact",
        "dynamics.revolutions_settle": 20,
        "lubrication.model": "short-bearing",
        "lubrication.viscosity": "0.05 Pa*s",
        "simulation.revolutions": 2,
        "simulation.update_contour": False,
    },
    "contact-impact, oiled, RK45-compiled": {
        "dynamics.model": "contact-impact",
        "dynamics.integrator": "RK45-compiled",
        "dynamics.revolutions_settle": 20,
        "lubrication.model": "long-bearing",
        "lubrication.viscosity": "2 mPa*s",
        "simulation.revolutions": 2,
        "simulation.update_contour": False,
    },
    "contact-impact, RK45-compiled": {
        "dynamics.model": "contact-impact",
        "dynamics.integrator": "RK45-compiled",
        "dynamics.revolutions_settle": 20,
        "simulation.revolutions": 2,
        "simulation.update_contour": False,
    },
}


@pytest.mark.skipif(not compiled_available(), reason="needs numba")
def test_after_the_warm_up_a_run_of_each_kind_compiles_nothing_new() -> None:
    """No kernel gains a signature (compiled or loaded) and numba compiles nothing."""
    import warnings

    from jointwear.compile_time import compile_seconds
    from jointwear.config import config_from_dict
    from jointwear.simulation import Simulation
    from jointwear.workflows.warm_up import WARM_UP_CASE

    times = warm_up()
    assert set(times["groups"]) >= {"contact", "slices", "orbit", "dynamics_film", "dynamics_rk45"}
    before, compiled = specialisations(), compile_seconds()
    assert all(before[f"{name}.revolution"] for name in COMPILED_MODULES[:2])
    assert before["jointwear.lubrication._orbit_kernel.cycle"]
    assert before["jointwear.mechanism.slider_crank._contact_impact_rk.integrate_revolution_rk"]
    base = config_from_dict(WARM_UP_CASE)
    for kind, overrides in RUNS.items():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            summary = Simulation(base.replace(overrides)).run(pressures=False).summary()
        assert summary["compile_time_s"] == 0.0, kind
        assert specialisations() == before, kind
    assert compile_seconds() == compiled
