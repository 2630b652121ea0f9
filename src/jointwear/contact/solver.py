"""The contact solve factory: the one place a contact solve path is chosen.

:class:`ContactSolver` is built once per run from the configuration (the law, the
pin, the balance options, whether the compiled kernel may load) and picks the path of
every contact solve of the run:

1. **a worn pin** (``facing`` given): each step on its own contour, the bushing's
   plus the pin's wear facing it at that step (:func:`jointwear.contact.solve` per step);
2. **the fused contact + Archard kernel** (:func:`jointwear.contact.kernel.revolution_wear`,
   warm-started revolutions of one load cycle by
   :class:`~jointwear.contact.kernel.WarmRevolutions`): inside the revolution loop
   (``sliding`` given), with the paper balance, a spring law and Archard's wear
   coefficient given to the solver;
3. **the general solve** (:func:`jointwear.contact.solve`): every other case, and
   every solve outside the loop (the pressure snapshots of a result).

A lubricated joint (``[lubrication]`` with a film model) takes none of these: film,
asperities and bulk share each step's load along the pin's periodic orbit
(:class:`~jointwear.contact.lubricated.LubricatedContact`), and the solution's pressure
is the asperity pressure plus the bulk's share solved dry (by path 1 or 3). Under the
contact–impact dynamics the film is already in the dynamics (its force acts on the pin
there, and the load cycle's ``load`` is the solid contact force alone, zero while the
film carries the pin): that load is solved dry as it is, and the film is not shared
a second time.

The fused kernel is the one exception to "contact computes pressure, tribology the
wear": it accumulates Archard's wear ``K_d p ds`` of every node inside the same
compiled pass that balances each load, so the dense pressure of a revolution is never
assembled. It receives the wear coefficient as a number, so this package never imports
the wear laws; :meth:`ContactSolver.wear_per_revolution` hands back the wear it
accumulated, or applies the run's wear law to the pressure of any other path.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from jointwear.contact import (
    ContactParameters,
    ContactSolution,
    check_model_choice,
    check_paper_spring_area,
    contact_law,
    solve,
)
from jointwear.contact.kernel import WarmRevolutions, revolution_wear
from jointwear.contact.laws import SpringLaw
from jointwear.geometry.contour import BushingContour, Pin

if TYPE_CHECKING:
    from collections.abc import Callable

    from jointwear.config import Config
    from jointwear.contact.lubricated import FilmRecord, LubricatedContact
    from jointwear.mechanism.cycle import LoadCycle

__all__ = ["COMPILED_KERNEL_SOLVES", "ContactSolver", "WarmStart", "compiled_kernel"]

FloatArray = NDArray[np.float64]

#: contact solves a run may need, above which the compiled kernel pays for loading numba
COMPILED_KERNEL_SOLVES = 500


def compiled_kernel(config: Config) -> bool | None:
    """Whether the run's contact solves may use the compiled kernel (``None``: where it can).

    Loading numba and its cached machine code takes ~0.7 s; the NumPy path solves a
    warm-started revolution of the paper's joint (360 steps, 360 nodes) in 0.5-1.7 ms, the
    compiled one in ~0.2 ms. A run that may need at most :data:`COMPILED_KERNEL_SOLVES`
    solves is about as fast or faster on the NumPy path (``False``). The
    bound is read from the configuration alone, so a run resumed from its checkpoint
    takes the same path and gives the same bits
    (:attr:`jointwear.config.SimulationConfig.contact_solves`).

    Parameters
    ----------
    config : Config
        The run's configuration.
    """
    return None if config.simulation.contact_solves > COMPILED_KERNEL_SOLVES else False


class WarmStart(NamedTuple):
    """Where the next contact solve of a run starts: the last solve's pin offsets.

    (The names are those of :class:`jointwear.state.SimulationState`'s fields that keep
    it between updates.)

    Attributes
    ----------
    warm_offset : ndarray, shape (M,)
        Pin displacement along each load line at the last solve [m].
    warm_slope : ndarray, shape (M,) or None
        Change of ``warm_offset`` per revolution between the last two solves [m]
        (``None``: no trend to extrapolate).
    window : int or None
        Node window half-width of the last solve [nodes].
    """

    warm_offset: FloatArray
    warm_slope: FloatArray | None
    window: int | None

    @classmethod
    def of_state(cls, state: Any) -> WarmStart | None:
        """The warm start a run's state keeps (``None`` before its first solve)."""
        if state.warm_offset is None:
            return None
        return cls(state.warm_offset, state.warm_slope, state.window)

    def guess(self, ahead: int) -> FloatArray:
        """The offsets extrapolated ``ahead`` revolutions along the trend [m]."""
        offset, slope = self.warm_offset, self.warm_slope
        if slope is None or not ahead:
            return offset
        # (one revolution ahead: the slope itself, 1 x is exact)
        return offset + (slope if ahead == 1 else ahead * slope)


