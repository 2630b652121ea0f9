"""``jointwear materials``: the materials library, its values, limits and sources."""

from __future__ import annotations

from typing import Annotated

import typer

from jointwear.cli.common import JsonOpt, app, console, emit_json


@app.command()
def materials(
    name: Annotated[
        str | None,
        typer.Argument(help="One material: every value with its source.", show_default=False),
    ] = None,
    json_: JsonOpt = False,
) -> None:
    """List the materials library ([materials] bushing = "NAME"): values, limits, sources."""
    from rich import box
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    from jointwear.materials import (
        OVERVIEW,
        TABLE_KEY,
        display_unit,
        get_material,
        library,
        material_units,
    )

    entries = [get_material(name, "NAME")] if name is not None else list(library().values())
    if json_:
        emit_json({"units": material_units(), "materials": {m.name: m.summary() for m in entries}})
        return
    if name is not None:
        material = entries[0]
        table = Table(title=escape(f"{material.name}: {material.description}"))
        for column in ("key", "value", "as given"):
            table.add_column(column, no_wrap=True)
        table.add_column("source")
        for key, value in material.values.items():
            if key != TABLE_KEY:
                table.add_row(key, material.display(key), str(value), material.sources[key])
        if "wear_coefficient" not in material.values:
            table.add_row(
                "wear_coefficient",
                material.display("wear_coefficient"),
                "",
                "from the wear form above",
            )
        console.print(table)
        wear_table = material.wear_table()
        if wear_table is not None:  # on its own lines: the points must not wrap
            from jointwear.config.wear_table import TABLE_VARIABLES

            unit = TABLE_VARIABLES[wear_table["against"]].replace("*", " ")
            points = ", ".join(f"{p:g}" for p in wear_table["points"])
            ks = ", ".join(f"{k:g}" for k in wear_table["coefficients"])
            console.print(
                f"{TABLE_KEY}: K_d against {wear_table['against']}\n"
                f"  points [{unit}]: {points}\n  K_d [m2/N]: {ks}\n"
                f"  source: {material.sources[TABLE_KEY]}",
                markup=False,
                soft_wrap=True,
            )
        return
    # numbers only (units under the headers): the table fits 80 columns; the description
    # and the source of every value are on `jointwear materials NAME`
    table = Table(
        title=escape('materials library ([materials] bushing = "NAME")'),
        box=box.SIMPLE_HEAD,
        pad_edge=False,
    )
    table.add_column("name", no_wrap=True)
    for key, header in OVERVIEW:
        unit = display_unit(key)
        label = f"{header}\n[{unit}]" if unit else header
        table.add_column(escape(label), justify="right", no_wrap=True)
    for material in entries:
        cells = [material.display(key, unit=False) for key, _ in OVERVIEW]
        table.add_row(material.name, *cells)
    # never cut a number: wider than the terminal wraps, which a pipe or a log does not
    Console(width=max(console.width, 104), highlight=False).print(table)
    console.print("Description and source of every value: `jointwear materials NAME` (or --json).")
