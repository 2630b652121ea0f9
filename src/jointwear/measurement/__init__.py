"""Measured worn bushings (paper §3.2): read points, fit the centre, get the wear profile.

Typical use::

    x, y = read_points("bushing.csv", units="mm")
    fit = fit_circle_robust(x, y, original_radius=7.5e-3)
    depth = measured_wear_profile(x, y, fit, 7.5e-3, nodes=360)
    metrics = wear_metrics(depth, 7.5e-3)

:func:`fit_circle_least_squares` is the paper's plain fit; on a worn bushing it
pulls the centre towards the scar and under-reports the depth (see
:mod:`jointwear.measurement.fit`).
"""

from jointwear.measurement.fit import (
    CircleFit,
    circle_residuals,
    fit_circle_kasa,
    fit_circle_least_squares,
    fit_circle_robust,
)
from jointwear.measurement.io import check_ring, length_unit_factor, read_points
from jointwear.measurement.profile import (
    PROFILE_METHODS,
    WearMetrics,
    align_profiles,
    measured_contour,
    measured_wear_profile,
    wear_metrics,
)
from jointwear.measurement.synthetic import cosine_squared_scar, synthesize_measurement

__all__ = [
    "PROFILE_METHODS",
    "CircleFit",
    "WearMetrics",
    "align_profiles",
    "check_ring",
    "circle_residuals",
    "cosine_squared_scar",
    "fit_circle_kasa",
    "fit_circle_least_squares",
    "fit_circle_robust",
    "length_unit_factor",
    "measured_contour",
    "measured_wear_profile",
    "read_points",
    "synthesize_measurement",
    "wear_metrics",
]
