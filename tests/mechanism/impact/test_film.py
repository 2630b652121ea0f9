"""The oil film's force in the contact-impact dynamics (``mechanism.impact.film``).

* the scalar film forces, in Python and compiled, equal the lubrication library's
  (``jointwear.lubrication.film``) to 1e-9, and Ocvirk's and Sommerfeld's closed forms
  for pure rotation and pure squeeze;
* the joint's film force is the library's force turned into the joint's frame, with the
  pin's eccentricity, its rate and the line of centres' turning from ``e`` and ``e'``;
* the transition band: the film's eccentricity is continuous with a continuous slope,
  and levels off at ``1 - b/2``;
* in the frame turning at half the sum of the spins the film only dissipates, in the
  band and in contact too; a free pin with no external work loses energy
  monotonically, and a viscous film stops it before the wall.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from jointwear.config import Config
from jointwear.errors import ConfigError
from jointwear.lubrication import film as library
from jointwear.mechanism.impact import film
from jointwear.mechanism.impact.free_pin import FreePinSystem
from jointwear.mechanism.impact.integrator import integrate_contacts
from jointwear.mechanism.impact.joint_contact import JointContact
from jointwear.mechanism.slider_crank.contact_impact import impact_kernel

from ..joints import joint_contact

R, L, C, MU = 0.01, 0.02, 20e-6, 0.05
ECCENTRICITIES = (0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 0.95)
#: (eps', omega_bar): approach, separation, rotation both ways, and mixtures [1/s, rad/s]
MOTIONS = ((40.0, 0.0), (-40.0, 0.0), (0.0, 100.0), (0.0, -100.0), (25.0, 80.0), (-7.0, -300.0))
MODELS = {"short": (film.short_bearing, library.short_bearing_force),
          "long": (film.long_bearing, library.long_bearing_force)}  # fmt: skip


def compiled_module():
    if impact_kernel() is None:
        pytest.skip("numba missing or JOINTWEAR_NO_NUMBA set")
    from jointwear.mechanism.impact import compiled_film

    return compiled_film


def library_force(model: str, eps: float, rate: float, wedge: float) -> np.ndarray:
    force = MODELS[model][1](R, L, C, MU, eps, rate, wedge)
    return np.array([float(force.radial), float(force.tangential)])


@pytest.mark.parametrize("model", sorted(MODELS))
@pytest.mark.parametrize("compiled", [False, True])
def test_film_force_equals_the_library(model: str, compiled: bool) -> None:
    function = MODELS[model][0]
    if compiled:
        function = getattr(compiled_module(), f"{model}_bearing")
    for eps in ECCENTRICITIES:
        for rate, wedge in MOTIONS:
            if eps == 0.0 and model == "long" and rate != 0.0:
                continue  # the library's squeeze terms at eps = 0 use eps = 1e-8 too
            ours = np.array(function(R, L, C, MU, eps, rate, wedge))
            theirs = library_force(model, eps, rate, wedge)
            scale = max(np.abs(theirs).max(), 1e-300)
            assert np.abs(ours - theirs).max() <= 1e-9 * scale, (eps, rate, wedge)


@pytest.mark.parametrize("eps", ECCENTRICITIES[1:])
def test_short_bearing_closed_forms(eps: float) -> None:
    # pure rotation (Ocvirk): F_r = -mu U L^3 eps^2 / (c^2 (1-eps^2)^2),
    # F_t = pi mu U L^3 eps / (4 c^2 (1-eps^2)^1.5), U = R omega_bar
    wedge = 150.0
    u = R * wedge
    radial, tangential = film.short_bearing(R, L, C, MU, eps, 0.0, wedge)
    assert radial == pytest.approx(-MU * u * L**3 * eps**2 / (C**2 * (1 - eps**2) ** 2), rel=1e-9)
    assert tangential == pytest.approx(
        math.pi * MU * u * L**3 * eps / (4 * C**2 * (1 - eps**2) ** 1.5), rel=1e-9
    )
    # pure squeeze towards the wall: no sideways force
    rate = 30.0
    radial, tangential = film.short_bearing(R, L, C, MU, eps, rate, 0.0)
    bracket = (1 + 2 * eps**2) * (math.pi / 2 + math.asin(eps)) + 3 * eps * math.sqrt(1 - eps**2)
    expected = -MU * R * L**3 * rate / (C**2 * (1 - eps**2) ** 2.5) * bracket
    assert radial == pytest.approx(expected, rel=1e-9)
    assert abs(tangential) <= 1e-9 * abs(expected)


@pytest.mark.parametrize("eps", ECCENTRICITIES[1:])
def test_long_bearing_closed_form(eps: float) -> None:
    # half Sommerfeld, pure rotation:
    # F_r = -12 mu U R^2 L eps^2 / (c^2 (2+eps^2)(1-eps^2)),
    # F_t = 6 pi mu U R^2 L eps / (c^2 (2+eps^2) sqrt(1-eps^2))
    wedge = 150.0
    u = R * wedge
    radial, tangential = film.long_bearing(R, L, C, MU, eps, 0.0, wedge)
    scale = MU * u * R**2 * L / (C**2 * (2 + eps**2))
    assert radial == pytest.approx(-12 * scale * eps**2 / (1 - eps**2), rel=1e-9)
    assert tangential == pytest.approx(6 * math.pi * scale * eps / math.sqrt(1 - eps**2), rel=1e-9)


def test_joint_film_force_is_the_library_force_in_the_joint_frame() -> None:
    rng = np.random.default_rng(11)
    band = 0.1
    for code, model in ((1.0, "short"), (2.0, "long")):
        for _ in range(40):
            eps = rng.uniform(0.05, 1.0 - band)
            angle = rng.uniform(-np.pi, np.pi)
            ex, ey = eps * C * math.cos(angle), eps * C * math.sin(angle)
            vx, vy = rng.normal(size=2) * 1e-3
            spin = rng.normal() * 50.0
            jx, jy = film.joint_film_force(ex, ey, vx, vy, spin, code, R, L, C, MU, band)
            rate = (ex * vx + ey * vy) / (eps * C * C)
            turning = (ex * vy - ey * vx) / (eps * C) ** 2
            force = MODELS[model][1](
                R, L, C, MU, eps, rate, library.wedge_speed(spin, 0.0, turning)
            )
            fx, fy = library.to_xy(force, angle)
            # the film's force on the pin, -J on the rod-side body that carries it
            assert [-jx, -jy] == pytest.approx([float(fx), float(fy)], rel=1e-9, abs=1e-12)


def test_film_eccentricity_blends_with_a_continuous_slope() -> None:
    band = 0.1
    eps = np.linspace(0.5, 1.3, 80001)
    blended = np.array([film.film_eccentricity(x, band) for x in eps])
    np.testing.assert_array_equal(blended[eps <= 0.9], eps[eps <= 0.9])
    np.testing.assert_allclose(blended[eps >= 1.0], 0.95, rtol=0.0, atol=1e-15)
    slope = np.diff(blended) / np.diff(eps)
    assert np.all(np.diff(blended) >= -1e-15)  # non-decreasing up to round-off
    assert np.max(np.abs(np.diff(slope))) < 1e-3  # no jump of the slope (C1)
    assert slope[0] == pytest.approx(1.0)
    assert slope[-1] == 0.0


@pytest.mark.parametrize("code", [1.0, 2.0])
def test_film_only_dissipates_in_the_squeeze_frame(code: float) -> None:
    """In the frame turning at (omega_pin + omega_bushing) / 2 the film is a pure squeeze
    film: the power of its force on the pin, relative to that frame, is never positive,
    also in the band and in contact (where its eccentricity is held)."""
    rng = np.random.default_rng(5)
    band = 0.1
    powers = []
    for _ in range(2000):
        eps = rng.uniform(0.0, 1.3)
        angle = rng.uniform(-np.pi, np.pi)
        ex, ey = eps * C * math.cos(angle), eps * C * math.sin(angle)
        vx, vy = rng.normal(size=2) * 10.0 ** rng.uniform(-5, -1)
        spin = rng.normal() * 10.0 ** rng.uniform(-1, 3)
        jx, jy = film.joint_film_force(ex, ey, vx, vy, spin, code, R, L, C, MU, band)
        half = 0.5 * spin
        rel_x, rel_y = vx + half * ey, vy - half * ex  # e' - Omega x e
        power = -(jx * rel_x + jy * rel_y)  # the force on the pin is -J
        scale = math.hypot(jx, jy) * math.hypot(rel_x, rel_y)
        powers.append(power / scale if scale > 0 else 0.0)
    powers = np.array(powers)
    assert powers.max() <= 1e-9
    assert powers.min() < -0.1  # and it does dissipate


def lubricated_contact(paper_config: Config, model: str, viscosity: float) -> JointContact:
    contact = joint_contact(paper_config.replace({"dynamics.restitution": 1.0}))
    return JointContact(
        contact.force_law, contact.clearance, contact.stiffness, 1.0,
        film=film.FilmParameters(model, viscosity), pin_radius=R, axial_length=L,
    )  # fmt: skip


@pytest.mark.parametrize("model", ["short-bearing", "long-bearing"])
def test_free_pin_loses_energy_to_the_film_only(paper_config: Config, model: str) -> None:
    """A free pin thrown at the wall, elastic contact, no external force: the film is the
    only loss, and the energy (kinetic + contact) never grows."""
    contact = lubricated_contact(paper_config, model, 1e-6)
    system = FreePinSystem(0.4, contact)
    speed = 0.2
    y0 = np.array([0.0, 0.0, speed * math.cos(0.4), speed * math.sin(0.4), 0.0])
    duration = 6 * contact.clearance / speed
    history = integrate_contacts(
        system, (0.0, duration), y0, in_contact=False, rtol=1e-10, atol=1e-14
    )
    assert len(history.impact_times) >= 1  # a thin film: the pin reaches the wall
    times = np.linspace(0.0, duration, 4001)
    states, _ = history.state(times)
    energy = np.array([system.energy(t, y) for t, y in zip(times, states, strict=True)])
    initial = 0.5 * 0.4 * speed**2
    assert np.all(np.diff(energy) <= 1e-9 * initial)
    assert energy[-1] < 0.9 * initial  # observed 0.14 (short), 0.77 (long)


def test_viscous_film_stops_the_pin_before_the_wall(paper_config: Config) -> None:
    contact = lubricated_contact(paper_config, "short-bearing", 0.05)
    system = FreePinSystem(0.4, contact)
    y0 = np.array([0.0, 0.0, 0.2, 0.0, 0.0])
    history = integrate_contacts(system, (0.0, 0.05), y0, in_contact=False)
    assert history.impact_times == []
    states, _ = history.state(np.linspace(0.0, 0.05, 2001))
    assert np.hypot(states[:, 0], states[:, 1]).max() < contact.clearance


def test_dry_film_is_no_film(paper_config: Config) -> None:
    contact = JointContact("lankarani-nikravesh", C, 1e9, 0.9, film=film.FilmParameters())
    assert contact.film is None
    assert contact.film_force(C, 0.0, 1.0, 0.0, 3.0) == (0.0, 0.0)


@pytest.mark.parametrize(
    ("fields", "match"),
    [
        ({"model": "finite-length"}, "lubrication.model.*finite-length film is available"),
        ({"model": "shortbearing"}, "lubrication.model"),
        ({"model": "short-bearing", "viscosity": -1.0}, "lubrication.viscosity"),
        ({"model": "short-bearing", "viscosity": math.nan}, "lubrication.viscosity"),
        ({"model": "short-bearing", "length": 0.0}, "lubrication.length"),
        ({"model": "short-bearing", "roughness": -1e-6}, "lubrication.roughness"),
        ({"model": "short-bearing", "transition": 0.0}, "lubrication.transition"),
    ],
)
def test_bad_film_parameters(fields: dict, match: str) -> None:
    with pytest.raises(ConfigError, match=match):
        film.FilmParameters(**fields)


def test_band_from_roughness_and_its_bounds() -> None:
    assert film.FilmParameters("short-bearing", 0.1).band(50e-6) == pytest.approx(5e-6)
    rough = film.FilmParameters("short-bearing", 0.1, roughness=4e-6)
    assert rough.band(50e-6) == pytest.approx(12e-6)
    with pytest.raises(ConfigError, match="lubrication.roughness"):
        rough.band(10e-6)
    with pytest.raises(ConfigError, match="lubrication.transition"):
        film.FilmParameters("short-bearing", 0.1, transition=60e-6).band(50e-6)
