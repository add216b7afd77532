"""Writes the synthetic restitution data of data/experiments/ (docs/fitting.md): bounce's own
model at stated parameters, sampled at stated speeds, plus Gaussian noise of a stated sigma
(Python's random.gauss with a stated seed), clipped to 0 <= e <= 1; a model e of 0 (the
grains stick) stays 0, an observed sticking collision. Not measurements: every file says so
in its header, with this command.

    /usr/bin/python3 tools/make_synthetic_data.py build/bin/bounce data/experiments
"""
import random
import subprocess
import sys
from pathlib import Path

# name: (pair and model options, speeds LO:HI:N, log spacing, sigma, seed, what it is)
SETS = {
    "synthetic-psl-quartz": (
        ["--material", "psl", "--radius", "0.635e-6", "--wall", "--material2", "quartz", "--model", "krijt",
         "--tvis", "3e-12", "--gamma", "0.05", "--gamma2", "0.05", "--yield", "2e8"],
        "1:15:30", False, 0.02, 3, "K13 Table 1 has PSL (1.27 um) on quartz at 2-15 m/s"),
    "synthetic-agglass-steel": (
        ["--material", "ag-coated-glass", "--radius", "4.3e-6", "--wall", "--material2", "steel", "--model", "krijt",
         "--tvis", "2e-11", "--gamma", "0.8", "--gamma2", "0.8", "--yield", "1e9"],
        "0.3:20:25", True, 0.01, 5, "K13 Table 1 has Ag-coated glass (8.6 um) on steel at 2-20 m/s; here "
                                    "from 0.3 m/s, with a sticking branch"),
    "synthetic-acrylic-spheres": (
        ["--material", "acrylic", "--radius", "1.98e-3", "--model", "krijt", "--tvis", "1e-9", "--gamma", "0.02",
         "--yield", "5e7"],
        "0.1:1:20", False, 0.03, 7, "K13 Table 1 has acrylic spheres (3.96 mm) on each other at 0.1-1 m/s"),
}


def main() -> None:
    cli, out = sys.argv[1], Path(sys.argv[2])
    for name, (options, speeds, log, sigma, seed, what) in SETS.items():
        command = [cli, "curve", *options, "--velocities", speeds, *(["--log"] if log else []), "--csv"]
        rows = [line.split(",")[:2] for line in subprocess.run(command, check=True, capture_output=True,
                                                                text=True).stdout.splitlines()[1:]]
        rng = random.Random(seed)
        shown = " ".join(["bounce", *command[1:]])
        lines = [f"# Synthetic, not measured: {shown}",
                 f"# plus Gaussian noise of sigma {sigma} (Python random.Random({seed}).gauss), clipped to [0, 1];",
                 f"# a model e of 0 (sticking) stays 0. {what}. Written by tools/make_synthetic_data.py.",
                 "velocity,cor,cor_error"]
        for v, e in rows:
            e = float(e)
            noisy = 0.0 if e == 0.0 else min(1.0, max(0.0, e + rng.gauss(0.0, sigma)))
            lines.append(f"{v},{noisy:.4f},{sigma}")
        (out / f"{name}.csv").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
