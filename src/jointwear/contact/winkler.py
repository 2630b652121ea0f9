"""Winkler elastic foundation (paper eqs. 4-5).

Each bushing node is an independent linear spring (Pödra and Andersson [1]_;
Johnson [2]_, §5.9),

.. math:: p_j = \\frac{E_w}{L} \\, \\delta_j ,

with ``L`` the bushing wall thickness and ``E_w`` the foundation modulus. The
paper calls ``E_w`` a "complex elastic modulus" and does not define it; two
definitions are offered:

* ``"youngs"``: ``E_w = E`` of the bushing (what the paper's numbers imply);
* ``"constrained"``: the thin-layer (oedometric) modulus
  ``E (1 - nu) / ((1 + nu)(1 - 2 nu))``, exact for a thin layer bonded to a
  rigid housing and loaded by a rigid indenter (no lateral strain).

"Traditional" Winkler (this module's model ``winkler``) assumes the bushing is
a circle, so its springs are symmetric about the load: the penetration is
evaluated on the circle through the contour at the compression centre. On an
unworn bushing it is identical to the asymmetric model
(:mod:`jointwear.contact.asymmetric_winkler`).

References
----------
.. [1] Pödra, P., Andersson, S.: Wear simulation with the Winkler surface model.
   Wear 207, 79-85 (1997).
.. [2] Johnson, K. L.: Contact Mechanics, Cambridge University Press (1985), §5.9.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.laws import ContactParameters, PowerLaw
from jointwear.errors import ConfigError

__all__ = ["circle_force", "foundation_modulus", "pressure", "spread_factor", "spring_law"]


def foundation_modulus(youngs_modulus: float, poisson_ratio: float, kind: str = "youngs") -> float:
    """Winkler foundation modulus ``E_w`` [Pa].

    Parameters
    ----------
    youngs_modulus : float
        Young's modulus of the bushing ``E`` [Pa].
    poisson_ratio : float
        Poisson's ratio of the bushing ``nu`` [-].
    kind : {"youngs", "constrained"}
        ``E``, or the constrained modulus ``E (1-nu) / ((1+nu)(1-2nu))``.
    """
    if kind == "youngs":
        return youngs_modulus
    if kind == "constrained":
        nu = poisson_ratio
        if not nu < 0.5:
            # 1 - 2 nu = 0: an incompressible layer has no constrained modulus (it
            # squeezes out sideways; the springs are no longer independent)
            raise ConfigError(
                f"contact.foundation_modulus: 'constrained' needs a Poisson ratio below 0.5 "
                f"(materials.bushing.poisson_ratio = {nu:g}); use 'youngs'"
            )
        return youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    raise ConfigError(
        f"contact.foundation_modulus: unknown kind {kind!r}; choose 'youngs' or 'constrained'"
    )


def pressure(penetration: ArrayLike, modulus: float, thickness: float) -> NDArray[np.float64]:
    """Winkler pressure ``p = E_w / L * delta`` [Pa] (eq. 4).

    Parameters
    ----------
    penetration : array_like
        Penetration ``delta`` [m], negative values mean no contact.
    modulus : float
        Foundation modulus ``E_w`` [Pa].
    thickness : float
        Elastic layer (bushing wall) thickness ``L`` [m].
    """
    return modulus / thickness * np.maximum(np.asarray(penetration, float), 0.0)


def circle_force(
    approach: ArrayLike,
    clearance: float,
    radius: float,
    axial_length: float,
    stiffness: float,
    pin_radius: float | None = None,
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Closed-form Winkler force on a circular bushing.

    With the pin displaced by ``s = c + delta_0`` along the load, the penetration
    at angle ``phi`` from the load line is, to first order in ``s / R_p``
    (small-clearance kinematics, ``pin_radius=None``),

    .. math:: \\delta(\\phi) = s \\cos\\phi - c ,

    contact spans ``|phi| < alpha`` with ``cos(alpha) = c / s`` and eq. (5),
    ``F = k b R int delta cos(phi) dphi``, integrates to

    .. math:: F = k b R \\left[ s(\\alpha + \\sin\\alpha\\cos\\alpha) - 2 c \\sin\\alpha \\right].

    This omits the curvature of the pin: the exact penetration along the node
    ray is ``s cos(phi) + sqrt(R_p^2 - s^2 sin^2(phi)) - R`` (what the load
    balance uses). Given ``pin_radius``, its second-order expansion is used,

    .. math:: \\delta(\\phi) = s \\cos\\phi - c - \\kappa \\sin^2\\phi,
              \\qquad \\kappa = \\frac{s^2}{2 R_p},

    so ``cos(alpha)`` is the root in ``[0, 1]`` of
    ``kappa cos^2(alpha) + s cos(alpha) - (c + kappa) = 0`` and

    .. math:: F = k b R \\left[ s(\\alpha + \\sin\\alpha\\cos\\alpha) - 2 c \\sin\\alpha
              - \\tfrac{2}{3} \\kappa \\sin^3\\alpha \\right].

    The neglected terms are ``O(s^4 / R_p^3)``. For the paper's joint at 200 N
    (``s ~ 59 um``, ``R_p = 7.45 mm``) the curvature term is about 0.07 um at
    the contact edge and changes the force by about 0.36 %.

    Parameters
    ----------
    approach : array_like
        Penetration at the compression centre ``delta_0`` [m].
    clearance : float
        Radial clearance ``c = R - R_p`` [m].
    radius : float
        Bushing radius ``R`` [m] (the spring area is ``R dphi b``).
    axial_length : float
        Axial length ``b`` [m].
    stiffness : float
        Foundation stiffness ``k = E_w / L`` [Pa/m].
    pin_radius : float, optional
        Pin radius ``R_p`` [m]. ``None`` (default): first-order kinematics
        without the pin-curvature term.

    Returns
    -------
    force : ndarray
        Resultant along the load [N].
    half_angle : ndarray
        Contact half-angle ``alpha`` [rad].
    """
    s = clearance + np.asarray(approach, float)
    if pin_radius is None:
        return _first_order_force(s, clearance, stiffness * axial_length * radius)
    return _curved_force(s, clearance, stiffness * axial_length * radius, pin_radius)


