"""Measured wear profile: from fitted points to ``h(theta)`` on the simulation grid.

The paper's step 3 (§3.2): the wear at a measured point is its distance from
the fitted bushing centre minus the unworn radius ``R0``. Here those values are
brought onto the simulation's node grid ``theta_j = 2 pi j / N``
(:func:`jointwear.geometry.node_angles`) so that a measured profile can be
compared with a simulated one node by node, turned into a
:class:`~jointwear.geometry.BushingContour`, and summarised with the same wear
metrics as a simulation (:mod:`jointwear.tribology.metrics`).

Angles: the measuring instrument's frame is not the bushing's. A feature at
bushing angle ``theta`` is seen at angle ``theta + angle_offset`` about the
fitted centre in the instrument frame. Give the offset if you know it (a
marked reference on the part), or find it with :func:`align_profiles` by best
fit against a reference (simulated) profile.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import DataError
from jointwear.geometry import BushingContour, node_angles
from jointwear.geometry.angles import angle_in_turn
from jointwear.measurement.fit import CircleFit
from jointwear.tribology.metrics import (
    wear_mass,
    wear_peak,
    wear_volume,
    wear_width,
    worn_area,
)

__all__ = [
    "PROFILE_METHODS",
    "WearMetrics",
    "align_profiles",
    "measured_contour",
    "measured_wear_profile",
    "wear_metrics",
]

FloatArray = NDArray[np.float64]


def measured_wear_profile(
    x: ArrayLike,
    y: ArrayLike,
    fit: CircleFit,
    original_radius: float,
    nodes: int,
    angle_offset: float = 0.0,
    method: str = "interpolate",
) -> FloatArray:
    """Wear depth of measured points on the equally spaced node grid.

    For every point, the wear is its distance from the fitted centre minus the
    unworn radius (the paper's definition). These values are brought onto the
    angles ``theta_j + angle_offset``, ``theta_j = 2 pi j / N``, either by
    periodic linear interpolation in angle (``method="interpolate"``) or by
    averaging the points nearest to each node (``method="bin"``; nodes without
    points are interpolated from their neighbours). Averaging reduces the noise
    by the square root of the points per node and is the better choice when
    there are several points per node; interpolation keeps every point's
    detail and bridges gaps linearly.

    Negative values -- points inside the unworn circle -- are kept as they are:
    on the unworn arc they are measurement noise (and cancel on average in the
    removed area). A biased centre shows differently: with the centre pulled
    towards the scar, the unworn side opposite the scar shows a phantom wear of
    about the centre error, and the scar's flanks dip below zero (see
    :mod:`jointwear.measurement.fit`).

    Parameters
    ----------
    x, y : array_like, shape (M,)
        Measured points [m] in the instrument frame.
    fit : CircleFit
        Fitted bushing centre (its radius is not used).
    original_radius : float
        Unworn radius ``R0`` [m].
    nodes : int
        Number of nodes ``N`` of the grid.
    angle_offset : float
        Instrument-frame angle of the bushing's ``theta = 0`` [rad].
    method : {"interpolate", "bin"}
        How points are brought onto the nodes.

    Returns
    -------
    ndarray, shape (N,)
        Wear depth ``h(theta_j)`` [m].

    Raises
    ------
    DataError
        Mismatched or too few points, non-positive radius, fewer than 3 nodes,
        unknown method.
    """
    x, y = _check_profile_inputs(x, y, original_radius, nodes, method)
    nodes = int(nodes)
    dx, dy = x - fit.center_x, y - fit.center_y
    # angle in the bushing frame
    angle = angle_in_turn(np.arctan2(dy, dx) - angle_offset)
    depth = np.hypot(dx, dy) - original_radius
    # depths within the coordinates' round-off are no wear (a ring far from the origin)
    depth = np.where(np.abs(depth) <= fit.resolution, 0.0, depth)
    theta = node_angles(nodes)
    if method == "bin":
        return _binned(angle, depth, theta)
    # np.interp with a period sorts the angles itself and wraps around 2 pi
    return np.interp(theta, angle, depth, period=2 * np.pi)


def _check_profile_inputs(
    x: ArrayLike, y: ArrayLike, original_radius: float, nodes: int, method: str
) -> tuple[FloatArray, FloatArray]:
    """Points ``x, y`` [m] as flat arrays, or a DataError naming the bad input."""
    x = np.asarray(x, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    if x.shape != y.shape or x.size < 2:
        raise DataError("wear profile: need at least 2 points with x and y of equal length")
    if not (np.isfinite(original_radius) and original_radius > 0):
        raise DataError(f"wear profile: original radius must be > 0, got {original_radius!r}")
    if int(nodes) != nodes or nodes < 3:
        raise DataError(f"wear profile: nodes must be an integer >= 3, got {nodes!r}")
    if method not in PROFILE_METHODS:
        raise DataError(
            f"wear profile: method must be one of {', '.join(PROFILE_METHODS)}, got {method!r}"
        )
    return x, y


def _binned(angle: FloatArray, depth: FloatArray, theta: FloatArray) -> FloatArray:
    """Mean depth [m] of the points nearest each node; empty nodes from their neighbours.

    ``angle`` [rad] in [0, 2 pi) and ``depth`` [m] per point; ``theta`` the node angles.
    """
    nodes = theta.size
    nearest = np.rint(angle / (2 * np.pi / nodes)).astype(int) % nodes
    count = np.bincount(nearest, minlength=nodes)
    total = np.bincount(nearest, weights=depth, minlength=nodes)
    filled = count > 0
    mean = total[filled] / count[filled]
    if filled.all():
        return mean
    return np.interp(theta, theta[filled], mean, period=2 * np.pi)


#: Ways of bringing measured points onto the node grid.
PROFILE_METHODS = ("interpolate", "bin")


def align_profiles(reference: ArrayLike, measured: ArrayLike) -> tuple[float, FloatArray]:
    """Rotate a measured profile onto a reference profile by best fit.

    The integer node shift maximises the circular cross-correlation of the
    mean-free profiles (computed with FFTs), ``c_k = sum_j ref_j meas_{j+k}``;
    a parabola through the peak and its neighbours refines it below one node.

    Parameters
    ----------
    reference : array_like, shape (N,)
        Reference profile on the node grid, e.g. a simulated wear depth [m].
    measured : array_like, shape (N,)
        Measured profile on the same grid [m].

    Returns
    -------
    offset : float
        Angle [rad], in ``(-pi, pi]``, such that ``measured(theta + offset)``
        matches ``reference(theta)``; the ``angle_offset`` to pass to
        :func:`measured_wear_profile` to get the aligned profile directly.
    aligned : ndarray, shape (N,)
        ``measured(theta_j + offset)``, interpolated linearly and periodically [m].

    Raises
    ------
    DataError
        Profiles of different length, fewer than 3 nodes or non-finite values.
    """
    ref = np.asarray(reference, dtype=float)
    meas = np.asarray(measured, dtype=float)
    if ref.ndim != 1 or ref.shape != meas.shape or ref.size < 3:
        raise DataError(
            f"align profiles: need two 1-D profiles of equal length >= 3, got shapes "
            f"{ref.shape} and {meas.shape}"
        )
    if not (np.all(np.isfinite(ref)) and np.all(np.isfinite(meas))):
        raise DataError("align profiles: profiles must be finite")
    nodes = ref.size
    ref0, meas0 = ref - ref.mean(), meas - meas.mean()
    correlation = np.fft.irfft(np.conj(np.fft.rfft(ref0)) * np.fft.rfft(meas0), n=nodes)
    peak = int(np.argmax(correlation))
    before, at, after = correlation[[(peak - 1) % nodes, peak, (peak + 1) % nodes]]
    curvature = before - 2 * at + after
    fraction = 0.5 * (before - after) / curvature if curvature < 0 else 0.0
    shift = peak + fraction
    shift = shift - nodes if shift > nodes / 2 else shift  # the shorter way round
    offset = float(shift * 2 * np.pi / nodes)
    theta = node_angles(nodes)
    aligned = np.interp(theta + offset, theta, meas, period=2 * np.pi)
    return offset, aligned


@dataclass(frozen=True)
class WearMetrics:
    """Wear metrics of a profile, as the paper reports them.

    Parameters
    ----------
    peak_depth : float
        Largest wear depth [m].
    peak_angle : float
        Node angle of the largest depth [rad].
    min_depth : float
        Smallest (most negative) depth [m]; noise, or a biased centre if large.
    width : float
        Angular extent where the depth exceeds ``threshold * peak`` [rad].
    area : float
        Removed cross-section area ``1/2 sum (r_j^2 - R0^2) dtheta`` [m^2].
    volume : float
        ``axial_length * area`` [m^3]; NaN without an axial length.
    mass : float
        ``density * volume`` [kg]; NaN without axial length and density.
    threshold : float
        Fraction of the peak used for the width [-].
    """

    peak_depth: float
    peak_angle: float
    min_depth: float
    width: float
    area: float
    volume: float
    mass: float
    threshold: float

    @property
    def width_deg(self) -> float:
        """Wear width [deg]."""
        return float(np.degrees(self.width))

    @property
    def peak_angle_deg(self) -> float:
        """Angle of the deepest node [deg]."""
        return float(np.degrees(self.peak_angle))


def wear_metrics(
    wear_depth: ArrayLike,
    original_radius: float,
    threshold: float = 0.01,
    axial_length: float | None = None,
    density: float | None = None,
    floor: float = 0.0,
) -> WearMetrics:
    """Peak, width, removed area (and volume, mass) of a wear profile.

    Uses :func:`jointwear.tribology.metrics.wear_peak`, ``wear_width`` and
    ``removed_area`` so that measured and simulated profiles are summarised
    the same way. The area is exact for the polar node contour
    ``r_j = R0 + h_j`` and includes negative depths (they are noise on a
    well-fitted profile and cancel on average).

    On a measured profile the default 1 % threshold is usually below the noise,
    so the width counts noise spikes on the unworn arc; pass ``floor`` (e.g.
    three times the robust fit's ``rms_residual``) to ignore depths at or below
    it when measuring the width.

    Parameters
    ----------
    wear_depth : array_like, shape (N,)
        Wear depth on the node grid [m].
    original_radius : float
        Unworn radius ``R0`` [m].
    threshold : float
        Fraction of the peak above which a node counts as worn [-].
    axial_length : float, optional
        Axial length ``b`` of the bushing [m], for volume and mass.
    density : float, optional
        Density of the bushing material [kg/m^3], for the mass.
    floor : float
        Depths at or below this do not count towards the width [m].

    Returns
    -------
    WearMetrics
    """
    depth = np.asarray(wear_depth, dtype=float)
    if depth.ndim != 1 or depth.size < 3 or not np.all(np.isfinite(depth)):
        raise DataError("wear metrics: need a finite 1-D wear profile of at least 3 nodes")
    if not (np.isfinite(original_radius) and original_radius > 0):
        raise DataError(f"wear metrics: original radius must be > 0, got {original_radius!r}")
    if not 0 <= threshold < 1:
        raise DataError(f"wear metrics: threshold must be in [0, 1), got {threshold!r}")
    if not (np.isfinite(floor) and floor >= 0):
        raise DataError(f"wear metrics: floor must be >= 0, got {floor!r}")
    for name, value in (("axial length", axial_length), ("density", density)):
        if value is not None and not (np.isfinite(value) and value > 0):
            raise DataError(f"wear metrics: {name} must be > 0, got {value!r}")
    area = worn_area(original_radius, depth)
    volume = wear_volume(area, axial_length) if axial_length is not None else float("nan")
    mass = (
        wear_mass(area, axial_length, density)
        if axial_length is not None and density is not None
        else float("nan")
    )
    above_floor = np.where(depth > floor, depth, 0.0)
    return WearMetrics(
        peak_depth=wear_peak(depth),
        peak_angle=float(node_angles(depth.size)[np.argmax(depth)]),
        min_depth=float(depth.min()),
        width=wear_width(above_floor, threshold),
        area=area,
        volume=volume,
        mass=mass,
        threshold=threshold,
    )


def measured_contour(
    wear_depth: ArrayLike, original_radius: float, axial_length: float
) -> BushingContour:
    """The worn bushing contour ``r_j = R0 + h_j`` of a measured profile.

    Ready to be used as the starting contour of a simulation or compared with
    a simulated one.

    Parameters
    ----------
    wear_depth : array_like, shape (N,)
        Wear depth on the node grid [m], ``N >= 16``.
    original_radius : float
        Unworn radius ``R0`` [m].
    axial_length : float
        Axial length ``b`` of the bushing [m].
    """
    return BushingContour.from_wear_profile(original_radius, wear_depth, axial_length)
