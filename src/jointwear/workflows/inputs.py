"""What a workflow reads before it runs: a config file with its overrides."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from jointwear.errors import ConfigError

if TYPE_CHECKING:
    from jointwear.config import Config

__all__ = ["load_config_file"]


def load_config_file(path: Path, overrides: Iterable[str] | None = None) -> Config:
    """Read a config file and apply ``--set`` overrides (errors name the file or key).

    Parameters
    ----------
    path : Path
        The TOML config file.
    overrides : iterable of str, optional
        ``section.key=VALUE`` strings (units allowed).

    Returns
    -------
    Config
        The validated configuration.

    Raises
    ------
    ConfigError
        The file does not exist, is not a valid config, or an override is not valid.
    """
    from jointwear.config import load_config

    if not path.exists():
        raise ConfigError(f"{path}: file not found")
    return load_config(path, list(overrides or []))
