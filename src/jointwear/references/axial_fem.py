"""Finite elements of the liner along the pin: how independent are the slices?

The slices of :mod:`jointwear.contact.axial` are independent planar contacts: a slice's
force depends on the pin's position in that slice only. In the liner they are one elastic
body, and a slice pressed harder than its neighbour drags it along by shear. This module
solves that body in three dimensions with scikit-fem, pressed by a rigid tilted pin, and
compares the force per unit length along the pin with the slices'.

The model
---------
The liner (bushing wall) of bore radius ``R_b``, wall thickness ``t`` and length ``L`` is
bonded to a rigid housing (zero displacement on ``r = R_b + t``); its ends ``z = +-L/2``
are free. Linear elasticity, small strain, trilinear hexahedra (``ElementHex1``,
2 x 2 x 2 Gauss points) on a structured grid in ``(rho, theta, z)`` mapped onto the
cylinder: ``circumferential`` elements over the half bore ``0 <= theta <= pi`` (the load
and the tilt lie in the plane ``y = 0``, a plane of symmetry: ``u_y = 0`` there),
``axial`` elements clustered at both ends (``z_k = -(L/2) cos(pi k / axial)``, where the
end effects live) and ``radial`` equal elements through the wall. The stiffness is
assembled from the nine scalar matrices ``D_pq = int d_p phi d_q phi`` (block ``(j, i)``:
``lambda D_ji + mu delta_ij sum_k D_kk + mu D_ij``), which scikit-fem assembles much faster
than the vector form.

The pin is rigid, its centre at ``s(z) = delta_0 + gamma z`` along the load (``x``), the
tilt ``gamma`` imposed. Along the ray of bore node ``j`` it overlaps the unloaded bore by
``g_j`` (:func:`jointwear.geometry.contour.pin_penetration`, the slices' ray geometry).
Contact is frictionless and unilateral: the displacement dofs of the bore nodes are
rotated to radial and tangential; an active set of nodes has its radial displacement
prescribed, ``u_r = g``, with a compressive reaction ``lambda >= 0``; the others stay open,
``u_r >= g``. Nodes in tension leave the set, open nodes the pin penetrates join it,
until neither happens. For each active set ``scipy.optimize.brentq`` finds ``delta_0``
such that the resultant along the load is ``W`` (one sparse LU factorisation per set,
a back-substitution per evaluation).

The line load ``f(z)`` is recovered from the bore's nodal forces: row ``k`` of nodes
carries the ``x``-resultant ``R_k = int N_k(z) f(z) dz`` (twice the half model's), so
``f = M^{-1} R`` with the one-dimensional consistent mass matrix ``M`` of the axial grid
(exact for a line load linear in ``z``).

What the slices neglect
-----------------------
With Poisson's ratio 0 and an aligned pin, the 3-D solution is the plane-strain one at
every ``z``: the displacement does not vary along the pin, ``u_z = 0``, no stress acts
on the end faces, which are therefore free as they must be. The slices, each that
plane-strain section, are then exact, and so is the discrete model (the extruded
2-D field solves the 3-D equations). With a tilt, ``s(z)`` varies linearly, and the
section's displacement ``s(z) U(r, theta)`` carries the shears ``gamma U_r`` and
``gamma U_theta`` over ``z``. In a flat layer ``U`` is a gradient and a ``u_z`` cancels
them (Winkler's layer is exact under a tilted flat punch); on the curved liner it is not,
and a shear stress proportional to ``gamma`` remains. It is the same at every ``z``, so it
transmits no force between slices in the interior, but it must vanish on the free ends:
an end layer a wall thickness long carries the difference. The slices' error is therefore

* zero in the interior (beyond a few ``t`` from the ends),
* proportional to the tilt's part of the line load, ``k gamma``, and to the length of
  the end layer, ``t``: ``|f_FE - f_slices| <= beta k gamma t`` at the ends,

with ``k`` the section stiffness [N/m^2]. :func:`check_against_slices` measures
``beta`` slice by slice (the FE's line load averaged over each slice). On the paper's
joint with 20 slices it falls with the mesh, 0.047, 0.036, 0.024, 0.019, 0.015 at the end
slice, about 0.004 at the next and 0.001 beyond; with half the wall it stays below 0.05.
The line load inside the last element itself does not settle with the mesh (-0.14 to
-0.28 ``k gamma t``): a feature narrower than that element, whose force vanishes with it,
which is why the comparison is made per slice.

With Poisson's ratio above 0 a second, larger difference appears: a free end of the liner
can bulge along the pin, so the wall within about a thickness of it is softer than the
confined section each slice is. With PTFE's 0.38 and an aligned pin the end slice carries
0.64 of the mid-plane's line load where the slices carry the same everywhere, and under
the tilt above the end's edge-to-mid ratio is 1.15 against the slices' 1.74. The slices
overstate the line load of a free end; this module measures by how much.

To separate this coupling from the planar difference between Winkler's law and
elasticity (a thick liner is stiffer than ``E/t``: the curvature, the circumferential
shear), the slices compared use the Winkler law with its modulus scaled so that one
slice has the FE's own section stiffness (measured with the aligned pin); the plain
Winkler law is reported beside it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray
from scipy import integrate, linalg, optimize, sparse
from scipy.sparse.linalg import splu

from jointwear.contact import ContactParameters, contact_law
from jointwear.contact.axial import AxialSlices, AxialSolution, Misalignment, solve_axial
from jointwear.errors import ConfigError, ContactError, ConvergenceError
from jointwear.geometry.contour import BushingContour, Pin, pin_penetration
from jointwear.references.fem import scikit_fem

__all__ = [
    "LinerContact",
    "LinerGrid",
    "SliceCheck",
    "TiltedPinLiner",
    "check_against_slices",
    "elasticity_stiffness",
]

FloatArray = NDArray[np.float64]

#: largest number of active-set updates of one contact solve
MAX_ACTIVE_SET_UPDATES = 60


@dataclass(frozen=True)
class LinerGrid:
    """Element counts of the liner's mesh.

    Parameters
    ----------
    circumferential : int
        Elements over the half bore ``0 <= theta <= pi`` [-].
    axial : int
        Elements along the liner, clustered at the ends; even, so that a row of nodes
        lies on the mid-plane [-].
    radial : int
        Elements through the wall [-].
    """

    circumferential: int = 24
    axial: int = 16
    radial: int = 3

    def __post_init__(self) -> None:
        counts = (self.circumferential, self.axial, self.radial)
        if any(isinstance(n, bool) or not isinstance(n, int) or n < 1 for n in counts):
            raise ConfigError(
                f"liner grid: element counts must be whole numbers >= 1, got {counts}"
            )
        if self.axial % 2:
            raise ConfigError(
                f"liner grid: axial must be even (a node row at z = 0), got {self.axial}"
            )

    @property
    def axial_positions(self) -> FloatArray:
        """Axial node positions on a unit length, clustered at the ends, ``-1/2 .. 1/2`` [-]."""
        positions = -0.5 * np.cos(np.pi * np.arange(self.axial + 1) / self.axial)
        positions[self.axial // 2] = 0.0
        return positions


@dataclass(frozen=True)
class LinerContact:
    """The liner pressed by the tilted pin under one load.

    Attributes
    ----------
    z : ndarray
        Axial positions of the node rows, ``-L/2 .. L/2`` [m].
    line_load : ndarray
        Force per unit length along the load ``f(z)`` at ``z`` [N/m].
    centre_offset : float
        ``delta_0``, the pin centre along the load at the mid-plane [m].
    tilt : float
        ``gamma``, the imposed tilt [rad].
    load : float
        ``W`` [N].
    resultant : float
        The nodal forces' resultant along the load [N].
    contact_angle : float
        Largest angle from the load line of a loaded bore node [rad].
    active_set_updates : int
        Active sets tried.
    """

    z: FloatArray
    line_load: FloatArray
    centre_offset: float
    tilt: float
    load: float
    resultant: float
    contact_angle: float
    active_set_updates: int

    def at(self, z: float) -> float:
        """The line load at ``z`` (linear between node rows) [N/m]."""
        return float(np.interp(z, self.z, self.line_load))

    def band_average(self, edges: FloatArray) -> FloatArray:
        """Mean line load over each band between consecutive ``edges`` [N/m].

        Exact for the recovered line load, which is linear between node rows.
        """
        edges = np.asarray(edges, dtype=float)
        points = np.union1d(self.z, edges)
        integral = integrate.cumulative_trapezoid(
            np.interp(points, self.z, self.line_load), points, initial=0.0
        )
        return np.diff(integral[np.searchsorted(points, edges)]) / np.diff(edges)


@dataclass(eq=False)
class TiltedPinLiner:
    """The liner's finite-element model, ready to be pressed by a rigid tilted pin.

    Parameters
    ----------
    parameters : ContactParameters
        The joint: pin radius, bore radius, wall thickness, length, the liner's Young's
        modulus and Poisson's ratio [SI].
    grid : LinerGrid
        Element counts.
    """

    parameters: ContactParameters
    grid: LinerGrid = field(default_factory=LinerGrid)
    dofs: int = field(init=False)
    _stiffness: Any = field(init=False, repr=False)
    _bore: Any = field(init=False, repr=False)
    _fixed: Any = field(init=False, repr=False)

    def __post_init__(self) -> None:
        skfem = scikit_fem()
        p = self.parameters
        if not p.bushing_radius > p.pin_radius:
            raise ConfigError("liner: the bore radius must exceed the pin radius")
        if not -1.0 < p.bushing_poisson_ratio < 0.5:
            raise ConfigError("liner: Poisson's ratio must lie in (-1, 0.5)")
        g = self.grid
        rho = np.linspace(0.0, 1.0, g.radial + 1)
        theta = np.linspace(0.0, np.pi, g.circumferential + 1)
        grid = skfem.MeshHex.init_tensor(rho, theta, g.axial_positions * p.axial_length)
        radius = p.bushing_radius + p.bushing_thickness * grid.p[0]
        angle = grid.p[1]
        points = np.vstack([radius * np.cos(angle), radius * np.sin(angle), grid.p[2]])
        mesh = skfem.MeshHex(points, grid.t)
        nodes = points.shape[1]
        bore = np.flatnonzero(grid.p[0] == 0.0)
        rotation = _bore_rotation(nodes, bore, angle[bore])
        blocked = elasticity_stiffness(mesh, p.bushing_youngs_modulus, p.bushing_poisson_ratio)
        self._stiffness = (rotation.T @ blocked @ rotation).tocsr()
        housing = np.flatnonzero(grid.p[0] == 1.0)
        symmetry = np.flatnonzero((angle == 0.0) | (angle == np.pi))
        # the rotated bore dofs keep the x slot radial and the y slot tangential, so the
        # symmetry planes fix the y slot (u_y, or +-u_t on the bore) everywhere
        self._fixed = np.unique(
            np.concatenate([housing, housing + nodes, housing + 2 * nodes, symmetry + nodes])
        )
        self._bore = _Bore(
            nodes=bore,
            theta=angle[bore],
            z=grid.p[2, bore],
            rows=np.searchsorted(g.axial_positions * p.axial_length, grid.p[2, bore]),
        )
        self.dofs = 3 * nodes

    @property
    def z(self) -> FloatArray:
        """Axial positions of the node rows [m]."""
        return self.grid.axial_positions * self.parameters.axial_length

    def penetration(self, centre_offset: float, tilt: float) -> FloatArray:
        """Overlap of the rigid pin with the unloaded bore at every bore node [m]."""
        p, bore = self.parameters, self._bore
        s = centre_offset + tilt * bore.z
        gap = p.bushing_radius - p.pin_radius
        return pin_penetration(s * np.cos(bore.theta), s * np.sin(bore.theta), gap, p.pin_radius)

    def solve(self, load: float, tilt: float) -> LinerContact:
        """Press the liner with the pin tilted by ``tilt`` under the load ``load``.

        Parameters
        ----------
        load : float
            Load ``W > 0`` along ``x`` [N].
        tilt : float
            Imposed tilt ``gamma`` of the pin in the load plane [rad].

        Returns
        -------
        LinerContact

        Raises
        ------
        ContactError
            The pin cannot carry the load without touching the housing.
        ConvergenceError
            The active set did not settle.
        """
        if not (math.isfinite(load) and load > 0 and math.isfinite(tilt)):
            raise ConfigError(f"liner: load must be > 0 and tilt finite, got {load!r}, {tilt!r}")
        p = self.parameters
        # the first active set: where the pin overlaps the bore at Winkler's approach
        winkler = p.bushing_youngs_modulus / p.bushing_thickness * p.pin_radius * p.axial_length
        active = self.penetration(load / winkler, tilt) > 0
        for update in range(1, MAX_ACTIVE_SET_UPDATES + 1):
            state = _ActiveSet(self, active)
            offset = state.balance(load, tilt)
            gap = self.penetration(offset, tilt)
            reaction, radial = state.response(gap)
            tolerance = 1e-9 * float(np.max(np.abs(gap)))
            tension = active & (reaction < 0)
            if tension.any():
                active = active & ~tension
                continue
            touched = ~active & (radial < gap - tolerance)
            if not touched.any():
                return self._contact(reaction, offset, tilt, load, update)
            active = active | touched
        raise ConvergenceError(
            f"liner: the contact set did not settle in {MAX_ACTIVE_SET_UPDATES} updates"
        )

    def _contact(self, reaction, offset, tilt, load, updates) -> LinerContact:
        bore = self._bore
        along = 2.0 * reaction * np.cos(bore.theta)  # both halves of the bore
        rows = np.bincount(bore.rows, along, minlength=self.z.size)
        loaded = reaction > 0
        return LinerContact(
            z=self.z,
            line_load=_line_load(self.z, rows),
            centre_offset=offset,
            tilt=tilt,
            load=load,
            resultant=float(along.sum()),
            contact_angle=float(bore.theta[loaded].max()) if loaded.any() else 0.0,
            active_set_updates=updates,
        )


@dataclass(frozen=True)
class _Bore:
    """The bore's nodes: indices, angles [rad], axial positions [m], axial row."""

    nodes: NDArray[np.intp]
    theta: FloatArray
    z: FloatArray
    rows: NDArray[np.intp]


