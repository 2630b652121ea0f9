"""``jointwear compare-models``: every contact model against the references."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated

import typer
from rich.markup import escape
from rich.table import Table

from jointwear.cli.common import ConfigArg, JsonOpt, SetOpt, app, console, emit_json, load
from jointwear.errors import ConfigError
from jointwear.units import to_si

_DEFAULT_LOADS = "50 N,100 N,200 N,400 N"


def _split(values: list[str] | None) -> list[str]:
    out: list[str] = []
    for value in values or []:
        out.extend(part.strip() for part in value.split(",") if part.strip())
    return out


def parse_loads(text: str) -> list[float]:
    """Parse a ``--loads`` option: comma-separated forces with units (``"50 N,100 N"``).

    Parameters
    ----------
    text : str
        The option's text; each load a positive force with its unit.

    Returns
    -------
    list of float
        The loads [N].

    Raises
    ------
    ConfigError
        No load, a bad unit, or a load that is not positive and finite.
    """
    loads = [to_si(part, "force", "--loads") for part in _split([text])]
    if not loads or any(not (math.isfinite(f) and f > 0) for f in loads):
        raise ConfigError('--loads: give loads > 0, e.g. "50 N,100 N,200 N"')
    return loads


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
    from jointwear.contact import CONTACT_MODELS, ContactParameters
    from jointwear.io import check_out, staged_output
    from jointwear.references.compare import DEFAULT_MODELS, METRICS, compare_models
    from jointwear.registry import suggest

    names = ("compare_models_pressure.png", "compare_models_pressure.svg")
    if out is not None:
        out = check_out(out, files=names)
    cfg = load(config, list(set_ or []))
    force = parse_loads(loads)
    names = _split(models) or list(DEFAULT_MODELS)
    for name in names:
        if name not in CONTACT_MODELS:
            raise ConfigError(
                f"--models: unknown contact model {name!r}{suggest(name, CONTACT_MODELS)}"
            )
    if reference not in CONTACT_MODELS:
        raise ConfigError(
            f"--reference: unknown contact model {reference!r}{suggest(reference, CONTACT_MODELS)}"
        )
    if reference not in names:
        names.append(reference)
    if target not in ("pressure", "metrics"):
        raise ConfigError(f"--target: unknown {target!r}; choose 'pressure' or 'metrics'")
    if calibrate and reference not in ("fem", "persson"):
        raise ConfigError("--calibrate: the reference must be 'fem' or 'persson'")
    params = ContactParameters.from_config(cfg)
    options = {
        "balance": cfg.contact.balance,
        "tolerance": cfg.contact.tolerance,
        "max_iterations": cfg.contact.max_iterations,
    }
    comparison = compare_models(params, force, names, cfg.contact.nodes, options)
    result = comparison.to_json()
    result["reference"] = reference
    if comparison.errors:
        result["errors"] = dict(comparison.errors)

    plots: list[Path] = []
    if out is not None:
        from jointwear.references.compare import plot_pressure

        with staged_output(out, files=names) as staging:
            staged = plot_pressure(comparison, staging)
        plots = [out / path.name for path in staged]
        result["plots"] = [str(p) for p in plots]

    fits = {}
    if calibrate:
        from jointwear.references.spring_fit import calibrate_to_reference

        fits = calibrate_to_reference(
            params, force, reference=reference, target=target, nodes=cfg.contact.nodes
        )
        result["calibration"] = {name: fit.to_json() for name, fit in fits.items()}

    if json_:
        emit_json(result)
        return

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
    for name, message in comparison.errors.items():
        console.print(f"{name}: {message}", markup=False)
    for path in plots:
        console.print(f"plot: {path}", markup=False)
    if fits:
        console.print(
            f"calibrated to {reference} ({target}) over {loads}:", markup=False, highlight=False
        )
        for name, fit in fits.items():
            console.print(f"  {name} (rms residual {fit.rms_residual:.3g})", markup=False)
            for k, v in fit.values.items():
                console.print(f"    {k} = {v:.6g} ± {fit.uncertainty[k]:.2g}", markup=False)
            for k, v in fit.equivalent.items():
                text = v if isinstance(v, str) else f"{v:.6g}"
                console.print(f"      {k} = {text}", markup=False)