def _first_order_force(s, clearance, scale):
    """:func:`circle_force` without the pin's curvature: force [N] and half-angle [rad] at
    offset ``s`` [m], clearance [m] and ``scale = k b R`` [N/m^2]."""
    alpha = np.arccos(np.clip(clearance / s, -1.0, 1.0))
    force = scale * (0.5 * s * (2 * alpha + np.sin(2 * alpha)) - 2 * clearance * np.sin(alpha))
    return force, alpha


def _curved_force(s, clearance, scale, pin_radius):
    """:func:`circle_force` with the pin's curvature to second order (pin radius [m])."""
    kappa = s**2 / (2.0 * pin_radius)
    # root of kappa x^2 + s x - (c + kappa) = 0 in the cancellation-free form
    cos_alpha = 2.0 * (clearance + kappa) / (s + np.sqrt(s**2 + 4.0 * kappa * (clearance + kappa)))
    alpha = np.arccos(np.clip(cos_alpha, -1.0, 1.0))
    sin_alpha = np.sin(alpha)
    force = scale * (
        s * (alpha + sin_alpha * np.cos(alpha))
        - 2.0 * clearance * sin_alpha
        - (2.0 / 3.0) * kappa * sin_alpha**3
    )
    return force, alpha


def spread_factor(half_angle: ArrayLike) -> NDArray[np.float64]:
    """Sum of the spring forces over the load they carry, on a circle [-].

    A contact arc carries the load at a slant: the springs push with
    ``sum_j F_j`` while only ``sum_j F_j cos(phi_j) = F`` balances the load. For
    linear springs and small-clearance kinematics (``p ~ cos(phi) - cos(alpha)``)

    .. math:: \\kappa(\\alpha) = \\frac{\\int p \\, d\\phi}{\\int p \\cos\\phi \\, d\\phi}
              = \\frac{2 (\\sin\\alpha - \\alpha \\cos\\alpha)}{\\alpha - \\sin\\alpha \\cos\\alpha}
              \\approx 1 + \\frac{\\alpha^2}{10}.

    Archard's law wears volume in proportion to ``sum_j F_j``, so ``kappa`` is the
    factor by which a wide contact wears more than its load alone would say.

    Parameters
    ----------
    half_angle : array_like
        Contact half-angle ``alpha`` [rad], in ``(0, pi/2]``.
    """
    alpha = np.asarray(half_angle, dtype=float)
    sin, cos = np.sin(alpha), np.cos(alpha)
    with np.errstate(invalid="ignore", divide="ignore"):
        exact = 2 * (sin - alpha * cos) / (alpha - sin * cos)
    # small arcs: the closed form loses ~eps / alpha^3 to cancellation, the series
    # (next term ~4e-4 alpha^6) is the better of the two below 0.03 rad
    series = 1 + alpha**2 / 10 + alpha**4 * (19 / 4200)
    return np.where(alpha < 0.03, series, exact)


def spring_law(parameters: ContactParameters) -> PowerLaw:
    """Traditional (symmetric) Winkler spring law from contact parameters."""
    modulus = foundation_modulus(
        parameters.bushing_youngs_modulus,
        parameters.bushing_poisson_ratio,
        parameters.foundation_modulus,
    )
    return PowerLaw(modulus / parameters.bushing_thickness, 1.0, name="winkler", symmetric=True)
