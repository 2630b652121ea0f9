"""The pin's periodic orbit by Booker's mobility method, with asperity contact.

Checked against closed forms: a steady load on a turning journal settles where
Ocvirk's (short) and Sommerfeld's (long, half-Sommerfeld) equilibria put it; a pin
pushed straight at the wall moves at the speed of the short bearing's closed-form
squeeze film; through a reversal of the sliding speed the squeeze film holds the pin
off the wall where the steady (no-squeeze) solution puts it on the wall. A pin that the
film alone cannot hold off the wall rests there at one angle, wherever it starts.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.lubrication import orbit as orbit_module
from jointwear.lubrication.mixed import steady_load_sharing
from jointwear.lubrication.mobility import dimensionless_force, mobility
from jointwear.lubrication.orbit import (
    WALL_GAP,
    CycleMap,
    OrbitSolver,
    film_shape,
    periodic_orbit,
    secant_jacobian,
    short_shape,
    stretched,
    unstretched,
)

RADIUS, CLEARANCE, VISCOSITY, SPEED = 0.01, 20e-6, 0.05, 100.0
#: a smooth surface: no asperity force at the eccentricities checked
SMOOTH = 1e-9


def ocvirk_load(eps: float, length: float) -> float:
    """Ocvirk: W = mu U L^3 / (4 c^2) eps / (1 - eps^2)^2 sqrt(pi^2 (1 - eps^2) + 16 eps^2)."""
    u = RADIUS * SPEED
    return (
        VISCOSITY
        * u
        * length**3
        / (4 * CLEARANCE**2)
        * eps
        / (1 - eps**2) ** 2
        * math.sqrt(math.pi**2 * (1 - eps**2) + 16 * eps**2)
    )


def sommerfeld_load(eps: float, length: float) -> float:
    """Half Sommerfeld: W = 6 mu U R^2 L eps sqrt(pi^2 (1-eps^2) + 4 eps^2)
    / (c^2 (2+eps^2)(1-eps^2))."""
    u = RADIUS * SPEED
    return (
        6
        * VISCOSITY
        * u
        * RADIUS**2
        * length
        * eps
        * math.sqrt(math.pi**2 * (1 - eps**2) + 4 * eps**2)
        / (CLEARANCE**2 * (2 + eps**2) * (1 - eps**2))
    )


def steady_orbit(model: str, length: float, load: float):
    solver = OrbitSolver(RADIUS, length, CLEARANCE, VISCOSITY, SMOOTH, 200e9, model)
    steps, period = 4, 0.01
    time = np.arange(steps) * period / steps
    return periodic_orbit(
        solver,
        time,
        period,
        np.zeros(steps),
        np.full(steps, -load),  # pressing downwards
        np.full(steps, 0.5 * SPEED),
        start=[0.2, -0.2],
    )


@pytest.mark.parametrize("eps", [0.3, 0.6, 0.85])
def test_a_steady_load_settles_at_ocvirks_equilibrium(eps):
    length = 0.005
    orbit = steady_orbit("short", length, ocvirk_load(eps, length))
    attitude = np.arctan2(orbit.eccentricity_x, -orbit.eccentricity_y)
    expected = math.atan(math.pi * math.sqrt(1 - eps**2) / (4 * eps))
    np.testing.assert_allclose(orbit.eccentricity_ratio, eps, rtol=1e-3)
    np.testing.assert_allclose(attitude, expected, rtol=1e-3)


@pytest.mark.parametrize("eps", [0.3, 0.6, 0.8])
def test_a_steady_load_settles_at_sommerfelds_equilibrium(eps):
    length = 0.04
    orbit = steady_orbit("long", length, sommerfeld_load(eps, length))
    attitude = np.arctan2(orbit.eccentricity_x, -orbit.eccentricity_y)
    expected = math.atan(math.pi * math.sqrt(1 - eps**2) / (2 * eps))
    np.testing.assert_allclose(orbit.eccentricity_ratio, eps, rtol=1e-2)
    np.testing.assert_allclose(attitude, expected, rtol=1e-2)


@pytest.mark.parametrize("eps", [0.1, 0.3, 0.6, 0.9])
def test_a_pin_pushed_at_the_wall_moves_at_the_squeeze_films_speed(eps):
    """F = mu R L^3 deps/dt / (c^2 (1-eps^2)^2.5)
    [(1 + 2 eps^2)(pi/2 + asin eps) + 3 eps sqrt(1-eps^2)], no sideways motion."""
    length, load = 0.005, 50.0
    solver = OrbitSolver(RADIUS, length, CLEARANCE, VISCOSITY, SMOOTH, 200e9, "short")
    velocity = solver.velocity(np.array([eps, 0.0]), load, 0.0, 0.0)
    bracket = (1 + 2 * eps**2) * (math.pi / 2 + math.asin(eps)) + 3 * eps * math.sqrt(1 - eps**2)
    rate = load * CLEARANCE**2 * (1 - eps**2) ** 2.5 / (VISCOSITY * RADIUS * length**3 * bracket)
    assert velocity[0] == pytest.approx(rate, rel=1e-9)
    assert abs(velocity[1]) < 1e-9 * rate


def test_the_closed_short_form_is_the_film_modules():
    eps = np.linspace(0.05, 0.95, 7)[:, None]
    beta = np.linspace(-math.pi, math.pi, 13)[None, :]
    np.testing.assert_allclose(
        short_shape(eps, beta, 0.4),
        dimensionless_force("short", eps, beta, np.array(0.4)),
        rtol=1e-11,
        atol=1e-14,
    )


@pytest.mark.parametrize("model", ["long", "finite"])
def test_the_tabulated_force_factor_follows_the_force_models(model):
    rng = np.random.default_rng(3)
    eps, beta = rng.uniform(0.0, 0.99, 200), rng.uniform(-math.pi, math.pi, 200)
    table = film_shape(model, 0.5)(eps, beta)
    direct = dimensionless_force(model, eps, beta, np.array(0.5))
    error = np.hypot(*(table - direct)) / np.hypot(*direct)
    assert error.max() < 5e-3


def test_the_squeeze_film_holds_the_pin_off_the_wall_through_a_speed_reversal():
    """An oscillating pin under a steady load: the steady (no-squeeze) solution puts the
    pin on the wall where the sliding speed reverses; the orbit keeps a film there."""
    length, load, period, steps = 0.01, 400.0, 1.0, 90
    time = np.arange(steps) * period / steps
    pin_speed = 0.5 * 2 * math.pi / period * np.cos(2 * math.pi * time / period)
    roughness, modulus = 0.2e-6, 115e9
    solver = OrbitSolver(RADIUS, length, CLEARANCE, 0.1, roughness, modulus, "short")
    orbit = periodic_orbit(
        solver, time, period, np.zeros(steps), np.full(steps, -load), 0.5 * pin_speed, [0.0, -0.5]
    )
    steady = steady_load_sharing(
        load, RADIUS, length, CLEARANCE, 0.1, 0.0, roughness, modulus, model="short"
    )
    gap = CLEARANCE * (1 - orbit.eccentricity_ratio) / roughness
    assert steady.film_parameter < 1e-3  # on the wall
    assert gap.min() > 2.0


def test_the_orbit_does_not_depend_on_where_it_starts():
    length, load, period, steps = 0.01, 300.0, 0.2, 60
    time = np.arange(steps) * period / steps
    phase = 2 * math.pi * time / period
    solver = OrbitSolver(RADIUS, length, CLEARANCE, 0.05, 0.2e-6, 115e9, "short")
    args = (solver, time, period, load * np.cos(phase), load * np.sin(phase), np.full(steps, 20.0))
    one = periodic_orbit(*args, start=[0.0, 0.0])
    other = periodic_orbit(*args, start=[-0.5, 0.6])
    gap = 1 - one.eccentricity_ratio.max()
    np.testing.assert_allclose(one.eccentricity_x, other.eccentricity_x, atol=1e-2 * gap)
    np.testing.assert_allclose(one.eccentricity_y, other.eccentricity_y, atol=1e-2 * gap)


def test_an_orbit_that_does_not_repeat_says_when_the_pin_sinks_below_its_film():
    from types import SimpleNamespace

    from jointwear.lubrication.orbit import creeping_pin

    joint = SimpleNamespace(clearance=50e-6, roughness=0.4e-6)
    angle = np.linspace(0.0, 2.0 * np.pi, 9)
    # least gap 0.1 um = 0.25 roughness: the film alone holds the pin
    sinking = (1.0 - 0.1e-6 / 50e-6) * np.vstack([np.cos(angle), np.sin(angle)])
    assert "least film parameter of 0.25" in creeping_pin(joint, sinking)
    # least gap 1 um = 2.5 roughness: a non-repeating orbit there is not this
    assert creeping_pin(joint, 0.98 * np.vstack([np.cos(angle), np.sin(angle)])) == ""


def rocking_pin_on_its_wall():
    """A long-bearing pin rocking under a load that swells and swings +-0.36 rad about
    -x, its asperities (1.7 N at contact, a soft bushing) far below the load: the
    rod-slider pin of a slider-crank, which the film alone must hold off the wall."""
    solver = OrbitSolver(7.45e-3, 18.7e-3, 50e-6, 0.3, 0.4e-6, 0.58e9, "long")
    steps, period = 120, 0.5
    time = np.arange(steps) * period / steps
    phase = 2.0 * np.pi * time / period
    load, azimuth = 270.0 - 70.0 * np.cos(phase), np.pi + 0.36 * np.sin(phase)
    cycle = (solver, time, period, load * np.cos(azimuth), load * np.sin(azimuth))
    return cycle, 2.2 * np.cos(phase)


def test_on_the_wall_sommerfelds_film_lets_an_oblique_load_slide_the_pin():
    """Close to the wall the long bearing's film resists sliding along it only like
    (1 - eps^2)^-1/2 and leaving it hardly at all: under a load 0.36 rad off the line of
    centres the pin's mobility tends to a finite limit as the gap closes (Booker's
    mobility of the closed form), and the orbit's solver follows it there."""
    cycle, _ = rocking_pin_on_its_wall()
    solver = cycle[0]
    limits = []
    for gap in (1e-4, 1e-5, 1e-6):
        exact = mobility(1.0 - gap, 0.36, solver.ratio, "long")
        limits.append((float(exact.radial), float(exact.tangential)))
        beta = solver.direction_of_motion(1.0 - gap, 0.36 + np.pi)
        shape = solver.scalar_shape(1.0 - gap, beta)
        size = solver.ratio / (3.0 * math.hypot(*shape))
        assert (size * math.sin(beta), -size * math.cos(beta)) == pytest.approx(
            limits[-1], rel=1e-6
        )
    np.testing.assert_allclose(limits[-1], limits[0], rtol=0.01)
    # the pin slides along the wall and leaves it, faster than it could approach it
    assert limits[-1][0] < 0.0 < limits[-1][1]
    approach = mobility(1.0 - 1e-6, 0.0, solver.ratio, "long")
    assert abs(float(approach.radial)) < 1e-6 * limits[-1][1]


