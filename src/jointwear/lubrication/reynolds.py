"""The finite-difference Reynolds equation of the finite-length bearing, both cavitations.

The dimensionless pressure ``Pi`` of the film (``p = 6 mu (R/c)^2 m Pi``, module text
of :mod:`jointwear.lubrication.mobility`) solves
``div(H^3 grad Pi) = -sin(theta - beta)`` on the bushing, ``Pi = 0`` at its ends; the
grid is uniform in Sommerfeld's angle, which crowds the nodes at the smallest film
(:func:`film_system`). Two cavitation conditions:

* **half-Sommerfeld** (Guembel): the positive part of the full-film solution
  (:func:`tabulated_forces`); the pressure drops to zero with a kink where the full
  film turns negative, and the flow is not conserved there.
* **Reynolds** (Swift 1932, Stieber 1933): the film ruptures where the pressure
  reaches zero *with zero gradient* (:func:`reynolds_forces`). ``Pi`` solves the
  complementarity problem

  .. math::

      \\Pi \\ge 0, \\qquad -\\nabla\\cdot(H^3\\nabla\\Pi) - s \\ge 0, \\qquad
      \\Pi\\,\\big(-\\nabla\\cdot(H^3\\nabla\\Pi) - s\\big) = 0,
      \\qquad s = \\sin(\\theta - \\beta),

  the discrete variational inequality of Reynolds' condition (Christopherson 1941:
  an obstacle problem), solved by the primal--dual active-set method (Hintermueller,
  Ito & Kunisch 2002), which ends in a finite number of steps for this M-matrix: the
  cavitated nodes are guessed, the free ones solved with ``Pi = 0`` on the others,
  and the guess corrected until it repeats.

Raimondi and Boyd's tables of the full journal bearing (1958) use Reynolds' condition
at the film's end and let the film *begin* at the largest film thickness (``Pi = 0``
along that line); ``film_start=True`` reproduces that convention for the comparison
with them. Without it the film begins where the complementarity problem puts it,
which is what a pin without an oil hole has, whichever way it moves.
:func:`steady_journal` gives the Sommerfeld number and attitude angle of a turning
journal with either condition.

Sources: [1]_, [2]_, [3]_.

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
from scipy.linalg import solveh_banded
from scipy.sparse import csc_matrix, diags, identity, kron
from scipy.sparse.linalg import splu

from jointwear.errors import JointwearError

__all__ = [
    "ANGLE_NODES",
    "AXIAL_CELLS",
    "BandedFilm",
    "Cavitation",
    "SteadyJournal",
    "complementary_pressure",
    "film_system",
    "reynolds_forces",
    "reynolds_solutions",
    "steady_journal",
    "tabulated_forces",
]

FloatArray = NDArray[np.float64]
#: the film's cavitation condition
Cavitation = Literal["half-Sommerfeld", "Reynolds"]
#: active-set steps before giving up (a few suffice; the set repeats in finitely many)
MOST_STEPS = 200
#: finite-difference grid: nodes around the bushing and over half its length
ANGLE_NODES = 120
AXIAL_CELLS = 16


def inverse_sommerfeld_angle(gamma: FloatArray, eps: float) -> FloatArray:
    """``theta`` of a Sommerfeld angle ``gamma`` (inverse of :func:`sommerfeld_angle`) [rad]."""
    b = eps / (1.0 + np.sqrt(1.0 - eps * eps))
    return gamma + 2.0 * np.arctan(b * np.sin(gamma) / (1.0 - b * np.cos(gamma)))


def film_system(
    eps: float,
    half_length: float,
    grid: tuple[int, int] | None = None,
    crowding: float | None = None,
) -> tuple[FloatArray, FloatArray, csc_matrix]:
    """The finite-difference Reynolds operator of the bushing's half on the grid.

    Conservative second-order stencil on ``ANGLE_NODES`` angles uniform in
    Sommerfeld's angle ``gamma`` and ``AXIAL_CELLS`` cells from the middle of the
    bushing (row 0, symmetric) to the node before its end (``Pi = 0`` there).

    Parameters
    ----------
    eps : float
        Eccentricity ratio [-].
    half_length : float
        ``L / (2R)`` [-].
    grid : tuple of int
        Angle nodes and axial cells [-] (a finer grid for films close to the wall);
        ``ANGLE_NODES`` and ``AXIAL_CELLS`` if None.
    crowding : float
        The eccentricity of the Sommerfeld angle the grid is uniform in [-]: ``eps`` if
        None; a smaller one crowds fewer nodes at the smallest film and leaves more on
        the wide side (the film of a pin leaving the wall, whose pressure lies there).

    Returns
    -------
    tuple
        ``theta`` of the angle nodes [rad], ``d theta / d gamma`` there [-], and the
        operator ``A`` with ``A Pi = (d theta / d gamma) f`` the discrete form of
        ``div(H^3 grad Pi) = f`` (rows: axial index major) [-].
    """
    angle_nodes, axial_cells = grid or (ANGLE_NODES, AXIAL_CELLS)
    step = 2.0 * np.pi / angle_nodes
    gamma = step * np.arange(angle_nodes)
    mapped = eps if crowding is None else crowding
    root = np.sqrt(1.0 - mapped * mapped)

    def stretch(g: FloatArray) -> FloatArray:  # d theta / d gamma
        return root / (1.0 - mapped * np.cos(g))

    def film(g: FloatArray) -> FloatArray:
        return 1.0 + eps * np.cos(inverse_sommerfeld_angle(g, mapped))

    mid = gamma + 0.5 * step
    flux = film(mid) ** 3 / stretch(mid) / step**2  # at gamma_{i+1/2}
    around = diags(-(flux + np.roll(flux, 1))) + diags(flux[:-1], 1) + diags(flux[:-1], -1)
    around = around + diags([flux[-1]], angle_nodes - 1) + diags([flux[-1]], 1 - angle_nodes)
    dz = half_length / axial_cells
    axial = diags(
        [-2.0 * np.ones(axial_cells), np.ones(axial_cells - 1), np.ones(axial_cells - 1)],
        [0, 1, -1],
    )
    axial = axial.tolil()
    axial[0, 1] = 2.0  # symmetric about the middle of the bushing
    weight = stretch(gamma) * film(gamma) ** 3 / dz**2
    matrix = kron(identity(axial_cells), around) + kron(axial.tocsr(), diags(weight))
    return inverse_sommerfeld_angle(gamma, mapped), stretch(gamma), matrix.tocsc()


def reynolds_solutions(
    eps: float,
    half_length: float,
    grid: tuple[int, int] | None = None,
    crowding: float | None = None,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Full-film solutions ``Pi_w`` (``beta = 0``) and ``Pi_s`` (``beta = pi/2``) on the grid.

    Parameters
    ----------
    eps : float
        Eccentricity ratio [-].
    half_length : float
        ``L / (2R)`` [-].
    grid : tuple of int
        Angle nodes and axial cells [-] (:func:`film_system`).
    crowding : float
        The grid's Sommerfeld-angle eccentricity [-] (:func:`film_system`).

    Returns
    -------
    tuple of ndarray
        ``theta`` of the angle nodes [rad], and ``Pi_w``, ``Pi_s`` of shape
        ``(AXIAL_CELLS + 1, ANGLE_NODES)`` from the middle (row 0) to the end [-].
    """
    angle_nodes, axial_cells = grid or (ANGLE_NODES, AXIAL_CELLS)
    theta, stretch, matrix = film_system(eps, half_length, grid, crowding)
    solver = splu(matrix)
    fields = []
    for source in (-np.sin(theta), np.cos(theta)):
        solution = solver.solve(np.tile(stretch * source, axial_cells))
        field = np.zeros((axial_cells + 1, angle_nodes))
        field[:-1] = solution.reshape(axial_cells, angle_nodes)
        fields.append(field)
    return theta, fields[0], fields[1]


