"""``jointwear warm-up``: compile (or load from the cache) every compiled kernel once."""

from __future__ import annotations

from jointwear.cli.common import JsonOpt, app, console, emit_json


@app.command("warm-up")
def warm_up(json_: JsonOpt = False) -> None:
    """Compile every numba kernel once after an install, so runs start at once: the contact
    kernel, the slices along the pin, the oiled pin's orbit and the contact-impact dynamics
    (LSODA's right-hand side and the compiled RK45, dry and oiled); the seconds of each."""
    from jointwear.workflows.warm_up import warm_up as run_warm_up

    times = run_warm_up()
    if json_:
        emit_json(times)
        return
    if not times["compiled"]:
        console.print("numba is not available (or JOINTWEAR_NO_NUMBA is set): nothing to compile")
    groups = ", ".join(f"{name} {seconds:.2f} s" for name, seconds in times["groups"].items())
    console.print(
        f"{groups}; total {times['total_s']:.2f} s, of it compiling {times['compile_s']:.2f} s "
        "(0: loaded from numba's cache)"
    )
