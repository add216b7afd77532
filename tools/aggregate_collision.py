#!/usr/bin/python3
"""Head-on collisions of two BPCA aggregates of ice monomers in LAMMPS (docs/aggregates.md,
Collisions; `make aggregate-collisions`).

Two aggregates of N monomers of 0.1 um (bounce aggregate build, seeds 1 and 2) meet head-on at a
relative speed v, in pair_style bounce with Wada et al. 2007's ice (E = 7 GPa, nu = 0.25,
gamma_s = 0.1 J/m^2 per surface, density 1000 kg/m^3): the elastic JKR contact (`jkr-viscoelastic`
with A = 0, no normal damping) and its rolling, sliding and twisting springs (xi_crit = 8 A). The
only losses are the springs' beyond their critical displacements (each contact made also
releases its adhesion energy into the monomers: docs/aggregates.md, the energy budget).

Each collision is measured from the monomers' final positions against the start:

* contacts broken (farther than 2r + delta_c at the end, delta_c JKR's critical overlap: beyond
  it no contact holds) and made (no contact at the start, closer than 2r at the end: it touched
  and holds); the pairs in between, whose state positions cannot tell, are counted apart;
* fragments: connected components of the final contacts; monomers lost (outside the largest two);
* the outcome: sticking (one fragment), sticking with monomers lost, bouncing (two fragments,
  each mostly one aggregate), disruption (the largest fragment holds less than half of them);

set against Dominik & Tielens 1997's energies (n_c contacts at the start): E < 5 E_roll no
restructuring, E ~ n_c E_roll the most compression, E ~ 3 n_c E_break monomers lost, E > 10 n_c
E_break catastrophic disruption (the last Wada et al. 2007's, from their 2D simulations); the
first three as the aggregate literature restates DT97.

    /usr/bin/python3 tools/aggregate_collision.py [--build build] [--out out] [--cores 2]
        [--n 1000] [--velocities 0.3,1,3,10,20,30,45,60,80,100,130] [--quick]

Writes out/aggregate_collisions/results.json and out/figures/aggregate_collisions.png.
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..")
sys.path.insert(0, os.path.join(ROOT, "tests", "lammps"))
import lammps_runs  # noqa: E402

RADIUS = 1e-7  # monomer radius [m]
ICE = {"E": 7e9, "nu": 0.25, "surface_energy": 0.1, "density": 1000.0}  # Wada et al. 2007's ice
XI_CRIT = 8e-10  # [m], W07's
DT = 1e-11  # [s]: a monomer pair's contact lasts 40 steps or more up to 130 m/s (docs/aggregates.md)
GAP = 3e-9  # [m] between the aggregates' nearest surfaces at the start (the quench moves monomers < 1 nm)
QUENCH = 20000  # steps of the quench: 100 damping times of 2 ns
# [m/s]: E = 0.4 E_roll .. 37 n_c E_roll at n = 1000
VELOCITIES = [0.3, 1.0, 3.0, 10.0, 20.0, 30.0, 45.0, 60.0, 80.0, 100.0, 130.0]


def refuse(name, value, allowed):
    """The project's one rule for bad input: what was typed, its value, what is allowed; exit 2."""
    print(f"aggregate_collision: {name} = {value} is invalid: expected {allowed}", file=sys.stderr)
    sys.exit(2)


def cli_json(cli, *args):
    done = subprocess.run([cli, *args, "--json"], capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"aggregate_collision: {cli} {' '.join(args)}: {done.stderr.strip()}")
    return json.loads(done.stdout)


def monomer_contact(cli):
    """The monomers' JKR contact and its energies, from bounce itself (docs/resistance.md)."""
    bodies = ["--E", str(ICE["E"]), "--nu", str(ICE["nu"]), "--surface-energy", str(ICE["surface_energy"]),
              "--density", str(ICE["density"]), "--radius", str(RADIUS)]
    resistance = cli_json(cli, "contact", "resistance", *bodies, "--xi-crit", str(XI_CRIT))
    rest = cli_json(cli, "contact", "--law", "jkr", *bodies)
    return {"rest_overlap": rest["overlap"], "critical_overlap": resistance["critical_overlap"],
            "contact_radius": resistance["contact_radius"], "E_roll": resistance["rolling"]["energy"],
            "E_break": resistance["break_energy"], "mass": resistance["pair"]["body1"]["mass"]}


