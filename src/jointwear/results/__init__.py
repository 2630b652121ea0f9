"""Results as data, built from the plain record a run hands back.

A run of the loop over revolutions ends in a :class:`jointwear.record.RunRecord`; this
package presents it, one module per topic:

* :mod:`~jointwear.results.contents` — the record as named, described plain arrays
  (:class:`ResultContents`), read like the xarray Dataset they become;
* :mod:`~jointwear.results.summary` — the scalar summary (``run --json``,
  ``summary.json``), engineering checks included when asked;
* :mod:`~jointwear.results.files` — netCDF and the per-update metrics CSV;
* :mod:`~jointwear.results.joints` — several clearance joints along a ``joint``
  dimension;
* :mod:`~jointwear.results.wear_result` — :class:`WearResult`, what
  :meth:`jointwear.Simulation.run` returns;

Nothing here imports xarray until a Dataset is asked for or a file is written or read.
"""

from __future__ import annotations

from jointwear.results.contents import (
    PRESSURE_SNAPSHOTS,
    ResultContents,
    ResultVariable,
    build_contents,
)
from jointwear.results.files import (
    WEAR_VARIABLES,
    check_result_content,
    config_of,
    read_result,
    write_metrics_csv,
    write_netcdf,
)
from jointwear.results.joints import combine_joints, joint_datasets, select_joint
from jointwear.results.summary import run_summary, summarize
from jointwear.results.wear_result import WearResult, read_wear_result

__all__ = [
    "PRESSURE_SNAPSHOTS",
    "WEAR_VARIABLES",
    "ResultContents",
    "ResultVariable",
    "WearResult",
    "build_contents",
    "check_result_content",
    "combine_joints",
    "config_of",
    "joint_datasets",
    "read_result",
    "read_wear_result",
    "run_summary",
    "select_joint",
    "summarize",
    "write_metrics_csv",
    "write_netcdf",
]
