"""NLCP: the nonlinear contact pressure distribution model (paper eq. 7).

The bushing is discretised into springs as in Winkler's model, but each spring
is a small cylinder-on-plane Hertz contact: the force of a spring grows as a
power of its penetration [1]_,

.. math:: p_j = \\frac{K \\delta_j^n}{A}, \\qquad
          K = \\frac{4}{3\\pi(\\sigma_p + \\sigma_b)} \\sqrt{R_p}, \\qquad
          \\sigma = \\frac{1-\\nu^2}{\\pi E},

``K`` being eq. (2) with the bushing radius ``R_j -> inf`` (a plane, Goldsmith [2]_), ``R_p`` the
pin radius, ``n = 1.5`` by default and ``A`` the spring area.

Mesh dependence
---------------
As the paper writes it, the force of spring ``j`` is ``p_j A_j = K delta_j^n``:
it does not depend on how much bushing surface the spring stands for, so the
total force of a contact arc grows with the number of springs in it. Halving
the node spacing doubles the stiffness of the joint; the pressure that balances
a given load falls and the contact narrows. The paper's results belong to a
spring every 1 degree, so the spring area ``A`` is an explicit parameter,
default the area of a 1 degree spring at the unworn radius,
``R_b * (pi/180) * b``. With ``nlcp_variant = "paper"`` each node's force is
``K delta^n`` (the paper, mesh-dependent unless ``nodes = 360``); with
``"mesh-independent"`` the pressure law ``p = K delta^n / A`` is integrated
over the nodes' own areas ``r_j dtheta b``, so results converge as ``N`` grows
and coincide with the paper's form at 1 degree spacing.

Stiffness
---------
``contact.stiffness`` overrides ``K``. Eq. (2)'s ``pi`` cancels against eq. (3)'s
``sigma = (1 - nu^2) / (pi E)``; Lankarani-Nikravesh write ``sigma = (1 - nu^2) / E``
without either ``pi``, and mixing the conventions gives ``K / pi``, a reading that
reproduces the paper's NLCP wear widths (docs/reproduction.md).

References
----------
.. [1] The NLCP paper, eqs. (2), (7).
.. [2] Goldsmith, W.: Impact. Arnold (1960).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.laws import ContactParameters, PowerLaw, effective_modulus

__all__ = ["pressure", "spring_law", "stiffness"]


def stiffness(
    pin_radius: float,
    pin_youngs_modulus: float,
    pin_poisson_ratio: float,
    bushing_youngs_modulus: float,
    bushing_poisson_ratio: float,
) -> float:
    """Spring stiffness ``K`` of eq. (2) with ``R_j -> inf`` [N/m^1.5].

    .. math:: K = \\tfrac{4}{3} E^* \\sqrt{R_p}

    Parameters
    ----------
    pin_radius : float
        Pin radius ``R_p`` [m].
    pin_youngs_modulus, bushing_youngs_modulus : float
        Young's moduli [Pa].
    pin_poisson_ratio, bushing_poisson_ratio : float
        Poisson's ratios [-].
    """
    modulus = effective_modulus(
        pin_youngs_modulus, pin_poisson_ratio, bushing_youngs_modulus, bushing_poisson_ratio
    )
    return 4.0 / 3.0 * modulus * np.sqrt(pin_radius)


def pressure(
    penetration: ArrayLike, stiffness: float, exponent: float, spring_area: float
) -> NDArray[np.float64]:
    """NLCP pressure ``p = K delta^n / A`` [Pa] (eq. 7).

    Parameters
    ----------
    penetration : array_like
        Penetration ``delta`` [m]; negative means no contact.
    stiffness : float
        ``K`` [N/m^n].
    exponent : float
        ``n`` [-].
    spring_area : float
        ``A`` [m^2].
    """
    return stiffness * np.maximum(np.asarray(penetration, float), 0.0) ** exponent / spring_area


def spring_law(parameters: ContactParameters) -> PowerLaw:
    """NLCP spring law from contact parameters (see the module notes on variants)."""
    k = parameters.stiffness
    if k is None:
        k = stiffness(
            parameters.pin_radius,
            parameters.pin_youngs_modulus,
            parameters.pin_poisson_ratio,
            parameters.bushing_youngs_modulus,
            parameters.bushing_poisson_ratio,
        )
    force_area = parameters.spring_area if parameters.nlcp_variant == "paper" else None
    return PowerLaw(
        k / parameters.spring_area, parameters.exponent, name="nlcp", force_area=force_area
    )
