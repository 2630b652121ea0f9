"""One revolution of contact and Archard wear in one call: the simulation's inner step.

:func:`revolution_wear` balances every load of a revolution (paper balance, eqs. (5)/(7))
and accumulates Archard's wear ``K_d sum_k p_jk ds_k`` straight from each load's
contact window; the dense (M, N) pressure is assembled only when asked for
(:meth:`RevolutionWear.solution`), and the compiled path evaluates the contact extent,
peak pressure, tangential force and springs in contact then too. With numba installed
the balance runs in a fused, compiled loop (:mod:`jointwear.contact._compiled`,
imported on first use and cached on disk); without it, or with
``JOINTWEAR_NO_NUMBA=1``, the same result comes from the NumPy path, the windowed
balance :func:`jointwear.contact.balance.solve_contact` itself. Both are held to the
plain statement of the balance (:mod:`jointwear.contact.balance.paper`) by the tests.

The compiled path applies to the power laws ``p = k delta^n`` with ``n`` 1 or 1.5
(Winkler, asymmetric Winkler, NLCP); any other law takes the NumPy path.

Archard's wear is computed here, not by :mod:`jointwear.tribology.archard`: this is
the one deliberate exception to "one implementation of each formula". The contact
stage sits below tribology, and the compiled loop adds a load's wear to the nodes as
soon as the load is balanced (its pressure is never stored), so the kernel takes what
it needs as plain numbers, the dimensional Archard coefficient ``K_d = k / H``
[1/Pa] and the sliding distance of each step [m], and adds ``K_d p_jk ds_k``
(:func:`archard_wear` on the NumPy path). ``tests/contact/test_kernel.py`` holds both
paths' wear to :func:`jointwear.tribology.archard.wear_depth` at 1e-12 relative.
"""

from __future__ import annotations

import math
import os
import threading
from typing import Any, ClassVar

import numpy as np
from numpy.typing import ArrayLike, NDArray

from jointwear.contact.balance.guesses import conformal_depth, step_curvature
from jointwear.contact.balance.solve import (
    check_converged,
    check_reach,
    checked_loads,
    solve_contact,
)
from jointwear.contact.balance.window import PIN_REACH, nearest_nodes, upper_bound
from jointwear.contact.laws import PowerLaw, SpringLaw
from jointwear.contact.solution import ContactSolution
from jointwear.errors import ContactError
from jointwear.geometry.contour import BushingContour, Pin, RadiusStencil

__all__ = [
    "RevolutionWear",
    "WarmRevolutions",
    "archard_wear",
    "compiled_available",
    "revolution_wear",
]

FloatArray = NDArray[np.float64]

#: a residual that this many units in the last place of the offset explain is round-off
ROUND_OFF_ULPS = 4.0
_COMPILED: Any = None
#: per (nodes, azimuths): the load lines' node indices, shifts and radius stencil
_AZIMUTH_CACHE: dict[tuple[int, bytes], _Lines] = {}


def compiled_available() -> bool:
    """True if the compiled kernel can be used (numba importable, not switched off)."""
    return _compiled() is not None


def _compiled():
    """The compiled module, imported on first use (None without numba)."""
    global _COMPILED
    if os.environ.get("JOINTWEAR_NO_NUMBA", "") not in ("", "0"):
        return None
    if _COMPILED is None:
        try:
            from jointwear.compile_time import watch_compiles

            watch_compiles()
            from jointwear.contact import _compiled as module
        except ImportError:
            module = False
        _COMPILED = module
    return _COMPILED or None


