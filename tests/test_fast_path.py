"""The fast load balance against the straightforward reference, batching and warm starts.

The reference (``tests/reference_impl.py``) solves every step on its own with
``scipy.optimize.brentq`` on the full node set and accumulates Archard's wear step by
step; the fast path (windows, batched bracketed Newton, warm starts, reused buffers)
must give the same pressure and wear to 1e-9 (relative to the peak).
"""

from __future__ import annotations

import threading

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config, load_config
from jointwear.contact import solve_contact
from jointwear.contact.balance.guesses import coarse_guess
from jointwear.geometry import BushingContour

from .conftest import REPO
from .reference_impl import reference_equilibrium_step, reference_revolution, reference_step

PAPER = REPO / "examples" / "paper" / "table5_nlcp_15000r.toml"
CALIBRATED = {
    "joint.axial_length": 0.01867,
    "joint.bushing_thickness": 0.003653,
    "mechanism.spring_preload": 121.8,
}
MODELS = ["winkler", "asymmetric-winkler", "nlcp"]
EPS = np.finfo(float).eps


@pytest.fixture(scope="module")
def table5() -> Config:
    """Paper Table 5 (NLCP, 120 rpm, 360 nodes x 360 steps), calibrated, one revolution.

    Without contour update in the config, so that the circular ``winkler`` (refused with
    it) is a model to solve here too; the steps below update the contour themselves.
    """
    return load_config(
        PAPER,
        overrides={
            **CALIBRATED,
            "simulation.revolutions": 1,
            "simulation.update_every": 1,
            "simulation.update_contour": False,
        },
    )


def worn_profile(nodes: int, azimuth: np.ndarray) -> np.ndarray:
    """An asymmetric worn profile over the loaded arc: a deep scar and a shallow one."""
    theta = 2 * np.pi * np.arange(nodes) / nodes
    centre = float(np.angle(np.mean(np.exp(1j * azimuth))))
    phi = np.angle(np.exp(1j * (theta - centre)))
    return 30e-6 * np.exp(-(((phi - np.radians(12)) / np.radians(25)) ** 2)) + 8e-6 * np.exp(
        -(((phi + np.radians(35)) / np.radians(10)) ** 2)
    )


def contour_for(simulation: Simulation, shape: str) -> BushingContour:
    if shape == "circle":
        return simulation.initial_contour()
    depth = worn_profile(simulation.config.contact.nodes, simulation.load_cycle.azimuth)
    joint = simulation.config.joint
    return BushingContour.from_wear_profile(joint.bushing_radius, depth, joint.axial_length)


def force_area(simulation: Simulation, contour: BushingContour) -> np.ndarray:
    """Area turning each node's pressure into its spring force, shape (M, N) [m^2]."""
    law, azimuth = simulation.law, simulation.load_cycle.azimuth
    shape = (azimuth.size, contour.nodes)
    if law.force_area is not None:
        return np.full(shape, law.force_area)
    if law.symmetric:  # springs on the circle through the compression centre
        radius = contour.radius_at(np.mod(azimuth, 2 * np.pi))
        return np.broadcast_to((radius * contour.dtheta * contour.axial_length)[:, None], shape)
    return np.broadcast_to(contour.spring_area, shape)


def assert_rows_close(fast: np.ndarray, ref: np.ndarray, rtol: float = 1e-9) -> None:
    """Every row within ``rtol`` of its own peak."""
    scale = np.maximum(np.abs(ref).max(axis=-1, keepdims=True), 1e-300)
    worst = float(np.max(np.abs(fast - ref) / scale))
    assert worst <= rtol, f"largest relative difference {worst:.3g}"


# ---------------------------------------------------------------- the oracle


@pytest.mark.parametrize("shape", ["circle", "worn"])
@pytest.mark.parametrize("model", MODELS)
def test_fast_path_matches_the_reference(table5, model, shape):
    """One revolution, 360 nodes x 360 steps: pressure of every step and the wear profile."""
    simulation = Simulation(table5.replace({"contact.model": model}))
    contour = contour_for(simulation, shape)
    load = simulation.load_cycle
    k_d = table5.materials.bushing.wear_coefficient
    solution = simulation.contact(contour)
    wear = simulation.wear_per_revolution(solution)
    pressure, ref_wear = reference_revolution(
        contour.radius,
        contour.axial_length,
        simulation.pin.radius,
        load.load,
        load.azimuth,
        simulation.law,
        simulation.sliding_distance,
        k_d,
    )
    assert_rows_close(solution.pressure, pressure)
    assert_rows_close(wear, ref_wear)
    # the balance itself: |F_total - F| <= max(1e-12 N, 8 eps sum|f_j|)
    force = solution.pressure * force_area(simulation, contour)
    phi = contour.theta[None, :] - load.azimuth[:, None]
    normal = (force * np.cos(phi)).sum(axis=1)
    bound = np.maximum(1e-12, 8 * EPS * np.abs(force).sum(axis=1))
    assert np.all(np.abs(solution.normal_force - load.load) <= bound)
    assert np.all(np.abs(normal - solution.normal_force) <= 16 * EPS * np.abs(force).sum(1))


