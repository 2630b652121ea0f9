"""Reynolds (Swift--Stieber) cavitation of the finite-length bearing, and the steady journal.

The finite-length bearing of :mod:`jointwear.lubrication.mobility` keeps the positive
part of the full-film pressure (half-Sommerfeld, Guembel): the pressure drops to zero
with a kink where the full film turns negative, and the flow is not conserved there.
Reynolds' condition (Swift 1932, Stieber 1933) lets the film rupture where the
pressure reaches zero *with zero gradient*: the dimensionless pressure ``Pi`` of the
film (``p = 6 mu (R/c)^2 m Pi``, module text of :mod:`~jointwear.lubrication.mobility`)
solves the complementarity problem

.. math::

    \\Pi \\ge 0, \\qquad -\\nabla\\cdot(H^3\\nabla\\Pi) - s \\ge 0, \\qquad
    \\Pi\\,\\big(-\\nabla\\cdot(H^3\\nabla\\Pi) - s\\big) = 0,
    \\qquad s = \\sin(\\theta - \\beta),

on the same finite-difference grid (:func:`~jointwear.lubrication.mobility.film_system`):
the discrete form of the variational inequality of the Reynolds condition
(Christopherson 1941: an obstacle problem). It is solved by
the primal--dual active-set method (Hintermueller, Ito & Kunisch 2002), which ends in
a finite number of steps for this M-matrix: the cavitated nodes are guessed, the free
ones solved with ``Pi = 0`` on the others, and the guess corrected until it repeats.

Raimondi and Boyd's tables of the full journal bearing (1958) use Reynolds' condition
at the film's end and let the film *begin* at the largest film thickness
(``Pi = 0`` along that line); ``film_start=True`` reproduces that convention for the
comparison with them. Without it the film begins where the complementarity problem
puts it, which is what a pin without an oil hole has.

References
----------
.. [1] A. A. Raimondi and J. Boyd, "A solution for the finite journal bearing and its
   application to analysis and design", parts I-III, ASLE Trans. 1 (1958).
.. [2] D. G. Christopherson, "A new mathematical method for the solution of film
   lubrication problems", Proc. Instn Mech. Engrs 146 (1941).
.. [3] M. Hintermueller, K. Ito and K. Kunisch, "The primal-dual active set strategy
   as a semismooth Newton method", SIAM J. Optim. 13 (2002).
"""

from __future__ import annotations

from typing import Literal, NamedTuple

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.integrate import simpson
from scipy.sparse import csc_matrix
from scipy.sparse.linalg import splu

from jointwear.errors import JointwearError
from jointwear.lubrication import mobility

__all__ = [
    "Cavitation",
    "SteadyJournal",
    "complementary_pressure",
    "reynolds_forces",
    "steady_journal",
]

FloatArray = NDArray[np.float64]
#: the film's cavitation condition
Cavitation = Literal["half-Sommerfeld", "Reynolds"]
#: active-set steps before giving up (a few suffice; the set repeats in finitely many)
MOST_STEPS = 200


def complementary_pressure(
    operator: csc_matrix,
    source: FloatArray,
    guess: FloatArray | None = None,
    fixed: NDArray[np.bool_] | None = None,
) -> FloatArray:
    """``Pi >= 0``, ``K Pi - f >= 0`` and ``Pi (K Pi - f) = 0`` with ``K = -A`` [-].

    The primal--dual active-set method: the nodes with ``(K Pi - f)_i > K_ii Pi_i``
    are cavitated (``Pi_i = 0``), the others solve ``K Pi = f``; repeated until the
    cavitated set repeats.

    Parameters
    ----------
    operator : csc_matrix
        ``A`` of :func:`~jointwear.lubrication.mobility.film_system` [-].
    source : ndarray
        ``f`` with ``A Pi = -f`` on the film [-].
    guess : ndarray, optional
        A start, e.g. the solution of a neighbouring state [-].
    fixed : ndarray of bool, optional
        Nodes held at ``Pi = 0`` (a supply line at ambient pressure).

    Returns
    -------
    ndarray
        ``Pi`` [-].
    """
    stiffness = -operator
    diagonal = stiffness.diagonal()
    pressure = np.zeros(source.size) if guess is None else guess.copy()
    held = np.zeros(source.size, bool) if fixed is None else fixed
    cavitated = (stiffness @ pressure - source > diagonal * pressure) | held
    for _ in range(MOST_STEPS):
        free = np.flatnonzero(~cavitated)
        pressure = np.zeros(source.size)
        pressure[free] = splu(stiffness[free][:, free]).solve(source[free])
        residual = stiffness @ pressure - source
        residual[free] = 0.0
        again = (residual > diagonal * pressure) | held
        if np.array_equal(again, cavitated):
            return pressure
        cavitated = again
    raise JointwearError(
        f"lubrication.cavitation: the Reynolds condition found no film boundary in "
        f"{MOST_STEPS} active-set steps"
    )