class RevolutionWear:
    """Wear and contact summary of one revolution (read-only).

    Attributes
    ----------
    wear : ndarray, shape (N,)
        Archard wear depth of the revolution at every node [m].
    offset : ndarray, shape (M,)
        Pin displacement along each load line [m] (warm start of the next solve).
    window : int
        Half-width [nodes] of a window holding every step's contact, plus a margin.
    iterations : ndarray of int, shape (M,)
        Residual evaluations of each step's balance.
    half_angle_left, half_angle_right : ndarray, shape (M,)
        Contact extent counter-clockwise / clockwise of the load line [rad].
    peak_pressure : ndarray, shape (M,)
        Largest pressure of each step [Pa].
    normal_force, tangential_force : ndarray, shape (M,)
        Resultants along and across the load [N].
    springs_left, springs_right : ndarray of int, shape (M,)
        Springs in contact each side of the load line.

    Notes
    -----
    A run reads the wear, the offsets, the window and the iterations of every
    revolution, and the rest seldom: the compiled path evaluates the half-angles, the
    peak pressure, the tangential force and the springs when one of them is first read
    (one more evaluation per load, at its balanced offset). Built with the first five
    attributes, and either the other six (``**evaluated``) or ``balanced``, ``rows ->
    (pressure, fields)``: the compiled path's balanced state, its dense pressure
    (``rows`` rows) and the fields it leaves out. ``solution``: the NumPy path's
    :class:`ContactSolution`; ``context``: ``(contour, pin, azimuth, law, centre_gap)``.
    """

    #: the fields the compiled path evaluates when first read
    _EVALUATED: ClassVar[frozenset[str]] = frozenset(
        {"half_angle_left", "half_angle_right", "peak_pressure", "tangential_force",
         "springs_left", "springs_right"}
    )  # fmt: skip

    def __init__(
        self, wear: FloatArray, offset: FloatArray, window: int,
        iterations: NDArray[np.int64], normal_force: FloatArray, *, balanced: Any = None,
        solution: ContactSolution | None = None, context: Any = None, **evaluated: Any,
    ) -> None:  # fmt: skip
        if evaluated and not self._EVALUATED.issuperset(evaluated):
            unknown = sorted(set(evaluated) - self._EVALUATED)
            raise TypeError(f"RevolutionWear: unknown fields {unknown}")
        # (the instance's dict: attributes are read-only, __setattr__ refuses them; one
        # store each, as a run builds one of these per revolution)
        fields = self.__dict__
        fields["wear"], fields["offset"], fields["window"] = wear, offset, window
        fields["iterations"], fields["normal_force"] = iterations, normal_force
        fields["_balanced"], fields["_solution"], fields["_context"] = balanced, solution, context
        if evaluated:
            fields.update(evaluated)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"RevolutionWear is read-only: cannot set {name!r}")

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"RevolutionWear is read-only: cannot delete {name!r}")

    def __repr__(self) -> str:
        return (
            f"<RevolutionWear: {self.offset.size} loads, peak wear {float(self.wear.max()):.4g} m>"
        )

    def __getattr__(self, name: str) -> Any:
        # only reached for a field not set: one the compiled path evaluates on first read
        assemble = vars(self).get("_balanced")
        if assemble is None or name not in self._EVALUATED:
            raise AttributeError(name)
        self._keep(assemble(0)[1])
        return vars(self)[name]

    def _keep(self, fields: dict[str, Any]) -> None:
        for name, value in fields.items():
            vars(self).setdefault(name, value)

    def _pressure(self) -> FloatArray:
        pressure, fields = self._balanced(self.offset.size)
        self._keep(fields)
        return pressure

    def solution(self) -> ContactSolution:
        """The revolution as a :class:`ContactSolution`; the (M, N) pressure, the
        eccentricity and the penetration are assembled when first read."""
        if self._solution is not None:
            return self._solution
        return _WindowSolution(self)

    def _eccentricity(self) -> FloatArray:
        azimuth = self._context[2]
        return self.offset[:, None] * np.stack([np.cos(azimuth), np.sin(azimuth)], axis=1)

    def _penetration(self) -> FloatArray:
        return np.maximum(self.offset - self._context[4], 0.0)


