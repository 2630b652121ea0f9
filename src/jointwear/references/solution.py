"""What the reference models share: checked loads, one solved state per load, and the
:class:`~jointwear.contact.ContactSolution` sampled from those states on the contour nodes."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.solution import ContactSolution
from jointwear.errors import ContactError
from jointwear.geometry.angles import wrap_angle
from jointwear.geometry.contour import BushingContour

__all__ = [
    "ReferenceState",
    "assemble_solution",
    "check_loads",
    "edge_from_pressure",
]

FloatArray = NDArray[np.float64]


def check_loads(load: ArrayLike, azimuth: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """Validate and broadcast loads and azimuths to 1-D arrays.

    Parameters
    ----------
    load : array_like
        Load magnitudes [N], finite and >= 0.
    azimuth : array_like
        Load directions [rad], broadcast against ``load``.
    """
    load = np.asarray(load, dtype=float).ravel()
    azimuth = np.broadcast_to(np.asarray(azimuth, dtype=float).ravel(), load.shape).copy()
    if not (np.all(np.isfinite(load)) and np.all(np.isfinite(azimuth))):
        raise ContactError("load: loads and azimuths must be finite")
    if np.any(load < 0):
        raise ContactError("load: must be >= 0 (the azimuth gives the direction)")
    return load, azimuth


@dataclass(frozen=True)
class ReferenceState:
    """Solution of a reference model for one load.

    Attributes
    ----------
    pressure : callable
        ``pressure(theta)`` on the bushing at absolute angles ``theta`` [rad -> Pa].
    eccentricity : ndarray, shape (2,)
        Pin-centre displacement from the bushing centre [m].
    penetration : float
        Approach: pin displacement along the load minus the clearance at the
        compression centre [m].
    normal_force, tangential_force : float
        Resultant of the contact pressure along / across the load [N].
    half_angle_left, half_angle_right : float
        Contact extent counter-clockwise / clockwise of the load line [rad].
    iterations : int
        Solver iterations (model specific).
    """

    pressure: Callable[[FloatArray], FloatArray]
    eccentricity: FloatArray
    penetration: float
    normal_force: float
    tangential_force: float
    half_angle_left: float
    half_angle_right: float
    iterations: int


def assemble_solution(
    contour: BushingContour,
    azimuth: FloatArray,
    states: Sequence[ReferenceState],
    model: str,
) -> ContactSolution:
    """Sample reference states on the contour nodes and build a :class:`ContactSolution`.

    Parameters
    ----------
    contour : BushingContour
        The contour whose nodes receive the pressure.
    azimuth : ndarray, shape (M,)
        Load directions [rad].
    states : sequence of ReferenceState
        One solved state per load.
    model : str
        Model name.
    """
    m = len(states)
    theta = contour.theta
    pressure = np.zeros((m, contour.nodes))
    for i, state in enumerate(states):
        row = np.maximum(state.pressure(theta), 0.0)
        # round-off specks at the contact edges are not contact
        row[row <= 1e-12 * row.max(initial=0.0)] = 0.0
        pressure[i] = row
    phi = wrap_angle(theta[None, :] - azimuth[:, None])
    contact = pressure > 0
    return ContactSolution(
        pressure=pressure,
        eccentricity=np.array([s.eccentricity for s in states], dtype=float).reshape(m, 2),
        penetration=np.array([s.penetration for s in states], dtype=float),
        normal_force=np.array([s.normal_force for s in states], dtype=float),
        tangential_force=np.array([s.tangential_force for s in states], dtype=float),
        half_angle_left=np.array([s.half_angle_left for s in states], dtype=float),
        half_angle_right=np.array([s.half_angle_right for s in states], dtype=float),
        springs_left=(contact & (phi > 0)).sum(axis=1).astype(np.int64),
        springs_right=(contact & (phi < 0)).sum(axis=1).astype(np.int64),
        iterations=np.array([s.iterations for s in states], dtype=np.int64),
        model=model,
    )


def edge_from_pressure(
    angle_in: float, angle_out: float, p_in: float, p_prev: float | None
) -> float:
    """Contact edge between the last loaded node and the first free one [rad].

    The pressure at a smooth contact edge vanishes like a square root, so ``p^2``
    is linear in the angle: extrapolate it from the last two loaded nodes,
    clamped to the interval between the last loaded and the first free node.

    Parameters
    ----------
    angle_in, angle_out : float
        Angles of the last loaded and first free node [rad].
    p_in : float
        Pressure at the last loaded node [Pa].
    p_prev : float or None
        Pressure at the loaded node before it [Pa] (None if there is none).
    """
    step = angle_out - angle_in
    if p_prev is None or p_prev <= p_in or p_in <= 0:
        return angle_in + 0.5 * step
    frac = p_in**2 / (p_prev**2 - p_in**2)
    return angle_in + min(max(frac, 0.0), 1.0) * step
