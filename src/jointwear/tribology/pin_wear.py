r"""Wear of the pin: the second surface, in the pin's own frame.

The paper takes the pin as rigid (hard steel on PTFE). With
``materials.pin.wear_coefficient`` set the pin wears too: its wear depth ``h_p``
lives on ``N`` nodes of the pin's own frame, and the pin turns by the relative
rotation ``phi_k`` (cumulative over the cycle) against the bushing, so the pin's
material point facing bushing node ``j`` at step ``k`` is the one at
``theta_j - phi_k`` in the pin frame.

*Contact.* A worn pin recedes towards its centre by ``h_p``; along the radial ray of
a bushing node that widens the gap by ``h_p(theta_j - phi_k)``, which (to first order
in ``h_p / R_p``, as the radial penetration of the spring models is) is the same as
a bushing radius larger by that much: the contact of step ``k`` is solved on the
contour ``r_j + h_p(theta_j - phi_k)`` (:func:`pin_on_bushing`).

*Wear.* The spring force of bushing node ``j``, ``p_jk A_j`` with ``A_j = r_j dtheta
b``, presses the pin over ``R_p dtheta b``, so the pin sees ``p_jk r_j / R_p``; Archard's
law with the pin's ``K_p`` over the same slip ``ds_k`` wears it by
``K_p p_jk (r_j / R_p) ds_k`` at pin angle ``theta_j - phi_k`` (:func:`pin_wear_depth`).
Summed over the pin, the worn volume is Archard's global form ``K_p sum_k N_k ds_k``,
as the bushing's is with ``K_d``.

*Along the pin* (``joint.axial_slices = S > 1``) the pin's wear is a map ``h_p,s`` of
shape ``(S, N)``: slice ``s`` of the pin faces slice ``s`` of the bushing, and the pin
turns as a rigid body, so every slice shares the rotation ``phi_k``. Slice ``s`` is
solved on ``r_sj + h_p,s(theta_j - phi_k)`` and wears by ``K_p p_sjk (r_sj / R_p) ds_k``;
both functions take the slices as a leading axis of their arrays.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["pin_on_bushing", "pin_wear_depth", "shift_weights"]

FloatArray = NDArray[np.float64]


def shift_weights(rotation: ArrayLike, nodes: int) -> tuple[NDArray[np.int64], FloatArray]:
    """Whole-node shift and fraction of each step's pin rotation on an ``N``-node grid.

    Parameters
    ----------
    rotation : array_like, shape (M,)
        Rotation of the pin relative to the bushing at each step [rad].
    nodes : int
        Nodes ``N`` around the circumference [-].

    Returns
    -------
    shift : ndarray of int, shape (M,)
        ``floor(phi / dtheta)``.
    fraction : ndarray, shape (M,)
        The rest, in nodes, in [0, 1).
    """
    position = np.asarray(rotation, dtype=float) * nodes / (2.0 * np.pi)
    shift = np.floor(position)
    return shift.astype(np.int64), position - shift


def pin_on_bushing(pin_depth: ArrayLike, rotation: ArrayLike) -> FloatArray:
    """The pin's wear seen from each bushing node at each step [m].

    ``h_p(theta_j - phi_k)``, periodic linear interpolation of the pin profile.

    Parameters
    ----------
    pin_depth : array_like, shape (N,) or (S, N)
        Wear depth of the pin at its nodes, pin frame [m]; along the pin, one row per
        slice.
    rotation : array_like, shape (M,)
        Rotation of the pin relative to the bushing at each step [rad] (the same for
        every slice: the pin turns as a rigid body).

    Returns
    -------
    ndarray, shape (M, N) or (S, M, N)
    """
    depth = np.asarray(pin_depth, dtype=float)
    nodes = depth.shape[-1]
    shift, fraction = shift_weights(rotation, nodes)
    index = (np.arange(nodes)[None, :] - shift[:, None]) % nodes
    # theta_j - phi = (j - shift - fraction) dtheta: between pin nodes index - 1 and index
    return (1.0 - fraction[:, None]) * depth[..., index] + fraction[:, None] * depth[..., index - 1]


def pin_wear_depth(
    pressure: ArrayLike,
    sliding_distance: ArrayLike,
    wear_coefficient: float,
    bushing_radius: ArrayLike,
    pin_radius: float,
    rotation: ArrayLike,
) -> FloatArray:
    """Archard wear of the pin over the steps, in the pin's frame [m].

    .. math:: h_{p,i} = K_p \\sum_k \\sum_j p_{jk} \\frac{r_j}{R_p} \\Delta s_k \\,
              w_{ijk}

    with ``w_ijk`` the linear weights that put bushing node ``j`` at pin angle
    ``theta_j - phi_k``.

    Along the pin, slice ``s`` of the pin wears by its bushing slice's pressure
    ``p_sjk`` and radii ``r_sj``, at the angles of the one rotation ``phi_k``.

    Parameters
    ----------
    pressure : array_like, shape (M, N) or (S, M, N)
        Bushing pressure on node ``j`` at step ``k`` [Pa] (of slice ``s``).
    sliding_distance : array_like, shape (M,)
        Slip of the step [m].
    wear_coefficient : float
        The pin's ``K_p`` [1/Pa].
    bushing_radius : array_like, shape (N,) or (S, N)
        Radius of the bushing nodes (their spring areas) [m] (of slice ``s``).
    pin_radius : float
        Unworn pin radius ``R_p`` [m].
    rotation : array_like, shape (M,)
        Rotation of the pin relative to the bushing at each step [rad].

    Returns
    -------
    ndarray, shape (N,) or (S, N)
        The pin's wear depth in its frame [m].
    """
    radius = np.asarray(bushing_radius, dtype=float) / pin_radius
    load = np.asarray(pressure, dtype=float) * radius[..., None, :]
    load = load * np.asarray(sliding_distance, dtype=float)[:, None]
    nodes = load.shape[-1]
    shift, fraction = shift_weights(rotation, nodes)
    index = (np.arange(nodes)[None, :] - shift[:, None]) % nodes
    depth = np.zeros((*load.shape[:-2], nodes))
    np.add.at(depth, (..., index), (1.0 - fraction[:, None]) * load)
    np.add.at(depth, (..., (index - 1) % nodes), fraction[:, None] * load)
    return wear_coefficient * depth
