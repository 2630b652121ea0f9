"""How wear and the rest of the run feed each other: the schedule of the revolution loop.

One module per topic, each a plain function or small class from one small data object
to the next, used by the loop over revolutions (:class:`jointwear.simulation.Simulation`):

* :mod:`~jointwear.coupling.jumping` — how far a contour update carries the wear
  (fixed intervals, adaptive cycle jumping with error control) and where it ends;
* :mod:`~jointwear.coupling.dynamics` — when the dynamics are solved again on the worn
  joint, and the record of each solve;
* :mod:`~jointwear.coupling.limits` — the ``[life]`` limits and the interpolated stop;
* :mod:`~jointwear.coupling.feedback` — the warnings a run gives once when its wear
  questions its load;
* :mod:`~jointwear.coupling.joints` — a mechanism's several clearance joints, a run each.
"""

from __future__ import annotations

from jointwear.coupling.conditions import revolution_of, wear_law_at
from jointwear.coupling.dynamics import (
    DYNAMICS_COLUMNS,
    DynamicsSchedule,
    JointLoad,
    dynamics_row,
    load_change,
    wear_signature,
    worn_cycle,
)
from jointwear.coupling.feedback import FeedbackWarnings
from jointwear.coupling.jumping import (
    Jumps,
    Solved,
    WearStep,
    adaptive_interval,
    adaptive_step,
    applied,
    grown,
    jump_error,
    linear_marks,
    next_step,
)
from jointwear.coupling.limits import LIFE_LIMITS, LifeLimits, at_stop, joint_geometry

__all__ = [
    "DYNAMICS_COLUMNS",
    "LIFE_LIMITS",
    "DynamicsSchedule",
    "FeedbackWarnings",
    "JointLoad",
    "Jumps",
    "LifeLimits",
    "Solved",
    "WearStep",
    "adaptive_interval",
    "adaptive_step",
    "applied",
    "at_stop",
    "dynamics_row",
    "grown",
    "joint_geometry",
    "jump_error",
    "linear_marks",
    "load_change",
    "next_step",
    "revolution_of",
    "wear_law_at",
    "wear_signature",
    "worn_cycle",
]
