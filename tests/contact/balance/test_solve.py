"""The windowed load balance (:func:`jointwear.contact.balance.solve_contact`): the
balance met, symmetries, batching, warm starts, windows, errors and custom laws."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from jointwear.contact import CONTACT_MODELS, contact_law, solve, solve_contact
from jointwear.errors import ContactError, GeometryError
from jointwear.geometry import BushingContour, Pin

from .common import (
    AZIMUTHS,
    EPS,
    LOADS,
    PAPER_MODELS,
    SPRING_MODELS,
    bound,
    force_area,
    pin_frame,
    resultants,
    revolution_loads,
)


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
@pytest.mark.parametrize("model", [*PAPER_MODELS, "mesh-independent nlcp"])
@pytest.mark.parametrize("shape", ["circle", "worn"])
def test_balance_is_met_for_every_model(params, pin, circle, worn, model, balance, shape):
    contour = circle if shape == "circle" else worn
    if model == "mesh-independent nlcp":
        params, model = dataclasses.replace(params, nlcp_variant="mesh-independent"), "nlcp"
    assert model in CONTACT_MODELS or model == "nlcp"
    sol = solve(contour, pin, LOADS, AZIMUTHS, model, params, balance=balance)
    area = contour.spring_area if model == "hertz" else force_area(model, contour, params, AZIMUTHS)
    normal, tangential, total = resultants(sol, contour, area, AZIMUTHS)
    assert np.all(np.isfinite(sol.pressure))
    assert np.all(sol.pressure >= 0)
    # |F_total - F| <= max(1e-12 N, 8 eps sum|f_j|): the paper's 1e-12 N with a round-off floor
    assert np.all(np.abs(sol.normal_force - LOADS) <= bound(total))
    # the reported resultant is the pressure's resultant (independent sum, other order)
    assert np.all(np.abs(normal - sol.normal_force) <= 16 * EPS * total + 1e-15)
    assert np.all(np.abs(tangential - sol.tangential_force) <= 16 * EPS * total + 1e-15)
    if balance == "equilibrium" and model != "hertz":
        assert np.all(np.abs(sol.tangential_force) <= bound(total))
    assert sol.model == model
    assert sol.pressure.shape == (LOADS.size, contour.nodes)


@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp"])
@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
def test_pressure_is_the_law_of_the_exact_penetration_at_every_node(
    params, pin, worn, model, balance
):
    """No node outside the solver's window may touch: check all N nodes, exactly."""
    sol = solve(worn, pin, LOADS, AZIMUTHS, model, params, balance=balance)
    law = contact_law(model, params)
    delta = worn.penetration(pin, sol.eccentricity)
    np.testing.assert_allclose(
        sol.pressure, law.pressure(delta), rtol=1e-10, atol=1e-12 * sol.pressure.max()
    )
    # the compression-centre penetration is measured along the load line (exact ray distance)
    rp = pin.radius
    a, b = pin_frame(sol, AZIMUTHS)
    expected = np.maximum(a + np.sqrt(rp**2 - b**2) - worn.radius_at(AZIMUTHS), 0.0)
    np.testing.assert_allclose(sol.penetration, expected, rtol=1e-9, atol=1e-16)