def tabulated_forces(
    eps: float,
    half_length: float,
    directions: FloatArray,
    grid: tuple[int, int] | None = None,
    crowding: float | None = None,
) -> FloatArray:
    """``G_r, G_t`` of the positive film for every direction ``beta``, shape ``(2, n)`` [-].

    ``grid``: angle nodes and axial cells, ``crowding``: the Sommerfeld-angle
    eccentricity of the grid (:func:`film_system`; the usual grid if None) [-].
    """
    angle_nodes, axial_cells = grid or (ANGLE_NODES, AXIAL_CELLS)
    theta, wedge, squeeze = reynolds_solutions(eps, half_length, grid, crowding)
    step = 2.0 * np.pi / angle_nodes
    mapped = eps if crowding is None else crowding
    stretch = np.sqrt(1.0 - mapped**2) / (1.0 - mapped * np.cos(step * np.arange(angle_nodes)))
    pressure = (
        np.cos(directions)[:, None, None] * wedge + np.sin(directions)[:, None, None] * squeeze
    )
    positive = np.maximum(pressure, 0.0) * stretch * step
    axial = np.linspace(0.0, half_length, axial_cells + 1)
    over_angle = np.stack([positive @ np.cos(theta), positive @ np.sin(theta)])
    return 2.0 * simpson(over_angle, x=axial, axis=-1)


