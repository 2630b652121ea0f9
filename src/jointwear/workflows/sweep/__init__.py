"""Parameter sweeps: many runs of one base configuration, in parallel.

A sweep file (TOML) names a base configuration and the values to vary::

    base = "base.toml"                 # relative to the sweep file
    [set]                              # fixed overrides for every case
    "simulation.revolutions" = 1
    [grid]                             # cartesian product
    "joint.clearance" = ["0.05 mm", "0.1 mm", "0.2 mm"]
    "mechanism.crank_speed" = ["120 rpm", "240 rpm"]
    [zip]                              # lists of equal length, taken row by row
    "contact.model" = ["winkler", "nlcp"]
    "contact.exponent" = [1.0, 1.5]
    [sample]                           # random samples (numpy, seeded)
    "materials.bushing.wear_coefficient" = {distribution = "lognormal",
                                            median = "5.05e-13 m^2/N", sigma = 0.5}
    samples = 8
    seed = 1

The cases are the product grid x zip x samples (each present part counts).
:func:`load_sweep` expands and validates everything before anything runs: an
unknown key or a value that cannot be read fails the whole sweep with one
line naming the sweep file and key. A combination that is invalid only
together (e.g. crank longer than rod) and any error during a case's run are
recorded as a *failed case* instead.

:func:`run_sweep` runs the cases on local processes
(:class:`concurrent.futures.ProcessPoolExecutor`) or on a dask.distributed
cluster, writes one record per case atomically as it finishes
(``DIR/cases/case-NNNN.json``) and finally ``DIR/cases.csv`` and
``DIR/sweep.nc``. ``run_sweep(..., resume=True)`` skips finished cases.

=============================================  ============================================
:mod:`~jointwear.workflows.sweep.plan`         the sweep file read and expanded into cases
:mod:`~jointwear.workflows.sweep.keys`         the swept keys: their fields, units, values
:mod:`~jointwear.workflows.sweep.sampling`     the ``[sample]`` distributions
:mod:`~jointwear.workflows.sweep.case`         one case: its run, record and material checks
:mod:`~jointwear.workflows.sweep.execution`    :func:`run_sweep`, :func:`sweep_to_folder`
:mod:`~jointwear.workflows.sweep.local`        cases here or on a pool of local processes
:mod:`~jointwear.workflows.sweep.cluster`      cases on a dask.distributed cluster
:mod:`~jointwear.workflows.sweep.outputs`      ``cases.csv`` and ``sweep.nc``
=============================================  ============================================
"""

from __future__ import annotations

from jointwear.workflows.sweep.case import (
    CASE_RESULTS,
    CHECK_COLUMNS,
    METRICS,
    case_checks,
    limit_counts,
    run_case,
)
from jointwear.workflows.sweep.execution import (
    SweepResult,
    checked_progress,
    resume_command,
    run_sweep,
    sweep_to_folder,
    writing,
)
from jointwear.workflows.sweep.local import WORKER_START, default_workers
from jointwear.workflows.sweep.outputs import CASES_CSV, DATASET_FILE
from jointwear.workflows.sweep.plan import (
    PLAN_FILE,
    SEED_MAX,
    Case,
    SweepPlan,
    expand_sweep,
    load_plan,
    load_sweep,
    seed_problem,
)
from jointwear.workflows.sweep.sampling import DISTRIBUTIONS

__all__ = [
    "CASES_CSV",
    "CASE_RESULTS",
    "CHECK_COLUMNS",
    "DATASET_FILE",
    "DISTRIBUTIONS",
    "METRICS",
    "PLAN_FILE",
    "SEED_MAX",
    "WORKER_START",
    "Case",
    "SweepPlan",
    "SweepResult",
    "case_checks",
    "checked_progress",
    "default_workers",
    "expand_sweep",
    "limit_counts",
    "load_plan",
    "load_sweep",
    "resume_command",
    "run_case",
    "run_sweep",
    "seed_problem",
    "sweep_to_folder",
    "writing",
]
