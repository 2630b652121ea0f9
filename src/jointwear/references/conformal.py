r"""Rigid-conformal wear of a journal under a load fixed in the bushing (exact reference).

A dry pin under a dead load, turning or swinging in its bushing, wears the bore
into the shape of the pin. When the pin is much stiffer than the wear is deep
(elastic approach small against the worn depth), the worn bore *is* the pin's
surface on the contact arc, and Archard's law [1]_ fixes the pressure: the pin sinks
along the load by ``d(t)``, so a point of the arc at angle ``beta`` from the load
(measured at the pin's centre) must recede along its normal by ``cos(beta)`` times
the sinking, ``K p ds = cos(beta) dd``, hence

.. math::

    p(\beta) = p_0 \cos\beta, \qquad |\beta| \le \beta_e,
    \qquad F = p_0 R_p b \, (\beta_e + \sin\beta_e \cos\beta_e),

with ``beta_e`` where the pin's surface meets the unworn bore of radius
``R_b = R_p + c``:

.. math:: \cos\beta_e = \frac{R_b^2 - R_p^2 - d^2}{2 d R_p}.

The worn section is the part of the pin's disc outside the bore, whose area grows
by ``2 R_p sin(beta_e) dd``; the worn volume grows by
``K b int p R_p dbeta ds = 2 K p_0 R_p b sin(beta_e) ds``. Both together give the
sinking per sliding distance ``s`` in closed form,

.. math::

    \frac{ds}{dd} = \frac{1}{K p_0} = \frac{R_p b \, (\beta_e + \sin\beta_e\cos\beta_e)}{K F},

integrated by quadrature from first contact (``d = c``). The worn volume per sliding
distance rises from ``K F`` (a narrow contact) to ``4 K F / \pi`` once the arc spans
half the bore (``beta_e = pi/2``), and the groove widens as it deepens: these are
the two properties a contact model must reproduce to predict a worn joint's life
(the unworn, elastic pin in a hole is Johnson's [2]_).
To first order in ``d / R_p`` (small clearance and wear) the solution is algebraic,
``s = (R b c / (K F)) (alpha / cos(alpha) - sin(alpha))`` with ``cos(alpha) = c / d``
(:func:`small_wear_sliding_distance`).

The depth, width and volume returned are the ones jointwear reports for a profile:
the depth along rays from the bushing's centre (``h(theta) = rho(theta) - R_b``, with
``rho`` the distance from the bushing centre to the pin's surface along the ray at
``theta``), the width where the depth exceeds a fraction of the peak, and the removed
area times ``b``. The sliding distance is jointwear's, ``R_b`` times the relative
rotation; this reference neglects elasticity, so a model's worn joint converges to it
once the wear is deep against the elastic approach.

References
----------
.. [1] Archard, J. F.: Contact and rubbing of flat surfaces. J. Appl. Phys. 24,
   981-988 (1953).
.. [2] Johnson, K. L.: Contact Mechanics, Cambridge University Press (1985), §5.9
   (the conformal pin in a hole; the rigid-wear limit is derived above).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import integrate, optimize

from jointwear.errors import ConfigError

__all__ = [
    "ConformalWear",
    "conformal_wear",
    "contact_half_angle",
    "sliding_distance",
    "small_wear_sliding_distance",
]

FloatArray = NDArray[np.float64]


def contact_half_angle(sinking: ArrayLike, pin_radius: float, clearance: float) -> FloatArray:
    """Half-angle ``beta_e`` of the contact arc at the pin's centre [rad].

    Parameters
    ----------
    sinking : array_like
        Displacement ``d`` of the pin's centre from the bushing's centre [m], ``>= c``.
    pin_radius : float
        Pin radius ``R_p`` [m].
    clearance : float
        Radial clearance ``c = R_b - R_p`` [m].
    """
    d = np.asarray(sinking, dtype=float)
    bore = pin_radius + clearance
    cos_edge = (bore**2 - pin_radius**2 - d**2) / (2.0 * d * pin_radius)
    return np.arccos(np.clip(cos_edge, -1.0, 1.0))


def sliding_distance(
    sinking: float,
    load: float,
    pin_radius: float,
    clearance: float,
    axial_length: float,
    wear_coefficient: float,
) -> float:
    """Sliding distance ``s`` [m] after which the pin has sunk to ``d`` (exact geometry).

    .. math:: s(d) = \\frac{R_p b}{K F} \\int_c^d (\\beta_e + \\sin\\beta_e\\cos\\beta_e)\\,dd'

    Parameters
    ----------
    sinking : float
        Displacement ``d`` of the pin's centre [m], ``c <= d < c + 2 R_p``.
    load : float
        Load ``F`` [N], > 0.
    pin_radius : float
        Pin radius ``R_p`` [m].
    clearance : float
        Radial clearance ``c`` [m].
    axial_length : float
        Axial length ``b`` [m].
    wear_coefficient : float
        Archard's dimensional wear coefficient ``K`` [m^2/N].
    """
    if sinking <= clearance:
        return 0.0
    # integrated over the half-angle, in which the integrand is smooth (in d it has a
    # square-root edge at first contact): d(beta) = -R_p cos(beta) + sqrt(R_p^2 cos^2
    # (beta) + R_b^2 - R_p^2)
    rp, bore = pin_radius, pin_radius + clearance

    def integrand(beta: float) -> float:
        cos, sin = math.cos(beta), math.sin(beta)
        root = math.sqrt(rp**2 * cos**2 + bore**2 - rp**2)
        sinking_rate = rp * sin * (1.0 - rp * cos / root)
        return (beta + sin * cos) * sinking_rate

    edge = float(contact_half_angle(sinking, pin_radius, clearance))
    integral, _ = integrate.quad(integrand, 0.0, edge, epsabs=0.0, epsrel=1e-12, limit=200)
    return pin_radius * axial_length * integral / (wear_coefficient * load)


def small_wear_sliding_distance(
    sinking: ArrayLike,
    load: float,
    radius: float,
    clearance: float,
    axial_length: float,
    wear_coefficient: float,
) -> FloatArray:
    """First-order (small clearance and wear) form of :func:`sliding_distance` [m].

    .. math:: s = \\frac{R b c}{K F}\\left(\\frac{\\alpha}{\\cos\\alpha} - \\sin\\alpha\\right),
              \\qquad \\cos\\alpha = c / d

    Parameters
    ----------
    sinking : array_like
        Displacement ``d`` of the pin's centre [m], ``>= c``.
    load : float
        Load ``F`` [N].
    radius : float
        Joint radius ``R`` [m] (pin and bushing alike to this order).
    clearance : float
        Radial clearance ``c`` [m].
    axial_length : float
        Axial length ``b`` [m].
    wear_coefficient : float
        Archard's dimensional wear coefficient ``K`` [m^2/N].
    """
    alpha = np.arccos(np.clip(clearance / np.asarray(sinking, dtype=float), -1.0, 1.0))
    scale = radius * axial_length * clearance / (wear_coefficient * load)
    return scale * (alpha / np.cos(alpha) - np.sin(alpha))


@dataclass(frozen=True)
class ConformalWear:
    """The rigid-conformal worn bore after a sliding distance.

    Attributes
    ----------
    sliding_distance : float
        Sliding distance ``s`` at the bushing radius [m].
    sinking : float
        Displacement ``d`` of the pin's centre [m].
    half_angle : float
        Contact half-angle at the pin's centre ``beta_e`` [rad].
    peak_wear_depth : float
        Deepest wear ``d - c`` [m].
    wear_width : float
        Angular extent at the bushing's centre where the depth exceeds
        ``width_threshold`` times the peak [rad].
    wear_volume : float
        Worn volume ``b`` times the pin's disc area outside the bore [m^3].
    peak_pressure : float
        Pressure ``p_0`` on the load line [Pa].
    """

    sliding_distance: float
    sinking: float
    half_angle: float
    peak_wear_depth: float
    wear_width: float
    wear_volume: float
    peak_pressure: float


def _groove_edge(sinking: float, pin_radius: float, clearance: float) -> float:
    """Angle from the load line, at the bushing's centre, where the groove meets the bore [rad]."""
    beta = float(contact_half_angle(sinking, pin_radius, clearance))
    return math.atan2(pin_radius * math.sin(beta), sinking + pin_radius * math.cos(beta))


