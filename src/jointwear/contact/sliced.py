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

A wearing pin (``materials.pin.wear_coefficient``) wears slice by slice too: its wear is
a map in its own frame, slice ``s`` of the pin facing slice ``s`` of the bushing, and
every step is balanced on the slices worn by the bushing's map plus the pin's wear
facing them at that step (:meth:`SlicedSolver.solve` with ``facing``), as the planar
solver does for one slice; the revolution's pressure is then kept for the pin's wear
(:func:`jointwear.tribology.pin_wear.pin_wear_depth`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, NamedTuple

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
    slice_wear : ndarray, shape (N, nodes) or None
        Archard's wear of the revolution on every slice, added up by the compiled
        balance inside the loop [m]; such a solution has no pressure (``None``).
    """

    slice_pressure: FloatArray = None  # type: ignore[assignment]
    slice_force: FloatArray = None  # type: ignore[assignment]
    centre_offset: FloatArray = None  # type: ignore[assignment]
    tilt: FloatArray = None  # type: ignore[assignment]
    slice_wear: FloatArray | None = None


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
    pin_wears : bool
        The pin wears (``materials.pin.wear_coefficient``): every revolution keeps its
        slices' pressure (the compiled balance does not add up Archard's wear inside).
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
        pin_wears: bool = False,
    ) -> None:
        self.planar = planar
        self.law, self.pin, self.parameters = planar.law, planar.pin, planar.parameters
        self.slice_law = spring_law_of(planar.law)
        self.slices = slices
        self.misalignment, self.misalignment_plane = misalignment, misalignment_plane
        self.load_offset, self.matrix, self.play = load_offset, matrix, play
        self.pin_wears = pin_wears
        # what the compiled balance reads, kept between solves (_steps, _areas, _angles)
        self._cycle: _Steps | None = None
        self._area: FloatArray | None = None
        self._angles_of: tuple[FloatArray, FloatArray] | None = None
        self._work: tuple[FloatArray, ...] | None = None

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
            pin_wears=config.materials.pin.wear_coefficient is not None,
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
        of :meth:`jointwear.contact.solver.ContactSolver.solve`; ``facing``, shape
        ``(N, M, nodes)``: the worn pin's wear facing each node of each slice at each
        step [m]).

        A rigid pin under a power law goes through the compiled balance
        (:mod:`jointwear.contact._sliced_kernel`, warm from the last solve or cold), which
        inside the loop with Archard's law (``sliding`` given) adds up each slice's wear
        without assembling the pressure (unless the pin wears); a load it does not
        balance, a bending pin and any other law are balanced by
        :func:`~jointwear.contact.axial.solve_axial` step by step. A worn pin: each step
        on the slices worn by ``contour``'s map plus ``facing`` at that step.
        """
        guess = None if warm is None else np.asarray(warm.guess(ahead), dtype=float)
        if guess is not None and guess.shape != (cycle.steps, 2):
            guess = None  # (a state of another cycle)
        if facing is not None:
            return self._worn_pin(contour, cycle, facing, guess)
        if self._compiles:
            return self._compiled(contour, cycle, guess, sliding)
        balances = [self._balance(contour, load, azimuth) for load, azimuth in _loads(cycle)]
        pressure = np.stack([b.pressure for b in balances], axis=1)
        state = np.array([[b.centre_offset, b.tilt] for b in balances])
        return self._solution(
            contour,
            cycle,
            state,
            pressure=pressure,
            force=np.stack([b.force for b in balances]),
            penetration=np.array([b.penetration.max() for b in balances]),
            iterations=np.array([b.evaluations for b in balances], dtype=np.int64),
        )

    @property
    def _compiles(self) -> bool:
        """Whether the compiled balance serves this run's warm solves."""
        law = self.slice_law
        return (
            self.planar.compiled is not False
            and self.matrix is None
            and self.play == 0
            and not law.symmetric
            and hasattr(law, "coefficient")
            and hasattr(law, "exponent")
        )

    def _balance(self, contour: SlicedContour, load: float, azimuth: float) -> AxialSolution:
        """One load balanced on the slices by :func:`solve_axial`."""
        return solve_axial(
            contour.contours,
            self.slices,
            self.pin,
            load,
            azimuth,
            self.slice_law,
            load_offset=self.load_offset,
            misalignment=self._misalignment(azimuth),
            compliance=self.matrix,
            tolerance=self.planar.tolerance,
            max_penetration=self.parameters.bushing_thickness,
        )

    def _tilts(self, azimuth: FloatArray) -> tuple[FloatArray, FloatArray]:
        """The imposed tilt along and across each load [rad]."""
        if self.misalignment_plane is None:
            return np.full(azimuth.size, self.misalignment), np.zeros(azimuth.size)
        relative = self.misalignment_plane - azimuth
        return self.misalignment * np.cos(relative), self.misalignment * np.sin(relative)

    def _steps(self, cycle: LoadCycle, sliding: FloatArray | None) -> _Steps:
        """What the compiled balance reads of ``cycle``'s steps and the ``sliding``
        distance [m] (``None``: zeros), kept while the loop solves the same cycle."""
        steps = self._cycle
        if steps is None or steps.cycle is not cycle or steps.sliding is not sliding:
            load, azimuth = (np.array(a, dtype=float) for a in (cycle.load, cycle.azimuth))
            along, across = self._tilts(azimuth)
            distance = np.zeros(load.size) if sliding is None else np.array(sliding, dtype=float)
            direction = np.column_stack([np.cos(azimuth), np.sin(azimuth)])
            steps = _Steps(cycle, sliding, load, azimuth, along, across, distance, direction)
            self._cycle = steps
        return steps

    def _areas(self, contour: SlicedContour) -> FloatArray:
        """Every node's spring area [m^2] (:class:`SliceContact`'s) of every slice of
        ``contour``, shape ``(N, 3 nodes)``: each row three turns long (the compiled
        balance's windows never wrap). Written into a buffer kept between solves (the
        balance reads it during its call only); a spring area of the law's own is written
        once."""
        count, nodes = contour.radius.shape
        area = self._area
        if area is None or area.shape != (count, 3 * nodes):
            area = self._area = np.empty((count, 3 * nodes))
            if self.slice_law.force_area is not None:  # (the same at every node and solve)
                area[:] = self.slice_law.force_area * self.slices.width / self.slices.length
        if self.slice_law.force_area is None:
            np.multiply(contour.radius, contour.dtheta, out=area[:, :nodes])
            area[:, :nodes] *= self.slices.width
            area[:, nodes : 2 * nodes] = area[:, :nodes]
            area[:, 2 * nodes :] = area[:, :nodes]
        return area

    def _angles(self, theta: FloatArray) -> tuple[FloatArray, FloatArray]:
        """``cos`` and ``sin`` of the node angles ``theta`` [rad], each three times (the
        compiled balance's windows never wrap); the same for every revolution."""
        angles = self._angles_of
        if angles is None or angles[0].size != 3 * theta.size:
            angles = (np.tile(np.cos(theta), 3), np.tile(np.sin(theta), 3))
            self._angles_of = angles
        return angles

    def _compiled(
        self,
        contour: SlicedContour,
        cycle: LoadCycle,
        guess: FloatArray | None,
        sliding: FloatArray | None,
    ) -> SlicedSolution:
        """The compiled balance of every step from ``guess`` (``(delta_0, gamma)`` per step
        [m, rad]; ``None``: a cold start); the loads it leaves go to :func:`solve_axial`."""
        steps = self._steps(cycle, sliding)
        fused = sliding is not None and self.planar.wear_coefficient is not None
        fused = fused and not self.pin_wears  # (the pin's wear reads the pressure)
        state, evaluations, wear, pressure, force = self._balanced(contour, steps, guess, fused)
        if fused:
            return self._solution(
                contour, cycle, state, iterations=evaluations, wear=wear, direction=steps.direction
            )
        return self._solution(contour, cycle, state, pressure=pressure, force=force,
                              iterations=evaluations)  # fmt: skip

    def _balanced(
        self, contour: SlicedContour, steps: _Steps, guess: FloatArray | None, fused: bool
    ) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray | None]:
        """The compiled balance of ``steps`` on ``contour`` from ``guess`` (module notes
        of :meth:`_compiled`): each step's ``(delta_0, gamma)`` [m, rad], evaluations,
        the slices' Archard wear where ``fused`` [m], else their pressure [Pa] and
        resultants along the load [N]."""
        from jointwear.compile_time import watch_compiles

        watch_compiles()  # (before the kernel compiles: its time is counted)
        from jointwear.contact import _sliced_kernel as kernel  # (numba: loaded when used)

        law = np.array([self.pin.radius, self.slice_law.coefficient, self.slice_law.exponent])
        count, nodes = contour.radius.shape
        area = self._areas(contour)
        cos_e, sin_e = self._angles(contour.theta)
        size = steps.load.size
        state = np.zeros((size, 2)) if guess is None else np.array(guess, dtype=float)
        status, evaluations = np.zeros(size, dtype=np.int64), np.zeros(size, dtype=np.int64)
        wear = np.empty((count, nodes))
        pressure = np.zeros((0, 0, 0)) if fused else np.zeros((count, size, nodes))
        if self._work is None or self._work[-2].size != 3 * count * nodes:
            self._work = kernel.scratch(count, nodes)
        kernel.revolution(
            steps.load, steps.azimuth, steps.along, steps.across, self.misalignment == 0,
            self.load_offset, self.slices.centres, np.ascontiguousarray(contour.radius),
            area.reshape(-1), cos_e, sin_e,
            law, self.planar.tolerance, self.planar.max_iterations, state, status, evaluations,
            steps.sliding_distance, self.planar.wear_coefficient if fused else 0.0, wear,
            pressure, guess is None, self._work,
        )  # fmt: skip
        for k in np.flatnonzero(status != kernel.CONVERGED):
            balanced = self._balance(contour, float(steps.load[k]), float(steps.azimuth[k]))
            state[k] = balanced.centre_offset, balanced.tilt
            evaluations[k] += balanced.evaluations
            if fused:
                wear += self.planar.wear_coefficient * steps.sliding_distance[k] * balanced.pressure
            else:
                pressure[:, k] = balanced.pressure
        if fused:
            return state, evaluations, wear, pressure, None
        area = area[:, :nodes]
        cosine = np.cos(contour.theta[None, :] - steps.azimuth[:, None])
        force = np.einsum("ikj,ij,kj->ki", pressure, area, cosine)
        return state, evaluations, wear, pressure, force

    def _worn_pin(
        self,
        contour: SlicedContour,
        cycle: LoadCycle,
        facing: FloatArray,
        guess: FloatArray | None,
    ) -> SlicedSolution:
        """Each step on its own slices: slice ``s`` worn by ``contour``'s map plus the
        pin's wear ``facing[s, k]`` [m] facing it at step ``k``, from ``guess`` (per step
        ``(delta_0, gamma)`` [m, rad]; ``None``: cold), as the planar solver's worn pin."""
        steps = self._steps(cycle, None)
        count, size, nodes = facing.shape
        pressure, force = np.empty((count, size, nodes)), np.empty((size, count))
        state, evaluations = np.empty((size, 2)), np.empty(size, dtype=np.int64)
        for k in range(size):
            worn = self.contour(contour.wear_depth + facing[:, k])
            if self._compiles:
                one = None if guess is None else guess[k : k + 1]
                balanced = self._balanced(worn, steps.step(k), one, False)
                state[k], evaluations[k] = balanced[0][0], balanced[1][0]
                pressure[:, k], force[k] = balanced[3][:, 0], balanced[4][0]
                continue
            solved = self._balance(worn, float(steps.load[k]), float(steps.azimuth[k]))
            state[k] = solved.centre_offset, solved.tilt
            evaluations[k], pressure[:, k] = solved.evaluations, solved.pressure
            force[k] = solved.force
        return self._solution(contour, cycle, state, pressure=pressure, force=force,
                              iterations=evaluations)  # fmt: skip

    def _solution(
        self,
        contour: SlicedContour,
        cycle: LoadCycle,
        state: FloatArray,
        *,
        pressure: FloatArray | None = None,
        force: FloatArray | None = None,
        penetration: FloatArray | None = None,
        iterations: FloatArray,
        wear: FloatArray | None = None,
        direction: FloatArray | None = None,
    ) -> SlicedSolution:
        """The :class:`SlicedSolution` of a revolution's balances (module notes); a fused
        revolution (``wear`` given) has no pressure. ``direction``: ``(cos, sin)`` of
        the loads' azimuth, shape (M, 2) [-], where known."""
        azimuth = np.asarray(cycle.azimuth, dtype=float)
        if direction is None:
            direction = np.column_stack([np.cos(azimuth), np.sin(azimuth)])
        centre = state[:, 0]
        steps = azimuth.size
        if pressure is None:
            left = right = np.zeros(steps)
            springs = np.zeros(steps, dtype=np.int64)
            mean = None
        else:
            left, right = _half_angles(pressure, contour.theta, azimuth)
            springs = (pressure > 0).sum(axis=2).max(axis=0)
            mean = pressure.mean(axis=0)
        if penetration is None:
            penetration = np.full(steps, np.nan)
        return SlicedSolution(
            pressure=mean,
            eccentricity=centre[:, None] * direction,
            penetration=penetration,
            normal_force=np.full(steps, np.nan) if force is None else force.sum(axis=1),
            tangential_force=np.zeros(steps),
            half_angle_left=left,
            half_angle_right=right,
            springs_left=springs // 2,
            springs_right=springs - springs // 2,
            iterations=iterations,
            model=self.slice_law.name,
            slice_pressure=pressure,
            slice_force=force,
            centre_offset=centre,
            tilt=state[:, 1],
            slice_wear=wear,
        )

    def node_pressure(self, solution: SlicedSolution) -> FloatArray:
        """Each slice's pressure on every node at every step [Pa], shape ``(N, M, nodes)``
        (what the pin's wear reads)."""
        return solution.slice_pressure

    def film_record(self, cycle: LoadCycle) -> None:
        """A joint along the pin is dry (a film needs one slice): no lubrication record."""
        return None

    def wear_per_revolution(
        self,
        solution: SlicedSolution,
        wear_law: Callable[[FloatArray, FloatArray], FloatArray],
        sliding: FloatArray,
    ) -> FloatArray:
        """The wear map of one revolution [m], shape ``(N, nodes)``: the run's wear law on
        each slice's pressure (``wear_law(pressure [Pa], sliding [m]) -> depth [m]``)."""
        if solution.slice_wear is not None:  # Archard's, added up by the compiled balance
            return solution.slice_wear
        return np.stack([wear_law(p, sliding) for p in solution.slice_pressure])

    def warm_start(
        self,
        solution: SlicedSolution,
        contour: SlicedContour,
        azimuth: FloatArray,
        previous_offset: FloatArray | None = None,
        interval: int = 1,
    ) -> WarmStart:
        """Where the next solve starts: each step's ``(delta_0, gamma)`` [m, rad] and
        their change per revolution since ``previous_offset``, ``interval`` revolutions
        before (:class:`~jointwear.contact.solver.WarmStart`)."""
        offset = np.column_stack([solution.centre_offset, solution.tilt])
        slope = None
        if previous_offset is not None and previous_offset.shape == offset.shape and interval > 0:
            slope = (offset - previous_offset) / interval
            slope.setflags(write=False)
        offset.setflags(write=False)
        return WarmStart(offset, slope, None)


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


class _Steps(NamedTuple):
    """A load cycle's steps as the compiled balance reads them (:meth:`SlicedSolver._steps`):
    the cycle and sliding distance they were read from, the load [N], its azimuth [rad],
    the imposed tilt along and across it [rad], the sliding distance [m] and the load's
    direction ``(cos, sin)`` of its azimuth [-], shape (M, 2)."""

    cycle: LoadCycle
    sliding: FloatArray | None
    load: FloatArray
    azimuth: FloatArray
    along: FloatArray
    across: FloatArray
    sliding_distance: FloatArray
    direction: FloatArray

    def step(self, k: int) -> _Steps:
        """Step ``k`` alone (its arrays one long, views of these)."""
        arrays = (self.load, self.azimuth, self.along, self.across, self.sliding_distance)
        return _Steps(self.cycle, self.sliding, *(a[k : k + 1] for a in arrays),
                      self.direction[k : k + 1])  # fmt: skip


def _loads(cycle: LoadCycle):
    """``(load [N], azimuth [rad])`` of every step as floats."""
    return zip(cycle.load.tolist(), cycle.azimuth.tolist(), strict=True)