def test_zero_load_gives_no_pressure(params, pin, circle):
    for model in SPRING_MODELS:
        sol = solve(circle, pin, [0.0], [0.3], model, params)
        assert sol.normal_force[0] == 0.0
        assert sol.pressure.max() == 0.0


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp", "winkler"])
def test_rotation_invariance(params, pin, worn, model, balance):
    loads = np.array([30.0, 200.0, 400.0])
    azimuth = np.array([0.0, 0.31, -0.2])
    base = solve(worn, pin, loads, azimuth, model, params, balance=balance)
    for k in (1, 45, 200, -77):
        turned = worn.rotated(k)
        sol = solve(turned, pin, loads, azimuth + k * worn.dtheta, model, params, balance=balance)
        scale = base.pressure.max()
        np.testing.assert_allclose(
            sol.pressure, np.roll(base.pressure, k, axis=1), rtol=1e-9, atol=1e-10 * scale
        )
        np.testing.assert_allclose(sol.penetration, base.penetration, rtol=1e-9, atol=1e-17)
        np.testing.assert_allclose(
            sol.tangential_force, base.tangential_force, rtol=1e-7, atol=1e-11
        )
        np.testing.assert_array_equal(sol.springs_left, base.springs_left)
        np.testing.assert_array_equal(sol.springs_right, base.springs_right)
        # the eccentricity rotates with the contour
        angle = k * worn.dtheta
        rot = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
        np.testing.assert_allclose(
            sol.eccentricity, base.eccentricity @ rot.T, rtol=1e-9, atol=1e-16
        )


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp"])
@pytest.mark.parametrize("node", [0, 17])
def test_mirror_symmetry(params, pin, worn, model, balance, node):
    """Mirroring the contour about the load line mirrors the pressure."""
    n = worn.nodes
    mirrored = BushingContour(
        worn.radius[(2 * node - np.arange(n)) % n], worn.axial_length, worn.original_radius
    )
    azimuth = np.full(3, node * worn.dtheta)
    loads = np.array([20.0, 200.0, 400.0])
    a = solve(worn, pin, loads, azimuth, model, params, balance=balance)
    b = solve(mirrored, pin, loads, azimuth, model, params, balance=balance)
    scale = a.pressure.max()
    np.testing.assert_allclose(
        b.pressure, a.pressure[:, (2 * node - np.arange(n)) % n], rtol=1e-9, atol=1e-10 * scale
    )
    np.testing.assert_allclose(b.tangential_force, -a.tangential_force, rtol=1e-8, atol=1e-11)
    np.testing.assert_array_equal(b.springs_left, a.springs_right)
    np.testing.assert_allclose(b.half_angle_left, a.half_angle_right, rtol=1e-9)
    along_a, across_a = pin_frame(a, azimuth)
    along_b, across_b = pin_frame(b, azimuth)
    np.testing.assert_allclose(along_b, along_a, rtol=1e-12)
    np.testing.assert_allclose(across_b, -across_a, rtol=1e-8, atol=1e-17)


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp", "winkler"])
def test_batch_equals_one_by_one(params, pin, worn, model, balance):
    """>= 64 loads take the coarse-to-fine warm start with a narrow window."""
    rng = np.random.default_rng(5)
    loads = rng.uniform(50, 400, 100)
    azimuth = np.radians(rng.uniform(-25, 25, 100))
    batch = solve(worn, pin, loads, azimuth, model, params, balance=balance)
    for i in range(0, 100, 7):
        one = solve(worn, pin, loads[i : i + 1], azimuth[i : i + 1], model, params, balance=balance)
        np.testing.assert_allclose(
            batch.pressure[i], one.pressure[0], rtol=1e-9, atol=1e-10 * one.pressure.max()
        )
        np.testing.assert_allclose(
            batch.eccentricity[i], one.eccentricity[0], rtol=1e-10, atol=1e-17
        )


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
def test_warm_start_gives_the_same_answer(params, pin, worn, balance):
    loads = np.linspace(50, 400, 20)
    azimuth = np.radians(np.linspace(-25, 25, 20))
    cold = solve(worn, pin, loads, azimuth, "nlcp", params, balance=balance)
    along, _ = pin_frame(cold, azimuth)
    for guess in (along, along * 1.02, np.full(20, pin.radius * 0.5), np.zeros(20)):
        warm = solve(
            worn, pin, loads, azimuth, "nlcp", params, balance=balance, initial_offset=guess
        )
        np.testing.assert_allclose(
            warm.pressure, cold.pressure, rtol=1e-9, atol=1e-10 * cold.pressure.max()
        )


@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
@pytest.mark.parametrize("window", [2, 5, 12])
def test_window_widening_matches_full_window(params, pin, worn, balance, window):
    loads = np.array([10.0, 200.0, 400.0])
    azimuth = np.array([0.0, 0.2, -0.35])
    full = solve(worn, pin, loads, azimuth, "asymmetric-winkler", params, balance=balance)
    narrow = solve(
        worn, pin, loads, azimuth, "asymmetric-winkler", params, balance=balance, window=window
    )
    np.testing.assert_allclose(
        narrow.pressure, full.pressure, rtol=1e-9, atol=1e-10 * full.pressure.max()
    )
    np.testing.assert_array_equal(narrow.springs_left, full.springs_left)
    np.testing.assert_array_equal(narrow.springs_right, full.springs_right)


