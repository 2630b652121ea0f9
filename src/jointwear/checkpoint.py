"""Checkpoints: the revolution loop's state on disk, so a killed run can continue.

A checkpoint directory holds two files, both written atomically (temporary
file + rename, :mod:`jointwear.io`):

``checkpoint.toml``
    The fully resolved configuration of the run (written once, at the start).
``checkpoint.npz``
    The :class:`~jointwear.state.SimulationState` after the latest
    checkpointed contour update: revolution, radii, wear rate, update interval,
    the per-update history, the saved profiles and the contact warm start.
    It also stores a digest of the configuration, so a state is never resumed
    under a different configuration, and a SHA-256 checksum of its own arrays,
    so a damaged or edited state is refused (and left in place) instead of
    resumed; on resuming the state is also checked against the configuration
    (node count, revolutions, finite values, increasing records).

Because the state holds everything the loop carries, a resumed run computes
exactly the numbers an uninterrupted run computes (bit for bit).

Examples
--------
>>> from jointwear import Simulation, load_config
>>> from jointwear.checkpoint import Checkpointer
>>> config = load_config(overrides={"simulation.update_contour": True,
...                                 "simulation.revolutions": 4,
...                                 "contact.nodes": 60,
...                                 "simulation.steps_per_revolution": 60})
>>> import tempfile
>>> folder = tempfile.mkdtemp()
>>> saver = Checkpointer(folder, config, every=2)
>>> saver.begin()
>>> result = Simulation(config).run(on_step=saver)
>>> saver.load().revolution
4
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import json
import shutil
import zipfile
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from jointwear.config import Config, config_from_dict, read_toml
from jointwear.errors import ConfigError, DataError
from jointwear.io import atomic_write, check_input, os_reason

if TYPE_CHECKING:
    from jointwear.state import SimulationState

__all__ = [
    "CHECKPOINT_CONFIG",
    "CHECKPOINT_STATE",
    "CheckpointWriteError",
    "Checkpointer",
    "check_state",
    "config_digest",
    "has_checkpoint",
    "load_checkpoint",
    "read_checkpoint_config",
    "read_state",
    "write_state",
]

#: state file inside a checkpoint directory
CHECKPOINT_STATE = "checkpoint.npz"
#: resolved configuration inside a checkpoint directory
CHECKPOINT_CONFIG = "checkpoint.toml"
#: version of the state layout (3: with a checksum of its arrays)
FORMAT = 3
#: array fields of a state that hold one value per contour node
_NODE_ARRAYS = ("wear_depth", "wear_rate", "load_depth", "pin_wear_depth", "pin_wear_rate")


def config_digest(config: Config) -> str:
    """SHA-256 of the resolved configuration's values (canonical JSON of ``to_dict``).

    The values, not a written text: a change of how configs are written (layout,
    quoting) must not orphan the checkpoints of an unchanged configuration.
    """
    canonical = json.dumps(config.to_dict(), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


def has_checkpoint(directory: str | Path) -> bool:
    """Whether ``directory`` holds a checkpoint (state or configuration)."""
    directory = Path(directory)
    return (directory / CHECKPOINT_STATE).exists() or (directory / CHECKPOINT_CONFIG).exists()


# ---------------------------------------------------------------- state <-> arrays


def _state_arrays(state: SimulationState, digest: str) -> dict[str, np.ndarray]:
    """Flatten a state into named arrays, generically over its dataclass fields.

    Field values are ``None``, booleans, integers, floats, strings, arrays or
    :class:`~jointwear.state.Log` objects of mapping rows (the per-update and dynamics
    records) or of ``(revolution, array)`` rows (the saved profiles).
    """
    from jointwear.state import Log

    arrays: dict[str, np.ndarray] = {
        "format": np.array(FORMAT, dtype=np.int64),
        "config_digest": np.array(digest),
    }
    schema: dict[str, str] = {}
    for spec in dataclasses.fields(state):
        name, value = spec.name, getattr(state, spec.name)
        if value is None:
            schema[name] = "none"
        elif isinstance(value, bool | np.bool_):
            schema[name] = "bool"
            arrays[f"f_{name}"] = np.array(bool(value))
        elif isinstance(value, int | np.integer):
            schema[name] = "int"
            arrays[f"f_{name}"] = np.array(int(value), dtype=np.int64)
        elif isinstance(value, float | np.floating):
            schema[name] = "float"
            arrays[f"f_{name}"] = np.array(float(value), dtype=np.float64)
        elif isinstance(value, str):
            schema[name] = "str"
            arrays[f"f_{name}"] = np.array(value)
        elif isinstance(value, np.ndarray):
            schema[name] = "array"
            arrays[f"f_{name}"] = value
        elif isinstance(value, Log) and (not len(value) or isinstance(value.last, dict)):
            schema[name] = "rows"
            columns = value.columns()
            arrays[f"f_{name}__keys"] = np.array(list(columns), dtype=str)
            for key, values in columns.items():
                integral = all(isinstance(v, int | np.integer) for v in values)
                dtype = np.int64 if integral and values else np.float64
                arrays[f"f_{name}__{key}"] = np.asarray(values, dtype=dtype)
        elif isinstance(value, Log):
            schema[name] = "profiles"
            rows = value.items()
            # (whole revolutions, but the fractional one where a limit ended the run)
            keys = [r for r, _ in rows]
            whole = all(isinstance(r, int | np.integer) for r in keys)
            arrays[f"f_{name}__keys"] = np.asarray(keys, dtype=np.int64 if whole else np.float64)
            for i, (_, profile) in enumerate(rows):
                arrays[f"f_{name}__{i}"] = np.asarray(profile)
        else:  # a state field this module does not know how to store: a bug
            raise TypeError(f"cannot checkpoint SimulationState.{name} ({type(value).__name__})")
    arrays["schema"] = np.array(json.dumps(schema))
    return arrays


def _state_from_arrays(arrays: dict[str, np.ndarray]) -> SimulationState:
    from jointwear.state import Log, SimulationState, revolution_number

    schema: dict[str, str] = json.loads(str(arrays["schema"]))
    expected = [spec.name for spec in dataclasses.fields(SimulationState)]
    if sorted(schema) != sorted(expected):
        raise ValueError("its state fields differ from this jointwear version's")
    values: dict[str, object] = {}
    for name, kind in schema.items():
        if kind == "none":
            values[name] = None
        elif kind == "bool":
            values[name] = bool(arrays[f"f_{name}"])
        elif kind == "int":
            values[name] = int(arrays[f"f_{name}"])
        elif kind == "float":
            values[name] = float(arrays[f"f_{name}"])
        elif kind == "str":
            values[name] = str(arrays[f"f_{name}"])
        elif kind == "array":
            values[name] = arrays[f"f_{name}"].copy()
        elif kind == "rows":
            keys = [str(key) for key in arrays[f"f_{name}__keys"]]
            columns = [arrays[f"f_{name}__{key}"].tolist() for key in keys]
            values[name] = Log.of(
                dict(zip(keys, row, strict=True)) for row in zip(*columns, strict=True)
            )
        elif kind == "profiles":
            values[name] = Log.of(
                (revolution_number(key), arrays[f"f_{name}__{i}"].copy())
                for i, key in enumerate(arrays[f"f_{name}__keys"])
            )
        else:
            raise ValueError(f"unknown field kind {kind!r}")
    return SimulationState(**values)


def _checksum(arrays: dict[str, np.ndarray]) -> str:
    """SHA-256 over every array's name, dtype, shape and bytes (the checksum excluded)."""
    digest = hashlib.sha256()
    for name in sorted(arrays):
        if name == "checksum":
            continue
        value = np.ascontiguousarray(arrays[name])
        digest.update(f"{name}\0{value.dtype.str}\0{value.shape}\0".encode())
        digest.update(value.tobytes())
    return digest.hexdigest()


