"""The progress bar: no thread of its own; where a life limit ended a run, it stays."""

from __future__ import annotations


def test_progress_bar_on_a_terminal_runs_no_thread():
    # a sweep forks its workers only while the process has a single thread
    import threading

    from jointwear.cli.progress import ProgressBar

    before = threading.active_count()
    with ProgressBar("cases", delay=0.0) as bar:
        bar.enabled = True  # as on a terminal
        for done in range(5):
            bar(done, 5)
            assert threading.active_count() == before
        assert bar._bar is not None
        bar(5, 5)
    assert bar._bar is None


def test_progress_bar_ends_where_a_limit_ended_the_run(monkeypatch):
    """The bar stays on screen at the stop with the limit, not at total/total."""
    import io

    from rich.console import Console

    import jointwear.cli.progress as progress
    from jointwear.cli.progress import ProgressBar, run_ends

    screen = io.StringIO()
    monkeypatch.setattr(progress, "err_console", Console(file=screen, force_terminal=True))
    summary = {"revolutions": 10755123.25, "stopped_by": "wall_thickness"}
    with ProgressBar("revolutions", delay=0.0) as bar:
        bar.enabled = True  # as on a terminal
        bar(1000, 100000000)
        bar(10755123.25, 10755123.25)  # the run is complete, ended at a limit
        assert bar._bar.tasks[0].total == 100000000
        bar.finish(*run_ends(summary))
        assert bar._bar.tasks[0].completed == 10755123.25
        kept = not bar._bar.live.transient
    assert kept
    assert "stopped: wall_thickness" in screen.getvalue()
    assert "10755123/100000000" in screen.getvalue()
    assert "100000000/100000000" not in screen.getvalue()
    assert run_ends({"revolutions": 1000, "stopped_by": None}) == (1000.0, "revolutions")
