"""Wear that feeds back: life limits, immutable states, dynamics solved on the worn joint."""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from jointwear import Simulation
from jointwear.config import Config
from jointwear.coupling import (
    LIFE_LIMITS,
    DynamicsSchedule,
    LifeLimits,
    load_change,
    wear_signature,
)
from jointwear.errors import WearFeedbackWarning
from jointwear.mechanism import LoadCycle
from jointwear.results import write_metrics_csv
from jointwear.state import Log
from jointwear.tribology.metrics import WEAR_METRICS, JointGeometry

LIMIT = 4e-6  # peak wear depth limit [m]


@pytest.fixture(scope="module")
def small(paper_config: Config) -> Config:
    return paper_config.replace(
        {
            "contact.nodes": 120,
            "simulation.steps_per_revolution": 90,
            "contact.model": "asymmetric-winkler",
        }
    )


def simulate(config: Config, pressures: bool = True):
    """The result of a run (the worn joint's load warnings are not the question here)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", WearFeedbackWarning)
        return Simulation(config).run(pressures=pressures)


def summary(config: Config) -> dict:
    return simulate(config).summary()


# ------------------------------------------------------------------ life limits


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
    assert stopped["peak_wear_depth_m"] == pytest.approx(LIMIT, rel=1e-12)
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
    assert data["life_hours"] == pytest.approx(life * PERIOD / 3600, rel=1e-12)
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
    assert data["life_revolutions"] == pytest.approx(thickness / rate, rel=1e-9)


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
    assert data[metric] == pytest.approx(limit, rel=1e-9)
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
    assert depth_at(at).max() == pytest.approx(limit, rel=1e-12)


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


# ------------------------------------------------------------------ the orchestrator


def test_states_are_immutable_and_do_not_share_records(small: Config) -> None:
    simulation = Simulation(
        small.replace({"simulation.update_contour": True, "simulation.revolutions": 5})
    )
    s0 = simulation.initial_state()
    s1 = simulation.step(s0)
    s2 = simulation.step(s1)
    assert [len(s.history) for s in (s0, s1, s2)] == [0, 1, 2]
    assert s1.history_columns["revolution"] == [1]
    with pytest.raises(ValueError, match="read-only"):
        s2.wear_depth[0] = 1.0
    with pytest.raises(AttributeError):
        s2.revolution = 7  # type: ignore[misc]
    # a retried step from the same state gives the same state, not a longer record
    again = simulation.step(s1)
    np.testing.assert_array_equal(again.wear_depth, s2.wear_depth)
    assert len(again.history) == 2


def test_log_is_persistent() -> None:
    a = Log().append(1).append(2)
    b = a.append(3)
    c = a.append(4)
    assert [list(a), list(b), list(c)] == [[1, 2], [1, 2, 3], [1, 2, 4]]
    assert Log.of([{"x": 1}, {"x": 2}]).columns() == {"x": [1, 2]}


def test_one_metric_schema_drives_record_dataset_summary_and_csv(small: Config, tmp_path) -> None:
    result = Simulation(
        small.replace(
            {
                "simulation.update_contour": True,
                "simulation.revolutions": 20,
                "simulation.update_every": 5,
            }
        )
    ).run()
    data = result.summary()
    for metric in WEAR_METRICS:
        assert result.dataset[metric.name].attrs["units"] == metric.units
        if metric.key is not None:
            last = float(result.dataset[metric.name].values[-1])
            assert data[metric.key] == pytest.approx(last * metric.scale, rel=1e-15)
    write_metrics_csv(result.dataset, tmp_path / "m.csv")
    header = (tmp_path / "m.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    assert header == ["revolution"] + [m.header for m in WEAR_METRICS]


# ------------------------------------------------------------------ dynamics feedback


def test_wear_signature_sees_where_the_load_wears() -> None:
    steps = 360
    cycle = LoadCycle.from_arrays(
        np.full(steps, 100.0), np.full(steps, 0.3), np.full(steps, 0.01), period=1.0
    )
    signature = wear_signature(cycle)
    assert signature.sum() == pytest.approx(100.0 * 0.01 * steps)
    assert np.argmax(signature) == round(0.3 / (2 * np.pi) * 72)
    turned = LoadCycle.from_arrays(cycle.load, cycle.azimuth + 0.5, cycle.relative_rotation)
    assert load_change(cycle, cycle) == 0.0
    # the load now wears elsewhere: no overlap, so the change is the hypotenuse of both norms
    before, after = np.linalg.norm(signature), np.linalg.norm(wear_signature(turned))
    assert load_change(cycle, turned) == pytest.approx(math.hypot(before, after) / before)
    assert load_change(cycle, cycle.with_load(1.1 * cycle.load)) == pytest.approx(0.1)


def test_adaptive_schedule_aims_at_the_tolerance() -> None:
    schedule = DynamicsSchedule("adaptive", 0.02)
    assert schedule.first_threshold(5e-5) == pytest.approx(1e-6)
    # the load moved 1 % over 10 um of wear: 0.9 x 2 % needs 18 um, capped at 4 x
    assert schedule.next_threshold(1e-5, 0.01, 6e-5) == pytest.approx(1.8e-5)
    assert schedule.next_threshold(1e-5, 1e-6, 6e-5) == pytest.approx(4e-5)
    # scatter without wear does not drive the interval below tolerance x clearance
    assert schedule.next_threshold(1e-7, 0.5, 1e-4) == pytest.approx(2e-6)
    assert DynamicsSchedule(3, 0.02).due(3, 0.0, 1.0)
    assert not DynamicsSchedule("once", 0.02).due(10**6, 1.0, 0.0)


def test_once_is_todays_result(small: Config) -> None:
    config = small.replace(
        {
            "simulation.update_contour": True,
            "simulation.revolutions": 500,
            "simulation.update_every": 50,
        }
    )
    default = Simulation(config).run().summary()
    once = Simulation(config.replace({"simulation.dynamics_update": "once"})).run().summary()
    assert once == {**default, "runtime_s": once["runtime_s"]}
    assert default["dynamics_updates"] == 0


def test_paper_joint_coupling_changes_little(paper_config: Config) -> None:
    """Pulling spring, continuous contact: the worn joint's load hardly moves (0.12 % at 1e5 r)."""
    config = paper_config.replace(
        {
            "contact.model": "nlcp",
            "simulation.update_contour": True,
            "simulation.update_every": "adaptive",
            "simulation.revolutions": 100000,
        }
    )
    once = summary(config)
    coupled = summary(config.replace({"simulation.dynamics_update": "adaptive"}))
    assert coupled["dynamics_updates"] >= 2
    assert coupled["peak_wear_depth_m"] == pytest.approx(once["peak_wear_depth_m"], rel=5e-3)
    assert coupled["wear_mass_kg"] == pytest.approx(once["wear_mass_kg"], rel=5e-3)
    assert coupled["peak_wear_depth_m"] != once["peak_wear_depth_m"]


