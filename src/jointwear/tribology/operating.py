r"""Wear laws that depend on how the joint runs: pressure, sliding speed, running-in.

Archard's law takes one wear coefficient ``K_d`` for every pressure and speed. Polymer
and composite bearings wear faster at high pressure and speed, and fastest while they
run in. Three laws of the registry (:data:`jointwear.tribology.wear_laws.WEAR_LAWS`,
``wear.law``) follow the conditions of each step:

``power-law`` (generalized Archard, e.g. Rhee's power law [1]_)
    .. math:: h_j = K_d \sum_k \left(\frac{p_{jk}}{p_\mathrm{ref}}\right)^{a}
              \left(\frac{v_k}{v_\mathrm{ref}}\right)^{b} p_{jk} \, \Delta s_k

    ``K_d`` = ``materials.bushing.wear_coefficient`` [1/Pa], the coefficient at
    ``p_ref`` = ``wear.reference_pressure`` [Pa] and ``v_ref`` = ``wear.reference_speed``
    [m/s]; ``a`` = ``wear.pressure_exponent`` [-], ``b`` = ``wear.speed_exponent`` [-].
    ``a = b = 0`` is Archard's law, bit for bit. ``v_k = \Delta s_k / \Delta t_k`` is
    the step's sliding speed at the sliding radius of the wear (``R_b``,
    :mod:`jointwear.tribology.sliding`).
``running-in`` (an exponential running-in transient, Blau [2]_, [3]_)
    .. math:: K(s) = K_\infty + (K_0 - K_\infty) \, e^{-s / \lambda}

    ``K_0`` = ``wear.initial_wear_coefficient`` [1/Pa], ``K_inf`` =
    ``materials.bushing.wear_coefficient`` [1/Pa] (the steady coefficient), ``lambda`` =
    ``wear.running_in_distance`` [m], ``s`` the distance slid since the joint was new.
    A cycle that starts at ``s_n`` and slides ``S`` wears with the mean of ``K`` over it,

    .. math:: \bar K_n = K_\infty + (K_0 - K_\infty) \frac{\lambda}{S}
              e^{-s_n / \lambda} \left(1 - e^{-S / \lambda}\right),

    so that cycle after cycle at constant pressure the wear is exactly
    ``p \int_0^{s} K \, ds``. ``s_n = n S``: the sliding distance of the current cycle
    times the cycles run (a duty cycle: its share-weighted distance).
``tabulated`` (a coefficient measured at several conditions)
    .. math:: h_j = \sum_k K(x_{jk}) \, p_{jk} \, \Delta s_k

    ``K`` linearly interpolated in ``wear.table_coefficients`` [1/Pa] at
    ``wear.table_points`` of ``x`` = ``wear.table_against`` (without them, in the bushing
    material's ``wear_table``, e.g. a library entry's with its source): the step's sliding speed
    ``v_k`` [m/s], the local ``p_jk v_k`` [Pa m/s] or the operating temperature
    ``wear.temperature`` [K] (one ``K`` for the run). Speed and PV beyond the table take
    its end values, with one warning per run; a temperature outside it is refused.

References
----------
.. [1] Rhee, S.K. (1970). Wear equation for polymers sliding against metal surfaces.
   Wear 16, 431-445.
.. [2] Blau, P.J. (2005). On the nature of running-in. Tribology International 38,
   1007-1012.
.. [3] Blau, P.J. (1989). Friction and Wear Transitions of Materials: Break-in,
   Run-in, Wear-in. Noyes Publications, Park Ridge NJ.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.config.wear_table import table_of
from jointwear.errors import ConfigError, MaterialLimitWarning
from jointwear.tribology import archard

if TYPE_CHECKING:
    from jointwear.config import MaterialConfig, WearConfig

__all__ = [
    "OperatingLaw",
    "WearConditions",
    "power_law_wear_depth",
    "running_in_coefficient",
    "running_in_mean_coefficient",
    "tabulated_coefficient",
]

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class WearConditions:
    """How the joint runs in the cycle a wear law is asked about.

    Attributes
    ----------
    speed : ndarray, shape (M,)
        Sliding speed of each step [m/s].
    distance : float
        Distance slid since the joint was new, at the start of the cycle [m].
    """

    speed: FloatArray
    distance: float = 0.0


def power_law_wear_depth(
    pressure: ArrayLike,
    sliding_distance: ArrayLike,
    speed: ArrayLike,
    wear_coefficient: float,
    reference_pressure: float,
    reference_speed: float,
    pressure_exponent: float,
    speed_exponent: float,
) -> FloatArray:
    """Generalized Archard wear depth at every node [m].

    .. math:: h_j = K_d \\sum_k (p_{jk}/p_\\mathrm{ref})^{a} (v_k/v_\\mathrm{ref})^{b}
              p_{jk} \\, \\Delta s_k

    Parameters
    ----------
    pressure : array_like, shape (M, N)
        Pressure on node ``j`` at step ``k`` [Pa].
    sliding_distance : array_like, shape (M,)
        Sliding distance of each step [m].
    speed : array_like, shape (M,)
        Sliding speed of each step [m/s].
    wear_coefficient : float
        ``K_d`` at the reference pressure and speed [1/Pa].
    reference_pressure : float
        ``p_ref`` [Pa].
    reference_speed : float
        ``v_ref`` [m/s].
    pressure_exponent : float
        ``a`` [-].
    speed_exponent : float
        ``b`` [-].
    """
    p = np.asarray(pressure, dtype=float)
    ds = np.asarray(sliding_distance, dtype=float)
    # a zero exponent multiplies by exactly one: Archard's law, bit for bit
    if pressure_exponent != 0.0:
        p = p * (p / reference_pressure) ** pressure_exponent
    if speed_exponent != 0.0:
        ds = ds * (np.asarray(speed, dtype=float) / reference_speed) ** speed_exponent
    return archard.wear_depth(p, ds, wear_coefficient)


def running_in_coefficient(
    distance: ArrayLike, initial: float, steady: float, length: float
) -> FloatArray:
    """The running-in wear coefficient ``K(s) = K_inf + (K_0 - K_inf) exp(-s / lambda)`` [1/Pa].

    Parameters
    ----------
    distance : array_like
        Distance slid since the joint was new ``s`` [m].
    initial : float
        ``K_0`` of the new joint [1/Pa].
    steady : float
        ``K_inf`` after running in [1/Pa].
    length : float
        ``lambda``, the sliding distance over which ``K - K_inf`` falls by ``e`` [m].
    """
    return steady + (initial - steady) * np.exp(-np.asarray(distance, dtype=float) / length)


def running_in_mean_coefficient(
    start: float, span: float, initial: float, steady: float, length: float
) -> float:
    """Mean of ``K(s)`` over ``[start, start + span]`` [1/Pa] (exact).

    .. math:: \\bar K = K_\\infty + (K_0 - K_\\infty) \\frac{\\lambda}{S}
              e^{-s_0/\\lambda} (1 - e^{-S/\\lambda})

    Parameters
    ----------
    start : float
        ``s_0`` [m].
    span : float
        ``S`` [m]; ``0`` gives ``K(s_0)``.
    initial, steady : float
        ``K_0``, ``K_inf`` [1/Pa].
    length : float
        ``lambda`` [m].
    """
    if span <= 0.0:
        return float(running_in_coefficient(start, initial, steady, length))
    # -expm1 keeps 1 - exp(-S / lambda) exact for a cycle short against lambda
    fraction = -math.expm1(-span / length) * length / span
    return steady + (initial - steady) * math.exp(-start / length) * fraction


class OperatingLaw:
    """A wear law that reads how the joint runs (:class:`WearConditions`).

    Called as ``law(pressure, sliding_distance, conditions)``; without conditions it
    refuses (a callable taking only pressure and sliding cannot serve it).

    Parameters
    ----------
    name : str
        The ``wear.law`` it is.
    depth : callable
        ``depth(pressure [Pa], sliding [m], conditions) -> wear depth [m]``.
    """

    needs_conditions = True

    def __init__(self, name: str, depth: Any) -> None:
        self.name = name
        self._depth = depth

    def __call__(
        self,
        pressure: FloatArray,
        sliding: FloatArray,
        conditions: WearConditions | None = None,
    ) -> FloatArray:
        if conditions is None:
            raise ConfigError(
                f"wear.law: {self.name!r} needs the sliding speed and distance of the run "
                f"(a Simulation gives them)"
            )
        return self._depth(pressure, sliding, conditions)


def power_law(wear: WearConfig, bushing: MaterialConfig) -> OperatingLaw:
    """The ``power-law`` wear law of a ``[wear]`` section and the bushing's material."""
    coefficient = bushing.wear_coefficient

    def depth(pressure, sliding, conditions: WearConditions) -> FloatArray:
        return power_law_wear_depth(
            pressure,
            sliding,
            conditions.speed,
            coefficient,
            wear.reference_pressure,
            wear.reference_speed,
            wear.pressure_exponent,
            wear.speed_exponent,
        )

    return OperatingLaw("power-law", depth)