class _WindowSolution(ContactSolution):
    """A :class:`ContactSolution` whose fields are taken from its :class:`RevolutionWear`
    when first read, the bulkier ones assembled then.

    Inside a run only the wear (``revolution``), the iterations and the half-angles are
    read; the dense pressure alone would be an (M, N) array per revolution.
    """

    #: fields assembled on first read, by the method of the revolution that builds them
    _ASSEMBLED: ClassVar[dict[str, str]] = {
        "pressure": "_pressure",
        "eccentricity": "_eccentricity",
        "penetration": "_penetration",
    }
    #: fields that are the revolution's own
    _SHARED = frozenset(
        {"normal_force", "tangential_force", "half_angle_left", "half_angle_right",
         "springs_left", "springs_right", "iterations"}
    )  # fmt: skip

    def __init__(self, revolution: RevolutionWear):
        # frozen: the instance's dict directly (object.__setattr__ costs its call); the
        # iterations now, as every revolution of a run reads them
        self.__dict__.update(revolution=revolution, iterations=revolution.iterations)

    def __getattr__(self, name: str) -> Any:
        # only reached for attributes not set yet: a field, on first use
        revolution = self.__dict__.get("revolution")
        if revolution is None:
            raise AttributeError(name)
        if name in self._SHARED:
            value = getattr(revolution, name)
        elif name in self._ASSEMBLED:
            value = getattr(revolution, self._ASSEMBLED[name])()
        elif name == "model":
            value = revolution._context[3].name
        else:
            raise AttributeError(name)
        self.__dict__[name] = value
        return value

    @property
    def loads(self) -> int:
        """Number of loads ``M``."""
        return int(self.iterations.size)


class _Lines:
    """Contour-independent data of the load lines: node nearest each, and its shift."""

    def __init__(self, nodes: int, azimuth: FloatArray) -> None:
        self.nodes = nodes
        dtheta = 2 * np.pi / nodes
        position, self.centre, self.shift = nearest_nodes(nodes, azimuth)
        self.cos_shift, self.sin_shift = np.cos(self.shift), np.sin(self.shift)
        #: the azimuths this is cached for (the key's bytes): a warm revolution's context
        self.azimuth = azimuth.copy()
        self.finite = bool(np.isfinite(azimuth).all())
        self.stencil = RadiusStencil.at(nodes, position)
        self.lower_weight = 1 - self.stencil.weight
        self.quarter = nodes // 4
        self.pad = self.quarter + 1
        offsets = np.arange(-self.quarter, self.quarter + 1)
        self.cos_o, self.sin_o = np.cos(offsets * dtheta), np.sin(offsets * dtheta)
        #: ``cos((n - 1/2) dtheta)`` for ``n = 1 .. quarter`` after a 1: the reach's table
        self.half_cos = np.concatenate(
            [[1.0], np.cos((np.arange(1, self.quarter + 1) - 0.5) * dtheta)]
        )
        #: node of each position of an array padded by ``pad`` nodes each side
        self.padded = np.arange(-self.pad, nodes + 1 + self.pad) % nodes
        # constants of the kernel's arguments, never written (not flagged read-only:
        # numba would compile the kernel again for read-only arrays)
        self.zeros, self.ones = np.zeros(azimuth.size), np.ones(azimuth.size)
        self.zeros_padded = np.zeros(self.padded.size)
        self._filled: dict[float, FloatArray] = {}
        self._scratch = threading.local()

    def arguments(self, gap_ext, area_ext, load_gap, load_area, gap_min, lower, upper):
        """The compiled kernel's ``nodes`` and ``lines`` from the contour's arrays."""
        nodes = (gap_ext, area_ext, self.cos_o, self.sin_o, self.half_cos)
        lines = (
            self.centre, self.cos_shift, self.sin_shift, load_gap, load_area, gap_min, lower,
            upper, self.shift,
        )  # fmt: skip
        return nodes, lines

    def grid(self, dtheta: float, rp: float, law: SpringLaw) -> tuple[Any, ...]:
        """The compiled kernel's ``grid``: node spacing [rad], pin radius [m], the law."""
        return (
            self.pad, self.quarter, dtheta, rp, float(law.exponent), float(law.coefficient),
        )  # fmt: skip

    def centre_radius(self, radius: FloatArray) -> FloatArray:
        """The radius on each load line [m]: ``self.stencil(radius)``, its weights kept."""
        stencil = self.stencil
        return self.lower_weight * radius.take(stencil.lower) + stencil.weight * radius.take(
            stencil.upper
        )

    def scratch(self, module: Any) -> tuple[FloatArray, ...]:
        """The compiled kernel's window scratch, one per thread (it writes it)."""
        local = self._scratch
        work = getattr(local, "work", None)
        if work is None:
            work = local.work = module.scratch(self.quarter)
        return work

    def filled(self, value: float) -> FloatArray:
        """A padded array of ``value`` (kept: the kernel never writes it)."""
        array = self._filled.get(value)
        if array is None:
            if len(self._filled) >= 4:
                self._filled.clear()
            array = self._filled[value] = np.full(self.padded.size, value)
        return array


