r"""The massless-link model of the slider-crank (paper eqs. 10-12), iterated to a fixed point.

**Massless-link model** (paper eqs. 10-12). The clearance is a massless link CD of
length ``e`` (the radial clearance). Under the continuous-contact hypothesis the
pin rests on the bushing wall in the direction of the load, so ``C - D = e n``
with ``n = J / |J|`` (this holds whichever body carries the bushing: with the
bushing in the rod, the pin on the slider presses on it with ``-J`` and the
bushing centre C sits at ``e n`` from the pin centre D). Closure of the loop
A-B-C-D, eq. (10), gives the rod angle and slider position for a given load
direction; the inverse dynamics then gives the load for that geometry. Both are
iterated to a fixed point (:func:`solve_massless_link`). The paper's ``gamma``
(direction of the link from C to D in eq. 10) is the direction of ``-J``.
"""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import replace
from typing import Any, Literal, NamedTuple

import numpy as np
from numpy.typing import NDArray

from jointwear.errors import ContactLossWarning, ConvergenceError, MechanismError
from jointwear.mechanism.cycle import LoadCycle
from jointwear.mechanism.inputs import MechanismInputs
from jointwear.mechanism.slider_crank.dynamics import (
    JointReaction,
    SliderCrank,
    SpringMode,
    inverse_dynamics,
)
from jointwear.mechanism.slider_crank.joint_load import slider_crank_cycle
from jointwear.mechanism.slider_crank.kinematics import (
    SliderCrankMotion,
    clearance_motion,
    crank_angle_grid,
    ideal_motion,
    load_bandwidth,
)

__all__ = [
    "MasslessLinkSolution",
    "contact_loss",
    "massless_link_load",
    "solve_massless_link",
]

FloatArray = NDArray[np.float64]


class MasslessLinkSolution(NamedTuple):
    """Self-consistent motion and load of the massless-link model.

    Attributes
    ----------
    motion : SliderCrankMotion
        Motion with the clearance link along the load.
    reaction : JointReaction
        Joint force and crank torque for that motion.
    iterations : int
        Geometry updates used by the fixed point (0 without clearance).
    bandwidth : int
        Highest harmonic of the crank frequency kept in the clearance
        correction's derivatives [-].
    """

    motion: SliderCrankMotion
    reaction: JointReaction
    iterations: int
    bandwidth: int


def solve_massless_link(
    mechanism: SliderCrank,
    crank_speed: float,
    clearance: float,
    steps: int,
    tolerance: float = 1e-12,
    max_iterations: int = 50,
    scheme: Literal["fixed-point", "paper"] = "fixed-point",
) -> MasslessLinkSolution:
    """Load and geometry of the massless-link model, iterated to a fixed point.

    Start from the load of the ideal mechanism, place the clearance link along
    it (eq. 10), recompute the load for that geometry (eq. 11) and repeat until
    the load changes by at most ``tolerance * max|J|`` at every step. The
    paper's scheme is the first pass of this loop.

    Parameters
    ----------
    mechanism : SliderCrank
        Mechanism data.
    crank_speed : float
        Constant crank angular velocity ``omega`` [rad/s].
    clearance : float
        Radial clearance ``e`` (``0`` gives the ideal mechanism) [m].
    steps : int
        Time steps ``N`` per revolution [-].
    tolerance : float
        Relative tolerance of the fixed point on the load vector [-].
    max_iterations : int
        Largest number of geometry updates [-].
    scheme : {"fixed-point", "paper"}
        ``"fixed-point"`` iterates to self-consistency; ``"paper"`` stops after
        one geometry update (link along the ideal load, paper section 3.1).

    Returns
    -------
    MasslessLinkSolution

    Raises
    ------
    ConvergenceError
        If the fixed point is not reached within ``max_iterations``.

    Notes
    -----
    The link direction is a degree of freedom with its own dynamics: the pin
    can swing along the bushing wall like a pendulum held by the load, with
    ``omega_n^2 ~ |J| / (m_eff e)``. A perturbation of harmonic ``m`` of the
    crank frequency comes back multiplied by about ``(m omega / omega_n)^2``, so
    the plain iteration amplifies round-off in harmonics above ``omega_n /
    omega`` (for the paper's mechanism at 240 rpm and 0.2 mm clearance that is
    harmonic ~50, inside the 180 a 360-step grid resolves) and ends on a
    spurious pin flutter. The load of the ideal mechanism is band-limited (its
    harmonics fall below round-off by about the 20th), so the correction is
    differentiated as a signal band-limited to the ideal load's harmonics
    (:func:`load_bandwidth`), which keeps the physical solution and drops the
    noise. If ``omega_n`` itself falls inside that band, the clearance mode is
    excited, the continuous-contact model breaks down and the iteration
    diverges (``ConvergenceError``).

    The solutions of the last few argument sets are kept (their arrays read-only): a
    coupled contact-impact run asks for the same one at every solve of the worn joint
    (its initial state and the comparison with the massless-link load).
    """
    return _kept_solution(
        mechanism, float(crank_speed), float(clearance), int(steps), float(tolerance),
        int(max_iterations), scheme,
    )  # fmt: skip


