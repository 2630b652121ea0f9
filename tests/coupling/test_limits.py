"""Life limits: the run ends where a ``[life]`` limit is reached, a fraction of a
revolution included, on every path the wear takes."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from jointwear.config import Config
from jointwear.coupling import LIFE_LIMITS, LifeLimits
from jointwear.tribology.metrics import JointGeometry
from tests.coupling.conftest import simulate, summary

LIMIT = 4e-6  # peak wear depth limit [m]


@pytest.mark.parametrize("update", [None, 1, 7])
def test_limit_stop_lies_between_the_fixed_length_runs(small: Config, update: int | None) -> None:
    """The stop is inside the revolution where fixed-length runs cross the limit, at it."""
    overrides = {"simulation.revolutions": 100000, "life.peak_wear_depth": LIMIT}
    if update is not None:
        overrides |= {
            "simulation.update_contour": True,
            "simulation.update_every": update,
            "contact.model": "asymmetric-winkler",
        }
    config = small.replace(overrides)
    stopped = summary(config)
    life = stopped["life_revolutions"]
    assert stopped["stopped_by"] == "peak_wear_depth"
    assert stopped["revolutions"] == life > 10
    assert stopped["peak_wear_depth_m"] == pytest.approx(LIMIT, rel=1e-12, abs=0)
    without_limit = config.replace({"life.peak_wear_depth": None})

    def peak(revolutions: int) -> float:
        return summary(without_limit.replace({"simulation.revolutions": revolutions}))[
            "peak_wear_depth_m"
        ]

    assert peak(math.floor(life)) < LIMIT <= peak(math.ceil(life))


def test_limit_inside_an_adaptive_jump(small: Config) -> None:
    """Adaptive jumps stop inside the jump, within the tolerance of per-revolution updating."""
    base = small.replace(
        {
            "simulation.revolutions": 200000,
            "simulation.update_contour": True,
            "life.peak_wear_depth": 3e-5,
        }
    )
    adaptive = summary(base.replace({"simulation.update_every": "adaptive"}))
    reference = summary(base.replace({"simulation.update_every": 1}))
    assert adaptive["contour_updates"] < reference["contour_updates"] / 20
    assert adaptive["life_revolutions"] == pytest.approx(reference["life_revolutions"], rel=5e-3)
    assert adaptive["peak_wear_depth_m"] == pytest.approx(3e-5, rel=1e-3)


def test_no_limit_reached_reports_no_life(small: Config) -> None:
    result = summary(small.replace({"life.peak_wear_depth": 1e-3}))
    assert result["stopped_by"] is None
    assert result["life_revolutions"] is None
    assert result["life_hours"] is None


# ------------------------------------------------------------------ stops inside a revolution

#: how a run advances the wear: the three paths a stop is interpolated on
SCHEMES = {
    "no update": {},
    "fixed": {"simulation.update_contour": True, "simulation.update_every": 7},
    "adaptive": {"simulation.update_contour": True, "simulation.update_every": "adaptive"},
}
PERIOD = 0.5  # 120 rpm [s]


@pytest.fixture(scope="module")
def wearing(paper_config: Config) -> Config:
    """The paper's joint, coarse, worn through in ~200-500 revolutions."""
    return paper_config.replace(
        {
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 90,
            "contact.model": "asymmetric-winkler",
            "materials.bushing.wear_coefficient": 1e-9,
            "simulation.revolutions": 10000,
        }
    )


def bushing_mass(config: Config) -> float:
    """Mass of the unworn bushing ``rho pi ((R + L)^2 - R^2) b`` [kg]."""
    joint = config.joint
    radius, wall = joint.bushing_radius, joint.bushing_thickness
    area = math.pi * ((radius + wall) ** 2 - radius**2)
    return config.materials.bushing.density * area * joint.axial_length


def assert_consistent_stop(result, config: Config) -> None:
    """The life keys, the record and the saved profiles all end at the same stop."""
    data = result.summary()
    life = data["life_revolutions"]
    assert data["revolutions"] == life
    assert data["life_hours"] == pytest.approx(life * PERIOD / 3600, rel=1e-12, abs=0)
    assert result.dataset["update_revolution"].values[-1] == life
    assert result.dataset["revolution"].values[-1] == life
    assert 0 < life < config.simulation.revolutions


