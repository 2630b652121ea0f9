r"""A duty cycle: several operating modes of a joint, each run in a share of the cycles.

A joint that digs in 30 % of its cycles and travels in 70 % wears, per cycle on
average, 0.3 of a digging cycle's wear plus 0.7 of a travelling cycle's. Mode ``i``
(any single mechanism type, ``[[mechanism.modes]]``) has its own load cycle and runs
in a fraction ``s_i`` of the cycles, ``sum_i s_i = 1``; the wear per cycle on the
current contour is

.. math:: w = \sum_i s_i \, w_i , \qquad
          w_{i,j} = K_d \sum_{k \in i} p_{jk} \, \Delta s_k ,

the modes taking turns much faster than the contour changes (a mode's wear of one
cycle is a small fraction of the clearance, so the order of the modes within a
contour update does not matter to first order in that fraction).

The modes' load cycles are laid one after the other in one
:class:`~jointwear.mechanism.cycle.LoadCycle` whose :attr:`LoadCycle.duty` names
them, their shares and their steps; the sliding distance of each step is computed
on its own mode's cycle and weighted by the mode's share
(:meth:`LoadCycle.parts`). Everything after the mechanism (contact, wear law, pin
wear, cycle jumping, limits, checkpoints) then works on that one cycle, and its wear
is exactly the share-weighted sum. The per-step outputs of a run keep every mode's
steps, one after the other, with the step's mode (``duty_mode``) and share
(``duty_share``) as diagnostics; ``time`` runs through the modes one after the
other (each mode's own time plus the periods of the modes before it).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from numpy.typing import NDArray

from jointwear.mechanism.base import cycles_of
from jointwear.mechanism.cycle import Diagnostic, DutyModes, LoadCycle
from jointwear.mechanism.inputs import MechanismInputs

__all__ = ["DUTY_CYCLE", "DutyCycleMechanism", "duty_cycle", "join_modes"]

FloatArray = NDArray[np.float64]


def join_modes(cycles: list[LoadCycle], shares: list[float], names: list[str]) -> LoadCycle:
    """The load cycles of a joint's modes laid one after the other, with their shares.

    Parameters
    ----------
    cycles : list of LoadCycle
        The joint's load cycle in each mode.
    shares : list of float
        Fraction of the cycles in each mode [-]; they sum to one.
    names : list of str
        Name of each mode.

    Returns
    -------
    LoadCycle
        Steps of every mode in order; ``time`` offset by the periods of the modes
        before [s]; ``duty`` says which steps are which mode's.
    """
    starts = np.cumsum([0] + [c.steps for c in cycles[:-1]])
    offsets = np.cumsum([0.0] + [c.period for c in cycles[:-1]])
    mode = np.concatenate([np.full(c.steps, float(i)) for i, c in enumerate(cycles)])
    share = np.concatenate([np.full(c.steps, s) for c, s in zip(cycles, shares, strict=True)])
    diagnostics = {
        "duty_mode": Diagnostic(
            mode, "1", "duty-cycle mode of the step (index of mechanism.modes)"
        ),
        "duty_share": Diagnostic(share, "1", "fraction of the cycles in the step's mode"),
    }
    first = cycles[0]
    duty = DutyModes(
        names=tuple(names),
        shares=tuple(float(s) for s in shares),
        starts=tuple(int(s) for s in starts),
        periods=tuple(c.period for c in cycles),
    )
    return LoadCycle(
        time=np.concatenate([c.time + o for c, o in zip(cycles, offsets, strict=True)]),
        load=np.concatenate([c.load for c in cycles]),
        azimuth=np.concatenate([c.azimuth for c in cycles]),
        relative_rotation=np.concatenate([c.relative_rotation for c in cycles]),
        period=float(offsets[-1] + cycles[-1].period),
        mechanism="duty-cycle",
        model=first.model if len({c.model for c in cycles}) == 1 else "mixed",
        joint=first.joint,
        lost_steps=np.concatenate([c.lost_steps for c in cycles]),
        iterations=max(c.iterations for c in cycles),
        converged=all(c.converged for c in cycles),
        diagnostics=diagnostics,
        extras=_extras(cycles, shares, names, duty),
        duty=duty,
    )


def _extras(cycles: list[LoadCycle], shares: list[float], names: list[str], duty: DutyModes):
    """The dynamics summary's scalars of a duty cycle: its modes and their largest loads
    (and, with an oil film, its largest eccentricity and joint force, its least film)."""
    extras: dict[str, object] = {
        "duty_modes": list(names),
        "duty_shares": [float(s) for s in shares],
        "mean_cycle_duration_s": duty.mean_period,
    }
    # the scalars the dynamics record reads, the worst of the modes
    peaks = [float(c.extras.get("peak_load_n", c.load.max())) for c in cycles]
    extras["peak_load_n"] = max(peaks)
    for key in ("impacts", "free_flight_fraction"):
        extras[key] = sum(s * c.extras.get(key, 0) for c, s in zip(cycles, shares, strict=True))
    if "integrator" in cycles[0].extras:  # the contact-impact integrator, one per mechanism
        extras["integrator"] = cycles[0].extras["integrator"]
    if all("film_model" in c.extras for c in cycles):  # an oil film in every mode's dynamics
        extras["film_model"] = cycles[0].extras["film_model"]
        extras["max_eccentricity_ratio"] = max(c.extras["max_eccentricity_ratio"] for c in cycles)
        extras["min_film_thickness_m"] = min(c.extras["min_film_thickness_m"] for c in cycles)
        extras["peak_joint_force_n"] = max(c.extras["peak_joint_force_n"] for c in cycles)
    return extras


def duty_cycle(inputs: MechanismInputs, wear_depth: FloatArray | None = None):
    """Load cycle of every clearance joint of a duty cycle: its modes one after the other.

    Parameters
    ----------
    inputs : MechanismInputs
        The duty cycle's section (``mechanism.modes``), the joint, the dynamics settings;
        each mode is solved with the same joint and settings.
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing [m] (the dynamics of the worn joint); ``None``: unworn.

    Returns
    -------
    dict of str to LoadCycle
        Joint name (the first mode's) -> its duty cycle (:func:`join_modes`).
    """
    modes = inputs.mechanism.modes
    per_mode = [
        list(cycles_of(replace(inputs, mechanism=mode), wear_depth).values()) for mode in modes
    ]
    names = [f"{i}:{mode.type}" for i, mode in enumerate(modes)]
    shares = [mode.share for mode in modes]
    return {
        name: join_modes([cycles[j] for cycles in per_mode], shares, names)
        for j, name in enumerate(inputs.mechanism.joints)
    }


class DutyCycleMechanism:
    """The ``duty-cycle`` mechanism type (:class:`~jointwear.mechanism.Mechanism`)."""

    description = (
        "operating modes run in shares of the cycles: [[mechanism.modes]], each a "
        "[mechanism] table of another type plus share (they sum to 1); wear per cycle "
        "the share-weighted sum"
    )
    # each mode checks the model against its own type
    models = ("massless-link", "contact-impact")

    def load_cycles(
        self, inputs: MechanismInputs, wear_depth: FloatArray | None = None
    ) -> dict[str, LoadCycle]:
        """The duty cycle of every clearance joint (:func:`duty_cycle`)."""
        return duty_cycle(inputs, wear_depth)


DUTY_CYCLE = DutyCycleMechanism()
