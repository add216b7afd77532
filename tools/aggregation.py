#!/usr/bin/python3
"""Aggregation of sticky ice grains in LAMMPS with K13's contact law (docs/lammps.md, Aggregation;
`make lammps-demo`).

A cloud of micrometre water-ice grains (K13 table 2: R = 1 um, E = 7 GPa, nu = 0.25,
gamma = 0.37 J/m^2, density 1000 kg/m^3) in a periodic box at volume fraction PHI, with Gaussian
velocities of rms SPEED: their mean relative speed at contact is near the sticking velocity. The
same cloud runs twice on 2 MPI ranks, frictionless, with its energy budget recorded
(ke + pe + compute pair bounce's crack- and bulk-dissipated energy against its start):

* viscoelastic: `krijt` with T_vis = 1e-12 s (sticking velocity 1.87 m/s, `bounce sticking`);
* elastic JKR: `krijt` with T_vis = 1e-16 s, its T_vis -> 0 limit: an instantaneous crack and
  no bulk force, so that the only loss is the JKR hysteresis (sticking velocity 1.47 m/s).

Grains closer than 2R + 10 nm (in contact: a stuck pair sits at a positive overlap, and a neck
holds at most 37 nm beyond touching) are one aggregate (LAMMPS's compute cluster/atom); every
grain is in one, monomers being aggregates of one. Recorded against time: the number of
aggregates and the mass of the largest, in grain masses; and snapshots of both clouds when the
viscoelastic one's largest aggregate first holds N/8 grains, coloured by the size of each grain's
aggregate. The time
step is t_H/100 at the mean relative speed (K13's Hertz time (22)).

    /usr/bin/python3 tools/aggregation.py [--build build] [--out out] [--quick]
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "lammps"))
import lammps_runs  # noqa: E402

RADIUS, DENSITY, PHI, SPEED, CELLS = 1e-6, 1000.0, 0.15, 1.5, 16
N = CELLS ** 3
MASS = 4.0 / 3.0 * math.pi * RADIUS ** 3 * DENSITY
CUTOFF = 2.0 * RADIUS + 1e-8
LAWS = {"viscoelastic": 1e-12, "elastic JKR": 1e-16}  # T_vis [s]
STEPS = 100000


def collision_time(cli):
    """t_H/100 at the mean relative speed of a Maxwellian gas, 4 sqrt(T / (pi m)), (3/2) T = m <v^2> / 2."""
    mean_relative = 4.0 * math.sqrt(SPEED ** 2 / (3.0 * math.pi))
    out = subprocess.run([cli, "collide", "--model", "krijt", "--material", "water-ice", "--radius", str(RADIUS),
                          "--tvis", "1e-12", "--velocity", str(mean_relative), "--json"],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)["closed_forms"]["hertz_time_k13_22"], mean_relative


def sticking_velocity(cli, tvis):
    out = subprocess.run([cli, "sticking", "--model", "krijt", "--material", "water-ice", "--radius", str(RADIUS),
                          "--tvis", str(tvis), "--json"], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)["sticking_velocity"]


def script(tvis, dt, steps, every):
    """The cloud (lammps_runs.gas_script), with its aggregates dumped every `every` steps and
    its energy budget in thermo: ke + pe + crack- + bulk-dissipated energy."""
    extra = f"""compute cl all cluster/atom {CUTOFF!r}
