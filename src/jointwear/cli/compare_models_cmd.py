"""``jointwear compare-models``: every contact model against the references."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import typer

from jointwear.cli.common import ConfigArg, JsonOpt, SetOpt, app, console, emit_json

_DEFAULT_LOADS = "50 N,100 N,200 N,400 N"


@app.command("compare-models")
def compare_models_command(
    config: ConfigArg,
    loads: Annotated[
        str, typer.Option("--loads", help='Comma-separated loads, e.g. "50 N,100 N,200 N".')
    ] = _DEFAULT_LOADS,
    models: Annotated[
        list[str] | None,
        typer.Option(
            "--models",
            help="Models to compare (repeatable or comma-separated); default all, "
            "references included.",
        ),
    ] = None,
    reference: Annotated[
        str, typer.Option("--reference", help="Model the deviations are measured from.")
    ] = "fem",
    out: Annotated[
        Path | None,
        typer.Option("--out", help="Folder for the p(theta) plot (PNG + SVG)."),
    ] = None,
    calibrate: Annotated[
        bool,
        typer.Option(
            "--calibrate",
            help="Also fit Winkler's stiffness and NLCP's K, n to the reference.",
        ),
    ] = False,
    target: Annotated[
        str,
        typer.Option("--target", help="Calibration target: 'pressure' or 'metrics'."),
    ] = "pressure",
    set_: SetOpt = None,
    json_: JsonOpt = False,
) -> None:
    """Contact half-angle, peak pressure and approach of every model over a load range."""
    from jointwear.workflows.contact_models import compare_contact_models

    done = compare_contact_models(
        config,
        loads,
        models=models,
        reference=reference,
        out=out,
        calibrate=calibrate,
        target=target,
        overrides=set_ or [],
    )
    if json_:
        emit_json(done.summary)
        return
    print_tables(done.comparison, reference)
    for name, message in done.comparison.errors.items():
        console.print(f"{name}: {message}", markup=False)
    for path in done.plots:
        console.print(f"plot: {path}", markup=False)
    if done.fits:
        console.print(
            f"calibrated to {reference} ({target}) over {loads}:", markup=False, highlight=False
        )
        print_fits(done.fits)


def print_tables(comparison: Any, reference: str) -> None:
    """One table per metric: each model's value at each load, and its deviation."""
    from rich.markup import escape
    from rich.table import Table

    from jointwear.references.compare import METRICS

    deviation = comparison.deviation(reference)
    for key, (label, unit, scale) in METRICS.items():
        table = Table(title=escape(f"{label} [{unit}] (deviation from {reference})"))
        table.add_column("model")
        for f in comparison.loads_n:
            table.add_column(f"{f:g} N", justify="right")
        for name, metrics in comparison.models.items():
            cells = []
            for i, value in enumerate(metrics[key]):
                if not math.isfinite(value):
                    cells.append("-")
                    continue
                text = f"{value * scale:.4g}"
                dev = deviation[name][key][i]
                if name != reference and math.isfinite(dev):
                    text += f" ({100 * dev:+.0f}%)"
                cells.append(text)
            table.add_row(name, *cells)
        console.print(table)


def print_fits(fits: dict[str, Any]) -> None:
    """The contact laws fitted to a reference: values, uncertainties, equivalents."""
    for name, fit in fits.items():
        console.print(f"  {name} (rms residual {fit.rms_residual:.3g})", markup=False)
        for k, v in fit.values.items():
            console.print(f"    {k} = {v:.6g} ± {fit.uncertainty[k]:.2g}", markup=False)
        for k, v in fit.equivalent.items():
            text = v if isinstance(v, str) else f"{v:.6g}"
            console.print(f"      {k} = {text}", markup=False)
