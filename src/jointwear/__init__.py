"""jointwear: wear of planar revolute joints with clearance.

Pipeline (paper Fig. 7), one module per stage::

    mechanism  -> joint load per time step (slider-crank, massless link)
    contact    -> pressure on the bushing (Hertz, Winkler, asymmetric Winkler, NLCP)
    tribology  -> sliding and Archard wear
    geometry   -> bushing contour and its update

:class:`Simulation` runs the loop over revolutions.

Every public name is imported on first use, so ``import jointwear`` stays light
(the orchestrator pulls in xarray, the config pydantic); ``dir(jointwear)`` and
tab completion list them all the same.
"""

from __future__ import annotations

import typing as _typing

__all__ = [
    "BushingContour",
    "Config",
    "JointwearError",
    "Pin",
    "Simulation",
    "WearResult",
    "__version__",
    "load_config",
]

#: public name -> module that defines it
_LAZY = {
    "BushingContour": "jointwear.geometry",
    "Config": "jointwear.config",
    "JointwearError": "jointwear.errors",
    "Pin": "jointwear.geometry",
    "Simulation": "jointwear.simulation",
    "WearResult": "jointwear.simulation",
    "load_config": "jointwear.config",
}
#: subpackages and modules reachable as attributes (``jointwear.plots``) without an import
_SUBMODULES = (
    "calibration",
    "cli",
    "config",
    "contact",
    "display",
    "errors",
    "geometry",
    "measurement",
    "mechanism",
    "parameter_sets",
    "plots",
    "paper",
    "references",
    "results",
    "simulation",
    "sweep",
    "tribology",
    "units",
)


def _package_version() -> str:
    # read when first asked for: importlib.metadata and the scan of the installed
    # distributions cost more than a one-revolution run's contact solve
    from importlib import metadata

    try:
        return metadata.version("jointwear")
    except metadata.PackageNotFoundError:  # running from a source tree
        return "0+unknown"

if _typing.TYPE_CHECKING:
    from jointwear.config import Config, load_config
    from jointwear.errors import JointwearError
    from jointwear.geometry import BushingContour, Pin
    from jointwear.simulation import Simulation, WearResult


def __getattr__(name: str) -> object:
    from importlib import import_module

    if name == "__version__":
        value: object = _package_version()
    elif name in _LAZY:
        value = getattr(import_module(_LAZY[name]), name)
    elif name in _SUBMODULES:
        value = import_module(f"jointwear.{name}")
    else:
        raise AttributeError(f"module 'jointwear' has no attribute {name!r}")
    globals()[name] = value  # later look-ups skip __getattr__
    return value


def __dir__() -> list[str]:
    dunders = {name for name in globals() if name.startswith("__")} | {"__version__"}
    return sorted(dunders | set(__all__) | set(_SUBMODULES))
