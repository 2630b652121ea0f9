"""The compiled revolution (balance + Archard in one loop) against the NumPy path, the
plain statement of the balance and Archard's law.

Both balance every load to round-off, so they agree to 1e-12 relative in wear and in
force balance; the dense pressure, assembled only on request, matches as well. Both
are held to the reference (:mod:`jointwear.contact.balance.paper` and
:func:`jointwear.tribology.archard.wear_depth`) at 1e-9, and their own Archard sums to
``wear_depth`` of their pressure at 1e-12.
"""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import load_config
from jointwear.contact import kernel
from jointwear.contact.balance.paper import paper_balance, paper_pressure
from jointwear.contact.kernel import revolution_wear
from jointwear.geometry import BushingContour
from jointwear.tribology.archard import wear_depth

from ..conftest import REPO
from ..test_fast_path import CALIBRATED, PAPER, worn_profile

MODELS = ["winkler", "asymmetric-winkler", "nlcp"]

needs_numba = pytest.mark.skipif(
    not kernel.compiled_available(), reason="numba missing or JOINTWEAR_NO_NUMBA set"
)
#: both paths of :func:`revolution_wear`: the NumPy one runs without numba too
PATHS = [pytest.param(False, id="numpy"), pytest.param(True, id="compiled", marks=needs_numba)]


@pytest.fixture(scope="module")
def config():
    # (without contour update: the circular winkler is one of the models solved here)
    return load_config(
        PAPER,
        overrides={
            **CALIBRATED,
            "simulation.revolutions": 1,
            "simulation.update_every": 1,
            "simulation.update_contour": False,
        },
    )


def revolution_inputs(config, model: str, shape: str):
    simulation = Simulation(config.replace({"contact.model": model}))
    load = simulation.load_cycle
    joint = config.joint
    if shape == "circle":
        contour = simulation.initial_contour()
    else:
        depth = worn_profile(config.contact.nodes, load.azimuth)
        contour = BushingContour.from_wear_profile(joint.bushing_radius, depth, joint.axial_length)
    args = (
        contour,
        simulation.pin,
        load.load,
        load.azimuth,
        simulation.sliding_distance,
        simulation.law,
        config.materials.bushing.wear_coefficient,
    )
    return args, {"max_penetration": joint.bushing_thickness}


