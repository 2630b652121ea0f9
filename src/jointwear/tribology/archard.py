"""Archard wear (paper eqs. 8-9), stage 3b: pressure and sliding -> wear depth.

Local form: the wear depth of a node over a step is

.. math:: \\Delta h_j = K_d \\, p_j \\, \\Delta s ,

``K_d`` the dimensional wear coefficient [1/Pa = m^2/N] (``k / H`` of eq. 8) and
``Delta s`` the step's sliding distance (:func:`jointwear.tribology.sliding.sliding_distance`,
``R_b |Delta phi|``). Wear is taken on the bushing (PTFE) only: the steel pin is orders of magnitude
harder, and its wear is neglected, as in the paper.

Global form: summing ``Delta h_j A_j`` over the nodes gives the worn volume of a
step, ``K_d Delta s sum_j p_j A_j``: Archard's ``V = K_d N s`` with ``N`` the total
normal (radial) spring force. On a conformal contact ``N`` exceeds the load
``F_N`` (the springs are not parallel to it; ``F_N = sum p_j A_j cos beta_j``),
by ``1/cos`` of an effective contact angle, a few per cent.

The simulation's inner step adds the same ``K_d p_j Delta s`` inside the fused contact
kernel (:func:`jointwear.contact.kernel.archard_wear` and its compiled loop), which is
tested against :func:`wear_depth` at 1e-12.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["archard_volume", "wear_depth"]

FloatArray = NDArray[np.float64]


def wear_depth(
    pressure: ArrayLike, sliding_distance: ArrayLike, wear_coefficient: float
) -> FloatArray:
    """Wear depth accumulated over a sequence of steps at every node [m].

    .. math:: h_j = K_d \\sum_k p_{jk} \\, \\Delta s_k

    Parameters
    ----------
    pressure : array_like, shape (M, N)
        Pressure on node ``j`` at step ``k`` [Pa].
    sliding_distance : array_like, shape (M,)
        Sliding distance of each step [m].
    wear_coefficient : float
        Dimensional wear coefficient ``K_d`` [1/Pa].

    Returns
    -------
    ndarray, shape (N,)
        Radial wear depth [m].
    """
    return wear_coefficient * (np.asarray(sliding_distance, float) @ np.asarray(pressure, float))


def archard_volume(
    normal_force: ArrayLike,
    sliding_distance: ArrayLike,
    wear_coefficient: float,
) -> float:
    """Archard's global form ``V = K_d sum_k N_k Delta s_k`` [m^3].

    Parameters
    ----------
    normal_force : array_like, shape (M,)
        Normal force pressed into the worn surface at each step [N].
    sliding_distance : array_like, shape (M,)
        Sliding distance of each step [m].
    wear_coefficient : float
        ``K_d`` [1/Pa].
    """
    return float(
        wear_coefficient
        * np.dot(np.asarray(normal_force, float), np.asarray(sliding_distance, float))
    )