def _depth_along_rays(
    theta: FloatArray, sinking: float, pin_radius: float, clearance: float
) -> FloatArray:
    """Worn depth along the bushing's rays at ``theta`` (from the load) [m].

    ``rho - R_b`` with ``rho = d cos(theta) + sqrt(R_p^2 - d^2 sin^2(theta))``, written
    without the cancellation of ``sqrt(...) - R_p`` for ``d << R_p``.
    """
    across = sinking * np.sin(theta)
    root = np.sqrt(np.maximum(pin_radius**2 - across**2, 0.0))
    reach = sinking * np.cos(theta) - clearance - across**2 / (root + pin_radius)
    return np.maximum(reach, 0.0)


def _removed_area(sinking: float, pin_radius: float, clearance: float) -> float:
    """Area of the pin's disc outside the bore [m^2].

    ``int ((R_b + h)^2 - R_b^2) / 2 dtheta`` over the groove, by quadrature: the closed
    form (the disc minus the two discs' lens) loses all digits to cancellation while the
    groove is shallow.
    """
    if sinking <= clearance:
        return 0.0
    bore = pin_radius + clearance
    edge = _groove_edge(sinking, pin_radius, clearance)

    def strip(theta: float) -> float:
        depth = float(_depth_along_rays(np.array(theta), sinking, pin_radius, clearance))
        return depth * (bore + 0.5 * depth)

    half, _ = integrate.quad(strip, 0.0, edge, epsabs=0.0, epsrel=1e-12, limit=200)
    return 2.0 * half