@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp"])
def test_equilibrium_mode_matches_the_reference(table5, model):
    """Full 2-D equilibrium on the worn contour against scipy's hybrid root finder."""
    simulation = Simulation(table5.replace({"contact.model": model}))
    contour = contour_for(simulation, "worn")
    load = simulation.load_cycle
    solution = solve_contact(
        contour,
        simulation.pin,
        load.load,
        load.azimuth,
        simulation.law,
        balance="equilibrium",
        max_penetration=table5.joint.bushing_thickness,
    )
    force = solution.pressure * force_area(simulation, contour)
    bound = np.maximum(1e-12, 8 * EPS * np.abs(force).sum(axis=1))
    # the 2-D solver also accepts a residual that 4 ulps of the pin position explain
    # (one ulp of |e| ~ 70 um moves a 1e8 N/m contact by ~1.4e-12 N)
    depth = contour.penetration(simulation.pin, solution.eccentricity)
    with np.errstate(divide="ignore", invalid="ignore"):
        stiffness = np.where(depth > 0, 1.5 * force / depth, 0.0).sum(axis=1)
    ulps = 4 * EPS * np.hypot(*solution.eccentricity.T) * 2 * stiffness
    assert np.all(np.abs(solution.normal_force - load.load) <= np.maximum(bound, ulps))
    assert np.all(np.abs(solution.tangential_force) <= np.maximum(bound, ulps))
    for k in range(0, load.load.size, 30):
        pressure, _ = reference_equilibrium_step(
            contour.radius,
            contour.axial_length,
            simulation.pin.radius,
            float(load.load[k]),
            float(load.azimuth[k]),
            simulation.law,
        )
        assert_rows_close(solution.pressure[k], pressure)


# ---------------------------------------------------------------- batching and warm starts


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
@pytest.mark.parametrize("model", MODELS)
def test_batched_equals_per_load(table5, model, balance):
    """The batch (coarse-to-fine warm start, narrow window) equals load-by-load solves."""
    simulation = Simulation(table5.replace({"contact.model": model}))
    contour = contour_for(simulation, "worn")
    load = simulation.load_cycle
    options = {"balance": balance, "max_penetration": table5.joint.bushing_thickness}
    batch = solve_contact(
        contour, simulation.pin, load.load, load.azimuth, simulation.law, **options
    )
    for k in range(0, load.load.size, 23):
        one = solve_contact(
            contour,
            simulation.pin,
            load.load[k : k + 1],
            load.azimuth[k : k + 1],
            simulation.law,
            **options,
        )
        assert_rows_close(batch.pressure[k], one.pressure[0])
        np.testing.assert_allclose(
            batch.eccentricity[k], one.eccentricity[0], rtol=1e-10, atol=1e-17
        )


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
def test_warm_starts_give_the_cold_answer(table5, balance):
    """Warm starts (previous offsets, extrapolated, narrow window) change nothing."""
    simulation = Simulation(table5.replace({"contact.balance": balance}))
    contour = contour_for(simulation, "worn")
    load = simulation.load_cycle
    cold = simulation.contact(contour)
    along = cold.eccentricity[:, 0] * np.cos(load.azimuth) + cold.eccentricity[:, 1] * np.sin(
        load.azimuth
    )
    for guess, window in ((along, 4), (along * (1 + 1e-3), 60), (along * 0.97, None)):
        warm = solve_contact(
            contour,
            simulation.pin,
            load.load,
            load.azimuth,
            simulation.law,
            balance=balance,
            initial_offset=guess,
            window=window,
            max_penetration=table5.joint.bushing_thickness,
        )
        assert_rows_close(warm.pressure, cold.pressure)


def test_simulation_steps_use_the_extrapolated_warm_start(table5):
    """After a few per-revolution updates the warm-started solve equals a cold one."""
    simulation = Simulation(
        table5.replace({"simulation.revolutions": 10, "simulation.update_contour": True})
    )
    state = simulation.initial_state()
    for _ in range(4):
        state = simulation.step(state)
    assert state.warm_slope is not None
    contour = simulation.solver.contour(state.wear_depth)
    warm = simulation.contact(contour, state)
    cold = simulation.contact(contour)
    assert_rows_close(warm.pressure, cold.pressure)


