"""Reliability of a joint from right-censored lives: B10/B50 lives, a Weibull fit, R(N).

A life study (:mod:`jointwear.workflows.life`) gives each case's life, or, for a case that
reached no limit within its run, the revolutions it ran: a right-censored life, known only
to be longer. From these:

* the **B-lives** ``B_p``, the life by which a fraction ``p`` of the joints reach a limit,
  read from the Kaplan-Meier estimate of the distribution [1]_ (no assumed shape), with
  the confidence bounds where its pointwise Greenwood band [2]_ crosses ``p``: the lower
  bound where the band's upper edge reaches ``p``, the upper where its lower edge does. A
  B-life the estimate does not reach lies beyond the longest run: it is reported as that
  run, a lower bound;
* a **two-parameter Weibull fit** ``F(N) = 1 - exp(-(N / eta)^beta)`` by maximum likelihood
  with the censored cases in the likelihood through their survival function, and Fisher
  matrix confidence bounds on ``beta``, ``eta`` and its B-lives (the ``reliability``
  package [3]_); it extrapolates where the cases were censored;
* the **probability of reaching each limit** by a given number of revolutions: the
  Aalen-Johansen cumulative incidence [4]_, which shares the joints between the limits
  that compete for them (the first reached ends the life).

References
----------
.. [1] Kaplan, E. L., Meier, P. (1958). Nonparametric estimation from incomplete
   observations. Journal of the American Statistical Association 53, 457-481.
.. [2] Greenwood, M. (1926). The natural duration of cancer. Reports on Public Health and
   Medical Subjects 33, 1-26.
.. [3] Reid, M. (2022). reliability: a Python library for reliability engineering.
   https://reliability.readthedocs.io (Fit_Weibull_2P).
.. [4] Aalen, O. O., Johansen, S. (1978). An empirical transition matrix for
   non-homogeneous Markov chains based on censored observations. Scandinavian Journal of
   Statistics 5, 141-150.
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

__all__ = [
    "B_LIVES",
    "CONFIDENCE",
    "b_life",
    "headline",
    "limit_probabilities",
    "reliability_summary",
    "weibull_cdf",
    "weibull_fit",
]

#: the B-lives reported: name -> fraction of joints worn out [-]
B_LIVES = {"b10": 0.10, "b50": 0.50}
#: two-sided confidence of the bounds [-]
CONFIDENCE = 0.95
#: fewest lives reached that a Weibull fit needs [-]
FIT_MINIMUM = 2


def _estimate(lives: np.ndarray, censored: np.ndarray) -> Any:
    """The Kaplan-Meier estimate of the distribution of lives (scipy)."""
    from scipy.stats import CensoredData, ecdf

    return ecdf(CensoredData(uncensored=lives[~censored], right=lives[censored])).cdf


def _first_reaching(times: np.ndarray, probabilities: np.ndarray, p: float) -> float | None:
    """The smallest time at which a step function of probabilities reaches ``p``."""
    # (the product of the estimate leaves round-off: 0.5 may be 0.4999999999999999)
    reached = np.flatnonzero(np.nan_to_num(probabilities, nan=0.0) >= p - 1e-12)
    return float(times[reached[0]]) if reached.size else None


def b_life(
    lives: ArrayLike, censored: ArrayLike, p: float, confidence: float = CONFIDENCE
) -> dict[str, Any]:
    """The life by which a fraction ``p`` of the joints reach a limit (Kaplan-Meier).

    Parameters
    ----------
    lives : array_like, shape (n,)
        Each case's life, or the revolutions a censored case ran [revolutions].
    censored : array_like of bool, shape (n,)
        Whether each case ended without reaching a limit.
    p : float
        Fraction of joints worn out [-], in (0, 1): 0.1 for B10.
    confidence : float
        Two-sided confidence of the bounds [-].

    Returns
    -------
    dict
        ``value`` [revolutions] (the longest run, a lower bound, where the estimate
        stays below ``p``), ``lower_bound`` (bool), ``lower`` and ``upper`` confidence
        bounds [revolutions] (``upper`` ``None`` where the band's lower edge never
        reaches ``p``: the data bound the life only from below).
    """
    lives = np.asarray(lives, dtype=float)
    censored = np.asarray(censored, dtype=bool)
    if not lives.size:
        return {"value": None, "lower_bound": False, "lower": None, "upper": None}
    longest = float(lives.max())
    if censored.all():
        return {"value": longest, "lower_bound": True, "lower": longest, "upper": None}
    cdf = _estimate(lives, censored)
    value = _first_reaching(cdf.quantiles, cdf.probabilities, p)
    with warnings.catch_warnings():
        # the log-log band is undefined where the estimate is 0 or 1: no bound there
        warnings.simplefilter("ignore", RuntimeWarning)
        band = cdf.confidence_interval(confidence_level=confidence, method="log-log")
    lower = _first_reaching(cdf.quantiles, band.high.evaluate(cdf.quantiles), p)
    upper = _first_reaching(cdf.quantiles, band.low.evaluate(cdf.quantiles), p)
    return {
        "value": longest if value is None else value,
        "lower_bound": value is None,
        "lower": longest if lower is None else lower,
        "upper": upper,
    }


def weibull_fit(
    lives: ArrayLike,
    censored: ArrayLike,
    confidence: float = CONFIDENCE,
    fractions: Sequence[float] = tuple(B_LIVES.values()),
) -> dict[str, Any] | None:
    """Two-parameter Weibull fit of right-censored lives (maximum likelihood).

    ``F(N) = 1 - exp(-(N / eta)^beta)``; a censored case contributes its survival
    ``exp(-(N_c / eta)^beta)`` to the likelihood. The bounds are the Fisher matrix
    bounds of the ``reliability`` package's ``Fit_Weibull_2P``.

    Parameters
    ----------
    lives : array_like, shape (n,)
        Each case's life, or the revolutions a censored case ran [revolutions].
    censored : array_like of bool, shape (n,)
        Whether each case ended without reaching a limit.
    confidence : float
        Two-sided confidence of the bounds [-].
    fractions : sequence of float
        Fractions ``p`` of the B-lives to report [-].

    Returns
    -------
    dict or None
        ``shape`` (``beta`` [-]) and ``scale_revolutions`` (``eta`` [revolutions]), each
        ``{"value", "lower", "upper"}``; ``b_lives`` (``p`` -> ``{"value", "lower",
        "upper"}`` [revolutions]); ``reached`` and ``censored`` counts. ``None`` with
        fewer than two lives reached (no fit).
    """
    from reliability.Fitters import Fit_Weibull_2P

    lives = np.asarray(lives, dtype=float)
    censored = np.asarray(censored, dtype=bool)
    reached = lives[~censored]
    if reached.size < FIT_MINIMUM or np.ptp(reached) == 0:
        return None
    fit = Fit_Weibull_2P(
        failures=reached,
        right_censored=lives[censored] if censored.any() else None,
        CI=confidence,
        quantiles=list(fractions),
        show_probability_plot=False,
        print_results=False,
    )
    table = fit.quantiles
    b_lives = {
        float(p): {"value": float(point), "lower": float(low), "upper": float(high)}
        for p, low, point, high in zip(
            table["Quantile"],
            table["Lower Estimate"],
            table["Point Estimate"],
            table["Upper Estimate"],
            strict=True,
        )
    }
    return {
        "shape": {
            "value": float(fit.beta),
            "lower": float(fit.beta_lower),
            "upper": float(fit.beta_upper),
        },
        "scale_revolutions": {
            "value": float(fit.alpha),
            "lower": float(fit.alpha_lower),
            "upper": float(fit.alpha_upper),
        },
        "b_lives": b_lives,
        "reached": int(reached.size),
        "censored": int(censored.sum()),
    }


def limit_probabilities(
    lives: ArrayLike, censored: ArrayLike, limits: Sequence[str], by: float
) -> dict[str, float]:
    """Probability that a joint reaches each limit first, within ``by`` revolutions.

    The Aalen-Johansen cumulative incidence ``P_k(N) = sum_{t_i <= N} S(t_i-) d_ki / n_i``
    (``S`` the Kaplan-Meier survival of all limits, ``d_ki`` lives ended by limit ``k``
    at ``t_i``, ``n_i`` cases still running there); the limits' probabilities add up to
    the Kaplan-Meier probability of reaching any.

    Parameters
    ----------
    lives : array_like, shape (n,)
        Each case's life, or the revolutions a censored case ran [revolutions].
    censored : array_like of bool, shape (n,)
        Whether each case ended without reaching a limit.
    limits : sequence of str, shape (n,)
        The limit that ended each case (ignored where censored).
    by : float
        Revolutions [revolutions].

    Returns
    -------
    dict
        Limit -> probability [-], and ``"any"``: of reaching any limit.
    """
    lives = np.asarray(lives, dtype=float)
    censored = np.asarray(censored, dtype=bool)
    limits = np.asarray([str(name) for name in limits], dtype=object)
    names = sorted(set(limits[~censored]))
    times, ended = np.unique(lives[~censored], return_counts=True)
    at_risk = lives.size - np.searchsorted(np.sort(lives), times, side="left")
    # S(t_i-): the Kaplan-Meier survival just before each time a life ends
    before = np.concatenate(([1.0], np.cumprod(1.0 - ended / at_risk)[:-1]))
    within = times <= by
    out = {}
    for name in names:
        by_limit = np.unique(lives[(~censored) & (limits == name)], return_counts=True)
        counts = np.zeros(times.size)
        counts[np.searchsorted(times, by_limit[0])] = by_limit[1]
        out[name] = float(np.sum((before * counts / at_risk)[within]))
    survival = float(np.prod((1.0 - ended / at_risk)[within]))
    return {**out, "any": 1.0 - survival}


def reliability_summary(
    lives: ArrayLike,
    censored: ArrayLike,
    limits: Sequence[str],
    by: float,
    confidence: float = CONFIDENCE,
) -> dict[str, Any]:
    """The reliability section of a life study (``life.json``'s ``reliability``).

    Parameters
    ----------
    lives : array_like, shape (n,)
        Each case's life, or the revolutions a censored case ran [revolutions].
    censored : array_like of bool, shape (n,)
        Whether each case ended without reaching a limit.
    limits : sequence of str, shape (n,)
        The limit that ended each case.
    by : float
        The revolutions of the probabilities of reaching each limit [revolutions].
    confidence : float
        Two-sided confidence of the bounds [-].

    Returns
    -------
    dict
        ``confidence``; ``b10`` and ``b50`` (:func:`b_life`, with the Weibull fit's
        ``{"value", "lower", "upper"}`` under ``weibull``, ``None`` without a fit);
        ``weibull`` (:func:`weibull_fit` without its distribution object, or ``None``);
        ``reach_probability`` (``by_revolutions``, ``limits``: :func:`limit_probabilities`,
        ``weibull``: the fit's ``F(by)``).
    """
    fit = weibull_fit(lives, censored, confidence)
    out: dict[str, Any] = {"confidence": confidence}
    for name, p in B_LIVES.items():
        entry = b_life(lives, censored, p, confidence)
        entry["weibull"] = None if fit is None else fit["b_lives"][p]
        out[name] = entry
    out["weibull"] = None if fit is None else {k: v for k, v in fit.items() if k != "b_lives"}
    out["reach_probability"] = {
        "by_revolutions": float(by),
        "limits": limit_probabilities(lives, censored, limits, by),
        "weibull": None if fit is None else float(weibull_cdf(by, fit)),
    }
    return out


def weibull_cdf(revolutions: ArrayLike, fit: Mapping[str, Any]) -> np.ndarray:
    """The fitted Weibull distribution ``F(N) = 1 - exp(-(N / eta)^beta)``.

    Parameters
    ----------
    revolutions : array_like
        ``N`` [revolutions].
    fit : mapping
        :func:`weibull_fit` (its ``shape`` and ``scale_revolutions`` values).

    Returns
    -------
    ndarray
        Fraction of joints that reached a limit by ``N`` [-].
    """
    from scipy.stats import weibull_min

    shape = fit["shape"]["value"]
    return weibull_min(shape, scale=fit["scale_revolutions"]["value"]).cdf(revolutions)


def headline(summary: Mapping[str, Any]) -> dict[str, float | None]:
    """The four numbers ``life --json`` shows at its top level.

    Parameters
    ----------
    summary : mapping
        :func:`reliability_summary`.

    Returns
    -------
    dict
        ``b10_revolutions``, ``b50_revolutions`` (Kaplan-Meier; a lower bound where
        flagged in ``reliability``), ``weibull_shape`` [-], ``weibull_scale_revolutions``
        (``None`` without a fit).
    """
    fit = summary["weibull"]
    return {
        "b10_revolutions": summary["b10"]["value"],
        "b50_revolutions": summary["b50"]["value"],
        "weibull_shape": None if fit is None else fit["shape"]["value"],
        "weibull_scale_revolutions": None if fit is None else fit["scale_revolutions"]["value"],
    }