@pytest.mark.parametrize(
    "update", [None, 1, 10, "adaptive"], ids=["no update", "every 1", "every 10", "adaptive"]
)
def test_wear_through_within_the_first_revolution_ends_at_the_wall(
    wearing: Config, update: int | str | None
) -> None:
    """K = 1e-3 wears through the wall in a fraction of the first revolution: the run ends
    there, with the wall at exactly 0 and the worn mass below the bushing's."""
    config = wearing.replace({"materials.bushing.wear_coefficient": 1e-3})
    if update is not None:
        config = config.replace(
            {"simulation.update_contour": True, "simulation.update_every": update}
        )
    result = simulate(config)
    data = result.summary()
    thickness = config.joint.bushing_thickness
    assert data["stopped_by"] == "wall_thickness"
    assert 0.0 <= data["min_wall_thickness_m"] <= 1e-12
    assert data["peak_wear_depth_m"] <= thickness
    assert data["wear_mass_kg"] < bushing_mass(config)
    assert_consistent_stop(result, config)
    # the first revolution is linear from the unworn contour, so the stop has a closed
    # form: the wall over the peak wear of one revolution (Archard's wear is linear in K)
    reference = 5.05e-13
    one = summary(
        wearing.replace(
            {"materials.bushing.wear_coefficient": reference, "simulation.revolutions": 1}
        )
    )
    rate = one["peak_wear_depth_m"] * 1e-3 / reference
    assert data["life_revolutions"] < 1
    assert data["life_revolutions"] == pytest.approx(thickness / rate, rel=1e-9, abs=0)


def test_a_wearing_pin_stops_with_the_bushing_on_its_own_path(wearing: Config) -> None:
    """The pin's wear at the stop is its rate times the fractional life, like the
    bushing's (both linear in their wear coefficients over the first update)."""
    pin = wearing.replace(
        {
            "contact.nodes": 60,
            "simulation.steps_per_revolution": 60,
            "simulation.update_contour": True,
            "simulation.update_every": 1000,
        }
    )
    worn = pin.replace(
        {"materials.bushing.wear_coefficient": 1e-6, "materials.pin.wear_coefficient": 1e-6}
    )
    data = summary(worn)
    one = summary(
        pin.replace(
            {
                "simulation.revolutions": 1,
                "materials.bushing.wear_coefficient": 1e-12,
                "materials.pin.wear_coefficient": 1e-12,
            }
        )
    )
    life = data["life_revolutions"]
    assert data["stopped_by"] == "wall_thickness"
    assert 0 < life < 1
    assert 0.0 <= data["min_wall_thickness_m"] <= 1e-12
    for key in ("peak_wear_depth_m", "pin_peak_wear_depth_m"):
        assert data[key] == pytest.approx(one[key] * 1e6 * life, rel=1e-9), key


LIMITS = {
    "peak_wear_depth": (3e-4, "peak_wear_depth_m"),
    "wear_mass": (1e-4, "wear_mass_kg"),
    "wear_volume": (5e-8, "wear_volume_m3"),
    "clearance": (3.5e-4, "max_clearance_m"),
    "wall_thickness": (2.2e-3, "min_wall_thickness_m"),
}


@pytest.mark.parametrize("scheme", SCHEMES)
@pytest.mark.parametrize("key", LIMITS)
def test_each_limit_ends_at_its_value(wearing: Config, key: str, scheme: str) -> None:
    """Every limit kind, on every path: the metric at the stop is the limit."""
    limit, metric = LIMITS[key]
    config = wearing.replace({**SCHEMES[scheme], f"life.{key}": limit})
    result = simulate(config)
    data = result.summary()
    assert data["stopped_by"] == key
    assert data[metric] == pytest.approx(limit, rel=1e-9, abs=0)
    assert_consistent_stop(result, config)
    assert not float(data["life_revolutions"]).is_integer()
    # the update before the stop had not reached it
    sense = LIFE_LIMITS[key][1]
    history = result.dataset[LIFE_LIMITS[key][0]].values
    if history.size > 1:
        assert sense * (history[-2] - limit) < 0


@pytest.mark.parametrize("scheme", SCHEMES)
def test_a_billion_revolutions_never_wear_below_the_wall(wearing: Config, scheme: str) -> None:
    config = wearing.replace(
        {
            **SCHEMES[scheme],
            "simulation.revolutions": 10**9,
            "materials.bushing.wear_coefficient": 5.05e-13,
        }
    )
    if scheme == "fixed":  # (long linear steps: the stop falls deep inside one)
        config = config.replace({"simulation.update_every": 10**5})
    result = simulate(config)
    data = result.summary()
    assert data["stopped_by"] == "wall_thickness"
    assert 0.0 <= data["min_wall_thickness_m"] <= 1e-12
    assert np.min(result.dataset["min_wall_thickness"].values) >= 0.0
    assert data["peak_wear_depth_m"] <= config.joint.bushing_thickness
    assert_consistent_stop(result, config)


