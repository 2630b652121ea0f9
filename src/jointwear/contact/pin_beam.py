"""The pin as a beam on the bushing's elastic foundation.

Along the pin (axis ``z``) the bushing's slices hold the pin like a Winkler foundation of
stiffness ``k(z)`` per unit length, the slices' linearised contact stiffness
``k_i = (dF_i / ds_i) / h_i`` (:attr:`jointwear.contact.axial.AxialSolution.foundation_stiffness`).
The pin's deflection ``w(z)`` under a line load ``q(z)`` obeys Euler–Bernoulli's

.. math:: EI \\, w'''' + k \\, w = q,

or Timoshenko's, for short pins whose shear deformation counts,

.. math:: EI \\, \\theta'' + \\kappa G A (w' - \\theta) = 0, \\qquad
          \\kappa G A (w' - \\theta)' + q - k w = 0,

with the section rotation ``theta`` and Cowper's shear coefficient
``kappa = 6 (1 + nu) / (7 + 6 nu)`` of a solid circle [3]_. Hetényi's characteristic
``lambda = (k / 4 EI)^{1/4}`` [1]_ says how far a load spreads: a pin of length ``L``
with ``lambda L < pi / 4`` is rigid on its foundation, one with ``lambda L > pi`` is
long (its ends do not feel each other).

Finite elements: two-node beam elements with cubic deflection (Hermite for
Euler–Bernoulli, the shear-dependent "interdependent interpolation" element for
Timoshenko [2]_, whose stiffness

.. math::
    K_e = \\frac{EI}{(1 + \\phi) \\ell^3}
    \\begin{bmatrix} 12 & 6\\ell & -12 & 6\\ell \\\\
    6\\ell & (4+\\phi)\\ell^2 & -6\\ell & (2-\\phi)\\ell^2 \\\\
    -12 & -6\\ell & 12 & -6\\ell \\\\
    6\\ell & (2-\\phi)\\ell^2 & -6\\ell & (4+\\phi)\\ell^2 \\end{bmatrix},
    \\qquad \\phi = \\frac{12 EI}{\\kappa G A \\ell^2},

is exact for a uniform beam loaded at its nodes, ``phi = 0`` being Euler–Bernoulli's).
Nodes sit at the slice centres, the supports and the loads; the foundation is lumped
at the slice centres, a spring ``k_i h_i`` each (the midpoint rule: a continuous
foundation is approached as ``O(h^2)``), which is also how the slices' forces act on the
pin. Assembled as a sparse matrix and solved by ``scipy.sparse.linalg.splu``.

Supports: a :class:`Clevis` holds the pin in two forks (simply supported; the fork
bores' fit clearance lets the pin tilt by ``2 c_f / span`` before it bears), a
:class:`Cantilever` clamps it at one end.

References
----------
.. [1] Hetényi, M.: Beams on Elastic Foundation. University of Michigan Press (1946),
   ch. II-III.
.. [2] Przemieniecki, J. S.: Theory of Matrix Structural Analysis. McGraw-Hill (1968), §5.6.
.. [3] Cowper, G. R.: The shear coefficient in Timoshenko's beam theory. J. Appl. Mech.
   33, 335-340 (1966).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.errors import ConfigError, GeometryError

if TYPE_CHECKING:
    import scipy.sparse as sparse

__all__ = [
    "Cantilever",
    "Clevis",
    "PinBeam",
    "beam_on_foundation",
    "bending",
    "characteristic",
    "compliance",
    "element_stiffness",
    "linearised_joint",
    "shear_coefficient",
]

FloatArray = NDArray[np.float64]

#: nodes closer than this fraction of the mesh's extent are one node [-]
MERGE_TOLERANCE = 1e-12


def shear_coefficient(poisson_ratio: float) -> float:
    """Cowper's shear coefficient of a solid circular section [-].

    .. math:: \\kappa = \\frac{6 (1 + \\nu)}{7 + 6 \\nu}

    Parameters
    ----------
    poisson_ratio : float
        Poisson's ratio ``nu`` of the pin [-].
    """
    return 6.0 * (1.0 + poisson_ratio) / (7.0 + 6.0 * poisson_ratio)


def characteristic(foundation: float, bending_stiffness: float) -> float:
    """Hetényi's characteristic ``lambda = (k / 4 EI)^{1/4}`` [1/m].

    Parameters
    ----------
    foundation : float
        Foundation stiffness per unit length ``k`` [N/m^2].
    bending_stiffness : float
        ``EI`` [N m^2].
    """
    return (foundation / (4.0 * bending_stiffness)) ** 0.25


@dataclass(frozen=True)
class PinBeam:
    """Bending and shear stiffness of the pin.

    Parameters
    ----------
    bending_stiffness : float
        ``EI`` [N m^2].
    shear_stiffness : float
        ``kappa G A`` [N]; ``inf`` (default) is Euler–Bernoulli.
    """

    bending_stiffness: float
    shear_stiffness: float = math.inf

    def __post_init__(self) -> None:
        if not (math.isfinite(self.bending_stiffness) and self.bending_stiffness > 0):
            raise ConfigError(
                f"pin.model: the bending stiffness must be positive and finite, got "
                f"{self.bending_stiffness!r}"
            )
        if not self.shear_stiffness > 0:  # NaN fails too
            raise ConfigError(
                f"pin.model: the shear stiffness must be positive, got {self.shear_stiffness!r}"
            )

    @classmethod
    def solid(
        cls, radius: float, youngs_modulus: float, poisson_ratio: float, model: str = "timoshenko"
    ) -> PinBeam:
        """A solid circular pin: ``I = pi R^4 / 4``, ``A = pi R^2``, ``G = E / 2(1 + nu)``.

        Parameters
        ----------
        radius : float
            Pin radius ``R_p`` [m].
        youngs_modulus : float
            ``E`` of the pin [Pa].
        poisson_ratio : float
            ``nu`` of the pin [-].
        model : {"timoshenko", "euler-bernoulli"}
            With or without shear deformation.
        """
        if model not in ("timoshenko", "euler-bernoulli"):
            raise ConfigError(
                f"pin.model: unknown beam model {model!r}; choose 'timoshenko' or 'euler-bernoulli'"
            )
        inertia, area = math.pi * radius**4 / 4.0, math.pi * radius**2
        shear = math.inf
        if model == "timoshenko":
            modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio))
            shear = shear_coefficient(poisson_ratio) * modulus * area
        return cls(youngs_modulus * inertia, shear)

    @property
    def model(self) -> str:
        """``"euler-bernoulli"`` (infinite shear stiffness) or ``"timoshenko"``."""
        return "euler-bernoulli" if math.isinf(self.shear_stiffness) else "timoshenko"


@dataclass(frozen=True)
class Clevis:
    """Two forks hold the pin, simply supported at their mid-planes.

    Parameters
    ----------
    forks : tuple of float
        Axial positions of the two forks ``z_A < z_B`` [m] (0 at the bushing's mid-plane).
    fit_clearance : float
        Radial clearance of the pin in the fork bores ``c_f`` [m]: the pin may tilt by
        ``2 c_f / (z_B - z_A)`` before it bears on them (:attr:`tilt_play`).
    """

    forks: tuple[float, float]
    fit_clearance: float = 0.0

    def __post_init__(self) -> None:
        low, high = (float(f) for f in self.forks)
        if not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise ConfigError(
                f"pin.support: fork positions must be finite and increasing, got {self.forks!r}"
            )
        if not (math.isfinite(self.fit_clearance) and self.fit_clearance >= 0):
            raise ConfigError(
                f"pin.support: fit clearance must be >= 0, got {self.fit_clearance!r}"
            )
        object.__setattr__(self, "forks", (low, high))

    @property
    def span(self) -> float:
        """Distance between the forks [m]."""
        return self.forks[1] - self.forks[0]

    @property
    def tilt_play(self) -> float:
        """Tilt the fit clearance allows, ``2 c_f / span`` [rad]."""
        return 2.0 * self.fit_clearance / self.span

    @property
    def held(self) -> list[tuple[float, int]]:
        """Held degrees of freedom: (position [m], 0 deflection / 1 rotation)."""
        return [(self.forks[0], 0), (self.forks[1], 0)]

    def reactions(self, load: float, load_offset: float):
        """Forces of the forks on the pin, along the load, for a load ``W`` [N] whose line
        crosses the axis at ``a`` [m]: ``R_A = W (z_B - a) / span``, ``R_B = W (a - z_A) /
        span``; as ``(forces, moments)``, lists of (position [m], value [N] / [N m])."""
        low, high = self.forks
        return [(low, load * (high - load_offset) / self.span),
                (high, load * (load_offset - low) / self.span)], []  # fmt: skip


@dataclass(frozen=True)
class Cantilever:
    """The pin clamped (built in) at one axial position, the bushing on its overhang.

    Parameters
    ----------
    clamp : float
        Axial position of the clamped section [m] (0 at the bushing's mid-plane).
    """

    clamp: float

    def __post_init__(self) -> None:
        if not math.isfinite(self.clamp):
            raise ConfigError(f"pin.support: the clamp position must be finite, got {self.clamp!r}")

    @property
    def tilt_play(self) -> float:
        """A clamp allows no tilt [rad]."""
        return 0.0

    @property
    def held(self) -> list[tuple[float, int]]:
        """Held degrees of freedom: (position [m], 0 deflection / 1 rotation)."""
        return [(self.clamp, 0), (self.clamp, 1)]

    def reactions(self, load: float, load_offset: float):
        """Force ``W`` [N] and moment ``W (a - z_c)`` [N m] of the clamp on the pin for a
        load ``W`` whose line crosses the axis at ``a`` [m], as ``(forces, moments)``."""
        return [(self.clamp, load)], [(self.clamp, load * (load_offset - self.clamp))]


Support = Clevis | Cantilever


def element_stiffness(beam: PinBeam, lengths: ArrayLike) -> FloatArray:
    """Stiffness matrices of beam elements, DOFs ``(w_1, theta_1, w_2, theta_2)``.

    The Timoshenko element with cubic deflection and ``phi = 12 EI / (kappa G A l^2)``
    (module notes), exact for a uniform beam loaded at its nodes; ``phi = 0``:
    Euler–Bernoulli's Hermite element.

    Parameters
    ----------
    beam : PinBeam
        Stiffnesses ``EI`` [N m^2] and ``kappa G A`` [N].
    lengths : array_like, shape (E,)
        Element lengths ``l`` [m].

    Returns
    -------
    ndarray, shape (E, 4, 4)
        [N/m], [N], [N m] by DOF pair.
    """
    ell = np.asarray(lengths, dtype=float)
    phi = 12.0 * beam.bending_stiffness / (beam.shear_stiffness * ell**2)
    factor = beam.bending_stiffness / ((1.0 + phi) * ell**3)
    a, b = 12.0 * np.ones_like(ell), 6.0 * ell
    c, d = (4.0 + phi) * ell**2, (2.0 - phi) * ell**2
    matrix = np.array(
        [[a, b, -a, b],
         [b, c, -b, d],
         [-a, -b, a, -b],
         [b, d, -b, c]]
    )  # fmt: skip
    return np.moveaxis(matrix, -1, 0) * factor[:, None, None]


class _Mesh:
    """Nodes at the given positions (merged where they coincide) and their elements."""

    def __init__(self, *positions: ArrayLike) -> None:
        every = np.concatenate([np.atleast_1d(np.asarray(p, dtype=float)) for p in positions])
        if every.size == 0 or not np.all(np.isfinite(every)):
            raise GeometryError("pin.model: beam positions must be finite")
        ordered = np.unique(every)
        extent = max(float(ordered[-1] - ordered[0]), float(np.abs(ordered).max()), 1e-300)
        keep = np.concatenate([[True], np.diff(ordered) > MERGE_TOLERANCE * extent])
        self.nodes = ordered[keep]
        self.tolerance = MERGE_TOLERANCE * extent
        if self.nodes.size < 2:
            raise GeometryError("pin.model: a beam needs two distinct positions")

    def index(self, positions: ArrayLike) -> NDArray[np.intp]:
        """The node at each position."""
        positions = np.atleast_1d(np.asarray(positions, dtype=float))
        index = np.clip(np.searchsorted(self.nodes, positions), 1, self.nodes.size - 1)
        nearer = np.abs(self.nodes[index - 1] - positions) <= np.abs(self.nodes[index] - positions)
        return np.where(nearer, index - 1, index)

    def stiffness(self, beam: PinBeam) -> sparse.csc_matrix:
        """The assembled beam stiffness, DOFs ``(w_0, theta_0, w_1, ...)``."""
        local = element_stiffness(beam, np.diff(self.nodes))
        first = 2 * np.arange(self.nodes.size - 1)
        dofs = first[:, None] + np.arange(4)[None, :]
        rows = np.broadcast_to(dofs[:, :, None], local.shape).ravel()
        cols = np.broadcast_to(dofs[:, None, :], local.shape).ravel()
        size = 2 * self.nodes.size
        import scipy.sparse as sparse  # (loaded only for a bending pin)

        return sparse.coo_matrix((local.ravel(), (rows, cols)), shape=(size, size)).tocsc()


def _solve(
    mesh: _Mesh,
    matrix: sparse.csc_matrix,
    right: FloatArray,
    held: Sequence[tuple[float, int]],
) -> FloatArray:
    """Displacements [m, rad] for the loads ``right`` (DOFs, columns) with the ``held``
    DOFs fixed at zero."""
    fixed = {2 * int(mesh.index(z)[0]) + dof for z, dof in held}
    free = np.setdiff1d(np.arange(matrix.shape[0]), np.fromiter(fixed, int, len(fixed)))
    try:
        from scipy.sparse.linalg import splu

        factor = splu(matrix[free][:, free].tocsc())
        reduced = factor.solve(np.ascontiguousarray(right[free]))
    except RuntimeError as error:  # splu: "Factor is exactly singular"
        raise GeometryError(
            "pin.support: the pin is not held (no supports and no foundation under it)"
        ) from error
    if not np.all(np.isfinite(reduced)):
        raise GeometryError("pin.support: the pin is not held (a singular beam)")
    result = np.zeros(right.shape)
    result[free] = reduced
    return result


def beam_on_foundation(
    beam: PinBeam,
    positions: ArrayLike,
    foundation: ArrayLike,
    widths: ArrayLike,
    forces: Sequence[tuple[float, float]] = (),
    moments: Sequence[tuple[float, float]] = (),
    supports: Support | None = None,
    at: ArrayLike | None = None,
) -> FloatArray:
    """Deflection of a beam on a Winkler foundation under point loads.

    .. math:: EI w'''' + k w = \\sum_m P_m \\delta(z - z_m)
              \\quad (\\text{or Timoshenko's pair, module notes})

    The foundation under slice ``i`` (centre ``z_i``, width ``h_i``) is a spring
    ``k_i h_i`` at ``z_i``; the beam's ends are the outermost nodes, free unless held.

    Parameters
    ----------
    beam : PinBeam
        The beam.
    positions : array_like, shape (N,)
        Slice centres ``z_i`` [m].
    foundation : array_like, shape (N,)
        Foundation stiffness per unit length ``k_i`` [N/m^2].
    widths : array_like, shape (N,)
        Slice widths ``h_i`` [m].
    forces : sequence of (float, float)
        Point forces ``(z_m [m], P_m [N])``, positive along ``w``.
    moments : sequence of (float, float)
        Point moments ``(z_m [m], M_m [N m])``, positive along the rotation ``w'``.
    supports : Clevis or Cantilever, optional
        Held deflections and rotations; ``None``: free ends.
    at : array_like, optional
        Where the deflection is wanted [m] (nodes are added there); default ``positions``.

    Returns
    -------
    ndarray
        Deflection ``w`` at ``at`` [m].
    """
    positions = np.atleast_1d(np.asarray(positions, dtype=float))
    springs = np.asarray(foundation, dtype=float) * np.asarray(widths, dtype=float)
    wanted = positions if at is None else np.atleast_1d(np.asarray(at, dtype=float))
    held = [] if supports is None else supports.held
    if not held and np.unique(positions[springs > 0]).size < 2:
        # a free beam is held by its foundation alone: springs at two places at least
        raise GeometryError(
            "pin.support: the pin is not held (no supports, and a foundation at fewer than "
            "two places)"
        )
    mesh = _Mesh(positions, wanted, [z for z, _ in forces], [z for z, _ in moments],
                 [z for z, _ in held])  # fmt: skip
    size = 2 * mesh.nodes.size
    matrix = mesh.stiffness(beam)
    spring_dofs = 2 * mesh.index(positions)
    import scipy.sparse as sparse

    matrix = matrix + sparse.csc_matrix((springs, (spring_dofs, spring_dofs)), shape=(size, size))
    right = np.zeros(size)
    for offset, loads in ((0, forces), (1, moments)):
        for z, value in loads:
            right[2 * int(mesh.index(z)[0]) + offset] += value
    displacement = _solve(mesh, matrix.tocsc(), right, held)
    return displacement[2 * mesh.index(wanted)]


def compliance(beam: PinBeam, supports: Support, positions: ArrayLike) -> FloatArray:
    """The pin's flexibility at the slice centres relative to its supports.

    ``C_ij`` is the deflection at ``z_i`` of the pin, held by ``supports``, under a unit
    force at ``z_j`` (exact for point loads: the elements are exact between nodes). The
    bending of a pin under the slices' forces ``F`` (which push the pin against the
    load) is ``w = -C F`` (:func:`bending`).

    Parameters
    ----------
    beam : PinBeam
        The pin.
    supports : Clevis or Cantilever
        What holds it.
    positions : array_like, shape (N,)
        Slice centres [m].

    Returns
    -------
    ndarray, shape (N, N)
        Symmetric, [m/N].
    """
    positions = np.atleast_1d(np.asarray(positions, dtype=float))
    held = supports.held
    mesh = _Mesh(positions, [z for z, _ in held])
    dofs = 2 * mesh.index(positions)
    right = np.zeros((2 * mesh.nodes.size, positions.size))
    right[dofs, np.arange(positions.size)] = 1.0
    matrix = _solve(mesh, mesh.stiffness(beam), right, held)[dofs]
    return 0.5 * (matrix + matrix.T)


def bending(
    beam: PinBeam, supports: Support, positions: ArrayLike, forces: ArrayLike
) -> FloatArray:
    """Deflection at the slice centres that adds to each slice's offset, ``w = -C F`` [m].

    Parameters
    ----------
    beam : PinBeam
        The pin.
    supports : Clevis or Cantilever
        What holds it; ``w`` is relative to the line through the supports.
    positions : array_like, shape (N,)
        Slice centres [m].
    forces : array_like, shape (N,)
        The slices' resultants along the load ``F_i`` [N] (they push the pin back).
    """
    return -compliance(beam, supports, positions) @ np.asarray(forces, dtype=float)


def linearised_joint(
    beam: PinBeam,
    supports: Support,
    positions: ArrayLike,
    widths: ArrayLike,
    foundation: ArrayLike,
    load: float,
    load_offset: float = 0.0,
) -> FloatArray:
    """Pin position relative to the bushing on a linear foundation, at the slice centres.

    The pin, free to move and tilt, lies on the bushing's foundation ``k_i`` and is
    pushed into it by its supports' reactions to the load ``W`` at ``z = a``
    (:meth:`Clevis.reactions`, :meth:`Cantilever.reactions`): a free beam on an elastic
    foundation whose deflection ``u_i`` is the slices' approach, ``F_i = k_i h_i u_i``,
    with ``sum F_i = W`` and ``sum F_i z_i = W a``. The linearised model of the joint
    (contact without clearance, the foundation fixed); the slices' own laws are
    balanced by :func:`jointwear.contact.axial.solve_axial` with :func:`compliance`.

    Parameters
    ----------
    beam : PinBeam
        The pin.
    supports : Clevis or Cantilever
        Where the load enters the pin.
    positions, widths : array_like, shape (N,)
        Slice centres and widths [m].
    foundation : array_like, shape (N,)
        Foundation stiffness per unit length ``k_i`` [N/m^2].
    load : float
        ``W`` [N].
    load_offset : float
        ``a`` [m].

    Returns
    -------
    ndarray, shape (N,)
        Approach ``u_i`` [m] (rigid motion and bending).
    """
    forces, moments = supports.reactions(load, load_offset)
    return beam_on_foundation(beam, positions, foundation, widths, forces, moments)