def build_aggregate(cli, n, seed, work):
    """The centres (n x 3) of `bounce aggregate build --kind bpca` of seed `seed`."""
    path = os.path.join(work, f"bpca{seed}.data")
    cli_json(cli, "aggregate", "build", "--kind", "bpca", "--n", str(n), "--radius", str(RADIUS), "--density",
             str(ICE["density"]), "--seed", str(seed), "-o", path)
    lines = open(path).read().splitlines()
    start = lines.index("Atoms # sphere") + 2
    return np.array([[float(v) for v in line.split()[4:7]] for line in lines[start:start + n]])


def contacts(positions, reach):
    """Pairs (i < j) closer than `reach`, as a set."""
    return {(int(i), int(j)) for i, j in cKDTree(positions).query_pairs(reach)}


def touching_shift(a, b, distance):
    """The shift s along x that brings b (placed at b + s x) up to a until its nearest pair is
    `distance` apart: pairs whose projections on the y-z plane are closer than `distance` meet at
    x_b + s - x_a = sqrt(distance^2 - h^2); the first of them to meet sets s."""
    near = cKDTree(a[:, 1:]).query_ball_tree(cKDTree(b[:, 1:]), distance)
    shifts = [a[i, 0] - b[j, 0] + math.sqrt(max(distance ** 2 - float(np.sum((a[i, 1:] - b[j, 1:]) ** 2)), 0.0))
              for i, js in enumerate(near) for j in js]
    if not shifts:
        raise SystemExit("aggregate_collision: the aggregates' shadows do not overlap: no head-on collision")
    return max(shifts)


def head_on(a, b, speed, rest_overlap):
    """Both aggregates set up for the collision: each shrunk about its centre of mass so that its
    tree contacts start at JKR's rest overlap (the builder puts them at 2r to round-off, where
    half would not form), then placed on the x axis with their nearest pair 2r + GAP apart,
    moving towards each other at speed/2 each. Returns positions and velocities, a's first."""
    scale = 1.0 - rest_overlap / (2.0 * RADIUS)
    a, b = ((p - p.mean(axis=0)) * scale for p in (a, b))
    b = b + np.array([touching_shift(a, b, 2.0 * RADIUS + GAP), 0.0, 0.0])
    positions = np.vstack([a, b])
    positions -= positions.mean(axis=0)
    velocities = np.zeros_like(positions)
    velocities[:len(a), 0], velocities[len(a):, 0] = speed / 2.0, -speed / 2.0
    return positions, velocities


