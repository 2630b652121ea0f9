"""Finite-element reference: the real bushing geometry with scikit-fem.

The bushing wall (inner contour ``r_in(theta)`` from a :class:`BushingContour`,
circular or worn; outer radius ``R_b + L``) is bonded to a rigid housing
(zero displacement on the outer boundary) and pressed by the pin. Plane
strain, linear elasticity, small strain; frictionless unilateral contact on the
inner boundary.

Discretisation
--------------
A structured mesh in ``(rho, theta)``: ``circumferential`` x ``radial``
9-node quadratic quadrilaterals (``ElementQuad2`` on a ``MeshQuad2``, so the
element edges follow the contour: every boundary node, corner and mid-side,
lies on ``r_in(theta)``), radial sizes graded geometrically towards the
contact surface. Boundary nodes are equally spaced in angle,
``2 * circumferential`` of them.

Contact
-------
The pin is a rigid circle of radius ``R_p`` whose centre sits at ``e``. Along
the ray of inner node ``j`` (angle ``theta_j``, radius ``r_j``) the pin
overlaps the undeformed bushing by
``g_j = e.u_j + sqrt(R_p^2 - (u_j x e)^2) - r_j`` (the same exact ray geometry as
the spring models). The node's radial displacement must close it,
``u_r,j >= g_j``, with a radial (ray-wise frictionless) nodal force
``lambda_j >= 0`` that vanishes where the gap stays open. The elastic response
of the boundary is condensed once per mesh into the radial flexibility matrix
``G`` (``u_r = G lambda``; one sparse LU factorisation, unit radial loads;
for a circular bushing ``G`` is block-circulant and two solves suffice), and the
contact problem ``G lambda - g >= 0, lambda >= 0, lambda (G lambda - g) = 0``
is solved by a block active-set method (Lawson-Hanson NNLS as fall-back).
The pin displacement ``s`` along the load is found by ``scipy.optimize.brentq``
so that the resultant ``b sum_j lambda_j u_j . w`` equals the load (the paper's
balance), or with ``balance="equilibrium"`` the 2-D position so that the
resultant *vector* equals the load (``scipy.optimize.root``).

Pressure: ``p_j = lambda_j / w_j`` with ``w_j = int N_j ds`` the (positive,
Simpson-like) boundary weights of the quadratic trace.

The pin: rigid by default (steel on PTFE: ``E'_b / E'_p = 0.0025``, so the
pin's own compliance changes the approach by about 0.3 %). ``pin="effective"``
lowers the bushing modulus to ``E*(1 - nu_b^2)`` so that the bushing's
half-space compliance equals the pair's ``1/E*`` (exact in the Hertz limit,
approximate otherwise).

"Approach", comparable with the spring models' penetration of the compression
centre: pin displacement along the load minus the clearance at the load line.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import optimize
from scipy.sparse.linalg import splu

from jointwear.contact.laws import ContactParameters
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ConfigError, ContactError, ConvergenceError, GeometryError
from jointwear.geometry.angles import angle_in_turn, wrap_angle
from jointwear.geometry.contour import BushingContour, Pin, pin_penetration
from jointwear.references.solution import (
    ReferenceState,
    assemble_solution,
    check_loads,
    edge_from_pressure,
)

__all__ = [
    "BushingMesh",
    "FemModel",
    "FemState",
    "build_mesh",
    "model",
    "solve_contact_fe",
]

FloatArray = NDArray[np.float64]


def scikit_fem():
    """The ``skfem`` module, or a :class:`ConfigError` naming the ``fem`` extra."""
    try:
        import skfem
    except ImportError as exc:  # pragma: no cover - optional dependency
        raise ConfigError(
            "contact.model: 'fem' needs scikit-fem (pip install 'jointwear[fem]')"
        ) from exc
    return skfem


@dataclass(eq=False)
class BushingMesh:
    """A meshed bushing wall with its condensed boundary flexibility.

    Attributes
    ----------
    theta : ndarray, shape (n,)
        Angles of the inner boundary nodes, increasing from 0 [rad].
    radius : ndarray, shape (n,)
        Radii of the inner boundary nodes [m].
    weight : ndarray, shape (n,)
        Boundary weights ``int N_j ds`` [m].
    circular : bool
        Unworn (block-circulant flexibility).
    circumferential, radial : int
        Elements around / through the wall.
    dofs : int
        Degrees of freedom of the FE model.
    """

    theta: FloatArray
    radius: FloatArray
    weight: FloatArray
    circular: bool
    circumferential: int
    radial: int
    dofs: int
    _factor: Any = field(repr=False, default=None)
    _free: Any = field(repr=False, default=None)
    _node_dofs: Any = field(repr=False, default=None)
    _columns: dict = field(repr=False, default_factory=dict)
    _basis: Any = field(repr=False, default=None)
    _stiffness: Any = field(repr=False, default=None)

    @property
    def nodes(self) -> int:
        """Number of inner boundary nodes."""
        return self.theta.size

    @property
    def normal(self) -> FloatArray:
        """Radial unit vectors of the inner nodes, shape (n, 2)."""
        return np.stack([np.cos(self.theta), np.sin(self.theta)], axis=1)

    def flexibility(self, rows: NDArray[np.intp]) -> FloatArray:
        """Radial flexibility ``G[rows][:, rows]`` [m per N/m of nodal force].

        Parameters
        ----------
        rows : ndarray of int
            Inner-node indices (a window around the load).
        """
        rows = np.asarray(rows, dtype=np.intp)
        n = self.nodes
        if self.circular:
            # block-circulant: columns of one corner and one mid-side node suffice
            base = {0: self._column(0), 1: self._column(1)}
            out = np.empty((rows.size, rows.size))
            for j, col in enumerate(rows):
                ref = base[int(col % 2)]
                shift = col - (col % 2)
                out[:, j] = ref[(rows - shift) % n]
            return 0.5 * (out + out.T)
        missing = [int(j) for j in rows if int(j) not in self._columns]
        for start in range(0, len(missing), 64):
            chunk = missing[start : start + 64]
            values = self._solve_unit(chunk)
            for k, j in enumerate(chunk):
                self._columns[j] = values[:, k]
        out = np.stack([self._columns[int(j)][rows] for j in rows], axis=1)
        return 0.5 * (out + out.T)

    def _column(self, j: int) -> FloatArray:
        if j not in self._columns:
            self._columns[j] = self._solve_unit([j])[:, 0]
        return self._columns[j]

    def _solve_unit(self, nodes: list[int]) -> FloatArray:
        """Radial displacements of all inner nodes for unit radial forces at ``nodes``."""
        normal = self.normal
        rhs = np.zeros((self._free.size, len(nodes)))
        for k, j in enumerate(nodes):
            dx, dy = np.searchsorted(self._free, self._node_dofs[j])
            rhs[dx, k] = normal[j, 0]
            rhs[dy, k] = normal[j, 1]
        solution = self._factor.solve(rhs)
        full = np.zeros((self.dofs, len(nodes)))
        full[self._free] = solution
        ux = full[self._node_dofs[:, 0]]
        uy = full[self._node_dofs[:, 1]]
        return ux * normal[:, 0:1] + uy * normal[:, 1:2]

    def radial_displacement(self, forces: FloatArray) -> FloatArray:
        """Radial displacement of the inner nodes for radial nodal forces [m].

        Parameters
        ----------
        forces : ndarray, shape (n,)
            Radial nodal forces per unit axial length, outward on the bushing [N/m].
        """
        u = self.displacement(forces)
        normal = self.normal
        return u[self._node_dofs[:, 0]] * normal[:, 0] + u[self._node_dofs[:, 1]] * normal[:, 1]

    def displacement(self, forces: FloatArray) -> FloatArray:
        """Full FE displacement vector for radial nodal forces on the inner nodes.

        Parameters
        ----------
        forces : ndarray, shape (n,)
            Radial nodal forces per unit axial length [N/m].
        """
        normal = self.normal
        f = np.zeros(self.dofs)
        f[self._node_dofs[:, 0]] = forces * normal[:, 0]
        f[self._node_dofs[:, 1]] = forces * normal[:, 1]
        u = np.zeros(self.dofs)
        u[self._free] = self._factor.solve(f[self._free])
        return u


def build_mesh(
    contour: BushingContour,
    thickness: float,
    youngs_modulus: float,
    poisson_ratio: float,
    circumferential: int = 180,
    radial: int = 6,
    grading: float = 4.0,
) -> BushingMesh:
    """Mesh the bushing wall, assemble and factorise the plane-strain stiffness.

    Parameters
    ----------
    contour : BushingContour
        Inner contour (circular or worn); the outer radius is
        ``contour.original_radius + thickness``.
    thickness : float
        Unworn wall thickness ``L`` [m].
    youngs_modulus : float
        Bushing Young's modulus [Pa].
    poisson_ratio : float
        Bushing Poisson's ratio [-], < 0.5.
    circumferential : int
        Elements around the bushing (boundary nodes: twice as many) [-].
    radial : int
        Elements through the wall [-].
    grading : float
        Ratio of the outermost to the innermost radial element size [-].
    """
    skfem = scikit_fem()
    _check_mesh_inputs(circumferential, radial, youngs_modulus, poisson_ratio, thickness)
    wall = _WallGrid(
        contour,
        contour.original_radius + thickness,
        int(circumferential),
        _radial_levels(int(radial), grading),
    )
    if np.any(contour.radius_at(wall.theta) >= wall.outer):
        raise GeometryError("bushing contour: the wear has reached the housing (wall consumed)")
    mesh = _quadratic_mesh(skfem, wall)
    basis = skfem.Basis(mesh, skfem.ElementVector(skfem.ElementQuad2()))
    stiffness = _plane_strain_stiffness(skfem, basis, youngs_modulus, poisson_ratio)
    inner = _inner_boundary(skfem, mesh, basis, wall)
    free = np.setdiff1d(np.arange(basis.N), inner.fixed)
    factor = splu(stiffness[free][:, free].tocsc())
    circular = bool(np.ptp(contour.radius) <= 1e-12 * contour.radius.mean())
    return BushingMesh(
        theta=inner.theta,
        radius=inner.radius,
        weight=inner.weight,
        circular=circular,
        circumferential=wall.circumferential,
        radial=wall.radial,
        dofs=basis.N,
        _factor=factor,
        _free=free,
        _node_dofs=inner.node_dofs,
        _basis=basis,
        _stiffness=stiffness,
    )


def _check_mesh_inputs(
    circumferential: int,
    radial: int,
    youngs_modulus: float,
    poisson_ratio: float,
    thickness: float,
) -> None:
    """Refuse too coarse a mesh, materials without plane strain, a wall without thickness."""
    if circumferential < 8 or radial < 1:
        raise ConfigError("fem: need at least 8 circumferential and 1 radial element")
    if not (youngs_modulus > 0 and -1.0 < poisson_ratio < 0.5):
        raise ConfigError("materials.bushing: the FE reference needs E > 0 and nu < 0.5")
    if not thickness > 0:
        raise GeometryError("joint.bushing_thickness: must be > 0")


def _radial_levels(radial: int, grading: float) -> FloatArray:
    """Element boundaries through the wall, 0 (bore) to 1 (housing), graded geometrically [-].

    The sizes grow by ``grading ** (1 / (radial - 1))`` from one element to the next, so
    that the outermost is ``grading`` times the innermost (the smallest, at the contact).
    """
    if radial == 1 or grading == 1.0:
        return np.linspace(0.0, 1.0, radial + 1)
    q = grading ** (1.0 / (radial - 1))
    sizes = q ** np.arange(radial)
    return np.concatenate([[0.0], np.cumsum(sizes) / sizes.sum()])


@dataclass(frozen=True)
class _WallGrid:
    """The structured ``(rho, theta)`` grid of the wall between the contour and the housing.

    Attributes
    ----------
    contour : BushingContour
        The bore.
    outer : float
        Housing radius ``R_b + L`` [m].
    circumferential : int
        Elements around [-].
    levels : ndarray, shape (radial + 1,)
        Element boundaries through the wall, 0 at the bore, 1 at the housing [-].
    """

    contour: BushingContour
    outer: float
    circumferential: int
    levels: FloatArray

    @property
    def radial(self) -> int:
        """Elements through the wall [-]."""
        return self.levels.size - 1

    @property
    def theta(self) -> FloatArray:
        """Angles of the element corners around the wall [rad]."""
        return 2.0 * np.pi * np.arange(self.circumferential) / self.circumferential

    def place(self, theta: FloatArray, rho: FloatArray) -> FloatArray:
        """Points ``(x, y)`` at angles ``theta`` and wall fractions ``rho``, shape (2, n) [m]."""
        r_in = self.contour.radius_at(theta)
        r = r_in + rho * (self.outer - r_in)
        return np.stack([r * np.cos(theta), r * np.sin(theta)])


def _quadratic_mesh(skfem: Any, wall: _WallGrid) -> Any:
    """The 9-node quadrilateral mesh of the wall, every node (mid-side too) on the grid.

    A linear quadrilateral mesh numbers the elements and their dofs; each of the 9
    nodes of an element is then placed at its reference ``(xi, eta)`` mapped onto
    ``(rho, theta)``, so that the boundary nodes lie on the contour ``r_in(theta)``.
    """
    from skfem.assembly import Dofs

    n_t, n_r, rho = wall.circumferential, wall.radial, wall.levels
    theta_v = wall.theta
    ii, kk = np.meshgrid(np.arange(n_t), np.arange(n_r + 1), indexing="ij")
    points = wall.place(theta_v[ii].ravel(), rho[kk].ravel())
    i0 = np.arange(n_t)[:, None]
    k0 = np.arange(n_r)[None, :]
    i1 = (i0 + 1) % n_t
    t = np.stack(
        [
            (i0 * (n_r + 1) + k0).ravel(),
            (i0 * (n_r + 1) + k0 + 1).ravel(),
            (i1 * (n_r + 1) + k0 + 1).ravel(),
            (i1 * (n_r + 1) + k0).ravel(),
        ]
    )
    dofs = Dofs(skfem.MeshQuad(points, t), skfem.ElementQuad2())
    element_dofs = dofs.element_dofs  # (9, n_elements)
    ref = skfem.ElementQuad2.doflocs  # (9, 2): xi (radial), eta (circumferential)
    elem_i = np.repeat(np.arange(n_t), n_r)
    elem_k = np.tile(np.arange(n_r), n_t)
    rho_e = rho[elem_k][None, :] + ref[:, 0:1] * (rho[elem_k + 1] - rho[elem_k])[None, :]
    theta_e = angle_in_turn(theta_v[elem_i][None, :] + ref[:, 1:2] * (2.0 * np.pi / n_t))
    doflocs = np.zeros((2, dofs.N))
    xy = wall.place(theta_e.ravel(), rho_e.ravel()).reshape(2, 9, -1)
    for j in range(9):
        doflocs[:, element_dofs[j]] = xy[:, j, :]
    return skfem.MeshQuad2(doflocs, t)


def _plane_strain_stiffness(
    skfem: Any, basis: Any, youngs_modulus: float, poisson_ratio: float
) -> Any:
    """Stiffness matrix (CSC) of plane-strain linear elasticity on ``basis``.

    ``sigma = lambda tr(eps) I + 2 mu eps`` with Lame's ``lambda = E nu / ((1 + nu)(1 - 2 nu))``
    and ``mu = E / (2 (1 + nu))``.
    """
    lam = youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio))
    mu = youngs_modulus / (2 * (1 + poisson_ratio))

    @skfem.BilinearForm
    def plane_strain(u, v, w):
        du, dv = u.grad, v.grad
        shear_u = du[0][1] + du[1][0]
        shear_v = dv[0][1] + dv[1][0]
        return lam * (du[0][0] + du[1][1]) * (dv[0][0] + dv[1][1]) + mu * (
            2.0 * (du[0][0] * dv[0][0] + du[1][1] * dv[1][1]) + shear_u * shear_v
        )

    return skfem.asm(plane_strain, basis).tocsc()


@dataclass(frozen=True)
class _InnerBoundary:
    """The bore's nodes, sorted by angle, and the housing's fixed dofs.

    Attributes
    ----------
    theta, radius : ndarray, shape (n,)
        Angles [rad] and radii [m] of the bore's nodes.
    weight : ndarray, shape (n,)
        Boundary weights ``int N_j ds`` [m].
    node_dofs : ndarray of int, shape (n, 2)
        The x and y displacement dofs of each node.
    fixed : ndarray of int
        Dofs on the housing (zero displacement).
    """

    theta: FloatArray
    radius: FloatArray
    weight: FloatArray
    node_dofs: NDArray[np.intp]
    fixed: NDArray[np.intp]


def _inner_boundary(skfem: Any, mesh: Any, basis: Any, wall: _WallGrid) -> _InnerBoundary:
    """The bore's nodes (corner and mid-side), their weights, and the housing's dofs."""
    n_t, n_r = wall.circumferential, wall.radial
    facets = mesh.facets
    ring = np.arange(n_t * (n_r + 1)) % (n_r + 1)  # radial level of each vertex
    inner_facets = np.flatnonzero((ring[facets[0]] == 0) & (ring[facets[1]] == 0))
    outer_facets = np.flatnonzero((ring[facets[0]] == n_r) & (ring[facets[1]] == n_r))
    fixed = basis.get_dofs(facets=outer_facets).all()
    inner = basis.get_dofs(facets=inner_facets)
    dx = np.concatenate([inner.nodal["u^1"], inner.facet["u^1"]])
    dy = np.concatenate([inner.nodal["u^2"], inner.facet["u^2"]])
    loc = basis.doflocs[:, dx]
    angle = angle_in_turn(np.arctan2(loc[1], loc[0]))
    order = np.argsort(angle)
    dx, dy, angle = dx[order], dy[order], angle[order]
    node_radius = np.hypot(basis.doflocs[0, dx], basis.doflocs[1, dx])

    # boundary weights int N_j ds of the scalar quadratic trace
    scalar = skfem.FacetBasis(mesh, skfem.ElementQuad2(), facets=inner_facets)

    @skfem.LinearForm
    def unit(v, w):
        return v

    trace = skfem.asm(unit, scalar)
    scalar_dofs = skfem.Basis(mesh, skfem.ElementQuad2()).get_dofs(facets=inner_facets)
    s_nodes = np.concatenate([scalar_dofs.nodal["u"], scalar_dofs.facet["u"]])[order]
    return _InnerBoundary(
        theta=angle,
        radius=node_radius,
        weight=np.asarray(trace[s_nodes], dtype=float),
        node_dofs=np.stack([dx, dy], axis=1),
        fixed=fixed,
    )


# ---------------------------------------------------------------- contact solver


def _lcp(g_matrix: FloatArray, gap: FloatArray, start: NDArray[np.bool_] | None):
    """``lambda >= 0, G lambda - gap >= 0``, complementary; returns (lambda, active, iters)."""
    n = gap.size
    active = (gap > 0) if start is None else start.copy()
    scale = max(float(np.max(np.abs(gap))), 1e-300)
    tol = 1e-12 * scale
    lam = np.zeros(n)
    for iteration in range(1, 4 * n + 20):
        lam = np.zeros(n)
        idx = np.flatnonzero(active)
        if idx.size:
            lam[idx] = np.linalg.solve(g_matrix[np.ix_(idx, idx)], gap[idx])
        negative = active & (lam < 0)
        if negative.any():
            # drop the loaded nodes with tension; add nothing in the same step
            active &= ~negative
            continue
        slack = g_matrix @ lam - gap
        violated = ~active & (slack < -tol)
        if not violated.any():
            return np.maximum(lam, 0.0), active, iteration
        active |= violated
    # fall-back: Lawson-Hanson on the Cholesky factor of G
    chol = np.linalg.cholesky(g_matrix)
    rhs = np.linalg.solve(chol, gap)
    lam, _ = optimize.nnls(chol.T, rhs, maxiter=50 * n)
    return lam, lam > 0, 4 * n + 20


@dataclass(frozen=True)
class FemState:
    """FE contact solution for one load.

    Attributes
    ----------
    theta : ndarray
        Angles of the inner boundary nodes [rad].
    pressure : ndarray
        Nodal contact pressure [Pa].
    force : ndarray
        Radial nodal forces per unit axial length [N/m].
    eccentricity : ndarray, shape (2,)
        Pin-centre position [m].
    approach : float
        Pin displacement along the load minus the clearance on the load line [m].
    normal_force, tangential_force : float
        Resultant along / across the load, per unit axial length [N/m].
    half_angle_left, half_angle_right : float
        Contact extent each side of the load line [rad].
    iterations : int
        Active-set iterations summed over the balance.
    """

    theta: FloatArray
    pressure: FloatArray
    force: FloatArray
    eccentricity: FloatArray
    approach: float
    normal_force: float
    tangential_force: float
    half_angle_left: float
    half_angle_right: float
    iterations: int

    @property
    def peak_pressure(self) -> float:
        """Largest nodal pressure [Pa]."""
        return float(self.pressure.max())

    def pressure_at(self, angle: ArrayLike) -> FloatArray:
        """Pressure interpolated (periodically, linearly) at absolute angles [Pa].

        Parameters
        ----------
        angle : array_like
            Angles in the bushing frame [rad].
        """
        a = angle_in_turn(angle)
        th = np.concatenate([self.theta, [self.theta[0] + 2.0 * np.pi]])
        p = np.concatenate([self.pressure, [self.pressure[0]]])
        return np.interp(a, th, p)


def solve_contact_fe(
    mesh: BushingMesh,
    pin_radius: float,
    load_per_length: float,
    azimuth: float,
    clearance_at_load: float,
    balance: str = "paper",
    window_deg: float = 100.0,
    tolerance: float = 1e-10,
) -> FemState:
    """Solve the unilateral contact of the rigid pin for one load.

    Parameters
    ----------
    mesh : BushingMesh
        The meshed bushing.
    pin_radius : float
        ``R_p`` [m].
    load_per_length : float
        Load per unit axial length [N/m], >= 0.
    azimuth : float
        Load direction (where the pin presses) [rad].
    clearance_at_load : float
        Contour radius on the load line minus ``R_p`` [m].
    balance : {"paper", "equilibrium"}
        Pin moves along the load only, or full 2-D equilibrium.
    window_deg : float
        Only nodes within this angle of the load line may touch [deg].
    tolerance : float
        Relative force tolerance of the balance [-].
    """
    if balance not in ("paper", "equilibrium"):
        raise ContactError(
            f"contact.balance: unknown mode {balance!r}; choose 'paper' or 'equilibrium'"
        )
    contact = _RigidPinContact.near_load(mesh, pin_radius, azimuth, window_deg)
    if load_per_length == 0:
        lam = np.zeros(contact.rows.size)
        ecc = contact.along * clearance_at_load
    else:
        s = _balance_along_load(contact, load_per_length, clearance_at_load)
        ecc = s * contact.along
        if balance == "equilibrium":
            ecc = _balance_in_plane(contact, load_per_length, s)
        lam = contact.forces(ecc)
        total = contact.resultant(lam) @ contact.along
        if abs(total - load_per_length) > max(tolerance, 1e-6) * load_per_length:
            raise ConvergenceError(f"fem: load balance off by {total - load_per_length:.3g} N/m")
    return _fem_state(mesh, contact, lam, ecc, clearance_at_load)


@dataclass
class _RigidPinContact:
    """The rigid pin against the bore's nodes near the load line (one load direction).

    Attributes
    ----------
    rows : ndarray of int
        Bore nodes within the window about the load line (the only ones that may touch).
    theta, radius : ndarray
        Their angles [rad] and radii [m].
    phi : ndarray
        Their angles from the load line, in (-pi, pi] [rad].
    flexibility : ndarray, shape (len(rows), len(rows))
        Radial flexibility among them [m per N/m].
    along, across : ndarray, shape (2,)
        Unit vectors along the load and counter-clockwise across it.
    pin_radius : float
        ``R_p`` [m].
    active : ndarray of bool or None
        The last contact set (the next solve starts from it).
    iterations : int
        Active-set iterations so far.
    """

    rows: NDArray[np.intp]
    theta: FloatArray
    radius: FloatArray
    phi: FloatArray
    flexibility: FloatArray
    along: FloatArray
    across: FloatArray
    pin_radius: float
    active: NDArray[np.bool_] | None = None
    iterations: int = 0

    @classmethod
    def near_load(
        cls, mesh: BushingMesh, pin_radius: float, azimuth: float, window_deg: float
    ) -> _RigidPinContact:
        """The nodes of ``mesh`` within ``window_deg`` of the load direction ``azimuth``."""
        phi_all = wrap_angle(mesh.theta - azimuth)
        rows = np.flatnonzero(np.abs(phi_all) <= math.radians(window_deg))
        along = np.array([math.cos(azimuth), math.sin(azimuth)])
        return cls(
            rows=rows,
            theta=mesh.theta[rows],
            radius=mesh.radius[rows],
            phi=phi_all[rows],
            flexibility=mesh.flexibility(rows),
            along=along,
            across=np.array([-along[1], along[0]]),
            pin_radius=pin_radius,
        )

    def forces(self, ecc: FloatArray) -> FloatArray:
        """Radial nodal forces [N/m] with the pin's centre at ``ecc`` [m] (unilateral contact)."""
        cos_t, sin_t = np.cos(self.theta), np.sin(self.theta)
        along = cos_t * ecc[0] + sin_t * ecc[1]
        across = cos_t * ecc[1] - sin_t * ecc[0]
        gap = pin_penetration(along, across, self.radius - self.pin_radius, self.pin_radius)
        if not np.any(gap > 0):
            self.active = None
            return np.zeros_like(gap)
        lam, active, its = _lcp(self.flexibility, gap, self.active)
        self.active = active
        self.iterations += its
        return lam

    def resultant(self, lam: FloatArray) -> FloatArray:
        """Resultant ``(x, y)`` of radial nodal forces [N/m]."""
        return np.array([np.sum(lam * np.cos(self.theta)), np.sum(lam * np.sin(self.theta))])