class _ActiveSet:
    """One active set: its radial dofs prescribed, the rest factorised once."""

    def __init__(self, liner: TiltedPinLiner, active: NDArray[np.bool_]) -> None:
        self.liner = liner
        self.active = active
        radial_dofs = liner._bore.nodes  # the x slot of a bore node is its radial dof
        self.prescribed = radial_dofs[active]
        self.radial_dofs = radial_dofs
        taken = np.zeros(liner.dofs, dtype=bool)
        taken[liner._fixed] = True
        taken[self.prescribed] = True
        self.free = np.flatnonzero(~taken)
        stiffness = liner._stiffness
        self.coupling = stiffness[self.free][:, self.prescribed]
        self.own = stiffness[self.prescribed][:, self.prescribed]
        self.back = stiffness[self.prescribed][:, self.free]
        self.factor = splu(stiffness[self.free][:, self.free].tocsc())

    def response(self, gap: FloatArray) -> tuple[FloatArray, FloatArray]:
        """Radial reactions and radial displacements of all bore nodes [N], [m]."""
        prescribed = gap[self.active]
        displacement = np.zeros(self.liner.dofs)
        displacement[self.prescribed] = prescribed
        displacement[self.free] = -self.factor.solve(self.coupling @ prescribed)
        reaction = np.zeros(gap.size)
        reaction[self.active] = self.back @ displacement[self.free] + self.own @ prescribed
        return reaction, displacement[self.radial_dofs]

    def resultant(self, offset: float, tilt: float) -> float:
        reaction, _ = self.response(self.liner.penetration(offset, tilt))
        return float(2.0 * reaction @ np.cos(self.liner._bore.theta))

    def balance(self, load: float, tilt: float) -> float:
        """``delta_0`` that carries ``load`` with this active set [m]."""
        p = self.liner.parameters
        reach = p.bushing_radius - p.pin_radius + p.bushing_thickness
        low, high = 0.0, 1e-9 * reach
        while self.resultant(high, tilt) < load:
            low, high = high, 2.0 * high
            if high > reach:
                raise ContactError("liner: the load pushes the pin through the wall")
        return float(
            optimize.brentq(
                lambda s: self.resultant(s, tilt) - load,
                low,
                high,
                xtol=1e-18,
                rtol=4 * np.finfo(float).eps,
            )
        )