class BandedFilm:
    """The film's stiffness ``K = -A`` as a symmetric band, for solves on part of the film.

    In angle-major order (node ``(i, k)`` at ``i * AXIAL_CELLS + k``) the five-point
    stencil is a band of half-width ``AXIAL_CELLS``, but for the ring's wrap-around;
    halving the middle row's equations (which the symmetry about the middle doubled)
    makes it symmetric. With a whole column of angle cavitated, the ring opens there:
    the free nodes, the column moved to the end, solve ``K Pi = f`` with one banded
    Cholesky factorisation (:func:`scipy.linalg.solveh_banded`) in a fraction of a
    general sparse LU's time.

    Parameters
    ----------
    operator : csc_matrix
        ``A`` of :func:`film_system` [-].
    grid : tuple of int
        Its angle nodes and axial cells [-]; ``ANGLE_NODES`` and ``AXIAL_CELLS`` if None.
    """

    def __init__(self, operator: csc_matrix, grid: tuple[int, int] | None = None) -> None:
        self.stiffness = (-operator).tocsr()
        self.angles, self.cells = grid or (ANGLE_NODES, AXIAL_CELLS)
        angles, cells = self.angles, self.cells
        half = np.ones(cells)
        half[0] = 0.5
        self.half = half

        def by_node(values: FloatArray) -> FloatArray:  # [k, i] rows -> [i, k]
            return values.reshape(cells, angles).T

        self.main = by_node(self.stiffness.diagonal()) * half
        self.axial = by_node(np.append(self.stiffness.diagonal(-angles), np.zeros(angles)))
        ring = by_node(np.append(self.stiffness.diagonal(1), 0.0))
        ring[-1] = np.asarray(
            self.stiffness[np.arange(cells) * angles + angles - 1, np.arange(cells) * angles]
        ).ravel()
        self.ring = ring * half

    def solve(self, cavitated: NDArray[np.bool_], source: FloatArray) -> FloatArray:
        """``Pi`` with ``Pi = 0`` on the cavitated nodes and ``K Pi = f`` on the others [-].

        Parameters
        ----------
        cavitated : ndarray of bool
            The nodes held at zero (film order: rows along the pin).
        source : ndarray
            ``f`` [-].
        """
        angles, cells = self.angles, self.cells
        free = ~cavitated.reshape(cells, angles).T
        closed = np.flatnonzero(~free.any(axis=1))
        if closed.size == 0:  # no column cavitated: the ring stays closed
            pressure = np.zeros(source.size)
            kept = np.flatnonzero(~cavitated)
            pressure[kept] = splu(self.stiffness[kept][:, kept].tocsc()).solve(source[kept])
            return pressure
        order = (np.arange(angles) + closed[0] + 1) % angles  # the closed column last
        on = free[order]
        band = np.zeros((cells + 1, angles * cells))
        band[cells] = np.where(on, self.main[order], 1.0).ravel()
        along = self.axial[order] * on * np.roll(on, -1, axis=1)
        band[cells - 1, 1:] = along.ravel()[:-1]
        band[0, cells:] = (self.ring[order] * on * np.roll(on, -1, axis=0))[:-1].ravel()
        load = (source.reshape(cells, angles).T * self.half)[order] * on
        solution = solveh_banded(band, load.ravel()).reshape(angles, cells)
        pressure = np.empty((angles, cells))
        pressure[order] = solution * on
        return pressure.T.ravel()


