r"""Wear laws, stage 3b: pressure and sliding over a cycle -> wear depth per node.

A wear law is a function ``law(pressure, sliding_distance) -> wear_depth`` of the
pressure on every node at every step [Pa], shape (M, N), and the sliding distance
of every step [m], shape (M,), returning the wear depth of every node over the
cycle [m], shape (N,). :data:`WEAR_LAWS` holds the named ones; ``wear.law`` selects
one, and :class:`~jointwear.simulation.Simulation` also takes any callable.

``archard`` (default; paper eqs. 8-9, Archard [1]_)
    .. math:: h_j = K_d \sum_k p_{jk} \Delta s_k

    ``K_d`` = ``materials.bushing.wear_coefficient`` [1/Pa].
``energy`` (dissipated-energy wear, Fouvry et al. [2]_)
    The worn volume is proportional to the friction energy dissipated, whose
    density over a step is ``mu p Delta s``:

    .. math:: h_j = k_E \sum_k \mu \, p_{jk} \Delta s_k

    ``k_E`` = ``wear.energy_coefficient`` [m^3/J = 1/Pa], ``mu`` =
    ``wear.friction_coefficient`` [-]. With a constant ``mu`` it is Archard's law with
    ``K_d = k_E mu``; the two part where the friction coefficient changes with the
    conditions (a callable ``mu(p)`` here).
``power-law``, ``running-in``, ``tabulated``
    Archard's coefficient following the pressure and sliding speed, or falling while
    the joint runs in (:mod:`jointwear.tribology.operating`); these laws are called
    with the run's :class:`~jointwear.tribology.operating.WearConditions` as well.

References
----------
.. [1] Archard, J.F. (1953). Contact and rubbing of flat surfaces. Journal of Applied
   Physics 24, 981-988.
.. [2] Fouvry, S., Liskiewicz, T., Kapsa, Ph., Hannel, S., Sauger, E. (2003). An energy
   description of wear mechanisms and its applications to oscillating sliding
   contacts. Wear 255, 287-298.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.registry import Registry
from jointwear.tribology import archard, operating

if TYPE_CHECKING:
    from jointwear.config import MaterialConfig, WearConfig

__all__ = ["WEAR_LAWS", "WearLaw", "energy_wear_depth", "wear_law"]

FloatArray = NDArray[np.float64]
#: ``law(pressure [Pa] (M, N), sliding_distance [m] (M,)) -> wear depth [m] (N,)``
WearLaw = Callable[[FloatArray, FloatArray], FloatArray]


def energy_wear_depth(
    pressure: ArrayLike,
    sliding_distance: ArrayLike,
    energy_coefficient: float,
    friction_coefficient: float | Callable[[FloatArray], FloatArray],
) -> FloatArray:
    """Wear depth from the friction energy dissipated at every node [m].

    .. math:: h_j = k_E \\sum_k \\mu(p_{jk}) \\, p_{jk} \\, \\Delta s_k

    Parameters
    ----------
    pressure : array_like, shape (M, N)
        Pressure on node ``j`` at step ``k`` [Pa].
    sliding_distance : array_like, shape (M,)
        Sliding distance of each step [m].
    energy_coefficient : float
        Energy wear coefficient ``k_E``, worn volume per dissipated energy [m^3/J].
    friction_coefficient : float or callable
        ``mu`` [-], or ``mu(p)`` of the pressure [Pa -> -].

    Returns
    -------
    ndarray, shape (N,)
        Radial wear depth [m].
    """
    p = np.asarray(pressure, dtype=float)
    mu = friction_coefficient(p) if callable(friction_coefficient) else friction_coefficient
    return energy_coefficient * (np.asarray(sliding_distance, float) @ (mu * p))


def _archard(wear: WearConfig, bushing: MaterialConfig) -> WearLaw:
    coefficient = bushing.wear_coefficient

    def law(pressure: FloatArray, sliding: FloatArray) -> FloatArray:
        return archard.wear_depth(pressure, sliding, coefficient)

    return law


def _energy(wear: WearConfig, bushing: MaterialConfig) -> WearLaw:
    def law(pressure: FloatArray, sliding: FloatArray) -> FloatArray:
        return energy_wear_depth(
            pressure, sliding, wear.energy_coefficient, wear.friction_coefficient
        )

    return law


#: ``wear.law`` -> builder ``(wear section, bushing material) -> WearLaw``
WEAR_LAWS: Registry[Callable[[WearConfig, MaterialConfig], WearLaw]] = Registry(
    "wear law", "wear.law"
)
WEAR_LAWS.add("archard", _archard)
WEAR_LAWS.add("energy", _energy)
WEAR_LAWS.add("power-law", operating.power_law)
WEAR_LAWS.add("running-in", operating.running_in)
WEAR_LAWS.add("tabulated", operating.tabulated)


def wear_law(
    wear: WearConfig, bushing: MaterialConfig, law: str | WearLaw | None = None
) -> WearLaw:
    """The wear law of a run: a registered name (default ``wear.law``) or a callable.

    Parameters
    ----------
    wear : jointwear.config.WearConfig
        The ``[wear]`` section: the law's name, the energy law's ``k_E`` [m^3/J] and
        ``mu`` [-].
    bushing : jointwear.config.MaterialConfig
        The bushing's material: Archard's ``wear_coefficient`` ``K_d`` [1/Pa].
    law : str or callable, optional
        Name of a law in :data:`WEAR_LAWS`, or ``law(pressure, sliding_distance)``
        [Pa, m -> m].
    """
    if law is None:
        law = wear.law
    if callable(law):
        return law
    return WEAR_LAWS.get(law)(wear, bushing)