def _lines(nodes: int, azimuth: FloatArray) -> _Lines:
    key = (nodes, azimuth.tobytes())
    lines = _AZIMUTH_CACHE.get(key)
    if lines is None:
        if len(_AZIMUTH_CACHE) >= 4:
            _AZIMUTH_CACHE.pop(next(iter(_AZIMUTH_CACHE)))
        lines = _AZIMUTH_CACHE[key] = _Lines(nodes, azimuth)
    return lines


def revolution_wear(
    contour: BushingContour,
    pin: Pin,
    load: ArrayLike,
    azimuth: ArrayLike,
    sliding_distance: ArrayLike,
    law: SpringLaw,
    wear_coefficient: float,
    *,
    max_penetration: float | None = None,
    initial_offset: ArrayLike | None = None,
    window: int | None = None,
    tolerance: float = 1e-12,
    max_iterations: int = 100,
    compiled: bool | None = None,
) -> RevolutionWear:
    """Balance every load of a revolution (paper balance) and its Archard wear.

    Parameters
    ----------
    contour : BushingContour
        Current bushing contour.
    pin : Pin
        The pin.
    load : array_like, shape (M,)
        Joint load magnitudes [N], >= 0.
    azimuth : array_like, shape (M,)
        Direction in which the pin presses on the bushing, bushing frame [rad].
    sliding_distance : array_like, shape (M,)
        Sliding distance of each step [m].
    law : SpringLaw
        Spring law (:func:`jointwear.contact.contact_law`).
    wear_coefficient : float
        Dimensional Archard coefficient ``K_d = k / H`` [1/Pa] (the kernel adds the wear
        itself: the module notes).
    max_penetration : float, optional
        Largest admissible penetration at the compression centre, normally the wall
        thickness [m]; a load needing more raises :class:`ContactError`.
    initial_offset : array_like, shape (M,), optional
        Guesses of the pin displacement along each load line [m] (warm start).
    window : int, optional
        Node window half-width of a previous solve [nodes]; the NumPy path starts from
        it, the compiled one sizes each load's window from its reach instead.
    tolerance : float
        Absolute force tolerance of the balance [N].
    max_iterations : int
        Residual evaluations allowed per load.
    compiled : bool, optional
        Force (True) or forbid (False) the compiled kernel; default: use it where it
        applies and numba is available.

    Returns
    -------
    RevolutionWear
    """
    module = _module_for(law, compiled)
    if compiled and module is None:
        raise ContactError("contact: the compiled kernel needs numba and a power law 1 or 1.5")
    if module is None:
        return _numpy_revolution(
            contour, pin, load, azimuth, sliding_distance, law, wear_coefficient,
            max_penetration, initial_offset, window, tolerance, max_iterations,
        )  # fmt: skip
    if initial_offset is not None:
        warm = WarmRevolutions._of_module(
            module, pin, load, azimuth, sliding_distance, law, wear_coefficient,
            contour.nodes, contour.axial_length, max_penetration, tolerance, max_iterations,
        )  # fmt: skip
        result = None if warm is None else warm(contour, initial_offset)
        if result is not None:
            return result
    return _compiled_revolution(
        module, contour, pin, load, azimuth, sliding_distance, law, wear_coefficient,
        max_penetration, initial_offset, tolerance, max_iterations,
    )  # fmt: skip


