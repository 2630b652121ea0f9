r"""Which fitted parameters the measurements fix, and which they do not.

A least-squares fit always returns numbers; whether the data determine them is a
property of the Jacobian ``J = dr/du`` of the residuals with respect to the parameters
on their fitting scale ``u`` (log or linear on ``[0, 1]``). Three signs that a
parameter is not identifiable from the cases given:

* **a direction the data do not see**: the columns of ``J``, each scaled to unit length,
  are nearly dependent; the smallest singular value over the largest below
  :data:`CONDITION_LIMIT` (a combination of the parameters is fixed, each on its own is
  not: e.g. ``K_d`` and the speed exponent from measurements all at one speed, where only
  ``K_d v^b`` matters);
* **a correlation** of the fitted parameters beyond :data:`CORRELATION_LIMIT`;
* **an interval wider than the search**: the confidence interval on the fitting scale
  spans more than a decade either way (log scale) or more than half the bounds (linear).

Each flagged parameter is reported with its reason (the ``calibrate`` summary's
``not_identifiable`` and one warning line each); its value and interval are then the
optimiser's pick along a valley, not a measurement. More cases that differ in what the
parameter acts on (other speeds for a speed exponent, other loads for a pressure
exponent, other cycle counts for running-in) make it identifiable.

References
----------
D. M. Bates, D. G. Watts (1988). Nonlinear Regression Analysis and Its Applications.
Wiley, ch. 2 (the linear approximation to the covariance) and ch. 3.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = ["CONDITION_LIMIT", "CORRELATION_LIMIT", "not_identifiable"]

FloatArray = NDArray[np.float64]

#: smallest over largest singular value of the column-scaled Jacobian below which a
#: direction of the parameters is not seen by the data [-]
CONDITION_LIMIT = 1e-4
#: correlation of two fitted parameters beyond which neither is fixed on its own [-]
CORRELATION_LIMIT = 0.995
#: the widest interval on a log scale taken as a measurement: a factor this each way [-]
LOG_INTERVAL_LIMIT = 10.0


def not_identifiable(
    keys: Sequence[str],
    jacobian: FloatArray,
    correlation: FloatArray,
    half_widths: Mapping[str, float],
    logarithmic: Mapping[str, bool],
) -> dict[str, str]:
    """The parameters the data do not determine, each with the reason.

    Parameters
    ----------
    keys : sequence of str
        The fitted config keys, in the order of the Jacobian's columns.
    jacobian : ndarray, shape (M, P)
        ``dr/du`` at the optimum, ``u`` the fitting scale of each parameter [-].
    correlation : ndarray, shape (P, P)
        Correlation of the fitted parameters (NaN where not estimable) [-].
    half_widths : mapping of str to float
        Half-width of each confidence interval on its fitting scale (of ``ln`` value
        for a log-scale parameter [-], else as a fraction of its bounds [-]); NaN where
        not estimable.
    logarithmic : mapping of str to bool
        Whether each parameter is fitted on a log scale.

    Returns
    -------
    dict of str to str
        Key -> why it is not identifiable; empty when every parameter is.
    """
    out: dict[str, str] = {}
    jac = np.asarray(jacobian, dtype=float)
    norms = np.linalg.norm(jac, axis=0)
    for key, norm in zip(keys, norms, strict=True):
        if not norm > 0.0:
            out[key] = "the measured profiles do not change with it"
    seen = norms > 0.0
    if seen.sum() > 1:
        _, singular, vt = np.linalg.svd(jac[:, seen] / norms[seen], full_matrices=False)
        ratio = singular[-1] / singular[0]
        if ratio < CONDITION_LIMIT:
            direction = np.abs(vt[-1])
            named = [k for k, s in zip(np.asarray(keys)[seen], direction, strict=True) if s > 0.1]
            for key in named:
                others = ", ".join(k for k in named if k != key)
                out.setdefault(
                    key,
                    f"only a combination with {others} is fixed by the data (condition "
                    f"{ratio:.1e}); add cases that tell them apart",
                )
    for i, key in enumerate(keys):
        for j, other in enumerate(keys):
            rho = correlation[i, j] if correlation.size else math.nan
            if i != j and abs(rho) > CORRELATION_LIMIT:
                out.setdefault(key, f"correlated {rho:+.4f} with {other}")
        width = half_widths.get(key, math.nan)
        limit = math.log(LOG_INTERVAL_LIMIT) if logarithmic.get(key) else 0.5
        if not math.isfinite(width):
            out.setdefault(key, "no confidence interval can be estimated")
        elif width > limit:
            out.setdefault(
                key,
                "its confidence interval spans more than "
                + ("a decade either way" if logarithmic.get(key) else "half its bounds"),
            )
    return out