@functools.lru_cache(maxsize=16)
def _kept_solution(*arguments: Any) -> MasslessLinkSolution:
    """:func:`_fixed_point` of ``arguments``, its arrays made read-only to be shared."""
    solution = _fixed_point(*arguments)
    for part in (solution.motion, solution.reaction):
        for value in part:
            if isinstance(value, np.ndarray):
                value.flags.writeable = False
    return solution


def _fixed_point(
    mechanism: SliderCrank,
    crank_speed: float,
    clearance: float,
    steps: int,
    tolerance: float,
    max_iterations: int,
    scheme: str,
) -> MasslessLinkSolution:
    """The fixed point of :func:`solve_massless_link` (its arguments)."""
    if clearance < 0.0:
        raise MechanismError(f"joint.clearance: must be >= 0, got {clearance:g} m")
    phi = crank_angle_grid(steps)
    motion = ideal_motion(phi, mechanism.crank_length, mechanism.rod_length, crank_speed)
    reaction = inverse_dynamics(motion, mechanism)
    bandwidth = load_bandwidth(reaction.force_x, reaction.force_y)
    if clearance == 0.0:
        return MasslessLinkSolution(motion, reaction, 0, bandwidth)
    if scheme not in ("fixed-point", "paper"):
        raise ValueError(f"unknown scheme {scheme!r}; choose 'fixed-point' or 'paper'")
    change = math.inf
    for iteration in range(1, max_iterations + 1):
        motion = clearance_motion(
            np.arctan2(reaction.force_y, reaction.force_x),
            clearance,
            mechanism.crank_length,
            mechanism.rod_length,
            crank_speed,
            bandwidth,
        )
        updated = inverse_dynamics(motion, mechanism)
        scale = float(np.max(np.hypot(updated.force_x, updated.force_y)))
        change = float(
            np.max(np.hypot(updated.force_x - reaction.force_x, updated.force_y - reaction.force_y))
        )
        reaction = updated
        if scheme == "paper" or change <= tolerance * scale:
            return MasslessLinkSolution(motion, reaction, iteration, bandwidth)
    raise ConvergenceError(
        f"dynamics.max_iterations: the massless-link force/geometry iteration did not "
        f"converge in {max_iterations} iterations (last change {change:.3g} N, "
        f"dynamics.fixed_point_tolerance = {tolerance:g} relative); a large clearance, "
        f"high crank speed or small load lets the pin swing in the clearance at a "
        f"frequency the load excites, outside the continuous-contact model"
    )


def contact_loss(
    motion: SliderCrankMotion, reaction: JointReaction, spring_mode: SpringMode
) -> NDArray[np.bool_]:
    """Steps where the joint force reverses relative to the rod.

    The massless-link model holds only while the axial component of the joint
    force keeps the sense the spring gives it: ``"pull"`` keeps the rod in
    tension (the force on the slider points from C towards B,
    ``J . (B - C) > 0``), ``"push"`` keeps it in compression (``J . (B - C) < 0``).

    Parameters
    ----------
    motion : SliderCrankMotion
        Motion (its rod angle is used).
    reaction : JointReaction
        Joint force of that motion.
    spring_mode : {"pull", "push"}
        Sense of the spring.

    Returns
    -------
    ndarray of bool
        True where the model's continuous-contact assumption fails.
    """
    theta = np.asarray(motion.rod_angle, dtype=float)
    # J . (B - C) / l2: component of J along the rod, towards the crank pin
    towards_crank = -(reaction.force_x * np.cos(theta) + reaction.force_y * np.sin(theta))
    if spring_mode == "pull":
        return towards_crank <= 0.0
    return towards_crank >= 0.0


def _angle_ranges(indices: NDArray[np.int64], steps: int) -> str:
    """``"0-12, 350-359"``: runs of consecutive steps as crank angles in degrees."""
    if indices.size == 0:
        return ""
    breaks = np.flatnonzero(np.diff(indices) != 1)
    starts = np.concatenate(([indices[0]], indices[breaks + 1]))
    ends = np.concatenate((indices[breaks], [indices[-1]]))
    to_deg = 360.0 / steps
    parts = [
        f"{s * to_deg:.4g}" if s == e else f"{s * to_deg:.4g}-{e * to_deg:.4g}"
        for s, e in zip(starts, ends, strict=True)
    ]
    return ", ".join(parts)


