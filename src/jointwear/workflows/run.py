"""A run to a folder: the checkpointed simulation, its files, its plots and its summary.

:func:`run_to_folder` is ``jointwear run`` without the printing: it starts a run from
a config file (or continues a checkpointed one from its folder), saves the state
every ``simulation.checkpoint_every`` revolutions, stops at a wall-clock limit, and
writes ``result.nc``, ``metrics.csv``, ``config.toml``, ``summary.json`` and the
plots into the folder, all at once when the run has ended. :func:`redraw_plots`
draws the figures of a saved result again.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointwear.errors import ConfigError, DataError

if TYPE_CHECKING:
    from jointwear.checkpoint import Checkpointer
    from jointwear.config import Config
    from jointwear.results import WearResult
    from jointwear.state import SimulationState

__all__ = [
    "OUT_FILES",
    "RUN_FILES",
    "FolderRun",
    "add_checks",
    "plot_joints",
    "redraw_plots",
    "run_to_folder",
    "write_outputs",
]

#: what ``jointwear run --out`` writes (files, then the plots folder)
RUN_FILES = ("result.nc", "metrics.csv", "config.toml", "summary.json")
#: entries of a run's --out directory a run may replace (checkpoints included)
OUT_FILES = (*RUN_FILES, "checkpoint.toml", "checkpoint.npz")


@dataclass(frozen=True)
class FolderRun:
    """Outcome of :func:`run_to_folder`.

    Attributes
    ----------
    result : WearResult
        The finished run.
    summary : dict
        Its summary with the engineering checks: the object ``run --json`` prints and
        ``summary.json`` holds.
    out : Path or None
        The folder the files were written into (``None``: none asked for).
    name : str
        What the run is called: the config file's name, or the resumed folder's.
    """

    result: WearResult
    summary: dict[str, Any]
    out: Path | None
    name: str


def run_to_folder(
    config: Path | None = None,
    out: Path | None = None,
    *,
    overrides: Sequence[str] = (),
    checkpoint_every: int | None = None,
    resume: Path | None = None,
    plots: bool = True,
    max_memory: str | None = None,
    time_limit: float | None = None,
    progress: Callable[[float, float], None] | None = None,
    on_end: Callable[[dict[str, Any]], None] | None = None,
) -> FolderRun:
    """Run a config (or continue a checkpointed run) and write its files into a folder.

    Everything is checked before anything is computed: the options, the folder, the
    config and the run's memory. A run that fails leaves no checkpoint (nor an empty
    folder it created) behind; a run stopped by the time limit or an interrupt keeps
    its last checkpoint, to be continued with ``resume``.

    Parameters
    ----------
    config : Path, optional
        The config file (TOML); omitted with ``resume``.
    out : Path, optional
        Folder for ``result.nc``, ``metrics.csv``, ``config.toml``, ``summary.json``,
        ``plots/`` and the checkpoints; ``None`` writes nothing.
    overrides : sequence of str
        ``section.key=VALUE`` overrides of the config (``--set``).
    checkpoint_every : int, optional
        Save the state into ``out`` every this many revolutions [-] (0: never); sets
        ``simulation.checkpoint_every``.
    resume : Path, optional
        A folder holding the checkpoint of an unfinished run: the run continues there
        with its own config.
    plots : bool
        Draw the figures into ``out/plots``.
    max_memory : str, optional
        Refuse a run whose arrays would need more memory than this, e.g. ``"16 GiB"``.
    time_limit : float, optional
        Stop with :class:`~jointwear.errors.TimeLimitError` after this wall-clock
        time [s], checked between revolutions.
    progress : callable, optional
        ``progress(revolutions_done, revolutions_total)`` [-].
    on_end : callable, optional
        ``on_end(summary)`` when the simulation has ended, before the files are written.

    Returns
    -------
    FolderRun
        The result, its summary with the checks, the folder and the run's name.

    Raises
    ------
    ConfigError
        Conflicting options, a bad config or folder, a run too large for the memory.
    TimeLimitError
        The time limit passed (a checkpoint stays for ``resume``).
    """
    from jointwear.resources import Deadline, check_run
    from jointwear.simulation import Simulation

    if resume is not None:
        cfg, state, checkpointer, out = resumed_run(
            config, out, resume, overrides, checkpoint_every
        )
        name = out.name
    else:
        if config is None:
            raise ConfigError("CONFIG: missing; give a config file or --resume DIR")
        state = None
        cfg, checkpointer, out = started_run(config, out, overrides, checkpoint_every)
        name = config.name
    check_run(cfg, max_memory)
    resume_command = f"jointwear run --resume {out}" if checkpointer is not None else None
    deadline = Deadline(time_limit, "revolutions", resume_command)
    simulation = Simulation(cfg)
    created = out is not None and not out.exists()
    if checkpointer is not None and state is None and resume is None:
        checkpointer.begin()
    watched = deadline.watching(progress or _no_progress)
    with _cleaned_up_on_failure(checkpointer, out, created):
        result = simulation.run(progress=watched, state=state, on_step=checkpointer)
        summary = result.summary()
        if on_end is not None:
            on_end(summary)
    # one summary, made once: the object `--json` prints is the one summary.json holds
    add_checks(summary, result)
    if out is not None:
        write_outputs(result, out, summary, plots=plots)
    if checkpointer is not None:
        checkpointer.clear()
    return FolderRun(result, summary, out, name)


def resumed_run(
    config: Path | None,
    out: Path | None,
    resume: Path,
    overrides: Sequence[str],
    checkpoint_every: int | None,
) -> tuple[Config, SimulationState | None, Checkpointer, Path]:
    """The config, state and checkpointer of a run continued from its folder.

    Parameters
    ----------
    config : Path or None
        Must be ``None``: a resumed run keeps its own config.
    out : Path or None
        ``None`` or ``resume`` itself.
    resume : Path
        The folder of the unfinished run.
    overrides : sequence of str
        Must be empty.
    checkpoint_every : int or None
        Must be ``None``: the run keeps its checkpoint interval [-].

    Returns
    -------
    tuple
        ``(config, state, checkpointer, folder)``.
    """
    from jointwear.checkpoint import load_checkpoint
    from jointwear.io import check_out

    if config is not None:
        raise ConfigError(f"--resume: give either CONFIG ({config}) or --resume DIR, not both")
    if overrides:
        raise ConfigError(
            "--set: a resumed run keeps its configuration (from --resume DIR/checkpoint.toml)"
        )
    if checkpoint_every is not None:
        raise ConfigError("--checkpoint-every: a resumed run keeps its checkpoint interval")
    if out is not None and out.resolve() != resume.resolve():
        raise ConfigError("--out: a resumed run writes its results into the --resume directory")
    out = check_out(resume, "--resume", files=OUT_FILES, dirs=("plots",))
    cfg, state, checkpointer = load_checkpoint(out)
    return cfg, state, checkpointer, out


def started_run(
    config: Path,
    out: Path | None,
    overrides: Sequence[str],
    checkpoint_every: int | None,
) -> tuple[Config, Checkpointer | None, Path | None]:
    """The config and checkpointer of a new run, its folder checked before it is read.

    Parameters
    ----------
    config : Path
        The config file.
    out : Path or None
        The run's folder, if any.
    overrides : sequence of str
        ``section.key=VALUE`` overrides.
    checkpoint_every : int or None
        Revolutions between checkpoints [-] (needs ``out``).

    Returns
    -------
    tuple
        ``(config, checkpointer or None, folder or None)``.
    """
    from jointwear.checkpoint import Checkpointer, has_checkpoint
    from jointwear.io import check_out
    from jointwear.workflows.inputs import load_config_file

    overrides = list(overrides)
    if checkpoint_every is not None:
        if checkpoint_every < 0:
            raise ConfigError(f"--checkpoint-every: must be >= 0, got {checkpoint_every}")
        if checkpoint_every > 0 and out is None:
            raise ConfigError("--checkpoint-every: needs --out DIR (checkpoints go there)")
        overrides.append(f"simulation.checkpoint_every={checkpoint_every}")
    if out is not None:  # before anything is computed
        out = check_out(out, files=OUT_FILES, dirs=("plots",))
    cfg = load_config_file(config, overrides)
    if out is not None and has_checkpoint(out):
        raise ConfigError(
            f"--out: {out} holds the checkpoint of an unfinished run; continue it with "
            f"`jointwear run --resume {out}` or delete {out}/checkpoint.*"
        )
    every = cfg.simulation.checkpoint_every
    checkpointer = Checkpointer(out, cfg) if out is not None and every > 0 else None
    return cfg, checkpointer, out


def _no_progress(done: float, total: float) -> None:
    """No progress report."""


@contextlib.contextmanager
def _cleaned_up_on_failure(checkpointer: Checkpointer | None, out: Path | None, created: bool):
    """Leave no checkpoint (or folder this run created) behind a run that cannot finish.

    A time limit keeps the checkpoint for ``--resume``; so does a checkpoint that could
    not be written (a full disk: the previous one stays). An interrupt of a run with a
    checkpoint names the command that continues it.
    """
    from jointwear.checkpoint import CheckpointWriteError
    from jointwear.errors import JointwearError, TimeLimitError
    from jointwear.interrupts import with_resume

    try:
        yield
    except TimeLimitError:
        raise  # a checkpoint stays for --resume
    except JointwearError as exc:
        if checkpointer is not None and not isinstance(exc, CheckpointWriteError):
            checkpointer.clear()
            if created:
                with contextlib.suppress(OSError):
                    out.rmdir()
        raise
    except KeyboardInterrupt as exc:
        if checkpointer is None or not checkpointer.config_path.exists():
            raise
        raise with_resume(exc, f"jointwear run --resume {out}") from None


def add_checks(summary: dict[str, Any], result: WearResult) -> None:
    """Add the engineering checks (PV, pressure, speed vs the bushing's limits) to a summary;
    each exceeded limit warns once.

    Parameters
    ----------
    summary : dict
        The run's summary (``result.summary()``), changed in place: ``checks``, and per
        joint of several ``joints[...]["checks"]``.
    result : WearResult
        The run.
    """
    from jointwear.tribology.metrics import engineering_checks

    summary["checks"] = engineering_checks(result.joint_data(), result.config)
    for joint, entry in summary.get("joints", {}).items():
        entry["checks"] = engineering_checks(result.joint_data(joint), result.config)


def write_outputs(
    result: WearResult, out: Path, summary: dict[str, Any], plots: bool = True
) -> None:
    """Write a run's files into ``out``: all or nothing (staged, then published at once).

    Parameters
    ----------
    result : WearResult
        The run.
    out : Path
        The folder.
    summary : dict
        The run's summary with its checks (:func:`add_checks`), written as
        ``summary.json`` as it is: the object ``run --json`` prints.
    plots : bool
        Draw the figures into ``out/plots``.
    """
    from jointwear.io import staged_output, write_json
    from jointwear.results import write_metrics_csv

    # the result file already holds the config as TOML text: written, not made again
    config_text = result.data.attrs.get("config")
    if not isinstance(config_text, str):
        config_text = result.config.to_toml()
    with staged_output(out, files=RUN_FILES, dirs=("plots",)) as staging:
        result.to_netcdf(staging / "result.nc")
        write_metrics_csv(result.data, staging / "metrics.csv")
        (staging / "config.toml").write_text(
            "# fully resolved configuration, SI units\n" + config_text, encoding="utf-8"
        )
        write_json(staging / "summary.json", summary)
        if plots:
            plot_joints(result.dataset, staging / "plots")


def plot_joints(dataset: Any, directory: Path, **options: Any) -> list[Path]:
    """Figures of a result; with several clearance joints, a folder per joint.

    A result with slices along the pin (a dimension ``z``) also gets its wear maps
    (:func:`~jointwear.plots_axial.plot_axial_result`).

    Parameters
    ----------
    dataset : xarray.Dataset
        A run's result.
    directory : Path
        Where the figures go.
    **options
        Passed to :func:`~jointwear.plots.plot_result` (``magnification``).

    Returns
    -------
    list of Path
        The files written.
    """
    from jointwear.plots import plot_result
    from jointwear.plots_axial import plot_axial_result
    from jointwear.results import joint_datasets

    # slices along the pin: the deepest slice's planar figures and the wear maps
    draw = plot_axial_result if "z" in dataset.dims else plot_result
    joints = joint_datasets(dataset)
    if len(joints) == 1:
        return draw(dataset, directory, **options)
    return [
        path
        for joint, single in joints.items()
        for path in draw(single, directory / joint, **options)
    ]


def redraw_plots(
    result: Path, out: Path | None = None, magnification: float | str = "auto"
) -> tuple[Path, int]:
    """Draw the figures of a saved result again (``jointwear plot``), all or nothing.

    Parameters
    ----------
    result : Path
        A ``result.nc`` written by :func:`run_to_folder`.
    out : Path, optional
        Folder for the figures; default ``plots/`` next to the result.
    magnification : float or "auto"
        Magnification of the wear in the polar plot [-].

    Returns
    -------
    folder : Path
        Where the figures are.
    count : int
        How many files were written.
    """
    from jointwear.io import check_out, staged_output
    from jointwear.plots import FIGURE_VARIABLES
    from jointwear.results import read_result

    target = check_out(out if out is not None else result.parent / "plots")
    dataset = read_result(result)
    for figure, names in FIGURE_VARIABLES.items():
        for name in names:
            if name not in dataset.variables:
                raise DataError(
                    f"{result}: no variable {name!r} (the {figure} figure draws it); "
                    "not a complete jointwear result"
                )
    with staged_output(target) as staging:
        count = len(plot_joints(dataset, staging, magnification=magnification))
    return target, count