def test_separating_joint_impacts_appear_as_it_wears(paper_config: Config) -> None:
    """Push spring, 1 N preload, 240 rpm, light rod: continuous contact on the new joint,
    impacts once the clearance has grown; the coupled wear differs from the uncoupled."""
    config = paper_config.replace(
        {
            "mechanism.spring_mode": "push",
            "mechanism.spring_preload": 1.0,
            "mechanism.crank_speed": "240 rpm",
            "mechanism.rod_mass": 0.3,
            "dynamics.model": "contact-impact",
            "simulation.steps_per_revolution": 90,
            "contact.nodes": 120,
            "materials.bushing.wear_coefficient": 5e-11,
            "simulation.revolutions": 200,
            "simulation.update_contour": True,
            "simulation.update_every": 25,
        }
    )
    once = Simulation(config).run()
    with pytest.warns(WearFeedbackWarning, match="separates"):
        coupled = Simulation(config.replace({"simulation.dynamics_update": 2})).run()
    impacts = coupled.dataset["dynamics_impacts"].values
    clearance = coupled.dataset["dynamics_max_clearance"].values
    assert impacts[0] == 0  # the unworn joint stays in contact
    assert np.all(np.diff(clearance) > 0)
    assert impacts[-1] > 0
    assert impacts.max() >= 3
    a, b = once.summary(), coupled.summary()
    assert b["dynamics_updates"] == 3
    assert abs(b["wear_mass_kg"] / a["wear_mass_kg"] - 1) > 1e-3


def test_a_given_load_cycle_is_never_resolved(small: Config) -> None:
    cycle = Simulation(small).load_cycle
    config = small.replace(
        {
            "simulation.dynamics_update": 1,
            "simulation.update_contour": True,
            "simulation.revolutions": 5,
        }
    )
    result = Simulation(config, load_cycle=cycle).run().summary()
    assert result["dynamics_updates"] == 0


def test_massless_link_warns_when_wear_passes_the_clearance(small: Config) -> None:
    config = small.replace(
        {
            "simulation.revolutions": 40000,
            "simulation.update_contour": True,
            "simulation.update_every": "adaptive",
        }
    )
    with pytest.warns(WearFeedbackWarning, match="contact-impact") as caught:
        Simulation(config).run()
    assert sum("clearance" in str(w.message) for w in caught) == 1  # said once
