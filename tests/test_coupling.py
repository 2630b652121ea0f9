"""Wear that feeds back: life limits, immutable states, dynamics solved on the worn joint."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from jointwear import Simulation
from jointwear.config import Config
from jointwear.coupling import DynamicsSchedule, load_change, wear_signature
from jointwear.errors import WearFeedbackWarning
from jointwear.mechanism import LoadCycle
from jointwear.results import write_metrics_csv
from jointwear.state import Log
from jointwear.tribology.metrics import WEAR_METRICS

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


def summary(config: Config) -> dict:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", WearFeedbackWarning)
        return Simulation(config).run().summary()


# ------------------------------------------------------------------ life limits


@pytest.mark.parametrize("update", [None, 1, 7])
def test_limit_stops_where_fixed_length_runs_cross_it(small: Config, update: int | None) -> None:
    """The stop revolution is the first whose fixed-length run reaches the limit."""
    overrides = {"simulation.revolutions": 100000, "life.peak_wear_depth": LIMIT}
    if update is not None:
        overrides |= {"simulation.update_contour": True, "simulation.update_every": update}
    config = small.replace(overrides)
    stopped = summary(config)
    life = stopped["life_revolutions"]
    assert stopped["stopped_by"] == "peak_wear_depth"
    assert stopped["revolutions"] == life > 10
    assert stopped["peak_wear_depth_m"] >= LIMIT
    without_limit = config.replace({"life.peak_wear_depth": None})

    def peak(revolutions: int) -> float:
        return summary(without_limit.replace({"simulation.revolutions": revolutions}))[
            "peak_wear_depth_m"
        ]

    assert peak(life - 1) < LIMIT <= peak(life)
    assert peak(life) == pytest.approx(stopped["peak_wear_depth_m"], rel=1e-12)


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


def test_every_limit_kind_and_hours(small: Config) -> None:
    config = small.replace({"simulation.revolutions": 10**6})
    free = summary(config.replace({"life.peak_wear_depth": LIMIT}))
    rate = free["peak_wear_depth_m"] / free["revolutions"]
    for key, value, metric in [
        ("wear_mass", 1e-9, "wear_mass_kg"),
        ("wear_volume", 1e-12, "wear_volume_m3"),
        ("clearance", 0.054e-3, "max_clearance_m"),
        ("wall_thickness", 2.499e-3, "min_wall_thickness_m"),
    ]:
        result = summary(config.replace({f"life.{key}": value}))
        assert result["stopped_by"] == key
        if key == "wall_thickness":
            assert result[metric] <= value
        else:
            assert result[metric] >= value
        period = 0.5  # 120 rpm
        assert result["life_hours"] == pytest.approx(result["life_revolutions"] * period / 3600)
    # no update: wear is linear, so the life is the first revolution past limit / rate
    assert free["life_revolutions"] == math.ceil(LIMIT / rate - 1e-9)


def test_no_limit_reached_reports_no_life(small: Config) -> None:
    result = summary(small.replace({"life.peak_wear_depth": 1e-3}))
    assert result["stopped_by"] is None
    assert result["life_revolutions"] is None
    assert result["life_hours"] is None


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