def _compiled_revolution(
    module, contour, pin, load, azimuth, sliding_distance, law, wear_coefficient,
    max_penetration, initial_offset, tolerance, max_iterations,
):  # fmt: skip
    """The compiled revolution from any inputs (checked here), cold or warm."""
    load, azimuth = checked_loads(load, azimuth)
    m = load.size
    sliding = np.asarray(sliding_distance, dtype=float).ravel()
    if sliding.size != m:
        sliding = np.broadcast_to(sliding, (m,))
    load, sliding = _plain(load), _plain(sliding)
    contour.check_pin(pin)
    nodes, grid, lines, centre_gap, known = _arguments(
        contour, pin, load, azimuth, law, max_penetration
    )
    if initial_offset is None:
        guess, conformal = known.zeros, _conformal_starts(contour, pin, law, load, centre_gap)
    else:
        guess, conformal = np.asarray(initial_offset, dtype=float).ravel(), known.zeros
        if guess.size != m:
            raise ContactError(f"initial_offset: need one offset per load ({m}), got {guess.size}")
    return _run(
        module, contour, pin, load, azimuth, sliding, law, wear_coefficient,
        initial_offset is not None, _solver(law, tolerance, max_iterations), guess, conformal,
        nodes, grid, lines, centre_gap, known,
    )  # fmt: skip


def _conformal_starts(contour, pin, law, load, centre_gap):
    """The conformal estimate of the offset [m] of each load without a balanced
    predecessor (the first, or one after a zero load), 0 for the others: they start from
    their predecessor (usually one load: scalars cost less than arrays of one)."""
    conformal = np.zeros(load.size)
    alone = np.flatnonzero((load > 0.0) & np.concatenate(([True], load[:-1] <= 0.0)))
    for k in alone.tolist():
        clearance = max(float(centre_gap[k]), 1e-12 * pin.radius)
        conformal[k] = clearance + conformal_depth(
            contour, pin.radius, law, float(load[k]), clearance
        )
    return conformal