def write_state(path: str | Path, state: SimulationState, digest: str) -> None:
    """Write ``state`` to ``path`` (``.npz``) atomically, with a checksum of its arrays."""
    arrays = _state_arrays(state, digest)
    arrays["checksum"] = np.array(_checksum(arrays))
    with atomic_write(path, "wb") as handle:
        np.savez(handle, **arrays)


def read_state(path: str | Path) -> tuple[SimulationState, str]:
    """Read a state written by :func:`write_state`; returns ``(state, config_digest)``.

    Raises
    ------
    DataError
        If the file is missing, truncated or not a jointwear checkpoint.
    """
    path = Path(path)
    check_input(path, "checkpoint", max_bytes=None)  # a FIFO or folder is never opened
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {name: data[name] for name in data.files}
    except FileNotFoundError:
        raise DataError(f"{path}: file not found") from None
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as exc:
        raise DataError(f"{path}: not a readable checkpoint ({type(exc).__name__})") from None
    try:
        version = int(arrays.get("format", -1))
    except (TypeError, ValueError):
        version = -1
    if version < 1:
        raise DataError(f"{path}: not a jointwear checkpoint (format {FORMAT} expected)")
    if version != FORMAT:
        raise DataError(
            f"{path}: written in checkpoint format {version}, this jointwear reads format "
            f"{FORMAT}; start the run again without --resume"
        )
    if "checksum" not in arrays or str(arrays["checksum"]) != _checksum(arrays):
        raise DataError(
            f"{path}: damaged checkpoint (its checksum does not match its contents); "
            "start the run again without --resume"
        )
    try:
        return _state_from_arrays(arrays), str(arrays["config_digest"])
    except (KeyError, IndexError, ValueError, TypeError) as exc:
        raise DataError(f"{path}: unusable checkpoint ({exc})") from None


