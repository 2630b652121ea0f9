"""How the joint runs, for a wear law that reads it: sliding speed and distance slid.

A wear law of :mod:`jointwear.tribology.operating` (``needs_conditions``) is handed,
with the pressure and the sliding distance of a cycle, the
:class:`~jointwear.tribology.operating.WearConditions` of that cycle: the sliding speed
of each step and the distance slid since the joint was new. :func:`wear_law_at` binds
them for the cycle a rate is asked at; :func:`revolution_of` says which cycle that is.
"""

from __future__ import annotations

from functools import partial
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from jointwear.tribology.operating import WearConditions
from jointwear.tribology.sliding import SLIDING_MODELS

if TYPE_CHECKING:
    from jointwear.coupling.dynamics import JointLoad
    from jointwear.state import SimulationState

__all__ = ["revolution_of", "sliding_speed", "wear_law_at"]

FloatArray = NDArray[np.float64]


def sliding_speed(load: JointLoad) -> FloatArray:
    """Sliding speed of each step of the current cycle [m/s].

    The step's sliding distance (``simulation.sliding``, at ``R_b``) over its duration,
    each mode of a duty cycle on its own cycle and not weighted by its share.

    Parameters
    ----------
    load : JointLoad
        The joint's load.
    """
    slide = SLIDING_MODELS.get(load.config.simulation.sliding)
    radius = load.config.joint.bushing_radius
    parts = [slide(part, radius) / part.step_duration for _, part in load.cycle.parts()]
    return parts[0] if len(parts) == 1 else np.concatenate(parts)


def wear_law_at(law: Any, load: JointLoad, revolution: float) -> Any:
    """``law``, with the conditions of the cycle that starts after ``revolution`` cycles
    bound where it reads them (any other law as it is).

    Parameters
    ----------
    law : callable
        The run's wear law.
    load : JointLoad
        The joint's load (its sliding distance per cycle: the distance slid is
        ``revolution`` times it [m]).
    revolution : float
        Cycles run before [-].
    """
    if not getattr(law, "needs_conditions", False):
        return law
    distance = revolution * float(np.sum(load.sliding_distance))
    return partial(law, conditions=WearConditions(sliding_speed(load), distance))


def revolution_of(state: SimulationState | None, wear_depth: FloatArray, ahead: int) -> float:
    """The cycle a rate of the loop is asked at [-].

    The loop asks for the rate on the state's own wear (at its revolution) or on a
    predicted wear ``ahead`` revolutions on (an adaptive jump's end).

    Parameters
    ----------
    state : SimulationState or None
        The state of the loop (``None``: the unworn joint, revolution 0).
    wear_depth : ndarray
        The wear the rate is asked on [m].
    ahead : int
        Revolutions on from the state's [-].
    """
    if state is None:
        return 0.0
    return float(state.revolution + (0 if wear_depth is state.wear_depth else ahead))
