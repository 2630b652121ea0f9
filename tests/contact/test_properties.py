"""Property tests of the load balance over wide parameter ranges (hypothesis)."""

from __future__ import annotations

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from jointwear.contact import ContactParameters, contact_law, solve
from jointwear.errors import ContactError
from jointwear.geometry import BushingContour, Pin

EPS = np.finfo(float).eps
SETTINGS = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def log_uniform(lo, hi):
    return st.floats(np.log10(lo), np.log10(hi)).map(lambda x: float(10.0**x))


joints = st.fixed_dictionaries(
    {
        "pin_radius": log_uniform(2e-3, 30e-3),
        "clearance": log_uniform(1e-6, 1e-3),
        "axial_length": log_uniform(5e-3, 50e-3),
        "thickness": log_uniform(0.5e-3, 10e-3),
        "modulus": log_uniform(1e8, 3e11),
        "poisson": st.floats(0.0, 0.45),
        "exponent": st.floats(1.0, 2.5),
        "model": st.sampled_from(["winkler", "asymmetric-winkler", "nlcp", "nlcp-independent"]),
        "wear_depth": st.one_of(st.just(0.0), st.floats(0.0, 2.0)),  # in clearances
        "wear_centre": st.floats(-np.pi, np.pi),
        "wear_width": st.floats(3.0, 60.0),  # deg
        "nodes": st.sampled_from([180, 360, 720]),
    }
)
loads = log_uniform(1e-3, 1e4)
azimuths = st.floats(-np.pi, np.pi)


def build(j):
    # a clearance joint: radial gap (clearance plus wear) small against the pin radius; the
    # model's ray geometry needs the pin centre inside the pin, |e| < R_p, and a pocket
    # worn half a pin radius deep is no longer a joint
    assume(j["clearance"] * (1 + j["wear_depth"]) <= 0.1 * j["pin_radius"])
    bushing = j["pin_radius"] + j["clearance"]
    params = ContactParameters(
        pin_radius=j["pin_radius"],
        bushing_radius=bushing,
        axial_length=j["axial_length"],
        bushing_thickness=j["thickness"],
        pin_youngs_modulus=2.1e11,
        pin_poisson_ratio=0.3,
        bushing_youngs_modulus=j["modulus"],
        bushing_poisson_ratio=j["poisson"],
        exponent=j["exponent"],
        nlcp_variant="mesh-independent" if j["model"] == "nlcp-independent" else "paper",
    )
    model = "nlcp" if j["model"].startswith("nlcp") else j["model"]
    theta = 2 * np.pi * np.arange(j["nodes"]) / j["nodes"]
    phi = np.angle(np.exp(1j * (theta - j["wear_centre"])))
    wear = j["wear_depth"] * j["clearance"] * np.exp(-((phi / np.radians(j["wear_width"])) ** 2))
    contour = BushingContour.from_wear_profile(bushing, wear, j["axial_length"])
    return params, model, contour, Pin(j["pin_radius"])


def areas(model, params, contour, azimuth):
    shape = (np.size(azimuth), contour.nodes)
    if model == "nlcp" and params.nlcp_variant == "paper":
        return np.full(shape, params.spring_area)
    if model == "winkler":
        radius = contour.radius_at(np.mod(azimuth, 2 * np.pi))
        return np.broadcast_to((radius * contour.dtheta * contour.axial_length)[:, None], shape)
    return np.broadcast_to(contour.spring_area, shape)


def capacity(model, params, contour, pin, azimuth):
    """Largest load the springs carry with the pin at the wall limit (paper kinematics)."""
    law = contact_law(model, params)
    centre = contour.radius_at(np.mod(azimuth, 2 * np.pi))
    s = min(0.999 * pin.radius, centre - pin.radius + params.bushing_thickness)
    e = s * np.array([np.cos(azimuth), np.sin(azimuth)])
    delta = penetration(law, contour, pin, e[None, :], np.array([azimuth]))[0]
    force = law.pressure(delta) * areas(model, params, contour, np.array([azimuth]))[0]
    return float(force @ np.cos(contour.theta - azimuth))


def penetration(law, contour, pin, eccentricity, azimuth):
    """Spring penetrations as the model sees them [m], one row per pin position.

    The symmetric (traditional Winkler) law puts its springs on the circle through each
    load's compression centre, not on the worn contour.
    """
    if not law.symmetric:
        return contour.penetration(pin, eccentricity)
    centre = contour.radius_at(np.mod(azimuth, 2 * np.pi))
    return np.stack(
        [
            BushingContour.circle(c, contour.nodes, contour.axial_length).penetration(pin, e)
            for c, e in zip(centre, eccentricity, strict=True)
        ]
    )


