"""The film force of :mod:`jointwear.mechanism.impact.film`, compiled by numba.

Imported on first use only, by the compiled right-hand sides of the contact systems
(:mod:`jointwear.mechanism.slider_crank._contact_impact_kernel`): ``import numba`` costs
a few tenths of a second that a dry run should not pay.

The functions are those of :mod:`~jointwear.mechanism.impact.film`, not copies: each is
compiled from the same code object, with the module's other functions replaced by
their compiled versions in its namespace (numba resolves a function's globals when it
compiles it), callees first. The machine code is cached on disk next to ``film.py``
and rebuilt when that file changes.
"""

from __future__ import annotations

import hashlib
import types
from collections.abc import Callable
from pathlib import Path
from typing import Any

from numba import njit

from jointwear.mechanism.impact import film

__all__ = ["SOURCE_DIGEST", "joint_film_force", "long_bearing", "short_bearing"]

#: the content of ``film.py`` in a few hex digits: a cached kernel that calls the film
#: force names itself by it (numba checks only the caller's own file when it loads a
#: cached function, not the files of the functions compiled into it)
SOURCE_DIGEST = hashlib.sha1(Path(film.__file__).read_bytes()).hexdigest()[:12]

#: the compiled functions, callees before their callers
_ORDER = (
    "sommerfeld_angle",
    "short_bearing",
    "long_bearing_sign",
    "long_bearing_root",
    "long_bearing_antiderivatives",
    "long_bearing",
    "film_eccentricity",
    "joint_film_force",
)


def _compile_all() -> dict[str, Any]:
    namespace = dict(vars(film))
    for name in _ORDER:
        source: Callable[..., Any] = getattr(film, name)
        clone = types.FunctionType(
            source.__code__, namespace, name, source.__defaults__, source.__closure__
        )
        clone.__qualname__ = source.__qualname__
        clone.__module__ = source.__module__
        clone.__doc__ = source.__doc__
        namespace[name] = njit(cache=True)(clone)
    return namespace


_COMPILED = _compile_all()
short_bearing = _COMPILED["short_bearing"]
long_bearing = _COMPILED["long_bearing"]
joint_film_force = _COMPILED["joint_film_force"]