@pytest.mark.parametrize("model", [*SPRING_MODELS, "hertz"])
@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
def test_load_through_the_wall_raises(params, pin, circle, model, balance):
    with pytest.raises(ContactError, match="through the bushing wall"):
        solve(circle, pin, [200.0, 1e9], [0.0, 0.0], model, params, balance=balance)


def test_max_penetration_limits_the_balance(params, pin, circle):
    law = contact_law("asymmetric-winkler", params)
    sol = solve_contact(circle, pin, [200.0], [0.0], law, max_penetration=1e-5)
    assert sol.penetration[0] < 1e-5  # 9.2 um fits
    with pytest.raises(ContactError, match="200 N"):
        solve_contact(circle, pin, [200.0], [0.0], law, max_penetration=9e-6)


@pytest.mark.parametrize("bad", [[np.nan], [np.inf], [-1.0]])
def test_bad_loads_raise(params, pin, circle, bad):
    with pytest.raises(ContactError, match="load"):
        solve(circle, pin, bad, [0.0], "nlcp", params)


def test_bad_balance_mode_and_pin(params, pin, circle):
    with pytest.raises(ContactError, match="contact.balance"):
        solve(circle, pin, [1.0], [0.0], "nlcp", params, balance="2d")
    with pytest.raises(GeometryError, match="pin_radius"):
        solve(circle, Pin(params.bushing_radius), [1.0], [0.0], "nlcp", params)


def test_custom_callable_law_equals_winkler(params, pin, circle, worn):
    k = params.bushing_youngs_modulus / params.bushing_thickness  # 2e11 Pa/m

    def linear(d):
        return 2e11 * d

    assert k == 2e11
    for contour, model in ((circle, "winkler"), (worn, "asymmetric-winkler")):
        for balance in ("paper", "equilibrium"):
            ref = solve(contour, pin, LOADS, AZIMUTHS, model, params, balance=balance)
            got = solve(contour, pin, LOADS, AZIMUTHS, linear, params, balance=balance)
            np.testing.assert_allclose(
                got.pressure, ref.pressure, rtol=1e-9, atol=1e-10 * ref.pressure.max()
            )
            assert got.model == "linear"
    # a lambda directly into solve_contact, nonlinear
    cubic = solve_contact(circle, pin, [200.0], [0.0], lambda d: 1e20 * d**3)
    delta = circle.penetration(pin, cubic.eccentricity[0])
    np.testing.assert_allclose(cubic.pressure[0], 1e20 * delta**3, rtol=1e-12, atol=1e-6)
    assert abs(cubic.normal_force[0] - 200.0) <= 1e-12


def test_spring_counts(params, pin, circle, worn):
    loads = np.array([50.0, 200.0, 400.0])
    on_circle = solve(circle, pin, loads, np.zeros(3), "asymmetric-winkler", params)
    np.testing.assert_array_equal(on_circle.springs_left, on_circle.springs_right)
    assert on_circle.springs_left[1] == 32  # 32.3 deg half-angle at 1 deg spacing
    on_worn = solve(worn, pin, loads, np.zeros(3), "asymmetric-winkler", params)
    assert np.all(on_worn.springs_left < on_worn.springs_right)
    # independent count from the exact penetration (the node on the load line is in neither)
    for sol in (on_circle, on_worn):
        contour = circle if sol is on_circle else worn
        phi = np.angle(np.exp(1j * contour.theta))
        touching = contour.penetration(pin, sol.eccentricity) > 0
        np.testing.assert_array_equal(sol.springs_left, (touching & (phi > 0)).sum(1))
        np.testing.assert_array_equal(sol.springs_right, (touching & (phi < 0)).sum(1))
        assert np.all(touching[:, 0])