class ContactSolver:
    """The contact solves of one run: the law, the pin and the path of each solve.

    Parameters
    ----------
    law : SpringLaw or law with ``.solve``
        The resolved contact law (:func:`jointwear.contact.contact_law`).
    parameters : ContactParameters
        Geometry and materials of the joint.
    balance : str
        ``contact.balance``.
    tolerance : float
        Absolute force tolerance of the balance [N].
    max_iterations : int
        Residual evaluations allowed per load.
    nodes : int
        Nodes of the run's contours [-].
    wear_coefficient : float, optional
        Dimensional Archard coefficient ``K_d`` [1/Pa] for the fused kernel (``None``:
        the run's wear law is not Archard's, and the kernel is not used).
    compiled : bool, optional
        Force (True), forbid (False) or allow (None) the compiled kernel.
    lubrication : LubricatedContact, optional
        The film and asperity load sharing of a lubricated joint (``None``: dry).
    """

    def __init__(
        self,
        law: Any,
        parameters: ContactParameters,
        *,
        balance: str,
        tolerance: float,
        max_iterations: int,
        nodes: int,
        wear_coefficient: float | None = None,
        compiled: bool | None = None,
        lubrication: LubricatedContact | None = None,
    ) -> None:
        self.law, self.parameters = law, parameters
        self.pin = Pin(parameters.pin_radius)
        self.balance, self.tolerance, self.max_iterations = balance, tolerance, max_iterations
        self.nodes = nodes
        self.wear_coefficient = wear_coefficient
        self.compiled = compiled
        self.lubrication = lubrication
        #: the load cycle and sliding distance whose warm revolutions are set up, and those
        self._warm_kernel: tuple[LoadCycle, FloatArray, WarmRevolutions | None] | None = None
        #: the load cycle whose bulk contact (a lubricated joint) was solved last, and
        #: where that solve ended
        self._warm_bulk: tuple[LoadCycle, WarmStart] | None = None

    @classmethod
    def from_config(
        cls, config: Config, model: str | Callable[..., Any] | Any, *, fused_archard: bool
    ) -> ContactSolver:
        """The solver of a run, its model checked against the run.

        Parameters
        ----------
        config : Config
            The run's configuration.
        model : str, SpringLaw or callable
            Contact model name, a law or ``pressure(penetration)`` [m -> Pa]; a model
            given here is refused as the config's would be.
        fused_archard : bool
            The run's wear law is Archard's: the fused kernel may accumulate it.

        Raises
        ------
        ConfigError
            A model that cannot follow the contour updates, or NLCP's paper form off
            its mesh.
        """
        parameters = ContactParameters.from_sections(config.joint, config.materials, config.contact)
        law = contact_law(model, parameters)
        check_model_choice(law, config.simulation.update_contour)
        if getattr(law, "force_area", None) is not None:
            joint, nodes = config.joint, config.contact.nodes
            node_area = BushingContour.circle(
                joint.bushing_radius, nodes, joint.axial_length
            ).spring_area[0]
            check_paper_spring_area(law.force_area, node_area, nodes)
        cfg = config.contact
        lubrication = None
        # contact-impact: the film acted in the dynamics; the load is the solid contact's
        if config.lubrication.lubricated and config.dynamics.model != "contact-impact":
            # the film's libraries (scipy's integrators, the mobility tables) load only here
            from jointwear.contact.lubricated import LubricatedContact

            lubrication = LubricatedContact(config.lubrication, parameters)
        return cls(
            law,
            parameters,
            balance=cfg.balance,
            tolerance=cfg.tolerance,
            max_iterations=cfg.max_iterations,
            nodes=cfg.nodes,
            wear_coefficient=(config.wearing_bushing.wear_coefficient if fused_archard else None),
            compiled=compiled_kernel(config),
            lubrication=lubrication,
        )

    @property
    def depth_shape(self) -> tuple[int]:
        """Shape of the run's wear depth: one value per node."""
        return (self.nodes,)

    def contour(self, wear_depth: FloatArray) -> BushingContour:
        """The bushing contour worn by ``wear_depth`` [m]."""
        # built anew from the depth at every update (as a resumed run rebuilds it), never
        # carried over: ``R + (h + dh)`` and ``(R + h) + dh`` differ in the last bits
        depth = np.asarray(wear_depth, dtype=float)
        radius, length = self.parameters.bushing_radius, self.parameters.axial_length
        return BushingContour._of_depth(radius, depth, length)

    def initial_contour(self) -> BushingContour:
        """The unworn bushing."""
        radius, length = self.parameters.bushing_radius, self.parameters.axial_length
        return BushingContour.circle(radius, self.nodes, length)

    def solve(
        self,
        contour: BushingContour,
        cycle: LoadCycle,
        *,
        sliding: FloatArray | None = None,
        warm: WarmStart | None = None,
        ahead: int = 0,
        facing: FloatArray | None = None,
    ) -> ContactSolution:
        """Pressure on every node at every step of ``cycle`` on ``contour``.

        Parameters
        ----------
        contour : BushingContour
            The bushing contour.
        cycle : LoadCycle
            The load cycle.
        sliding : ndarray, shape (M,), optional
            Sliding distance of each step [m]: a solve of the revolution loop, which the
            fused kernel may serve (its solution then carries the revolution's wear).
        warm : WarmStart, optional
            The last solve of the run, extrapolated ``ahead`` revolutions.
        ahead : int
            Revolutions since the warm start's solve [-].
        facing : ndarray, shape (M, N), optional
            The pin's wear facing each node at each step [m] (a worn pin).
        """
        if self.lubrication is not None:
            return self._lubricated(contour, cycle, facing)
        if facing is not None:
            return self._worn_pin(contour, cycle.load, cycle.azimuth, facing)
        options = {}
        if warm is not None:
            options = {"initial_offset": warm.guess(ahead), "window": warm.window}
        if sliding is not None and self._fuses():
            return self._fused(contour, cycle, sliding, options)
        return solve(
            contour,
            self.pin,
            cycle.load,
            cycle.azimuth,
            self.law,
            self.parameters,
            balance=self.balance,
            tolerance=self.tolerance,
            max_iterations=self.max_iterations,
            **options,
        )

    def wear_per_revolution(
        self,
        solution: ContactSolution,
        wear_law: Callable[[FloatArray, FloatArray], FloatArray],
        sliding: FloatArray,
    ) -> FloatArray:
        """Wear depth of one revolution at every node [m]: the fused kernel's, or
        ``wear_law(pressure, sliding)``.

        Parameters
        ----------
        solution : ContactSolution
            A solve of :meth:`solve`.
        wear_law : callable
            ``wear_law(pressure [Pa], sliding distance [m]) -> depth [m]``.
        sliding : ndarray, shape (M,)
            Sliding distance of each step [m].
        """
        revolution = getattr(solution, "revolution", None)
        if revolution is not None:  # Archard, accumulated by the fused solve from each window
            return revolution.wear
        return wear_law(solution.pressure, sliding)

    def warm_start(
        self,
        solution: ContactSolution,
        contour: BushingContour,
        azimuth: FloatArray,
        previous_offset: FloatArray | None = None,
        interval: int = 1,
    ) -> WarmStart:
        """Where the next solve starts, from ``solution`` on ``contour``.

        Parameters
        ----------
        solution : ContactSolution
            The solve.
        contour : BushingContour
            Its contour.
        azimuth : ndarray, shape (M,)
            The load directions of the solve [rad].
        previous_offset : ndarray, optional
            The offsets of the solve ``interval`` revolutions before [m] (``None``: no
            trend to extrapolate).
        interval : int
            Revolutions between the two solves [-].
        """
        revolution = getattr(solution, "revolution", None)
        if revolution is not None:
            offset, window = revolution.offset, revolution.window
        else:
            eccentricity = solution.eccentricity
            offset = eccentricity[:, 0] * np.cos(azimuth) + eccentricity[:, 1] * np.sin(azimuth)
            widest = max(
                float(solution.half_angle_left.max()), float(solution.half_angle_right.max())
            )
            window = int(np.ceil(widest / contour.dtheta) + 3)
        slope = None
        if previous_offset is not None and previous_offset.shape == offset.shape and interval > 0:
            change = offset - previous_offset
            # (x / 1 is exact: a per-revolution update skips the division)
            slope = change if interval == 1 else change / interval
            slope.setflags(write=False)
        # arrays of this solve alone, never written again: a state keeps them uncopied
        offset.setflags(write=False)
        return WarmStart(offset, slope, window)

    # ---------------------------------------------------------------- paths
    def _fuses(self) -> bool:
        return (
            self.wear_coefficient is not None
            and self.balance == "paper"
            and isinstance(self.law, SpringLaw)
        )

    def _fused(
        self,
        contour: BushingContour,
        cycle: LoadCycle,
        sliding: FloatArray,
        options: dict[str, Any],
    ) -> ContactSolution:
        """The fused contact + Archard revolution (its solution carries the wear)."""
        if options:
            revolutions = self._warm_revolutions(cycle, sliding)
            solved = (
                None if revolutions is None else revolutions(contour, options["initial_offset"])
            )
            if solved is not None:
                return solved.solution()
        # (a cold start, or inputs the warm revolutions refuse: the general path, which
        # raises where they were wrong)
        return revolution_wear(
            contour,
            self.pin,
            cycle.load,
            cycle.azimuth,
            sliding,
            self.law,
            self.wear_coefficient,
            max_penetration=self.parameters.bushing_thickness,
            tolerance=self.tolerance,
            max_iterations=self.max_iterations,
            compiled=self.compiled,
            **options,
        ).solution()

    def _warm_revolutions(self, cycle: LoadCycle, sliding: FloatArray) -> WarmRevolutions | None:
        """The compiled kernel's warm revolutions of ``cycle``, set up once per cycle
        (None without the kernel: :func:`revolution_wear` takes the NumPy path)."""
        kept = self._warm_kernel
        if kept is None or kept[0] is not cycle or kept[1] is not sliding:
            revolutions = WarmRevolutions.of(
                self.pin,
                cycle.load,
                cycle.azimuth,
                sliding,
                self.law,
                self.wear_coefficient,
                nodes=self.nodes,
                axial_length=self.parameters.axial_length,
                max_penetration=self.parameters.bushing_thickness,
                tolerance=self.tolerance,
                max_iterations=self.max_iterations,
                compiled=self.compiled,
            )
            kept = self._warm_kernel = (cycle, sliding, revolutions)
        return kept[2]

    def node_pressure(self, solution: ContactSolution) -> FloatArray:
        """The pressure on every node at every step [Pa], shape ``(M, N)`` (what the pin's
        wear reads)."""
        return solution.pressure

    def film_record(self, cycle: LoadCycle) -> FilmRecord | None:
        """The lubrication state of every step of ``cycle`` (``None``: a dry joint)."""
        if self.lubrication is None:
            return None
        return self.lubrication.record(cycle)

    def _lubricated(
        self, contour: BushingContour, cycle: LoadCycle, facing: FloatArray | None
    ) -> ContactSolution:
        """Film, asperities and bulk share each step's load: the asperity pressure on the
        nodes along the orbit plus the dry solve of the bulk's share."""
        lubrication, steps = self.lubrication, cycle.steps
        pressure = lubrication.asperity_pressure(cycle, contour.radius.size)
        record = lubrication.record(cycle)
        bulk = np.flatnonzero(record.bulk_load_fraction * cycle.load > 0.0)
        if bulk.size == steps:  # (no copy of the rows in and out)
            pressure += self._bulk_pressure(contour, cycle, bulk, facing)
        elif bulk.size:
            pressure[bulk] += self._bulk_pressure(contour, cycle, bulk, facing)
        touching = np.count_nonzero(pressure > 0.0, axis=1)
        half_angle = 0.5 * touching * contour.dtheta
        return ContactSolution(
            pressure=pressure,
            eccentricity=lubrication.centre(cycle),
            penetration=np.zeros(steps),
            normal_force=record.asperity_load_fraction * cycle.load,
            tangential_force=np.zeros(steps),
            half_angle_left=half_angle,
            half_angle_right=half_angle.copy(),
            springs_left=(touching + 1) // 2,
            springs_right=touching // 2,
            iterations=np.zeros(steps, dtype=np.int64),
            model=getattr(self.law, "name", "custom"),
        )

    def _bulk_pressure(
        self,
        contour: BushingContour,
        cycle: LoadCycle,
        bulk: NDArray[np.intp],
        facing: FloatArray | None,
    ) -> FloatArray:
        """The bulk's share of the load at the steps ``bulk``, solved dry [Pa], (B, N).

        The steps and their loads are the same every revolution of a load cycle (the
        orbit is the unworn bushing's): each solve starts from the last one's offsets,
        as the dry loop's solves do.
        """
        record = self.lubrication.record(cycle)
        load, azimuth = record.bulk_load_fraction[bulk] * cycle.load[bulk], cycle.azimuth[bulk]
        if facing is not None:
            return self._worn_pin(contour, load, azimuth, facing[bulk]).pressure
        kept, options = self._warm_bulk, {}
        if kept is not None and kept[0] is cycle:
            options = {"initial_offset": kept[1].warm_offset, "window": kept[1].window}
        solved = solve(
            contour,
            self.pin,
            load,
            azimuth,
            self.law,
            self.parameters,
            balance=self.balance,
            tolerance=self.tolerance,
            max_iterations=self.max_iterations,
            **options,
        )
        self._warm_bulk = (cycle, self.warm_start(solved, contour, azimuth))
        return solved.pressure

    def _worn_pin(
        self, contour: BushingContour, load: FloatArray, azimuth: FloatArray, facing: FloatArray
    ) -> ContactSolution:
        """Each step on its own contour: the bushing plus the pin's wear facing it."""
        radius, length = self.parameters.bushing_radius, self.parameters.axial_length
        parts = [
            solve(
                BushingContour.from_wear_profile(radius, contour.wear_depth + facing[k], length),
                self.pin,
                load[k : k + 1],
                azimuth[k : k + 1],
                self.law,
                self.parameters,
                balance=self.balance,
                tolerance=self.tolerance,
                max_iterations=self.max_iterations,
            )
            for k in range(load.size)
        ]
        fields = {
            name: np.concatenate([getattr(part, name) for part in parts])
            for name in (
                "pressure",
                "eccentricity",
                "penetration",
                "normal_force",
                "tangential_force",
                "half_angle_left",
                "half_angle_right",
                "springs_left",
                "springs_right",
                "iterations",
            )
        }
        return ContactSolution(**fields, model=parts[0].model)