def _bore_rotation(nodes: int, bore: NDArray[np.intp], theta: FloatArray) -> Any:
    """``u = T v``: the bore nodes' (x, y) displacement dofs turned into (radial, tangential).

    Dofs are blocked by component: ``x`` of node ``n`` is ``n``, ``y`` is ``n + nodes``.
    """
    cos, sin = np.cos(theta), np.sin(theta)
    diagonal = np.ones(3 * nodes)
    diagonal[bore] = cos
    diagonal[bore + nodes] = cos
    rotation = sparse.diags(diagonal, format="lil")
    rotation[bore, bore + nodes] = -sin  # u_x = cos u_r - sin u_t
    rotation[bore + nodes, bore] = sin  # u_y = sin u_r + cos u_t
    return rotation.tocsr()


def elasticity_stiffness(mesh: Any, youngs_modulus: float, poisson_ratio: float) -> Any:
    """Stiffness of 3-D linear elasticity on ``mesh`` (trilinear), dofs blocked by component.

    Assembled from nine scalar matrices, much faster in scikit-fem than the vector form.

    ``a(u, v) = int lambda div u div v + 2 mu eps(u) : eps(v)``; for ``u = phi_b e_i`` and
    ``v = phi_a e_j`` this is ``lambda D_ji + mu delta_ij sum_k D_kk + mu D_ij`` with
    ``D_pq = int d_p phi_a d_q phi_b``.

    Parameters
    ----------
    mesh : skfem.MeshHex
        A mesh of trilinear hexahedra [m].
    youngs_modulus : float
        Young's modulus ``E`` [Pa].
    poisson_ratio : float
        Poisson's ratio ``nu`` [-].

    Returns
    -------
    scipy.sparse.csr_matrix
        The stiffness [N/m], dofs ``x`` of every node, then ``y``, then ``z``.
    """
    skfem = scikit_fem()
    from skfem.models.elasticity import lame_parameters

    lam, mu = lame_parameters(youngs_modulus, poisson_ratio)
    basis = skfem.Basis(mesh, skfem.ElementHex1(), intorder=3)
    products = {}
    for first in range(3):
        for second in range(first, 3):
            form = skfem.BilinearForm(lambda u, v, w, a=first, b=second: v.grad[a] * u.grad[b])
            products[first, second] = form.assemble(basis)
            products[second, first] = products[first, second].T
    laplace = products[0, 0] + products[1, 1] + products[2, 2]
    blocks = [
        [
            lam * products[j, i] + mu * products[i, j] + (mu * laplace if i == j else 0)
            for i in range(3)
        ]
        for j in range(3)
    ]
    return sparse.bmat(blocks, format="csr")


