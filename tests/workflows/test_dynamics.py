"""Load cycles of the joints: the CSV reads back as the same load, warnings come before files."""

from __future__ import annotations

import numpy as np
import pytest

from jointwear.errors import ConfigError, MechanismError
from jointwear.mechanism.history import read_load_history
from jointwear.workflows.dynamics import csv_paths, joint_load_cycles

CONTACT_LOSS = [
    "mechanism.spring_mode=push",
    "mechanism.spring_preload=1",
    "mechanism.crank_speed=240 rpm",
]


def test_the_csv_reads_back_as_the_same_load_cycle(paper_config_path, tmp_path):
    path = tmp_path / "sub" / "load.csv"
    done = joint_load_cycles(paper_config_path, csv_path=path)
    (cycle,) = done.cycles.values()
    back = read_load_history(path)
    np.testing.assert_allclose(back.load, cycle.load, rtol=1e-12)
    np.testing.assert_allclose(np.cos(back.azimuth - cycle.azimuth), 1.0, rtol=0, atol=1e-12)
    (summary,) = done.summaries.values()
    assert summary["clearance_m"] == pytest.approx(done.config.joint.clearance)


def test_warnings_are_handed_over_before_the_files_are_written(paper_config_path, tmp_path):
    path = tmp_path / "load.csv"
    seen = []

    def on_warnings(messages: list[str]) -> None:
        seen.append((messages, path.exists()))

    joint_load_cycles(
        paper_config_path, overrides=CONTACT_LOSS, csv_path=path, on_warnings=on_warnings
    )
    ((messages, written),) = seen
    assert any("contact" in message for message in messages)
    assert not written
    assert path.is_file()


def test_strict_turns_the_lost_contact_into_an_error(paper_config_path, tmp_path):
    with pytest.raises(MechanismError, match="assumes continuous contact"):
        joint_load_cycles(paper_config_path, overrides=CONTACT_LOSS, strict=True)


def test_a_directory_as_csv_target_is_refused_before_the_dynamics(tmp_path):
    (tmp_path / "load.csv").mkdir()
    with pytest.raises(ConfigError, match="is a directory"):
        joint_load_cycles(tmp_path / "missing.toml", csv_path=tmp_path / "load.csv")


def test_several_joints_get_a_file_each(tmp_path):
    path = tmp_path / "load.csv"
    assert csv_paths(path, ["B"]) == {"B": path}
    assert csv_paths(path, ["B", "C"]) == {
        "B": tmp_path / "load.B.csv",
        "C": tmp_path / "load.C.csv",
    }