def conformal_wear(
    sliding_distance_m: float,
    load: float,
    pin_radius: float,
    clearance: float,
    axial_length: float,
    wear_coefficient: float,
    width_threshold: float = 0.01,
) -> ConformalWear:
    """The rigid-conformal worn bore after sliding ``s`` under a fixed load.

    Parameters
    ----------
    sliding_distance_m : float
        Sliding distance at the bushing radius [m], ``>= 0``.
    load : float
        Load ``F`` fixed in the bushing [N], > 0.
    pin_radius : float
        Pin radius ``R_p`` [m].
    clearance : float
        Radial clearance ``c`` [m], > 0.
    axial_length : float
        Axial length ``b`` [m].
    wear_coefficient : float
        Archard's dimensional wear coefficient ``K`` [m^2/N].
    width_threshold : float
        Fraction of the peak depth that bounds the wear width [-].

    Returns
    -------
    ConformalWear

    Raises
    ------
    ConfigError
        If an input is not positive and finite, or the pin would wear through its own
        diameter of bore.
    """
    _check_conformal_inputs(
        sliding_distance_m, load, pin_radius, clearance, axial_length, wear_coefficient
    )
    sinking = _sinking_after(
        sliding_distance_m, load, pin_radius, clearance, axial_length, wear_coefficient
    )
    beta = float(contact_half_angle(sinking, pin_radius, clearance))
    peak = sinking - clearance
    arc = beta + math.sin(beta) * math.cos(beta)
    return ConformalWear(
        sliding_distance=float(sliding_distance_m),
        sinking=float(sinking),
        half_angle=beta,
        peak_wear_depth=float(peak),
        wear_width=2.0 * _groove_half_width(sinking, pin_radius, clearance, width_threshold),
        wear_volume=axial_length * _removed_area(sinking, pin_radius, clearance),
        peak_pressure=load / (pin_radius * axial_length * arc) if arc > 0 else math.inf,
    )


def _check_conformal_inputs(
    sliding_distance_m: float,
    load: float,
    pin_radius: float,
    clearance: float,
    axial_length: float,
    wear_coefficient: float,
) -> None:
    """Refuse inputs that are not positive and finite (the sliding distance may be 0)."""
    values = {
        "load": load,
        "pin_radius": pin_radius,
        "clearance": clearance,
        "axial_length": axial_length,
        "wear_coefficient": wear_coefficient,
    }
    for name, value in values.items():
        if not (math.isfinite(value) and value > 0):
            raise ConfigError(f"{name}: must be positive and finite, got {value!r}")
    if not (math.isfinite(sliding_distance_m) and sliding_distance_m >= 0):
        raise ConfigError(f"sliding_distance: must be >= 0, got {sliding_distance_m!r}")


def _sinking_after(
    sliding_distance_m: float,
    load: float,
    pin_radius: float,
    clearance: float,
    axial_length: float,
    wear_coefficient: float,
) -> float:
    """Displacement ``d`` of the pin's centre after sliding ``s`` [m]: ``s(d) = s`` by brentq.

    The sinking grows with ``s``; the bracket ends where the arc spans the whole pin.
    """
    if sliding_distance_m == 0.0:
        return clearance

    def distance(d: float) -> float:
        return sliding_distance(d, load, pin_radius, clearance, axial_length, wear_coefficient)

    upper = clearance + pin_radius
    if distance(upper) < sliding_distance_m:
        raise ConfigError(
            "sliding_distance: the pin would sink deeper than its radius into the bore"
        )
    return optimize.brentq(
        lambda d: distance(d) - sliding_distance_m,
        clearance,
        upper,
        xtol=1e-15 * pin_radius,
        rtol=1e-13,
    )


def _groove_half_width(
    sinking: float, pin_radius: float, clearance: float, width_threshold: float
) -> float:
    """Angle from the load line where the depth falls to ``width_threshold`` of the peak [rad].

    The depth falls monotonically away from the load line, so brentq between the load
    line and the groove's edge; 0 before wear.
    """
    peak = sinking - clearance
    if not peak > 0:
        return 0.0
    edge = _groove_edge(sinking, pin_radius, clearance)
    return optimize.brentq(
        lambda t: (
            float(_depth_along_rays(np.array(t), sinking, pin_radius, clearance))
            - width_threshold * peak
        ),
        0.0,
        edge,
        xtol=1e-14,
    )
