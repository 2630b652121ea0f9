"""A lubricated contact solve: film, asperities and bulk share each step's load.

The pin's centre follows the periodic orbit of Booker's mobility method over the load
cycle (:func:`jointwear.lubrication.orbit.periodic_orbit`): the film carries the load
by wedge and squeeze action, and Greenwood--Tripp's asperities (Proc. IMechE 185
(1970) 625-633) carry their share where the film is thin. The film's wedge speed comes
from the step's relative rotation rate ``relative_rotation / dt`` in the bushing's
frame, where the load's direction turns with the cycle's azimuth (Pinkus & Sternlicht
1961; Flores et al., Mech. Mach. Theory 41 (2006) 247-261). The film geometry is the
unworn, rigid bushing's.

At step ``k`` with the centre at ``eps_k`` along ``phi_k`` the asperities carry the
share ``s_k = -F_a(eps_k) cos(phi_k - azimuth_k) / W_k`` of the load. Where the film is
thinner than the roughness the rigid-bulk model leaves its range (the asperities are
flattened and the bulk deforms): the film's share passes smoothly to the bulk contact,

.. math::

    b_k = w(\\lambda_k)\\,(1 - s_k), \\qquad
    w(\\lambda) = 1 - 3x^2 + 2x^3,\\; x = \\min(\\lambda, 1),

none of it at ``lambda >= 1`` and all of it at ``lambda = 0``; the bulk share is solved
with the dry contact model under the load ``b_k W_k``. The wear law sees the solid
contact's pressure only: the asperity pressure at the nodes plus the bulk's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray
from scipy.optimize import brentq

from jointwear.geometry.angles import wrap_angle
from jointwear.lubrication.asperity import FIT_OMEGA, asperity_pressure, composite_modulus
from jointwear.lubrication.lubricants import section_viscosity
from jointwear.lubrication.orbit import Orbit, OrbitSolver, periodic_orbit

if TYPE_CHECKING:
    from jointwear.config import LubricationConfig
    from jointwear.contact.laws import ContactParameters
    from jointwear.mechanism.cycle import LoadCycle

__all__ = [
    "FILM_MODEL_OF",
    "FilmRecord",
    "LubricatedContact",
    "bulk_weight",
    "film_speeds",
    "reach_columns",
]

FloatArray = NDArray[np.float64]

#: ``lubrication.model`` -> the film model of :mod:`jointwear.lubrication.mobility`
FILM_MODEL_OF = {"short-bearing": "short", "long-bearing": "long", "finite-length": "finite"}
#: the orbit's first guess lies no closer to the wall than this eccentricity ratio
FIRST_GUESS_LIMIT = 0.9
#: the steady equilibrium of the first guess is sought up to this eccentricity ratio
STEADY_LIMIT = 1.0 - 1e-9


@dataclass(frozen=True)
class FilmRecord:
    """The lubrication state of every step of a load cycle.

    Attributes
    ----------
    min_film_thickness : ndarray, shape (M,)
        ``h_min = c (1 - eps)`` [m].
    film_parameter : ndarray, shape (M,)
        ``lambda = h_min / sigma`` [-].
    asperity_load_fraction : ndarray, shape (M,)
        Share of the load the solid contact carries (asperities and bulk) [-]; 0 at
        a step without load.
    bulk_load_fraction : ndarray, shape (M,)
        The part of it the bulk (the dry contact model) carries [-].
    eccentricity_x, eccentricity_y : ndarray, shape (M,)
        The orbit: the pin centre's offset over the clearance, in the bushing's
        frame [-].
    """

    min_film_thickness: FloatArray
    film_parameter: FloatArray
    asperity_load_fraction: FloatArray
    bulk_load_fraction: FloatArray
    eccentricity_x: FloatArray
    eccentricity_y: FloatArray


def film_speeds(cycle: LoadCycle) -> tuple[FloatArray, FloatArray]:
    """The relative rotation rate and the load direction's turning rate of each step [rad/s].

    Rates over each step ``[t_k, t_{k+1})`` (the last to ``period``); the load's turn
    from the last step to the first is the cycle's wrap-around.

    Parameters
    ----------
    cycle : LoadCycle
        The load cycle.
    """
    duration = np.diff(np.append(cycle.time, cycle.period))
    turn = wrap_angle(np.diff(np.append(cycle.azimuth, cycle.azimuth[0])))
    return cycle.relative_rotation / duration, turn / duration


def bulk_weight(film_parameter: FloatArray) -> FloatArray:
    """``w(lambda)``: the share of the film's load that passes to the bulk [-].

    ``1 - 3x^2 + 2x^3`` with ``x = min(lambda, 1)``: 1 at ``lambda = 0``, 0 from
    ``lambda = 1`` on (where the film is thicker than the roughness), smooth between.

    Parameters
    ----------
    film_parameter : ndarray
        ``lambda = h_min / sigma`` [-].
    """
    x = np.clip(np.asarray(film_parameter, float), 0.0, 1.0)
    return 1.0 - 3.0 * x * x + 2.0 * x**3


def reach_columns(
    eccentricity_x: FloatArray, eccentricity_y: FloatArray, nodes: int, reach: float
) -> NDArray[np.intp]:
    """The nodes of each step that the asperities may reach, (M, W) indices.

    The film ``c (1 - eps cos(theta - phi))`` is thinner than ``reach c`` on the arc
    ``|theta - phi| < arccos((1 - reach) / eps)`` around the line of centres; the
    nodes of that arc and two more on each side (round-off), or all nodes where the
    arc is most of the circle.

    Parameters
    ----------
    eccentricity_x, eccentricity_y : ndarray, shape (M,)
        The orbit, ``e / c`` [-].
    nodes : int
        Nodes around the bushing, the first at ``theta = 0`` [-].
    reach : float
        The asperities' reach over the clearance [-].
    """
    eps = np.hypot(eccentricity_x, eccentricity_y)
    ratio = np.divide(1.0 - reach, eps, out=np.full_like(eps, 2.0), where=eps > 0.0)
    spacing = 2.0 * np.pi / nodes
    width = int(np.ceil(np.arccos(np.clip(ratio, -1.0, 1.0)).max() / spacing)) + 2
    if 2 * width + 1 >= nodes:
        return np.broadcast_to(np.arange(nodes), (eps.size, nodes))
    centre = np.rint(np.arctan2(eccentricity_y, eccentricity_x) / spacing).astype(np.intp)
    return (centre[:, None] + np.arange(-width, width + 1)) % nodes


class LubricatedContact:
    """The film, asperity and bulk load sharing of a run's joint.

    Parameters
    ----------
    section : LubricationConfig
        ``[lubrication]``, a film model chosen.
    parameters : ContactParameters
        Geometry and materials of the joint.
    """

    def __init__(self, section: LubricationConfig, parameters: ContactParameters) -> None:
        self.model = FILM_MODEL_OF[section.model]
        if section.cavitation == "Reynolds":  # the finite length's (the configuration checks)
            self.model = "finite-reynolds"
        self.viscosity = section_viscosity(section)
        self.roughness = section.roughness
        self.asperity = {
            "eta_beta_sigma": section.eta_beta_sigma,
            "sigma_over_beta": section.sigma_over_beta,
        }
        self.parameters = parameters
        self.clearance = parameters.bushing_radius - parameters.pin_radius
        self.modulus = float(
            composite_modulus(
                parameters.pin_youngs_modulus,
                parameters.pin_poisson_ratio,
                parameters.bushing_youngs_modulus,
                parameters.bushing_poisson_ratio,
            )
        )
        self.solver = OrbitSolver(
            parameters.pin_radius,
            parameters.axial_length,
            self.clearance,
            self.viscosity,
            self.roughness,
            self.modulus,
            self.model,
            **self.asperity,
        )
        #: the cycle and its orbit last solved (one per load cycle)
        self._kept: tuple[Any, Orbit, FilmRecord] | None = None
        #: the cycle, the node count and the asperity pressure along its orbit last found
        #: (the flat indices of the nodes and steps it is not nil at, and its values)
        self._pressure: tuple[Any, int, NDArray[np.intp], FloatArray] | None = None

    def first_guess(self, cycle: LoadCycle) -> FloatArray:
        """The film's steady equilibrium under the first step's load, at most 0.9 off
        centre [-].

        A steady pin (no squeeze, ``beta = 0`` or ``pi``) whose centre follows the load
        at ``omega_load`` moves at ``eps |omega_mean - omega_load|`` in the frame of
        Booker's mobility method, which the load drives at ``k |M|`` (module
        :mod:`jointwear.lubrication.orbit`):

        .. math::

            \\varepsilon\\,|\\omega_{mean} - \\omega_{load}| = \\frac{W (c/R)^2}{\\mu L D}
            \\frac{L/D}{3\\,|G(\\varepsilon, \\beta)|},

        solved for ``eps`` with :func:`scipy.optimize.brentq` from the film model's own
        force factor ``G``; the attitude puts the film's force against the load. The
        asperities are left out (they act only closer to the wall than the guess goes).
        Only a start: the orbit is iterated to its periodic state from here.
        """
        solver = self.solver
        pin_speed, load_speed = film_speeds(cycle)
        relative = 0.5 * float(pin_speed[0]) - float(load_speed[0])
        load = float(cycle.load[0])
        if load <= 0.0 or relative == 0.0:
            return np.zeros(2)
        beta = 0.0 if relative > 0.0 else math.pi
        scalar_shape = solver.steady_shape()

        def excess_speed(eps: float) -> float:
            shape = scalar_shape(eps, beta)
            rate = load * solver.mobility_scale * solver.ratio / (3.0 * math.hypot(*shape))
            return eps * abs(relative) - rate

        eps = STEADY_LIMIT
        if excess_speed(STEADY_LIMIT) > 0.0:
            eps = brentq(excess_speed, 1e-6, STEADY_LIMIT, xtol=1e-12)
        shape = scalar_shape(eps, beta)
        angle = float(cycle.azimuth[0]) + math.pi - math.atan2(shape[1], shape[0])
        eps = min(eps, FIRST_GUESS_LIMIT)
        return np.array([eps * math.cos(angle), eps * math.sin(angle)])

    def orbit(self, cycle: LoadCycle) -> tuple[Orbit, FilmRecord]:
        """The periodic orbit of ``cycle`` and the :class:`FilmRecord` of its steps."""
        kept = self._kept
        if kept is not None and kept[0] is cycle:
            return kept[1], kept[2]
        rate, _ = film_speeds(cycle)
        # rates hold over steps; at a step's start the mean of the two steps it joins
        mean_speed = 0.25 * (rate + np.roll(rate, 1))
        orbit = periodic_orbit(
            self.solver,
            cycle.time,
            cycle.period,
            cycle.load * np.cos(cycle.azimuth),
            cycle.load * np.sin(cycle.azimuth),
            mean_speed,
            self.first_guess(cycle),
        )
        record = self.film_record(cycle, orbit)
        self._kept = (cycle, orbit, record)
        return orbit, record

    def film_record(self, cycle: LoadCycle, orbit: Orbit) -> FilmRecord:
        """The shares of film, asperities and bulk along ``orbit``."""
        h_min = self.clearance * (1.0 - orbit.eccentricity_ratio)
        lam = h_min / self.roughness
        phi = np.arctan2(orbit.eccentricity_y, orbit.eccentricity_x)
        loaded = cycle.load > 0.0
        along = -orbit.asperity_force * np.cos(phi - cycle.azimuth)
        share = np.clip(np.divide(along, cycle.load, out=np.zeros_like(along), where=loaded), 0, 1)
        bulk = np.where(loaded, bulk_weight(lam) * (1.0 - share), 0.0)
        return FilmRecord(
            min_film_thickness=h_min,
            film_parameter=lam,
            asperity_load_fraction=np.where(loaded, share + bulk, 0.0),
            bulk_load_fraction=bulk,
            eccentricity_x=orbit.eccentricity_x,
            eccentricity_y=orbit.eccentricity_y,
        )

    def record(self, cycle: LoadCycle) -> FilmRecord:
        """The per-step :class:`FilmRecord` of ``cycle``."""
        return self.orbit(cycle)[1]

    def asperity_pressure(self, cycle: LoadCycle, nodes: int) -> FloatArray:
        """The asperity pressure at every node and step along the orbit, (M, N) [Pa].

        A new array each call; the pressure along the orbit of one load cycle is
        computed once (the film's geometry is the unworn bushing's: it does not change
        as the contour wears).
        """
        kept = self._pressure
        if kept is None or kept[0] is not cycle or kept[1] != nodes:
            kept = (cycle, nodes, *self._touched(cycle, nodes))
            self._pressure = kept
        pressure = np.zeros((cycle.steps, nodes))
        pressure.reshape(-1)[kept[2]] = kept[3]
        return pressure

    def _touched(self, cycle: LoadCycle, nodes: int) -> tuple[NDArray[np.intp], FloatArray]:
        """The flat indices of the (step, node) pairs the asperities touch and their
        pressure [Pa]."""
        orbit, _ = self.orbit(cycle)
        angles = 2.0 * np.pi * np.arange(nodes) / nodes
        # the pressure only at the nodes the asperities reach, a few per cent along an
        # orbit: candidates around each step's line of centres, then the same test and
        # the same values as on the whole grid
        columns = reach_columns(
            orbit.eccentricity_x,
            orbit.eccentricity_y,
            nodes,
            FIT_OMEGA * self.roughness / self.clearance,
        )
        offset = orbit.eccentricity_x[:, None] * np.cos(angles)[columns]
        offset += orbit.eccentricity_y[:, None] * np.sin(angles)[columns]
        film = self.clearance * (1.0 - offset)
        within = film / self.roughness < FIT_OMEGA
        within &= (cycle.load > 0.0)[:, None]
        flat = (columns + nodes * np.arange(columns.shape[0])[:, None])[within]
        return flat, asperity_pressure(film[within], self.roughness, self.modulus, **self.asperity)

    def centre(self, cycle: LoadCycle) -> FloatArray:
        """The pin centre's offset from the bushing centre at every step [m], (M, 2)."""
        orbit, _ = self.orbit(cycle)
        return self.clearance * np.column_stack([orbit.eccentricity_x, orbit.eccentricity_y])
