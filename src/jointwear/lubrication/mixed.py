"""Mixed lubrication under a steady load: how film and asperities share it.

A pin turning under a steady load moves off the centre until the film force and the
force of the touching asperities together balance the load:

.. math::

    \\big(F_r^{film}(\\varepsilon) + F^{asp}(\\varepsilon)\\big)^2
    + F_t^{film}(\\varepsilon)^2 = W^2,

a monotone equation in the eccentricity ratio solved with
:func:`scipy.optimize.elementwise.find_root` (thousands of states at once). The film
force is one of the models of :mod:`jointwear.lubrication.mobility` (short, long,
finite length; half-Sommerfeld cavitation) with the wedge speed
``omega_pin + omega_bushing - 2 omega_load``; the asperity force is Greenwood--Tripp's
(:func:`~jointwear.lubrication.asperity.journal_asperity_force`), along the line of
centres. The bulk of pin and bushing is rigid here: the asperities alone deform.

What the wear law needs is the asperity pressure over the bushing: where the
asperities touch, the surfaces wear; where the film separates them, they do not. The
film parameter ``lambda = h_min / sigma`` gives the regime.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.optimize import elementwise

from jointwear.errors import ConfigError
from jointwear.lubrication.asperity import (
    BOUNDARY_LIMIT,
    DEFAULT_ETA_BETA_SIGMA,
    DEFAULT_SIGMA_OVER_BETA,
    asperity_pressure,
    film_parameter,
    journal_asperity_force,
    lubrication_regime,
)
from jointwear.lubrication.film import min_film_thickness
from jointwear.lubrication.mobility import FILM_MODELS, film_force
from jointwear.registry import suggest

__all__ = ["LoadSharing", "steady_load_sharing"]

FloatArray = NDArray[np.float64]

#: the largest eccentricity ratio searched: h_min = 1e-9 c
LARGEST_ECCENTRICITY = 1.0 - 1e-9


@dataclass(frozen=True)
class LoadSharing:
    """Equilibrium of a pin under a steady load, film and asperities together.

    Attributes
    ----------
    eccentricity_ratio : ndarray
        ``eps`` at equilibrium [-].
    attitude_angle : ndarray
        Angle from the load's direction to the eccentricity, positive towards positive
        angles [rad].
    min_film_thickness : ndarray
        ``h_min = c (1 - eps)`` [m].
    film_parameter : ndarray
        ``lambda = h_min / sigma`` [-].
    regime : ndarray of str
        ``"hydrodynamic"``, ``"mixed"`` or ``"boundary"`` by ``lambda``.
    film_load, asperity_load : ndarray
        Magnitudes of the film's and of the asperities' force on the pin [N].
    asperity_load_fraction : ndarray
        Share of the load the asperities carry, measured along the load (film and
        asperity shares add up to 1) [-].
    asperity_pressure : ndarray
        Asperity pressure at the requested bushing angles, shape ``(..., n_angles)``
        [Pa]: the pressure the wear law sees.
    bulk_contact : ndarray of bool
        The rigid-bulk model has left its range: the film is thinner than the
        roughness (``lambda <= 1``) and the asperities could not carry the load even
        at ``h_min -> 0``, so the film carries the rest at a thickness no real surface
        keeps. A real joint deforms in bulk there: the dry contact models govern.
        Without film (no viscosity or no speed) the values are those at
        ``h_min -> 0``.
    """

    eccentricity_ratio: FloatArray
    attitude_angle: FloatArray
    min_film_thickness: FloatArray
    film_parameter: FloatArray
    regime: NDArray[np.str_]
    film_load: FloatArray
    asperity_load: FloatArray
    asperity_load_fraction: FloatArray
    asperity_pressure: FloatArray
    bulk_contact: NDArray[np.bool_]


def total_force(
    eps: FloatArray, model: str, geometry: tuple[FloatArray, ...], asperity: dict[str, object]
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Film radial, film tangential and asperity radial force at ``eps`` [N]."""
    radius, length, clearance, viscosity, wedge, roughness, modulus, ebs, sob = geometry
    film = film_force(model, radius, length, clearance, viscosity, eps, 0.0, wedge)
    asp = journal_asperity_force(
        radius, length, clearance, eps, roughness, modulus, ebs, sob, asperity["exact"]
    )
    return np.asarray(film.radial), np.asarray(film.tangential), asp