def test_no_update_wear_is_exactly_linear(table5):
    """Without contour update the wear of n revolutions is n times the reference revolution."""
    config = table5.replace({"simulation.revolutions": 1000, "simulation.update_contour": False})
    simulation = Simulation(config)
    result = simulation.run()
    contour = simulation.initial_contour()
    load = simulation.load_cycle
    _, wear = reference_revolution(
        contour.radius,
        contour.axial_length,
        simulation.pin.radius,
        load.load,
        load.azimuth,
        simulation.law,
        simulation.sliding_distance,
        config.materials.bushing.wear_coefficient,
    )
    assert_rows_close(result.wear_depth, 1000 * wear)
    revolutions = result.dataset["update_revolution"].values
    peaks = result.dataset["peak_wear_depth"].values
    np.testing.assert_allclose(peaks / revolutions, peaks[-1] / revolutions[-1], rtol=1e-12)


def test_reference_step_is_the_paper_balance(table5):
    """The oracle itself: its pressure balances the load to round-off."""
    simulation = Simulation(table5)
    contour = contour_for(simulation, "worn")
    law = simulation.law
    pressure, offset = reference_step(
        contour.radius, contour.axial_length, simulation.pin.radius, 250.0, 3.0, law
    )
    phi = contour.theta - 3.0
    force = pressure * law.force_area
    assert abs(float(np.sum(force * np.cos(phi))) - 250.0) < 1e-9
    assert offset > contour.radius.min() - simulation.pin.radius


# ---------------------------------------------------------------- cold starts


@pytest.mark.parametrize("model", MODELS)
def test_coarse_pass_guesses_a_worn_contour(table5, model):
    """A cold batch on a worn contour solves every 8th load with two steps and one more,
    unevaluated (polish), and interpolates the rest: most guesses are within ~1e-5 of the
    penetration, none far off (the evaluations a load take: ``benchmarks/bench_simulation.py
    --only evaluations``)."""
    simulation = Simulation(table5.replace({"contact.model": model}))
    contour = contour_for(simulation, "worn")
    load = simulation.load_cycle
    guess, widest = coarse_guess(
        contour,
        simulation.pin,
        simulation.law,
        load.load,
        load.azimuth,
        1e-12,
        100,
        table5.joint.bushing_thickness,
        None,
    )
    solution = simulation.contact(contour)
    along = solution.eccentricity[:, 0] * np.cos(load.azimuth) + solution.eccentricity[
        :, 1
    ] * np.sin(load.azimuth)
    error = np.abs(guess - along) / (along - (contour.radius.min() - simulation.pin.radius))
    assert np.median(error) < 1e-4
    assert error.max() < 1e-2
    # the window is 1.05 times the widest coarse contact + 3 nodes
    half = np.maximum(solution.half_angle_left, solution.half_angle_right).max()
    assert abs(widest - half) < 0.05 * half


# ---------------------------------------------------------------- buffers and caches


def test_threads_do_not_share_scratch_buffers(table5):
    """Each thread has its own scratch buffers: concurrent solves give the serial answer."""
    simulation = Simulation(table5)
    load = simulation.load_cycle
    contours = [contour_for(simulation, "circle"), contour_for(simulation, "worn")]
    serial = [simulation.contact(c).pressure for c in contours]
    results: dict[int, np.ndarray] = {}

    def work(i: int) -> None:
        for _ in range(3):
            results[i] = solve_contact(
                contours[i % 2],
                simulation.pin,
                load.load,
                load.azimuth,
                simulation.law,
                max_penetration=table5.joint.bushing_thickness,
            ).pressure

    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    for i in range(4):
        np.testing.assert_array_equal(results[i], serial[i % 2])


def test_cached_window_geometry_follows_the_azimuths(table5):
    """The window geometry is cached by azimuths: a new load set must not reuse it."""
    simulation = Simulation(table5)
    contour = contour_for(simulation, "worn")
    load = simulation.load_cycle
    first = solve_contact(contour, simulation.pin, load.load, load.azimuth, simulation.law)
    turned = solve_contact(
        contour.rotated(7),
        simulation.pin,
        load.load,
        load.azimuth + 7 * contour.dtheta,
        simulation.law,
    )
    assert_rows_close(turned.pressure, np.roll(first.pressure, 7, axis=1))


def test_warm_revolution_balances_every_load(table5):
    """Inside a run, warm-started: every load within tolerance, the cold answer (the
    evaluations a load take: ``benchmarks/bench_simulation.py --only evaluations``)."""
    simulation = Simulation(
        table5.replace({"simulation.revolutions": 20, "simulation.update_every": 1})
    )
    state = simulation.initial_state()
    for _ in range(6):
        state = simulation.step(state)
    contour = simulation.solver.contour(state.wear_depth)
    warm = simulation.contact(contour, state)
    load = simulation.load_cycle.load
    force = warm.pressure * force_area(simulation, contour)
    bound = np.maximum(1e-12, 8 * EPS * np.abs(force).sum(axis=1))
    assert np.all(np.abs(warm.normal_force - load) <= bound)
    assert_rows_close(warm.pressure, simulation.contact(contour).pressure)
