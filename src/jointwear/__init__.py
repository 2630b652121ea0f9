"""jointwear: wear of planar revolute joints with clearance.

Pipeline (paper Fig. 7), one module per stage::

    mechanism  -> joint load per time step (slider-crank, massless link)
    contact    -> pressure on the bushing (Hertz, Winkler, asymmetric Winkler, NLCP)
    tribology  -> sliding and Archard wear
    geometry   -> bushing contour and its update

:class:`Simulation` runs the loop over revolutions.
"""

from __future__ import annotations

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("jointwear")
except PackageNotFoundError:  # running from a source tree
    __version__ = "0+unknown"

from jointwear.config import Config, load_config
from jointwear.errors import JointwearError
from jointwear.geometry import BushingContour, Pin


def __getattr__(name: str):
    # the orchestrator pulls in xarray; import it lazily to keep `import jointwear` light
    if name in {"Simulation", "WearResult"}:
        from jointwear import simulation

        return getattr(simulation, name)
    raise AttributeError(f"module 'jointwear' has no attribute {name!r}")


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
