"""`jointwear sweep`: a sweep resumed from its folder, a sweep on a dask scheduler."""

from __future__ import annotations

import json

import pytest

from jointwear.cli import main
from jointwear.workflows.sweep import PLAN_FILE
from tests.workflows.sweep.conftest import TINY, write_sweep


def test_cli_sweep_resume(tmp_path, capsys):
    path = write_sweep(tmp_path, TINY + '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n')
    out = tmp_path / "out"
    main(["sweep", str(path), "--out", str(out), "--json", "--workers", "1"])
    first = json.loads(capsys.readouterr().out)
    assert first["ok"] == 2
    (out / "cases" / "case-0001.json").unlink()
    main(["sweep", "--resume", str(out), "--json", "--workers", "1"])
    second = json.loads(capsys.readouterr().out)
    assert second["skipped"] == 1
    assert second["ok"] == 2
    assert json.loads((out / PLAN_FILE).read_text())["keys"] == ["joint.clearance"]


def test_cli_sweep_on_a_dask_scheduler(tmp_path, capsys):
    distributed = pytest.importorskip("dask.distributed")
    path = write_sweep(tmp_path, TINY + '[grid]\n"joint.clearance" = ["0.05 mm", "0.1 mm"]\n')
    with distributed.LocalCluster(
        n_workers=1, processes=False, threads_per_worker=2, dashboard_address=None
    ) as cluster:
        main(
            [
                "sweep",
                str(path),
                "--out",
                str(tmp_path / "out"),
                "--json",
                "--scheduler",
                cluster.scheduler_address,
            ]
        )
    summary = json.loads(capsys.readouterr().out)
    assert summary["scheduler"] == cluster.scheduler_address
    assert summary["ok"] == 2