def test_a_rocking_pin_held_by_its_film_has_one_orbit_wherever_it_starts():
    """The film (Sommerfeld's close to the wall) holds the rocking pin 3.6e-3 of the
    clearance off the wall (lambda = 0.45): one periodic orbit from off-centre starts
    and from a start 1e-6 of the clearance off the wall, 0.2 rad along it."""
    cycle, speed = rocking_pin_on_its_wall()
    on_the_wall = (1.0 - 1e-6) * np.array([math.cos(np.pi - 0.2), math.sin(np.pi - 0.2)])
    starts = ([-0.5, 0.0], [0.0, 0.5], [0.3, -0.3], on_the_wall)
    orbits = [periodic_orbit(*cycle, speed, start) for start in starts]
    gaps = [1.0 - orbit.eccentricity_ratio.max() for orbit in orbits]
    angles = [math.atan2(orbit.eccentricity_y[0], orbit.eccentricity_x[0]) for orbit in orbits]
    assert gaps[0] == pytest.approx(3.64e-3, rel=0.01)
    assert gaps[0] > 1e5 * WALL_GAP  # not on the wall
    np.testing.assert_allclose(gaps, gaps[0], rtol=1e-4)
    assert max(angles) - min(angles) < 1e-6
    # the load swings symmetrically about -x: the pin sits near it, turned by the wedge
    assert abs(math.remainder(angles[0] - np.pi, 2.0 * np.pi)) < 0.05


