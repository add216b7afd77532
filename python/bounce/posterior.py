"""Posteriors of a model's parameters given a measured restitution curve (docs/fitting.md,
"Posteriors"): emcee's affine-invariant ensemble sampler (Goodman & Weare 2010, Foreman-Mackey
et al. 2013) over the parameters :func:`bounce.fit` fits, with the likelihood of K13 (31)'s
residuals computed by the C++ library for a whole ensemble at once.
"""
from __future__ import annotations

import math
import numbers
import sys
import time
from typing import Mapping

import numpy as np

from . import _bounce as b

#: Without ``steps``: the ensemble's moves. With ``walkers`` of 8 per parameter this is about 50
#: autocorrelation times for K13's three parameters on the synthetic PSL-on-quartz data (measured;
#: the result's ``warnings`` say where a chain is shorter than that).
DEFAULT_STEPS = 1500


def _invalid(name: str, value: object, expected: str) -> ValueError:
    return ValueError(f"{name} = {value} is invalid: expected {expected}")


def _whole(name: str, value: object, least: int) -> int:
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} = {value!r} is invalid: expected a whole number")
    if value < least:
        raise _invalid(name, value, f"a whole number >= {least}")
    return int(value)


def _grid(priors: Mapping | None, names: list[str], defaults: list) -> dict | None:
    """The priors as the fit's grid {name: (lo, hi, 2)}: the front door checks each range; a
    yield strength's ends at most at the default prior's 0.2 E_soft (the theoretical bound)."""
    if priors is None:
        return None
    if not isinstance(priors, Mapping):
        raise TypeError(f"priors = {priors!r} is invalid: expected a dict {{name: (lo, hi)}}")
    grid = {}
    for name, bounds in priors.items():
        key = "yield" if name == "yield_strength" else name
        if key not in names:
            raise _invalid("priors", name, f"one of the fitted parameters {', '.join(names)}")
        try:
            lo, hi = (float(x) for x in bounds)
        except (TypeError, ValueError):
            raise TypeError(f"priors[{name}] = {bounds!r} is invalid: expected (lo, hi), two numbers") from None
        if not (0.0 < lo < hi < math.inf):
            raise _invalid(f"priors[{name}]", (lo, hi), "0 < lo < hi, finite (a log-uniform prior)")
        bound = defaults[names.index(key)][1]
        if key == "yield" and hi > bound * (1.0 + 1e-12):  # 1e-12: the bound's round-off, as computed in C++
            raise _invalid(f"priors[{name}]", (lo, hi), f"hi <= 0.2 E_soft = {bound:.4g} Pa, the theoretical yield "
                           "strength (K13 Fig 7 (b); docs/fitting.md)")
        grid[key] = (lo, hi, 2)
    return grid


