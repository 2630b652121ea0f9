"""``jointwear warm-up``: compile (or load from the cache) every compiled kernel once."""

from __future__ import annotations

from jointwear.cli.common import JsonOpt, app, console, emit_json


@app.command("warm-up")
def warm_up(json_: JsonOpt = False) -> None:
    """Compile the numba kernels once after an install (~20 s), so runs start at once."""
    from jointwear.workflows.warm_up import warm_up as run_warm_up

    times = run_warm_up()
    if json_:
        emit_json(times)
        return
    if not times["compiled"]:
        console.print("numba is not available (or JOINTWEAR_NO_NUMBA is set): nothing to compile")
    console.print(
        f"contact kernel {times['contact_kernel_s']:.2f} s, contact-impact right-hand side "
        f"{times['dynamics_kernel_s']:.2f} s, total {times['total_s']:.2f} s, of it "
        f"compiling {times['compile_s']:.2f} s (0: loaded from numba's cache)"
    )