compute e all pair bounce
thermo_style custom step ke pe c_e[1] c_e[2]
thermo_modify format float %.10g norm no
dump clusters all custom {every} clusters.dump id x y z c_cl
dump_modify clusters sort id"""
    return lammps_runs.gas_script(f"krijt material water-ice tvis {tvis!r}", cells=CELLS, radius=RADIUS,
                                  density=DENSITY, phi=PHI, speed=SPEED, dt=dt, steps=steps, seed=8191,
                                  thermo=every, extra=extra)


def read_clusters(path):
    """[(step, box length, [x y z cluster] per grain)] of a dump of id x y z c_cl."""
    frames, lines = [], open(path).read().splitlines()
    i = 0
    while i < len(lines):
        step = int(lines[i + 1])
        count = int(lines[i + 3])
        low, high = (float(v) for v in lines[i + 5].split())
        atoms = np.array([[float(v) for v in line.split()[1:]] for line in lines[i + 9:i + 9 + count]])
        frames.append((step, high - low, atoms))
        i += 9 + count
    return frames


def run(name, tvis, dt, steps, every, cores):
    started = time.time()
    print(f"aggregation: {name}: {steps} steps of {dt:.3g} s, {N} grains, {cores} ranks ...", flush=True)
    with tempfile.TemporaryDirectory() as work:
        try:
            log = lammps_runs.run_in(work, script(tvis, dt, steps, every), cores, "in.aggregation")
        except RuntimeError as e:
            sys.exit(f"aggregation: {e}")
        frames = read_clusters(os.path.join(work, "clusters.dump"))
    print(f"aggregation: {name}: {time.time() - started:.0f} s", flush=True)
    times, number, largest = [], [], []
    for step, _, atoms in frames:
        sizes = np.bincount(np.unique(atoms[:, 3], return_inverse=True)[1])
        times.append(step * dt)
        number.append(len(sizes))
        largest.append(int(sizes.max()))
    # The energy budget of the whole cloud: ke + pe + crack- + bulk-dissipated against its start.
    rows = np.array(lammps_runs.thermo_rows(log))
    budget = rows[:, 1] + rows[:, 2] + rows[:, 3] + rows[:, 4]
    return dict(times=np.array(times), number=np.array(number), largest=np.array(largest), frames=frames,
                closure=float(np.max(np.abs(budget / budget[0] - 1.0))))


def half_time(times, number):
    """When the number of aggregates first falls to N/2 (linear interpolation); None if never."""
    below = np.nonzero(number <= N / 2)[0]
    if not len(below):
        return None
    k = below[0]
    if k == 0:
        return float(times[0])
    t0, t1, n0, n1 = times[k - 1], times[k], number[k - 1], number[k]
    return float(t0 + (n0 - N / 2) / (n0 - n1) * (t1 - t0))


def main():
    args, build = lammps_runs.demo_setup(
        __doc__.splitlines()[0], ROOT, "aggregation",
        lambda p: p.add_argument("--steps", type=int, default=STEPS, help=f"time steps of each run (default {STEPS})"))
    cli = lammps_runs.CLI
    t_hertz, mean_relative = collision_time(cli)
    dt = t_hertz / 100.0
    steps = args.steps // 10 if args.quick else args.steps
    every = steps // 60
    results = {"N": N, "phi": PHI, "radius": RADIUS, "rms_speed": SPEED, "mean_relative_speed": mean_relative,
               "dt": dt, "steps": steps, "quick": args.quick}
    runs = {}
    for name, tvis in LAWS.items():
        r = run(name, tvis, dt, steps, every, args.cores)
        runs[name] = r
        results[name] = dict(tvis=tvis, sticking_velocity=sticking_velocity(cli, tvis),
                             half_time=half_time(r["times"], r["number"]), final_number=int(r["number"][-1]),
                             final_largest=int(r["largest"][-1]), energy_closure=r["closure"],
                             times=r["times"].tolist(), number=r["number"].tolist(), largest=r["largest"].tolist())
        print(f"aggregation: {name}: {r['number'][-1]} aggregates at the end, the largest of {r['largest'][-1]} "
              f"grains; N/2 aggregates at {results[name]['half_time']}; energy budget closed to {r['closure']:.2e}",
              flush=True)
    a, b = results["viscoelastic"]["half_time"], results["elastic JKR"]["half_time"]
    results["speed_up"] = b / a if a and b else None
    with open(os.path.join(args.out, "aggregation", "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    plot(runs, results, os.path.join(args.out, "figures", "aggregation"))


def snapshot(ax, frame, title):
    """The grains of a frame, coloured by the size of their aggregate (monomers small and grey)."""
    _, length, atoms = frame
    _, inverse, counts = np.unique(atoms[:, 3], return_inverse=True, return_counts=True)
    size = counts[inverse]
    xyz = (atoms[:, :3] % length) * 1e6
    alone = size == 1
    ax.scatter(*xyz[alone].T, s=0.5, color="0.75", depthshade=False)
    order = np.argsort(size[~alone])
    sc = ax.scatter(*xyz[~alone][order].T, c=np.log10(size[~alone][order]), s=3, cmap="viridis", vmin=0,
                    vmax=np.log10(N), depthshade=False)
    ax.set_title(title, fontsize=8)
    for label, axis in (("x", ax.xaxis), ("y", ax.yaxis), ("z", ax.zaxis)):
        axis.set_label_text(f"{label} [$\\mu$m]", fontsize=6)
    ax.tick_params(labelsize=5)
    return sc


def plot(runs, results, stem):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(10, 8))
    colours = {"viscoelastic": "tab:red", "elastic JKR": "tab:blue"}
    ax1, ax2 = fig.add_subplot(2, 2, 1), fig.add_subplot(2, 2, 2)
    for name, r in runs.items():
        res = results[name]
        label = f"{name}, T$_{{vis}}$ = {res['tvis']:g} s (v$_s$ = {res['sticking_velocity']:.2f} m/s)"
        ax1.plot(r["times"] * 1e6, r["number"], "-", color=colours[name], label=label)
        ax2.plot(r["times"] * 1e6, r["largest"], "-", color=colours[name], label=name)
    ax1.axhline(N / 2, color="0.6", lw=0.8, ls=":")
    ax1.set_xlabel("t [$\\mu$s]")
    ax1.set_ylabel("number of aggregates (monomers included)")
    ax1.legend(fontsize=7)
    ax2.set_xlabel("t [$\\mu$s]")
    ax2.set_ylabel("largest aggregate [grain masses]")
    ax2.set_yscale("log")
    ax2.legend(fontsize=7)
    # Both clouds when the viscoelastic one's largest aggregate first holds N/8 grains (or at the end).
    times = runs["viscoelastic"]["times"]
    grown = np.nonzero(runs["viscoelastic"]["largest"] >= N / 8)[0]
    k = int(grown[0]) if len(grown) else len(times) - 1
    for column, name in ((3, "viscoelastic"), (4, "elastic JKR")):
        ax = fig.add_subplot(2, 2, column, projection="3d")
        frame = runs[name]["frames"][k]
        sc = snapshot(ax, frame, f"{name} at t = {times[k] * 1e6:.2f} $\\mu$s:\n{runs[name]['number'][k]} aggregates, "
                                 f"the largest of {runs[name]['largest'][k]} grains")
    fig.subplots_adjust(hspace=0.3)
    fig.colorbar(sc, ax=fig.axes[-2:], shrink=0.5, label="log$_{10}$ aggregate size [grains]")
    speed_up = results.get("speed_up")
    fig.suptitle(f"{N} ice grains of 1 $\\mu$m, $\\phi$ = {PHI}, rms speed {SPEED} m/s, pair_style bounce krijt, "
                 f"2 MPI ranks" + (f"\nviscoelastic grains reach N/2 aggregates {speed_up:.1f}x sooner than elastic "
                                   "JKR grains" if speed_up else ""), fontsize=9)
    for ext in ("png", "svg"):
        fig.savefig(f"{stem}.{ext}", dpi=150)
    print(f"aggregation: {stem}.png", flush=True)


if __name__ == "__main__":
    main()
