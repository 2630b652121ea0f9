"""Asperity contact through a thin film: Greenwood--Tripp, film parameter, regime.

Where the film is thin compared with the surface roughness the tallest asperities of
pin and bushing touch and carry part of the load. Greenwood and Tripp's model of two
rough surfaces with Gaussian summit heights gives the nominal asperity pressure at the
local separation ``h`` of the mean planes:

.. math::

    p_a(h) = \\frac{16\\sqrt{2}}{15}\\,\\pi\\,(\\eta\\beta\\sigma)^2
             \\sqrt{\\frac{\\sigma}{\\beta}}\\;E^*\\,F_{5/2}\\Big(\\frac{h}{\\sigma}\\Big),
    \\qquad
    F_{5/2}(H) = \\frac{1}{\\sqrt{2\\pi}}\\int_H^\\infty (s-H)^{5/2} e^{-s^2/2}\\,ds,

with ``sigma`` the composite roughness (Rq) of the two surfaces, ``eta`` the summit
density, ``beta`` the summit radius and ``E*`` the plane-strain composite modulus
``1/E* = (1 - nu_1^2)/E_1 + (1 - nu_2^2)/E_2`` (the Hertz modulus; texts that write
``8 sqrt(2)/15`` use ``E' = 2 E*``). ``F_{5/2}`` is usually replaced by the fit
``A (Omega - H)^z`` for ``H < Omega`` and 0 beyond, with ``A = 4.4086e-5``,
``Omega = 4``, ``z = 6.804`` (Arnell et al. 1991; Hu et al. 1994); the exact integral
(:func:`greenwood_tripp_integral`) is available too. The fit is within 11 % of the
integral for ``H <= 2`` and falls below it beyond (by 74 % at ``H = 3``; see
``docs/lubrication.md``), which hardly matters there: the asperity pressure is then a
thousandth of that at contact.

Default asperity parameters: ``eta beta sigma = 0.04`` and ``sigma / beta = 0.001``,
mid-range of the values Greenwood and Tripp (1970) give for engineering surfaces
(``eta beta sigma`` 0.03-0.05, ``sigma / beta`` 1e-4 to 1e-2). Measure them (a
profilometer's summit analysis) where the asperity load matters.

Sources: [1]_, [2]_, [3]_, [4]_.

References
----------
.. [1] J. A. Greenwood and J. H. Tripp, "The contact of two nominally flat rough
   surfaces", Proc. Instn Mech. Engrs 185 (1970) 625-633.
.. [2] R. D. Arnell, P. B. Davies, J. Halling and T. L. Whomes, *Tribology: Principles
   and Design Applications*, Macmillan (1991).
.. [3] Y. Hu, H. S. Cheng, T. Arai, Y. Kobayashi and S. Aoyama, "Numerical simulation
   of piston ring in mixed lubrication -- a nonaxisymmetrical analysis", ASME J.
   Tribol. 116 (1994) 470-478.
.. [4] I. M. Hutchings and P. Shipway, *Tribology: Friction and Wear of Engineering
   Materials*, 2nd ed., Butterworth-Heinemann (2017).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import fixed_quad
from scipy.special import gamma, pbdv

__all__ = [
    "BOUNDARY_LIMIT",
    "DEFAULT_ETA_BETA_SIGMA",
    "DEFAULT_SIGMA_OVER_BETA",
    "FIT_A",
    "FIT_OMEGA",
    "FIT_Z",
    "MIXED_LIMIT",
    "asperity_pressure",
    "composite_modulus",
    "composite_roughness",
    "film_parameter",
    "greenwood_tripp_fit",
    "greenwood_tripp_integral",
    "journal_asperity_force",
    "lubrication_regime",
]

FloatArray = NDArray[np.float64]

#: the fit F_{5/2}(H) ~ A (Omega - H)^z (Arnell et al. 1991; Hu et al. 1994)
FIT_A = 4.4086e-5
FIT_OMEGA = 4.0
FIT_Z = 6.804
#: eta beta sigma and sigma / beta: mid-range of Greenwood & Tripp (1970)
DEFAULT_ETA_BETA_SIGMA = 0.04
DEFAULT_SIGMA_OVER_BETA = 1e-3
#: film parameter bands: full film above 3, mixed from 1 to 3, boundary at 1 and below
MIXED_LIMIT = 3.0
BOUNDARY_LIMIT = 1.0
#: where the exact integral is cut off: F_{5/2}(8) ~ 1e-17
EXACT_CUTOFF = 8.0
#: Gauss-Legendre nodes over the contact arc of a journal
ARC_NODES = 48


def composite_roughness(roughness_pin: ArrayLike, roughness_bushing: ArrayLike) -> FloatArray:
    """Composite roughness ``sigma = sqrt(Rq_1^2 + Rq_2^2)`` of two surfaces [m].

    Parameters
    ----------
    roughness_pin, roughness_bushing : array_like
        Root-mean-square roughness Rq of each surface [m].
    """
    return np.hypot(np.asarray(roughness_pin, float), np.asarray(roughness_bushing, float))


def composite_modulus(
    modulus_pin: ArrayLike,
    poisson_pin: ArrayLike,
    modulus_bushing: ArrayLike,
    poisson_bushing: ArrayLike,
) -> FloatArray:
    """Plane-strain composite (Hertz) modulus ``E*`` [Pa].

    .. math:: \\frac{1}{E^*} = \\frac{1-\\nu_1^2}{E_1} + \\frac{1-\\nu_2^2}{E_2}

    Parameters
    ----------
    modulus_pin, modulus_bushing : array_like
        Young's moduli [Pa].
    poisson_pin, poisson_bushing : array_like
        Poisson's ratios [-].
    """
    compliance = (1.0 - np.asarray(poisson_pin, float) ** 2) / np.asarray(modulus_pin, float)
    compliance = compliance + (1.0 - np.asarray(poisson_bushing, float) ** 2) / np.asarray(
        modulus_bushing, float
    )
    return 1.0 / compliance


def greenwood_tripp_fit(separation: ArrayLike) -> FloatArray:
    """The fit ``F_{5/2}(H) = A (Omega - H)^z`` for ``H < Omega``, else 0 [-].

    Parameters
    ----------
    separation : array_like
        ``H = h / sigma``, the separation of the mean planes over the roughness [-].

    References
    ----------
    Arnell et al. (1991); Hu et al. (1994).
    """
    gap = np.maximum(FIT_OMEGA - np.asarray(separation, dtype=float), 0.0)
    return FIT_A * gap**FIT_Z


def greenwood_tripp_integral(separation: ArrayLike) -> FloatArray:
    """The exact ``F_{5/2}(H)`` of Gaussian summit heights [-].

    .. math::

        F_{5/2}(H) = \\frac{1}{\\sqrt{2\\pi}}\\int_H^\\infty (s-H)^{5/2}e^{-s^2/2}ds
                   = \\frac{\\Gamma(7/2)}{\\sqrt{2\\pi}}\\,e^{-H^2/4}\\,D_{-7/2}(H),

    with ``D`` the parabolic cylinder function (:func:`scipy.special.pbdv`).

    Parameters
    ----------
    separation : array_like
        ``H = h / sigma`` [-].
    """
    h = np.minimum(np.asarray(separation, dtype=float), EXACT_CUTOFF)
    value = gamma(3.5) * np.exp(-h * h / 4.0) * pbdv(-3.5, h)[0] / np.sqrt(2.0 * np.pi)
    return np.where(np.asarray(separation) >= EXACT_CUTOFF, 0.0, value)


def asperity_pressure(
    film_thickness: ArrayLike,
    roughness: ArrayLike,
    composite_modulus: ArrayLike,
    eta_beta_sigma: ArrayLike = DEFAULT_ETA_BETA_SIGMA,
    sigma_over_beta: ArrayLike = DEFAULT_SIGMA_OVER_BETA,
    exact: bool = False,
) -> FloatArray:
    """Greenwood--Tripp nominal asperity pressure at a local film thickness [Pa].

    .. math::

        p_a = \\frac{16\\sqrt{2}}{15}\\pi(\\eta\\beta\\sigma)^2\\sqrt{\\sigma/\\beta}\\,
              E^* F_{5/2}(h/\\sigma)

    Parameters
    ----------
    film_thickness : array_like
        Local separation ``h`` of the mean planes [m].
    roughness : array_like
        Composite roughness ``sigma`` (:func:`composite_roughness`) [m].
    composite_modulus : array_like
        ``E*`` (:func:`composite_modulus`) [Pa].
    eta_beta_sigma : array_like
        Summit density times summit radius times roughness [-].
    sigma_over_beta : array_like
        Roughness over summit radius [-].
    exact : bool
        Use the exact ``F_{5/2}`` instead of the usual fit.

    References
    ----------
    Greenwood & Tripp (1970).
    """
    separation = np.asarray(film_thickness, float) / np.asarray(roughness, float)
    shape = greenwood_tripp_integral(separation) if exact else greenwood_tripp_fit(separation)
    factor = 16.0 * np.sqrt(2.0) / 15.0 * np.pi * np.asarray(eta_beta_sigma, float) ** 2
    return factor * np.sqrt(sigma_over_beta) * np.asarray(composite_modulus, float) * shape


def film_parameter(min_film_thickness: ArrayLike, roughness: ArrayLike) -> FloatArray:
    """Film parameter ``lambda = h_min / sigma`` [-].

    Parameters
    ----------
    min_film_thickness : array_like
        ``h_min`` [m].
    roughness : array_like
        Composite roughness ``sigma`` [m].
    """
    return np.asarray(min_film_thickness, float) / np.asarray(roughness, float)


def lubrication_regime(film_parameter: ArrayLike) -> NDArray[np.str_]:
    """Lubrication regime by the film parameter ``lambda``.

    ``"hydrodynamic"`` for ``lambda > 3``, ``"mixed"`` for ``1 < lambda <= 3`` and
    ``"boundary"`` for ``lambda <= 1``: the bands commonly used for conformal contacts
    (Hutchings & Shipway 2017; Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film
    Lubrication*, 2004, draw the same boundaries at 1 and 3).

    Parameters
    ----------
    film_parameter : array_like
        ``lambda = h_min / sigma`` [-].

    Returns
    -------
    ndarray of str
        The regime of each value.
    """
    value = np.asarray(film_parameter, dtype=float)
    return np.where(
        value > MIXED_LIMIT, "hydrodynamic", np.where(value > BOUNDARY_LIMIT, "mixed", "boundary")
    )


def journal_asperity_force(
    radius: ArrayLike,
    length: ArrayLike,
    clearance: ArrayLike,
    eccentricity_ratio: ArrayLike,
    roughness: ArrayLike,
    composite_modulus: ArrayLike,
    eta_beta_sigma: ArrayLike = DEFAULT_ETA_BETA_SIGMA,
    sigma_over_beta: ArrayLike = DEFAULT_SIGMA_OVER_BETA,
    exact: bool = False,
) -> FloatArray:
    """Radial asperity force on a pin at an eccentricity [N] (negative: towards the centre).

    The asperity pressure at ``h = c (1 + eps cos theta)`` is integrated over the arc
    where it is not zero, around the smallest film (``theta = pi``); it is symmetric
    about the line of centres, so the force has no tangential part:

    .. math::

        F_{a} = R L \\int p_a\\big(c(1+\\varepsilon\\cos\\theta)\\big)
                \\cos\\theta\\, d\\theta

    (Gauss--Legendre, :func:`scipy.integrate.fixed_quad`, over the contact arc).

    Parameters
    ----------
    radius : array_like
        Pin radius ``R`` [m].
    length : array_like
        Bushing length ``L`` [m].
    clearance : array_like
        Radial clearance ``c`` [m].
    eccentricity_ratio : array_like
        ``eps``; values up to 1 (surfaces' mean planes touching) [-].
    roughness : array_like
        Composite roughness ``sigma`` [m].
    composite_modulus : array_like
        ``E*`` [Pa].
    eta_beta_sigma, sigma_over_beta : array_like
        Asperity parameters [-] (:func:`asperity_pressure`).
    exact : bool
        Use the exact ``F_{5/2}`` instead of the fit.
    """
    eps, c, sigma = np.broadcast_arrays(
        np.asarray(eccentricity_ratio, float),
        np.asarray(clearance, float),
        np.asarray(roughness, float),
    )
    cutoff = EXACT_CUTOFF if exact else FIT_OMEGA
    # the arc |theta - pi| < half_width is where h < cutoff sigma
    threshold = (cutoff * sigma / c - 1.0) / np.maximum(eps, 1e-300)
    half_width = np.pi - np.arccos(np.clip(threshold, -1.0, 1.0))

    def integrand(node: FloatArray) -> FloatArray:
        offset = half_width[..., None] * node
        film = c[..., None] * (1.0 - eps[..., None] * np.cos(offset))
        pressure = asperity_pressure(
            film,
            sigma[..., None],
            np.asarray(composite_modulus, float)[..., None],
            np.asarray(eta_beta_sigma, float)[..., None],
            np.asarray(sigma_over_beta, float)[..., None],
            exact,
        )
        return -pressure * np.cos(offset)

    integral = fixed_quad(integrand, -1.0, 1.0, n=ARC_NODES)[0] * half_width
    return np.asarray(radius, float) * np.asarray(length, float) * integral
