"""The reproduction's protocol: calibrate what the paper leaves open on one table row.

The paper does not give the joint's axial length ``b``, the bushing wall
thickness ``L`` or the spring preload. They are fitted on **one** row
(:data:`CALIBRATION_CASE`: Table 3, Winkler, 120 rpm, 0.05 mm, one revolution)
to its wear peak, width and mass -- three parameters, three targets, an exact
fit -- and every other row is a prediction with those values.
:func:`calibrate_paper_row` does the same on any row, with any parameters (this
is ``jointwear calibrate --paper-row``).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.measurement.parameter_fit import DEFAULT_BOUNDS
from jointwear.paper.cases import PAPER_ROWS, case_config, case_names
from jointwear.registry import suggest
from jointwear.workflows.parameter_fit import CalibrationResult, Parameter, calibrate_metrics

__all__ = [
    "CALIBRATION_CASE",
    "CALIBRATION_PARAMETERS",
    "METRIC_ORDER",
    "calibrate_paper_row",
    "paper_row_calibration",
    "row_config",
]

#: the one row the undisclosed parameters are calibrated on
CALIBRATION_CASE = "table3_winkler_120rpm"
#: the undisclosed parameters, with their search bounds [SI]
CALIBRATION_PARAMETERS = tuple(
    Parameter(key, *DEFAULT_BOUNDS[key])
    for key in ("joint.axial_length", "joint.bushing_thickness", "mechanism.spring_preload")
)
#: the row's metrics (``run --json`` keys) in the order they are fitted when fewer are
#: asked for: the mass pins the load, the width the foundation stiffness
METRIC_ORDER = ("wear_mass_kg", "wear_width_deg", "peak_wear_depth_m")


def row_config(
    row: str, overrides: Mapping[str, Any] | None = None, config: Config | None = None
) -> Config:
    """The config a paper row is calibrated with: its packaged one, or ``config``.

    Parameters
    ----------
    row : str
        A key of :data:`~jointwear.paper.cases.PAPER_ROWS`.
    overrides : mapping, optional
        Dotted-key overrides (values SI numbers or strings with units).
    config : Config, optional
        Use this config instead of the packaged one; ``overrides`` are applied to it.

    Raises
    ------
    ConfigError
        Unknown row (with a suggestion), or no packaged config and no ``config``.
    """
    if row not in PAPER_ROWS:
        raise ConfigError(f"--paper-row: unknown row {row!r}{suggest(row, PAPER_ROWS)}")
    if config is None:
        if row not in case_names():
            raise ConfigError(
                f"--paper-row: no packaged config for {row}; give its CONFIG "
                f"(examples/paper/{row}.toml)"
            )
        return case_config(row, dict(overrides or {}))
    return config.replace(dict(overrides)) if overrides else config


def calibrate_paper_row(
    row: str = CALIBRATION_CASE,
    parameters: Sequence[Parameter] | None = None,
    overrides: Mapping[str, Any] | None = None,
    config: Config | None = None,
    metrics: int | None = None,
) -> CalibrationResult:
    """Calibrate parameters on the wear peak, width and mass of one of the paper's rows.

    With the defaults this is the reproduction's protocol: the calibration row,
    the three undisclosed parameters, three metrics -- an exact fit (no
    uncertainty can be estimated).

    Parameters
    ----------
    row : str
        A key of :data:`~jointwear.paper.cases.PAPER_ROWS`.
    parameters : sequence of Parameter, optional
        What to fit, with bounds [SI]; default :data:`CALIBRATION_PARAMETERS`.
    overrides : mapping, optional
        Dotted-key overrides of the row's packaged config (e.g. coarser grids).
    config : Config, optional
        Use this config instead of the packaged one (needed for rows without a
        packaged config); ``overrides`` are applied to it.
    metrics : int, optional
        Fit only the first ``metrics`` of :data:`METRIC_ORDER` (e.g. as many as
        there are free parameters); default all three.

    Returns
    -------
    CalibrationResult
        Residuals are ``log(metric / paper)`` [-] in the order of :data:`METRIC_ORDER`.

    Raises
    ------
    ConfigError
        Unknown row (with a suggestion), no config for it, or ``metrics`` not 1-3.
    """
    config = row_config(row, overrides, config)
    count = len(METRIC_ORDER) if metrics is None else metrics
    if not 1 <= count <= len(METRIC_ORDER):
        raise ConfigError(f"calibrate: metrics must be 1 to {len(METRIC_ORDER)}, not {metrics}")
    targets = {key: PAPER_ROWS[row].targets[key] for key in METRIC_ORDER[:count]}
    chosen = CALIBRATION_PARAMETERS if parameters is None else parameters
    return calibrate_metrics(config, targets, list(chosen))


def paper_row_calibration(
    row: str,
    *,
    config: Path | None = None,
    overrides: Sequence[str] = (),
    fit: Sequence[str] = (),
    measured: Sequence[Path] = (),
    cases: Sequence[str] = (),
) -> dict[str, Any]:
    """``calibrate --paper-row``: fit a paper row's metrics and compare the calibrated model.

    Parameters
    ----------
    row : str
        A key of :data:`~jointwear.paper.cases.PAPER_ROWS`.
    config : Path, optional
        A config file instead of the row's packaged one (needed for rows without one).
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config.
    fit : sequence of str
        Parameters to fit (as ``calibrate --fit``); default :data:`CALIBRATION_PARAMETERS`.
    measured, cases : sequence
        Must be empty: the paper's table is fitted, not measured files.

    Returns
    -------
    dict
        The ``jointwear calibrate --paper-row --json`` object: ``paper_row``,
        ``parameters`` (per key its value, uncertainty (``None`` where none can be
        estimated), unit, initial value and bounds [SI]), ``rms_residual``,
        ``residual_unit``, ``evaluations``, ``targets`` and ``achieved`` (the paper's
        and the calibrated model's peak [m], width [deg] and mass [kg]).
    """
    from jointwear.config import parse_override
    from jointwear.measurement.parameter_fit import key_unit, parse_fit
    from jointwear.simulation import Simulation
    from jointwear.workflows.inputs import load_config_file
    from jointwear.workflows.parameter_fit import config_value

    if measured or cases:
        raise ConfigError("--paper-row: fits the paper's table, not measured files; drop them")
    if config is not None:
        base = row_config(row, config=load_config_file(config, overrides))
    else:
        base = row_config(row, dict(parse_override(text) for text in overrides))
    parameters = [parse_fit(text, base) for text in fit] if fit else list(CALIBRATION_PARAMETERS)
    result = calibrate_paper_row(row, parameters, config=base)
    achieved = Simulation(result.config).run().summary()
    targets = PAPER_ROWS[row].targets
    return {
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


def _finite(value: float) -> float | None:
    return value if math.isfinite(value) else None
