"""``jointwear calibrate``: fit parameters to measured wear profiles or to a paper row."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any

import typer

from jointwear.cli.common import (
    JsonOpt,
    MaxMemoryOpt,
    SetOpt,
    UnitsOpt,
    app,
    console,
    emit_json,
)

if TYPE_CHECKING:
    from rich.table import Table

CalConfigArg = Annotated[
    Path | None,
    typer.Argument(
        help="Config file (TOML) of the measured runs; optional with --paper-row.",
        show_default=False,
    ),
]
MeasuredArgs = Annotated[
    list[Path] | None,
    typer.Argument(
        help="Measured inner-surface points, one file per bushing run with CONFIG as is "
        "(use --case for runs with their own settings).",
        show_default=False,
    ),
]
FitParamOpt = Annotated[
    list[str] | None,
    typer.Option(
        "--fit",
        help="Parameter to fit: wear_coefficient | axial_length | bushing_thickness | "
        "spring_preload | a dotted key; bounds as NAME=LOWER..UPPER (units allowed). Repeat.",
        show_default=False,
    ),
]
CaseOpt = Annotated[
    list[str] | None,
    typer.Option(
        "--case",
        help="A measured file with its own settings: FILE:KEY=VALUE[,KEY=VALUE...], e.g. "
        '"worn240.csv:mechanism.crank_speed=240 rpm". Repeat.',
        show_default=False,
    ),
]
CircleFitOpt = Annotated[
    str,
    typer.Option(
        "--circle-fit",
        help="Bushing centre of the measurements: robust (started on the unworn arc, then "
        "fitted with each simulated profile) | least-squares (the paper's plain fit, fixed).",
    ),
]
NoiseOpt = Annotated[
    str | None,
    typer.Option(
        "--noise",
        help='Measurement noise (radial standard deviation) of the points, e.g. "0.7 um"; '
        "default: estimated per file on the unworn arc.",
        show_default=False,
    ),
]
AlignOpt = Annotated[
    str,
    typer.Option(
        "--align",
        help='Rotation of the measurements: "best" or the angle of the bushing\'s theta = 0 '
        'in the files\' frame, e.g. "12 deg".',
    ),
]
ProfileOpt = Annotated[
    str, typer.Option("--profile", help="Points to nodes: auto | interpolate | bin.")
]
PaperRowOpt = Annotated[
    str | None,
    typer.Option(
        "--paper-row",
        help="Calibrate on a row of the paper's tables (peak, width, mass), e.g. "
        "table3_winkler_120rpm (the reproduction's calibration row); default parameters "
        "axial_length, bushing_thickness, spring_preload.",
        show_default=False,
    ),
]


ReferenceOpt = Annotated[
    str | None,
    typer.Option(
        "--reference",
        help="Fit the contact laws (Winkler stiffness, NLCP K and n) to an exact reference "
        "instead: fem or persson (with --loads).",
        show_default=False,
    ),
]
LoadsOpt = Annotated[
    str, typer.Option("--loads", help='Loads of the --reference fit, e.g. "50 N,100 N,200 N".')
]


@app.command()
def calibrate(
    config: CalConfigArg = None,
    measured: MeasuredArgs = None,
    fit: FitParamOpt = None,
    case: CaseOpt = None,
    set_: SetOpt = None,
    units: UnitsOpt = None,
    circle_fit: CircleFitOpt = "robust",
    noise: NoiseOpt = None,
    align: AlignOpt = "best",
    profile: ProfileOpt = "auto",
    paper_row: PaperRowOpt = None,
    reference: ReferenceOpt = None,
    loads: LoadsOpt = "50 N,100 N,200 N,400 N",
    json_: JsonOpt = False,
    max_memory: MaxMemoryOpt = None,
) -> None:
    """Fit model parameters to measured wear profiles by least squares.

    Every measured file is simulated with CONFIG (plus its --case settings), and
    the simulated profiles minus the measured ones (each divided by its measured
    peak) are minimised over the --fit parameters. Reports the fitted values with
    1-sigma uncertainties. With --paper-row, fits a paper table row's peak, width
    and mass instead (the reproduction's calibration). With --reference fem|persson,
    fits the contact laws to that exact reference over --loads.
    """
    if reference is not None:
        from jointwear.workflows.calibration import calibrate_contact_laws

        laws = calibrate_contact_laws(
            reference, loads, config=config, overrides=set_ or [], measured=measured or []
        )
        print_contact_laws(laws, loads, json_)
        return
    if paper_row is not None:
        from jointwear.paper.protocol import paper_row_calibration

        summary = paper_row_calibration(
            paper_row,
            config=config,
            overrides=set_ or [],
            fit=fit or [],
            measured=measured or [],
            cases=case or [],
        )
        print_paper_row(summary, json_)
        return
    from jointwear.workflows.calibration import calibrate_to_measurements

    outcome = calibrate_to_measurements(
        config,
        measured or [],
        fit or [],
        cases=case or [],
        overrides=set_ or [],
        units=units,
        circle_fit=circle_fit,
        noise=noise,
        align=align,
        profile=profile,
        max_memory=max_memory,
    )
    summary = outcome.summary()
    if json_:
        emit_json(summary)
        return
    print_measured(summary, f"calibrate: {config.name}, {len(summary['cases'])} case(s)")


def print_measured(summary: dict[str, Any], title: str) -> None:
    """The fitted parameters, their intervals, the residual and each case at the fit."""
    from rich.table import Table

    from jointwear.measurement.parameter_fit import PARAMETER_ALIASES

    console.print(_parameter_table(summary["parameters"], title))
    short = {key: name for name, key in PARAMETER_ALIASES.items()}
    for key, item in summary["parameters"].items():
        low, high = item["interval"]
        if low is not None and high is not None:
            scale, unit = (1e3, "mm") if item["unit"] == "m" else (1.0, item["unit"])
            console.print(
                f"{100 * item['confidence']:.3g} % interval of {short.get(key, key)}: "
                f"{low * scale:.4g} … {high * scale:.4g} {unit}".rstrip(),
                markup=False,
            )
    method = summary["method"]
    console.print(
        f"RMS residual {100 * summary['rms_residual']:.3g} % of the measured peak; "
        f"{method['global_trials']} trials in the global {method['global']} search, "
        f"{method['starts']} least-squares polish(es), {summary['evaluations']} evaluations, "
        f"{summary['simulations']} simulations"
    )
    cases_table = Table(title="cases at the fitted values")
    for column in ("case", "RMS error", "misfit / noise", "peak sim. / meas.", "offset"):
        cases_table.add_column(
            column, justify="left" if column == "case" else "right", overflow="fold"
        )
    for item in summary["cases"]:
        cases_table.add_row(
            item["name"],
            f"{item['rms_error_m'] * 1e6:.3g} µm",
            f"{item['misfit_m'] * 1e6:.3g} / {item['expected_misfit_m'] * 1e6:.3g} µm",
            f"{item['peak_wear_depth_simulated_m'] * 1e6:.4g} / "
            f"{item['peak_wear_depth_measured_m'] * 1e6:.4g} µm",
            f"{item['alignment_offset_deg']:.4g}°",
        )
    console.print(cases_table)
    for item in summary["cases"]:
        if item["overrides"]:
            settings = ", ".join(f"{k}={v}" for k, v in item["overrides"].items())
            console.print(f"{item['name']}: {settings}", markup=False)
    for key, item in summary["parameters"].items():
        if item["at_bound"]:
            console.print(f"note: {key} ended at a bound; widen it (--fit {key}=LOWER..UPPER)")


def print_paper_row(summary: dict[str, Any], json_: bool) -> None:
    """The fitted parameters and the paper's metrics beside the calibrated model's."""
    from rich.table import Table

    from jointwear.paper.cases import PAPER_ROWS

    if json_:
        emit_json(summary)
        return
    row, targets = summary["paper_row"], summary["targets"]
    console.print(_parameter_table(summary["parameters"], f"calibrate: paper row {row}"))
    table = Table(title=f"{PAPER_ROWS[row].table} row {row}: paper vs calibrated model")
    for column in ("metric", "paper", "model", "deviation"):
        table.add_column(column, justify="left" if column == "metric" else "right")
    for key, scale, unit in (
        ("peak_wear_depth_m", 1e3, " mm"),
        ("wear_width_deg", 1.0, "°"),
        ("wear_mass_kg", 1e3, " g"),
    ):
        target, value = targets[key], summary["achieved"][key]
        table.add_row(
            key,
            f"{target * scale:.4g}{unit}",
            f"{value * scale:.4g}{unit}",
            f"{100 * (value / target - 1):+.3g} %",
        )
    console.print(table)
    evaluations = summary["evaluations"]
    console.print(
        f"{evaluations} evaluations; with as many metrics as parameters the fit is "
        "exact and no uncertainty can be estimated"
        if len(summary["parameters"]) >= len(targets)
        else f"{evaluations} evaluations"
    )


def print_contact_laws(laws: Any, loads: str, json_: bool) -> None:
    """The contact laws fitted to a reference: values, uncertainties, equivalents."""
    if json_:
        emit_json(laws.summary())
        return
    console.print(f"contact laws fitted to {laws.reference} over {loads}:", markup=False)
    for name, fit in laws.fits.items():
        console.print(f"  {name} (rms residual {fit.rms_residual:.3g})", markup=False)
        for key, value in fit.values.items():
            console.print(f"    {key} = {value:.6g} ± {fit.uncertainty[key]:.2g}", markup=False)
        for key, value in fit.equivalent.items():
            text = value if isinstance(value, str) else f"{value:.6g}"
            console.print(f"      {key} = {text}", markup=False)


def _parameter_table(parameters: dict[str, dict[str, Any]], title: str) -> Table:
    from rich.table import Table

    from jointwear.measurement.parameter_fit import PARAMETER_ALIASES

    short = {key: name for name, key in PARAMETER_ALIASES.items()}
    table = Table(title=title)
    table.add_column("parameter", overflow="fold")
    table.add_column("value", justify="right", no_wrap=True)
    table.add_column("± 1σ", justify="right", no_wrap=True)
    table.add_column("unit", no_wrap=True)
    table.add_column("initial", justify="right", no_wrap=True)
    table.add_column("bounds", justify="right", no_wrap=True)
    for key, item in parameters.items():
        scale, unit = (1e3, "mm") if item["unit"] == "m" else (1.0, item["unit"])

        def show(value: float | None, digits: int, scale: float = scale) -> str:
            return "-" if value is None or value != value else f"{value * scale:.{digits}g}"

        table.add_row(
            short.get(key, key),
            show(item["value"], 6),
            show(item["uncertainty"], 3),
            unit,
            show(item.get("initial"), 4),
            f"{show(item['lower'], 3)} … {show(item['upper'], 3)}",
        )
    return table