class WarmRevolutions:
    """Warm-started compiled revolutions of one load cycle, on contours that change.

    A run solves the same loads on a new contour at every update: what stays the same
    (the loads, azimuths and sliding distances, checked once to be plain float arrays;
    the load lines, the law's constants, the scratch) is set up here once. A call builds
    the contour's arguments in one compiled loop (``prepare``: the NumPy expressions of
    the general path, which it also checks) and runs the revolution from the guesses.
    Build it with :meth:`of`.
    """

    def __init__(
        self, module: Any, pin: Pin, load: FloatArray, azimuth: FloatArray,
        sliding: FloatArray, law: PowerLaw, wear_coefficient: float, known: _Lines,
        axial_length: float, reach: float, tolerance: float, max_iterations: int,
    ) -> None:  # fmt: skip
        self.module, self.pin, self.law, self.known = module, pin, law, known
        self.load, self.sliding, self.wear_coefficient = load, sliding, wear_coefficient
        self.nodes, self.axial_length = known.nodes, axial_length
        self.rp = float(pin.radius)
        dtheta = 2.0 * np.pi / self.nodes
        #: the kernel's constant tuples
        self.grid = known.grid(dtheta, self.rp, law)
        self.solver = _solver(law, tolerance, max_iterations)
        spring = dtheta * axial_length
        stencil = known.stencil
        #: ``prepare``'s ``built``
        self.built = (
            1 if law.symmetric else 2, law.force_area is None, stencil.lower, stencil.upper,
            stencil.weight, known.lower_weight, known.padded, spring, reach,
        )  # fmt: skip
        #: the spring areas, where the law fixes them
        self.area_ext = None
        if law.force_area is not None:
            self.area_ext = known.filled(float(law.force_area))
        elif law.symmetric:
            self.area_ext = known.filled(spring)

    @classmethod
    def of(
        cls, pin: Pin, load: FloatArray, azimuth: FloatArray, sliding_distance: FloatArray,
        law: SpringLaw, wear_coefficient: float, *, nodes: int, axial_length: float,
        max_penetration: float | None = None, tolerance: float = 1e-12,
        max_iterations: int = 100, compiled: bool | None = None,
    ) -> WarmRevolutions | None:  # fmt: skip
        """The warm revolutions of a load cycle, or None where the compiled kernel does
        not apply (law, numba, ``compiled=False``) or the inputs are not plain float
        arrays of one length with finite azimuths (:func:`revolution_wear` then serves).

        Parameters are those of :func:`revolution_wear`; ``nodes`` and ``axial_length``
        [m] those of the contours to come.
        """
        module = _module_for(law, compiled)
        if module is None:
            return None
        return cls._of_module(
            module, pin, load, azimuth, sliding_distance, law, wear_coefficient, nodes,
            axial_length, max_penetration, tolerance, max_iterations,
        )  # fmt: skip

    @classmethod
    def _of_module(
        cls, module, pin, load, azimuth, sliding, law, wear_coefficient, nodes, axial_length,
        max_penetration, tolerance, max_iterations,
    ):  # fmt: skip
        ndarray = np.ndarray
        if not (type(load) is type(azimuth) is type(sliding) is ndarray):
            return None
        m = load.size
        if not (
            load.dtype == azimuth.dtype == sliding.dtype == np.float64
            and load.shape == azimuth.shape == sliding.shape == (m,)
        ):
            return None
        known = _lines(nodes, azimuth)
        if not known.finite:
            return None
        reach = np.inf if max_penetration is None else float(max_penetration)
        return cls(
            module, pin, _plain(load), known.azimuth, _plain(sliding), law, wear_coefficient,
            known, axial_length, reach, tolerance, max_iterations,
        )  # fmt: skip

    def __call__(
        self, contour: BushingContour, initial_offset: FloatArray
    ) -> RevolutionWear | None:
        """The revolution on ``contour`` from the guesses ``initial_offset`` [m]; None where
        the contour or the guesses are not those this was set up for, or a check fails
        (:func:`revolution_wear` then raises its error)."""
        arguments = self.arguments(contour)
        guess = initial_offset
        if arguments is None or not (
            type(guess) is np.ndarray and guess.dtype == np.float64
            and guess.shape == self.load.shape
        ):  # fmt: skip
            return None
        nodes, grid, lines, centre_gap = arguments
        known = self.known
        return _run(
            self.module, contour, self.pin, self.load, known.azimuth, self.sliding, self.law,
            self.wear_coefficient, True, self.solver, guess, known.zeros, nodes, grid, lines,
            centre_gap, known,
        )  # fmt: skip

    def arguments(self, contour: BushingContour) -> tuple[Any, ...] | None:
        """:func:`_arguments` on ``contour``, filled by the compiled ``prepare``: ``nodes``,
        ``grid``, ``lines`` and the gap on each load line [m]; None where a check fails."""
        if contour.nodes != self.nodes or contour.axial_length != self.axial_length:
            return None
        known, law = self.known, self.law
        m = self.load.size
        centre_gap = np.empty(m)
        upper = np.empty(m)
        # the arrays the kernel fills: those of _arguments, laid out as there
        if law.symmetric:
            gap_ext, load_gap, gap_min = known.zeros_padded, centre_gap, centre_gap
            area_ext = self.area_ext
            load_area = np.empty(m) if law.force_area is None else known.ones
        else:
            gap_ext, load_gap, gap_min = np.empty(known.padded.size), known.zeros, np.empty(m)
            area_ext = np.empty(known.padded.size) if self.area_ext is None else self.area_ext
            load_area = known.ones
        out = (centre_gap, gap_ext, area_ext, load_gap, load_area, gap_min, upper)
        if not self.module.prepare(self.load, contour.radius, self.rp, self.built, out):
            return None
        nodes, lines = known.arguments(
            gap_ext, area_ext, load_gap, load_area, gap_min, gap_min, upper
        )
        return nodes, self.grid, lines, centre_gap