def running_in(wear: WearConfig, bushing: MaterialConfig) -> OperatingLaw:
    """The ``running-in`` wear law of a ``[wear]`` section and the bushing's material."""
    steady, initial = bushing.wear_coefficient, wear.initial_wear_coefficient
    length = wear.running_in_distance

    def depth(pressure, sliding, conditions: WearConditions) -> FloatArray:
        span = float(np.sum(sliding))
        mean = running_in_mean_coefficient(conditions.distance, span, initial, steady, length)
        return archard.wear_depth(pressure, sliding, mean)

    return OperatingLaw("running-in", depth)


def tabulated_coefficient(
    value: ArrayLike, points: ArrayLike, coefficients: ArrayLike, against: str
) -> FloatArray:
    """A wear coefficient interpolated linearly in a table [1/Pa].

    Outside the table the end values are taken, with a warning
    (:class:`~jointwear.errors.MaterialLimitWarning`) that names the variable and the
    range: the wear there is the table's end value, not an extrapolation.

    Parameters
    ----------
    value : array_like
        Where the coefficient is wanted [m/s, Pa m/s or K, as ``against``].
    points : array_like, shape (T,)
        The table's increasing points [same unit].
    coefficients : array_like, shape (T,)
        The coefficient at each point [1/Pa].
    against : str
        What the table is against (``"speed"``, ``"pv"``, ``"temperature"``).
    """
    x = np.asarray(value, dtype=float)
    grid = np.asarray(points, dtype=float)
    # (a node out of contact has p v = 0: not a condition the joint runs at)
    running = x[x > 0.0] if against == "pv" else x
    if running.size and (running.min() < grid[0] or running.max() > grid[-1]):
        warnings.warn(
            f"wear.table_points: the {against} of the run reaches {running.min():.4g} to "
            f"{running.max():.4g} (SI), beyond the table's {grid[0]:.4g} to {grid[-1]:.4g}; "
            f"the table's end values are used there",
            MaterialLimitWarning,
            stacklevel=2,
        )
    return np.interp(x, grid, np.asarray(coefficients, dtype=float))