def _balance_along_load(
    contact: _RigidPinContact, load_per_length: float, clearance_at_load: float
) -> float:
    """Pin displacement along the load [m] whose contact force along it is the load.

    ``scipy.optimize.brentq`` from ``s = 0`` (the pin centred in the bore does not
    touch) to a step beyond the clearance, doubled until the force exceeds the load.
    """
    pin_radius = contact.pin_radius

    def along_residual(s: float) -> float:
        return float(contact.resultant(contact.forces(s * contact.along)) @ contact.along) - (
            load_per_length
        )

    base = max(clearance_at_load, 0.0)
    step = 1e-3 * max(base, 1e-6 * pin_radius)
    upper = base + step
    while along_residual(upper) <= 0:
        step *= 2.0
        upper = base + step
        if upper > 0.999 * pin_radius:
            raise ContactError(
                f"load: {load_per_length:.6g} N/m finds no balance: the pin would leave "
                "the bushing wall"
            )
    return optimize.brentq(
        along_residual,
        0.0,
        upper,
        xtol=1e-15 * pin_radius,
        rtol=4 * np.finfo(float).eps,
        maxiter=200,
    )


def _balance_in_plane(contact: _RigidPinContact, load_per_length: float, s: float) -> FloatArray:
    """Pin-centre position [m] whose contact force is the load vector (``scipy.optimize.root``).

    Started from the balance along the load, ``s`` [m] on the load line.
    """
    w, w_perp = contact.along, contact.across

    def residual(x: FloatArray) -> FloatArray:
        f = contact.resultant(contact.forces(x[0] * w + x[1] * w_perp))
        return np.array([f @ w - load_per_length, f @ w_perp]) / load_per_length

    sol = optimize.root(residual, np.array([s, 0.0]), method="hybr", tol=1e-13)
    if not sol.success and np.max(np.abs(residual(sol.x))) > 1e-8:
        raise ConvergenceError(f"fem: 2-D equilibrium did not converge ({sol.message})")
    return sol.x[0] * w + sol.x[1] * w_perp