def test_the_secant_jacobian_of_an_affine_cycle_map_is_its_own():
    """Three repeated cycles of ``q -> A q + b`` give the residual's Jacobian ``A - I``;
    a map that shrinks every direction alike steps along one line: no estimate."""
    matrix, shift = np.array([[0.3, -0.2], [0.1, 0.5]]), np.array([1.0, -2.0])
    starts, ends = [np.array([4.0, 7.0])], []
    for _ in range(3):
        ends.append(matrix @ starts[-1] + shift)
        starts.append(ends[-1])
    np.testing.assert_allclose(secant_jacobian(starts[:3], ends), matrix - np.eye(2), atol=1e-12)
    assert secant_jacobian(starts[:2], ends[:2]) is None  # two cycles: one step
    along = [np.array([4.0, 7.0]) * 0.5**k for k in range(4)]
    assert secant_jacobian(along[:3], along[1:]) is None


def paper_pin_cycle(overrides: list[str]) -> tuple[OrbitSolver, tuple, np.ndarray]:
    """The paper's Table 3 rod-slider pin with the film of ``overrides``: its solver, the
    arguments of :func:`periodic_orbit` and the first guess."""
    from pathlib import Path

    from jointwear import Simulation, load_config
    from jointwear.contact.lubricated import film_speeds

    config = Path(__file__).resolve().parents[2] / "examples/paper/table3_winkler_120rpm.toml"
    simulation = Simulation(load_config(config, overrides=overrides))
    lubrication, cycle = simulation.solver.lubrication, simulation.load_cycle
    rate, _ = film_speeds(cycle)
    arguments = (
        lubrication.solver,
        cycle.time,
        cycle.period,
        cycle.load * np.cos(cycle.azimuth),
        cycle.load * np.sin(cycle.azimuth),
        0.25 * (rate + np.roll(rate, 1)),
    )
    return lubrication.solver, arguments, lubrication.first_guess(cycle)