def _module_for(law: SpringLaw, compiled: bool | None):
    """The compiled module where it applies to ``law`` (a power law 1 or 1.5) and
    ``compiled`` allows it (None: where numba is available), else None."""
    applies = isinstance(law, PowerLaw) and law.exponent in (1.0, 1.5)
    return _compiled() if applies and compiled is not False else None


def _plain(array: FloatArray) -> FloatArray:
    """``array`` as a writable C-contiguous array (copied only if it is not): one type for
    every array the kernel reads, or numba compiles it again for each (~8 s on a new
    machine, and two processes compiling at once may swap the variants in its cache)."""
    if array.flags.writeable and array.flags.c_contiguous:
        return array
    return np.array(array, order="C")


def _solver(law: SpringLaw, tolerance: float, max_iterations: int) -> tuple[Any, ...]:
    """The compiled kernel's ``solver``: force tolerance [N], round-off ulps, evaluations
    allowed, the Chebyshev step's ``kappa``."""
    return (float(tolerance), ROUND_OFF_ULPS, int(max_iterations), step_curvature(law))


def _run(
    module, contour, pin, load, azimuth, sliding, law, wear_coefficient, warm, solver, guess,
    conformal, nodes, grid, lines, centre_gap, known,
):  # fmt: skip
    """The compiled revolution and its :class:`RevolutionWear` (``warm``: every load starts
    from ``guess``)."""
    m = load.size
    # (a run's guesses are often the state's read-only offsets)
    guess = _plain(guess)
    # (the kernel writes every entry of its outputs, and zeroes the padded wear)
    floats = np.empty((2, m))
    counts = np.empty((2, m), dtype=np.int64)
    work = known.scratch(module)
    wear_ext = np.empty(known.padded.size)
    wear = np.empty(contour.nodes)
    failed, widest = module.revolution(
        load, sliding, guess, warm, conformal, nodes, grid, lines, solver,
        floats, counts, wear_ext, wear_coefficient * law.coefficient, wear, work,
    )  # fmt: skip
    offset, total = floats
    # the revolution's own: a state keeps its wear uncopied
    wear.setflags(write=False)
    if failed:
        check_converged(counts[1] == 0, offset, lines[7], load, azimuth, total - load)

    def balanced(rows: int) -> tuple[FloatArray, dict[str, Any]]:
        pressure = np.zeros((rows, contour.nodes))
        evaluated = np.empty((4, m))
        springs = np.empty((2, m), dtype=np.int64)
        # its own scratch: it may be read long after, from any thread
        module.balanced_state(
            offset, load, nodes, grid, lines, pressure, evaluated, springs,
            module.scratch(known.quarter),
        )  # fmt: skip
        tangential, left, right, peak = evaluated
        return pressure, {
            "tangential_force": tangential, "half_angle_left": left,
            "half_angle_right": right, "peak_pressure": peak, "springs_left": springs[0],
            "springs_right": springs[1],
        }  # fmt: skip

    # (the widest window holds every node in contact, and one beyond)
    return RevolutionWear(
        wear, offset, widest + 2, counts[0], total, balanced=balanced,
        context=(contour, pin, azimuth, law, centre_gap),
    )  # fmt: skip