def _fem_state(
    mesh: BushingMesh,
    contact: _RigidPinContact,
    lam: FloatArray,
    ecc: FloatArray,
    clearance_at_load: float,
) -> FemState:
    """The state of a balanced contact: nodal forces and pressures, resultant, extent."""
    force = np.zeros(mesh.nodes)
    force[contact.rows] = lam
    f = contact.resultant(lam)
    w, w_perp = contact.along, contact.across
    approach = pin_penetration(
        float(ecc @ w), float(ecc @ w_perp), clearance_at_load, contact.pin_radius
    )
    left, right = _half_angles(contact.phi, lam / mesh.weight[contact.rows])
    return FemState(
        theta=mesh.theta,
        pressure=force / mesh.weight,
        force=force,
        eccentricity=ecc,
        approach=float(approach),
        normal_force=float(f @ w),
        tangential_force=float(f @ w_perp),
        half_angle_left=left,
        half_angle_right=right,
        iterations=int(contact.iterations),
    )


def _half_angles(phi: FloatArray, pressure: FloatArray) -> tuple[float, float]:
    """Contact extent each side of the load line from nodal pressures [rad]."""
    loaded = pressure > 0
    if not loaded.any():
        return 0.0, 0.0
    order = np.argsort(phi)
    phi, pressure, loaded = phi[order], pressure[order], loaded[order]
    idx = np.flatnonzero(loaded)
    first, last = int(idx[0]), int(idx[-1])
    if last + 1 < phi.size:
        left = edge_from_pressure(
            phi[last], phi[last + 1], pressure[last], pressure[last - 1] if last > first else None
        )
    else:
        left = phi[last]
    if first > 0:
        right = -edge_from_pressure(
            -phi[first],
            -phi[first - 1],
            pressure[first],
            pressure[first + 1] if last > first else None,
        )
    else:
        right = phi[first]
    return max(float(left), 0.0), max(float(-right), 0.0)