def _contact_loss_message(lost: NDArray[np.bool_], spring_mode: SpringMode) -> str:
    indices = np.flatnonzero(lost)
    state = "tension" if spring_mode == "pull" else "compression"
    return (
        f"dynamics.model: the massless-link model assumes continuous contact, but the joint "
        f"force reverses relative to the rod (spring_mode={spring_mode!r} needs the rod in "
        f"{state}) at {indices.size} of {lost.size} steps, crank angles "
        f"{_angle_ranges(indices, lost.size)} deg; raise mechanism.spring_preload or "
        f"lower mechanism.crank_speed"
    )


def massless_link_load(inputs: MechanismInputs, wear_depth: FloatArray | None = None) -> LoadCycle:
    """Joint load over one revolution from the massless-link model (eqs. 10-12).

    Parameters
    ----------
    inputs : MechanismInputs
        Uses the slider-crank's ``[mechanism]`` section, the joint's clearance, the
        ``[dynamics]`` settings of the model (``strict``, ``scheme``,
        ``fixed_point_tolerance``, ``max_iterations``) and the steps per revolution.
    wear_depth : ndarray, shape (N,), optional
        Wear depth of the bushing [m]: on the worn joint the pin rests in the scar, so
        the link is the clearance plus the deepest wear. ``None``: the unworn joint.

    Returns
    -------
    LoadCycle
        Load, its azimuth in the frame of ``mechanism.bushing_body`` and the
        relative rotation of pin and bushing per step.

    Warns
    -----
    ContactLossWarning
        If the joint force reverses relative to the rod somewhere (the result
        is then outside the model's validity).

    Raises
    ------
    MechanismError
        Instead of the warning when ``dynamics.strict`` is true.
    ConvergenceError
        If the force/geometry fixed point does not converge.
    """
    if wear_depth is not None and np.any(wear_depth):
        worn = inputs.joint.with_clearance(inputs.clearance + float(wear_depth.max()))
        inputs = replace(inputs, joint=worn)
    mechanism = SliderCrank.from_config(inputs.mechanism)
    spring_mode = mechanism.spring_mode
    strict = inputs.dynamics.strict
    # the ideal mechanism first: if its load reverses, the clearance iteration may
    # not converge (the pin would jump across the clearance), so report that first
    ideal = solve_massless_link(mechanism, inputs.mechanism.crank_speed, 0.0, inputs.steps)
    ideal_lost = contact_loss(ideal.motion, ideal.reaction, spring_mode)
    if ideal_lost.any() and strict:
        raise MechanismError(_contact_loss_message(ideal_lost, spring_mode))
    solution, converged = _clearance_solution(mechanism, inputs, ideal_lost.any())
    lost = contact_loss(solution.motion, solution.reaction, spring_mode)
    fallback = ""
    if not converged:
        lost |= ideal_lost
        fallback = (
            "; the force/geometry fixed point does not converge, so the paper's "
            "one-pass scheme (clearance link along the ideal load) is reported"
        )
    if lost.any():
        message = _contact_loss_message(lost, spring_mode) + fallback
        if strict:
            raise MechanismError(message)
        warnings.warn(message, ContactLossWarning, stacklevel=2)

    motion, reaction = solution.motion, solution.reaction
    theta = motion.rod_angle
    return slider_crank_cycle(
        inputs.mechanism,
        reaction.force_x,
        reaction.force_y,
        theta,
        # exact increment of the rod angle over each step (periodic: step N-1 ends at step 0)
        np.roll(theta, -1) - theta,
        motion.slider_position,
        reaction.crank_torque,
        model="massless-link",
        lost_steps=lost,
        iterations=solution.iterations,
        converged=converged,
    )


def _clearance_solution(
    mechanism: SliderCrank, inputs: MechanismInputs, ideal_lost: bool
) -> tuple[MasslessLinkSolution, bool]:
    """The fixed point with the clearance, or the paper's one pass where the load reverses.

    Returns the solution and whether the fixed point converged.
    """
    omega, steps, dynamics = inputs.mechanism.crank_speed, inputs.steps, inputs.dynamics
    try:
        solution = solve_massless_link(
            mechanism, omega, inputs.clearance, steps,
            tolerance=dynamics.fixed_point_tolerance,
            max_iterations=dynamics.max_iterations,
            scheme=dynamics.scheme,
        )  # fmt: skip
    except ConvergenceError:
        if not ideal_lost:
            raise
        # where the load reverses, the pin would have to jump across the clearance
        # and no continuous-contact fixed point exists; the user asked for a
        # warning, not an error, so give the paper's one-pass answer, flagged
        return solve_massless_link(mechanism, omega, inputs.clearance, steps, scheme="paper"), False
    return solution, True