def test_symmetric_and_asymmetric_winkler(params, pin, circle, worn):
    a = solve(circle, pin, LOADS, AZIMUTHS, "winkler", params)
    b = solve(circle, pin, LOADS, AZIMUTHS, "asymmetric-winkler", params)
    np.testing.assert_allclose(a.pressure, b.pressure, rtol=1e-12, atol=1e-12 * b.pressure.max())
    np.testing.assert_array_equal(a.springs_left, b.springs_left)
    # near the scar (20 +- 12 deg) the two differ; far from it the contour is the circle
    near = np.radians([0.0, 10.0, 20.0, 30.0, 40.0])
    a = solve(worn, pin, np.full(5, 200.0), near, "winkler", params)
    b = solve(worn, pin, np.full(5, 200.0), near, "asymmetric-winkler", params)
    assert np.all(np.abs(a.pressure.max(1) - b.pressure.max(1)) > 1e-3 * b.pressure.max(1))
    assert np.all(np.abs(a.tangential_force) < 0.05)  # symmetric springs: ~0 sideways
    assert np.all(np.abs(b.tangential_force[[0, 1, 3]]) > 10.0)
    assert abs(b.tangential_force[2]) < 1e-9  # load on the scar's axis of symmetry
    far = np.radians([150.0, -120.0])
    a = solve(worn, pin, np.full(2, 200.0), far, "winkler", params)
    b = solve(worn, pin, np.full(2, 200.0), far, "asymmetric-winkler", params)
    np.testing.assert_allclose(a.pressure, b.pressure, rtol=1e-9, atol=1e-3)
    # the traditional model ignores the scar: springs symmetric about the load line
    at_zero = solve(worn, pin, [200.0], [0.0], "winkler", params)
    assert at_zero.springs_left[0] == at_zero.springs_right[0]
    assert abs(at_zero.tangential_force[0]) < 1e-9


def joint_stiffness(law, contour, pin, sol, area):
    """dF/ds along the load, from the springs' slopes [N/m]."""
    delta = contour.penetration(pin, sol.eccentricity)
    phi = (
        contour.theta[None, :] - np.arctan2(sol.eccentricity[:, 1], sol.eccentricity[:, 0])[:, None]
    )
    return (law.pressure_derivative(delta) * area * np.cos(phi) ** 2).sum(1)


@pytest.mark.parametrize("model", ["winkler", "asymmetric-winkler", "nlcp"])
@pytest.mark.parametrize("balance", ["paper", "equilibrium"])
def test_stiff_bushing_converges_to_round_off(params, pin, circle, worn, model, balance):
    """Bronze/steel bushing (E = 200 GPa): one ulp of the pin position moves the Winkler force
    by ~1e-11 N, more than the 1e-12 N tolerance. The balance must still succeed, with the
    residual at what double precision can resolve."""
    stiff = dataclasses.replace(params, bushing_youngs_modulus=2e11, bushing_poisson_ratio=0.3)
    law = contact_law(model, stiff)
    loads = np.array([0.01, 1.0, 10.0, 200.0, 1000.0, 5000.0])
    azimuth = np.radians([0.0, 3.3, -40.0, 20.0, 100.0, 0.5])
    for contour in (circle, worn):
        sol = solve(contour, pin, loads, azimuth, model, stiff, balance=balance)
        area = force_area(model, contour, stiff, azimuth)
        _, _, total = resultants(sol, contour, area, azimuth)
        s = np.hypot(sol.eccentricity[:, 0], sol.eccentricity[:, 1])
        ulp = 8 * EPS * s * joint_stiffness(law, contour, pin, sol, area)
        tol = np.maximum(bound(total), ulp)
        assert np.all(np.abs(sol.normal_force - loads) <= tol)
        assert np.any(ulp > 1e-12)  # the regime where 1e-12 N is out of reach
        if balance == "equilibrium":
            assert np.all(np.abs(sol.tangential_force) <= tol)
        # still accurate: the spring forces are the law of the exact penetration
        delta = contour.penetration(pin, sol.eccentricity)
        if model != "winkler":
            np.testing.assert_allclose(
                sol.pressure, law.pressure(delta), rtol=1e-9, atol=1e-12 * sol.pressure.max()
            )


