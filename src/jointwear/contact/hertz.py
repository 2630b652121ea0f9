"""Hertz contact of a pin in a hole (paper eqs. 1-3), the non-conformal baseline.

Force law (eq. 1) of Hertz [2]_ with the stiffness of eq. (2) for internal contact
(radii of opposite curvature, ``R_j > R_i``):

.. math::
    F = K \\delta^n, \\qquad
    K = \\frac{4}{3\\pi(\\sigma_i + \\sigma_j)}
        \\left[\\frac{R_i R_j}{R_j - R_i}\\right]^{1/2}, \\qquad
    \\sigma_k = \\frac{1-\\nu_k^2}{\\pi E_k}.

Pressure profile: Hertz line contact of two cylinders (Johnson [1]_, §4.2) with the
conformal relative radius ``R* = R_p R_b / (R_b - R_p)`` and load per unit
length ``F' = F / b``:

.. math::
    a = \\sqrt{\\frac{4 F' R^*}{\\pi E^*}}, \\qquad
    p_0 = \\frac{2 F'}{\\pi a}, \\qquad
    p(x) = p_0 \\sqrt{1 - x^2/a^2},

with ``x = R_b (theta - psi)`` the arc length from the compression centre.
Hertz assumes the contact is small compared with the radii; for a small
clearance the contact arc ``a / R_b`` is not small, which is why the paper
(and this package) treat Hertz as the baseline the Winkler-type models
improve on. On the node grid the profile is scaled so that its discrete
resultant equals the load exactly (the same balance the spring models meet).

References
----------
.. [1] Johnson, K. L.: Contact Mechanics. Cambridge University Press (1985), §4.2.
.. [2] Hertz, H.: Über die Berührung fester elastischer Körper (1882).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.balance.window import angle_addition, nearest_nodes
from jointwear.contact.laws import ContactParameters, effective_modulus
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ContactError
from jointwear.geometry.contour import BushingContour, Pin

__all__ = ["HertzLaw", "half_width", "peak_pressure", "pressure_profile", "solve", "stiffness"]

FloatArray = NDArray[np.float64]


def stiffness(
    pin_radius: float,
    bushing_radius: float,
    pin_youngs_modulus: float,
    pin_poisson_ratio: float,
    bushing_youngs_modulus: float,
    bushing_poisson_ratio: float,
) -> float:
    """Contact stiffness ``K`` of eq. (2) for a pin in a hole [N/m^1.5].

    Parameters
    ----------
    pin_radius : float
        ``R_i`` [m].
    bushing_radius : float or ndarray
        ``R_j`` [m], > ``pin_radius``.
    pin_youngs_modulus, bushing_youngs_modulus : float
        Young's moduli [Pa].
    pin_poisson_ratio, bushing_poisson_ratio : float
        Poisson's ratios [-].
    """
    modulus = effective_modulus(
        pin_youngs_modulus, pin_poisson_ratio, bushing_youngs_modulus, bushing_poisson_ratio
    )
    relative = pin_radius * bushing_radius / (bushing_radius - pin_radius)
    return 4.0 / 3.0 * modulus * np.sqrt(relative)


def half_width(
    load: ArrayLike, axial_length: float, relative_radius: float, modulus: float
) -> FloatArray:
    """Hertz line-contact half-width ``a = sqrt(4 F R* / (pi b E*))`` [m].

    Parameters
    ----------
    load : array_like
        Normal load ``F`` [N].
    axial_length : float
        Contact length ``b`` [m].
    relative_radius : float
        ``R*`` [m].
    modulus : float
        ``E*`` [Pa].
    """
    return np.sqrt(4 * np.asarray(load, float) * relative_radius / (np.pi * axial_length * modulus))


def peak_pressure(
    load: ArrayLike, axial_length: float, relative_radius: float, modulus: float
) -> FloatArray:
    """Hertz line-contact peak pressure ``p0 = 2 F / (pi a b)`` [Pa].

    Parameters are those of :func:`half_width`.
    """
    a = half_width(load, axial_length, relative_radius, modulus)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(a > 0, 2 * np.asarray(load, float) / (np.pi * a * axial_length), 0.0)


def pressure_profile(x: ArrayLike, a: ArrayLike, p0: ArrayLike) -> FloatArray:
    """Elliptical Hertz profile ``p0 sqrt(1 - x^2/a^2)`` [Pa] at arc positions ``x`` [m]."""
    x, a, p0 = (np.asarray(v, float) for v in (x, a, p0))
    with np.errstate(invalid="ignore", divide="ignore"):
        inside = np.clip(1.0 - (x / a) ** 2, 0.0, None)
    return np.where(a > 0, p0 * np.sqrt(inside), 0.0)


def _window_profile(x: FloatArray, a: FloatArray, p0: FloatArray) -> FloatArray:
    """:func:`pressure_profile` of an (M, W) window, row ``k`` with half-width ``a[k]``
    [m] and peak ``p0[k]`` [Pa], at arc positions ``x`` [m]: the same values, computed
    in place (a revolution's window is the bulk of a Hertz solve)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = x / a[:, None]
    np.multiply(ratio, ratio, out=ratio)
    np.subtract(1.0, ratio, out=ratio)
    np.maximum(ratio, 0.0, out=ratio)
    np.sqrt(ratio, out=ratio)
    np.multiply(ratio, p0[:, None], out=ratio)
    if not np.all(a > 0):
        ratio[~(a > 0)] = 0.0
    return ratio


@dataclass(frozen=True)
class HertzLaw:
    """Hertz model bound to its parameters (closed form, no spring balance).

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials.
    """

    parameters: ContactParameters
    name: str = "hertz"

    def solve(
        self,
        contour: BushingContour,
        pin: Pin,
        load: ArrayLike,
        azimuth: ArrayLike,
        max_penetration: float | None = None,
        **_: object,
    ) -> ContactSolution:
        """Solve; ``max_penetration`` [m] defaults to the bushing wall thickness."""
        if max_penetration is None:
            max_penetration = self.parameters.bushing_thickness
        return solve(contour, pin, load, azimuth, self.parameters, max_penetration)


def solve(
    contour: BushingContour,
    pin: Pin,
    load: ArrayLike,
    azimuth: ArrayLike,
    parameters: ContactParameters,
    max_penetration: float | None = None,
) -> ContactSolution:
    """Hertz pressure on the bushing nodes for many loads.

    Parameters
    ----------
    contour : BushingContour
        Bushing contour (its radius at the compression centre is used).
    pin : Pin
        The pin.
    load : array_like, shape (M,)
        Load magnitudes [N].
    azimuth : array_like, shape (M,)
        Load directions in the bushing frame [rad].
    parameters : ContactParameters
        Materials, exponent and axial length.
    max_penetration : float, optional
        Largest admissible penetration, normally the bushing wall thickness [m];
        a load needing more raises :class:`ContactError`.

    Returns
    -------
    ContactSolution
    """
    contour.check_pin(pin)
    load = np.asarray(load, float).ravel()
    azimuth = np.broadcast_to(np.asarray(azimuth, float).ravel(), load.shape)
    if np.any(~np.isfinite(load)) or np.any(load < 0):
        raise ContactError("load: must be finite and >= 0")
    b = contour.axial_length
    r_b = contour.radius_at(azimuth)
    r_p = pin.radius
    modulus = parameters.effective_modulus
    k = stiffness(
        r_p,
        r_b,
        parameters.pin_youngs_modulus,
        parameters.pin_poisson_ratio,
        parameters.bushing_youngs_modulus,
        parameters.bushing_poisson_ratio,
    )
    penetration = (load / k) ** (1.0 / parameters.exponent)
    if max_penetration is not None and np.any(penetration > max_penetration):
        i = int(np.argmax(penetration > max_penetration))
        raise ContactError(
            f"load: {load[i]:.6g} N at {np.degrees(azimuth[i]):.4g} deg would push the pin "
            f"through the bushing wall (Hertz penetration {penetration[i]:.3g} m)"
        )
    relative = r_p * r_b / (r_b - r_p)
    a = half_width(load, b, relative, modulus)
    p0 = peak_pressure(load, b, relative, modulus)
    # the profile is nonzero only within a of the compression centre: evaluate it on a
    # window of nodes about each load line and scatter it into the (M, N) pressure
    window = _Window(contour.nodes, azimuth, np.minimum(a / r_b, 0.5 * np.pi))
    profile = _window_profile(r_b[:, None] * window.phi, a, p0)
    narrow = window.shape(profile, load)
    area = contour.spring_area[window.index]
    carried = (profile * area * window.cos).sum(axis=1)
    scale = np.where(carried > 0, load / np.where(carried > 0, carried, 1.0), 0.0)
    window_pressure = profile * scale[:, None]
    half_angle = np.where(narrow, 0.0, np.minimum(a / r_b, 0.5 * np.pi))
    eccentricity = (
        np.stack([np.cos(azimuth), np.sin(azimuth)], axis=1) * ((r_b - r_p) + penetration)[:, None]
    )
    return window.solution(window_pressure, area, eccentricity, penetration, half_angle)


class _Window:
    """Nodes within the widest Hertz contact of each load line (offsets ``-W .. W``
    about the nearest node, :func:`~jointwear.contact.balance.window.nearest_nodes`)."""

    def __init__(self, nodes: int, azimuth: FloatArray, reach: FloatArray) -> None:
        dtheta = 2 * np.pi / nodes
        self.nodes, self.dtheta = nodes, dtheta
        self.position, self.centre, self.shift = nearest_nodes(nodes, azimuth)
        width = int(min(np.ceil(float(reach.max(initial=0.0)) / dtheta) + 2, (nodes - 1) // 2))
        offsets = np.arange(-width, width + 1)
        self.width = width
        self.phi = offsets * dtheta + self.shift[:, None]
        self.cos, self.sin = angle_addition(offsets, dtheta, self.shift)
        self.index = (self.centre[:, None] + offsets) % nodes

    def shape(self, profile: FloatArray, load: FloatArray) -> NDArray[np.bool_]:
        """Cut ``profile`` [Pa] at 90 degrees and give a contact narrower than a node to
        the two nearest nodes, in place; the loads [N] so given."""
        width, dtheta = self.width, self.dtheta
        # Hertz knows nothing of the geometry: past a quarter of the circumference its
        # ellipse would wrap onto the back of the bushing, where a smaller pin cannot
        # touch (and where cos(beta) < 0 would make springs pull). Cut it at 90 degrees
        # (|shift| <= dtheta / 2: a window short of it has nothing to cut).
        if (width + 0.5) * dtheta >= 0.5 * np.pi:
            profile[np.abs(self.phi) >= 0.5 * np.pi] = 0.0
        # contacts narrower than a node: share the load between the two nearest nodes. The
        # centre column is the nearest node (|phi| = |shift| <= dtheta / 2, and the profile
        # falls with |phi| in floating point too): no node is inside where it is not
        narrow = profile[:, width] <= 0.0
        if np.any(narrow & (load > 0)):
            rows = np.flatnonzero(narrow & (load > 0))
            pos = self.position[rows] / dtheta
            lo = np.floor(pos).astype(int) % self.nodes
            frac = pos - np.floor(pos)
            # the window columns of nodes lo and lo + 1
            column = (lo - self.centre[rows] + width) % self.nodes
            profile[rows, column] = 1.0 - frac
            profile[rows, column + 1] = frac
        return narrow

    def solution(self, window_pressure, area, eccentricity, penetration, half_angle):
        """The :class:`ContactSolution` of the window's pressure [Pa] (spring areas [m^2],
        pin centre [m], approach [m], contact half-angles [rad])."""
        m, width, nodes = window_pressure.shape[0], self.width, self.nodes
        force = window_pressure * area
        pressure = np.zeros((m, nodes))
        # a window holds each node at most once (2 width + 1 <= nodes): one flat scatter,
        # without put_along_axis's index broadcasting (a fifth of the solve)
        row_start = np.arange(m)[:, None] * nodes
        pressure.reshape(-1)[row_start + self.index] = window_pressure
        contact = window_pressure > 0
        centre, shift = contact[:, width], self.shift
        return ContactSolution(
            pressure=pressure,
            eccentricity=eccentricity,
            penetration=penetration,
            normal_force=(force * self.cos).sum(axis=1),
            tangential_force=(force * self.sin).sum(axis=1),
            half_angle_left=half_angle,
            half_angle_right=half_angle,
            # (phi grows along a row, and only the centre column's sign is its shift's)
            springs_left=contact[:, width + 1 :].sum(axis=1) + (centre & (shift > 0)),
            springs_right=contact[:, :width].sum(axis=1) + (centre & (shift < 0)),
            iterations=np.zeros(m, dtype=np.int64),
            model="hertz",
        )
