"""A notebook session, cell by cell: load, change, run, look, plot -- no file written.

What a user types in Jupyter must work without a backend choice, without
pyplot and without touching the working folder or matplotlib's settings.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest
from matplotlib.figure import Figure

import jointwear as jw
from jointwear.display import wear_result_html, wear_result_repr
from jointwear.plots import FIGURES, plot_dataset, plot_wear_result


@pytest.fixture
def session(tmp_path, monkeypatch, paper_config_path):
    """An empty working folder and matplotlib's settings before the session."""
    monkeypatch.chdir(tmp_path)
    return paper_config_path, dict(dict.items(matplotlib.rcParams))


def test_load_change_run_plot(session, tmp_path) -> None:
    path, settings = session

    # [1] what is there
    assert jw.__version__ != "0+unknown"
    assert {"Config", "Simulation", "WearResult", "load_config", "plots"} <= set(dir(jw))

    # [2] load and change (a config is immutable: replace returns a new one)
    config = jw.load_config(path)
    wider = config.replace({"joint.clearance": "0.2 mm", "contact.model": "nlcp"})
    assert wider.joint.clearance == pytest.approx(0.2e-3)
    assert config.joint.clearance == pytest.approx(0.05e-3)

    # [3] run and look
    result = jw.Simulation(wider).run()
    text = wear_result_repr(result)
    assert text.startswith("<WearResult nlcp, 1 r: peak ")
    assert "\n" not in text
    assert len(text) < 120
    page = wear_result_html(result)
    assert page.startswith("<div>")
    assert "wear width" in page

    # [4] plot: every kind is a Figure; the polar figure shows the worn contour
    for kind in FIGURES:
        assert isinstance(plot_wear_result(result, kind), Figure)
    fig = plot_wear_result(result)
    radii = fig.axes[0].lines[1].get_ydata()  # mm, wear magnified
    assert radii.max() > fig.axes[0].lines[0].get_ydata()[0]

    # nothing written, no global setting changed
    assert list(tmp_path.iterdir()) == []
    assert dict(dict.items(matplotlib.rcParams)) == settings


def test_unknown_figure_kind_is_an_error(paper_config) -> None:
    result = jw.Simulation(paper_config).run()
    with pytest.raises(jw.JointwearError, match="unknown figure 'polar'"):
        plot_wear_result(result, "polar")


def test_old_results_with_crank_angle_redraw(paper_config) -> None:
    """Results written before the per-step coordinate was called ``phase`` still plot."""
    dataset = jw.Simulation(paper_config).run().dataset
    if "phase" in dataset.coords:
        old = dataset.rename({"phase": "crank_angle"})
        new = dataset
    else:
        old = dataset
        new = dataset.rename({"crank_angle": "phase"})
    curves = [plot_dataset(d, "joint_load").axes[1] for d in (old, new)]
    assert curves[0].get_xlabel() == curves[1].get_xlabel() == "cycle phase [deg]"
    np.testing.assert_array_equal(curves[0].lines[0].get_xdata(), curves[1].lines[0].get_xdata())


def test_reprs_are_short(params, circle, pin) -> None:
    from jointwear.contact import solve

    solution = solve(circle, pin, np.array([100.0, 200.0]), np.zeros(2), "winkler", params)
    assert repr(solution).startswith("<ContactSolution winkler: 2 loads x 360 nodes")
    assert repr(circle).startswith("<BushingContour 360 nodes, R0 7.5 mm")


def test_version_is_not_importlibs_function() -> None:
    assert not callable(getattr(jw, "version", None))
    assert isinstance(jw.__version__, str)
