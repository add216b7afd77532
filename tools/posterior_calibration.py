"""Calibration of bounce.posterior (docs/fitting.md, "Posteriors"; opt-in: `make check-posterior`).

A Bayesian interval is calibrated when, over data sets whose true parameters are drawn from the
prior and whose noise is the one the likelihood assumes, the 68 % (95 %) interval holds the truth
in 68 % (95 %) of the sets (simulation-based calibration; Cook, Gelman & Rubin 2006, Talts et al.
2018). Each set here: acrylic spheres (R = 1.98 mm, K13 Table 2) with the viscoelastic law plus
K13's plasticity (28)-(30), true (A, Y) log-uniform in the prior below, 15 speeds from 0.1 to
3 m/s, Gaussian noise of sigma = 0.01 given as the data's errors. Each set is sampled by
bounce.posterior (its default walkers and steps) and fitted by bounce.fit over the prior's box
(K13's factor-2 ranges, chi^2 <= 2 chi^2_min, and the Delta chi^2 = 1 intervals), and the rate
at which each interval holds the truth is printed with its binomial standard error
sqrt(p (1 - p) / n).

    /usr/bin/python3 tools/posterior_calibration.py [SETS] [SEED]     (default 100 sets, seed 1)

With PYTHONPATH pointing at build/python. Exits 1 when a posterior rate is more than three
standard errors from its nominal value.
"""
import math
import sys
import time

import numpy as np

import bounce

PAIR = bounce.Pair(material="acrylic", radius=1.98e-3)
PRIOR = {"A": (3e-7, 3e-6), "yield": (5e7, 5e8)}
SPEEDS = np.geomspace(0.1, 3.0, 15)
SIGMA = 0.01
#: The posterior's warnings, by a phrase of each.
WARNINGS = {"autocorrelation": "chain short against tau", "not constrained": "unconstrained", "edge": "prior edge",
            "acceptance": "acceptance"}


def draw(rng):
    """True values log-uniform in the prior and data with Gaussian noise; a set whose noisy COR
    leaves [0, 1] (a clipped point would break the Gaussian likelihood) is drawn again."""
    while True:
        truth = {k: float(10 ** rng.uniform(math.log10(lo), math.log10(hi))) for k, (lo, hi) in PRIOR.items()}
        exact = bounce.curve(PAIR, bounce.Model("viscoelastic", **truth), SPEEDS)["cor"]
        cor = exact + SIGMA * rng.standard_normal(SPEEDS.size)
        if np.all(exact > 0) and np.all((cor >= 0) & (cor <= 1)):
            return truth, cor


def inside(interval, x):
    lo, hi = interval
    return (lo is None or lo <= x) and (hi is None or x <= hi)


def main():
    sets = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    rng = np.random.default_rng(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
    kinds = ("credible_68", "credible_95", "factor-2 range", "delta chi2 = 1")
    hits = {(k, n): 0 for k in kinds for n in PRIOR}
    warned, kinds_warned, start = 0, {}, time.monotonic()
    for i in range(sets):
        truth, cor = draw(rng)
        errors = np.full(SPEEDS.size, SIGMA)
        post = bounce.posterior(PAIR, bounce.Model("viscoelastic"), SPEEDS, cor, cor_error=errors,
                                fit=list(PRIOR), priors=PRIOR, seed=i)
        fit = bounce.fit(PAIR, bounce.Model("viscoelastic"), SPEEDS, cor, cor_error=errors, fit=list(PRIOR),
                         grid={k: (lo, hi, 30) for k, (lo, hi) in PRIOR.items()})
        warned += bool(post["warnings"])
        for w in post["warnings"]:
            kind = next((k for k in WARNINGS if k in w), "other")
            kinds_warned[kind] = kinds_warned.get(kind, 0) + 1
        for n, x in truth.items():
            hits["credible_68", n] += inside(post["credible_68"][n], x)
            hits["credible_95", n] += inside(post["credible_95"][n], x)
            hits["factor-2 range", n] += inside(fit["ranges"][n], x)
            hits["delta chi2 = 1", n] += inside(fit["intervals"][n], x)
        print(f"set {i + 1}/{sets}: truth " + ", ".join(f"{n} = {x:.3g}" for n, x in truth.items())
              + f"; {time.monotonic() - start:.0f} s", file=sys.stderr, flush=True)
    print(f"{sets} data sets, {warned} with a sampler warning ("
          + ", ".join(f"{WARNINGS.get(k, k)}: {n}" for k, n in sorted(kinds_warned.items())) + f"); {time.monotonic() - start:.0f} s")
    print("| interval | " + " | ".join(PRIOR) + " |")
    print("|---|" + "---|" * len(PRIOR))
    failed = False
    for k in kinds:
        cells = []
        for n in PRIOR:
            p = hits[k, n] / sets
            cells.append(f"{100 * p:.0f} % ± {100 * math.sqrt(max(p * (1 - p), 1e-12) / sets):.0f} %")
            nominal = {"credible_68": 0.68, "credible_95": 0.95}.get(k)
            if nominal is not None and abs(p - nominal) > 3 * math.sqrt(nominal * (1 - nominal) / sets):
                failed = True
        print(f"| {k} | " + " | ".join(cells) + " |")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