@settings(max_examples=8, deadline=None)
@given(
    exponent=st.floats(min_value=-10.0, max_value=-4.0),
    factor=st.floats(min_value=1.001, max_value=100.0),
)
@pytest.mark.parametrize("update", [None, 5], ids=["no update", "every 5"])
def test_a_larger_wear_coefficient_stops_earlier(
    wearing: Config, update: int | None, exponent: float, factor: float
) -> None:
    """A larger K stops earlier; without contour update in exact inverse proportion."""
    base = wearing
    if update is not None:
        base = base.replace({"simulation.update_contour": True, "simulation.update_every": update})
    lives = [
        simulate(
            base.replace({"materials.bushing.wear_coefficient": k}), pressures=False
        ).summary()["life_revolutions"]
        for k in (10.0**exponent, factor * 10.0**exponent)
    ]
    assert lives[1] < lives[0]
    if update is None:
        assert lives[0] == pytest.approx(factor * lives[1], rel=1e-9)


def joint() -> JointGeometry:
    return JointGeometry(
        bushing_radius=7.5e-3, clearance=5e-5, axial_length=0.02, bushing_thickness=2.5e-3,
        density=2200.0,
    )  # fmt: skip


def test_a_peak_limit_on_a_quadratic_path_is_found_where_the_first_node_reaches_it() -> None:
    """The corrector's quadratic: each node's crossing is a root of a quadratic."""
    rng = np.random.default_rng(3)
    start, rate, end = rng.uniform(0, 1e-4, 8), rng.uniform(0, 2e-5, 8), rng.uniform(0, 3e-5, 8)
    jump = 40.0

    def depth_at(n: float) -> np.ndarray:
        return start + n * rate + (0.5 * n * n / jump) * (end - rate)

    limit = 6e-4
    limits = LifeLimits((("peak_wear_depth", "peak_wear_depth", limit, 1),), joint())
    at, key = limits.first_reached(depth_at, jump)
    # a n^2 + b n + c = 0 per node, the root in [0, jump]
    a, b, c = 0.5 * (end - rate) / jump, rate, start - limit
    roots = np.where(
        np.abs(a) > 0, (-b + np.sqrt(b * b - 4 * a * c)) / (2 * np.where(a == 0, 1, a)), -c / b
    )
    assert key == "peak_wear_depth"
    assert at == pytest.approx(roots[(roots >= 0) & (roots <= jump)].min(), rel=1e-12)
    assert depth_at(at).max() == pytest.approx(limit, rel=1e-12, abs=0)


def test_a_mass_limit_on_a_linear_path_is_the_root_of_the_area_quadratic() -> None:
    """The removed area ``pi/N sum h (2R + h)`` is quadratic in the revolutions."""
    geometry = joint()
    start, rate = np.linspace(0, 2e-5, 8), np.linspace(1e-6, 3e-6, 8)
    mass = 2e-4
    limits = LifeLimits((("wear_mass", "wear_mass", mass, 1),), geometry)
    at, key = limits.first_reached(lambda n: start + n * rate, 1000.0, (start, rate))
    scale = geometry.density * geometry.axial_length * np.pi / start.size
    radius = geometry.bushing_radius
    a = scale * np.sum(rate**2)
    b = scale * np.sum(2 * rate * (radius + start))
    c = scale * np.sum(start * (2 * radius + start)) - mass
    assert key == "wear_mass"
    assert at == pytest.approx((-b + math.sqrt(b * b - 4 * a * c)) / (2 * a), rel=1e-12)


def test_the_first_limit_in_time_ends_the_run_and_ties_go_in_table_order() -> None:
    geometry = replace(joint(), clearance=2.0**-14)  # (binary fractions: an exact tie)
    start, rate = np.zeros(8), np.full(8, 2.0**-17)
    path = (lambda n: start + n * rate, 100.0, (start, rate))
    peak = ("peak_wear_depth", "peak_wear_depth", 2.0**-13, 1)  # at 16 revolutions
    early = ("clearance", "max_clearance", 2.0**-14 + 2.0**-15, 1)  # at 4
    tied = ("clearance", "max_clearance", 2.0**-14 + 2.0**-13, 1)  # at 16
    assert LifeLimits((peak, early), geometry).first_reached(*path) == (4.0, "clearance")
    assert LifeLimits((peak, tied), geometry).first_reached(*path) == (16.0, "peak_wear_depth")
    assert LifeLimits((peak,), geometry).first_reached(lambda n: start + n * rate, 9.0) is None