def _line_load(z: FloatArray, rows: FloatArray) -> FloatArray:
    """``f`` from the rows' resultants ``R_k = int N_k f dz``: ``M f = R`` (consistent mass)."""
    h = np.diff(z)
    diagonal = np.zeros(z.size)
    diagonal[:-1] += h / 3.0
    diagonal[1:] += h / 3.0
    off = h / 6.0
    banded = np.zeros((3, z.size))
    banded[0, 1:] = off
    banded[1] = diagonal
    banded[2, :-1] = off
    return linalg.solve_banded((1, 1), banded, rows)


@dataclass(frozen=True)
class SliceCheck:
    """The FE liner against the slices under one tilted pin.

    Attributes
    ----------
    aligned, tilted : LinerContact
        The FE solutions without and with the tilt.
    matched, winkler : AxialSolution
        The slices with the Winkler law scaled to the FE's section stiffness, and with
        the plain Winkler law.
    section_stiffness : float
        ``k``, the FE's force per unit length per unit approach, ``W / (L delta_0)`` with
        the aligned pin [N/m^2].
    winkler_stiffness : float
        The same of the plain Winkler slices [N/m^2].
    thickness : float
        Wall thickness ``t`` [m].
    """

    aligned: LinerContact
    tilted: LinerContact
    matched: AxialSolution
    winkler: AxialSolution
    section_stiffness: float
    winkler_stiffness: float
    thickness: float

    @property
    def edges(self) -> FloatArray:
        """The slices' boundaries [m]."""
        return np.concatenate(
            [
                [self.matched.centres[0] - 0.5 * self.matched.widths[0]],
                self.matched.centres + 0.5 * self.matched.widths,
            ]
        )

    @property
    def fe_line_load(self) -> FloatArray:
        """The FE's tilted line load averaged over each slice [N/m]."""
        return self.tilted.band_average(self.edges)

    @property
    def slice_error(self) -> FloatArray:
        """``(f_FE - f_slices) / (k gamma t)`` slice by slice, the matched slices [-]."""
        scale = self.section_stiffness * abs(self.tilted.tilt) * self.thickness
        return (self.fe_line_load - self.matched.line_load) / scale

    def edge_to_mid(self) -> dict[str, tuple[float, float]]:
        """Each end slice's line load over the line load at the mid-plane [-].

        Returns
        -------
        dict
            ``"fe"``, ``"matched"``, ``"winkler"``: ``(z < 0 end, z > 0 end)``; the slices'
            mid-plane line load is that of their line fit at 0 (a linear law: ``W / L``).
        """
        fe = self.fe_line_load
        ratios = {"fe": (fe[0] / self.tilted.at(0.0), fe[-1] / self.tilted.at(0.0))}
        for name, solution in (("matched", self.matched), ("winkler", self.winkler)):
            mid = np.polyval(np.polyfit(solution.centres, solution.line_load, 1), 0.0)
            ratios[name] = (solution.line_load[0] / mid, solution.line_load[-1] / mid)
        return {name: (float(low), float(high)) for name, (low, high) in ratios.items()}


