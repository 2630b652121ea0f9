"""Compare a measured wear profile with a simulated one (paper §3.2, Figs. 18-20).

The paper's last step: "collate the experimental data and make comparison with
simulation data". Here both profiles are put on the simulation's node grid
``theta_j = 2 pi j / N``, the measured one is rotated onto the simulated one
(the instrument's frame is not the bushing's), and the difference is reported
as an RMS error [m] and as differences of the paper's metrics: wear peak,
wear width (threshold a fraction of the peak, as the reproduction measures it) and wear area / mass.

Two entry points:

* :func:`compare_profiles` -- two profiles already on the same grid;
* :func:`compare_measurement` -- simulated profile and measured points: the
  bushing centre is fitted (robust fit of the unworn arc by default, the
  paper's plain least squares on request; see :mod:`jointwear.measurement.fit`),
  the wear ``distance - R0`` is brought onto the grid and compared.

Alignment
---------
A feature at bushing angle ``theta`` appears at ``theta + offset`` in the
measured frame (the ``angle_offset`` of
:func:`~jointwear.measurement.profile.measured_wear_profile`). With
``align="best"`` the offset maximises the correlation of the two mean-free
profiles (for profiles of equal size: the least RMS difference): circular
cross-correlation (:func:`~jointwear.measurement.profile.align_profiles`) to
the nearest node, then a bounded scalar search within one node
(:func:`best_offset`). The criterion is scale-free, so a simulation that is
too deep or too shallow overall still aligns right.
With a number the offset is taken as given [rad] (a marked reference on the part).

Both frames are reported: the *measured frame* (the profile as measured, no
rotation; its peak angle next to the predicted one and their difference --
how far the real load direction is from the model's) and the *aligned* one
(rotated by the offset; the errors of shape, depth, width and mass). An angle
after rotation is never reported as the measured one.

Signs: every error is *measured minus simulated*; relative errors are divided
by the simulated value.

All quantities are SI (m, rad, m^2, kg) unless a name says ``_deg``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import minimize_scalar

from jointwear.errors import ConfigError, DataError
from jointwear.geometry import node_angles
from jointwear.geometry.angles import angle_in_turn, wrap_angle
from jointwear.measurement.fit import CircleFit, fit_circle_least_squares, fit_circle_robust
from jointwear.measurement.profile import (
    PROFILE_METHODS,
    WearMetrics,
    align_profiles,
    measured_wear_profile,
    wear_metrics,
)
from jointwear.registry import suggest

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = [
    "ALIGN_BEST",
    "CIRCLE_FITS",
    "PROFILE_CHOICES",
    "Comparison",
    "best_offset",
    "compare_measurement",
    "compare_profiles",
    "fit_circle",
    "plot_comparison",
    "resolve_profile_method",
]

FloatArray = NDArray[np.float64]

#: ``align`` value asking for the best-fit rotation.
ALIGN_BEST = "best"
#: Circle fits for the measured centre (``"least_squares"`` is accepted too).
CIRCLE_FITS = ("robust", "least-squares")
#: Ways of bringing points onto the grid: ``"auto"`` bins when there are at least
#: :data:`_POINTS_PER_NODE_TO_BIN` points per node, else interpolates.
PROFILE_CHOICES = ("auto", *PROFILE_METHODS)
_POINTS_PER_NODE_TO_BIN = 3


@dataclass(frozen=True)
class Comparison:
    """A measured wear profile next to a simulated one, on the simulation grid.

    Parameters
    ----------
    theta : ndarray, shape (N,)
        Node angles of the simulation grid, bushing frame [rad].
    simulated : ndarray, shape (N,)
        Simulated wear depth [m].
    measured : ndarray, shape (N,)
        Measured wear depth, aligned onto the bushing frame [m].
    original_radius : float
        Unworn bushing radius ``R0`` [m].
    alignment_offset : float
        Angle [rad] of the bushing's ``theta = 0`` in the measured frame.
    aligned : bool
        True if the offset was found by best fit, False if it was given.
    simulated_metrics, measured_metrics : WearMetrics
        Peak, width, area (volume, mass) of each profile, with the same
        threshold and floor.
    fit : CircleFit, optional
        The circle fit of the measured points (None for :func:`compare_profiles`).
    profile_method : str, optional
        How the points were brought onto the grid (``"interpolate"`` or ``"bin"``).
    points : int
        Number of measured points (0 if unknown).
    measured_frame : ndarray, shape (N,), optional
        Measured wear depth in its own frame, not rotated [m] (default: ``measured``
        rotated back by the offset, see :attr:`measured_unrotated`).
    """

    theta: FloatArray
    simulated: FloatArray
    measured: FloatArray
    original_radius: float
    alignment_offset: float
    aligned: bool
    simulated_metrics: WearMetrics
    measured_metrics: WearMetrics
    fit: CircleFit | None = None
    profile_method: str | None = None
    points: int = 0
    measured_frame: FloatArray | None = None

    def __repr__(self) -> str:
        return (
            f"<Comparison {self.nodes} nodes: RMS error {self.rms_error * 1e6:.4g} µm, "
            f"peak error {100 * self.peak_error_rel:+.3g} %, "
            f"offset {math.degrees(self.alignment_offset):.4g}°>"
        )

    @property
    def nodes(self) -> int:
        """Number of grid nodes."""
        return int(self.theta.size)

    @property
    def difference(self) -> FloatArray:
        """Measured minus simulated depth per node [m]."""
        return self.measured - self.simulated

    @property
    def rms_error(self) -> float:
        """Root mean square of the aligned difference over all nodes [m]."""
        return float(np.sqrt(np.mean(self.difference**2)))

    @property
    def max_abs_error(self) -> float:
        """Largest absolute difference of the aligned profiles [m]."""
        return float(np.max(np.abs(self.difference)))

    @property
    def measured_unrotated(self) -> FloatArray:
        """Measured wear depth in the measured frame, not rotated [m]."""
        if self.measured_frame is not None:
            return self.measured_frame
        # the aligned profile seen from the measured frame again
        return np.interp(
            self.theta - self.alignment_offset, self.theta, self.measured, period=2 * np.pi
        )

    @property
    def peak_angle_measured_frame(self) -> float:
        """Angle of the deepest node of the measured profile as measured, not rotated [rad]."""
        return float(self.theta[np.argmax(self.measured_unrotated)])

    @property
    def peak_angle_difference(self) -> float:
        """Measured-frame peak angle minus the simulated one, wrapped to (-pi, pi] [rad].

        No rotation: how far the measured wear sits from the predicted one as measured
        (a load direction of the real joint off the model's shows here).
        """
        return _wrapped(self.peak_angle_measured_frame - self.simulated_metrics.peak_angle)

    @property
    def rms_error_measured_frame(self) -> float:
        """Root mean square of measured (not rotated) minus simulated depth [m]."""
        return float(np.sqrt(np.mean((self.measured_unrotated - self.simulated) ** 2)))

    @property
    def peak_angle_residual(self) -> float:
        """Aligned (rotated) measured peak angle minus the simulated one, wrapped [rad]."""
        return _wrapped(self.measured_metrics.peak_angle - self.simulated_metrics.peak_angle)

    @property
    def peak_error(self) -> float:
        """Measured minus simulated wear peak [m]."""
        return self.measured_metrics.peak_depth - self.simulated_metrics.peak_depth

    @property
    def peak_error_rel(self) -> float:
        """Peak error relative to the simulated peak [-]."""
        return _relative(self.peak_error, self.simulated_metrics.peak_depth)

    @property
    def width_error(self) -> float:
        """Measured minus simulated wear width [rad]."""
        return self.measured_metrics.width - self.simulated_metrics.width

    @property
    def width_error_deg(self) -> float:
        """Measured minus simulated wear width [deg]."""
        return math.degrees(self.width_error)

    @property
    def area_error(self) -> float:
        """Measured minus simulated removed area [m^2]."""
        return self.measured_metrics.area - self.simulated_metrics.area

    @property
    def area_error_rel(self) -> float:
        """Area (= volume = mass) error relative to the simulated area [-]."""
        return _relative(self.area_error, self.simulated_metrics.area)

    @property
    def mass_error(self) -> float:
        """Measured minus simulated wear mass [kg]; NaN without axial length and density."""
        return self.measured_metrics.mass - self.simulated_metrics.mass

    @property
    def mass_error_rel(self) -> float:
        """Mass error relative to the simulated mass [-] (equals :attr:`area_error_rel`)."""
        return _relative(self.mass_error, self.simulated_metrics.mass)

    def summary(self) -> dict[str, Any]:
        """Flat dictionary of the comparison (the ``jointwear compare --json`` object).

        Keys carry their unit (``_m``, ``_deg``, ``_m2``, ``_kg``, ``_rel`` for
        a fraction); NaN where a quantity is not available (mass without
        density, fit fields without points).
        """
        sim, meas = self.simulated_metrics, self.measured_metrics
        fit = self.fit
        return {
            "rms_error_m": self.rms_error,
            "max_abs_error_m": self.max_abs_error,
            "peak_wear_depth_simulated_m": sim.peak_depth,
            "peak_wear_depth_measured_m": meas.peak_depth,
            "peak_error_m": self.peak_error,
            "peak_error_rel": self.peak_error_rel,
            "peak_angle_simulated_deg": sim.peak_angle_deg,
            # the measured frame: as measured, no rotation
            "peak_angle_measured_deg": math.degrees(self.peak_angle_measured_frame),
            "peak_angle_difference_deg": math.degrees(self.peak_angle_difference),
            "rms_error_measured_frame_m": self.rms_error_measured_frame,
            # the aligned frame: the measured profile rotated by the offset
            "peak_angle_aligned_deg": meas.peak_angle_deg,
            "peak_angle_residual_deg": math.degrees(self.peak_angle_residual),
            "wear_width_simulated_deg": sim.width_deg,
            "wear_width_measured_deg": meas.width_deg,
            "width_error_deg": self.width_error_deg,
            "wear_area_simulated_m2": sim.area,
            "wear_area_measured_m2": meas.area,
            "area_error_rel": self.area_error_rel,
            "wear_mass_simulated_kg": sim.mass,
            "wear_mass_measured_kg": meas.mass,
            "mass_error_kg": self.mass_error,
            "mass_error_rel": self.mass_error_rel,
            "min_wear_depth_measured_m": meas.min_depth,
            "alignment_offset_deg": math.degrees(self.alignment_offset),
            "alignment": ALIGN_BEST if self.aligned else "given",
            "fit": None if fit is None else _fit_name(fit.method),
            "center_x_m": math.nan if fit is None else fit.center_x,
            "center_y_m": math.nan if fit is None else fit.center_y,
            "fit_rms_residual_m": math.nan if fit is None else fit.rms_residual,
            "points": self.points,
            "points_used": 0 if fit is None else fit.points_used,
            "profile": self.profile_method,
            "nodes": self.nodes,
            "original_radius_m": self.original_radius,
            "threshold": sim.threshold,
        }


def _wrapped(angle: float) -> float:
    """An angle difference wrapped to (-pi, pi] [rad], as a float."""
    return float(wrap_angle(angle))


def _relative(error: float, reference: float) -> float:
    return error / reference if reference != 0 and math.isfinite(reference) else math.nan


def _fit_name(method: str) -> str:
    return "least-squares" if method == "least_squares" else method


def fit_circle(
    x: ArrayLike, y: ArrayLike, original_radius: float, fit: str = "robust"
) -> CircleFit:
    """Fit the bushing centre by name.

    Parameters
    ----------
    x, y : array_like
        Measured points [m].
    original_radius : float
        Unworn radius ``R0`` [m]; the robust fit fixes the radius to it.
    fit : str
        ``"robust"`` (default) or ``"least-squares"`` (also ``"least_squares"``).

    Raises
    ------
    ConfigError
        Unknown fit name (with a suggestion).
    DataError
        The fit fails (see :mod:`jointwear.measurement.fit`).
    """
    name = str(fit).replace("_", "-")
    if name == "robust":
        return fit_circle_robust(x, y, original_radius)
    if name == "least-squares":
        return fit_circle_least_squares(x, y)
    raise ConfigError(f"fit: unknown circle fit {fit!r}{suggest(name, CIRCLE_FITS)}")


def resolve_profile_method(profile: str, points: int, nodes: int) -> str:
    """``"interpolate"`` or ``"bin"`` for a profile choice (``"auto"`` decides by density).

    ``"auto"`` averages the points of each node (``"bin"``) when there are at
    least 3 points per node: a grid profile interpolated from single noisy
    points has a peak biased upwards by about two noise standard deviations
    (the largest of the noisy values near the peak); averaging divides that by
    the square root of the points per node.

    Raises
    ------
    ConfigError
        Unknown choice.
    """
    if profile == "auto":
        return "bin" if points >= _POINTS_PER_NODE_TO_BIN * nodes else "interpolate"
    if profile not in PROFILE_METHODS:
        raise ConfigError(
            f"profile: unknown method {profile!r}{suggest(str(profile), PROFILE_CHOICES)}"
        )
    return profile


def best_offset(
    reference: ArrayLike,
    profile_at: Any,
    coarse: float,
    nodes: int,
) -> float:
    """Refine a rotation within one node of ``coarse`` by maximal correlation.

    Maximises the normalised correlation of the mean-free profiles,
    ``<m(o), s> / |m(o)|`` -- for profiles of the same size the same as the
    least RMS difference, and scale-free: a simulated profile that is too
    deep or too shallow overall (a wrong ``K_d``) aligns as well.

    Parameters
    ----------
    reference : array_like, shape (N,)
        Reference (simulated) profile [m].
    profile_at : callable
        ``profile_at(offset) -> ndarray (N,)``, the measured profile seen from
        ``offset`` [rad]; must be continuous in the offset.
    coarse : float
        Starting offset [rad], e.g. from :func:`align_profiles`.
    nodes : int
        Grid size (the search interval is one node spacing either side).

    Returns
    -------
    float
        The offset [rad], wrapped to ``(-pi, pi]``.
    """
    ref = np.asarray(reference, dtype=float)
    ref = ref - ref.mean()
    spacing = 2 * np.pi / nodes

    def negative_correlation(offset: float) -> float:
        seen = profile_at(offset)
        seen = seen - seen.mean()
        norm = float(np.sqrt(np.sum(seen**2)))
        return -float(np.dot(seen, ref)) / norm if norm > 0 else 0.0

    result = minimize_scalar(
        negative_correlation,
        bounds=(coarse - spacing, coarse + spacing),
        method="bounded",
        options={"xatol": 1e-7},
    )
    better = negative_correlation(float(result.x)) <= negative_correlation(coarse)
    offset = float(result.x) if better else coarse
    return _wrapped(offset)


def _check_profile(name: str, values: ArrayLike, nodes: int | None = None) -> FloatArray:
    array = np.asarray(values, dtype=float)
    if array.ndim != 1 or array.size < 3 or not np.all(np.isfinite(array)):
        raise DataError(f"compare: the {name} profile must be a finite 1-D array of >= 3 nodes")
    if nodes is not None and array.size != nodes:
        raise DataError(
            f"compare: the {name} profile has {array.size} nodes, the simulated one {nodes}"
        )
    return array


def _check_align(align: str | float) -> float | None:
    """None for best fit, else the offset [rad]."""
    if isinstance(align, str):
        if align != ALIGN_BEST:
            raise ConfigError(f"align: expected {ALIGN_BEST!r} or an angle [rad], got {align!r}")
        return None
    value = float(align)
    if not math.isfinite(value):
        raise ConfigError(f"align: the offset must be finite, got {align!r}")
    return value


def _metrics(
    simulated: FloatArray,
    measured: FloatArray,
    original_radius: float,
    axial_length: float | None,
    density: float | None,
    threshold: float,
    floor: float,
) -> tuple[WearMetrics, WearMetrics]:
    return (
        wear_metrics(simulated, original_radius, threshold, axial_length, density, floor),
        wear_metrics(measured, original_radius, threshold, axial_length, density, floor),
    )


def _alignment_offset(simulated: FloatArray, measured: FloatArray, given: float | None) -> float:
    """The given offset, else the best-fit one [rad] of ``measured`` onto ``simulated``.

    Best fit: :func:`align_profiles` to the nearest node, then :func:`best_offset`
    within a node, the measured profile interpolated periodically between nodes.
    """
    if given is not None:
        return given
    theta = node_angles(simulated.size)

    def seen_from(offset: float) -> FloatArray:
        return np.interp(theta + offset, theta, measured, period=2 * np.pi)

    coarse, _ = align_profiles(simulated, measured)
    return best_offset(simulated, seen_from, coarse, simulated.size)


def compare_profiles(
    simulated_depth: ArrayLike,
    measured_depth: ArrayLike,
    original_radius: float,
    axial_length: float | None = None,
    density: float | None = None,
    threshold: float = 0.01,
    align: str | float = ALIGN_BEST,
    floor: float = 0.0,
) -> Comparison:
    """Compare two wear profiles on the same node grid.

    Parameters
    ----------
    simulated_depth : array_like, shape (N,)
        Simulated wear depth at ``theta_j = 2 pi j / N``, bushing frame [m].
    measured_depth : array_like, shape (N,)
        Measured wear depth on the same grid, in its own frame [m] (e.g.
        :func:`~jointwear.measurement.profile.measured_wear_profile` with
        ``angle_offset=0``).
    original_radius : float
        Unworn bushing radius ``R0`` [m].
    axial_length : float, optional
        Bushing axial length ``b`` [m], for volume and mass.
    density : float, optional
        Bushing density [kg/m^3], for the mass.
    threshold : float
        Wear width threshold, fraction of each profile's own peak [-].
    align : "best" or float
        ``"best"``: rotate the measured profile onto the simulated one by
        maximal correlation (:func:`best_offset`); a number: the offset [rad] of the bushing's
        ``theta = 0`` in the measured frame.
    floor : float
        Depths at or below this do not count towards either width [m]
        (measurement noise; e.g. 3 x the robust fit's RMS residual).

    Returns
    -------
    Comparison
        With ``fit=None``.

    Raises
    ------
    DataError
        Profiles of different length, non-finite, or bad radius / length / density.
    ConfigError
        Bad ``align``.
    """
    simulated = _check_profile("simulated", simulated_depth)
    measured = _check_profile("measured", measured_depth, simulated.size)
    theta = node_angles(simulated.size)
    given = _check_align(align)
    offset = _alignment_offset(simulated, measured, given)
    aligned = np.interp(theta + offset, theta, measured, period=2 * np.pi)
    sim_metrics, meas_metrics = _metrics(
        simulated, aligned, original_radius, axial_length, density, threshold, floor
    )
    return Comparison(
        theta=theta,
        simulated=simulated,
        measured=aligned,
        original_radius=float(original_radius),
        alignment_offset=offset,
        aligned=given is None,
        simulated_metrics=sim_metrics,
        measured_metrics=meas_metrics,
        measured_frame=measured,
    )


def compare_measurement(
    simulated_depth: ArrayLike,
    x: ArrayLike,
    y: ArrayLike,
    original_radius: float,
    *,
    fit: str | CircleFit = "robust",
    axial_length: float | None = None,
    density: float | None = None,
    threshold: float = 0.01,
    align: str | float = ALIGN_BEST,
    floor: float = 0.0,
    profile: str = "auto",
) -> Comparison:
    """Compare measured points of a worn bushing with a simulated wear profile.

    The centre is fitted (``fit``), the wear of every point (its distance from
    the centre minus ``R0``, the paper's definition) is brought onto the
    simulation's grid, seen from the alignment offset, and compared with
    :func:`compare_profiles`' metrics. With ``align="best"`` the offset is
    found on a first profile and the final profile is then taken from the
    points at that offset (no second interpolation).

    Parameters
    ----------
    simulated_depth : array_like, shape (N,)
        Simulated wear depth at ``theta_j = 2 pi j / N`` [m].
    x, y : array_like, shape (M,)
        Measured points of the inner surface, instrument frame [m].
    original_radius : float
        Unworn bushing radius ``R0`` [m].
    fit : str or CircleFit
        ``"robust"`` (default: the unworn arc, radius fixed to ``R0``),
        ``"least-squares"`` (the paper's plain fit, biased towards the scar),
        or a ready :class:`CircleFit`.
    axial_length, density : float, optional
        For volume and mass [m], [kg/m^3].
    threshold : float
        Width threshold, fraction of the peak [-].
    align : "best" or float
        Best-fit rotation or a given offset [rad].
    floor : float
        Depths at or below this do not count towards the widths [m].
    profile : str
        ``"auto"`` (bin if at least 3 points per node, else interpolate),
        ``"interpolate"`` or ``"bin"``; see
        :func:`~jointwear.measurement.profile.measured_wear_profile`.

    Returns
    -------
    Comparison

    Raises
    ------
    DataError
        Bad points or profile, failed circle fit.
    ConfigError
        Unknown fit, profile method, or bad ``align``.
    """
    simulated = _check_profile("simulated", simulated_depth)
    nodes = simulated.size
    x = np.asarray(x, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    method = resolve_profile_method(profile, x.size, nodes)
    given = _check_align(align)
    circle = fit if isinstance(fit, CircleFit) else fit_circle(x, y, original_radius, fit)
    # the profile as measured (offset 0): the measured frame
    first = measured_wear_profile(x, y, circle, original_radius, nodes, 0.0, method)
    offset = _alignment_offset(simulated, first, given)
    measured = measured_wear_profile(x, y, circle, original_radius, nodes, offset, method)
    comparison = compare_profiles(
        simulated, measured, original_radius, axial_length, density, threshold, 0.0, floor
    )
    return Comparison(
        theta=comparison.theta,
        simulated=comparison.simulated,
        measured=comparison.measured,
        original_radius=comparison.original_radius,
        alignment_offset=offset,
        aligned=given is None,
        simulated_metrics=comparison.simulated_metrics,
        measured_metrics=comparison.measured_metrics,
        fit=circle,
        profile_method=method,
        points=int(x.size),
        measured_frame=first,
    )


def _frame_titles(comparison: Comparison) -> tuple[str, str]:
    """The measured-frame comparison and the kind of rotation, as plot title text."""
    frames = (
        f"as measured: peak at {math.degrees(comparison.peak_angle_measured_frame):.4g}° vs "
        f"{comparison.simulated_metrics.peak_angle_deg:.4g}° predicted "
        f"({math.degrees(comparison.peak_angle_difference):+.3g}°)"
    )
    return frames, "best alignment" if comparison.aligned else "given offset"


def plot_comparison(
    comparison: Comparison,
    directory: str | Path,
    x: ArrayLike | None = None,
    y: ArrayLike | None = None,
    label: str = "",
    magnification: float | None = None,
) -> list[Path]:
    """Overlay plots of a comparison, PNG + SVG each, written atomically.

    Titles give both frames: the measured peak angle as measured (no rotation)
    against the predicted one, and the rotation applied to the measured profile.

    * ``compare_polar``: original circle, simulated and measured (rotated) contours with
      the wear magnified (``R0 + m h``, ``m`` a power of ten as in the paper's
      figures, :func:`jointwear.plots.polar_magnification`), and the measured
      points in the bushing frame; drawn as a roundness chart, the radial axis
      starting at ``0.8 R0``;
    * ``compare_profile``: wear depth [µm] vs bushing angle [deg], simulated,
      measured profile (rotated, and as measured when the rotation is not zero)
      and points, and their difference.

    Parameters
    ----------
    comparison : Comparison
        The comparison to draw.
    directory : path-like
        Output folder (created).
    x, y : array_like, optional
        The measured points [m], drawn as dots when given with a fit.
    label : str
        Title prefix.
    magnification : float, optional
        Wear magnification of the polar plot [-]; default automatic.

    Returns
    -------
    list of Path
        The files written.
    """
    from jointwear.plots import polar_magnification, save_figure

    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    r0 = comparison.original_radius
    peak = max(float(comparison.simulated.max()), float(comparison.measured.max()))
    mag = polar_magnification(peak, r0) if magnification is None else float(magnification)
    points = _points_in_bushing_frame(comparison, x, y)
    title = f"{label}: " if label else ""
    written = save_figure(_polar_figure(comparison, points, mag, title), directory, "compare_polar")
    written += save_figure(_profile_figure(comparison, points, title), directory, "compare_profile")
    return written


def _points_in_bushing_frame(
    comparison: Comparison, x: ArrayLike | None, y: ArrayLike | None
) -> tuple[FloatArray, FloatArray] | None:
    """Bushing-frame angle [rad] and depth [m] of (at most about 3000 of) the points.

    None without points or without a circle fit to see them from.
    """
    if x is None or y is None or comparison.fit is None:
        return None
    px = np.asarray(x, dtype=float) - comparison.fit.center_x
    py = np.asarray(y, dtype=float) - comparison.fit.center_y
    step = max(1, px.size // 3000)
    angle = angle_in_turn(np.arctan2(py, px)[::step] - comparison.alignment_offset)
    return angle, np.hypot(px, py)[::step] - comparison.original_radius


def _polar_figure(
    comparison: Comparison,
    points: tuple[FloatArray, FloatArray] | None,
    mag: float,
    title: str,
) -> Figure:
    """The roundness chart: original circle, simulated and measured contours, points.

    The wear is magnified ``mag`` times [-]; the radial axis starts at ``0.8 R0``.
    """
    from jointwear.plots import new_figure

    r0 = comparison.original_radius
    theta = comparison.theta
    shift = math.degrees(comparison.alignment_offset)
    frames, rotation = _frame_titles(comparison)
    closed = np.append(theta, theta[0])

    def ring(depth: FloatArray) -> FloatArray:
        return (r0 + mag * np.append(depth, depth[0])) * 1e3

    fig = new_figure((5.5, 5.5))
    ax = fig.add_subplot(projection="polar")
    ax.plot(closed, np.full_like(closed, r0 * 1e3), "k--", lw=1, label="original bushing")
    if points is not None:
        ax.plot(
            points[0],
            (r0 + mag * points[1]) * 1e3,
            ".",
            ms=1.5,
            color="0.6",
            label="measured points",
        )
    ax.plot(closed, ring(comparison.simulated), lw=1.6, color="tab:blue", label="simulated")
    ax.plot(
        closed,
        ring(comparison.measured),
        "--",
        lw=1.2,
        color="tab:orange",
        label=f"measured, rotated by {shift:+.3g}°",
    )
    # a roundness chart: the radial axis starts at 0.8 R0 so that the wear shows
    outer = max(float(np.max(ring(comparison.simulated))), float(np.max(ring(comparison.measured))))
    ax.set_ylim(0.8 * r0 * 1e3, 1.02 * outer)
    ax.set_title(
        f"{title}worn contour, wear x{mag:g} [mm], radial axis from 0.8 R0\n"
        f"measured rotated by {shift:+.3g}° ({rotation}); {frames}",
        fontsize=8,
    )
    ax.legend(loc="lower left", fontsize=7, bbox_to_anchor=(-0.1, -0.12), ncol=2)
    return fig


def _profile_figure(
    comparison: Comparison, points: tuple[FloatArray, FloatArray] | None, title: str
) -> Figure:
    """Wear depth [µm] against the bushing angle [deg], and measured minus simulated."""
    from jointwear.plots import new_figure

    shift = math.degrees(comparison.alignment_offset)
    frames, rotation = _frame_titles(comparison)
    fig = new_figure((7, 5.5))
    ax1, ax2 = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    degrees = np.degrees(comparison.theta)
    if points is not None:
        ax1.plot(
            np.degrees(points[0]),
            points[1] * 1e6,
            ".",
            ms=1.5,
            color="0.6",
            label="measured points (rotated)",
        )
    ax1.plot(degrees, comparison.simulated * 1e6, lw=1.6, color="tab:blue", label="simulated")
    if abs(comparison.alignment_offset) > 1e-9:
        ax1.plot(
            degrees,
            comparison.measured_unrotated * 1e6,
            ":",
            lw=1.0,
            color="tab:red",
            label="measured, as measured (not rotated)",
        )
    ax1.plot(
        degrees,
        comparison.measured * 1e6,
        "--",
        lw=1.2,
        color="tab:orange",
        label=f"measured, rotated by {shift:+.3g}°",
    )
    ax1.set_ylabel("wear depth [µm]")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=7)
    ax1.set_title(
        f"{title}{frames}\n{rotation}, rotated by {shift:+.3g}°: "
        f"RMS error {comparison.rms_error * 1e6:.3g} µm, "
        f"peak error {100 * comparison.peak_error_rel:+.3g} %",
        fontsize=9,
    )
    ax2.plot(degrees, comparison.difference * 1e6, color="k", lw=1)
    ax2.axhline(0.0, color="0.5", lw=0.8)
    ax2.set_ylabel("meas. - sim. [µm]")
    ax2.set_xlabel("bushing angle θ [deg]")
    ax2.set_xlim(0, 360)
    ax2.grid(alpha=0.3)
    return fig