def write_data(path, positions, velocities):
    """A LAMMPS data file (atom_style sphere) of the monomers, with their velocities."""
    low, high = positions.min(axis=0) - 4 * RADIUS, positions.max(axis=0) + 4 * RADIUS
    lines = ["LAMMPS data file (atom_style sphere, units si): tools/aggregate_collision.py", "",
             f"{len(positions)} atoms", "1 atom types", ""]
    lines += [f"{lo!r} {hi!r} {axis}lo {axis}hi" for lo, hi, axis in zip(low, high, "xyz")]
    lines += ["", "Atoms # sphere", ""]
    lines += [f"{i + 1} 1 {2 * RADIUS!r} {ICE['density']!r} {x!r} {y!r} {z!r}" for i, (x, y, z) in enumerate(positions)]
    lines += ["", "Velocities", ""]
    lines += [f"{i + 1} {vx!r} {vy!r} {vz!r} 0 0 0" for i, (vx, vy, vz) in enumerate(velocities)]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def script(n, speed, chunk, chunks, settle=20000):
    """The collision: W07's ice, elastic JKR and the three springs.

    First each aggregate at rest is quenched (QUENCH steps under a drag of time constant 2 ns),
    since the shrink to JKR's rest distance brings a few pairs that nearly touched into contact
    short of it (18 at n = 1000: docs/aggregates.md), and they would release their energy into
    the collision; the positions then are the start. Then the aggregates get their speeds and
    run in chunks of `chunk` steps of DT until their centres of mass (of each one's monomers,
    wherever they went) no longer close in on each other faster than 1 % of `speed` (at most
    `chunks` chunks: "CAPPED" in the log then), and as long again (at least `settle` steps, 0.2 us:
    what leaves at 1 cm/s is then 2 nm, more than delta_c, away; at most ten times that), so that
    a slow rebound shows and every contact that is to break has broken.

    Thermo: ke, rotational ke, pe, what the springs dissipated since the quench, touching pairs
    (twice), the speed at which the centres of mass close in. Neighbours by `nsq`: the box grows
    with what flies off (`m` boundaries), and LAMMPS's bins would grow with it (6x the cost a step
    at 45 m/s)."""
    coeff = " ".join(f"{k} {v!r}" for k, v in ICE.items() if k != "density")
    drag = 4.0 / 3.0 * math.pi * RADIUS ** 3 * ICE["density"] / 2e-9  # m / tau [kg/s]
    return f"""
units si
atom_style sphere
atom_modify map array
boundary m m m
comm_modify vel yes
read_data collision.data
group a id 1:{n}
group b id {n + 1}:{2 * n}
plugin load {lammps_runs.PLUGIN}
pair_style bounce
pair_coeff * * jkr-viscoelastic {coeff} A 0 rolling yes sliding yes twisting yes xi_crit {XI_CRIT!r}
neighbor 1e-8 nsq
neigh_modify delay 0 every 1 check yes
timestep {DT!r}
fix 1 all nve/sphere
compute e all pair bounce
fix quench all viscous {drag!r}
thermo_style custom step ke c_e[5] c_e[6] c_e[7]
thermo {QUENCH}
run {QUENCH}
unfix quench
write_dump all custom start.dump id x y z modify sort id format float %.17g
velocity a set {speed / 2!r} 0 0
velocity b set {-speed / 2!r} 0 0
set group all omega 0 0 0
variable rolled equal c_e[5]-$(c_e[5]:%.17g)  # current: the quench's last thermo line computed it
variable slid equal c_e[6]-$(c_e[6]:%.17g)
variable twisted equal c_e[7]-$(c_e[7]:%.17g)
compute rot all erotate/sphere
compute touch all contact/atom
compute touching all reduce sum c_touch
variable closing equal (vcm(a,x)-vcm(b,x))*(xcm(b,x)-xcm(a,x))/abs(xcm(b,x)-xcm(a,x))
variable settled equal v_closing<{0.01 * speed!r}
thermo_style custom step ke c_rot pe v_rolled v_slid v_twisted c_touching v_closing
thermo_modify format float %.15g norm no
thermo {chunk}
variable k loop {chunks}
label chunk
run {chunk}
if "${{settled}} == 1" then "jump SELF settle"
next k
jump SELF chunk
print "CAPPED"
label settle
# as long as the approach took, within [settle, 10 settle] (LAMMPS's min and max act on vectors)
variable taken equal step-{QUENCH}
variable capped equal 0.5*(v_taken+{10 * settle}-abs(v_taken-{10 * settle}))
variable settle equal 0.5*(v_capped+{settle}+abs(v_capped-{settle}))
run ${{settle}}
write_dump all custom final.dump id x y z modify sort id format float %.17g
"""


def fragments(n, pairs):
    """Sizes of the connected components of n monomers joined by `pairs`, largest first, and each
    monomer's component."""
    parent = list(range(n))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i, j in pairs:
        parent[root(i)] = root(j)
    labels = np.array([root(i) for i in range(n)])
    _, labels, sizes = np.unique(labels, return_inverse=True, return_counts=True)
    return sizes, labels


def outcome(n, result):
    """The class of a collision of two aggregates of n monomers each, from its fragments (how much
    it restructured is in its numbers of contacts broken and made)."""
    sizes = result["fragments"]
    if result["largest_two_mostly_one_aggregate"]:
        return "bouncing"
    if sizes[0] < n:
        return "disruption"
    return "sticking, monomers lost" if result["lost"] > 0 else "sticking"


def gyration_radius(positions):
    return float(np.sqrt(np.mean(np.sum((positions - positions.mean(axis=0)) ** 2, axis=1))))


