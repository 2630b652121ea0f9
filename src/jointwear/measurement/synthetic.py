"""Synthetic measurements of worn bushings, for tests, docs and method studies.

A synthetic measurement is what an optical measuring instrument would report
for a bushing of unworn radius ``R0`` worn by a known profile ``h(theta)``:
points ``R0 + h(theta) + noise`` at (randomly spaced) angles, expressed in the
instrument's frame, which is shifted and rotated with respect to the bushing's.
Because the truth is known, the fits of :mod:`jointwear.measurement.fit` can be
checked against it.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import DataError
from jointwear.geometry import node_angles
from jointwear.geometry.angles import wrap_angle

__all__ = ["cosine_squared_scar", "synthesize_measurement"]

FloatArray = NDArray[np.float64]


def cosine_squared_scar(
    nodes: int, peak_depth: float, width: float, center_angle: float = 0.0
) -> FloatArray:
    """A smooth one-sided wear scar ``h = peak cos^2(pi phi / width)`` on the node grid.

    Parameters
    ----------
    nodes : int
        Number of nodes ``N`` of the grid ``theta_j = 2 pi j / N``.
    peak_depth : float
        Depth at the scar centre [m].
    width : float
        Full angular support of the scar [rad], ``0 < width <= 2 pi``; the depth
        is zero for ``|phi| >= width / 2``. The width at 1 % of the peak (the
        paper's metric) is ``width * arccos(0.1) / (pi / 2)``, about 0.936 of it.
    center_angle : float
        Angle of the deepest point [rad].

    Returns
    -------
    ndarray, shape (N,)
        Wear depth [m].
    """
    if not 0 < width <= 2 * np.pi:
        raise DataError(f"scar width must be in (0, 2 pi] rad, got {width!r}")
    # angle from the scar centre
    phi = wrap_angle(node_angles(nodes) - center_angle)
    depth = peak_depth * np.cos(np.pi * phi / width) ** 2
    return np.where(np.abs(phi) < width / 2, depth, 0.0)


def synthesize_measurement(
    wear_depth: ArrayLike,
    original_radius: float,
    n_points: int,
    noise_std: float,
    rng: np.random.Generator | int | None = None,
    center: tuple[float, float] = (0.0, 0.0),
    rotation: float = 0.0,
    random_spacing: bool = True,
) -> tuple[FloatArray, FloatArray]:
    """Points an instrument would measure on a worn bushing.

    In the bushing's frame a point at angle ``theta`` lies at radius
    ``R0 + h(theta) + noise``, ``h`` interpolated periodically (linearly) from
    the node grid. The instrument's frame is the bushing's rotated by
    ``rotation`` and shifted by ``center``: a feature at bushing angle
    ``theta`` appears at angle ``theta + rotation`` about ``center``. Hence
    :func:`~jointwear.measurement.profile.measured_wear_profile` with
    ``angle_offset=rotation`` and the true centre gives back ``h``.

    Parameters
    ----------
    wear_depth : array_like, shape (N,)
        Wear depth at ``theta_j = 2 pi j / N`` in the bushing frame [m].
    original_radius : float
        Unworn radius ``R0`` [m].
    n_points : int
        Number of points.
    noise_std : float
        Standard deviation of the Gaussian radial noise [m].
    rng : numpy.random.Generator or int, optional
        Random generator or seed.
    center : tuple of float
        Bushing centre in the instrument frame [m].
    rotation : float
        Rotation of the bushing frame in the instrument frame [rad].
    random_spacing : bool
        Uniformly random angles if True, else equally spaced angles starting at 0.

    Returns
    -------
    x, y : ndarray, shape (n_points,)
        Point coordinates in the instrument frame [m], in angular order.
    """
    depth = np.asarray(wear_depth, dtype=float)
    if depth.ndim != 1 or depth.size < 2:
        raise DataError("synthetic measurement: wear_depth must be a 1-D profile on the node grid")
    if not (np.isfinite(original_radius) and original_radius > 0):
        raise DataError(
            f"synthetic measurement: original radius must be > 0, got {original_radius!r}"
        )
    if n_points < 1:
        raise DataError(f"synthetic measurement: n_points must be >= 1, got {n_points!r}")
    if not (np.isfinite(noise_std) and noise_std >= 0):
        raise DataError(f"synthetic measurement: noise_std must be >= 0, got {noise_std!r}")
    generator = np.random.default_rng(rng)
    if random_spacing:
        theta = np.sort(generator.uniform(0.0, 2 * np.pi, n_points))
    else:
        theta = 2 * np.pi * np.arange(n_points) / n_points
    radius = (
        original_radius
        + np.interp(theta, node_angles(depth.size), depth, period=2 * np.pi)
        + generator.normal(0.0, noise_std, n_points)
    )
    x = center[0] + radius * np.cos(theta + rotation)
    y = center[1] + radius * np.sin(theta + rotation)
    return x, y