def steady_load_sharing(
    load: ArrayLike,
    radius: ArrayLike,
    length: ArrayLike,
    clearance: ArrayLike,
    viscosity: ArrayLike,
    pin_speed: ArrayLike,
    roughness: ArrayLike,
    composite_modulus: ArrayLike,
    *,
    bushing_speed: ArrayLike = 0.0,
    load_speed: ArrayLike = 0.0,
    model: str = "finite",
    eta_beta_sigma: ArrayLike = DEFAULT_ETA_BETA_SIGMA,
    sigma_over_beta: ArrayLike = DEFAULT_SIGMA_OVER_BETA,
    exact: bool = False,
    load_direction: ArrayLike = 0.0,
    bushing_angles: ArrayLike | None = None,
) -> LoadSharing:
    """Eccentricity at which film and asperities together carry a steady load.

    Solves ``|F_film(eps) + F_asp(eps)| = W`` for ``eps`` in ``[0, 1 - 1e-9]`` (module
    text) and returns the state the wear law needs.

    Parameters
    ----------
    load : array_like
        Magnitude ``W`` of the load on the pin, > 0 [N].
    radius : array_like
        Pin radius ``R`` [m].
    length : array_like
        Bushing length ``L`` [m].
    clearance : array_like
        Radial clearance ``c`` [m].
    viscosity : array_like
        Dynamic viscosity ``mu`` [Pa s]
        (:func:`~jointwear.lubrication.lubricants.dynamic_viscosity`).
    pin_speed : array_like
        Angular velocity of the pin [rad/s].
    roughness : array_like
        Composite roughness ``sigma`` [m].
    composite_modulus : array_like
        ``E*`` of pin and bushing [Pa].
    bushing_speed : array_like
        Angular velocity of the bushing [rad/s].
    load_speed : array_like
        Angular velocity of the load's direction [rad/s]; the pin's centre follows it.
    model : str
        Film model: ``"short"``, ``"long"``, ``"finite"`` or ``"finite-reynolds"``.
    eta_beta_sigma, sigma_over_beta : array_like
        Greenwood--Tripp asperity parameters [-].
    exact : bool
        Exact ``F_{5/2}`` instead of the usual fit.
    load_direction : array_like
        Direction of the load in the joint's frame [rad].
    bushing_angles : array_like, optional
        Angles of the bushing, in the joint's frame, at which to give the asperity
        pressure [rad]; 360 angles over the turn if omitted.

    Returns
    -------
    LoadSharing
        The equilibrium.

    Raises
    ------
    ConfigError
        For an unknown film model (with the closest name).
    """
    if model not in FILM_MODELS:
        raise ConfigError(
            f"lubrication.model: unknown film model {model!r}{suggest(model, FILM_MODELS)}"
        )
    wedge = (
        np.asarray(pin_speed, float)
        + np.asarray(bushing_speed, float)
        - 2.0 * np.asarray(load_speed, float)
    )
    parts = np.broadcast_arrays(
        *(
            np.asarray(a, float)
            for a in (
                load,
                radius,
                length,
                clearance,
                viscosity,
                wedge,
                roughness,
                composite_modulus,
                eta_beta_sigma,
                sigma_over_beta,
            )
        )
    )
    weight, geometry = parts[0], tuple(parts[1:])
    options = {"exact": exact}

    def residual(eps: FloatArray, weight: FloatArray, *geometry: FloatArray) -> FloatArray:
        radial, tangential, asp = total_force(eps, model, geometry, options)
        return np.hypot(radial + asp, tangential) - weight

    high = np.full(weight.shape, LARGEST_ECCENTRICITY)
    no_root = residual(high, weight, *geometry) < 0.0
    found = elementwise.find_root(
        residual,
        (np.zeros(weight.shape), high),
        args=(weight, *geometry),
        tolerances={"xatol": 1e-13, "xrtol": 1e-12},
    )
    eps = np.where(no_root, LARGEST_ECCENTRICITY, found.x)
    capacity = -total_force(high, model, geometry, options)[2]
    state = sharing_state(eps, geometry, model, options, load_direction, bushing_angles)
    bulk = (capacity < weight) & (state.film_parameter <= BOUNDARY_LIMIT)
    return replace(state, bulk_contact=bulk)


def sharing_state(
    eps: FloatArray,
    geometry: tuple[FloatArray, ...],
    model: str,
    options: dict[str, object],
    load_direction: ArrayLike,
    bushing_angles: ArrayLike | None,
) -> LoadSharing:
    """The :class:`LoadSharing` of an equilibrium eccentricity (see :func:`steady_load_sharing`).

    ``bulk_contact`` is left False; the caller sets it.
    """
    clearance, roughness, modulus, ebs, sob = geometry[2], *geometry[5:]
    radial, tangential, asp = total_force(eps, model, geometry, options)
    total_radial = radial + asp
    attitude = np.arctan2(tangential, -total_radial)
    h_min = min_film_thickness(clearance, eps)
    lam = film_parameter(h_min, roughness)
    carried = np.maximum(np.hypot(total_radial, tangential), np.finfo(float).tiny)
    angles = (
        np.linspace(0.0, 2.0 * np.pi, 360, endpoint=False)
        if bushing_angles is None
        else np.asarray(bushing_angles, float)
    )
    centre = np.asarray(load_direction, float) + attitude
    film = clearance[..., None] * (1.0 - eps[..., None] * np.cos(angles - centre[..., None]))
    pressure = asperity_pressure(
        film,
        roughness[..., None],
        modulus[..., None],
        ebs[..., None],
        sob[..., None],
        bool(options["exact"]),
    )
    return LoadSharing(
        eccentricity_ratio=eps,
        attitude_angle=attitude,
        min_film_thickness=h_min,
        film_parameter=lam,
        regime=lubrication_regime(lam),
        film_load=np.hypot(radial, tangential),
        asperity_load=np.abs(asp),
        asperity_load_fraction=asp * total_radial / carried**2,
        asperity_pressure=pressure,
        bulk_contact=np.zeros(eps.shape, dtype=bool),
    )