def _start(likelihood: b.Likelihood, lo: np.ndarray, hi: np.ndarray, walkers: int, rng: np.random.Generator,
           threads: int) -> np.ndarray:
    """The walkers' start: 8 draws a walker from the prior, the best quarter kept, each walker
    one of them moved by 1 % of the prior's width (all at distinct, finite points)."""
    draws = lo + (hi - lo) * rng.random((8 * walkers, lo.size))
    log_l = likelihood.evaluate(10.0 ** draws, threads)
    finite = np.flatnonzero(np.isfinite(log_l))
    if finite.size == 0:
        raise RuntimeError("posterior: the likelihood is -inf at every one of the prior's first draws (every collision "
                           "failed); narrow the priors")
    best = finite[np.argsort(log_l[finite])[::-1][: max(walkers // 4, 1)]]
    picks = draws[rng.choice(best, walkers)]
    return np.clip(picks + 0.01 * (hi - lo) * rng.standard_normal(picks.shape), lo, hi)


def _warnings(names: list[str], x: np.ndarray, lo: np.ndarray, hi: np.ndarray, tau: np.ndarray, steps: int,
              acceptance: float) -> list[str]:
    out = []
    if not np.all(np.isfinite(tau)) or steps < 50 * np.max(tau):
        out.append(f"the chain of {steps} steps is shorter than 50 autocorrelation times "
                   f"(tau = {', '.join(f'{t:.3g}' for t in tau)} steps): run more steps")
    for i, name in enumerate(names):
        width = hi[i] - lo[i]
        q = np.percentile(x[:, i], [2.5, 97.5])
        if q[1] - q[0] > 0.8 * width:
            out.append(f"{name} is not constrained by the data: its 95 % interval spans {100 * (q[1] - q[0]) / width:.0f} "
                       "% of the prior's log-range (the interval is the prior's, not a measurement)")
        elif q[0] - lo[i] < 0.01 * width or hi[i] - q[1] < 0.01 * width:
            edge = "lower" if q[0] - lo[i] < 0.01 * width else "upper"
            out.append(f"{name}: the walkers pile at the prior's {edge} edge ({10 ** (lo[i] if edge == 'lower' else hi[i]):.3g}):"
                       " the interval there is the prior's; widen it")
    # emcee's stretch move accepts 0.2-0.5 of its proposals in a few dimensions and up to ~0.8 in
    # one; below 0.1 walkers are stuck (a multimodal or very narrow posterior), above 0.9 they
    # barely move (a likelihood flat over the prior).
    if not 0.1 <= acceptance <= 0.9:
        out.append(f"mean acceptance fraction {acceptance:.2f} outside 0.1-0.9: the ensemble moves poorly")
    return out


def posterior(pair: b.Pair, model: b.Model, velocity=None, cor=None, *, cor_error=None, data: str | None = None,
              fit=None, priors: Mapping | None = None, walkers: int | None = None, steps: int | None = None,
              seed: int = 0, threads: int = 0, progress: bool = False) -> dict:
    """The posterior of the fitted parameters (docs/fitting.md, Posteriors).

    The data as for :func:`bounce.fit`: arrays ``velocity`` [m/s] and ``cor`` (0: stuck),
    optionally ``cor_error``, or ``data='file.csv'``. ``fit``: the parameters (default the
    model's, as fit's). ``priors``: {name: (lo, hi)} log-uniform priors in SI units (default: the
    fit's default grid ranges, the yield strength's up to the theoretical 0.2 E_soft). The
    likelihood is K13 (31)'s residuals as Gaussian errors: with
    ``cor_error`` their sigmas, without one sigma marginalised (Jeffreys' prior). ``walkers``
    (default 8 per parameter, at least 16, even) run ``steps`` moves (default 1500) of emcee's
    stretch move in log10 of the parameters; ``seed`` makes the run reproducible whatever
    ``threads`` (0: every core) evaluates the ensemble's likelihoods in C++ (Ctrl-C interrupts).

    Returns a dict: ``samples`` (n x p, SI, burn-in of twice the largest autocorrelation time
    removed, thinned by half the smallest), ``names``, ``median``, ``credible_68`` and
    ``credible_95`` ({name: [lo, hi]}, central intervals), ``acceptance_fraction`` (the mean),
    ``autocorrelation_time`` ({name: steps}), ``walkers``, ``steps``, ``burn_in``, ``thin``,
    ``log_likelihood`` (of each sample) and ``warnings`` (a chain short against its
    autocorrelation time, a parameter the data do not constrain, walkers at a prior's edge).
    """
    import emcee  # Debian's python3-emcee

    fit_names = fit
    likelihood = b._likelihood(pair, model, velocity, cor, cor_error=cor_error, data=data, fit=fit_names)
    names = list(likelihood.names)
    grid = _grid(priors, names, list(likelihood.ranges))
    if grid is not None:  # the priors, checked by the fit's rules for its grids
        likelihood = b._likelihood(pair, model, velocity, cor, cor_error=cor_error, data=data, fit=fit_names,
                                   grid=grid)
    ndim = len(names)
    walkers = _whole("walkers", walkers, 2 * ndim) if walkers is not None else max(16, 8 * ndim)
    if walkers % 2:
        raise _invalid("walkers", walkers, "an even number (emcee's stretch move updates half the ensemble at a time)")
    steps = _whole("steps", steps, 10) if steps is not None else DEFAULT_STEPS
    seed = _whole("seed", seed, 0)
    threads = _whole("threads", threads, 0)
    if not isinstance(progress, bool):
        raise TypeError(f"progress = {progress!r} is invalid: expected True or False")
    lo, hi = (np.log10(np.array([r[k] for r in likelihood.ranges])) for k in (0, 1))

    def log_probability(x: np.ndarray) -> np.ndarray:
        inside = np.all((x >= lo) & (x <= hi), axis=1)
        out = np.full(x.shape[0], -np.inf)
        if np.any(inside):
            out[inside] = likelihood.evaluate(10.0 ** x[inside], threads)
        return out

    rng = np.random.default_rng(seed)
    start = _start(likelihood, lo, hi, walkers, rng, threads)
    sampler = emcee.EnsembleSampler(walkers, ndim, log_probability, vectorize=True)
    sampler.random_state = np.random.RandomState(seed).get_state()
    last = time.monotonic()
    for i, _ in enumerate(sampler.sample(start, iterations=steps), start=1):
        if progress and (time.monotonic() - last >= 1.0 or i == steps):
            last = time.monotonic()
            print(f"bounce.posterior: {i}/{steps} steps ({100 * i / steps:.0f}%)", file=sys.stderr, flush=True)
    tau = np.asarray(sampler.get_autocorr_time(tol=0), float)
    burn = min(int(2 * np.nanmax(tau)) if np.all(np.isfinite(tau)) else steps // 2, steps // 2)
    thin = max(1, int(0.5 * np.nanmin(tau)) if np.all(np.isfinite(tau)) else 1)
    x = sampler.get_chain(discard=burn, thin=thin, flat=True)
    samples = 10.0 ** x
    acceptance = float(np.mean(sampler.acceptance_fraction))
    interval = {p: {n: [float(v) for v in np.percentile(samples[:, i], [50 - p / 2, 50 + p / 2])]
                    for i, n in enumerate(names)} for p in (68, 95)}
    return {
        "names": names,
        "samples": samples,
        "log_likelihood": sampler.get_log_prob(discard=burn, thin=thin, flat=True),
        "median": {n: float(np.median(samples[:, i])) for i, n in enumerate(names)},
        "credible_68": interval[68],
        "credible_95": interval[95],
        "acceptance_fraction": acceptance,
        "autocorrelation_time": {n: float(t) for n, t in zip(names, tau)},
        "walkers": walkers,
        "steps": steps,
        "burn_in": burn,
        "thin": thin,
        "prior": {n: [float(10 ** lo[i]), float(10 ** hi[i])] for i, n in enumerate(names)},
        "weighted": bool(likelihood.weighted),
        "warnings": _warnings(names, x, lo, hi, tau, steps, acceptance),
    }
