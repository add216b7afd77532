#!/usr/bin/python3
"""Direct integration and master curve of bounce against scipy's solve_ivp (DOP853).

Runs bench_viscoelastic (Google Benchmark, JSON) and a scipy implementation of the
same scaled equation, BP04 (8.67): x'' + (5/4) x^{3/2} + kappa sqrt(x) x' = 0,
x(0) = 0, x'(0) = 1, with the same event definitions, in one process run, and
prints the ratios as a Markdown table (recorded in docs/benchmarks.md).

`viscoelastic_vs_scipy.py BUILD whole-process` times what a user runs instead: the CLI's
400-speed curve (issue 40, point 24) as a whole process, against a whole Python process that
imports scipy and integrates the same 400 speeds with DOP853 (the dimensional equation of BP04
(8.42), each speed's tolerances scaled to its xi0 and g), both curves compared; and the CLI's
start alone (`bounce --version`), the part of the process that is not the curve.

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


CURVE = ["curve", "--model", "viscoelastic", "--method", "integrate", "--A", "4.9e-6", "--E", "1e10", "--nu", "0.3",
         "--density", "1000", "--radius", "0.01", "--velocities", "0.1:10:400", "--log", "--csv"]
# The same pair and speeds in scipy: identical spheres, E* = E / (2 (1 - nu^2)), C0 = (4/3) E* sqrt(R_eff).
SCIPY_CURVE = r"""
import math, sys
import numpy as np
from scipy.integrate import solve_ivp
E, NU, RHO, R, A = 1e10, 0.3, 1000.0, 0.01, 4.9e-6
e_star, r_eff, m = E / (2 * (1 - NU * NU)), R / 2, 4 / 3 * math.pi * R ** 3 * RHO / 2
k = 4 / 3 * e_star * math.sqrt(r_eff) / m
def rhs(t, y):
    s = math.sqrt(max(y[0], 0.0))
    return [y[1], -k * (y[0] * s + 1.5 * A * s * y[1])]
def end(t, y):
    return y[0]
end.terminal, end.direction = True, -1
for g in np.geomspace(0.1, 10, 400):
    xi0 = (5 * g * g / (4 * k)) ** 0.4
    sol = solve_ivp(rhs, (0.0, 1e3), [0.0, g], method="DOP853", rtol=1e-12, atol=[1e-12 * xi0, 1e-12 * g], events=end,
                    first_step=1e-3 * xi0 / g)
    print(f"{g!r},{-sol.y_events[0][0][1] / g!r}")
"""


def median_wall(command, repeats):
    """Median wall time of the process with its output discarded (as `> /dev/null`), and its output."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        times.append(time.perf_counter() - start)
    return float(np.median(times)), subprocess.run(command, capture_output=True, text=True, check=True).stdout


def whole_process(build):
    cli = f"{build}/bin/bounce"
    ours, csv = median_wall([cli, *CURVE], 41)
    start, _ = median_wall([cli, "--version"], 41)
    theirs, text = median_wall([sys.executable, "-c", SCIPY_CURVE], 3)
    ours_e = [float(line.split(",")[1]) for line in csv.splitlines()[1:]]
    their_e = [float(line.split(",")[1]) for line in text.splitlines()]
    difference = max(abs(a - b) for a, b in zip(ours_e, their_e))
    print("| whole process, 400 speeds | bounce curve | of it, the start (`--version`) | python + scipy DOP853 | "
          "largest difference of e | ratio |")
    print("|---|---|---|---|---|---|")
    print(f"| viscoelastic, A = 4.9e-6 s, 0.1-10 m/s | {ours * 1e3:.1f} ms | {start * 1e3:.1f} ms | "
          f"{theirs * 1e3:.0f} ms | {difference:.1e} | {theirs / ours:.0f}x |")


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[2] == "whole-process":
        whole_process(sys.argv[1])
    else:
        main()
