"""A lubricated contact solve: film and asperities share each step's load.

At every step ``k`` of a load cycle the pin is taken in the steady equilibrium of
:func:`jointwear.lubrication.mixed.steady_load_sharing` under the step's load ``W_k``:

.. math::

    \\big(F_r^{film}(\\varepsilon) + F^{asp}(\\varepsilon)\\big)^2
    + F_t^{film}(\\varepsilon)^2 = W_k^2,
    \\qquad \\bar\\omega_k = \\dot\\varphi_{rel,k} - 2\\dot\\phi_{load,k},

with the wedge speed ``omega_bar`` from the step's relative rotation rate
``relative_rotation / dt`` and the turning rate of the load's direction (Pinkus &
Sternlicht 1961; Flores et al., Mech. Mach. Theory 41 (2006) 247-261). **Quasi-static**:
each step is a steady state; the squeeze film (``d eps / dt``) is left out, so a load
that rises fast is carried at the steady eccentricity, not the lower one the squeeze
would keep. The film geometry is the unworn, rigid bushing's.

The wear law sees only the asperity pressure (Greenwood & Tripp, Proc. IMechE 185
(1970) 625-633) at the contour's nodes. Where the asperities cannot carry the load
even at ``h_min -> 0`` (``bulk_contact``), the bulk deforms: those steps are solved
with the dry contact model (``dry_fallback`` in :class:`FilmRecord`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from jointwear.geometry.angles import wrap_angle
from jointwear.lubrication.asperity import composite_modulus
from jointwear.lubrication.lubricants import dynamic_viscosity
from jointwear.lubrication.mixed import LoadSharing, steady_load_sharing

if TYPE_CHECKING:
    from jointwear.config import LubricationConfig
    from jointwear.contact.laws import ContactParameters
    from jointwear.mechanism.cycle import LoadCycle

__all__ = ["FILM_MODEL_OF", "FilmRecord", "LubricatedContact", "film_speeds"]

FloatArray = NDArray[np.float64]

#: ``lubrication.model`` -> the film model of :mod:`jointwear.lubrication.mobility`
FILM_MODEL_OF = {"short-bearing": "short", "long-bearing": "long", "finite-length": "finite"}


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
        Share of the load the asperities carry [-]; 1 where the dry contact carried it
        (``dry_fallback``), 0 at a step without load.
    dry_fallback : ndarray of bool, shape (M,)
        The asperities could not carry the load: the step was solved dry.
    """

    min_film_thickness: FloatArray
    film_parameter: FloatArray
    asperity_load_fraction: FloatArray
    dry_fallback: NDArray[np.bool_]


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


class LubricatedContact:
    """The film and asperity load sharing of a run's joint.

    Parameters
    ----------
    section : LubricationConfig
        ``[lubrication]``, a film model chosen.
    parameters : ContactParameters
        Geometry and materials of the joint.
    """

    def __init__(self, section: LubricationConfig, parameters: ContactParameters) -> None:
        self.model = FILM_MODEL_OF[section.model]
        if section.viscosity is not None:
            self.viscosity = float(section.viscosity)
        else:
            self.viscosity = float(dynamic_viscosity(section.lubricant, section.oil_temperature))
        self.roughness = section.roughness
        self.asperity = {
            "eta_beta_sigma": section.eta_beta_sigma,
            "sigma_over_beta": section.sigma_over_beta,
        }
        self.parameters = parameters
        self.modulus = float(
            composite_modulus(
                parameters.pin_youngs_modulus,
                parameters.pin_poisson_ratio,
                parameters.bushing_youngs_modulus,
                parameters.bushing_poisson_ratio,
            )
        )
        #: the cycle, node count and sharing last solved (one per load cycle)
        self._kept: tuple[Any, int, LoadSharing] | None = None

    def sharing(self, cycle: LoadCycle, nodes: int) -> LoadSharing:
        """The load sharing at every step, the asperity pressure at ``nodes`` angles.

        A step without load is solved under a vanishing one (its pressure is zeroed
        by :meth:`asperity_pressure`).

        Parameters
        ----------
        cycle : LoadCycle
            The load cycle.
        nodes : int
            Nodes of the bushing contour, at ``2 pi j / nodes`` [-].
        """
        kept = self._kept
        if kept is not None and kept[0] is cycle and kept[1] == nodes:
            return kept[2]
        joint = self.parameters
        pin_speed, load_speed = film_speeds(cycle)
        load = np.maximum(cycle.load, np.finfo(float).tiny ** 0.5)
        sharing = steady_load_sharing(
            load,
            joint.pin_radius,
            joint.axial_length,
            joint.bushing_radius - joint.pin_radius,
            self.viscosity,
            pin_speed,
            self.roughness,
            self.modulus,
            load_speed=load_speed,
            model=self.model,
            load_direction=cycle.azimuth,
            bushing_angles=2.0 * np.pi * np.arange(nodes) / nodes,
            **self.asperity,
        )
        self._kept = (cycle, nodes, sharing)
        return sharing

    def record(self, cycle: LoadCycle, nodes: int) -> FilmRecord:
        """The per-step :class:`FilmRecord` of ``cycle``."""
        sharing = self.sharing(cycle, nodes)
        fallback = np.asarray(sharing.bulk_contact, bool)
        fraction = np.where(cycle.load > 0.0, sharing.asperity_load_fraction, 0.0)
        return FilmRecord(
            min_film_thickness=np.asarray(sharing.min_film_thickness, float),
            film_parameter=np.asarray(sharing.film_parameter, float),
            asperity_load_fraction=np.where(fallback, 1.0, fraction),
            dry_fallback=fallback,
        )

    def asperity_pressure(self, cycle: LoadCycle, nodes: int) -> FloatArray:
        """The asperity pressure at every node and step, zero without load [Pa], (M, N)."""
        pressure = self.sharing(cycle, nodes).asperity_pressure
        return np.where((cycle.load > 0.0)[:, None], pressure, 0.0)

    def centre(self, cycle: LoadCycle, nodes: int) -> FloatArray:
        """The pin centre's offset from the bushing centre at every step [m], (M, 2)."""
        sharing = self.sharing(cycle, nodes)
        clearance = self.parameters.bushing_radius - self.parameters.pin_radius
        offset = sharing.eccentricity_ratio * clearance
        direction = cycle.azimuth + sharing.attitude_angle
        return np.column_stack([offset * np.cos(direction), offset * np.sin(direction)])
