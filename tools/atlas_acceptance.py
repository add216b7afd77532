#!/usr/bin/python3
"""The atlas's acceptance check (docs/atlas.md, "Measured"): for each model, an atlas of water
ice over R_eff 0.1 um - 1 mm and 0.01 - 100 m/s at T_vis = 1e-11 s, tol 1e-4, is built with the
CLI (timed, on every core), then compared with direct collisions (bounce.collide) at random
points (R1, R2, v) and with bisections of the sticking velocity (bounce.sticking_velocity,
1e-10) at random pairs:

  |eps_atlas - eps_collide| <= the stored error everywhere;
  stick/bounce agree outside the stored v_stick band |v/v_stick - 1| <= errors/v_stick;
  v_stick within 1e-6 relative of the bisection (where v_stick lies inside the speeds).

    PYTHONPATH=build/python /usr/bin/python3 tools/atlas_acceptance.py BUILD [POINTS] [PAIRS] [MODEL ...]

Prints one line per model and a JSON summary; exit 1 when a check fails. `make check-long`
runs it (CTest label long); ~5 minutes on 2 cores.
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import bounce
import bounce.atlas

MODELS = {"krijt": ["--tvis", "1e-11"], "viscoelastic": ["--tvis", "1e-11"], "maugis-viscoelastic": ["--tvis", "1e-11"]}
RANGE = ["--materials", "water-ice", "--radius", "1e-7:1e-3:9", "--velocity", "0.01:100:9", "--tol", "1e-4"]


def random_pair(rng, lo, hi):
    """Radii of two ice grains (or a grain and a wall, one time in eight) with R_eff in [lo, hi]."""
    while True:
        r1 = lo * (hi / lo * 4) ** rng.uniform()
        r2 = math.inf if rng.uniform() < 0.125 else r1 * 10 ** rng.uniform(-2, 2)
        r = r1 if math.isinf(r2) else r1 * r2 / (r1 + r2)
        if lo <= r <= hi:
            return r1, r2


def pair_of(r1, r2):
    if math.isinf(r2):
        return bounce.Pair(material="water-ice", radius=r1, wall=True)
    return bounce.Pair(material="water-ice", radius=r1, radius2=r2)


def check(cli, name, args, points, pairs, folder):
    path = os.path.join(folder, f"{name}.h5")
    start = time.monotonic()
    subprocess.run([cli, "atlas", "build", "--model", name, *args, *RANGE, "-o", path], check=True,
                   capture_output=True)
    build = time.monotonic() - start
    atlas = bounce.atlas.open(path, model=name)
    model = bounce.Model(name, tvis=1e-11)
    rng = np.random.default_rng(2026)
    lo, hi = atlas.radius_range
    v_lo, v_hi = atlas.velocity_range
    worst, outside_band, in_band = 0.0, 0, 0
    for _ in range(points):
        r1, r2 = random_pair(rng, lo, hi)
        v = math.exp(rng.uniform(math.log(v_lo), math.log(v_hi)))
        direct = bounce.collide(pair_of(r1, r2), model, v)
        stick = direct["outcome"] == "stick"
        if stick != bool(atlas.sticks(r1, r2, v)):
            vs = atlas.v_stick(r1, r2)
            if abs(v / vs - 1) <= atlas.v_stick_error:
                in_band += 1
            else:
                outside_band += 1
            continue
        worst = max(worst, abs(atlas.cor(r1, r2, v) - (0.0 if stick else direct["cor"])))
    vs_worst, vs_count = 0.0, 0
    if atlas.describe()["body1"].get("gamma") and name != "viscoelastic":
        for _ in range(pairs):
            r1, r2 = random_pair(rng, lo, hi)
            direct = bounce.sticking_velocity(pair_of(r1, r2), model, 1e-10)
            if direct is None or direct > v_hi:
                continue
            vs_worst = max(vs_worst, abs(atlas.v_stick(r1, r2) / direct - 1))
            vs_count += 1
    ok = worst <= atlas.cor_error and outside_band == 0 and vs_worst <= 1e-6
    return ok, {"model": name, "build_seconds": round(build, 1), "grid": atlas.describe()["grid"],
                "cor_error_stated": atlas.cor_error, "cor_error_found": worst, "points": points,
                "outcome_differs_in_band": in_band, "outcome_differs_outside_band": outside_band,
                "v_stick_error_stated": atlas.v_stick_error, "v_stick_error_found": vs_worst,
                "v_stick_pairs": vs_count}


def main(argv):
    if len(argv) < 2 or not os.path.isfile(os.path.join(argv[1], "bin", "bounce")):
        print("usage: atlas_acceptance.py BUILD [POINTS] [PAIRS] [MODEL ...] (BUILD/bin/bounce must exist)",
              file=sys.stderr)
        return 2
    cli = os.path.join(argv[1], "bin", "bounce")
    points = int(argv[2]) if len(argv) > 2 else 1000
    pairs = int(argv[3]) if len(argv) > 3 else 60
    names = argv[4:] or list(MODELS)
    results, failed = [], False
    with tempfile.TemporaryDirectory() as folder:
        for name in names:
            ok, r = check(cli, name, MODELS[name], points, pairs, folder)
            failed |= not ok
            results.append(r)
            print(f"{name}: {'ok' if ok else 'FAILED'} {json.dumps(r)}", flush=True)
    print(json.dumps(results, indent=1))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
