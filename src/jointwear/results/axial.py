"""What a run along the pin adds to its results: the ``z`` coordinate and two scalars.

With ``joint.axial_slices = N > 1`` the wear depth is a map over the slices and the
bushing angle: ``wear_depth`` has dimensions ``("revolution", "z", "theta")``,
``wear_rate`` and ``bushing_radius`` ``("z", "theta")``, and the coordinate ``z`` holds
the slice centres ``z_i = (i + 1/2) L / N - L / 2`` [m] (0 at the mid-plane). A planar
run (``N = 1``) keeps ``("revolution", "theta")`` and has no ``z``.

The summary of such a run adds ``peak_wear_z_m`` (the slice centre of the deepest wear)
and ``edge_to_mid_wear_ratio`` (the deeper edge slice's peak over the mid-plane's: the
middle slice's peak, or the mean of the two middle slices' for an even ``N``); a
planar run's summary has neither.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = ["axial_coordinates", "axial_shape", "axial_summary"]

FloatArray = NDArray[np.float64]

#: slices whose peaks differ by less than this fraction are worn alike [-]
TIE = 1e-9


def axial_shape(config: Config, nodes: int) -> tuple[tuple[int, ...], tuple[str, ...]]:
    """Shape and dimensions of one wear profile of a run: ``(nodes,)`` and ``("theta",)``,
    or ``(N, nodes)`` and ``("z", "theta")`` along the pin."""
    count = config.joint.axial_slices
    return ((nodes,), ("theta",)) if count == 1 else ((count, nodes), ("z", "theta"))


def axial_coordinates(config: Config) -> dict[str, tuple[tuple[str, ...], FloatArray, str, str]]:
    """The ``z`` coordinate as ``{name: (dims, values [m], units, long_name)}`` (empty for
    a planar run)."""
    joint = config.joint
    if joint.axial_slices == 1:
        return {}
    from jointwear.contact.axial import AxialSlices  # (only a run along the pin needs it)

    centres = AxialSlices(joint.axial_length, joint.axial_slices).centres
    return {"z": (("z",), centres, "m", "axial position of the slice centre, 0 at mid-plane")}


def axial_summary(wear_depth: ArrayLike, z: ArrayLike) -> dict[str, Any]:
    """``peak_wear_z_m`` and ``edge_to_mid_wear_ratio`` of a final wear map.

    Parameters
    ----------
    wear_depth : array_like, shape (N, nodes)
        The final wear map [m].
    z : array_like, shape (N,)
        Slice centres [m].

    Returns
    -------
    dict
        ``peak_wear_z_m`` [m] (of slices worn alike to :data:`TIE`, the one nearest the
        mid-plane) and ``edge_to_mid_wear_ratio`` [-] (``None`` where the mid-plane has
        not worn).
    """
    depth, z = np.asarray(wear_depth, dtype=float), np.asarray(z, dtype=float)
    peaks = depth.max(axis=1)
    count = peaks.size
    middle = peaks[count // 2] if count % 2 else 0.5 * (peaks[count // 2 - 1] + peaks[count // 2])
    edge = max(peaks[0], peaks[-1])
    # slices worn alike to rounding (an aligned pin) count as one: the nearest the middle
    tied = np.flatnonzero(peaks >= peaks.max() * (1.0 - TIE))
    deepest = int(tied[np.argmin(np.abs(z[tied]))])
    return {
        "peak_wear_z_m": float(z[deepest]),
        "edge_to_mid_wear_ratio": float(edge / middle) if middle > 0 else None,
    }
