"""``jointwear contact`` and ``jointwear models``."""

from __future__ import annotations

from typing import Annotated

import typer

from jointwear.cli.common import ConfigArg, JsonOpt, SetOpt, app, console, emit_json
from jointwear.contact import CONTACT_MODELS, MODEL_DESCRIPTIONS


@app.command()
def contact(
    config: ConfigArg,
    load_: Annotated[str, typer.Option("--load", help='Joint load, e.g. "200 N".')] = "200 N",
    azimuth: Annotated[
        str, typer.Option("--azimuth", help='Load direction in the bushing frame, e.g. "0 deg".')
    ] = "0 deg",
    model: Annotated[
        str | None, typer.Option("--model", help="Contact model (overrides contact.model).")
    ] = None,
    set_: SetOpt = None,
    json_: JsonOpt = False,
) -> None:
    """Pressure distribution for one load on the unworn bushing."""
    from rich.markup import escape
    from rich.table import Table

    from jointwear.workflows.contact_models import contact_on_unworn_bushing

    done = contact_on_unworn_bushing(config, load_, azimuth, model=model, overrides=set_ or [])
    summary, force = done.summary, done.load
    if json_:
        emit_json(summary)
        return
    table = Table(title=escape(f"contact: {summary['contact_model']}, {force:g} N at {azimuth}"))
    table.add_column("quantity")
    table.add_column("value", justify="right")
    rows = [
        ("penetration of compression centre", f"{summary['penetration_m'] * 1e6:.6g} µm"),
        (
            "contact half-angle left / right",
            f"{summary['contact_half_angle_left_deg']:.4g}° / "
            f"{summary['contact_half_angle_right_deg']:.4g}°",
        ),
        ("peak pressure", f"{summary['peak_pressure_pa'] / 1e6:.6g} MPa"),
        ("resultant along load", f"{summary['resultant_normal_n']:.12g} N"),
        ("resultant sideways", f"{summary['resultant_tangential_n']:.3g} N"),
        ("springs N_L / N_R", f"{summary['springs_left']} / {summary['springs_right']}"),
        ("iterations", str(summary["iterations"])),
    ]
    for name, value in rows:
        table.add_row(name, value)
    console.print(table)


@app.command()
def models(json_: JsonOpt = False) -> None:
    """List the contact models."""
    from rich.markup import escape
    from rich.table import Table

    names = CONTACT_MODELS.names()
    if json_:
        emit_json({"contact_models": {n: MODEL_DESCRIPTIONS.get(n, "") for n in names}})
        return
    table = Table(title=escape("contact models ([contact] model = ...)"))
    table.add_column("name")
    table.add_column("description")
    for name in names:
        table.add_row(name, MODEL_DESCRIPTIONS.get(name, ""))
    console.print(table)
