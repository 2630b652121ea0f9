"""``jointwear calibrate``: fit parameters to measured wear profiles or to a paper row."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Any

import typer
from rich.table import Table

from jointwear.cli.common import (
    JsonOpt,
    MaxMemoryOpt,
    SetOpt,
    UnitsOpt,
    app,
    console,
    emit_json,
    load,
)
from jointwear.errors import ConfigError

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
        _reference(reference, loads, config, measured, set_, json_)
        return
    if paper_row is not None:
        _paper(paper_row, config, measured, case, fit, set_, json_)
        return

    from jointwear.cli.compare_cmd import parse_align
    from jointwear.measurement.calibrate import (
        PARAMETER_ALIASES,
        MeasuredCase,
        calibrate_profiles,
        parse_case,
        parse_fit,
    )
    from jointwear.measurement.compare import CIRCLE_FITS, PROFILE_CHOICES
    from jointwear.measurement.io import length_unit_factor
    from jointwear.registry import suggest
    from jointwear.resources import check_run
    from jointwear.units import to_si

    if config is None:
        raise ConfigError("CONFIG: missing; give the config of the measured runs (or --paper-row)")
    if config.suffix.lower() != ".toml" and config.suffix.lower() in {".csv", ".txt", ".dat"}:
        raise ConfigError(f"CONFIG: {config} looks like a measurement; give the config first")
    base = load(config, set_)
    check_run(base, max_memory)  # every trial is a run of this size
    if not fit:
        raise ConfigError("--fit: name at least one parameter, e.g. --fit wear_coefficient")
    parameters = [parse_fit(text, base) for text in fit]
    keys = [p.key for p in parameters]
    if len(set(keys)) != len(keys):
        raise ConfigError("--fit: a parameter is named twice")
    fit_name = circle_fit.replace("_", "-")
    if fit_name not in CIRCLE_FITS:
        raise ConfigError(
            f"--circle-fit: unknown circle fit {circle_fit!r}{suggest(fit_name, CIRCLE_FITS)}"
        )
    if profile not in PROFILE_CHOICES:
        raise ConfigError(
            f"--profile: unknown method {profile!r}{suggest(profile, PROFILE_CHOICES)}"
        )
    alignment = parse_align(align)
    noise_m = None
    if noise is not None:
        noise_m = to_si(noise, "length", "--noise")
        if not noise_m > 0:
            raise ConfigError(f"--noise: must be > 0, got {noise!r}")
    if units is not None:
        length_unit_factor(units, "--units")
    specs: list[tuple[Path, dict[str, Any]]] = [(path, {}) for path in measured or []]
    specs += [parse_case(text) for text in case or []]
    if not specs:
        raise ConfigError("MEASURED: give at least one measured file (or --case FILE:...)")
    cases = [MeasuredCase.from_file(path, overrides, units, alignment) for path, overrides in specs]
    seen: dict[str, int] = {}
    for i, item in enumerate(cases):
        # the same file (name) twice, e.g. with other settings: number the repeats
        seen[item.name] = seen.get(item.name, 0) + 1
        if seen[item.name] > 1:
            cases[i] = MeasuredCase(
                f"{item.name}#{seen[item.name]}", item.x, item.y, item.overrides, item.align
            )
    outcome = calibrate_profiles(
        base, cases, parameters, fit=fit_name, profile=profile, noise=noise_m
    )
    summary = outcome.summary()
    if json_:
        emit_json(summary)
        return
    title = f"calibrate: {config.name}, {len(cases)} case(s)"
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


def _paper(
    row: str,
    config: Path | None,
    measured: list[Path] | None,
    case: list[str] | None,
    fit: list[str] | None,
    set_: list[str] | None,
    json_: bool,
) -> None:
    """``calibrate --paper-row``: fit the paper's metrics of one table row."""
    from jointwear.config import parse_override
    from jointwear.measurement.calibrate import key_unit, parse_fit
    from jointwear.paper.cases import PAPER_ROWS
    from jointwear.paper.protocol import (
        CALIBRATION_PARAMETERS,
        calibrate_paper_row,
        row_config,
    )
    from jointwear.simulation import Simulation
    from jointwear.workflows.parameter_fit import config_value

    if measured or case:
        raise ConfigError("--paper-row: fits the paper's table, not measured files; drop them")
    if config is not None:
        base = row_config(row, config=load(config, set_))
    else:
        base = row_config(row, dict(parse_override(text) for text in set_ or []))
    parameters = [parse_fit(text, base) for text in fit] if fit else list(CALIBRATION_PARAMETERS)
    result = calibrate_paper_row(row, parameters, config=base)
    achieved = Simulation(result.config).run().summary()
    paper = PAPER_ROWS[row]
    targets = paper.targets
    summary = {
        "paper_row": row,
        "parameters": {
            p.key: {
                "value": result.values[p.key],
                "uncertainty": _finite(result.uncertainty[p.key]),
                "unit": key_unit(p.key),
                "initial": config_value(base, p.key),
                "lower": p.lower,
                "upper": p.upper,
            }
            for p in parameters
        },
        "rms_residual": result.rms_residual,
        "residual_unit": "log(metric / paper)",
        "evaluations": result.evaluations,
        "targets": targets,
        "achieved": {key: achieved[key] for key in targets},
    }
    if json_:
        emit_json(summary)
        return
    console.print(_parameter_table(summary["parameters"], f"calibrate: paper row {row}"))
    table = Table(title=f"{paper.table} row {row}: paper vs calibrated model")
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
    console.print(
        f"{result.evaluations} evaluations; with as many metrics as parameters the fit is "
        "exact and no uncertainty can be estimated"
        if len(parameters) >= len(targets)
        else f"{result.evaluations} evaluations"
    )


def _finite(value: float) -> float | None:
    return value if math.isfinite(value) else None


def _parameter_table(parameters: dict[str, dict[str, Any]], title: str) -> Table:
    from jointwear.measurement.calibrate import PARAMETER_ALIASES

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


def _reference(reference, loads, config, measured, set_, json_) -> None:
    """``calibrate --reference``: Winkler's stiffness and NLCP's K, n fitted to a reference."""
    from jointwear.cli.compare_models_cmd import parse_loads
    from jointwear.config import load_config
    from jointwear.contact import ContactParameters
    from jointwear.references.calibrate import calibrate_to_reference

    if reference not in ("fem", "persson"):
        from jointwear.registry import suggest

        raise ConfigError(
            f"--reference: unknown reference {reference!r}{suggest(reference, ['fem', 'persson'])}"
        )
    if measured:
        raise ConfigError("--reference: fits the contact laws to a reference, not measured files")
    cfg = load(config, set_) if config is not None else load_config(overrides=set_ or [])
    force = parse_loads(loads)
    fits = calibrate_to_reference(
        ContactParameters.from_config(cfg), force, reference=reference, nodes=cfg.contact.nodes
    )
    if json_:
        emit_json(
            {
                "reference": reference,
                "loads_n": force,
                "fits": {name: fit.to_json() for name, fit in fits.items()},
            }
        )
        return
    console.print(f"contact laws fitted to {reference} over {loads}:", markup=False)
    for name, fit in fits.items():
        console.print(f"  {name} (rms residual {fit.rms_residual:.3g})", markup=False)
        for key, value in fit.values.items():
            console.print(f"    {key} = {value:.6g} ± {fit.uncertainty[key]:.2g}", markup=False)
        for key, value in fit.equivalent.items():
            text = value if isinstance(value, str) else f"{value:.6g}"
            console.print(f"      {key} = {text}", markup=False)
