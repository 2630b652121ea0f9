"""The contact solves of a run along the pin: every step through the axial balance.

With ``joint.axial_slices = N > 1`` (docs/along-the-pin.md) the run's contact solve is
one :func:`jointwear.contact.axial.solve_axial` per step of the load cycle: every slice
on its own worn contour, the slices sharing the pin's offset and tilt (free, from the
moment balance, or imposed by ``joint.misalignment``), the load's line of action at
``joint.load_offset``, and with ``pin.model = "beam"`` the pin's bending in its clevis
or cantilever (:func:`jointwear.contact.pin_beam.compliance`). :func:`solver_of` is the
factory the loop calls: the planar :class:`~jointwear.contact.solver.ContactSolver` for
one slice (today's joint, bit for bit), a :class:`SlicedSolver` otherwise.

A :class:`SlicedSolution` is the planar view of the revolution (the pressure averaged
over the length, the pin centre at the mid-plane, the widest contact of any slice), so
the loop's records, warnings and pressure snapshots read it as a planar solve, and it
carries each slice's pressure, from which :meth:`SlicedSolver.wear_per_revolution`
applies the run's wear law slice by slice: a wear map of shape ``(N, nodes)``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from jointwear.contact.axial import (
    AxialSlices,
    AxialSolution,
    Misalignment,
    solve_axial,
    spring_law_of,
)
from jointwear.contact.pin_beam import Cantilever, Clevis, PinBeam, compliance
from jointwear.contact.solution import ContactSolution
from jointwear.contact.solver import ContactSolver, WarmStart
from jointwear.errors import ConfigError
from jointwear.geometry.angles import wrap_angle
from jointwear.geometry.slices import SlicedContour

if TYPE_CHECKING:
    from collections.abc import Callable

    from jointwear.config import Config
    from jointwear.mechanism.cycle import LoadCycle

__all__ = ["SlicedSolution", "SlicedSolver", "solver_of"]

FloatArray = NDArray[np.float64]


def solver_of(
    config: Config, model: str | Callable[..., Any] | Any, *, fused_archard: bool
) -> ContactSolver | SlicedSolver:
    """The contact solver of a run: planar for one slice, along the pin for several.

    Parameters
    ----------
    config : Config
        The run's configuration.
    model : str, SpringLaw or callable
        Contact model name, a law or ``pressure(penetration)`` [m -> Pa].
    fused_archard : bool
        The run's wear law is Archard's (the planar solver's fused kernel).
    """
    planar = ContactSolver.from_config(config, model, fused_archard=fused_archard)
    if config.joint.axial_slices == 1:
        return planar
    return SlicedSolver.from_config(config, planar)


@dataclass(frozen=True, eq=False)
class SlicedSolution(ContactSolution):
    """A revolution's contact on the slices, read as a planar solve.

    The planar fields are the joint's: ``pressure`` the slices' pressure averaged over
    the length [Pa], ``eccentricity`` the pin centre at the mid-plane [m],
    ``penetration`` the deepest of any slice [m], ``normal_force`` the slices' total
    along the load [N], the half-angles the widest contact of any slice [rad].

    Attributes
    ----------
    slice_pressure : ndarray, shape (N, M, nodes)
        Pressure on every node of every slice at every step [Pa].
    slice_force : ndarray, shape (M, N)
        Resultant of each slice along the load [N].
    centre_offset : ndarray, shape (M,)
        Pin centre along the load at the mid-plane ``delta_0`` [m].
    tilt : ndarray, shape (M,)
        Pin tilt in the load plane ``gamma`` [rad].
    """

    slice_pressure: FloatArray = None  # type: ignore[assignment]
    slice_force: FloatArray = None  # type: ignore[assignment]
    centre_offset: FloatArray = None  # type: ignore[assignment]
    tilt: FloatArray = None  # type: ignore[assignment]


class SlicedSolver:
    """The contact solves of a run along the pin (one axial balance per step).

    Parameters
    ----------
    planar : ContactSolver
        The run's planar solver: its law, pin, parameters and force tolerance.
    slices : AxialSlices
        The slices of the bushing.
    misalignment : float
        Imposed tilt of the pin against the bushing [rad] (0 with a free tilt).
    misalignment_plane : float or None
        Azimuth of the tilt's plane in the bushing frame [rad]; ``None``: the plane of
        the load at every step.
    load_offset : float
        Axial position of the load's line of action [m].
    matrix : ndarray, shape (N, N), optional
        The pin's compliance at the slice centres [m/N] (``None``: a rigid pin).
    play : float
        Tilt the supports allow about the imposed one [rad].
    """

    def __init__(
        self,
        planar: ContactSolver,
        slices: AxialSlices,
        *,
        misalignment: float = 0.0,
        misalignment_plane: float | None = None,
        load_offset: float = 0.0,
        matrix: FloatArray | None = None,
        play: float = 0.0,
    ) -> None:
        self.planar = planar
        self.law, self.pin, self.parameters = planar.law, planar.pin, planar.parameters
        self.slice_law = spring_law_of(planar.law)
        self.slices = slices
        self.misalignment, self.misalignment_plane = misalignment, misalignment_plane
        self.load_offset, self.matrix, self.play = load_offset, matrix, play

    @classmethod
    def from_config(cls, config: Config, planar: ContactSolver) -> SlicedSolver:
        """The sliced solver of ``config`` (``[joint]`` along-the-pin keys and ``[pin]``)."""
        joint, pin = config.joint, config.pin
        slices = AxialSlices(joint.axial_length, joint.axial_slices)
        matrix, play = None, 0.0
        if pin.model == "beam":
            material = config.materials.pin
            beam = PinBeam.solid(
                joint.pin_radius, material.youngs_modulus, material.poisson_ratio, pin.beam_theory
            )
            support = Clevis(pin.forks, pin.fit_clearance) if pin.support == "clevis" else None
            support = support or Cantilever(pin.clamp)
            matrix, play = compliance(beam, support, slices.centres), support.tilt_play
        return cls(
            planar,
            slices,
            misalignment=joint.misalignment,
            misalignment_plane=joint.misalignment_angle,
            load_offset=joint.load_offset,
            matrix=matrix,
            play=play,
        )

    # ---------------------------------------------------------------- contours
    @property
    def depth_shape(self) -> tuple[int, int]:
        """Shape of the run's wear map ``(slices, nodes)``."""
        return (self.slices.count, self.planar.nodes)

    def contour(self, wear_depth: FloatArray) -> SlicedContour:
        """The slices worn by the map ``wear_depth`` [m]."""
        radius, length = self.parameters.bushing_radius, self.parameters.axial_length
        return SlicedContour.of_depth(radius, wear_depth, length)

    def initial_contour(self) -> SlicedContour:
        """The unworn slices."""
        return self.contour(np.zeros(self.depth_shape))

    # ---------------------------------------------------------------- solves
    def _misalignment(self, azimuth: float) -> Misalignment | None:
        if self.misalignment == 0 and self.play == 0:
            return None
        plane = azimuth if self.misalignment_plane is None else self.misalignment_plane
        return Misalignment(self.misalignment, plane, self.play)

    def solve(
        self,
        contour: SlicedContour,
        cycle: LoadCycle,
        *,
        sliding: FloatArray | None = None,
        warm: WarmStart | None = None,
        ahead: int = 0,
        facing: FloatArray | None = None,
    ) -> SlicedSolution:
        """Every step of ``cycle`` balanced on the slices of ``contour`` (the parameters
        of :meth:`jointwear.contact.solver.ContactSolver.solve`; a worn pin is refused by
        the configuration, the warm start is not needed by the axial balance)."""
        if facing is not None:
            raise ConfigError(
                "materials.pin.wear_coefficient: a wearing pin needs joint.axial_slices = 1"
            )
        contours = contour.contours
        balances = [
            solve_axial(
                contours,
                self.slices,
                self.pin,
                float(load),
                float(azimuth),
                self.slice_law,
                load_offset=self.load_offset,
                misalignment=self._misalignment(float(azimuth)),
                compliance=self.matrix,
                tolerance=self.planar.tolerance,
                max_penetration=self.parameters.bushing_thickness,
            )
            for load, azimuth in zip(cycle.load, cycle.azimuth, strict=True)
        ]
        return self._solution(contour, np.asarray(cycle.azimuth, dtype=float), balances)

    def _solution(
        self, contour: SlicedContour, azimuth: FloatArray, balances: list[AxialSolution]
    ) -> SlicedSolution:
        """The :class:`SlicedSolution` of a revolution's balances (module notes)."""
        pressure = np.stack([b.pressure for b in balances], axis=1)
        force = np.stack([b.force for b in balances])
        centre = np.array([b.centre_offset for b in balances])
        left, right = _half_angles(pressure, contour.theta, azimuth)
        springs = (pressure > 0).sum(axis=2).max(axis=0)
        return SlicedSolution(
            pressure=pressure.mean(axis=0),
            eccentricity=np.column_stack([centre * np.cos(azimuth), centre * np.sin(azimuth)]),
            penetration=np.array([b.penetration.max() for b in balances]),
            normal_force=force.sum(axis=1),
            tangential_force=np.array([b.lateral_force.sum() for b in balances]),
            half_angle_left=left,
            half_angle_right=right,
            springs_left=springs // 2,
            springs_right=springs - springs // 2,
            iterations=np.array([b.evaluations for b in balances], dtype=np.int64),
            model=self.slice_law.name,
            slice_pressure=pressure,
            slice_force=force,
            centre_offset=centre,
            tilt=np.array([b.tilt for b in balances]),
        )

    def wear_per_revolution(
        self,
        solution: SlicedSolution,
        wear_law: Callable[[FloatArray, FloatArray], FloatArray],
        sliding: FloatArray,
    ) -> FloatArray:
        """The wear map of one revolution [m], shape ``(N, nodes)``: the run's wear law on
        each slice's pressure (``wear_law(pressure [Pa], sliding [m]) -> depth [m]``)."""
        return np.stack([wear_law(p, sliding) for p in solution.slice_pressure])

    def warm_start(
        self,
        solution: SlicedSolution,
        contour: SlicedContour,
        azimuth: FloatArray,
        previous_offset: FloatArray | None = None,
        interval: int = 1,
    ) -> WarmStart:
        """The state's record of the last solve: the mid-plane offsets [m] (the axial
        balance brackets its own start)."""
        offset = np.array(solution.centre_offset)
        offset.setflags(write=False)
        return WarmStart(offset, None, None)


def _half_angles(
    pressure: FloatArray, theta: FloatArray, azimuth: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Widest contact of any slice counter-clockwise and clockwise of the load [rad].

    Parameters
    ----------
    pressure : ndarray, shape (N, M, nodes)
        Pressure of every slice at every step [Pa].
    theta : ndarray, shape (nodes,)
        Node angles [rad].
    azimuth : ndarray, shape (M,)
        Load directions [rad].
    """
    loaded = (pressure > 0).any(axis=0)
    relative = wrap_angle(theta[None, :] - azimuth[:, None])
    left = np.where(loaded, relative, 0.0).max(axis=1, initial=0.0)
    right = -np.where(loaded, relative, 0.0).min(axis=1, initial=0.0)
    return left, right