def test_wear_pocket_beyond_the_pins_reach(params):
    """The ray geometry needs the pin centre inside the pin (|e| < R_p). A 2 mm pin in a
    bushing worn 2 mm deep cannot be balanced: a clear ContactError, never a silent answer."""
    rp, c, nodes = 2.05e-3, 1e-3, 180
    small = dataclasses.replace(params, pin_radius=rp, bushing_radius=rp + c)
    theta = 2 * np.pi * np.arange(nodes) / nodes
    phi = np.angle(np.exp(1j * (theta - 0.5)))
    pocket = BushingContour.from_wear_profile(
        rp + c, 2 * c * np.exp(-((phi / np.radians(26)) ** 2)), params.axial_length
    )
    # paper mode balances along the load, on the pocket's flank
    paper = solve(pocket, Pin(rp), [1.0], [0.0], "asymmetric-winkler", small)
    assert abs(paper.normal_force[0] - 1.0) <= 1e-12
    # 2-D equilibrium would need the pin deeper in the pocket than the model allows
    with pytest.raises(ContactError, match="2-D equilibrium not found"):
        solve(pocket, Pin(rp), [1.0], [0.0], "asymmetric-winkler", small, balance="equilibrium")
    # a load line straight into the pocket (gap 3 mm > R_p): out of reach at once
    with pytest.raises(ContactError, match="out of the pin's reach"):
        solve(pocket, Pin(rp), [1.0], [0.5], "winkler", small)


@pytest.mark.parametrize("model", SPRING_MODELS)
@pytest.mark.parametrize("balance_mode", ["paper", "equilibrium"])
@pytest.mark.parametrize("clearance", [0.05e-3, 0.2e-3])
def test_cold_start_on_a_circle_gives_the_warm_answer(params, pin, model, balance_mode, clearance):
    """Cold (node-free guess, fourth-order steps, window from the estimated contact) and warm
    (offsets 3 % off, 90 degree window) solves agree, with zero loads in the batch; every
    load balanced to its bound."""
    joint = dataclasses.replace(params, bushing_radius=params.pin_radius + clearance)
    circle = BushingContour.circle(joint.bushing_radius, 360, joint.axial_length)
    law = contact_law(model, joint)
    load, azimuth = revolution_loads()
    load[::37] = 0.0
    cold = solve_contact(circle, pin, load, azimuth, law, balance=balance_mode)
    along, _ = pin_frame(cold, azimuth)
    warm = solve_contact(
        circle, pin, load, azimuth, law, balance=balance_mode, initial_offset=1.03 * along
    )
    scale = np.maximum(np.abs(warm.pressure).max(axis=1, keepdims=True), 1e-300)
    assert np.max(np.abs(cold.pressure - warm.pressure) / scale) <= 1e-9
    area = force_area(model, circle, joint, azimuth)
    _, _, total = resultants(cold, circle, area, azimuth)
    assert np.all(np.abs(cold.normal_force - load) <= bound(total))
    assert np.all(cold.pressure[load == 0] == 0.0)


@pytest.mark.parametrize("model", ["asymmetric-winkler", "nlcp", "mesh-independent nlcp"])
def test_unworn_window_equals_the_general_window(params, pin, circle, model):
    """On an unworn bushing the window keeps one gap per row (a column) and one spring area.
    A contour that differs only at a node out of every load's reach takes the general
    window (gathered gaps and areas) and the conformal start: the same answer."""
    if model == "mesh-independent nlcp":
        params, model = dataclasses.replace(params, nlcp_variant="mesh-independent"), "nlcp"
    law = contact_law(model, params)
    radius = circle.radius.copy()
    radius[180] += 1e-6  # 180 degrees from the loads, outwards
    bumped = BushingContour(radius, circle.axial_length, circle.original_radius)
    load = np.array([0.0, 0.01, 1.0, 50.0, 200.0, 400.0, 1000.0])
    azimuth = np.radians([0.0, 10.0, -20.0, 30.0, 5.5, -0.3, 12.0])
    plain = solve_contact(circle, pin, load, azimuth, law)
    general = solve_contact(bumped, pin, load, azimuth, law)
    # (both balanced to 1e-12 N: for 10 mN that is 1e-10 of the load)
    scale = np.maximum(general.pressure.max(axis=1, keepdims=True), 1e-300)
    assert np.max(np.abs(plain.pressure - general.pressure) / scale) <= 1e-9
    np.testing.assert_allclose(plain.eccentricity, general.eccentricity, rtol=1e-11, atol=1e-20)
