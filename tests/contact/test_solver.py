"""The contact solve factory: every path it picks gives the contact (and wear) of the others."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.contact.kernel import compiled_available
from jointwear.contact.solver import (
    COMPILED_KERNEL_SOLVES,
    ContactSolver,
    WarmStart,
    compiled_kernel,
)
from jointwear.errors import ConfigError
from jointwear.geometry import BushingContour
from jointwear.mechanism import LoadCycle
from jointwear.tribology.archard import wear_depth
from tests.conftest import scar

STEPS = 48


@pytest.fixture(scope="module")
def config(paper_config: Config) -> Config:
    return paper_config.replace(
        {"contact.nodes": 120, "contact.model": "asymmetric-winkler", "simulation.revolutions": 1}
    )


@pytest.fixture(scope="module")
def cycle() -> LoadCycle:
    """A load swinging +-40 degrees about the x axis, 150-250 N, turning the pin once."""
    phase = 2 * np.pi * np.arange(STEPS) / STEPS
    return LoadCycle.from_arrays(
        200 + 50 * np.cos(phase), 0.7 * np.sin(phase), np.full(STEPS, 2 * np.pi / STEPS)
    )


@pytest.fixture(scope="module")
def contour(config: Config) -> BushingContour:
    joint = config.joint
    return BushingContour.from_wear_profile(
        joint.bushing_radius, scar(config.contact.nodes, depth=15e-6), joint.axial_length
    )


def sliding_of(config: Config, cycle: LoadCycle) -> np.ndarray:
    return config.joint.bushing_radius * np.abs(cycle.relative_rotation)


def close(a: np.ndarray, b: np.ndarray, rtol: float = 1e-9) -> None:
    np.testing.assert_allclose(a, b, rtol=0, atol=rtol * float(np.abs(b).max()))


@pytest.mark.parametrize("compiled", [False, True], ids=["numpy", "compiled"])
def test_the_fused_path_wears_as_archards_law_on_the_general_solve(
    config, cycle, contour, compiled
):
    """The fused path (Archard accumulated with the balance; compiled: inside the kernel)
    against the general solve with Archard's law on its pressure, ``h_j = K_d sum_k p_jk
    ds_k``."""
    if compiled and not compiled_available():
        pytest.skip("numba is not installed")
    fused = ContactSolver.from_config(config, "asymmetric-winkler", fused_archard=True)
    fused.compiled = compiled
    plain = ContactSolver.from_config(config, "asymmetric-winkler", fused_archard=False)
    sliding = sliding_of(config, cycle)
    k_d = config.materials.bushing.wear_coefficient

    def archard(pressure, distance):
        return wear_depth(pressure, distance, k_d)

    solved = fused.solve(contour, cycle, sliding=sliding)
    general = plain.solve(contour, cycle, sliding=sliding)
    # the compiled kernel's solution carries its wear; no wear coefficient: the general path
    assert (getattr(solved, "revolution", None) is not None) is compiled
    assert getattr(general, "revolution", None) is None
    wear = fused.wear_per_revolution(solved, archard, sliding)
    reference = plain.wear_per_revolution(general, archard, sliding)
    assert wear.max() > 0
    close(wear, reference)
    close(solved.pressure, general.pressure)


def test_outside_the_loop_the_solve_is_the_general_one(config, cycle, contour):
    """Without the sliding distance (a result's snapshots) no wear is accumulated."""
    solver = ContactSolver.from_config(config, "asymmetric-winkler", fused_archard=True)
    assert getattr(solver.solve(contour, cycle), "revolution", None) is None


def test_a_worn_pin_that_has_not_worn_yet_is_the_general_solve(config, cycle, contour):
    """Each step on its own contour (bushing + the pin's wear facing it): with no pin wear,
    every step's contour is the bushing's, so the steps are those of one solve."""
    solver = ContactSolver.from_config(config, "asymmetric-winkler", fused_archard=False)
    facing = np.zeros((STEPS, config.contact.nodes))
    per_step = solver.solve(contour, cycle, facing=facing)
    whole = solver.solve(contour, cycle)
    close(per_step.pressure, whole.pressure)
    np.testing.assert_allclose(per_step.normal_force, cycle.load, rtol=1e-9)


def test_a_warm_start_extrapolates_the_offsets_along_their_trend():
    offset, slope = np.array([1e-5, 2e-5]), np.array([1e-8, -1e-8])
    warm = WarmStart(offset, slope, 7)
    assert warm.guess(0) is offset
    np.testing.assert_array_equal(warm.guess(1), offset + slope)
    np.testing.assert_allclose(warm.guess(40), offset + 40 * slope, rtol=1e-15)
    assert WarmStart(offset, None, 7).guess(40) is offset


def test_the_warm_start_is_the_pin_offset_along_each_load(config, cycle, contour):
    """The general solve's eccentricity projected on the load direction is the offset the
    fused kernel keeps; the trend is the change per revolution between two solves."""
    fused = ContactSolver.from_config(config, "asymmetric-winkler", fused_archard=True)
    plain = ContactSolver.from_config(config, "asymmetric-winkler", fused_archard=False)
    sliding = sliding_of(config, cycle)
    kernel = fused.warm_start(fused.solve(contour, cycle, sliding=sliding), contour, cycle.azimuth)
    general = plain.warm_start(plain.solve(contour, cycle), contour, cycle.azimuth)
    close(general.warm_offset, kernel.warm_offset)
    assert kernel.warm_slope is None
    later = plain.warm_start(
        plain.solve(contour, cycle), contour, cycle.azimuth, general.warm_offset - 4e-9, 4
    )
    np.testing.assert_allclose(later.warm_slope, 1e-9, rtol=1e-6)
    # (the window holds the widest contact of the solve)
    assert 3 < general.window < config.contact.nodes // 2


def test_the_compiled_kernel_loads_only_for_runs_that_pay_for_it(config):
    """Up to the bound the NumPy path serves (False); above it the kernel where it can."""
    few = config.replace(
        {
            "simulation.revolutions": COMPILED_KERNEL_SOLVES,
            "simulation.update_contour": True,
            "simulation.update_every": 1,
        }
    )
    assert few.simulation.contact_solves <= COMPILED_KERNEL_SOLVES
    assert compiled_kernel(few) is False
    many = few.replace({"simulation.revolutions": 4 * COMPILED_KERNEL_SOLVES})
    assert compiled_kernel(many) is None


def test_a_model_that_cannot_follow_a_worn_contour_is_refused(config):
    updating = config.replace({"simulation.update_contour": True})
    with pytest.raises(ConfigError, match="contact.model: 'winkler'"):
        ContactSolver.from_config(updating, "winkler", fused_archard=True)
