"""`bounce fit` speed (docs/benchmarks.md): K13's grid of 60 gamma x 60 T_vis x 100 Y against
30 data points, the whole CLI process, with 1 and 2 threads; beside it the reference, the same
collisions run as single `bounce collide` calls in one `bounce curve` process (the cost of one
collision outside the fitter).

    /usr/bin/python3 bench/fit_speed.py [BUILD_DIR]
"""
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build")
BOUNCE = os.path.join(BUILD, "bin", "bounce")
DATA = os.path.join(ROOT, "data", "experiments", "synthetic-psl-quartz.csv")
PAIR = ["--material", "psl", "--radius", "0.635e-6", "--wall", "--material2", "quartz"]


def timed(args):
    start = time.perf_counter()
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return time.perf_counter() - start, out


def main():
    print(f"K13 grid 60 x 60 x 100 against {DATA} (30 points), whole process:")
    results = {}
    for threads in (1, 2):
        seconds, out = timed([BOUNCE, "fit", "--data", DATA, *PAIR, "--threads", str(threads), "--timing", "--json"])
        fit = json.loads(out)
        results[threads] = (seconds, fit)
        t = fit["timing"]
        print(f"  {threads} thread(s): {seconds:6.2f} s wall; grid collisions {t['grid_collisions']:.2f} s "
              f"({fit['collisions']} collisions in all), e_P table {t['plastic'] * 1e3:.2f} ms, "
              f"chi2 {t['chi2'] * 1e3:.1f} ms, refinement {t['refinement']:.2f} s; "
              f"{t['cost_per_collision'] * 1e6:.0f} us CPU per grid collision")
    same = {k: v for k, v in results[1][1].items() if k != "timing"} == \
           {k: v for k, v in results[2][1].items() if k != "timing"}
    print(f"  results identical for 1 and 2 threads: {same}")
    print(f"  speed-up with 2 threads: {results[1][0] / results[2][0]:.2f}x")
    # The reference: one collision at a time, as `bounce curve` runs them (tolerance 1e-5, the
    # fit's default), at the best fit's T_vis and gamma over the data's 30 speeds, 20 times.
    best = results[2][1]["best"]
    args = [BOUNCE, "curve", *PAIR, "--model", "krijt", "--tvis", repr(best["tvis"]), "--gamma", repr(best["gamma"]),
            "--gamma2", repr(best["gamma"]), "--adhesive-tolerance", "1e-5", "--velocities", "1:15:600", "--csv"]
    seconds, _ = timed(args)
    print(f"  reference: 600 collisions in one `bounce curve` process: {seconds / 600 * 1e6:.0f} us per collision "
          f"(process start included)")


if __name__ == "__main__":
    main()
