"""A straightforward reference of one revolution of contact and wear (the paper's algorithm).

Per time step, the load balance is a scalar equation in the pin displacement ``x``
along the load, solved by :func:`scipy.optimize.brentq` on the *full* node set with
the textbook penetration ``delta_j = max(t_j - r_j, 0)``, ``t_j`` the distance from the
bushing centre to the far side of the pin along node ``j``'s ray; a plain Python loop
runs over the steps and accumulates Archard's wear ``h_j += K_d p_j ds`` step by step.
No windows, no batching, no warm starts: slow on purpose.

It is the oracle the fast path (:mod:`jointwear.contact.balance`) must match to 1e-9
(``tests/test_fast_path.py``) and the baseline the benchmarks divide by
(``benchmarks/bench_simulation.py`` imports it from here).
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq, root

__all__ = ["reference_equilibrium_step", "reference_revolution", "reference_step"]

_EPS = np.finfo(float).eps


def _nodes(radius: np.ndarray, azimuth: float, law) -> tuple[np.ndarray, ...]:
    """Node angle from the load line, and the radius and area each spring sees."""
    n = radius.size
    dtheta = 2 * math.pi / n
    phi = dtheta * np.arange(n) - azimuth
    if law.symmetric:  # traditional Winkler: the circle through the compression centre
        position = (azimuth % (2 * math.pi)) / dtheta
        lower = math.floor(position)
        frac = position - lower
        centre = (1 - frac) * radius[lower % n] + frac * radius[(lower + 1) % n]
        r = np.full(n, centre)
    else:
        r = np.asarray(radius, dtype=float)
    return phi, r, dtheta


def _area(law, r: np.ndarray, dtheta: float, axial_length: float):
    return law.force_area if law.force_area is not None else r * dtheta * axial_length


def reference_step(
    radius: np.ndarray,
    axial_length: float,
    pin_radius: float,
    load: float,
    azimuth: float,
    law,
) -> tuple[np.ndarray, float]:
    """Pressure on every node for one load (paper balance), by brentq.

    Parameters
    ----------
    radius : ndarray, shape (N,)
        Bushing radii at ``2 pi j / N`` [m].
    axial_length : float
        Axial length [m].
    pin_radius : float
        Pin radius [m].
    load, azimuth : float
        Load [N] and its direction [rad].
    law : SpringLaw
        Spring law (``pressure``, ``force_area``, ``symmetric``).

    Returns
    -------
    pressure : ndarray, shape (N,)
        [Pa].
    offset : float
        Pin displacement along the load [m].
    """
    phi, r, dtheta = _nodes(radius, azimuth, law)
    area = _area(law, r, dtheta, axial_length)
    cos, sin = np.cos(phi), np.sin(phi)

    def pressure(x: float) -> np.ndarray:
        t = x * cos + np.sqrt(pin_radius**2 - (x * sin) ** 2)
        return law.pressure(np.maximum(t - r, 0.0))

    def residual(x: float) -> float:
        return float(np.sum(pressure(x) * area * cos)) - load

    lower = float(np.min(r)) - pin_radius  # no node can touch yet
    if load == 0.0:
        return np.zeros_like(r), lower
    step = 1e-7
    upper = lower + step
    while residual(upper) <= 0.0:
        step *= 2.0
        upper = lower + step
    x = brentq(residual, lower, upper, xtol=1e-30, rtol=4 * _EPS, maxiter=500)
    return pressure(x), x


def reference_equilibrium_step(
    radius: np.ndarray,
    axial_length: float,
    pin_radius: float,
    load: float,
    azimuth: float,
    law,
) -> tuple[np.ndarray, np.ndarray]:
    """Pressure for one load in full 2-D equilibrium, by :func:`scipy.optimize.root`.

    The pin position ``(a, b)`` (along and across the load) is found so that the
    springs' resultant vector equals the load vector, starting from the paper solution.

    Returns
    -------
    pressure : ndarray, shape (N,)
        [Pa].
    position : ndarray, shape (2,)
        ``(a, b)`` [m].
    """
    phi, r, dtheta = _nodes(radius, azimuth, law)
    area = _area(law, r, dtheta, axial_length)
    cos, sin = np.cos(phi), np.sin(phi)

    def pressure(p: np.ndarray) -> np.ndarray:
        a, b = p
        t = a * cos + b * sin + np.sqrt(pin_radius**2 - (cos * b - sin * a) ** 2)
        return law.pressure(np.maximum(t - r, 0.0))

    def residual(p: np.ndarray) -> np.ndarray:
        force = pressure(p) * area
        return np.array([np.sum(force * cos) - load, np.sum(force * sin)]) / max(load, 1e-300)

    _, along = reference_step(radius, axial_length, pin_radius, load, azimuth, law)
    if load == 0.0:
        return np.zeros_like(r), np.array([along, 0.0])
    solution = root(residual, np.array([along, 0.0]), method="hybr", options={"xtol": 1e-15})
    return pressure(solution.x), solution.x


def reference_revolution(
    radius: np.ndarray,
    axial_length: float,
    pin_radius: float,
    loads: np.ndarray,
    azimuths: np.ndarray,
    law,
    sliding_distance: np.ndarray,
    wear_coefficient: float,
    balance: str = "paper",
) -> tuple[np.ndarray, np.ndarray]:
    """One revolution, step by step: pressure of every step and the Archard wear.

    Returns
    -------
    pressure : ndarray, shape (M, N)
        [Pa].
    wear : ndarray, shape (N,)
        Wear depth of the revolution ``K_d sum_k p_k ds_k`` [m].
    """
    step = reference_step if balance == "paper" else reference_equilibrium_step
    pressures = np.zeros((len(loads), radius.size))
    wear = np.zeros(radius.size)
    for k in range(len(loads)):
        p, _ = step(radius, axial_length, pin_radius, float(loads[k]), float(azimuths[k]), law)
        pressures[k] = p
        wear += wear_coefficient * p * sliding_distance[k]
    return pressures, wear