@pytest.mark.parametrize(
    "overrides",
    [
        # plain cycles that contract by 1e-4 a cycle: the next one is bound to close
        [
            "lubrication.model=finite-length",
            "lubrication.lubricant=iso-vg-68",
            "lubrication.temperature=60 degC",
        ],
    ],
)
def test_a_search_about_to_close_ends_with_the_proofs_cycle(monkeypatch, overrides):
    """Where the search's next cycle will close, that cycle integrated at the proof's
    tolerance ends it: the orbit is the one of the search that integrates that cycle at
    its own tolerance and then the proof's, within the orbit's tolerance, in fewer
    cycles; and it closes within the tolerance when integrated afresh."""
    solver, arguments, guess = paper_pin_cycle(overrides)
    fast = periodic_orbit(*arguments, guess)
    with monkeypatch.context() as patch:
        patch.setattr(orbit_module, "closing_cycle", lambda *_: None)
        searched_on = periodic_orbit(*arguments, guess)
    floor = solver.roughness / solver.clearance
    allowed = 1e-3 * max(1.0 - fast.eccentricity_ratio.max(), floor)
    shift = np.hypot(
        fast.eccentricity_x - searched_on.eccentricity_x,
        fast.eccentricity_y - searched_on.eccentricity_y,
    )
    assert shift.max() < allowed
    assert fast.cycles < searched_on.cycles
    start = np.array([fast.eccentricity_x[0], fast.eccentricity_y[0]])
    end = unstretched(CycleMap(*arguments)(stretched(start))[:, -1])
    assert np.hypot(*(end - start)) < allowed


def test_the_secant_search_finds_the_plain_root_finders_orbit(monkeypatch):
    """A short-bearing pin whose plain cycles contract slowly (0.03 Pa s: the root
    finder runs): the orbit from the plain cycles' secant Jacobian, stopped where a cycle
    closes within a twentieth of the tolerance, is the one the root finder finds with its
    forward differences and its own step tolerance (no cycle at the proof's tolerance
    before it stops), within the orbit's tolerance at every
    step, in fewer cycles; and one more cycle from its start, integrated afresh, closes
    within the tolerance."""
    solver, arguments, guess = paper_pin_cycle(
        ["lubrication.model=short-bearing", "lubrication.viscosity=0.03 Pa*s"]
    )
    fast = periodic_orbit(*arguments, guess)
    with monkeypatch.context() as patch:
        patch.setattr(orbit_module, "SECANT_CONDITION", 0.0)
        patch.setattr(orbit_module, "SETTLED", 0.0)
        patch.setattr(orbit_module, "closing_cycle", lambda *_: None)
        plain = periodic_orbit(*arguments, guess)
    floor = solver.roughness / solver.clearance
    allowed = 1e-3 * max(1.0 - fast.eccentricity_ratio.max(), floor)
    shift = np.hypot(
        fast.eccentricity_x - plain.eccentricity_x, fast.eccentricity_y - plain.eccentricity_y
    )
    assert shift.max() < allowed
    assert fast.cycles < plain.cycles
    start = np.array([fast.eccentricity_x[0], fast.eccentricity_y[0]])
    end = unstretched(CycleMap(*arguments)(stretched(start))[:, -1])
    assert np.hypot(*(end - start)) < allowed
