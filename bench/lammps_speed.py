#!/usr/bin/python3
"""pair_style bounce against LAMMPS's own pair granular in the same lmp (docs/benchmarks.md):

1. per-contact cost on a settled bed of 20 000 soft viscoelastic grains under gravity (every grain
   in contact with its neighbours for good), frictionless and with friction, side by side:
   `pair_style bounce` (corrected and plain) and `pair_style granular hertz/material ... damping
   viscoelastic` with the coefficients `bounce lammps` prints (and a linear_history tangential
   force where friction is on); LAMMPS's own timer of the Pair section per step and contact; and
   the same on a dense gas (volume fraction 0.45), where contacts form and end;
2. krijt (K13's crack law) against the plugin's viscoelastic law with the same A, on a dense gas
   of micrometre water-ice grains whose contacts stick and persist, and on a gas of colliding
   ones whose contacts form and break (the Pair section per step and contact); both again with
   the crack constant k = 0.1 and 0.5 instead of K13's 0.02;
3. strong scaling: 103 823 grains on 1 and 2 ranks (loop time);
4. W07's rolling, sliding and twisting springs (docs/resistance.md) on a dense gas of adhesive
   grains, against the same law without them (the Pair section per step and contact).

    /usr/bin/python3 bench/lammps_speed.py [BUILD_DIR [bed|scaling|resistance]]  (after make lammps; one part alone)
    /usr/bin/python3 bench/lammps_speed.py BUILD_DIR against OLD/bounceplugin.so   (this plugin beside another)
"""
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "build"))
os.environ.setdefault("BOUNCE_LMP", os.path.join(BUILD, "lammps", "lmp"))
os.environ.setdefault("BOUNCE_PLUGIN", os.path.join(BUILD, "lammps", "bounceplugin.so"))
os.environ.setdefault("BOUNCE_CLI", os.path.join(BUILD, "bin", "bounce"))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "lammps"))
import lammps_runs as L  # noqa: E402

# Soft viscoelastic grains: E = 1e7 Pa, R = 1 mm, density 1000, A = 3e-6 s (eps ~ 0.89 at 1 m/s,
# t_c = 1.4e-4 s); dt = 3e-6 s.
E, NU, A, RADIUS, DENSITY = 1e7, 0.3, 3e-6, 1e-3, 1000.0
# The asperity law with its form named: the default since issue 40 (passive), which a plugin
# from before took as published, so that `against` compares the same law.
ROUGH = "friction 0.3 asperity 1e-6 asperity_form passive"


def section(output, name):
    """Average seconds of a section of LAMMPS's MPI task timing breakdown."""
    match = re.search(rf"^{name}\s*\|\s*\S+\s*\|\s*(\S+)", output, re.M)
    return float(match.group(1))


def loop_time(output):
    return float(re.search(r"^Loop time of (\S+)", output, re.M).group(1))


def contacts(output):
    """Mean number of contacts over the thermo rows (compute contact/atom counts each twice)."""
    rows = L.thermo_rows(output)
    return sum(r[2] for r in rows[1:]) / len(rows[1:]) / 2