def check_state(state: SimulationState, config: Config, path: str | Path) -> None:
    """Refuse a state that cannot belong to ``config`` (one-line error naming ``path``).

    Checks the node count of every per-node array, the revolution against the
    configured revolutions, that every array of the state is finite, and that the records
    (updates, saved profiles, dynamics solves) run forward in revolutions and
    end at or before the state's revolution.

    Parameters
    ----------
    state : SimulationState
        The state read from ``path``.
    config : Config
        The run's configuration.
    path : path-like
        The state file (for messages).
    """

    def bad(reason: str) -> DataError:
        return DataError(f"{path}: inconsistent checkpoint ({reason})")

    nodes = config.contact.nodes
    # (a run along the pin keeps a map: a row of nodes per slice)
    shape = (nodes,) if config.joint.axial_slices == 1 else (config.joint.axial_slices, nodes)
    if not 0 <= state.revolution <= config.simulation.revolutions:
        raise bad(f"revolution {state.revolution} outside 0..{config.simulation.revolutions}")
    for name in _NODE_ARRAYS:
        value = getattr(state, name)
        if value is not None and np.shape(value) != shape:
            raise bad(f"{name} has shape {np.shape(value)}, the config has {nodes} nodes")
    for spec in dataclasses.fields(state):
        value = getattr(state, spec.name)
        if isinstance(value, np.ndarray) and value.dtype.kind in "fc":
            if not np.all(np.isfinite(value)):
                raise bad(f"{spec.name} holds non-finite values")
        elif isinstance(value, float) and not np.isfinite(value):
            raise bad(f"{spec.name} is not finite")
    if state.interval < 1 or (state.next_interval is not None and state.next_interval < 1):
        raise bad("update interval below 1")
    if state.updates_since_dynamics < 0:
        raise bad("negative count of updates since the dynamics")
    for name in ("history", "dynamics_updates"):
        columns = getattr(state, name).columns()
        revolutions = np.asarray(columns.get("revolution", []), dtype=float)
        if revolutions.size and (
            not np.all(np.isfinite(revolutions))
            or np.any(np.diff(revolutions) < 0)
            or revolutions[-1] > state.revolution
        ):
            raise bad(f"{name} revolutions do not run forward to {state.revolution}")
    saved = [revolution for revolution, _ in state.profiles.items()]
    if saved and (np.any(np.diff(saved) <= 0) or saved[-1] > state.revolution):
        raise bad(f"saved profiles do not run forward to {state.revolution}")
    for revolution, profile in state.profiles.items():
        if np.shape(profile) != shape or not np.all(np.isfinite(profile)):
            raise bad(f"the profile of revolution {revolution} is not {nodes} finite values")


# ---------------------------------------------------------------- the run's side


class CheckpointWriteError(DataError):
    """A checkpoint could not be written (full disk ...); the previous one is intact."""


def _written(path: Path, write) -> None:
    try:
        write()
    except OSError as exc:
        raise CheckpointWriteError(
            f"{path}: cannot write the checkpoint ({os_reason(exc)}); the previous "
            f"checkpoint is kept: make room, then `jointwear run --resume {path.parent}`"
        ) from None


