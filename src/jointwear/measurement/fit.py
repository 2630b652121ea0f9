"""Circle fits for measured bushing contours: where is the centre of a worn bushing?

The paper (§3.2) measures the inner surface of a worn bushing, fits its centre
"by the least squares method" and reports the wear as the distance from that
centre minus the unworn radius ``R0``. This module offers that plain fit and a
robust one.

Why a plain least-squares fit is biased on a worn bushing
---------------------------------------------------------
Wear is one-sided: it only moves the surface *outwards*, so a point at angle
``theta`` lies at distance ``R0 + h(theta)`` from the true centre. For a centre
displaced by a small vector ``c``, the distance becomes
``R0 + h(theta) - c . u(theta)`` (``u`` the unit ray). A least-squares fit
minimises the squared misfit of these distances to a circle; with points spread
around the ring it removes the *first Fourier harmonic* of ``h``:

.. math::

    \\mathbf{c}_{LS} \\approx \\frac{1}{\\pi} \\int_0^{2\\pi} h(\\theta)\\,
    \\mathbf{u}(\\theta)\\, d\\theta ,

i.e. the fitted centre moves *towards* the scar (and the fitted radius grows by
the mean of ``h``). Measured from that centre, with the paper's "distance minus
``R0``", the scar looks shallower by about ``|c_LS|``, the unworn side opposite
the scar shows a phantom wear of about ``+|c_LS|``, and the scar's flanks dip
below zero. The removed area barely changes (a centre shift moves area from one
side to the other), so wear mass survives the bias, but peak and width do not.
For a 60 µm deep, 170° wide cos² scar on a 7.5 mm bushing (the paper's Table 5
scale) the centre moves by about 25 µm and the peak is under-reported by about
40 % (see ``tests/measurement/test_fit.py``).

The robust fit
--------------
:func:`fit_circle_robust` fits the circle to the *unworn arc* only, as a
metrologist would. A least-trimmed-squares search (the quarter of the points
closest to a circle, found by a grid search and concentration steps) locates
the unworn arc; the fit is then repeated on every point within a few noise
standard deviations of the circle. The noise is estimated from the points
*inside* the circle, which wear cannot have touched. When the unworn radius
``R0`` is known -- it always is for a bushing whose drawing you have -- the
radius is *fixed* to ``R0`` and only the centre is fitted; this is much better
conditioned than fitting a radius to a partial arc, which drifts outwards into
the shallow edges of the scar.

Assumptions of the robust fit (state them with any result):

* wear only increases the radius (no deposits or plastic flow inwards);
* a sizeable part of the circumference is unworn: at least ``coverage`` (a
  quarter by default) of the points and a 90° arc with a known ``R0``; about
  half of the circumference without it;
* the unworn arc is still a circle of radius ``R0`` (no creep, no ovality of
  the part beyond the measurement noise), and the longest such arc: the bottom
  of a very wide scar (over about 220°) is itself nearly an arc of radius
  ``R0`` and can be taken for the unworn arc;
* the noise is small compared with the wear.

All lengths are in metres; all functions are vectorised over the points.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import DataError
from jointwear.geometry.angles import angle_in_turn

__all__ = [
    "CircleFit",
    "angular_extent",
    "circle_residuals",
    "coordinate_resolution",
    "fit_circle_kasa",
    "fit_circle_least_squares",
    "fit_circle_robust",
]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class CircleFit:
    """Result of a circle fit.

    Parameters
    ----------
    center_x, center_y : float
        Centre of the circle in the points' frame [m].
    radius : float
        Radius [m]; for a robust fit with a known unworn radius this is that
        radius (fixed, not fitted).
    rms_residual : float
        Root mean square of the geometric residuals ``|p_i - c| - radius`` over
        the points the fit used [m].
    method : str
        ``"kasa"``, ``"least_squares"`` or ``"robust"``.
    points_used : int
        Number of points the final fit used (all points except for the robust fit).
    radius_fixed : bool
        True if the radius was given, not fitted.
    inliers : ndarray of bool, optional
        Which points the final fit used (``None`` means all of them).
    resolution : float
        Smallest distance the points' coordinates resolve [m]
        (:func:`coordinate_resolution`): depths within it are round-off, not wear.
    """

    center_x: float
    center_y: float
    radius: float
    rms_residual: float
    method: str
    points_used: int = 0
    radius_fixed: bool = False
    inliers: NDArray[np.bool_] | None = field(default=None, repr=False, compare=False)
    resolution: float = 0.0

    @property
    def center(self) -> tuple[float, float]:
        """Centre ``(x, y)`` [m]."""
        return (self.center_x, self.center_y)

    def residuals(self, x: ArrayLike, y: ArrayLike) -> FloatArray:
        """Geometric residuals ``|p_i - c| - radius`` of points [m]."""
        return circle_residuals(x, y, self.center_x, self.center_y, self.radius)


def circle_residuals(
    x: ArrayLike, y: ArrayLike, center_x: float, center_y: float, radius: float
) -> FloatArray:
    """Signed distance of points to a circle, positive outside [m].

    Parameters
    ----------
    x, y : array_like
        Point coordinates [m].
    center_x, center_y : float
        Circle centre [m].
    radius : float
        Circle radius [m].

    Returns
    -------
    ndarray
        ``hypot(x - center_x, y - center_y) - radius`` [m].
    """
    return np.hypot(np.asarray(x, float) - center_x, np.asarray(y, float) - center_y) - radius


#: round-off of a coordinate, in units in the last place of the largest one
_RESOLUTION_ULPS = 8


def coordinate_resolution(x: ArrayLike, y: ArrayLike) -> float:
    """Smallest distance that coordinates as large as these resolve [m].

    A double carries about 16 significant digits: a ring of 7.5 mm measured in a
    frame 10 km from the origin has coordinates resolved to ~2e-12 m only, and
    distances from any centre scatter by that much however the fit is done.
    Depths within this resolution are round-off and must not count as wear.

    Parameters
    ----------
    x, y : array_like
        Point coordinates [m].

    Returns
    -------
    float
        ``8`` units in the last place of the largest coordinate magnitude [m].
    """
    largest = max(float(np.max(np.abs(x), initial=0.0)), float(np.max(np.abs(y), initial=0.0)))
    return float(_RESOLUTION_ULPS * np.spacing(largest))


def _as_points(x: ArrayLike, y: ArrayLike, minimum: int = 3) -> tuple[FloatArray, FloatArray]:
    x = np.asarray(x, dtype=float).ravel()
    y = np.asarray(y, dtype=float).ravel()
    if x.shape != y.shape:
        raise DataError(f"circle fit: x and y differ in length ({x.size} vs {y.size})")
    if x.size < minimum:
        raise DataError(f"circle fit: need at least {minimum} points, got {x.size}")
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
        raise DataError("circle fit: coordinates must be finite")
    return x, y


def _kasa(x: FloatArray, y: FloatArray) -> tuple[float, float, float]:
    """Algebraic circle ``x^2 + y^2 + D x + E y + F = 0`` by linear least squares.

    Coordinates are centred and scaled first so the normal equations stay well
    conditioned for a millimetre ring far from the origin.
    """
    x0, y0 = x.mean(), y.mean()
    scale = float(np.sqrt(np.mean((x - x0) ** 2 + (y - y0) ** 2)))
    if not scale > 0:
        raise DataError("circle fit: all points coincide")
    u, v = (x - x0) / scale, (y - y0) / scale
    design = np.column_stack([u, v, np.ones_like(u)])
    rhs = -(u**2 + v**2)
    solution, _, rank, singular = np.linalg.lstsq(design, rhs, rcond=None)
    if rank < 3 or singular[-1] < 1e-9 * singular[0]:
        raise DataError("circle fit: points are collinear, no circle through them")
    d, e, f = solution
    cu, cv = -d / 2, -e / 2
    r2 = cu**2 + cv**2 - f
    if not r2 > 0:
        raise DataError("circle fit: points do not describe a circle")
    return float(x0 + scale * cu), float(y0 + scale * cv), float(scale * np.sqrt(r2))


def _rms(values: FloatArray) -> float:
    return float(np.sqrt(np.mean(values**2))) if values.size else float("nan")


def fit_circle_kasa(x: ArrayLike, y: ArrayLike) -> CircleFit:
    """Algebraic (Kåsa) circle fit.

    Minimises ``sum (|p_i - c|^2 - R^2)^2``, a linear problem with a closed-form
    solution. It is exact for points on a circle, but for noisy points on a
    short arc it is biased towards small radii because it weights the misfit by
    the distance. Used as the starting point of the geometric fits.

    Parameters
    ----------
    x, y : array_like, shape (M,)
        Point coordinates [m], ``M >= 3``.

    Returns
    -------
    CircleFit
        With ``method="kasa"``; ``rms_residual`` is geometric [m].

    Raises
    ------
    DataError
        Fewer than 3 points, non-finite, coincident or collinear points.
    """
    x, y = _as_points(x, y)
    cx, cy, r = _kasa(x, y)
    residual = circle_residuals(x, y, cx, cy, r)
    return CircleFit(
        cx, cy, r, _rms(residual), "kasa", x.size, False, None, coordinate_resolution(x, y)
    )


def _geometric_fit(
    x: FloatArray,
    y: FloatArray,
    start: tuple[float, float, float],
    radius: float | None,
    loss: str = "linear",
    f_scale: float = 1.0,
) -> tuple[float, float, float]:
    """Minimise ``sum rho((|p_i - c| - R)^2)`` with scipy; ``radius`` fixes ``R``.

    The problem is solved in coordinates centred on the start and scaled by the
    start radius, so that the tolerances are relative and parameters are O(1).
    """
    cx0, cy0, r0 = start
    scale = radius if radius is not None else r0
    u, v = (x - cx0) / scale, (y - cy0) / scale

    def split(params: FloatArray) -> tuple[float, float, float]:
        if radius is None:
            return params[0], params[1], params[2]
        return params[0], params[1], 1.0

    def residual(params: FloatArray) -> FloatArray:
        a, b, rho = split(params)
        return np.hypot(u - a, v - b) - rho

    def jacobian(params: FloatArray) -> FloatArray:
        a, b, _ = split(params)
        distance = np.hypot(u - a, v - b)
        # a point exactly at the centre has no defined direction; any unit vector will do
        distance = np.where(distance > 0, distance, 1.0)
        columns = [-(u - a) / distance, -(v - b) / distance]
        if radius is None:
            columns.append(-np.ones_like(u))
        return np.column_stack(columns)

    initial = np.array([0.0, 0.0, r0 / scale] if radius is None else [0.0, 0.0])
    from scipy.optimize import least_squares  # lazy: keeps the CLI quick to start

    solution = least_squares(
        residual,
        initial,
        jac=jacobian,
        method="trf",
        loss=loss,
        f_scale=f_scale / scale,
        xtol=1e-15,
        ftol=1e-15,
        gtol=1e-15,
        max_nfev=200,
    )
    a, b, rho = split(solution.x)
    return float(cx0 + scale * a), float(cy0 + scale * b), float(scale * rho)


def fit_circle_least_squares(x: ArrayLike, y: ArrayLike) -> CircleFit:
    """Geometric least-squares circle fit (the paper's "least squares method").

    Minimises the sum of squared distances of the points to the circle,
    ``sum (|p_i - c| - R)^2``, over centre and radius with
    :func:`scipy.optimize.least_squares`, starting from the algebraic
    (:func:`fit_circle_kasa`) solution.

    On a worn bushing this fit is biased: the centre moves towards the wear
    scar and the wear measured from it is too shallow (see the module
    docstring); use :func:`fit_circle_robust` to measure wear.

    Parameters
    ----------
    x, y : array_like, shape (M,)
        Point coordinates [m], ``M >= 3``.

    Returns
    -------
    CircleFit
        With ``method="least_squares"``; ``rms_residual`` over all points [m].

    Raises
    ------
    DataError
        Fewer than 3 points, non-finite, coincident or collinear points.
    """
    x, y = _as_points(x, y)
    start = _kasa(x, y)
    cx, cy, r = _geometric_fit(x, y, start, radius=None)
    residual = circle_residuals(x, y, cx, cy, r)
    return CircleFit(
        cx,
        cy,
        r,
        _rms(residual),
        "least_squares",
        x.size,
        False,
        None,
        coordinate_resolution(x, y),
    )


def fit_circle_robust(
    x: ArrayLike,
    y: ArrayLike,
    original_radius: float | None = None,
    *,
    band: float | None = None,
    cutoff: float = 3.0,
    coverage: float = 0.25,
    min_arc_deg: float = 90.0,
    search_nodes: int = 41,
    max_iterations: int = 100,
) -> CircleFit:
    """Circle fit to the unworn arc of a worn bushing.

    The fit keeps only the points that lie on a circle -- the unworn arc -- and
    ignores the scar, whose points lie *outside* the circle. It proceeds in
    four steps, all on the geometric residuals ``r_i = |p_i - c| - R``
    (``R = original_radius`` when given):

    1. **Global search** of the *trimmed* objective: the sum of the
       ``coverage * M`` smallest ``r_i^2`` (least trimmed squares, LTS) is
       evaluated by :func:`scipy.optimize.brute` on a ``search_nodes`` square
       grid of centres around the plain least-squares centre, out to 1.5 times
       the peak-to-valley of its residuals (a generous bound on the
       least-squares pull, which is about the first harmonic of the wear),
       with axes along and across that pull. The trimmed objective is smallest
       where a quarter of the points sit exactly on the circle, i.e. at the
       unworn arc; a local search from the biased least-squares centre can
       stall in a false minimum, hence the grid.
    2. **Concentration steps** (Rousseeuw & Van Driessen's C-steps for LTS):
       keep the ``coverage * M`` points of smallest ``|r_i|``, refit on them
       with :func:`scipy.optimize.least_squares`, repeat until the set is
       stable. Each step lowers the trimmed objective.
    3. **Reweighting**: keep all points with ``|r_i| <= band`` and refit on
       them, until the kept set is stable. The default ``band`` is ``cutoff``
       times the noise, estimated as the RMS of the *negative* residuals:
       wear only moves points outwards, so the points inside the circle are
       unworn and their residuals are half of a zero-mean noise distribution.
    4. **Polish** on all points with the smooth, redescending ``"arctan"`` loss
       of :func:`scipy.optimize.least_squares` (scale ``2/3 band``: weight 1/2
       at two noise standard deviations, nil in the scar). Hard 0/1 weights can
       settle on kept sets that differ by a few boundary points when started
       from slightly different places; the smooth loss removes most of that
       arbitrariness (the result turns and shifts with the points to within
       about 1 % of the noise).

    With a known ``R0`` only the centre is fitted (the radius stays ``R0``),
    which is what a metrologist does and is far better conditioned than fitting
    a radius to a partial arc. Without it the radius is fitted to the unworn
    arc too (in step 1 each candidate centre gets the radius of its best
    window of sorted distances).

    Assumptions: wear only increases the radius (no deposits, no inward creep);
    at least ``coverage`` of the points and a ``min_arc_deg`` arc are unworn;
    the unworn arc is a circle of radius ``R0`` (a bushing machined to a
    different radius shows up as uniform "wear", and, with ``R`` fixed, as a
    one-sided offset of the centre -- fit without ``original_radius`` to check);
    the unworn arc is the largest arc of radius ``R0`` in the data; the noise
    is small compared with the wear. The last one can fail for very wide scars:
    the bottom of a scar worn by a pin of nearly the bushing's radius is itself
    an arc of radius about ``R0``, centred one wear depth towards the scar. When
    that arc is as long as the unworn one (a cos² scar wider than about 220°
    leaves less than 140° unworn) the two are indistinguishable from the
    geometry alone; check which points were kept (``inliers``).

    Parameters
    ----------
    x, y : array_like, shape (M,)
        Point coordinates [m].
    original_radius : float, optional
        Unworn radius ``R0`` [m]. If given, the radius is fixed to it and only
        the centre is fitted (recommended). If not, it is fitted to the unworn arc.
    band : float, optional
        Half-width of the inlier band around the circle [m] for step 3.
        Default: ``cutoff`` times the RMS of the negative residuals, at least
        ``1e-9 * R`` (so that noise-free data keep their unworn points).
    cutoff : float
        Width of the default band in noise standard deviations [-].
    coverage : float
        Share of the points the trimmed steps 1-2 use [-], in (0, 1]; it must
        not exceed the unworn share of the circumference. The default 0.25
        tolerates scars up to about 270°.
    min_arc_deg : float
        Smallest angular extent of the kept points about the fitted centre
        [deg]; a shorter arc does not fix the centre and raises.
    search_nodes : int
        Grid points per axis of the global search (odd, so that the grid
        contains the least-squares centre).
    max_iterations : int
        Largest number of steps in each of steps 2 and 3.

    Returns
    -------
    CircleFit
        With ``method="robust"``; ``rms_residual`` and ``points_used`` refer to
        the kept (unworn) points, ``inliers`` is their mask.

    Raises
    ------
    DataError
        Bad points (see :func:`fit_circle_kasa`), a non-positive radius or
        band, bad options, or an unworn arc shorter than ``min_arc_deg``.

    References
    ----------
    P. J. Rousseeuw, K. Van Driessen, "Computing LTS regression for large data
    sets", Data Mining and Knowledge Discovery 12 (2006) 29-45.
    """
    x, y = _as_points(x, y)
    _check_robust_options(original_radius, band, cutoff, coverage, search_nodes, max_iterations)
    fixed = original_radius is not None
    # the parameters fitted: centre (2) and, unless fixed, radius (1); a fit needs one more point
    trimmed_count = min(x.size, max(4 if fixed else 5, int(np.ceil(coverage * x.size))))
    plain = _geometric_fit(x, y, _kasa(x, y), radius=None)
    circle = _search_trimmed(x, y, plain, original_radius, coverage, trimmed_count, search_nodes)
    circle = _concentrate(x, y, circle, trimmed_count, original_radius, max_iterations)
    # The noise is estimated once, at the trimmed solution: re-estimating it as the circle
    # moves lets a free radius creep outwards into the scar, widening the band as it goes.
    if band is None:
        band = cutoff * _noise_from_inside(circle_residuals(x, y, *circle))
    half_width = max(band, 1e-9 * circle[2])
    circle = _reweight(x, y, circle, half_width, original_radius, max_iterations)
    # 4. polish with a smooth redescending loss (weight 1 / (1 + (r / f)^4), f = 2/3 band).
    # Hard 0/1 weights can settle on slightly different kept sets from slightly different
    # starts; the smooth loss makes the result all but independent of where it started.
    cx, cy, fitted = _geometric_fit(
        x, y, circle, radius=original_radius, loss="arctan", f_scale=2 * half_width / 3
    )
    radius = circle[2] if fixed else fitted
    kept = np.abs(circle_residuals(x, y, cx, cy, radius)) <= half_width
    arc = np.degrees(angular_extent(x[kept] - cx, y[kept] - cy))
    if arc < min_arc_deg:
        raise DataError(
            f"robust circle fit: the unworn arc spans only {arc:.0f}° "
            f"(< {min_arc_deg:g}°), too short to fix the centre"
        )
    residual = circle_residuals(x[kept], y[kept], cx, cy, radius)
    return CircleFit(
        float(cx),
        float(cy),
        float(radius),
        _rms(residual),
        "robust",
        int(np.count_nonzero(kept)),
        fixed,
        kept,
        coordinate_resolution(x, y),
    )


def _check_robust_options(
    original_radius: float | None,
    band: float | None,
    cutoff: float,
    coverage: float,
    search_nodes: int,
    max_iterations: int,
) -> None:
    """Refuse options of :func:`fit_circle_robust` outside their ranges (one line each)."""
    if original_radius is not None and not (np.isfinite(original_radius) and original_radius > 0):
        raise DataError(f"robust circle fit: original radius must be > 0, got {original_radius!r}")
    if band is not None and not (np.isfinite(band) and band > 0):
        raise DataError(f"robust circle fit: band must be > 0, got {band!r}")
    if not (np.isfinite(cutoff) and cutoff > 0):
        raise DataError(f"robust circle fit: cutoff must be > 0, got {cutoff!r}")
    if not 0 < coverage <= 1:
        raise DataError(f"robust circle fit: coverage must be in (0, 1], got {coverage!r}")
    if search_nodes < 3 or max_iterations < 1:
        raise DataError("robust circle fit: search_nodes must be >= 3 and max_iterations >= 1")


def _search_trimmed(
    x: FloatArray,
    y: FloatArray,
    plain: tuple[float, float, float],
    original_radius: float | None,
    coverage: float,
    trimmed_count: int,
    search_nodes: int,
) -> tuple[float, float, float]:
    """Step 1: the circle of least trimmed squares on a grid of centres around ``plain``.

    The grid reaches 1.5 times the peak-to-valley of the plain fit's residuals; its axes
    follow their first harmonic (towards the wear, the direction of the least-squares
    bias), so that the search, and the result, turn with the points instead of depending
    on the instrument's axes. ``plain``: the least-squares circle ``(cx, cy, R)`` [m].
    """
    cx, cy, r_plain = plain
    radius = float(original_radius) if original_radius is not None else r_plain
    plain_residual = circle_residuals(x, y, cx, cy, r_plain)
    reach = 1.5 * float(np.ptp(plain_residual))
    if not reach > 1e-9 * radius:
        return cx, cy, radius
    angle = np.arctan2(y - cy, x - cx)
    axis = np.array(
        [np.sum(plain_residual * np.cos(angle)), np.sum(plain_residual * np.sin(angle))]
    )
    norm = float(np.hypot(*axis))
    along = axis / norm if norm > 0 else np.array([1.0, 0.0])
    across = np.array([-along[1], along[0]])
    # the objective only needs a fair sample of the ring to locate the basin
    step = max(1, x.size // _SEARCH_SAMPLE)
    xs, ys = x[::step], y[::step]
    m = min(xs.size, max(3, int(np.ceil(coverage * xs.size))))

    def trimmed(offset: FloatArray) -> float:
        center = (
            cx + offset[0] * along[0] + offset[1] * across[0],
            cy + offset[0] * along[1] + offset[1] * across[1],
        )
        return _trimmed_objective(xs, ys, center[0], center[1], original_radius, m)[0]

    from scipy.optimize import brute

    best = brute(trimmed, ((-reach, reach), (-reach, reach)), Ns=search_nodes, finish=None)
    cx, cy = (
        float(cx + best[0] * along[0] + best[1] * across[0]),
        float(cy + best[0] * along[1] + best[1] * across[1]),
    )
    if original_radius is None:
        radius = _trimmed_objective(x, y, cx, cy, None, trimmed_count)[1]
    return cx, cy, radius


def _concentrate(
    x: FloatArray,
    y: FloatArray,
    circle: tuple[float, float, float],
    trimmed_count: int,
    original_radius: float | None,
    max_iterations: int,
) -> tuple[float, float, float]:
    """Step 2: concentration steps of least trimmed squares, until the kept set is stable.

    Keep the ``trimmed_count`` points nearest the circle and refit on them; each step
    lowers the trimmed objective.
    """
    kept: NDArray[np.bool_] | None = None
    for _ in range(max_iterations):
        residual = circle_residuals(x, y, *circle)
        new_kept = np.zeros(x.size, dtype=bool)
        new_kept[np.argpartition(np.abs(residual), trimmed_count - 1)[:trimmed_count]] = True
        if kept is not None and np.array_equal(new_kept, kept):
            break
        kept = new_kept
        circle = _refit(x, y, kept, *circle, original_radius)
    return circle


def _reweight(
    x: FloatArray,
    y: FloatArray,
    circle: tuple[float, float, float],
    half_width: float,
    original_radius: float | None,
    max_iterations: int,
) -> tuple[float, float, float]:
    """Step 3: refit on every point within ``half_width`` [m] of the circle, until stable.

    Every point within the band of the circle is taken as unworn.
    """
    kept: NDArray[np.bool_] | None = None
    for _ in range(max_iterations):
        residual = circle_residuals(x, y, *circle)
        new_kept = np.abs(residual) <= half_width
        if np.count_nonzero(new_kept) < 3:
            raise DataError(
                "robust circle fit: fewer than 3 points lie within the band around the "
                "circle; is the unworn radius right?"
            )
        if kept is not None and np.array_equal(new_kept, kept):
            break
        kept = new_kept
        circle = _refit(x, y, kept, *circle, original_radius)
    return circle


#: Largest number of points the global search of the robust fit evaluates.
_SEARCH_SAMPLE = 2000


def _refit(
    x: FloatArray,
    y: FloatArray,
    kept: NDArray[np.bool_],
    cx: float,
    cy: float,
    radius: float,
    fixed_radius: float | None,
) -> tuple[float, float, float]:
    """Geometric fit on the kept points, starting from the current circle."""
    cx, cy, fitted = _geometric_fit(x[kept], y[kept], (cx, cy, radius), radius=fixed_radius)
    return cx, cy, (fitted if fixed_radius is None else fixed_radius)


def _trimmed_objective(
    x: FloatArray, y: FloatArray, cx: float, cy: float, radius: float | None, m: int
) -> tuple[float, float]:
    """Sum of the ``m`` smallest squared residuals and the radius it uses [m^2], [m].

    With ``radius=None`` the radius is the mean of the best window of ``m``
    consecutive sorted distances (the exact 1-D least-trimmed-squares location).
    """
    distance = np.hypot(x - cx, y - cy)
    if radius is not None:
        return float(np.sum(np.partition((distance - radius) ** 2, m - 1)[:m])), radius
    reference = float(np.median(distance))
    d = np.sort(distance) - reference  # centred, so the running sums do not cancel
    s1 = np.concatenate([[0.0], np.cumsum(d)])
    s2 = np.concatenate([[0.0], np.cumsum(d * d)])
    window_sum = s1[m:] - s1[:-m]
    window_sse = (s2[m:] - s2[:-m]) - window_sum**2 / m
    best = int(np.argmin(window_sse))
    return float(max(window_sse[best], 0.0)), reference + float(window_sum[best] / m)


def _noise_from_inside(residual: FloatArray) -> float:
    """Noise standard deviation from the residuals of points inside the circle [m].

    Wear only moves the surface outwards, so points with negative residuals are
    unworn and their residuals are one half of a zero-mean noise distribution,
    whose RMS is the noise standard deviation.
    """
    inside = residual[residual < 0]
    return float(np.sqrt(np.mean(inside**2))) if inside.size else 0.0


def angular_extent(dx: FloatArray, dy: FloatArray) -> float:
    """Angle covered by points seen from the origin: 2 pi minus the largest gap [rad].

    Parameters
    ----------
    dx, dy : ndarray, shape (M,)
        Points relative to the origin (e.g. a fitted centre) [m, or any length unit].

    Returns
    -------
    float
        Angular coverage [rad], 0 for fewer than two points.
    """
    if dx.size < 2:
        return 0.0
    angle = np.sort(angle_in_turn(np.arctan2(dy, dx)))
    gaps = np.diff(np.concatenate([angle, angle[:1] + 2 * np.pi]))
    return float(2 * np.pi - gaps.max())