def tabulated(wear: WearConfig, bushing: MaterialConfig) -> OperatingLaw:
    """The ``tabulated`` wear law: ``h_j = sum_k K(x_jk) p_jk ds_k``, ``x`` the step's
    sliding speed, the local ``p v`` or the operating temperature; the table is
    ``[wear]``'s, else the bushing material's ``wear_table``."""
    table = table_of(wear, bushing)
    if table is None:
        raise ConfigError(
            "wear.table_against: missing (needed by wear.law = 'tabulated', unless the "
            "bushing's material has a wear_table)"
        )
    points, coefficients, against = table.points, table.coefficients, table.against
    said = []

    def coefficient(value: ArrayLike) -> FloatArray:
        # warned once per run, not at every cycle
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            k = tabulated_coefficient(value, points, coefficients, against)
        if caught and not said:
            said.append(True)
            warnings.warn(str(caught[0].message), MaterialLimitWarning, stacklevel=3)
        return k

    def depth(pressure, sliding, conditions: WearConditions) -> FloatArray:
        p = np.asarray(pressure, dtype=float)
        ds = np.asarray(sliding, dtype=float)
        if against == "temperature":
            return archard.wear_depth(p, ds, float(coefficient(wear.temperature)))
        if against == "speed":
            return ds @ (coefficient(conditions.speed)[:, None] * p)
        return ds @ (coefficient(p * np.asarray(conditions.speed)[:, None]) * p)

    return OperatingLaw("tabulated", depth)
