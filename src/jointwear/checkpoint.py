"""Checkpoints: the revolution loop's state on disk, so a killed run can continue.

A checkpoint directory holds two files, both written atomically (temporary
file + rename, :mod:`jointwear.io`):

``checkpoint.toml``
    The fully resolved configuration of the run (written once, at the start).
``checkpoint.npz``
    The :class:`~jointwear.simulation.SimulationState` after the latest
    checkpointed contour update: revolution, radii, wear rate, update interval,
    the per-update history, the saved profiles and the contact warm start.
    It also stores a digest of the configuration, so a state is never resumed
    under a different configuration.

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
import zipfile
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from jointwear.config import Config, config_from_dict, read_toml
from jointwear.errors import ConfigError, DataError
from jointwear.io import atomic_write

if TYPE_CHECKING:
    from jointwear.simulation import SimulationState

__all__ = [
    "CHECKPOINT_CONFIG",
    "CHECKPOINT_STATE",
    "Checkpointer",
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
#: version of the state layout
FORMAT = 2


def config_digest(config: Config) -> str:
    """SHA-256 of the resolved configuration (TOML text)."""
    return hashlib.sha256(config.to_toml().encode("utf-8")).hexdigest()


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
            arrays[f"f_{name}__keys"] = np.asarray([r for r, _ in rows], dtype=np.int64)
            for i, (_, profile) in enumerate(rows):
                arrays[f"f_{name}__{i}"] = np.asarray(profile)
        else:  # a state field this module does not know how to store: a bug
            raise TypeError(f"cannot checkpoint SimulationState.{name} ({type(value).__name__})")
    arrays["schema"] = np.array(json.dumps(schema))
    return arrays


def _state_from_arrays(arrays: dict[str, np.ndarray]) -> SimulationState:
    from jointwear.simulation import SimulationState
    from jointwear.state import Log

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
                (int(key), arrays[f"f_{name}__{i}"].copy())
                for i, key in enumerate(arrays[f"f_{name}__keys"])
            )
        else:
            raise ValueError(f"unknown field kind {kind!r}")
    return SimulationState(**values)


def write_state(path: str | Path, state: SimulationState, digest: str) -> None:
    """Write ``state`` to ``path`` (``.npz``) atomically."""
    with atomic_write(path, "wb") as handle:
        np.savez(handle, **_state_arrays(state, digest))


def read_state(path: str | Path) -> tuple[SimulationState, str]:
    """Read a state written by :func:`write_state`; returns ``(state, config_digest)``.

    Raises
    ------
    DataError
        If the file is missing, truncated or not a jointwear checkpoint.
    """
    path = Path(path)
    try:
        with np.load(path, allow_pickle=False) as data:
            arrays = {name: data[name] for name in data.files}
    except FileNotFoundError:
        raise DataError(f"{path}: file not found") from None
    except (OSError, ValueError, EOFError, zipfile.BadZipFile) as exc:
        raise DataError(f"{path}: not a readable checkpoint ({type(exc).__name__})") from None
    if int(arrays.get("format", -1)) != FORMAT:
        raise DataError(f"{path}: not a jointwear checkpoint (format {FORMAT} expected)")
    try:
        return _state_from_arrays(arrays), str(arrays["config_digest"])
    except (KeyError, IndexError, ValueError, TypeError) as exc:
        raise DataError(f"{path}: unusable checkpoint ({exc})") from None


# ---------------------------------------------------------------- the run's side


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
        self.directory.mkdir(parents=True, exist_ok=True)
        with contextlib.suppress(FileNotFoundError):
            self.state_path.unlink()
        with atomic_write(self.config_path, encoding="utf-8") as handle:
            handle.write(
                "# checkpointed run: fully resolved configuration, SI units\n"
                + self.config.to_toml()
            )

    def load(self) -> SimulationState | None:
        """The saved state, or ``None`` if there is none for this configuration."""
        if not self.state_path.exists():
            return None
        state, digest = read_state(self.state_path)
        if digest != self.digest:
            return None
        self.continue_from(state)
        return state

    def continue_from(self, state: SimulationState) -> None:
        """Next checkpoint after ``state`` (a resumed run)."""
        self._next = (state.revolution // self.every + 1) * self.every

    def __call__(self, state: SimulationState) -> None:
        if state.revolution >= self._next:
            write_state(self.state_path, state, self.digest)
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
    checkpointer.continue_from(state)
    return config, state, checkpointer
