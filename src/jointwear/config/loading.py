"""A validated :class:`Config` from data, a file and overrides.

:func:`config_from_dict` merges the named parameter set underneath the data and
validates it; :func:`load_config` reads a TOML file and applies ``--set`` overrides
first. Every problem is one :class:`~jointwear.errors.ConfigError`.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from jointwear.config.lookup import check_bare_numbers
from jointwear.config.mechanisms import MECHANISM_TYPES
from jointwear.config.messages import error_message, first_error
from jointwear.config.overrides import (
    apply_overrides,
    deep_merge,
    material_defaults,
    without_none,
)
from jointwear.config.parameter_sets import get_parameter_set
from jointwear.config.schema import ConfigSchema
from jointwear.config.toml import read_toml, toml_text
from jointwear.errors import ConfigError
from jointwear.registry import suggest
from jointwear.units import shown

__all__ = ["Config", "config_from_dict", "load_config"]


class Config(ConfigSchema):
    """A whole jointwear configuration (all values SI).

    Its sections are those of :class:`~jointwear.config.schema.ConfigSchema`; a stage
    takes the section it needs (``config.joint``, ``config.wear``).
    """

    def to_toml(self) -> str:
        """The resolved config as TOML text (SI units, :func:`~jointwear.config.toml.toml_text`).

        A value a bare number would not be taken for (:func:`check_bare_numbers`, e.g.
        an angle of more than a turn) is written with its SI unit, so that the text
        reads back as the same config.
        """
        return toml_text(self.to_dict(), self.mechanism.type)

    def replace(self, overrides: Mapping[str, Any] | Iterable[str] | str) -> Config:
        """Return a new config with dotted-key overrides applied and validated.

        Parameters
        ----------
        overrides : mapping, iterable of str, or str
            ``{"joint.clearance": "0.2 mm"}``, ``["joint.clearance=0.2 mm"]`` or
            ``"joint.clearance=0.2 mm"``; quantities as SI numbers or strings with units.

        Raises
        ------
        ConfigError
            For overrides of another form, an unknown key or an invalid value.
        """
        # the raw fields, not to_dict(): derived defaults (rod inertia from the rod
        # mass, spring area from the axial length) must follow the overrides
        data = without_none(self.model_dump(mode="json"))
        apply_overrides(data, overrides)
        return config_from_dict(data, defaults=False)


def config_from_dict(data: Mapping[str, Any], defaults: bool = True) -> Config:
    """Validate a (nested) config mapping into a :class:`Config`.

    Parameters
    ----------
    data : mapping
        Nested sections; quantities as SI numbers or strings with units.
    defaults : bool
        Merge the named parameter set's values underneath ``data``.
    """
    if not isinstance(data, Mapping):
        raise ConfigError(f"config: expected a mapping of sections, got {shown(data)}")
    data = dict(data)
    mechanism = data.get("mechanism", {})
    if not isinstance(mechanism, Mapping):
        raise ConfigError("mechanism: expected a section")
    kind = mechanism.get("type", "slider-crank")
    if not isinstance(kind, str) or kind not in MECHANISM_TYPES:
        raise ConfigError(
            f"mechanism.type: {shown(kind)} is not a mechanism type"
            f"{suggest(shown(kind).strip(chr(39)), MECHANISM_TYPES)}"
        )
    data["mechanism"] = {**mechanism, "type": kind}
    if defaults:
        name = data.get("parameter_set", "nlcp-paper")
        if not isinstance(name, str):
            raise ConfigError(f"parameter_set: expected a name, got {name!r}")
        data = deep_merge(material_defaults(get_parameter_set(name, kind), data), data)
        data["mechanism"] = mode_defaults(data["mechanism"], name)
    try:
        return Config.model_validate(data)
    except ValidationError as exc:
        raise ConfigError(error_message(first_error(exc.errors()))) from None


def load_config(
    path: str | Path | None = None, overrides: Iterable[str] | Mapping[str, Any] | str = ()
) -> Config:
    """Read a TOML config, apply overrides, validate.

    Parameters
    ----------
    path : path-like, optional
        TOML file; ``None`` uses the parameter set's defaults only.
    overrides : iterable of str, str or mapping
        ``"section.key=VALUE"`` strings (CLI ``--set``), one such string, or a
        dotted-key mapping.
    """
    data: dict[str, Any] = {} if path is None else read_toml(path)
    apply_overrides(data, overrides)
    check_bare_numbers(data)
    base = Path.cwd() if path is None else Path(path).parent
    for mechanism in mechanism_tables(data.get("mechanism")):
        _file_beside(mechanism, base)
    return config_from_dict(data)


def _file_beside(mechanism: dict[str, Any], base: Path) -> None:
    """``mechanism.file`` made absolute, relative to the config's folder ``base``."""
    if isinstance(mechanism.get("file"), str):
        # a data file named in a config is found next to the config, wherever it is run
        # absolute, but a link keeps its name (messages name the file the user wrote)
        try:
            if "\x00" in mechanism["file"]:
                raise ValueError("embedded null byte")
            mechanism["file"] = str(Path.absolute(base / mechanism["file"]))
        except (OSError, ValueError) as exc:  # e.g. a NUL or a lone surrogate in the name
            raise ConfigError(f"mechanism.file: {shown(mechanism['file'])}: {exc}") from None


def mechanism_tables(mechanism: Any) -> list[dict[str, Any]]:
    """The ``[mechanism]`` table, or a duty cycle's mode tables, as written."""
    if not isinstance(mechanism, dict):
        return []
    modes = mechanism.get("modes")
    if mechanism.get("type") == "duty-cycle" and isinstance(modes, list):
        return [mode for mode in modes if isinstance(mode, dict)]
    return [mechanism]


def mode_defaults(mechanism: dict[str, Any], name: str) -> dict[str, Any]:
    """A duty cycle's modes with the parameter set ``name``'s defaults of their types
    underneath (any other mechanism as it is)."""
    if mechanism.get("type") != "duty-cycle" or not isinstance(mechanism.get("modes"), list):
        return mechanism
    modes = []
    for mode in mechanism["modes"]:
        kind = mode.get("type") if isinstance(mode, dict) else None
        if isinstance(kind, str) and kind in MECHANISM_TYPES and kind != "duty-cycle":
            mode = deep_merge(get_parameter_set(name, kind).get("mechanism", {}), mode)
        modes.append(mode)
    return {**mechanism, "modes": modes}