def relative(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


@needs_numba
@pytest.mark.parametrize("shape", ["circle", "worn"])
@pytest.mark.parametrize("model", MODELS)
def test_compiled_equals_numpy(config, model, shape):
    """Wear, force balance, offsets, extents and the dense pressure, cold and warm."""
    args, options = revolution_inputs(config, model, shape)
    load = args[2]
    numpy_path = revolution_wear(*args, compiled=False, **options)
    for warm in (None, numpy_path.offset * (1 + 1e-7)):
        fast = revolution_wear(*args, compiled=True, initial_offset=warm, **options)
        assert relative(fast.wear, numpy_path.wear) <= 1e-12
        for result in (fast, numpy_path):
            assert np.all(np.abs(result.normal_force - load) <= 1e-12 * load)
        assert relative(fast.offset, numpy_path.offset) <= 1e-12
        np.testing.assert_array_equal(fast.springs_left, numpy_path.springs_left)
        np.testing.assert_array_equal(fast.springs_right, numpy_path.springs_right)
        np.testing.assert_allclose(fast.half_angle_left, numpy_path.half_angle_left, atol=1e-12)
        np.testing.assert_allclose(fast.half_angle_right, numpy_path.half_angle_right, atol=1e-12)
        assert relative(fast.tangential_force, numpy_path.tangential_force) <= 1e-9
        dense, reference = fast.solution().pressure, numpy_path.solution().pressure
        assert relative(dense, reference) <= 1e-12
        np.testing.assert_allclose(fast.peak_pressure, reference.max(axis=1), rtol=1e-12)


@needs_numba
@pytest.mark.parametrize("model", MODELS)
def test_fast_solvers_solve_the_stated_balance(config, model):
    """The plain statement of eqs. (5)/(7) on every node (balance.paper) gives the offsets
    of the compiled kernel and of the NumPy window solver."""
    args, options = revolution_inputs(config, model, "worn")
    contour, pin, load, azimuth, _, law, _ = args
    rows = slice(0, None, 12)
    stated = paper_balance(contour, pin, load[rows], azimuth[rows], law)
    for compiled in (True, False):
        result = revolution_wear(*args, compiled=compiled, **options)
        assert relative(result.offset[rows], stated) <= 1e-12


@pytest.mark.parametrize("compiled", PATHS)
@pytest.mark.parametrize("shape", ["circle", "worn"])
@pytest.mark.parametrize("model", MODELS)
def test_revolution_wear_is_the_reference_wear(config, model, shape, compiled):
    """Every 12th step of the paper's revolution: the wear of eqs. (5)/(7) solved plainly on
    every node (balance.paper) and of Archard's law (tribology.archard), to 1e-9."""
    args, options = revolution_inputs(config, model, shape)
    contour, pin, load, azimuth, sliding, law, k_d = args
    rows = slice(0, None, 12)
    steps = (load[rows].copy(), azimuth[rows].copy(), sliding[rows].copy())
    result = revolution_wear(contour, pin, *steps, law, k_d, compiled=compiled, **options)
    offset = paper_balance(contour, pin, steps[0], steps[1], law)
    pressure = paper_pressure(contour, pin, offset, steps[1], law)
    assert relative(result.wear, wear_depth(pressure, steps[2], k_d)) <= 1e-9


@pytest.mark.parametrize("compiled", PATHS)
@pytest.mark.parametrize("model", MODELS)
def test_fused_wear_is_archards(config, model, compiled):
    """The kernel adds Archard's ``K_d p ds`` itself (its one copy of a formula): cold and
    warm, its wear is tribology.archard's of its own pressure to 1e-12 relative."""
    args, options = revolution_inputs(config, model, "worn")
    sliding, k_d = args[4], args[6]
    cold = revolution_wear(*args, compiled=compiled, **options)
    guess = cold.offset * (1 + 1e-7)
    warm = revolution_wear(
        *args, compiled=compiled, initial_offset=guess, window=cold.window, **options
    )
    for result in (cold, warm):
        expected = wear_depth(result.solution().pressure, sliding, k_d)
        assert relative(result.wear, expected) <= 1e-12


@needs_numba
def test_dense_pressure_is_the_balanced_state(config):
    """The pressure assembled on request is the state the balance accepted: its Archard
    wear is the accumulated one, and its resultant the reported force."""
    args, options = revolution_inputs(config, "nlcp", "worn")
    contour, _, load, azimuth, sliding, law, k_d = args
    result = revolution_wear(*args, **options)
    solution = result.solution()
    assert solution.loads == load.size
    assert "pressure" not in vars(solution)  # not assembled until read
    pressure = solution.pressure
    np.testing.assert_allclose(k_d * (sliding @ pressure), result.wear, rtol=1e-12, atol=0)
    phi = contour.theta[None, :] - azimuth[:, None]
    normal = (pressure * law.force_area * np.cos(phi)).sum(axis=1)
    np.testing.assert_allclose(normal, result.normal_force, rtol=1e-13)


@needs_numba
@pytest.mark.parametrize("model", MODELS)
def test_contact_fields_are_evaluated_when_read(config, model):
    """The compiled path evaluates the extent, peak, tangential force and springs only
    when one is read, from the balanced state: every node of the dense pressure in
    contact is counted once, on its side of the load line, and reading the pressure
    first gives the same fields."""
    args, options = revolution_inputs(config, model, "worn")
    azimuth = args[3]
    result = revolution_wear(*args, **options)
    evaluated = ("half_angle_left", "half_angle_right", "peak_pressure", "tangential_force",
                 "springs_left", "springs_right")  # fmt: skip
    assert not set(evaluated) & set(vars(result))
    left, right = result.springs_left, result.springs_right
    pressure = revolution_wear(*args, **options).solution().pressure
    np.testing.assert_array_equal(left + right, (pressure > 0).sum(axis=1))
    nodes = pressure.shape[1]
    offset = np.angle(np.exp(1j * (np.arange(nodes) * 2 * np.pi / nodes - azimuth[:, None])))
    np.testing.assert_array_equal(left, ((pressure > 0) & (offset > 0)).sum(axis=1))
    again = revolution_wear(*args, **options)
    _ = again.solution().pressure
    for name in evaluated:
        np.testing.assert_array_equal(getattr(again, name), getattr(result, name))
    np.testing.assert_array_equal(result.peak_pressure, pressure.max(axis=1))


@needs_numba
def test_simulation_steps_match_the_numpy_path(config):
    """Ten per-revolution updates with the kernel and with the NumPy path."""
    cfg = config.replace({"simulation.revolutions": 10, "simulation.update_contour": True})
    depths = []
    for switch in ("0", "1"):
        os.environ["JOINTWEAR_NO_NUMBA"] = switch
        try:
            simulation = Simulation(cfg)
            state = simulation.initial_state()
            for _ in range(10):
                state = simulation.step(state)
        finally:
            del os.environ["JOINTWEAR_NO_NUMBA"]
        depths.append(state.wear_depth)
    assert relative(depths[0], depths[1]) <= 1e-12


@needs_numba
def test_zero_loads_and_errors(config):
    """No load: the pin touches, no wear; a load through the wall raises ContactError."""
    args, options = revolution_inputs(config, "nlcp", "circle")
    contour, pin, load, azimuth, sliding, law, k_d = args
    some = load.copy()
    some[::5] = 0.0
    result = revolution_wear(contour, pin, some, azimuth, sliding, law, k_d, **options)
    numpy_path = revolution_wear(
        contour, pin, some, azimuth, sliding, law, k_d, compiled=False, **options
    )
    assert relative(result.wear, numpy_path.wear) <= 1e-12
    assert np.all(result.peak_pressure[::5] == 0.0)
    from jointwear.errors import ContactError

    with pytest.raises(ContactError, match="through the bushing wall"):
        revolution_wear(contour, pin, 1e9 * load, azimuth, sliding, law, k_d, **options)


@needs_numba
@pytest.mark.parametrize("model", MODELS)
def test_warm_inputs_checked_as_cold(config, model):
    """A warm start builds the contour's arguments in the compiled loop: the same result as
    from lists (the general path), and the same errors for a load that is not finite or
    negative and for a pin that does not fit."""
    from jointwear.errors import ContactError, GeometryError
    from jointwear.geometry import Pin

    args, options = revolution_inputs(config, model, "worn")
    contour, pin, load, azimuth, sliding, law, k_d = args
    guess = revolution_wear(*args, **options).offset * (1 + 1e-7)
    warm = revolution_wear(*args, initial_offset=guess, **options)
    listed = revolution_wear(
        contour, pin, load.tolist(), azimuth.tolist(), sliding, law, k_d,
        initial_offset=guess.tolist(), **options,
    )  # fmt: skip
    assert relative(warm.wear, listed.wear) <= 1e-12
    assert relative(warm.offset, listed.offset) <= 1e-12
    assert relative(warm.solution().eccentricity, listed.solution().eccentricity) <= 1e-12
    for bad, match in ((np.nan, "finite"), (np.inf, "finite"), (-1.0, ">= 0")):
        broken = load.copy()
        broken[7] = bad
        with pytest.raises(ContactError, match=match):
            revolution_wear(
                contour, pin, broken, azimuth, sliding, law, k_d, initial_offset=guess,
                **options,
            )  # fmt: skip
    with pytest.raises(GeometryError, match="clearance"):
        revolution_wear(
            contour, Pin(float(contour.radius.min())), load, azimuth, sliding, law, k_d,
            initial_offset=guess, **options,
        )  # fmt: skip


@needs_numba
def test_numba_is_imported_only_when_used():
    """``import jointwear`` (and a whole simulation object) does not import numba."""
    code = (
        "import sys, jointwear, jointwear.simulation, jointwear.contact.kernel; "
        "print('numba' in sys.modules)"
    )
    env = {**os.environ, "PYTHONPATH": str(REPO / "src")}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env
    )
    assert out.stdout.strip() == "False"


