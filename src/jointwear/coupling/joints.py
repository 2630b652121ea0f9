"""Several clearance joints of one mechanism: a run of its own for each joint.

Where ``mechanism.clearance_joint`` leaves more than one joint, each wears in a run of
its own from the mechanism's unworn load cycle at that joint (with coupled dynamics the
joint's cycle is solved again as it wears), and each run ends in its own record.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from jointwear.errors import ConfigError
from jointwear.record import RunRecord

__all__ = ["joint_records"]


def joint_records(
    simulation: Any,
    progress: Callable[[float, float], None] | None,
    resumed: bool,
    pressures: bool,
) -> list[RunRecord]:
    """The record of every clearance joint's run, in the order of the mechanism's joints.

    Parameters
    ----------
    simulation : Simulation
        The run of all joints (its ``joint`` None); each joint's run is one of its type
        with the same config, contact model and wear law.
    progress : callable, optional
        Passed to each joint's run (:meth:`Simulation.record`).
    resumed : bool
        Whether a state or a step callback was given (a checkpoint holds one joint).
    pressures : bool
        Solve the pressure snapshots of each joint (:meth:`Simulation.run`).

    Raises
    ------
    ConfigError
        If ``resumed``: checkpoints hold one clearance joint.
    """
    if resumed:
        raise ConfigError(
            "simulation.checkpoint_every: checkpoints hold one clearance joint; give "
            "mechanism.clearance_joint a single joint to checkpoint"
        )
    coupled = simulation.load.schedule.coupled
    records = []
    for joint, cycle in simulation.load.cycles.items():
        run = type(simulation)(
            simulation.config,
            simulation.contact_model,
            None if coupled else cycle,
            joint,
            simulation.wear_law,
        )
        if coupled:
            run.load.use(cycle)
        records.append(run.record(progress, pressures=pressures))
    return records
