#!/usr/bin/python3
"""Direct integration and master curve of bounce against scipy's solve_ivp (DOP853).

Runs bench_viscoelastic (Google Benchmark, JSON) and a scipy implementation of the
same scaled equation, BP04 (8.67): x'' + (5/4) x^{3/2} + kappa sqrt(x) x' = 0,
x(0) = 0, x'(0) = 1, with the same event definitions, in one process run, and
prints the ratios as a Markdown table (recorded in docs/benchmarks.md).

scipy's tolerances are chosen so that its error against the master curve is at
least as small as bounce's (equal accuracy); each error is measured, not assumed.
"""
import json
import math
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

KAPPAS = [0.01, 0.3, 3.0]


def scipy_collision(kappa: float, rule: str, tol: float):
    def rhs(t, y):
        s = math.sqrt(max(y[0], 0.0))
        return [y[1], -1.25 * y[0] * s - kappa * s * y[1]]

    def end(t, y):  # overlap rule: x falls through 0; force rule: F = 0
        return y[0] if rule == "overlap" else 1.25 * y[0] + kappa * y[1]

    end.terminal = True
    end.direction = -1
    sol = solve_ivp(rhs, (0.0, 1e6), [0.0, 1.0], method="DOP853", rtol=tol, atol=tol,
                    events=end, first_step=1e-3)
    return -sol.y_events[0][0][1]


def time_scipy(kappa, rule, tol, repeats=5):
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        e = scipy_collision(kappa, rule, tol)
        best = min(best, time.perf_counter() - start)
    return best, e


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    raw = subprocess.run([f"{build}/bin/bench_viscoelastic", "--benchmark_format=json",
                          "--benchmark_min_time=0.2"], capture_output=True, text=True, check=True).stdout
    runs = json.loads(raw)["benchmarks"]
    master_ns = {r["name"].split("/")[1]: r["cpu_time"] for r in runs if r["name"].startswith("master")}
    rows = []
    for r in runs:
        if not r["name"].startswith("integrate"):
            continue
        rule = r["name"].split("/")[1]
        kappa = r["kappa"]
        ours_s = r["cpu_time"] * 1e-6
        ours_err = r["error"]
        # The reference: the master curve value, through bounce's own CLI-free path.
        exact = float(subprocess.run([f"{build}/bin/bench_viscoelastic_exact", str(kappa), rule],
                                     capture_output=True, text=True, check=True).stdout)
        for tol in (1e-11, 1e-12, 1e-13, 1e-14):
            scipy_s, e = time_scipy(kappa, rule, tol)
            if abs(e - exact) <= max(ours_err, 1e-13):
                break
        rows.append((rule, kappa, ours_s, ours_err, int(r["steps"]), tol, scipy_s, abs(e - exact)))
    print("| end rule | kappa | bounce integrate | its error | scipy DOP853 (tol) | its error | speed-up |")
    print("|---|---|---|---|---|---|---|")
    for rule, kappa, ours_s, ours_err, steps, tol, scipy_s, scipy_err in rows:
        print(f"| {rule} | {kappa:g} | {ours_s * 1e6:.1f} us ({steps} steps) | {ours_err:.1e} | "
              f"{scipy_s * 1e3:.1f} ms ({tol:g}) | {scipy_err:.1e} | {scipy_s / ours_s:.0f}x |")
    print()
    scipy_typical = np.median([row[6] for row in rows])
    print("| master curve | time per evaluation | speed-up over scipy (median collision) |")
    print("|---|---|---|")
    for rule, ns in master_ns.items():
        print(f"| {rule} | {ns:.1f} ns | {scipy_typical / (ns * 1e-9):.1e}x |")


if __name__ == "__main__":
    main()
