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

from collections.abc import Mapping, Sequence
from typing import Any

from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.measurement.calibrate import DEFAULT_BOUNDS
from jointwear.paper.cases import PAPER_ROWS, case_config, case_names
from jointwear.registry import suggest
from jointwear.workflows.parameter_fit import CalibrationResult, Parameter, calibrate_metrics

__all__ = [
    "CALIBRATION_CASE",
    "CALIBRATION_PARAMETERS",
    "METRIC_ORDER",
    "calibrate_paper_row",
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
