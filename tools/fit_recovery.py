"""Synthetic recovery of `bounce fit` (docs/fitting.md; `make check-long`): data from K13's
model at random true (gamma, T_vis, Y), with Gaussian noise of sigma = 0.01 and 0.03, 20-40
points, on three pairs (sphere-wall micrometre grains, one with a sticking branch, and
millimetre spheres); each fitted with K13's method. Records how often the true values lie
inside the reported factor-2 ranges (all three at once, and each), and checks that the
refined minimum is never above the grid's. Fails below 90 %.

    /usr/bin/python3 tools/fit_recovery.py build/bin/bounce [CASES_PER_NOISE]
"""
import json
import math
import random
import subprocess
import sys
import tempfile
from pathlib import Path

# name: (body options, truths' ranges (gamma [J/m^2], T_vis [s], Y [Pa]), speeds [m/s], log spacing, grids)
PAIRS = {
    "psl-quartz": (["--material", "psl", "--radius", "0.635e-6", "--wall", "--material2", "quartz"],
                   ((0.02, 0.1), (1e-12, 1e-11), (1e8, 5e8)), (1.0, 15.0), False,
                   "gamma=0.0025:2.5:30,tvis=1e-15:1e-8:30,yield=3.4e5:3.4e9:60"),
    "agglass-steel (sticking branch)": (
        ["--material", "ag-coated-glass", "--radius", "4.3e-6", "--wall", "--material2", "steel"],
        ((0.4, 1.6), (5e-12, 5e-11), (5e8, 2e9)), (0.3, 20.0), True,
        "gamma=0.06:60:30,tvis=1e-15:1e-8:30,yield=7.2e6:7.2e10:60"),
    "acrylic spheres": (["--material", "acrylic", "--radius", "1.98e-3"],
                        ((0.01, 0.04), (3e-10, 3e-9), (2e7, 1e8)), (0.1, 1.0), False,
                        "gamma=0.002:2:30,tvis=1e-15:1e-8:30,yield=3e5:3e9:60"),
}


def log_uniform(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def one_case(cli, rng, sigma, directory):
    name = rng.choice(sorted(PAIRS))
    body, truths, (v_lo, v_hi), log, grid = PAIRS[name]
    gamma, tvis, y = (log_uniform(rng, lo, hi) for lo, hi in truths)
    n = rng.randint(20, 40)
    model = ["--model", "krijt", "--tvis", repr(tvis), "--gamma", repr(gamma), "--gamma2", repr(gamma), "--yield",
             repr(y)]
    rows = subprocess.run([cli, "curve", *body, *model, "--velocities", f"{v_lo}:{v_hi}:{n}",
                           *(["--log"] if log else []), "--csv"], check=True, capture_output=True,
                          text=True).stdout.splitlines()[1:]
    lines = ["velocity,cor"]  # K13's ranges need no errors (and the Delta chi^2 = 1 intervals would double the cost)
    for row in rows:
        v, e = row.split(",")[:2]
        e = float(e)
        noisy = 0.0 if e == 0.0 else min(1.0, max(0.0, e + rng.gauss(0.0, sigma)))
        lines.append(f"{v},{noisy:.5f}")
    data = Path(directory) / "case.csv"
    data.write_text("\n".join(lines) + "\n")
    fit = json.loads(subprocess.run([cli, "fit", "--data", str(data), *body, "--grid", grid, "--json"], check=True,
                                    capture_output=True, text=True).stdout)
    inside = {}
    for key, truth in (("gamma", gamma), ("tvis", tvis), ("yield", y)):
        lo, hi = fit["ranges"][key]
        inside[key] = (lo is None or lo <= truth) and (hi is None or truth <= hi)
    return name, inside, fit["chi2"] <= fit["grid_chi2"], sum(1 for l in lines[1:] if l.split(",")[1] == "0.00000")


def main():
    cli = sys.argv[1]
    cases = int(sys.argv[2]) if len(sys.argv) > 2 else 50
    failed = False
    with tempfile.TemporaryDirectory() as directory:
        for sigma, seed in ((0.01, 2026), (0.03, 2027)):
            rng = random.Random(seed)
            all_inside, each, lower, sticking = 0, {"gamma": 0, "tvis": 0, "yield": 0}, 0, 0
            for _ in range(cases):
                name, inside, refined_lower, stuck = one_case(cli, rng, sigma, directory)
                all_inside += all(inside.values())
                for key in each:
                    each[key] += inside[key]
                lower += refined_lower
                sticking += stuck > 0
                if not all(inside.values()):
                    print(f"  sigma {sigma}: {name}: outside for {[k for k, v in inside.items() if not v]}", flush=True)
            rate = all_inside / cases
            print(f"sigma = {sigma}: {cases} cases ({sticking} with observed sticking): all three true values inside "
                  f"the ranges in {100 * rate:.0f} %; gamma {100 * each['gamma'] / cases:.0f} %, T_vis "
                  f"{100 * each['tvis'] / cases:.0f} %, Y {100 * each['yield'] / cases:.0f} %; refined minimum <= "
                  f"grid minimum in {lower}/{cases}", flush=True)
            failed |= rate < 0.9 or lower < cases
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
