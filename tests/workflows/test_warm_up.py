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