class Checkpointer:
    """Save the simulation state into ``directory`` every ``every`` revolutions.

    Use as the ``on_step`` callback of :meth:`jointwear.Simulation.run`.

    Parameters
    ----------
    directory : path-like
        Checkpoint directory (created by :meth:`begin`).
    config : Config
        The run's resolved configuration.
    every : int, optional
        Revolutions between checkpoints; default ``simulation.checkpoint_every``.
        With an adaptive update interval a checkpoint is written at the first
        update at or past each multiple of ``every``.
    """

    def __init__(self, directory: str | Path, config: Config, every: int | None = None) -> None:
        self.directory = Path(directory)
        self.config = config
        self.every = int(config.simulation.checkpoint_every if every is None else every)
        if self.every < 1:
            raise ConfigError(f"simulation.checkpoint_every: must be >= 1, got {self.every}")
        self.digest = config_digest(config)
        self._next = self.every

    @property
    def state_path(self) -> Path:
        return self.directory / CHECKPOINT_STATE

    @property
    def config_path(self) -> Path:
        return self.directory / CHECKPOINT_CONFIG

    def begin(self) -> None:
        """Write the configuration (start of a fresh run)."""
        text = "# checkpointed run: fully resolved configuration, SI units\n"
        text += self.config.to_toml()

        def write() -> None:
            self.directory.mkdir(parents=True, exist_ok=True)
            with contextlib.suppress(FileNotFoundError):
                self.state_path.unlink()
            with atomic_write(self.config_path, encoding="utf-8") as handle:
                handle.write(text)

        created = not self.directory.exists()
        try:
            write()
        except OSError as exc:
            if created:
                with contextlib.suppress(OSError):
                    shutil.rmtree(self.directory)
            raise DataError(f"--out: {self.directory}: {os_reason(exc)}") from None

    def load(self) -> SimulationState | None:
        """The saved state, or ``None`` if there is none for this configuration."""
        if not self.state_path.exists():
            return None
        state, digest = read_state(self.state_path)
        if digest != self.digest:
            return None
        check_state(state, self.config, self.state_path)
        self.continue_from(state)
        return state

    def continue_from(self, state: SimulationState) -> None:
        """Next checkpoint after ``state`` (a resumed run)."""
        self._next = (state.revolution // self.every + 1) * self.every

    def __call__(self, state: SimulationState) -> None:
        if state.revolution >= self._next:
            _written(self.state_path, lambda: write_state(self.state_path, state, self.digest))
            self.continue_from(state)

    def clear(self) -> None:
        """Remove the checkpoint files (the run finished or cannot be continued)."""
        for path in (self.state_path, self.config_path):
            with contextlib.suppress(FileNotFoundError):
                path.unlink()


def read_checkpoint_config(directory: str | Path) -> Config:
    """The configuration stored in a checkpoint directory."""
    path = Path(directory) / CHECKPOINT_CONFIG
    if not path.exists():
        raise DataError(
            f"{directory}: no checkpoint to resume (no {CHECKPOINT_CONFIG}; the run finished "
            "or was started without --checkpoint-every)"
        )
    data = read_toml(path, DataError)
    try:
        return config_from_dict(data, defaults=False)
    except ConfigError as exc:
        raise DataError(f"{path}: {exc}") from None


def load_checkpoint(directory: str | Path) -> tuple[Config, SimulationState | None, Checkpointer]:
    """Configuration, saved state (``None`` if none was written yet) and a checkpointer.

    Raises
    ------
    DataError
        If ``directory`` holds no checkpoint, or the state does not belong to
        the stored configuration.
    """
    directory = Path(directory)
    if not directory.is_dir():
        raise DataError(f"{directory}: no such directory to resume")
    config = read_checkpoint_config(directory)
    every = config.simulation.checkpoint_every
    checkpointer = Checkpointer(directory, config, every if every > 0 else 1)
    if not checkpointer.state_path.exists():
        return config, None, checkpointer
    state, digest = read_state(checkpointer.state_path)
    if digest != checkpointer.digest:
        raise DataError(
            f"{checkpointer.state_path}: belongs to a different configuration than "
            f"{checkpointer.config_path}"
        )
    check_state(state, config, checkpointer.state_path)
    checkpointer.continue_from(state)
    return config, state, checkpointer