@needs_numba
@pytest.mark.parametrize("shape", ["circle", "worn"])
@pytest.mark.parametrize("model", MODELS)
def test_warm_arguments_are_the_numpy_ones(config, model, shape):
    """The compiled warm entry fills the kernel's arguments with the NumPy expressions of
    the general path, evaluated in one loop: every array and constant the same, to
    round-off (the compiler may contract a product and a sum). Gaps are differences of
    radii: their round-off is a few ulp of the radius, not of the gap."""
    args, options = revolution_inputs(config, model, shape)
    contour, pin, load, azimuth, sliding, law, k_d = args
    reach = options["max_penetration"]
    revolutions = kernel.WarmRevolutions.of(
        pin, load, azimuth, sliding, law, k_d, nodes=contour.nodes,
        axial_length=contour.axial_length, max_penetration=reach,
    )  # fmt: skip
    warm = revolutions.arguments(contour)
    assert warm is not None
    cold = kernel._arguments(contour, pin, load, azimuth, law, reach)
    radius_ulps = 4 * np.finfo(float).eps * float(contour.radius.max())
    # (nodes, grid, lines): the positions of the gaps in each tuple
    gaps = ({0}, set(), {3, 5, 6, 7})
    for built, expected, gap in zip(warm[:3], cold[:3], gaps, strict=True):
        assert len(built) == len(expected)
        for position, (a, b) in enumerate(zip(built, expected, strict=True)):
            atol = radius_ulps if position in gap else 0.0
            np.testing.assert_allclose(a, b, rtol=4e-16, atol=atol)
    np.testing.assert_allclose(warm[3], cold[3], rtol=0, atol=radius_ulps)


