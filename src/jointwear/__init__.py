"""jointwear: wear of planar revolute joints with clearance.

Pipeline (paper Fig. 7), one module per stage::

    mechanism  -> joint load per time step (slider-crank, massless link)
    contact    -> pressure on the bushing (Hertz, Winkler, asymmetric Winkler, NLCP)
    tribology  -> sliding and Archard wear
    geometry   -> bushing contour and its update

:class:`Simulation` runs the loop over revolutions; :func:`run` is the short way::

    import jointwear as jw

    result = jw.run("joint.toml", {"contact.model": "hertz"})   # a WearResult
    result.summary()["peak_wear_depth_m"]
    jw.read_result("out/result.nc")     # a run folder's result, read back
    jw.models()["contact.model"]        # the contact models there are

Every public name is imported on first use, so ``import jointwear`` stays light
(the orchestrator pulls in xarray, the config pydantic); ``dir(jointwear)`` and
tab completion list them all the same. The command line's own modules (``cli``,
``display``, ``paper``, ...) stay importable but are not listed.
"""

from __future__ import annotations

import typing as _typing

__all__ = [
    "BushingContour",
    "Config",
    "JointwearError",
    "LoadCycle",
    "Pin",
    "Simulation",
    "WearResult",
    "__version__",
    "load_config",
    "models",
    "read_result",
    "run",
]

#: public name -> (module that defines it, its name there)
_LAZY = {
    "BushingContour": ("jointwear.geometry", "BushingContour"),
    "Config": ("jointwear.config", "Config"),
    "JointwearError": ("jointwear.errors", "JointwearError"),
    "LoadCycle": ("jointwear.mechanism", "LoadCycle"),
    "Pin": ("jointwear.geometry", "Pin"),
    "Simulation": ("jointwear.simulation", "Simulation"),
    "WearResult": ("jointwear.results", "WearResult"),
    "load_config": ("jointwear.config", "load_config"),
    "read_result": ("jointwear.results", "read_wear_result"),
}
#: subpackages and modules reachable as attributes (``jointwear.plots``) without an import:
#: attribute -> module (the workflows also by their short names, ``jointwear.life``)
_SUBMODULES = {
    **{
        name: f"jointwear.{name}"
        for name in (
            "config",
            "contact",
            "errors",
            "geometry",
            "lubrication",
            "materials",
            "measurement",
            "mechanism",
            "plots",
            "references",
            "results",
            "simulation",
            "tribology",
            "units",
            "workflows",
        )
    },
    "calibration": "jointwear.workflows.calibration",
    "life": "jointwear.workflows.life",
    "sweep": "jointwear.workflows.sweep",
}
#: the command line's and the package's own modules: reachable as attributes, not listed
_INTERNAL = ("checkpoint", "cli", "display", "io", "paper", "resources")


if _typing.TYPE_CHECKING:
    from collections.abc import Iterable, Mapping
    from os import PathLike

    from jointwear.config import Config, load_config
    from jointwear.errors import JointwearError
    from jointwear.geometry import BushingContour, Pin
    from jointwear.mechanism import LoadCycle
    from jointwear.results import WearResult
    from jointwear.results import read_wear_result as read_result
    from jointwear.simulation import Simulation


def run(
    config: Config | str | PathLike[str] | None = None,
    overrides: Mapping[str, object] | Iterable[str] | str | None = None,
    /,
    **settings: object,
) -> WearResult:
    """Run a wear simulation and return its result.

    Parameters
    ----------
    config : Config or path-like, optional
        A validated :class:`Config`, or a TOML config file (read by
        :func:`load_config`); ``None`` runs the default parameter set.
    overrides : mapping or iterable of str, optional
        Dotted-key overrides, ``{"contact.model": "hertz"}`` or
        ``["joint.clearance=0.2 mm"]`` (as ``--set``); quantities as SI numbers
        or strings with units.
    **settings
        More overrides as keywords, a double underscore for the dot:
        ``simulation__revolutions=10`` sets ``simulation.revolutions``.

    Returns
    -------
    WearResult
        The result (``.summary()`` is the ``jointwear run --json`` object without
        the engineering checks; ``.dataset`` the full result).

    Raises
    ------
    ConfigError
        For a config or an override that is not valid (one line naming the key).

    Examples
    --------
    >>> import jointwear as jw
    >>> result = jw.run(None, {"contact.model": "nlcp"}, simulation__revolutions=1000)
    >>> result.summary()["peak_wear_depth_m"] > 0
    True
    """
    from os import PathLike

    from jointwear.config import Config, load_config, normalized_overrides
    from jointwear.errors import ConfigError
    from jointwear.simulation import Simulation

    changes = normalized_overrides(() if overrides is None else overrides)
    changes.extend((key.replace("__", "."), value) for key, value in settings.items())
    if isinstance(config, Config):
        cfg = config.replace(dict(changes)) if changes else config
    elif config is None or isinstance(config, str | PathLike):
        cfg = load_config(config, dict(changes))
    else:
        raise ConfigError(
            f"config: expected a Config or the path of a TOML file, got {type(config).__name__}"
        )
    return Simulation(cfg).run()


def models() -> dict[str, list[str]]:
    """The names of the models there are, by the config key that selects one.

    Returns
    -------
    dict
        ``{"contact.model": [...], "wear.law": [...], "mechanism.type": [...],
        "dynamics.model": [...], "simulation.sliding": [...]}``, each list in
        registration order.
    """
    from jointwear.contact import CONTACT_MODELS
    from jointwear.mechanism import DYNAMICS_MODELS, MECHANISMS
    from jointwear.tribology.sliding import SLIDING_MODELS
    from jointwear.tribology.wear_laws import WEAR_LAWS

    registries = (CONTACT_MODELS, WEAR_LAWS, MECHANISMS, DYNAMICS_MODELS, SLIDING_MODELS)
    return {registry.key: registry.names() for registry in registries}


def __getattr__(name: str) -> object:
    from importlib import import_module

    if name == "__version__":
        from jointwear.version import package_version

        value: object = package_version()
    elif name in _LAZY:
        module, attribute = _LAZY[name]
        value = getattr(import_module(module), attribute)
    elif name in _SUBMODULES:
        value = import_module(_SUBMODULES[name])
    elif name in _INTERNAL:
        value = import_module(f"jointwear.{name}")
    else:
        raise AttributeError(f"module 'jointwear' has no attribute {name!r}")
    globals()[name] = value  # later look-ups skip __getattr__
    return value


def __dir__() -> list[str]:
    dunders = {name for name in globals() if name.startswith("__")} | {"__version__"}
    return sorted(dunders | set(__all__) | set(_SUBMODULES))