def dense(style, coeff, cells, steps, cores=1):
    extra = "compute touch all contact/atom\ncompute total all reduce sum c_touch\nthermo_style custom step c_ke c_total"
    script = L.gas_script(coeff, cells=cells, radius=RADIUS, density=DENSITY, phi=0.45, speed=1.0, dt=3e-6,
                          steps=steps, thermo=max(steps // 5, 1), pair_style=style, extra=extra, skin=0.1 * RADIUS)
    _, output = L.run_lammps(script, cores=cores)
    return output


def per_contact():
    mass = 4.0 / 3.0 * 3.141592653589793 * RADIUS ** 3 * DENSITY
    e_star = E / (2 * (1 - NU * NU))
    eta = 2 * A * e_star / (mass / 2)
    stock = f"hertz/material {E!r} {eta!r} {NU} damping viscoelastic tangential linear_nohistory 0 0"
    ours = f"viscoelastic E {E!r} nu {NU} A {A}"
    cells, steps = 30, 2000
    styles = [("pair granular hertz/material + viscoelastic", "granular", stock),
              ("pair_style bounce viscoelastic (plain)", "bounce integration plain", ours),
              ("pair_style bounce viscoelastic (corrected)", "bounce", ours)]
    best = {}
    for _ in range(5):  # interleaved, the fastest of five: the least disturbed by the machine
        for label, style, coeff in styles:
            out = dense(style, coeff, cells, steps)
            pair = section(out, "Pair")
            if label not in best or pair < best[label][0]:
                best[label] = (pair, loop_time(out), contacts(out))
    rows = [(label,) + best[label] for label, _, _ in styles]
    n = cells ** 3
    print(f"{n} grains at volume fraction 0.45, {steps} steps; LAMMPS's Pair time per step and contact:")
    base = None
    for label, pair, loop, c in rows:
        per = pair / steps / c
        base = base or (per, loop)
        print(f"  {label:45s} {per * 1e9:6.1f} ns/contact ({2 * c / n:.2f} contacts/grain): x{per / base[0]:.2f}; "
              f"whole loop {loop:.2f} s (x{loop / base[1]:.2f})")


def bed_script(style, coeff, data, steps, wall):
    """The settled bed read from `data`, `steps` steps of `style` with a floor `wall`."""
    plugin = f"plugin load {L.PLUGIN}" if style.startswith("bounce") else ""
    return f"""
units si
atom_style sphere
boundary p p f
comm_modify vel yes
read_data {data}
{plugin}
pair_style {style}
pair_coeff * * {coeff}
neighbor {0.1 * RADIUS!r} bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve/sphere
fix 2 all gravity 9.81 vector 0 0 -1
fix 3 all {wall}
compute touch all contact/atom
compute total all reduce sum c_touch
compute ke all ke
thermo_style custom step c_ke c_total
thermo {max(steps // 5, 1)}
timestep 3e-6
run {steps}
"""


def settled_bed(work):
    """20 000 grains (25 x 25 x 32 on a simple cubic lattice, shaken by random velocities of 0.1 m/s)
    let fall and settle for 10 000 steps with strong damping (A = 3e-5 s) onto a floor: a data
    file."""
    data = os.path.join(work, "bed.data")
    mass = 4.0 / 3.0 * 3.141592653589793 * RADIUS ** 3 * DENSITY
    spacing = 2.02 * RADIUS
    script = f"""
units si
atom_style sphere
boundary p p f
comm_modify vel yes
lattice sc {spacing!r}
region box block 0 25 0 25 0 40
create_box 1 box
region fill block 0 25 0 25 0.5 32.5
create_atoms 1 region fill
set type 1 diameter {2 * RADIUS!r} density {DENSITY!r}
velocity all create {mass * 0.1 ** 2 / (3 * 1.380649e-23)!r} 8271 dist gaussian mom yes rot no loop geom
plugin load {L.PLUGIN}
pair_style bounce
pair_coeff * * viscoelastic E {E!r} nu {NU} A 3e-5
neighbor {0.1 * RADIUS!r} bin
fix 1 all nve/sphere
fix 2 all gravity 9.81 vector 0 0 -1
fix 3 all wall/bounce zplane 0 NULL viscoelastic E {E!r} nu {NU} A 3e-5
timestep 3e-6
thermo 5000
run 10000
write_data {data}
"""
    L.run_in(work, script, 1, "in.settle")
    return data


def bed_per_contact():
    """The issue's bound: bounce at most 1.1x pair granular per contact, frictionless and with
    friction, on the settled bed; the fastest of three interleaved runs."""
    import tempfile
    mass = 4.0 / 3.0 * 3.141592653589793 * RADIUS ** 3 * DENSITY
    e_star = E / (2 * (1 - NU * NU))
    eta = 2 * A * e_star / (mass / 2)
    stock = f"hertz/material {E!r} {eta!r} {NU} damping viscoelastic"
    ours = f"viscoelastic E {E!r} nu {NU} A {A}"
    wall_stock = f"wall/gran granular {stock} tangential linear_nohistory 0 0 zplane 0 NULL"
    wall_ours = f"wall/bounce zplane 0 NULL {ours}"
    steps = 1000
    with tempfile.TemporaryDirectory() as work:
        data = settled_bed(work)
        for friction in (False, True):
            tangential = "tangential linear_history 1e3 0 0.3" if friction else "tangential linear_nohistory 0 0"
            rough = " " + ROUGH if friction else ""
            styles = [("pair granular hertz/material + viscoelastic", "granular", f"{stock} {tangential}", wall_stock),
                      ("pair_style bounce viscoelastic (plain)", "bounce integration plain", ours + rough, wall_ours),
                      ("pair_style bounce viscoelastic (corrected)", "bounce", ours + rough, wall_ours)]
            best = {}
            for _ in range(3):
                for label, style, coeff, wall in styles:
                    out = L.run_lammps(bed_script(style, coeff, data, steps, wall))[1]
                    pair = section(out, "Pair")
                    if label not in best or pair < best[label][0]:
                        best[label] = (pair, contacts(out))
            n = 25 * 25 * 32
            print(f"settled bed of {n} grains, {'with friction' if friction else 'frictionless'}, {steps} steps; "
                  "LAMMPS's Pair time per step and contact:")
            base = None
            for label, _, _, _ in styles:
                pair, c = best[label]
                per = pair / steps / c
                base = base or per
                print(f"  {label:45s} {per * 1e9:6.1f} ns/contact ({2 * c / n:.2f} contacts/grain): x{per / base:.2f}")


def krijt_against_viscoelastic(title, phi, speed, dt, steps, k=0.02):
    """krijt (T_vis = 1e-12 s, crack constant `k`) against viscoelastic with A = T_vis / nu^2 (K13
    after (18)) on a gas of 1 um water-ice grains (K13 table 2) at volume fraction `phi` and rms
    `speed`, the same skin for both (krijt's neck reaches 37 nm beyond touching); the Pair section
    per step and contact, the fastest of three interleaved runs."""
    tvis, radius = 1e-12, 1e-6
    ice = "material water-ice"
    styles = [("pair_style bounce viscoelastic, A = T_vis/nu^2", f"viscoelastic {ice} A {tvis / 0.25 ** 2!r}"),
              (f"pair_style bounce krijt, T_vis = 1e-12 s, k = {k}", f"krijt {ice} tvis {tvis!r} k {k!r}")]
    extra = "compute touch all contact/atom\ncompute total all reduce sum c_touch\nthermo_style custom step c_ke c_total"
    cells = 22
    best = {}
    for _ in range(3):
        for label, coeff in styles:
            script = L.gas_script(coeff, cells=cells, radius=radius, density=1000.0, phi=phi, speed=speed, dt=dt,
                                  steps=steps, thermo=max(steps // 10, 1), extra=extra, skin=0.1 * radius)
            _, out = L.run_lammps(script)
            pair = section(out, "Pair")
            if label not in best or pair < best[label][0]:
                best[label] = (pair, contacts(out))
    n = cells ** 3
    print(f"{n} micrometre ice grains {title} (volume fraction {phi}, {speed} m/s rms), {steps} steps of t_H/100; Pair "
          "time per step and contact:")
    base = None
    for label, _ in styles:
        pair, c = best[label]
        per = pair / steps / c
        base = base or per
        print(f"  {label:50s} {per * 1e9:6.1f} ns/contact ({2 * c / n:.3f} contacts/grain): x{per / base:.2f}")


def krijt_cost(k=0.02):
    """Contacts that hold: the grains on a simple cubic lattice pressed 2 nm into each other (volume
    fraction 0.525), at 1 m/s rms, below the sticking velocity (1.9 m/s at T_vis = 1e-12 s): six
    contacts a grain that hold, and some that open and close; dt = t_H/100 at 1 m/s."""
    krijt_against_viscoelastic("in contact", phi=0.525, speed=1.0, dt=1.1e-10, steps=1000, k=k)


def krijt_gas_cost(k=0.02):
    """Contacts that form and break all the time (krijt's formation and break cost more than its
    steps): volume fraction 0.3, rms speed 5 m/s (2.7 times the sticking velocity, so that most
    collisions bounce), dt = 6e-11 s (t_H/100 at 5 m/s)."""
    krijt_against_viscoelastic("colliding", phi=0.3, speed=5.0, dt=6e-11, steps=3000, k=k)


def krijt_other_k_cost():
    """Both gases with k = 0.1 and 0.5: the crack law carried to any k (docs/adhesive.md) costs
    what it costs at K13's k = 0.02 (docs/benchmarks.md)."""
    for k in (0.1, 0.5):
        krijt_cost(k)
        krijt_gas_cost(k)


def scaling():
    coeff = f"viscoelastic E {E!r} nu {NU} A {A} {ROUGH}"
    cells, steps = 47, 300
    times = {}
    for cores in (1, 2):
        script = L.gas_script(coeff, cells=cells, radius=RADIUS, density=DENSITY, phi=0.3, speed=1.0, dt=3e-6,
                              steps=steps, thermo=steps)
        best = None
        for _ in range(2):
            _, out = L.run_lammps(script, cores=cores)
            t = loop_time(out)
            best = t if best is None else min(best, t)
        times[cores] = best
    print(f"strong scaling, {cells ** 3} grains (volume fraction 0.3, asperity law), {steps} steps: "
          f"1 rank {times[1]:.2f} s, 2 ranks {times[2]:.2f} s: speed-up {times[1] / times[2]:.2f}")


def against(other, reps=7):
    """This build's plugin side by side with another bounceplugin.so (one kept from before a change),
    on the dense gas with friction, interleaved: the Pair section per step and contact, the fastest
    of `reps` runs of each, pair granular (frictionless) as the machine's yardstick."""
    if not os.path.isfile(other):
        sys.exit(f"lammps_speed.py: against = {other} is invalid: expected the path of a bounceplugin.so")
    mass = 4.0 / 3.0 * 3.141592653589793 * RADIUS ** 3 * DENSITY
    eta = 2 * A * E / (2 * (1 - NU * NU)) / (mass / 2)
    stock = f"hertz/material {E!r} {eta!r} {NU} damping viscoelastic tangential linear_nohistory 0 0"
    ours = f"viscoelastic E {E!r} nu {NU} A {A} {ROUGH}"
    runs = [("pair granular (frictionless)", "granular", stock, L.PLUGIN), (f"bounce, {other}", "bounce", ours, other),
            ("bounce, this build", "bounce", ours, L.PLUGIN)]
    best, mine = {}, L.PLUGIN
    for _ in range(reps):
        for label, style, coeff, plugin in runs:
            L.PLUGIN = plugin
            out = dense(style, coeff, 24, 1500)
            per = section(out, "Pair") / 1500 / contacts(out)
            best.setdefault(label, []).append(per)
    L.PLUGIN = mine
    base = min(best[runs[1][0]])
    for label, _, _, _ in runs:
        times = best[label]
        print(f"  {label:50s} fastest {min(times) * 1e9:6.1f} ns/contact (x{min(times) / base:.3f} of the other "
              f"plugin's), runs {min(times) * 1e9:.1f}-{max(times) * 1e9:.1f}")


def resistance_cost():
    """The issue's bound: the three springs cost at most 2x the same adhesive law without them, per
    step and contact (LAMMPS's Pair section), on a dense gas (volume fraction 0.45, 27 000 grains,
    2000 steps) of W07's 0.1 um ice grains (gamma_s = 0.1 J/m^2, jkr-viscoelastic) at 1 m/s, with a
    step of 1e-11 s (a hundredth of the contact's period, as W07 step; a grain moves 1e-11 m a step,
    far below xi_crit); the fastest of five interleaved runs."""
    law = "jkr-viscoelastic E 7e9 nu 0.25 surface_energy 0.1 A 1e-12"
    styles = [("jkr-viscoelastic", law), ("jkr-viscoelastic + rolling, sliding, twisting",
                                           law + " rolling yes sliding yes twisting yes")]
    extra = "compute touch all contact/atom\ncompute total all reduce sum c_touch\nthermo_style custom step c_ke c_total"
    cells, steps, best = 30, 2000, {}
    for _ in range(5):
        for label, coeff in styles:
            script = L.gas_script(coeff, cells=cells, radius=1e-7, density=1000.0, phi=0.45, speed=1.0, dt=1e-11,
                                  steps=steps, thermo=steps // 5, extra=extra, skin=1e-8)
            out = L.run_lammps(script)[1]
            pair = section(out, "Pair")
            if label not in best or pair < best[label][0]:
                best[label] = (pair, loop_time(out), contacts(out))
    print(f"{cells ** 3} adhesive ice grains of 0.1 um at volume fraction 0.45, {steps} steps; LAMMPS's Pair time "
          "per step and contact:")
    base = None
    for label, _ in styles:
        pair, loop, c = best[label]
        per = pair / steps / c
        base = base or (per, loop)
        print(f"  {label:48s} {per * 1e9:6.1f} ns/contact ({2 * c / cells ** 3:.2f} contacts/grain): "
              f"x{per / base[0]:.2f}; whole loop {loop:.2f} s (x{loop / base[1]:.2f})")


if __name__ == "__main__":
    start = time.time()
    if len(sys.argv) > 3 and sys.argv[2] == "against":  # this build's plugin beside another
        against(os.path.abspath(sys.argv[3]))
        sys.exit(0)
    if len(sys.argv) > 2 and sys.argv[2] in ("bed", "scaling", "resistance"):  # one part alone
        {"bed": bed_per_contact, "scaling": scaling, "resistance": resistance_cost}[sys.argv[2]]()
        print(f"({time.time() - start:.0f} s)")
        sys.exit(0)
    bed_per_contact()
    per_contact()
    krijt_cost()
    krijt_gas_cost()
    krijt_other_k_cost()
    resistance_cost()
    scaling()
    print(f"({time.time() - start:.0f} s)")