def complementary_pressure(
    operator: csc_matrix | BandedFilm,
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
    operator : csc_matrix or BandedFilm
        ``A`` of :func:`film_system`, or its :class:`BandedFilm` [-].
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
    film = operator if isinstance(operator, BandedFilm) else BandedFilm(operator)
    stiffness = film.stiffness
    diagonal = stiffness.diagonal()
    pressure = np.zeros(source.size) if guess is None else guess.copy()
    held = np.zeros(source.size, bool) if fixed is None else fixed
    cavitated = (stiffness @ pressure - source > diagonal * pressure) | held
    for _ in range(MOST_STEPS):
        pressure = film.solve(cavitated, source)
        residual = stiffness @ pressure - source
        residual[~cavitated] = 0.0
        again = (residual > diagonal * pressure) | held
        if np.array_equal(again, cavitated):
            return pressure
        cavitated = again
    raise JointwearError(
        f"lubrication.cavitation: the Reynolds condition found no film boundary in "
        f"{MOST_STEPS} active-set steps"
    )


def turned(pressure: FloatArray, theta: FloatArray, turn: float) -> FloatArray:
    """A film's pressure turned by ``turn`` in ``theta``: the next direction's first guess [-].

    The source ``sin(theta - beta)`` turns with ``beta``, and the film nearly with it.

    Parameters
    ----------
    pressure : ndarray
        ``Pi`` of the grid (rows: axial index major) [-].
    theta : ndarray
        Angles of the grid's nodes, increasing in [0, 2 pi) [rad].
    turn : float
        The change of ``beta`` [rad].
    """
    rows = pressure.reshape(-1, theta.size)
    return np.stack(
        [np.interp(theta - turn, theta, row, period=2.0 * np.pi) for row in rows]
    ).ravel()


def reynolds_forces(
    eps: float,
    half_length: float,
    directions: ArrayLike,
    film_start: bool = False,
    grid: tuple[int, int] | None = None,
    crowding: float | None = None,
) -> FloatArray:
    """``G_r, G_t`` of the film with Reynolds' condition, shape ``(2, n)`` [-].

    The same force factor as
    :func:`tabulated_forces`, of the complementarity
    solution (module text) instead of the positive part of the full film; the
    directions are solved in turn, each started from the one before turned by the
    change of direction (:func:`turned`).

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
    grid : tuple of int
        Angle nodes and axial cells [-] (:func:`film_system`; the usual grid if None).
    crowding : float
        The grid's Sommerfeld-angle eccentricity [-] (:func:`film_system`).
    """
    theta, stretch, operator = film_system(eps, half_length, grid, crowding)
    columns, rows = grid or (ANGLE_NODES, AXIAL_CELLS)
    fixed = None
    if film_start:
        fixed = np.zeros(rows * columns, bool)
        fixed[::columns] = True  # theta = 0 of every row
    step = 2.0 * np.pi / columns
    axial = np.linspace(0.0, half_length, rows + 1)
    film = BandedFilm(operator, grid)
    pressure, previous = None, 0.0
    forces = []
    for beta in np.atleast_1d(np.asarray(directions, float)):
        source = np.tile(stretch * np.sin(theta - beta), rows)
        guess = None if pressure is None else turned(pressure, theta, beta - previous)
        pressure, previous = complementary_pressure(film, source, guess, fixed), beta
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
        shape = tabulated_forces(eps, ratio, np.array([0.0]))[:, 0]
    else:
        raise JointwearError(
            f"cavitation: expected 'half-Sommerfeld' or 'Reynolds', got {cavitation!r}"
        )
    return SteadyJournal(
        ratio / (3.0 * np.pi * eps * float(np.hypot(*shape))),
        float(np.arctan2(shape[1], -shape[0])),
    )
