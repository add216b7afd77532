#!/usr/bin/python3
"""Python lookups of the collision atlas (docs/atlas.md) side by side with the collisions they
replace, on one core: eps at N random (R1, R2, v) of 1-10 um ice grains (krijt, T_vis = 1e-11 s),
vectorised (one call, numpy arrays), against bounce.collide at a sample of the same points.

    PYTHONPATH=build/python /usr/bin/python3 bench/atlas_python.py BUILD [N]

Prints pairs per second of each and their ratio (docs/benchmarks.md). The atlas is built with
one thread into a temporary folder (about 10 s).
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import bounce
import bounce.atlas


def main(argv):
    if len(argv) < 2 or not os.path.isfile(os.path.join(argv[1], "bin", "bounce")):
        print("usage: atlas_python.py BUILD [N] (BUILD/bin/bounce must exist)", file=sys.stderr)
        return 2
    n = int(argv[2]) if len(argv) > 2 else 2_000_000
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "ice.h5")
        subprocess.run([os.path.join(argv[1], "bin", "bounce"), "atlas", "build", "--model", "krijt", "--tvis", "1e-11",
                        "--materials", "water-ice", "--radius", "1e-6:1e-5:4", "--velocity", "0.3:20:5", "--tol", "1e-3",
                        "--threads", "1", "-o", path], check=True, capture_output=True)
        atlas = bounce.atlas.open(path, model="krijt")
        rng = np.random.default_rng(1)
        r1, r2 = 2e-6 * 5.0 ** rng.uniform(size=(2, n))
        v = 0.3 * (20 / 0.3) ** rng.uniform(size=n)
        best = np.inf
        for _ in range(5):
            start = time.perf_counter()
            atlas.cor(r1, r2, v)
            best = min(best, time.perf_counter() - start)
        lookups = n / best
        model = bounce.Model("krijt", tvis=1e-11)
        sample = 200
        start = time.perf_counter()
        for i in range(sample):
            bounce.collide(bounce.Pair(material="water-ice", radius=r1[i], radius2=r2[i]), model, v[i])
        collisions = sample / (time.perf_counter() - start)
    print(f"atlas.cor, vectorised: {lookups:.3g} pairs/s ({1e9 / lookups:.1f} ns a pair, best of 5 over {n})")
    print(f"bounce.collide:        {collisions:.3g} pairs/s ({1e3 / collisions:.3f} ms a pair, {sample} pairs)")
    print(f"ratio: {lookups / collisions:.3g}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
