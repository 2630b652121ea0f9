"""What the command line imports: the plain run path stays free of heavy libraries.

Each check runs in a fresh interpreter (``sys.modules`` of the test process already
holds everything) and reports the modules loaded when the command has finished.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from jointwear import load_config
from jointwear.contact.solver import COMPILED_KERNEL_SOLVES, compiled_kernel

SRC = Path(__file__).resolve().parents[2] / "src"
#: libraries a summary of a run needs none of (the dask package itself is not one of them:
#: pint imports ``dask.base`` whenever dask is installed)
HEAVY = ("dask.array", "xarray", "pandas", "matplotlib", "distributed")
ONE_REVOLUTION = ["--set", "simulation.revolutions=1", "--json", "-q"]


def heavy(modules: set[str]) -> list[str]:
    """The modules of :data:`HEAVY` (or inside them) among ``modules``."""
    return [m for m in modules if any(m == h or m.startswith(h + ".") for h in HEAVY)]


def loaded_after(code: str, tmp_path: Path) -> set[str]:
    """Top-level and dotted module names loaded after ``code`` ran in a fresh interpreter."""
    report = tmp_path / "modules.json"
    script = (
        "import json, sys\n"
        f"{code}\n"
        f"open({str(report)!r}, 'w').write(json.dumps(sorted(sys.modules)))\n"
    )
    path = os.pathsep.join([str(SRC), os.environ.get("PYTHONPATH", "")])
    env = {**os.environ, "PYTHONPATH": path}
    env.pop("JOINTWEAR_NO_NUMBA", None)
    done = subprocess.run(
        [sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=300
    )
    assert done.returncode == 0, done.stderr
    return set(json.loads(report.read_text()))


def cli(args: list[str]) -> str:
    return f"from jointwear.cli import main\nmain({args!r})"


@pytest.mark.parametrize("model", ["nlcp", "winkler", "asymmetric-winkler", "hertz"])
def test_plain_run_imports_no_dataset_plotting_or_compiler_library(
    paper_config_path, tmp_path, model
):
    modules = loaded_after(
        cli(["run", str(paper_config_path), "--set", f"contact.model={model}", *ONE_REVOLUTION]),
        tmp_path,
    )
    assert not heavy(modules)
    # one revolution plans two contact solves: the NumPy kernel, numba never loaded
    assert "numba" not in modules
    # a JSON summary prints through no rich console (a warning does: Hertz's range here);
    # a slider-crank loads no other mechanism
    assert ("rich" in modules) == (model == "hertz")
    others = ("jointwear.mechanism.four_bar", "jointwear.mechanism.oscillating")
    assert not [m for m in modules if m.startswith(others)]


def test_a_config_of_si_numbers_runs_without_pint(paper_config_path, tmp_path):
    # a plain number is SI: no text to read, so no pint (nor the dask.base pint imports
    # where dask is installed); the resolved config of the paper's joint is all numbers
    config = tmp_path / "si.toml"
    config.write_text(load_config(paper_config_path).to_toml())
    modules = loaded_after(cli(["run", str(config), *ONE_REVOLUTION]), tmp_path)
    assert "pint" not in modules
    assert "dask" not in modules


def test_short_contact_impact_run_does_not_load_numba(paper_config_path, tmp_path):
    # one settled revolution of contact-impact dynamics is faster in Python than numba's load
    # (under LSODA; the default "auto" integrates the slider-crank compiled whatever the run)
    lsoda = ["--set", "dynamics.integrator=LSODA"]
    args = ["--set", "dynamics.model=contact-impact", *lsoda, *ONE_REVOLUTION]
    modules = loaded_after(cli(["run", str(paper_config_path), *args]), tmp_path)
    assert "numba" not in modules


def test_compiled_contact_impact_run_does_not_import_scipy_integrate(paper_config_path, tmp_path):
    # the compiled integrator carries RK45's tables itself: scipy.integrate costs ~0.5 s
    args = ["--set", "dynamics.model=contact-impact", "--set", "dynamics.integrator=RK45-compiled"]
    modules = loaded_after(cli(["run", str(paper_config_path), *args, *ONE_REVOLUTION]), tmp_path)
    assert "numba" in modules
    assert "scipy.integrate" not in modules


def test_writing_a_result_imports_no_dataset_plotting_or_compiler_library(
    paper_config_path, tmp_path
):
    # one joint's result.nc is written from its plain arrays with h5netcdf (xarray's
    # writer and Dataset would import xarray, pandas and, where dask is installed,
    # dask.array and distributed); the files are those of xarray's writer
    out = tmp_path / "out"
    modules = loaded_after(
        cli(["run", str(paper_config_path), *ONE_REVOLUTION, "--out", str(out), "--no-plots"]),
        tmp_path,
    )
    assert (out / "result.nc").is_file()
    assert "h5netcdf" in modules
    assert not heavy(modules)
    assert "numba" not in modules


def test_a_sweep_case_builds_no_dataset(paper_config_path, tmp_path):
    config = load_config(paper_config_path, {"simulation.revolutions": 3})
    code = (
        "from jointwear.workflows.sweep import run_case\n"
        f"record = run_case({{'case': 'case-0000', 'config': {config.to_toml()!r}, "
        "'checkpoint': None})\n"
        "assert record['status'] == 'ok', record\n"
    )
    modules = loaded_after(code, tmp_path)
    assert not heavy(modules)


def test_units_then_dask_arrays_with_units_still_work(tmp_path):
    # the package's unit registry keeps pint's support of dask arrays
    code = (
        "import jointwear.units as units\n"
        "import dask.array as da\n"
        "q = units.ureg.Quantity(da.arange(4.0, chunks=2), 'mm')\n"
        "assert list(q.to('m').compute().magnitude) == [0.0, 0.001, 0.002, 0.003]\n"
        "assert type(q.persist().magnitude).__name__ == 'Array'\n"
        "import dask\n"
        "assert dask.is_dask_collection(q)\n"
    )
    assert "dask.array" in loaded_after(code, tmp_path)


def test_dask_arrays_in_xarray_after_writing_a_result(paper_config_path, tmp_path):
    # a result of NumPy arrays written first, then one of dask arrays
    code = (
        "from jointwear import Simulation, load_config\n"
        "from jointwear.results import read_result, write_netcdf\n"
        f"result = Simulation(load_config({str(paper_config_path)!r}, "
        "{'simulation.revolutions': 1})).run()\n"
        f"write_netcdf(result.dataset, {str(tmp_path / 'a.nc')!r})\n"
        "chunked = result.dataset.chunk({'theta': 30})\n"
        "assert type(chunked['wear_depth'].data).__module__.startswith('dask.array')\n"
        f"write_netcdf(chunked, {str(tmp_path / 'b.nc')!r})\n"
        f"back = read_result({str(tmp_path / 'b.nc')!r})\n"
        "assert (back['wear_depth'].values == result.dataset['wear_depth'].values).all()\n"
    )
    assert "dask.array" in loaded_after(code, tmp_path)


@pytest.mark.parametrize(
    ("overrides", "compiled"),
    [
        ({"simulation.revolutions": 1, "simulation.update_every": "adaptive"}, False),
        ({"simulation.revolutions": COMPILED_KERNEL_SOLVES}, False),
        ({"simulation.revolutions": COMPILED_KERNEL_SOLVES + 1}, None),
        ({"simulation.revolutions": 15000, "simulation.update_every": "adaptive"}, None),
        ({"simulation.revolutions": 15000, "simulation.update_every": 100}, False),
        ({"simulation.revolutions": 15000, "simulation.update_every": 10}, None),
        ({"simulation.revolutions": 15000, "simulation.update_contour": False}, False),
    ],
)
def test_kernel_choice_follows_from_the_config_alone(paper_config_path, overrides, compiled):
    settings = {"simulation.update_contour": True, "simulation.update_every": 1, **overrides}
    assert compiled_kernel(load_config(paper_config_path, settings)) is compiled
    # read again (as a resumed run reads its checkpointed config): the same choice
    assert compiled_kernel(load_config(paper_config_path, settings)) is compiled