def measure(n, start, final, labels_from, reach):
    """Contacts broken and made, fragments and lost monomers, from the start and final positions.
    Positions alone cannot tell a contact stretched towards its fold (2r .. 2r + delta_c apart)
    from a pair that never touched at that distance, so each count takes what is certain: broken,
    a contact of the start now beyond `reach` = 2r + delta_c; made, a pair of no contact at the
    start now closer than 2r (it touched and holds). The pairs in between are counted (`between`);
    fragments join every pair within `reach`. The contacts at the start are the pairs closer than 2r
    (after the quench every contact sits near JKR's rest overlap, and no other pair is that close)."""
    before, after = contacts(start, 2.0 * RADIUS), contacts(final, reach)
    made = contacts(final, 2.0 * RADIUS) - before
    sizes, labels = fragments(2 * n, after)
    order = np.argsort(-sizes)
    sizes = sizes[order]
    mostly_one = False
    if len(sizes) >= 2 and sizes[1] >= n // 2:  # bouncing: the largest two, each > 90 % one aggregate
        shares = [np.mean(labels_from[labels == order[k]]) for k in (0, 1)]
        mostly_one = all(min(s, 1 - s) < 0.1 for s in shares) and round(shares[0]) != round(shares[1])
    lost = 2 * n - int(sizes[0]) - (int(sizes[1]) if mostly_one else 0)
    gyration = gyration_radius(final[labels == order[0]])
    across = sum(1 for i, j in made if labels_from[i] != labels_from[j])  # between the two aggregates
    return {"contacts_start": len(before), "contacts_end": len(after), "broken": len(before - after),
            "made": len(made), "made_across": across, "made_within": len(made) - across,
            "between": len(after - contacts(final, 2.0 * RADIUS)), "fragments": [int(s) for s in sizes],
            "lost": lost, "largest_two_mostly_one_aggregate": bool(mostly_one), "largest_gyration_radius": gyration,
            "gyration_radius_start": gyration_radius(start)}


def read_positions(path, count):
    lines = open(path).read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    return np.array([[float(v) for v in line.split()[1:4]] for line in lines[start:start + count]])


def collide(a, b, speed, contact, cores, chunk=1000, chunks=500):
    """One collision at relative speed `speed` [m/s]: its measures, energies and thermo rows."""
    n = len(a)
    placed, _ = head_on(a, b, speed, contact["rest_overlap"])
    with tempfile.TemporaryDirectory() as work:
        write_data(os.path.join(work, "collision.data"), placed, np.zeros_like(placed))
        log = lammps_runs.run_in(work, script(n, speed, chunk, chunks), cores, "in.collision")
        start = read_positions(os.path.join(work, "start.dump"), 2 * n)
        final = read_positions(os.path.join(work, "final.dump"), 2 * n)
    rows = np.array([row for row in lammps_runs.thermo_rows(log) if len(row) == 9])  # after the quench
    mu = n * contact["mass"] / 2.0  # the two aggregates' reduced mass
    from_b = np.r_[np.zeros(n), np.ones(n)]
    result = measure(n, start, final, from_b, 2.0 * RADIUS + contact["critical_overlap"])
    result.update(speed=speed, impact_energy=0.5 * mu * speed ** 2, steps=int(rows[-1, 0]) - QUENCH,
                  settled="\nCAPPED" not in log,
                  dissipated={"rolling": rows[-1, 4], "sliding": rows[-1, 5], "twisting": rows[-1, 6]},
                  kinetic_end=float(rows[-1, 1] + rows[-1, 2]), rows=rows.tolist())
    result["outcome"] = outcome(n, result)
    return result


def regimes(n_contacts, contact):
    """DT97's (and W07's) thresholds of the impact energy for n_c contacts [J]."""
    roll, brk = contact["E_roll"], contact["E_break"]
    return {"hit_and_stick_below (5 E_roll, DT97)": 5 * roll,
            "maximal_compression (n_c E_roll, DT97)": n_contacts * roll,
            "monomer_loss (3 n_c E_break, DT97)": 3 * n_contacts * brk,
            "catastrophic_disruption (10 n_c E_break, W07)": 10 * n_contacts * brk}


def report(results, thresholds, n_contacts, contact):
    print(f"R_g of the two at the start (touching): {results[0]['gyration_radius_start'] * 1e6:.3f} um; "
          f"n_c = {n_contacts} contacts ({n_contacts - results[0]['monomers'] + 2} beyond the two trees)")
    print(f"{'v [m/s]':>8} {'E/E_roll':>9} {'E/n_cE_roll':>11} {'E/n_cE_br':>9} {'broken':>7} {'made':>6} "
          f"{'across':>6} {'between':>7} {'largest':>8} {'lost':>5} {'R_g [um]':>8}  outcome")
    for r in results:
        e = r["impact_energy"]
        print(f"{r['speed']:8.3g} {e / contact['E_roll']:9.3g} {e / (n_contacts * contact['E_roll']):11.3g} "
              f"{e / (n_contacts * contact['E_break']):9.3g} {r['broken']:7d} {r['made']:6d} {r['made_across']:6d} "
              f"{r['between']:7d} {r['fragments'][0]:8d} {r['lost']:5d} "
              f"{r['largest_gyration_radius'] * 1e6:8.3f}  {r['outcome']}")
    for name, energy in thresholds.items():
        speed = math.sqrt(2 * energy / results[0]["reduced_mass"])
        print(f"  {name}: E = {energy:.3g} J, v = {speed:.3g} m/s")


