"""The result of a contact solve: pressure on every node for every load."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

__all__ = ["ContactSolution"]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class ContactSolution:
    """Contact state for ``M`` loads on one bushing contour of ``N`` nodes.

    Attributes
    ----------
    pressure : ndarray, shape (M, N)
        Pressure on each node [Pa].
    eccentricity : ndarray, shape (M, 2)
        Pin-centre position relative to the bushing centre [m].
    penetration : ndarray, shape (M,)
        Penetration at the compression centre (on the load line) [m].
    normal_force : ndarray, shape (M,)
        Resultant of the springs along the load [N].
    tangential_force : ndarray, shape (M,)
        Resultant perpendicular to the load, positive counter-clockwise [N].
    half_angle_left, half_angle_right : ndarray, shape (M,)
        Contact extent counter-clockwise / clockwise of the load line [rad].
    springs_left, springs_right : ndarray of int, shape (M,)
        Springs in contact on each side (paper eq. 6).
    iterations : ndarray of int, shape (M,)
        Residual evaluations of the balance.
    model : str
        Name of the contact model.
    """

    pressure: FloatArray
    eccentricity: FloatArray
    penetration: FloatArray
    normal_force: FloatArray
    tangential_force: FloatArray
    half_angle_left: FloatArray
    half_angle_right: FloatArray
    springs_left: NDArray[np.int64]
    springs_right: NDArray[np.int64]
    iterations: NDArray[np.int64]
    model: str

    def __repr__(self) -> str:
        peak = float(self.pressure.max()) if self.pressure.size else 0.0
        return (
            f"<ContactSolution {self.model}: {self.pressure.shape[0]} loads x "
            f"{self.pressure.shape[1]} nodes, peak pressure {peak / 1e6:.4g} MPa>"
        )

    @property
    def loads(self) -> int:
        """Number of loads ``M``."""
        return self.pressure.shape[0]

    def summary(self, index: int = 0) -> dict[str, float | int | str]:
        """Scalar results of load ``index`` (SI), keyed as ``jointwear contact --json``."""
        return {
            "penetration_m": float(self.penetration[index]),
            "contact_half_angle_left_deg": float(np.degrees(self.half_angle_left[index])),
            "contact_half_angle_right_deg": float(np.degrees(self.half_angle_right[index])),
            "peak_pressure_pa": float(self.pressure[index].max()),
            "resultant_normal_n": float(self.normal_force[index]),
            "resultant_tangential_n": float(self.tangential_force[index]),
            "springs_left": int(self.springs_left[index]),
            "springs_right": int(self.springs_right[index]),
            "iterations": int(self.iterations[index]),
            "contact_model": self.model,
            "eccentricity_x_m": float(self.eccentricity[index, 0]),
            "eccentricity_y_m": float(self.eccentricity[index, 1]),
        }