def check_solution(sol, load, azimuth, model, params, contour, pin, balance):
    law = contact_law(model, params)
    area = areas(model, params, contour, azimuth)
    force = sol.pressure * area
    total = np.abs(force).sum(1)
    assert np.all(np.isfinite(sol.pressure))
    assert np.all(sol.pressure >= 0)
    assert np.all(np.isfinite(sol.eccentricity))
    assert np.all(sol.penetration >= 0)
    assert np.all((sol.half_angle_left >= 0) & (sol.half_angle_left <= np.pi))
    assert np.all((sol.half_angle_right >= 0) & (sol.half_angle_right <= np.pi))
    # balance, with the round-off floors: sum of forces, and one ulp of the pin position
    delta = penetration(law, contour, pin, sol.eccentricity, azimuth)
    s = np.hypot(sol.eccentricity[:, 0], sol.eccentricity[:, 1])
    stiffness = (law.pressure_derivative(delta) * area).sum(1)
    tol = np.maximum.reduce([np.full(load.size, 1e-12), 8 * EPS * total, 8 * EPS * s * stiffness])
    assert np.all(np.abs(sol.normal_force - load) <= tol), (sol.normal_force - load, tol)
    if balance == "equilibrium":
        assert np.all(np.abs(sol.tangential_force) <= tol), (sol.tangential_force, tol)
    # the reported resultant is the pressure's own
    phi = contour.theta[None, :] - azimuth[:, None]
    assert np.all(
        np.abs((force * np.cos(phi)).sum(1) - sol.normal_force) <= 16 * EPS * total + 1e-300
    )
    if not law.symmetric:
        # pressure is the law of the exact penetration at every node; contour.penetration
        # is a difference of radii, good to a few eps * R absolute (the balance is better)
        err = 8 * EPS * contour.radius.max()
        low = law.pressure(np.maximum(delta - err, 0.0)) * (1 - 1e-12)
        high = law.pressure(delta + err) * (1 + 1e-12)
        assert np.all((low <= sol.pressure) & (sol.pressure <= high))


@SETTINGS
@given(
    joint=joints, load=loads, azimuth=azimuths, balance=st.sampled_from(["paper", "equilibrium"])
)
def test_balance_holds_or_the_load_goes_through_the_wall(joint, load, azimuth, balance):
    params, model, contour, pin = build(joint)
    limit = capacity(model, params, contour, pin, azimuth)
    try:
        sol = solve(contour, pin, [load], [azimuth], model, params, balance=balance)
        refused = ""
    except ContactError as exc:
        sol, refused = None, str(exc)
    if "out of the pin's reach" in refused:  # worn deeper than the pin radius
        assert contour.radius.max() - pin.radius >= 0.999 * pin.radius
        return
    if refused:
        # otherwise only a load beyond what the springs carry at the wall may be refused
        assert "through the bushing wall" in refused
        assert load > 0.999 * limit, (load, limit)
        return
    assert load <= 1.001 * limit
    check_solution(sol, np.array([load]), np.array([azimuth]), model, params, contour, pin, balance)


@SETTINGS
@given(joint=joints, load=loads, ratio=log_uniform(1e-6, 10.0), azimuth=azimuths)
def test_penetration_grows_with_load(joint, load, ratio, azimuth):
    """F(s) is non-decreasing, so F1 < F2 needs s1 <= s2 (paper mode, along the load)."""
    params, model, contour, pin = build(joint)
    pair = np.array([load, load * (1 + ratio)])
    if pair[1] > 0.99 * capacity(model, params, contour, pin, azimuth):
        return  # through the wall: covered above
    both = np.full(2, azimuth)
    sol = solve(contour, pin, pair, both, model, params)
    check_solution(sol, pair, both, model, params, contour, pin, "paper")
    along = sol.eccentricity @ np.array([np.cos(azimuth), np.sin(azimuth)])
    assert along[0] <= along[1] * (1 + 4 * EPS)
    assert sol.penetration[0] <= sol.penetration[1] * (1 + 4 * EPS) + 1e-300
    # and the spring force of each solution, re-evaluated, is ordered the same way
    law = contact_law(model, params)
    area = areas(model, params, contour, both)
    forces = (
        law.pressure(penetration(law, contour, pin, sol.eccentricity, both))
        * area
        * np.cos(contour.theta - azimuth)
    ).sum(1)
    assert forces[0] <= forces[1] + 1e-12 + 16 * EPS * forces[1]


@SETTINGS
@given(
    joint=joints,
    load=st.lists(loads, min_size=2, max_size=6),
    balance=st.sampled_from(["paper", "equilibrium"]),
    data=st.data(),
)
def test_batch_of_loads(joint, load, balance, data):
    params, model, contour, pin = build(joint)
    load = np.array(load)
    azimuth = np.array(data.draw(st.lists(azimuths, min_size=load.size, max_size=load.size)))
    limits = np.array([capacity(model, params, contour, pin, a) for a in azimuth])
    keep = load < 0.99 * limits
    if not keep.any():
        return
    load, azimuth = load[keep], azimuth[keep]
    sol = solve(contour, pin, load, azimuth, model, params, balance=balance)
    check_solution(sol, load, azimuth, model, params, contour, pin, balance)
    one = solve(contour, pin, load[:1], azimuth[:1], model, params, balance=balance)
    assert np.allclose(
        sol.pressure[0], one.pressure[0], rtol=1e-7, atol=1e-9 * max(one.pressure.max(), 1e-300)
    )