def plot(results, thresholds, n_contacts, contact, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x = np.array([r["impact_energy"] for r in results]) / (n_contacts * contact["E_roll"])
    fig, (top, middle, bottom) = plt.subplots(3, 1, figsize=(6.4, 8.4), sharex=True)
    top.plot(x, [r["broken"] / n_contacts for r in results], "o-", label="contacts broken")
    top.plot(x, [r["made_within"] / n_contacts for r in results], "s-", label="made within an aggregate")
    top.plot(x, [r["made_across"] / n_contacts for r in results], "^-", label="made between the two")
    top.set_ylabel("per initial contact")
    middle.plot(x, [r["fragments"][0] / r["monomers"] for r in results], "o-", label="largest fragment")
    middle.plot(x, [r["lost"] / r["monomers"] for r in results], "s-", label="monomers lost")
    middle.set_ylabel("fraction of the monomers")
    bottom.plot(x, [r["largest_gyration_radius"] * 1e6 for r in results], "o-", label="largest fragment")
    bottom.axhline(results[0]["gyration_radius_start"] * 1e6, color="grey", lw=1, label="the two at the start")
    bottom.set_ylabel(r"$R_g$ [$\mu$m]")
    bottom.set_xlabel(r"$E_{imp} / (n_c E_{roll})$")
    for ax in (top, middle, bottom):
        ax.set_xscale("log")
        for (name, energy), style in zip(thresholds.items(), (":", "--", "-.", "-")):
            ax.axvline(energy / (n_contacts * contact["E_roll"]), color="grey", ls=style, lw=1,
                       label=name.split(" (")[0].replace("_", " ") if ax is top else None)
        ax.legend(fontsize=7)
    top.set_title(f"two BPCA aggregates of {results[0]['monomers'] // 2} ice monomers (0.1 um), head-on")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    def options(parser):
        parser.add_argument("--n", type=int, default=1000, help="monomers in each aggregate (default 1000)")
        parser.add_argument("--velocities", default=",".join(f"{v:g}" for v in VELOCITIES),
                            help="relative speeds [m/s], comma-separated")
    args, _ = lammps_runs.demo_setup(__doc__.splitlines()[0], ROOT, "aggregate_collisions", options)
    n = args.n // 10 if args.quick else args.n
    if not 2 <= n <= 131072:
        refuse("--n", args.n, "2 to 131072 monomers in each aggregate (--quick takes a tenth)")
    try:
        speeds = [float(v) for v in args.velocities.split(",")]
    except ValueError:
        speeds = []
    if not speeds or not all(math.isfinite(v) and 0 < v <= 1000 for v in speeds):
        refuse("--velocities", args.velocities, "relative speeds 0 < v <= 1000 [m/s], comma-separated")
    contact = monomer_contact(lammps_runs.CLI)
    with tempfile.TemporaryDirectory() as work:
        a, b = (build_aggregate(lammps_runs.CLI, n, seed, work) for seed in (1, 2))
    results = []
    for speed in speeds:
        started = time.time()
        r = collide(a, b, speed, contact, args.cores)
        r.update(monomers=2 * n, reduced_mass=n * contact["mass"] / 2.0)
        results.append(r)
        print(f"aggregate_collision: v = {speed:g} m/s: {r['outcome']}, {r['steps']} steps, "
              f"{time.time() - started:.0f} s" + ("" if r["settled"] else " (still closing at the chunks' cap)"),
              flush=True)
    n_contacts = results[0]["contacts_start"]
    thresholds = regimes(n_contacts, contact)
    report(results, thresholds, n_contacts, contact)
    plot(results, thresholds, n_contacts, contact, os.path.join(args.out, "figures", "aggregate_collisions.png"))
    for r in results:
        r.pop("rows")
    with open(os.path.join(args.out, "aggregate_collisions", "results.json"), "w") as f:
        json.dump({"n": n, "monomer": {"radius": RADIUS, **ICE, "xi_crit": XI_CRIT}, "contact": contact,
                   "n_contacts": n_contacts, "thresholds": thresholds, "dt": DT, "quick": args.quick,
                   "collisions": results}, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