def reynolds_forces(
    eps: float, half_length: float, directions: ArrayLike, film_start: bool = False
) -> FloatArray:
    """``G_r, G_t`` of the film with Reynolds' condition, shape ``(2, n)`` [-].

    The same force factor as
    :func:`~jointwear.lubrication.mobility.tabulated_forces`, of the complementarity
    solution (module text) instead of the positive part of the full film; the
    directions are solved in turn, each started from the one before.

    Parameters
    ----------
    eps : float
        Eccentricity ratio [-].
    half_length : float
        ``L / (2R)``, i.e. ``L / D`` [-].
    directions : array_like
        ``beta`` of the motion [rad].
    film_start : bool
        Hold ``Pi = 0`` along the largest film (Raimondi and Boyd's full bearing).
    """
    theta, stretch, operator = mobility.film_system(eps, half_length)
    rows, columns = mobility.AXIAL_CELLS, mobility.ANGLE_NODES
    fixed = None
    if film_start:
        fixed = np.zeros(rows * columns, bool)
        fixed[::columns] = True  # theta = 0 of every row
    step = 2.0 * np.pi / columns
    axial = np.linspace(0.0, half_length, rows + 1)
    pressure = None
    forces = []
    for beta in np.atleast_1d(np.asarray(directions, float)):
        source = np.tile(stretch * np.sin(theta - beta), rows)
        pressure = complementary_pressure(operator, source, pressure, fixed)
        field = np.zeros((rows + 1, columns))
        field[:-1] = pressure.reshape(rows, columns)
        weighted = field * stretch * step
        over_angle = np.stack([weighted @ np.cos(theta), weighted @ np.sin(theta)])
        forces.append(2.0 * simpson(over_angle, x=axial, axis=-1))
    return np.stack(forces, axis=-1)


class SteadyJournal(NamedTuple):
    """A journal turning under a steady load.

    Attributes
    ----------
    sommerfeld_number : float
        ``S = mu N L D (R/c)^2 / W`` (``N`` in revolutions per second) [-].
    attitude_angle : float
        Angle from the load to the line of centres [rad].
    """

    sommerfeld_number: float
    attitude_angle: float


def steady_journal(
    eccentricity_ratio: float,
    length_to_diameter: float,
    cavitation: Cavitation = "half-Sommerfeld",
    film_start: bool = False,
) -> SteadyJournal:
    """Sommerfeld number and attitude angle of a finite journal bearing [-, rad].

    A turning journal (``beta = 0``) at rest in its bushing:

    .. math:: S = \\frac{L/D}{3\\pi\\varepsilon|G|}, \\qquad
              \\varphi = \\operatorname{atan2}(G_t, -G_r),

    from ``F = 6 mu R^2 (R/c)^2 eps omega G`` and ``S = mu (omega / 2 pi) L D (R/c)^2 / |F|``.
    Raimondi and Boyd's tables (1958) give both against ``eps`` for ``L/D`` = 1/4, 1/2,
    1 and infinity (Reynolds' condition, film from the largest thickness).

    Parameters
    ----------
    eccentricity_ratio : float
        ``eps`` in (0, 1) [-].
    length_to_diameter : float
        ``L / D`` [-].
    cavitation : {"half-Sommerfeld", "Reynolds"}
        The film's cavitation condition.
    film_start : bool
        With ``"Reynolds"``: ``Pi = 0`` along the largest film (Raimondi and Boyd).
    """
    eps, ratio = float(eccentricity_ratio), float(length_to_diameter)
    if cavitation == "Reynolds":
        shape = reynolds_forces(eps, ratio, [0.0], film_start)[:, 0]
    elif cavitation == "half-Sommerfeld":
        shape = mobility.tabulated_forces(eps, ratio, np.array([0.0]))[:, 0]
    else:
        raise JointwearError(
            f"cavitation: expected 'half-Sommerfeld' or 'Reynolds', got {cavitation!r}"
        )
    return SteadyJournal(
        ratio / (3.0 * np.pi * eps * float(np.hypot(*shape))),
        float(np.arctan2(shape[1], -shape[0])),
    )
