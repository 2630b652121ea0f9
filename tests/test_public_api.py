"""The package's own names: ``jw.run``, ``jw.read_result``, ``jw.models`` and what ``dir`` lists."""

from __future__ import annotations

import json

import pytest

import jointwear as jw
from jointwear.cli import main
from jointwear.config import MECHANISM_TYPES
from jointwear.errors import ConfigError, DataError
from jointwear.results.summary import WALL_CLOCK_KEYS

FAST = {"contact.nodes": 120, "simulation.steps_per_revolution": 90}


def without_runtime(summary: dict) -> dict:
    return {key: value for key, value in summary.items() if key not in WALL_CLOCK_KEYS}


def test_run_is_the_simulation_of_the_config_with_its_overrides(paper_config_path):
    wide = {**FAST, "joint.clearance": "0.2 mm", "simulation.revolutions": 2000}
    expected = jw.Simulation(jw.load_config(paper_config_path, wide)).run().summary()
    from_path = jw.run(paper_config_path, wide)
    assert isinstance(from_path, jw.WearResult)
    assert without_runtime(from_path.summary()) == without_runtime(expected)
    # a Config, "key=value" strings and keywords (a double underscore for the dot) alike
    base = jw.load_config(paper_config_path)
    strings = [f"{key}={value}" for key, value in wide.items() if key != "joint.clearance"]
    from_config = jw.run(base, ['joint.clearance="0.2 mm"', *strings])
    keywords = jw.run(
        paper_config_path, FAST, joint__clearance="0.2 mm", simulation__revolutions=2000
    )
    for result in (from_config, keywords):
        assert without_runtime(result.summary()) == without_runtime(expected)


def test_run_refuses_what_is_not_a_config(paper_config_path):
    with pytest.raises(ConfigError, match="^config: expected a Config or the path"):
        jw.run(42)
    with pytest.raises(ConfigError, match="^overrides: expected"):
        jw.run(paper_config_path, 5)


def test_read_result_gives_back_the_run_it_was_written_by(paper_config_path, tmp_path, capsys):
    out = tmp_path / "run"
    sets = [arg for key, value in FAST.items() for arg in ("--set", f"{key}={value}")]
    main(["run", str(paper_config_path), *sets, "--out", str(out), "--no-plots", "-q"])
    capsys.readouterr()
    result = jw.read_result(out / "result.nc")
    written = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    written.pop("checks")
    assert result.summary() == written
    # (the stored config is the resolved one: derived defaults written out)
    assert result.config.to_toml() == jw.load_config(paper_config_path, FAST).to_toml()


def test_read_result_of_a_file_that_is_no_result(tmp_path):
    path = tmp_path / "result.nc"
    path.write_text("not netCDF", encoding="utf-8")
    with pytest.raises(DataError, match="result.nc"):
        jw.read_result(path)


def test_models_are_the_registries_names():
    names = jw.models()
    assert list(names["mechanism.type"]) == list(MECHANISM_TYPES)
    assert {"hertz", "winkler", "asymmetric-winkler", "nlcp"} <= set(names["contact.model"])
    assert {"archard", "energy"} <= set(names["wear.law"])
    # each key is one a config sets, and its names are the ones it takes
    for model in ("hertz", "winkler", "asymmetric-winkler", "nlcp"):
        assert jw.load_config(overrides={"contact.model": model}).contact.model == model
    with pytest.raises(ConfigError, match="^dynamics.model: "):
        jw.load_config(overrides={"dynamics.model": "no-such-model"})


def test_dir_lists_the_public_names_and_not_the_command_lines():
    listed = set(dir(jw))
    public = {"run", "Simulation", "load_config", "Config", "LoadCycle", "WearResult"}
    assert public | {"read_result", "models", "life", "materials"} <= listed
    assert not listed & {"cli", "display", "paper", "checkpoint"}
    # not listed, still reachable
    assert jw.cli.__name__ == "jointwear.cli"
    assert jw.checkpoint.__name__ == "jointwear.checkpoint"
    assert jw.LoadCycle is jw.mechanism.LoadCycle
    with pytest.raises(AttributeError):
        _ = jw.no_such_name
