"""Exact elastic reference: Persson's pin-in-hole contact problem.

A cylindrical pin (radius ``R_p``, elastic or rigid) is pressed by a load ``P``
per unit length into a cylindrical hole (radius ``R_b = R_p + c``) with radial
clearance ``c``. Plane strain, linear elasticity, frictionless, dissimilar
materials. The hole is cut either in an infinite plate (Persson's classical
problem, ``housing="infinite"``) or in a bushing of wall thickness ``L`` bonded
to a rigid housing (``housing="rigid"``, the real joint of the paper).

Formulation
-----------
Both bodies are loaded on their circular boundary by the same normal pressure
``p(theta) = p_0 + sum_k p_k cos(k theta)`` (symmetric about the load line).
For a circular boundary, each Fourier mode of pressure produces the same mode
of radial displacement, ``u_k = U_k p_k``; the mode compliances ``U_k`` follow
exactly from the Kolosov-Muskhelishvili potentials [3]_ (``kappa = 3 - 4 nu``,
``mu`` shear modulus):

* pin (disk, radius ``R``): ``U_0 = -(kappa-1) R / (4 mu)``,
  ``U_k = -R/(4 mu) [kappa/(k+1) + 1/(k-1)]`` for ``k >= 2``;
* hole in an infinite plate: ``U_0 = R/(2 mu)``,
  ``U_k = R/(4 mu) [kappa/(k-1) + 1/(k+1)]``;
* bushing in a rigid housing: a 2x2 (``k = 0``, ``k = 1``) or 4x4 (``k >= 2``)
  linear system per mode, with zero displacement at ``R_b + L``.

The combined compliance ``C_k = U_k^{hole} - U_k^{pin}`` is, for ``k >= 2``,

.. math:: C_k = \\frac{C_\\infty k + B}{k^2 - 1}, \\qquad
          C_\\infty = \\frac{2 R_b}{E'_b} + \\frac{2 R_p}{E'_p}, \\qquad
          \\frac{B}{C_\\infty} \\to \\beta \\ (R_p \\to R_b),

with ``E' = E/(1-nu^2)`` and ``beta`` Dundurs' second parameter: the
structure of Persson's integral equation [1]_, whose leading part is the
Cauchy (Hilbert) kernel ``cot((theta - phi)/2)`` and whose ``beta`` part is
a bounded kernel. The mode ``k = 1`` carries the net force: in an infinite
plate its displacement grows like ``ln`` of the distance at which the plate is
held, so the pin *approach* is only defined with a reference radius
``r_ref`` (the plate's mean displacement on the circle ``r_ref`` is zero;
default ``r_ref = R_b + L``, the housing); the pressure and contact angle do not
depend on it. The pin's rigid displacement is its boundary's mean displacement.

Contact condition on the arc ``|theta| < alpha``: the radial displacements
close the gap between the displaced pin (centre at ``e`` along the load) and
the hole,

.. math:: w(\\theta) = \\sum_k C_k p_k \\cos k\\theta
          = e\\cos\\theta + \\sqrt{R_p^2 - e^2\\sin^2\\theta} - R_b

(``gap="exact"``; ``gap="linear"`` uses Persson's ``e cos(theta) - c``), with
``p >= 0`` on the arc, the gap open outside, and ``P = R_b int p cos(theta)``.

Numerical solution: ``p`` is piecewise linear on a uniform grid over
``[0, (1 + 8/nodes) alpha]`` (mirrored), the influence of each hat function is
summed over all Fourier modes in O(N log N) by folding the modes onto an FFT
grid (``h = 2 pi / N``; modes beyond ``4N`` in closed form, Hurwitz zeta), the
equations are collocated at the grid nodes (Cholesky of the symmetric
compliance once per grid; its leading blocks serve every contact set) and the
load is imposed with ``e`` as an extra unknown. The contact set is the largest
set of loaded nodes whose edge pressure stays ``>= 0``, the edge ``alpha`` by the
square-root behaviour of ``p`` there, and the grid is then fitted to
``alpha`` and the problem solved again.

Checks (``tests/references``): small loads reproduce Hertz with
``R* = R_p R_b / (R_b - R_p)``; for ``B = 0`` (e.g. a rigid pin in an
incompressible plate, or identical materials) the solution is closed form
(:func:`similar_solution`, below); at zero clearance the contact angle does not
depend on the load (:func:`similar_neat_fit_angle`).

Closed form for ``B = 0``
-------------------------
Applying ``d^2/dtheta^2 + 1`` to the contact condition removes the rigid-body
modes and leaves a Cauchy equation on the arc,
``H[p](theta) = A theta + p_1 sin(theta)`` with ``A = (c + C_0 p_0) / C_inf``
(``H`` the conjugate-function operator). With ``x = tan(theta/2)`` it becomes a
finite Hilbert transform whose bounded solution is elementary:

.. math:: p(\\theta) = 2A\\,\\operatorname{artanh}
          \\frac{\\sqrt{\\sin^2(\\alpha/2) - \\sin^2(\\theta/2)}}{\\cos(\\theta/2)}
          + 2 p_1 \\cos\\frac{\\theta}{2}
          \\sqrt{\\sin^2\\frac{\\alpha}{2} - \\sin^2\\frac{\\theta}{2}},

(compare Persson [1]_ and Ciavarella & Decuzzi [2]_, whose closed form for
elastic similarity has this structure); the two moments ``p_0`` and ``p_1`` of
``p`` close the system and give ``P = pi R_b p_1`` as a function of ``alpha``.
For small ``alpha`` both shapes tend to ``sqrt(alpha^2 - theta^2)``, Hertz [4]_.

References
----------
.. [1] Persson, A.: On the stress distribution of cylindrical elastic bodies in
   contact. PhD thesis, Chalmers, Göteborg (1964).
.. [2] Ciavarella, M., Decuzzi, P.: The state of stress induced by the plane
   frictionless cylindrical contact. I. The case of elastic similarity;
   II. The general case (elastic dissimilarity). Int. J. Solids Struct. 38,
   4507-4523 and 4525-4533 (2001).
.. [3] Muskhelishvili, N. I.: Some Basic Problems of the Mathematical Theory of
   Elasticity. Noordhoff (1953), §§ 41-56.
.. [4] Johnson, K. L.: Contact Mechanics. Cambridge University Press (1985), §5.3.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy import integrate, linalg, optimize, special

from jointwear.contact.laws import ContactParameters
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ConfigError, ContactError, ConvergenceError, GeometryError
from jointwear.geometry.angles import wrap_angle
from jointwear.geometry.contour import BushingContour, Pin
from jointwear.references.solution import (
    ReferenceState,
    assemble_solution,
    check_loads,
    edge_from_pressure,
)

__all__ = [
    "ArcSolution",
    "PerssonModel",
    "PerssonProblem",
    "annulus_compliance",
    "disk_compliance",
    "hole_compliance",
    "model",
    "similar_neat_fit_angle",
    "similar_solution",
]

FloatArray = NDArray[np.float64]

#: periods of the FFT grid whose modes are summed explicitly (the rest in closed form)
_EXPLICIT_PERIODS = 4


def _lame(youngs_modulus: float, poisson_ratio: float) -> tuple[float, float]:
    """Shear modulus ``mu`` [Pa] (inf for a rigid body) and plane-strain ``kappa`` [-]."""
    if not (youngs_modulus > 0) or not (-1.0 < poisson_ratio <= 0.5):
        raise ConfigError(
            f"materials: need E > 0 and -1 < nu <= 0.5, got E={youngs_modulus!r}, "
            f"nu={poisson_ratio!r}"
        )
    return youngs_modulus / (2.0 * (1.0 + poisson_ratio)), 3.0 - 4.0 * poisson_ratio


def disk_compliance(
    modes: ArrayLike, radius: float, youngs_modulus: float, poisson_ratio: float
) -> FloatArray:
    """Radial boundary displacement of a disk per unit ``cos(k theta)`` pressure [m/Pa].

    Plane strain; the pressure pushes the boundary inwards, so the values are
    negative (except ``k = 1``, where the rigid translation is removed: the pin's
    position is its boundary's mean displacement; the net force is reacted at the
    centre).

    Parameters
    ----------
    modes : array_like of int
        Fourier orders ``k >= 0`` [-].
    radius : float
        Disk radius ``R`` [m].
    youngs_modulus : float
        Young's modulus [Pa]; ``inf`` for a rigid pin (zero compliance).
    poisson_ratio : float
        Poisson's ratio [-].
    """
    k = np.asarray(modes, dtype=float)
    mu, kappa = _lame(youngs_modulus, poisson_ratio)
    scale = radius / (4.0 * mu)
    with np.errstate(divide="ignore", invalid="ignore"):
        general = -scale * (kappa / (k + 1.0) + 1.0 / (k - 1.0))
    return np.select(
        [k == 0, k == 1], [-(kappa - 1.0) * scale, 0.5 * (2.0 - kappa) * scale], general
    )


def hole_compliance(
    modes: ArrayLike,
    radius: float,
    youngs_modulus: float,
    poisson_ratio: float,
    reference_radius: float,
) -> FloatArray:
    """Radial displacement of a hole in an infinite plate per unit ``cos(k theta)`` pressure.

    Outward positive [m/Pa]. For ``k = 1`` (the net force) the plate is held so
    that its mean displacement on the circle ``reference_radius`` is zero.

    Parameters
    ----------
    modes : array_like of int
        Fourier orders ``k >= 0`` [-].
    radius : float
        Hole radius ``R`` [m].
    youngs_modulus : float
        Young's modulus [Pa].
    poisson_ratio : float
        Poisson's ratio [-].
    reference_radius : float
        Radius at which the plate is held (mean displacement zero) [m], ``>= R``.
    """
    k = np.asarray(modes, dtype=float)
    mu, kappa = _lame(youngs_modulus, poisson_ratio)
    scale = radius / (4.0 * mu)
    with np.errstate(divide="ignore", invalid="ignore"):
        general = scale * (kappa / (k - 1.0) + 1.0 / (k + 1.0))
    mode1 = 0.5 * scale + 2.0 * scale * kappa / (1.0 + kappa) * math.log(reference_radius / radius)
    return np.select([k == 0, k == 1], [2.0 * scale, mode1], general)


def annulus_compliance(
    modes: ArrayLike,
    radius: float,
    outer_radius: float,
    youngs_modulus: float,
    poisson_ratio: float,
) -> FloatArray:
    """Radial displacement of the inner boundary of a bushing in a rigid housing.

    The ring ``radius <= r <= outer_radius`` is bonded (zero displacement) at
    ``outer_radius`` and loaded by a ``cos(k theta)`` pressure on its inner
    boundary; outward positive [m/Pa]. Exact plane-strain solution per mode
    from the Kolosov-Muskhelishvili potentials ``z^(k+1), z^(1-k)`` (``phi``)
    and ``z^(k-1), z^(-k-1)`` (``psi``), with ``log z`` terms for ``k = 1``.

    Parameters
    ----------
    modes : array_like of int
        Fourier orders ``k >= 0`` [-].
    radius : float
        Inner radius ``R_b`` [m].
    outer_radius : float
        Housing radius ``R_b + L`` [m].
    youngs_modulus : float
        Young's modulus [Pa].
    poisson_ratio : float
        Poisson's ratio [-].
    """
    k_all = np.asarray(modes, dtype=np.int64)
    mu, kappa = _lame(youngs_modulus, poisson_ratio)
    if not outer_radius > radius:
        raise GeometryError("joint.bushing_thickness: must be > 0")
    rho = outer_radius / radius
    out = np.empty(k_all.shape, dtype=float)
    # far modes do not feel the housing: (R/R_o)^k below round-off
    cutoff = math.ceil(40.0 / math.log(rho)) + 2
    far = k_all > cutoff
    out[far] = hole_compliance(k_all[far], radius, youngs_modulus, poisson_ratio, outer_radius)
    out[k_all == 0] = (
        (kappa - 1.0) * radius * (rho**2 - 1.0) / (2.0 * mu * (2.0 + (kappa - 1.0) * rho**2))
    )
    if np.any(k_all == 1):
        r, ro = radius, outer_radius
        a_log = -r / (2.0 * (1.0 + kappa))
        matrix = np.array([[2.0 * r, 2.0 / r**3], [kappa * ro**2, -1.0 / ro**2]])
        a2, b = np.linalg.solve(matrix, [-0.5 - 2.0 * a_log / r, a_log])
        c_minus = 2.0 * kappa * a_log * math.log(r / ro) - 2.0 * a2 * r**2 + 2.0 * a2 * ro**2
        c_plus = -a_log + kappa * a2 * r**2 - b / r**2
        out[k_all == 1] = (c_plus + c_minus) / (2.0 * mu)
    near = (k_all >= 2) & ~far
    if np.any(near):
        k = k_all[near].astype(float)
        q = rho ** (-k)
        z = np.zeros_like(k)
        system = np.stack(
            [
                np.stack([(k + 1) * (1 - k) * q, 1 - k, -(k - 1) * q * rho**2, z], axis=-1),
                np.stack([(k + 1) * q, -(k**2 - 1), z, k + 1], axis=-1),
                np.stack([kappa + z, (k - 1) * q, z, -q / rho**2], axis=-1),
                np.stack([-(k + 1), kappa * q, -1 + z, z], axis=-1),
            ],
            axis=-2,
        )
        rhs = np.zeros((k.size, 4, 1))
        rhs[:, 0, 0] = rhs[:, 1, 0] = -0.5
        y = np.linalg.solve(system, rhs)[..., 0]
        c_plus = kappa * q * y[:, 0] + (k - 1) * y[:, 1] - y[:, 3]
        c_minus = -(k + 1) * q * y[:, 0] + kappa * y[:, 1] - q * rho**2 * y[:, 2]
        out[near] = radius * (c_plus + c_minus) / (2.0 * mu)
    return out


@dataclass(frozen=True)
class ArcSolution:
    """Persson solution for one load (symmetric about the load line).

    Attributes
    ----------
    load_per_length : float
        Load per unit axial length ``P`` [N/m].
    half_angle : float
        Contact half-angle ``alpha`` [rad].
    eccentricity : float
        Pin displacement ``e`` along the load [m].
    approach : float
        ``e - c``, the comparable of the spring models' penetration at the
        compression centre [m].
    theta : ndarray
        Grid angles from the load line, ``0 .. theta_max`` [rad].
    pressure : ndarray
        Pressure at ``theta`` (piecewise linear in between, zero beyond) [Pa].
    iterations : int
        Linear solves used.
    """

    load_per_length: float
    half_angle: float
    eccentricity: float
    approach: float
    theta: FloatArray
    pressure: FloatArray
    iterations: int

    @property
    def peak_pressure(self) -> float:
        """Pressure on the load line [Pa]."""
        return float(self.pressure[0]) if self.pressure.size else 0.0

    def pressure_at(self, angle: ArrayLike) -> FloatArray:
        """Pressure at angles from the load line [Pa] (even in the angle).

        Parameters
        ----------
        angle : array_like
            Angles measured from the load line [rad].
        """
        a = np.abs(wrap_angle(angle))
        if self.pressure.size == 0:
            return np.zeros_like(a)
        return np.interp(a, self.theta, self.pressure, right=0.0)


@dataclass(frozen=True)
class PerssonProblem:
    """Geometry and materials of a pin in a hole (SI).

    Parameters
    ----------
    pin_radius : float
        ``R_p`` [m].
    bushing_radius : float
        ``R_b`` [m], ``>= R_p`` (equal: neat fit).
    pin_youngs_modulus : float
        [Pa]; ``inf`` for a rigid pin.
    pin_poisson_ratio : float
        [-].
    bushing_youngs_modulus : float
        [Pa].
    bushing_poisson_ratio : float
        [-].
    housing : {"infinite", "rigid"}
        Hole in an infinite plate (Persson) or bushing bonded in a rigid housing.
    outer_radius : float
        Housing radius ``R_b + L`` [m]: the rigid housing, or (``"infinite"``) the
        radius at which the plate is held for the approach (``r_ref``).
    gap : {"exact", "linear"}
        Exact pin-circle gap along the radial rays, or Persson's ``e cos(theta) - c``.
    """

    pin_radius: float
    bushing_radius: float
    pin_youngs_modulus: float
    pin_poisson_ratio: float
    bushing_youngs_modulus: float
    bushing_poisson_ratio: float
    housing: str = "infinite"
    outer_radius: float = math.nan
    gap: str = "exact"
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    def __post_init__(self) -> None:
        if self.housing not in ("infinite", "rigid"):
            raise ConfigError(
                f"persson.housing: unknown {self.housing!r}; choose 'infinite' or 'rigid'"
            )
        if self.gap not in ("exact", "linear"):
            raise ConfigError(f"persson.gap: unknown {self.gap!r}; choose 'exact' or 'linear'")
        if not (self.pin_radius > 0 and self.bushing_radius >= self.pin_radius):
            raise GeometryError("joint: need 0 < pin radius <= bushing radius")
        if math.isnan(self.outer_radius):
            object.__setattr__(self, "outer_radius", 1.5 * self.bushing_radius)
        if not self.outer_radius > self.bushing_radius:
            raise GeometryError("joint.bushing_thickness: outer radius must exceed the bore")

    @classmethod
    def from_parameters(
        cls,
        parameters: ContactParameters,
        housing: str = "infinite",
        gap: str = "exact",
        rigid_pin: bool = False,
        bushing_radius: float | None = None,
        pin_radius: float | None = None,
    ) -> PerssonProblem:
        """Build from :class:`~jointwear.contact.ContactParameters`.

        Parameters
        ----------
        parameters : ContactParameters
            Geometry and materials (``R_b + L`` is the housing / reference radius).
        housing : {"infinite", "rigid"}
            See the class.
        gap : {"exact", "linear"}
            See the class.
        rigid_pin : bool
            Treat the pin as rigid.
        bushing_radius, pin_radius : float, optional
            Override the radii [m] (e.g. from the contour and pin actually solved).
        """
        r_b = parameters.bushing_radius if bushing_radius is None else bushing_radius
        return cls(
            pin_radius=parameters.pin_radius if pin_radius is None else pin_radius,
            bushing_radius=r_b,
            pin_youngs_modulus=math.inf if rigid_pin else parameters.pin_youngs_modulus,
            pin_poisson_ratio=parameters.pin_poisson_ratio,
            bushing_youngs_modulus=parameters.bushing_youngs_modulus,
            bushing_poisson_ratio=parameters.bushing_poisson_ratio,
            housing=housing,
            outer_radius=r_b + parameters.bushing_thickness,
            gap=gap,
        )

    # ------------------------------------------------------------ compliance
    @property
    def clearance(self) -> float:
        """Radial clearance ``c = R_b - R_p`` [m]."""
        return self.bushing_radius - self.pin_radius

    @property
    def effective_modulus(self) -> float:
        """Plane-strain contact modulus ``E*`` [Pa]."""
        inv = (1 - self.bushing_poisson_ratio**2) / self.bushing_youngs_modulus
        inv += (1 - self.pin_poisson_ratio**2) / self.pin_youngs_modulus
        return 1.0 / inv

    def compliance(self, modes: ArrayLike) -> FloatArray:
        """Combined mode compliance ``C_k = U_k^{bushing} - U_k^{pin}`` [m/Pa].

        Parameters
        ----------
        modes : array_like of int
            Fourier orders ``k >= 0`` [-].
        """
        pin = disk_compliance(
            modes, self.pin_radius, self.pin_youngs_modulus, self.pin_poisson_ratio
        )
        if self.housing == "rigid":
            bushing = annulus_compliance(
                modes,
                self.bushing_radius,
                self.outer_radius,
                self.bushing_youngs_modulus,
                self.bushing_poisson_ratio,
            )
        else:
            bushing = hole_compliance(
                modes,
                self.bushing_radius,
                self.bushing_youngs_modulus,
                self.bushing_poisson_ratio,
                self.outer_radius,
            )
        return bushing - pin

    @property
    def asymptotic_compliance(self) -> tuple[float, float]:
        """``(C_inf, B)`` of ``C_k = (C_inf k + B)/(k^2 - 1)`` (infinite plate) [m/Pa]."""
        mu_b, kappa_b = _lame(self.bushing_youngs_modulus, self.bushing_poisson_ratio)
        mu_p, kappa_p = _lame(self.pin_youngs_modulus, self.pin_poisson_ratio)
        r_b, r_p = self.bushing_radius, self.pin_radius
        c_inf = r_b * (kappa_b + 1) / (4 * mu_b) + r_p * (kappa_p + 1) / (4 * mu_p)
        b = r_b * (kappa_b - 1) / (4 * mu_b) - r_p * (kappa_p - 1) / (4 * mu_p)
        return c_inf, b

    def kernel(self, points: int) -> FloatArray:
        """``g(m h) = sum_k C_k sinc^2(k h/2) cos(k m h)``, ``h = 2 pi / points``.

        ``cos(k m h)`` and ``cos(k h)`` depend on ``k mod points`` only, so the
        series is folded onto ``points`` residues and summed by one FFT. Modes up
        to ``K`` (a multiple of ``points``, past the housing's reach) are summed
        explicitly; beyond, ``C_k = (C_inf k + B)/(k^2 - 1)`` exactly and the
        folded tail is a sum of Hurwitz zeta functions.

        Parameters
        ----------
        points : int
            Nodes of the periodic grid over the whole circle [-].

        Returns
        -------
        ndarray, shape (points,)
            ``g(m h)`` for ``m = 0 .. points - 1`` [m/Pa].
        """
        key = ("kernel", points)
        if key in self._cache:
            return self._cache[key]
        h = 2.0 * np.pi / points
        explicit = _EXPLICIT_PERIODS * points
        if self.housing == "rigid":
            reach = math.log(self.outer_radius / self.bushing_radius)
            explicit = max(explicit, points * math.ceil((40.0 / reach + 2.0) / points))
        k = np.arange(1, explicit + 1)
        x = 0.5 * k * h
        smooth = (np.sin(x) / x) ** 2
        folded = np.bincount(k % points, weights=self.compliance(k) * smooth, minlength=points)
        # tail k = explicit + r + j points (j >= 0), residue r; r = 0 starts one period later
        c_inf, b = self.asymptotic_compliance
        r = np.arange(points)
        start = np.where(r == 0, explicit + points, explicit + r) / points
        tail = np.zeros(points)
        for power, coefficient in ((3, c_inf), (4, b), (5, c_inf), (6, b), (7, c_inf)):
            tail += coefficient * special.zeta(power, start) / float(points) ** power
        folded += 2.0 * (1.0 - np.cos(r * h)) / h**2 * tail
        self._cache.clear()  # one grid at a time
        self._cache[key] = np.fft.fft(folded).real
        return self._cache[key]

    # ------------------------------------------------------------ solution
    def hertz_half_angle(self, load_per_length: float) -> float:
        """Hertz half-angle ``a / R_b`` with ``R* = R_p R_b / c`` [rad] (inf at neat fit).

        Parameters
        ----------
        load_per_length : float
            ``P`` [N/m].
        """
        if self.clearance <= 0:
            return math.inf
        relative = self.pin_radius * self.bushing_radius / self.clearance
        a = math.sqrt(4 * load_per_length * relative / (math.pi * self.effective_modulus))
        return a / self.bushing_radius

    def solve(self, load_per_length: float, nodes: int = 160) -> ArcSolution:
        """Contact arc, pressure and approach for one load.

        Parameters
        ----------
        load_per_length : float
            Load per unit axial length ``P`` [N/m], >= 0.
        nodes : int
            Grid nodes across the half contact arc (accuracy ~ 1/nodes^2 in the
            pressure, ~1/nodes in the half-angle) [-].
        """
        if not (math.isfinite(load_per_length) and load_per_length >= 0):
            raise ContactError("load: must be finite and >= 0")
        nodes = max(int(nodes), 16)
        if load_per_length == 0:
            return ArcSolution(0.0, 0.0, self.clearance, 0.0, np.zeros(1), np.zeros(1), 0)
        guess = min(2.5 * self.hertz_half_angle(load_per_length), 0.62 * np.pi)
        extent = max(guess, 1e-4)
        solves = 0
        coarse = max(nodes // 3, 24)
        alpha = None
        for attempt in range(12):
            count = coarse if attempt == 0 else nodes
            arc, used, at_end = self._solve_grid(load_per_length, extent, count, alpha)
            solves += used
            if at_end:
                if extent >= np.pi * 0.999:
                    raise ContactError(
                        "persson: the contact arc reaches the back of the pin; the load is "
                        "outside the range of the small-strain solution"
                    )
                extent = min(2.0 * extent, np.pi)
                alpha = None
                continue
            alpha = arc.half_angle
            target = alpha * (1.0 + 8.0 / nodes)
            if attempt > 0 and abs(extent - target) <= 3.0 * extent / nodes:
                return ArcSolution(
                    arc.load_per_length,
                    arc.half_angle,
                    arc.eccentricity,
                    arc.approach,
                    arc.theta,
                    arc.pressure,
                    solves,
                )
            extent = min(target, np.pi)
        raise ConvergenceError("persson: the contact grid did not settle on the contact arc")

    def _solve_grid(
        self, load_per_length: float, extent: float, nodes: int, alpha: float | None = None
    ) -> tuple[ArcSolution, int, bool]:
        """Solve on a grid of about ``nodes`` nodes over ``[0, extent]`` [rad].

        Returns the arc, the linear solves used, and whether the contact reached the
        grid's end (the grid is too short). ``alpha`` [rad], the half-angle of a previous
        grid, starts the search for the contact set there.
        """
        grid = _CollocationGrid.build(self, extent, nodes)
        sets = _ContactSets(self, grid, load_per_length / self.bushing_radius)
        m = _largest_loaded_set(sets, grid, alpha)
        p, ecc = sets.solve(m)
        p_prev = float(p[m - 1]) if m >= 1 else None
        edge = edge_from_pressure(grid.theta[m], grid.theta[m] + grid.h, float(p[m]), p_prev)
        pressure = np.zeros(grid.theta.size)
        pressure[: m + 1] = np.maximum(p, 0.0)
        arc = ArcSolution(
            load_per_length, edge, ecc, ecc - self.clearance, grid.theta, pressure, sets.solves
        )
        return arc, sets.solves, m >= grid.last


@dataclass(frozen=True)
class _CollocationGrid:
    """The half arc's grid of hat functions and their collocation system.

    Attributes
    ----------
    h : float
        Grid spacing ``2 pi / points`` [rad].
    theta : ndarray, shape (n + 1,)
        Nodes ``0, h, ..., n h`` [rad].
    eps : ndarray, shape (n + 1,)
        1 for the centre hat, 2 for the mirrored pairs [-].
    compliance : ndarray, shape (n + 1, n + 1)
        Symmetric compliance ``S`` of the hat functions at the nodes [m/Pa]; the
        collocation matrix is ``S diag(eps)``.
    load_row : ndarray, shape (n + 1,)
        ``P / R_b = load_row . p`` [-].
    cholesky : ndarray or None
        Lower Cholesky factor of ``compliance``; its leading blocks factorise every
        contact set.
    """

    h: float
    theta: FloatArray
    eps: FloatArray
    compliance: FloatArray
    load_row: FloatArray
    cholesky: FloatArray | None

    @property
    def last(self) -> int:
        """Index of the last node that may carry pressure [-]."""
        return self.theta.size - 2

    @classmethod
    def build(cls, problem: PerssonProblem, extent: float, nodes: int) -> _CollocationGrid:
        """The grid of about ``nodes`` nodes over ``[0, extent]`` [rad] of ``problem``."""
        points = max(round(2.0 * np.pi * nodes / extent), 4 * nodes)
        h = 2.0 * np.pi / points
        n = int(min(math.floor(extent / h), points // 2 - 1))
        g = problem.kernel(points)
        c0 = float(problem.compliance([0])[0])
        theta = np.arange(n + 1) * h
        i = np.arange(n + 1)
        eps = np.where(i == 0, 1.0, 2.0)
        difference = np.abs(i[:, None] - i[None, :])
        total = (i[:, None] + i[None, :]) % points
        compliance = (c0 + g[difference] + g[total]) * (h / (2.0 * np.pi))
        sinc_h = (math.sin(h / 2) / (h / 2)) ** 2
        try:
            cholesky = linalg.cholesky(compliance, lower=True, check_finite=False)
        except linalg.LinAlgError:  # pragma: no cover - compliance is positive definite
            cholesky = None
        return cls(h, theta, eps, compliance, eps * h * sinc_h * np.cos(theta), cholesky)

    def inverse(self, size: int) -> Callable[[FloatArray], FloatArray]:
        """``v -> compliance[:size, :size]^-1 v`` (the contact set of nodes ``0..size-1``)."""
        if self.cholesky is None:  # pragma: no cover - compliance is positive definite
            factor = linalg.lu_factor(self.compliance[:size, :size], check_finite=False)
            return lambda v: linalg.lu_solve(factor, v, check_finite=False)
        block = self.cholesky[:size, :size]

        def inverse(v: FloatArray) -> FloatArray:
            y = linalg.solve_triangular(block, v, lower=True, check_finite=False)
            return linalg.solve_triangular(block.T, y, lower=False, check_finite=False)

        return inverse


class _ContactSets:
    """Pressures and pin displacement with the contact on nodes ``0..m`` (cached per ``m``).

    Parameters
    ----------
    problem : PerssonProblem
        Geometry, materials and gap.
    grid : _CollocationGrid
        The grid.
    target : float
        ``P / R_b`` [Pa].
    """

    def __init__(self, problem: PerssonProblem, grid: _CollocationGrid, target: float) -> None:
        self.problem = problem
        self.grid = grid
        self.target = target
        self.solves = 0
        self._sin2 = np.sin(grid.theta) ** 2
        self._cos = np.cos(grid.theta)
        self._results: dict[int, tuple[FloatArray, float]] = {}

    def loaded(self, m: int) -> bool:
        """The edge node ``m`` carries pressure when nodes ``0..m`` are in contact."""
        return bool(self.solve(m)[0][-1] > 0)

    def solve(self, m: int) -> tuple[FloatArray, float]:
        """Pressures on nodes ``0..m`` [Pa] and the pin displacement ``e`` [m].

        The pressure is linear in ``e`` (``p = base + e per_e``) and ``e`` follows from
        the load; with the exact gap, whose right-hand side depends on ``e``, by fixed
        point iteration.
        """
        if m in self._results:
            return self._results[m]
        size = m + 1
        grid, problem = self.grid, self.problem
        clearance, r_p = problem.clearance, problem.pin_radius
        inverse = grid.inverse(size)
        per_e = inverse(self._cos[:size])
        weights = grid.load_row[:size] / grid.eps[:size]
        ecc = clearance
        for _ in range(50):
            rhs = np.full(size, -clearance)
            if problem.gap == "exact":
                lateral = ecc**2 * self._sin2[:size]
                rhs -= lateral / (r_p + np.sqrt(np.maximum(r_p**2 - lateral, 0.0)))
            base = inverse(rhs)
            new = (self.target - weights @ base) / (weights @ per_e)
            if problem.gap == "linear" or abs(new - ecc) <= 1e-14 * abs(new):
                break
            ecc = new
        self.solves += 1
        self._results[m] = ((base + new * per_e) / grid.eps[:size], float(new))
        return self._results[m]


def _largest_loaded_set(sets: _ContactSets, grid: _CollocationGrid, alpha: float | None) -> int:
    """The contact set: the largest ``m`` whose edge node still carries pressure.

    Searched from a previous half-angle ``alpha`` [rad] node by node, or by bisection
    over the whole grid.
    """
    last = grid.last
    if alpha is not None:
        m = int(min(max(math.floor(alpha / grid.h), 0), last))
        if sets.loaded(m):
            while m + 1 <= last and sets.loaded(m + 1):
                m += 1
        else:
            while m > 0 and not sets.loaded(m):
                m -= 1
        return m
    lo, hi = 0, last
    if sets.loaded(hi):
        return hi
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if sets.loaded(mid):
            lo = mid
        else:
            hi = mid
    return lo


# ---------------------------------------------------------------- closed form, B = 0


def _similar_shapes(theta: FloatArray, alpha: float) -> tuple[FloatArray, FloatArray]:
    s_a = math.sin(alpha / 2) ** 2
    half = np.cos(np.asarray(theta) / 2)
    root = np.sqrt(np.clip(s_a - np.sin(np.asarray(theta) / 2) ** 2, 0.0, None))
    shape_a = 2.0 * np.arctanh(np.clip(root / half, 0.0, 1.0 - 1e-16))
    shape_s = 2.0 * half * root
    return shape_a, shape_s


def _similar_moments(alpha: float) -> tuple[float, float, float, float]:
    def moment(func):
        value, _ = integrate.quad(func, 0.0, alpha, limit=200, epsabs=0.0, epsrel=1e-12)
        return 2.0 * value

    m_a0 = moment(lambda t: _similar_shapes(np.array(t), alpha)[0])
    m_a1 = moment(lambda t: _similar_shapes(np.array(t), alpha)[0] * math.cos(t))
    m_s0 = moment(lambda t: _similar_shapes(np.array(t), alpha)[1])
    m_s1 = moment(lambda t: _similar_shapes(np.array(t), alpha)[1] * math.cos(t))
    return m_a0, m_a1, m_s0, m_s1


def similar_solution(
    half_angle: float, clearance: float, radius: float, c0: float, c_inf: float
) -> tuple[float, Any]:
    """Closed-form Persson solution when ``C_k = C_inf k / (k^2 - 1)`` for ``k >= 2``.

    That is Dundurs ``beta = 0`` with equal radii (e.g. identical materials, or a
    rigid pin in an incompressible plate). Linear gap ``e cos(theta) - c``.

    Parameters
    ----------
    half_angle : float
        Contact half-angle ``alpha`` [rad], ``0 < alpha < pi``.
    clearance : float
        Radial clearance ``c`` [m].
    radius : float
        Bushing radius ``R_b`` [m] (load = ``pi R_b p_1``).
    c0 : float
        Compliance of the uniform mode ``C_0`` [m/Pa].
    c_inf : float
        Asymptotic compliance ``C_inf = lim k C_k`` [m/Pa].

    Returns
    -------
    load_per_length : float
        ``P`` [N/m] that produces ``alpha``.
    pressure : callable
        ``pressure(theta)`` [rad -> Pa].
    """
    m_a0, m_a1, m_s0, m_s1 = _similar_moments(half_angle)
    ratio = m_a1 / (np.pi - m_s1)  # p_1 / A
    denominator = c_inf - c0 * (m_a0 + ratio * m_s0) / (2.0 * np.pi)
    a_coef = clearance / denominator
    p1 = ratio * a_coef

    def pressure(theta: ArrayLike) -> FloatArray:
        t = np.abs(wrap_angle(theta))
        shape_a, shape_s = _similar_shapes(np.minimum(t, half_angle), half_angle)
        return np.where(t < half_angle, a_coef * shape_a + p1 * shape_s, 0.0)

    return float(np.pi * radius * p1), pressure


def similar_neat_fit_angle(c0_over_c_inf: float) -> float:
    """Load-independent contact half-angle at zero clearance for ``B = 0`` [rad].

    Root of ``C_inf - C_0 (m_A0 + m_A1 m_S0 / (pi - m_S1)) / (2 pi) = 0``, the
    condition for a non-trivial solution of the homogeneous (``c = 0``) problem.

    Parameters
    ----------
    c0_over_c_inf : float
        ``C_0 / C_inf`` [-] (1/2 for identical materials, 1 for a rigid pin in an
        incompressible plate).
    """

    def residual(alpha: float) -> float:
        m_a0, m_a1, m_s0, m_s1 = _similar_moments(alpha)
        return 1.0 - c0_over_c_inf * (m_a0 + m_a1 * m_s0 / (np.pi - m_s1)) / (2.0 * np.pi)

    return float(optimize.brentq(residual, 0.3, 0.999 * np.pi, xtol=1e-12))


# ---------------------------------------------------------------- the contact model


@dataclass
class PerssonModel:
    """Persson's exact solution as a jointwear contact model (registry name ``persson``).

    Valid on circular contours only (the solution is built on circles).

    Parameters
    ----------
    parameters : ContactParameters
        Geometry and materials; ``bushing_thickness`` sets the housing radius.
    housing : {"infinite", "rigid"}
        Classical infinite plate (default) or the bushing in a rigid housing.
    gap : {"exact", "linear"}
        Gap along the node rays (default, like the spring models) or Persson's.
    rigid_pin : bool
        Ignore the pin's compliance.
    nodes : int
        Grid nodes across the half contact arc [-].
    """

    parameters: ContactParameters
    housing: str = "infinite"
    gap: str = "exact"
    rigid_pin: bool = False
    nodes: int = 160
    name: str = "persson"
    _solved: dict = field(default_factory=dict, repr=False)

    def problem(self, contour: BushingContour, pin: Pin) -> PerssonProblem:
        """The :class:`PerssonProblem` of a circular contour and pin.

        Parameters
        ----------
        contour : BushingContour
            Circular bushing contour.
        pin : Pin
            The pin.
        """
        contour.check_pin(pin)
        radius = contour.radius
        if np.ptp(radius) > 1e-9 * radius.mean():
            raise ContactError(
                "persson: the exact solution needs a circular bushing; this contour is worn "
                f"(radius varies by {np.ptp(radius) * 1e6:.3g} um) - use contact model 'fem'"
            )
        return PerssonProblem.from_parameters(
            self.parameters,
            housing=self.housing,
            gap=self.gap,
            rigid_pin=self.rigid_pin,
            bushing_radius=float(radius.mean()),
            pin_radius=pin.radius,
        )

    def solve(
        self,
        contour: BushingContour,
        pin: Pin,
        load: ArrayLike,
        azimuth: ArrayLike,
        nodes: int | None = None,
        **_: object,
    ) -> ContactSolution:
        """Pressure on the contour nodes for many loads.

        Parameters
        ----------
        contour : BushingContour
            Circular bushing contour (a worn one raises :class:`ContactError`).
        pin : Pin
            The pin.
        load : array_like, shape (M,)
            Load magnitudes [N].
        azimuth : array_like, shape (M,)
            Load directions in the bushing frame [rad].
        nodes : int, optional
            Grid nodes across the half contact arc [-].
        **_
            Options of the spring models (``balance``, ``tolerance`` ...) are ignored:
            the solution is symmetric and balanced exactly.
        """
        load, azimuth = check_loads(load, azimuth)
        problem = self.problem(contour, pin)
        count = self.nodes if nodes is None else int(nodes)
        b = contour.axial_length
        key_base = (problem, count)
        states = []
        for force, psi in zip(load, azimuth, strict=True):
            key = (key_base, float(force))
            if key not in self._solved:
                if len(self._solved) > 4096:
                    self._solved.clear()
                self._solved[key] = problem.solve(force / b, count)
            arc = self._solved[key]
            states.append(
                ReferenceState(
                    pressure=lambda theta, arc=arc, psi=psi: arc.pressure_at(theta - psi),
                    eccentricity=arc.eccentricity * np.array([math.cos(psi), math.sin(psi)]),
                    penetration=arc.approach,
                    normal_force=float(force),
                    tangential_force=0.0,
                    half_angle_left=arc.half_angle,
                    half_angle_right=arc.half_angle,
                    iterations=arc.iterations,
                )
            )
        return assemble_solution(contour, azimuth, states, self.name)


def model(parameters: ContactParameters) -> PerssonModel:
    """Registry factory of the ``persson`` contact model (infinite plate, exact gap)."""
    return PerssonModel(parameters)