def printed_by(code: str) -> list[str]:
    """What ``code`` prints in a fresh interpreter (its own numba dispatchers), by word."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO / "src"), str(REPO)])}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env,
        cwd=REPO,
    )  # fmt: skip
    return out.stdout.split()


@needs_numba
def test_one_compiled_variant_of_the_kernel():
    """Cold and warm revolutions, read-only and scalar inputs and a whole run reach the
    compiled kernel with the same array types: numba compiles (and caches) one variant,
    not one per combination of read-only or strided arrays (~8 s each on a new machine)."""
    code = """
import numpy as np
from jointwear import Simulation
from jointwear.config import load_config
from jointwear.contact import kernel
from tests.test_fast_path import CALIBRATED, PAPER
config = load_config(PAPER, overrides={**CALIBRATED, "simulation.revolutions": 600,
                                       "simulation.update_every": 1})
simulation = Simulation(config)
state = simulation.initial_state()
for _ in range(3):
    state = simulation.step(state)
cycle = simulation.load_cycle
contour = simulation.solver.contour(state.wear_depth)
args = (contour, simulation.pin, cycle.load, cycle.azimuth)
rest = (simulation.law, config.materials.bushing.wear_coefficient)
guess = state.warm_offset  # read-only
kernel.revolution_wear(*args, simulation.sliding_distance, *rest, initial_offset=guess)
kernel.revolution_wear(*args, 1e-4, *rest)  # one sliding distance for every step
kernel.revolution_wear(*args, 1e-4, *rest, initial_offset=guess.tolist())
module = kernel._compiled()
print(len(module.revolution.signatures), len(module.prepare.signatures))
"""
    assert printed_by(code) == ["1", "1"]


@needs_numba
def test_one_compiled_variant_of_the_fields_read_later():
    """The fields evaluated on read and the dense pressure reach ``balanced_state`` with
    one set of array types, whichever is read first: one compiled variant."""
    code = """
from jointwear import Simulation
from jointwear.config import load_config
from jointwear.contact import kernel
from tests.test_fast_path import CALIBRATED, PAPER
config = load_config(PAPER, overrides={**CALIBRATED, "simulation.revolutions": 1})
simulation = Simulation(config)
cycle = simulation.load_cycle
args = (simulation.initial_contour(), simulation.pin, cycle.load, cycle.azimuth, 1e-4,
        simulation.law, config.materials.bushing.wear_coefficient)
first = kernel.revolution_wear(*args)
first.springs_left  # the fields alone: a pressure of no rows
second = kernel.revolution_wear(*args, initial_offset=first.offset.tolist())
second.solution().pressure  # the pressure, and the fields with it
print(len(kernel._compiled().balanced_state.signatures), int(second.springs_left.sum() > 0))
"""
    assert printed_by(code) == ["1", "1"]


def test_a_revolution_is_read_only(config):
    """A revolution's result cannot be changed after the fact (a run keeps its wear
    uncopied), nor built with fields it does not have."""
    args, options = revolution_inputs(config, "nlcp", "circle")
    result = revolution_wear(*args, compiled=False, **options)
    with pytest.raises(AttributeError, match="read-only"):
        result.wear = result.wear * 2
    with pytest.raises(AttributeError, match="read-only"):
        del result.offset
    with pytest.raises(TypeError, match="unknown fields"):
        kernel.RevolutionWear(result.wear, result.offset, 3, result.iterations,
                              result.normal_force, peak=1.0)  # fmt: skip