def check_against_slices(
    parameters: ContactParameters,
    grid: LinerGrid,
    load: float,
    tilt: float,
    slices: int = 20,
    nodes: int = 720,
) -> SliceCheck:
    """The FE liner and the slices under the same load and imposed tilt.

    Parameters
    ----------
    parameters : ContactParameters
        The joint [SI]; a near-zero clearance makes Winkler's slices linear.
    grid : LinerGrid
        The FE mesh.
    load : float
        Load ``W`` [N].
    tilt : float
        Imposed tilt ``gamma`` [rad].
    slices : int
        Number of slices ``N`` [-].
    nodes : int
        Nodes of each slice's contour [-].

    Returns
    -------
    SliceCheck
    """
    liner = TiltedPinLiner(parameters, grid)
    aligned = liner.solve(load, 0.0)
    tilted = liner.solve(load, tilt)
    length = parameters.axial_length
    cut = AxialSlices(length, slices)
    contours = cut.contours(BushingContour.circle(parameters.bushing_radius, nodes, length))
    pin = Pin(parameters.pin_radius)
    law = contact_law("asymmetric-winkler", parameters)
    plain = solve_axial(contours, cut, pin, load, 0.0, law)
    section = load / (length * aligned.centre_offset)
    plain_section = load / (length * plain.centre_offset)
    # a linear law: scaling its modulus scales the section stiffness by the same factor
    scaled = replace(law, coefficient=law.coefficient * section / plain_section)
    misaligned = Misalignment(abs(tilt), 0.0 if tilt >= 0 else np.pi)
    return SliceCheck(
        aligned=aligned,
        tilted=tilted,
        matched=solve_axial(contours, cut, pin, load, 0.0, scaled, misalignment=misaligned),
        winkler=solve_axial(contours, cut, pin, load, 0.0, law, misalignment=misaligned),
        section_stiffness=section,
        winkler_stiffness=plain_section,
        thickness=parameters.bushing_thickness,
    )