# ---------------------------------------------------------------- the contact model


@dataclass
class FemModel:
    """The FE reference as a jointwear contact model (registry name ``fem``).

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials (``bushing_thickness`` is the wall ``L``).
    circumferential : int
        Elements around the bushing [-].
    radial : int
        Elements through the wall [-].
    grading : float
        Outermost / innermost radial element size [-].
    pin : {"rigid", "effective"}
        Rigid pin, or the pin's compliance folded into the bushing modulus.
    window_deg : float
        Nodes farther than this from the load line never touch [deg].
    """

    parameters: ContactParameters
    circumferential: int = 180
    radial: int = 6
    grading: float = 4.0
    pin: str = "rigid"
    window_deg: float = 100.0
    name: str = "fem"
    _meshes: OrderedDict = field(default_factory=OrderedDict, repr=False)

    def __post_init__(self) -> None:
        if self.pin not in ("rigid", "effective"):
            raise ConfigError(f"fem.pin: unknown {self.pin!r}; choose 'rigid' or 'effective'")

    @property
    def bushing_modulus(self) -> float:
        """Young's modulus used for the bushing [Pa] (see ``pin``)."""
        if self.pin == "rigid":
            return self.parameters.bushing_youngs_modulus
        return self.parameters.effective_modulus * (1.0 - self.parameters.bushing_poisson_ratio**2)

    def mesh(self, contour: BushingContour) -> BushingMesh:
        """The (cached) mesh of a contour.

        Parameters
        ----------
        contour : BushingContour
            Bushing contour.
        """
        key = (
            contour.radius.tobytes(),
            contour.original_radius,
            self.parameters.bushing_thickness,
            self.bushing_modulus,
            self.parameters.bushing_poisson_ratio,
            self.circumferential,
            self.radial,
            self.grading,
        )
        if key in self._meshes:
            self._meshes.move_to_end(key)
            return self._meshes[key]
        mesh = build_mesh(
            contour,
            self.parameters.bushing_thickness,
            self.bushing_modulus,
            self.parameters.bushing_poisson_ratio,
            self.circumferential,
            self.radial,
            self.grading,
        )
        self._meshes[key] = mesh
        while len(self._meshes) > 4:
            self._meshes.popitem(last=False)
        return mesh

    def solve_one(
        self,
        contour: BushingContour,
        pin: Pin,
        load: float,
        azimuth: float,
        balance: str = "paper",
    ) -> FemState:
        """FE state for one load [N] at one azimuth [rad] (forces per unit length inside).

        Parameters
        ----------
        contour : BushingContour
            Bushing contour.
        pin : Pin
            The pin.
        load : float
            Load [N].
        azimuth : float
            Load direction [rad].
        balance : {"paper", "equilibrium"}
            See :func:`solve_contact_fe`.
        """
        contour.check_pin(pin)
        mesh = self.mesh(contour)
        clearance = float(contour.radius_at(np.array([azimuth]))[0]) - pin.radius
        return solve_contact_fe(
            mesh,
            pin.radius,
            load / contour.axial_length,
            azimuth,
            clearance,
            balance=balance,
            window_deg=self.window_deg,
        )

    def solve(
        self,
        contour: BushingContour,
        pin: Pin,
        load: ArrayLike,
        azimuth: ArrayLike,
        balance: str = "paper",
        **_: object,
    ) -> ContactSolution:
        """Pressure on the contour nodes for many loads (one FE contact solve each).

        Parameters
        ----------
        contour : BushingContour
            Bushing contour, circular or worn.
        pin : Pin
            The pin.
        load : array_like, shape (M,)
            Load magnitudes [N].
        azimuth : array_like, shape (M,)
            Load directions in the bushing frame [rad].
        balance : {"paper", "equilibrium"}
            Pin along the load only (default), or full 2-D equilibrium.
        **_
            Other spring-model options (``tolerance``, ``max_iterations`` ...) are ignored.
        """
        load, azimuth = check_loads(load, azimuth)
        b = contour.axial_length
        states = []
        for force, psi in zip(load, azimuth, strict=True):
            fe = self.solve_one(contour, pin, float(force), float(psi), balance)
            states.append(
                ReferenceState(
                    pressure=fe.pressure_at,
                    eccentricity=fe.eccentricity,
                    penetration=fe.approach,
                    normal_force=fe.normal_force * b,
                    tangential_force=fe.tangential_force * b,
                    half_angle_left=fe.half_angle_left,
                    half_angle_right=fe.half_angle_right,
                    iterations=fe.iterations,
                )
            )
        return assemble_solution(contour, azimuth, states, self.name)


def model(parameters: ContactParameters) -> FemModel:
    """Registry factory of the ``fem`` contact model (default mesh, rigid pin)."""
    return FemModel(parameters)
