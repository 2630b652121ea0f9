"""The slider-crank's contact-impact revolution integrated by RODAS4, compiled.

``dynamics.integrator = "Rodas4-compiled"`` (and ``auto`` for a lubricated joint): the
stiff integrator of :mod:`jointwear.mechanism.impact.rosenbrock` bound to the
slider-crank's compiled right-hand side and gap functions
(:mod:`jointwear.mechanism.slider_crank._contact_impact_kernel`). Its right-hand side
does not depend on the crank work ``W``, the state's last component, so the
Jacobian's differences run over the first four. Imported on first use only.

The differences step by 1e-11 of ``max(|y_j|, 1)``, far below the usual ``sqrt(eps)``:
a stiff step amplifies the Jacobian's error by ``|lambda| h`` (1e3-1e5 here), and the
squeeze film is nonlinear in the pin's radial speed on a scale of ``omega_bar eps c``,
1e-7-1e-5 m/s (its force is homogeneous in the squeeze and the wedge speed, with
half-Sommerfeld cavitation switching sides as the radial speed changes sign); with
``sqrt(eps)`` the steps of RODAS4 on the paper's joint shrink to those of the explicit
pair. The entries that matter are 1e6-1e9 1/s, so the rounding of the differences,
``eps |f| / step``, stays far below them.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

from jointwear.mechanism.impact import rosenbrock
from jointwear.mechanism.impact.compiled_film import SOURCE_DIGEST
from jointwear.mechanism.slider_crank import _contact_impact_kernel as kernel

__all__ = ["STIFF_SYSTEM", "integrate_revolution_rosenbrock"]

#: the cache entries carry the right-hand side's and the film force's sources (numba
#: checks only the integrator's own file when it loads a cached function)
_DIGEST = hashlib.sha1(Path(kernel.__file__).read_bytes()).hexdigest()[:12] + SOURCE_DIGEST

#: the slider-crank for a stiff integrator's ``bind``: its compiled functions, the
#: Jacobian's columns and difference step (above); RADAU5's binding takes it too
STIFF_SYSTEM = {
    "rhs": kernel.rhs,
    "gap": kernel.gap,
    "gap_and_rate": kernel.gap_and_rate,
    "JACOBIAN_COLUMNS": 4,
    "DIFFERENCE_STEP": 1e-11,
}

#: ``integrate_revolution_rk``'s arguments and results, RODAS4's steps
integrate_revolution_rosenbrock = rosenbrock.bind(STIFF_SYSTEM, f"slider_crank_{_DIGEST}")