def _arguments(contour, pin, load, azimuth, law, max_penetration):
    """The compiled kernel's tuples (see :mod:`jointwear.contact._compiled`).

    Returns ``nodes``, ``grid``, ``lines``, the gap on each load line [m] and the
    :class:`_Lines` of the azimuths.
    """
    lines = _lines(contour.nodes, azimuth)
    radius = contour.radius
    rp = pin.radius
    m = load.size
    centre_radius = lines.centre_radius(radius)
    centre_gap = centre_radius - rp
    spring = contour.dtheta * contour.axial_length
    # r - R_p is exact (Sterbenz); the symmetric law's springs lie on the circle through
    # the compression centre, one gap per load
    if law.symmetric:
        gap_ext, load_gap, gap_min = lines.zeros_padded, centre_gap, centre_gap
        check_reach(gap_min, load, azimuth, rp)
    else:
        padded_radius = radius.take(lines.padded)
        gap_ext, load_gap = padded_radius - rp, lines.zeros
        smallest = float(radius.min()) - rp
        if smallest >= PIN_REACH * rp:
            check_reach(np.full(m, smallest), load, azimuth, rp)
        gap_min = np.full(m, smallest)
    if law.force_area is not None:
        area_ext, load_area = lines.filled(float(law.force_area)), lines.ones
    elif law.symmetric:
        area_ext, load_area = lines.filled(spring), centre_radius
    else:
        area_ext, load_area = padded_radius * spring, lines.ones
    # the bracket: no node touches at the smallest gap; the pin's reach or the wall
    lower = gap_min
    upper = upper_bound(centre_gap, rp, max_penetration, lower)
    nodes, per_load = lines.arguments(gap_ext, area_ext, load_gap, load_area, gap_min, lower, upper)
    grid = lines.grid(contour.dtheta, float(rp), law)
    return nodes, grid, per_load, centre_gap, lines


def _numpy_revolution(
    contour,
    pin,
    load,
    azimuth,
    sliding,
    law,
    wear_coefficient,
    max_penetration,
    initial_offset,
    window,
    tolerance,
    max_iterations,
):
    """The NumPy path: the windowed balance, then Archard on the dense pressure."""
    warm: dict[str, Any] = {}
    if initial_offset is not None:
        warm = {"initial_offset": initial_offset, "window": window}
    solution = solve_contact(
        contour,
        pin,
        load,
        azimuth,
        law,
        tolerance=tolerance,
        max_iterations=max_iterations,
        max_penetration=max_penetration,
        **warm,
    )
    load, azimuth = checked_loads(load, azimuth)
    sliding = np.broadcast_to(np.asarray(sliding, dtype=float).ravel(), load.shape)
    unit = np.stack([np.cos(azimuth), np.sin(azimuth)], axis=1)
    offset = np.einsum("ij,ij->i", solution.eccentricity, unit)
    widest = max(float(solution.half_angle_left.max()), float(solution.half_angle_right.max()))
    return RevolutionWear(
        wear=archard_wear(solution.pressure, sliding, wear_coefficient),
        offset=offset,
        window=int(math.ceil(widest / contour.dtheta) + 3),
        iterations=solution.iterations,
        half_angle_left=solution.half_angle_left,
        half_angle_right=solution.half_angle_right,
        peak_pressure=solution.pressure.max(axis=1),
        normal_force=solution.normal_force,
        tangential_force=solution.tangential_force,
        springs_left=solution.springs_left,
        springs_right=solution.springs_right,
        solution=solution,
    )


def archard_wear(
    pressure: FloatArray, sliding_distance: FloatArray, wear_coefficient: float
) -> FloatArray:
    """Archard's wear depth of a revolution at every node [m] (the NumPy path's).

    .. math:: h_j = K_d \\sum_k p_{jk} \\, \\Delta s_k

    :func:`jointwear.tribology.archard.wear_depth`, written here as the kernel's one
    deliberate copy of a formula (the module notes); the compiled loop adds the same
    ``K_d p_jk ds_k`` load by load.

    Parameters
    ----------
    pressure : ndarray, shape (M, N)
        Pressure on node ``j`` at step ``k`` [Pa].
    sliding_distance : ndarray, shape (M,)
        Sliding distance of each step [m].
    wear_coefficient : float
        Dimensional Archard coefficient ``K_d = k / H`` [1/Pa].
    """
    return wear_coefficient * (sliding_distance @ pressure)
