"""Validated configuration: TOML in, SI floats out.

Every quantity in a config file is a plain number (SI) or a string with units
(``"0.2 mm"``, ``"240 rpm"``); a plain number that can only be a unit slip is
refused (:func:`check_bare_numbers`). :func:`load_config` reads a file, applies
``--set section.key=VALUE`` overrides and returns a :class:`Config` whose
fields are SI floats. Any problem raises :class:`~jointwear.errors.ConfigError`
with a one-line message that starts with the dotted key.

Defaults come from a named parameter set (:mod:`jointwear.config.parameter_sets`),
``nlcp-paper`` unless the file says ``parameter_set = "..."``.

The package imports no physics: the stages' choices (contact models, wear laws,
dynamics models) are validated against names kept in :mod:`.choices`, and the
stages' checks and closed-form defaults are reached through lazy ``"module:attr"``
entries (:class:`jointwear.registry.Lazy`). Its modules, lowest first:

==================  ==============================================================
``fields``          quantities read into SI (:func:`field_kind`), the section base
``choices``         the stages' open choices: names and lazy entries
``mechanisms``      the ``[mechanism]`` tables, discriminated by ``type``
``sections``        ``[joint]``, ``[materials]``, ``[contact]``, ... ``[life]``
``parameter_sets``  named sets of defaults (PyBaMM style)
``schema``          the whole configuration's sections, cross-checks, derived values
``lookup``          dotted keys (:func:`key_field`) and bare-number checks
``messages``        a validation error as one line naming its key
``overrides``       dotted keys and ``--set`` (:func:`apply_overrides`)
``toml``            reading a file, writing a resolved config (``tomli-w``)
``loading``         :class:`Config`, :func:`config_from_dict`, :func:`load_config`
==================  ==============================================================
"""

from __future__ import annotations

from jointwear.config.fields import MAX_COUNT, MAX_INTEGRATOR_STEPS, field_kind
from jointwear.config.loading import Config, config_from_dict, load_config
from jointwear.config.lookup import BARE_LINK_LENGTH, check_bare_numbers, is_section, key_field
from jointwear.config.mechanisms import (
    DYNAMIC_TYPES,
    FOUR_BAR_JOINT_BODIES,
    MECHANISM_TYPES,
    FourBarConfig,
    LoadHistoryConfig,
    MechanismConfig,
    OscillatingConfig,
    SliderCrankConfig,
)
from jointwear.config.messages import error_key
from jointwear.config.overrides import apply_overrides, normalized_overrides, parse_override
from jointwear.config.sections import (
    ContactConfig,
    DynamicsConfig,
    JointConfig,
    LifeConfig,
    LubricationConfig,
    MaterialConfig,
    MaterialsConfig,
    SimulationConfig,
    WearConfig,
)
from jointwear.config.toml import MAX_TOML_DEPTH, read_toml

__all__ = [
    "BARE_LINK_LENGTH",
    "DYNAMIC_TYPES",
    "FOUR_BAR_JOINT_BODIES",
    "MAX_COUNT",
    "MAX_INTEGRATOR_STEPS",
    "MAX_TOML_DEPTH",
    "MECHANISM_TYPES",
    "Config",
    "ContactConfig",
    "DynamicsConfig",
    "FourBarConfig",
    "JointConfig",
    "LifeConfig",
    "LoadHistoryConfig",
    "LubricationConfig",
    "MaterialConfig",
    "MaterialsConfig",
    "MechanismConfig",
    "OscillatingConfig",
    "SimulationConfig",
    "SliderCrankConfig",
    "WearConfig",
    "apply_overrides",
    "check_bare_numbers",
    "config_from_dict",
    "error_key",
    "field_kind",
    "is_section",
    "key_field",
    "load_config",
    "normalized_overrides",
    "parse_override",
    "read_toml",
]
