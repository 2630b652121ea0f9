"""The slider-crank's contact-impact revolution integrated by RADAU5, compiled.

``dynamics.integrator = "Radau-compiled"``: the fully implicit integrator of
:mod:`jointwear.mechanism.impact.radau` bound to the slider-crank's compiled
right-hand side and gap functions
(:mod:`jointwear.mechanism.slider_crank._contact_impact_kernel`), with the Jacobian's
columns and difference step of the RODAS4 binding
(:mod:`jointwear.mechanism.slider_crank._contact_impact_rosenbrock`, where the step is
argued). Imported on first use only.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from jointwear.mechanism.impact import radau, rosenbrock
from jointwear.mechanism.impact.compiled_film import SOURCE_DIGEST
from jointwear.mechanism.slider_crank import _contact_impact_kernel as kernel
from jointwear.mechanism.slider_crank._contact_impact_rosenbrock import STIFF_SYSTEM

__all__ = ["integrate_revolution_radau"]

#: the cache entries carry the sources of the right-hand side, the film force and RODAS4's
#: shared functions (numba checks only a function's own file when it loads it)
_DIGEST = (
    hashlib.sha1(
        Path(kernel.__file__).read_bytes() + Path(rosenbrock.__file__).read_bytes()
    ).hexdigest()[:12]
    + SOURCE_DIGEST
)

#: ``integrate_revolution_rk``'s arguments and results, RADAU5's steps
integrate_revolution_radau = radau.bind(STIFF_SYSTEM, f"slider_crank_{_DIGEST}")
