#!/usr/bin/python3
"""Golden LAMMPS runs of pair_style bounce and fix wall/bounce (docs/lammps.md, Goldens): every
number a few short runs leave, printed to 17 digits, so that a change that should not move a
result (a refactoring of the contact step) can be checked to the last bit.

    goldens.py              print the runs' numbers (BOUNCE_LMP, BOUNCE_PLUGIN, BOUNCE_CLI set)
    goldens.py --compare F  run them and compare with the file F: exit 0 if every number is the
                            same bit for bit, else 1 and the numbers that differ

The runs: two spheres with friction (viscoelastic, oblique, spinning), krijt bouncing with
friction and sticking, jkr-viscoelastic with `integration plain` (its neck holds beyond
touching), maugis-viscoelastic (its contact forms before touching), a grain sliding on a wall
with friction, and restarts written mid-contact (krijt's crack, a gas's springs) continued on 1
and 2 ranks."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lammps_runs as L  # noqa: E402

DUMP = "write_dump all custom {name}.dump id x y z vx vy vz fx fy fz omegax omegay omegaz tqx tqy tqz " \
       "modify sort id format float %.17g"
ENERGIES = 'print "E {name} $(ke:%.17g) $(pe:%.17g)"'
KRIJT_ENERGIES = 'print "E {name} $(ke:%.17g) $(pe:%.17g) $(c_e[1]:%.17g) $(c_e[2]:%.17g) $(c_e[3]:%.17g) ' \
                 '$(c_e[4]:%.17g)"'


def two_spheres(coeff, r, m, v, u, dt, style="bounce", gap=0.0, spin=0.0):
    """Two spheres of radius r and mass m touching at t = 0 (or `gap` apart), closing at v along x
    and sliding at u along y, atom 1 spinning at `spin` about z."""
    return L.preamble(6 * r, 1) + f"""
create_atoms 1 single {-r - gap / 2!r} 0 0
create_atoms 1 single {r + gap / 2!r} 0 0
set type 1 diameter {2 * r!r} mass {m!r}
velocity all set 0 0 0
set atom 1 vx {v / 2!r} vy {u / 2!r} omega 0 0 {spin!r}
set atom 2 vx {-v / 2!r} vy {-u / 2!r}
plugin load {L.PLUGIN}
pair_style {style}
pair_coeff * * {coeff}
neighbor {0.6 * r!r} bin
neigh_modify delay 0 every 1 check yes
timestep {dt!r}
fix 1 all nve/sphere
compute e all pair bounce
thermo_style custom step ke pe
"""


def stages(name, steps, krijt=False):
    """Runs `steps` (a list) one after the other, dumping and printing energies after each."""
    energies = KRIJT_ENERGIES if krijt else ENERGIES
    text = ""
    for k, n in enumerate(steps):
        tag = f"{name}-{k}"
        text += f"run {n}\n{DUMP.format(name=tag)}\n{energies.format(name=tag)}\n"
    return text


def collisions():
    """(name, script, cores) of the collisions."""
    ice = L.bounce("--material", "ice-bshp96", "--radius", "1e-3", "--model", "viscoelastic", "--A", "1e-6",
                   "--velocity", "0.5")
    r, m = ice["pair"]["body1"]["radius"], ice["pair"]["body1"]["mass"]
    dt = ice["contact_time"] / 500
    coeff = "viscoelastic material ice-bshp96 A 1e-6 friction 0.3 asperity 1e-6"
    yield "visco-friction", two_spheres(coeff, r, m, 0.5, 0.4, dt, spin=30.0) + stages("visco-friction", [250, 1250])
    krijt = L.bounce("--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis", "1e-12",
                     "--velocity", "3")
    r, m = krijt["pair"]["body1"]["radius"], krijt["pair"]["body1"]["mass"]
    dt = krijt["closed_forms"]["hertz_time_k13_22"] / 100
    coeff = "krijt material water-ice tvis 1e-12 friction 0.3 asperity 1e-9"
    yield "krijt-bounce", two_spheres(coeff, r, m, 3.0, 1.0, dt) + stages("krijt-bounce", [100, 700], krijt=True)
    yield "krijt-stick", two_spheres(coeff, r, m, 0.3, 0.0, dt) + stages("krijt-stick", [100, 700], krijt=True)
    jkr = L.bounce("--material", "water-ice", "--radius", "1e-6", "--model", "jkr-viscoelastic", "--tvis", "1e-11",
                   "--velocity", "5")
    dt = jkr["contact_time"] / 500
    coeff = "jkr-viscoelastic material water-ice tvis 1e-11 contact_end pull-off"
    yield "jkr-plain", two_spheres(coeff, r, m, 5.0, 0.0, dt, "bounce integration plain") + \
        stages("jkr-plain", [250, 1250])
    maugis = L.bounce("--material", "water-ice", "--radius", "1e-6", "--model", "maugis-viscoelastic", "--tvis",
                      "1e-11", "--velocity", "5")
    dt = maugis["contact_time"] / 500
    coeff = "maugis-viscoelastic material water-ice tvis 1e-11"
    yield "maugis-snap", two_spheres(coeff, r, m, 5.0, 0.0, dt, gap=2e-9) + stages("maugis-snap", [260, 1250])


def wall():
    """A grain sliding and spinning on a floor with friction, under gravity."""
    script = L.preamble(0.05, 1) + f"""
create_atoms 1 single 0 0 0.00999985
set type 1 diameter 0.02 density 1000
velocity all set 0.05 0 -0.01
set atom 1 omega 2.0 0 0
plugin load {L.PLUGIN}
pair_style bounce
pair_coeff * * viscoelastic material ice-bshp96 A 1e-6
fix 1 all nve/sphere
fix 2 all gravity 9.81 vector 0 0 -1
fix floor all wall/bounce zplane 0 NULL viscoelastic material ice-bshp96 A 1e-6 friction 0.3 asperity 1e-5
timestep 1e-6
thermo_style custom step ke pe
"""
    return script + stages("wall", [500, 2000])


def restarts(work, cores):
    """krijt's crack and a gas's springs written to a restart mid-contact and continued in a second
    process: the dumps of the second."""
    krijt = L.bounce("--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis", "1e-12",
                     "--velocity", "3")
    r, m = krijt["pair"]["body1"]["radius"], krijt["pair"]["body1"]["mass"]
    dt = krijt["closed_forms"]["hertz_time_k13_22"] / 100
    first = two_spheres("krijt material water-ice tvis 1e-12 friction 0.3 asperity 1e-9", r, m, 3.0, 1.0, dt)
    L.run_in(work, first + "run 100\nwrite_restart k.restart\n", cores, "in.k1")
    second = f"""
plugin load {L.PLUGIN}
read_restart k.restart
neighbor {0.6 * r!r} bin
fix 1 all nve/sphere
compute e all pair bounce
"""
    name = f"restart-krijt-{cores}"
    out = L.run_in(work, second + stages(name, [700], krijt=True), cores, "in.k2")
    gas = L.gas_script("viscoelastic E 1e7 nu 0.3 A 3e-6 friction 0.3 asperity 1e-6", cells=5, phi=0.3, dt=3e-6,
                       steps=400, thermo=400, skin=2e-4)
    L.run_in(work, gas + "write_restart g.restart\n", cores, "in.g1")
    second = f"""
plugin load {L.PLUGIN}
read_restart g.restart
neighbor 2e-4 bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve/sphere
"""
    name = f"restart-gas-{cores}"
    out += L.run_in(work, second + stages(name, [400]), cores, "in.g2")
    return out


def numbers(work, output):
    """The lines of the goldens: each dump's atoms and each printed energy line."""
    lines = []
    for line in output.splitlines():
        if line.startswith("E ") and len(line.split()) > 2:
            lines.append(line)
    for dump in sorted(f for f in os.listdir(work) if f.endswith(".dump")):
        for atom, values in sorted(L.read_dump(os.path.join(work, dump)).items()):
            lines.append(f"D {dump[:-5]} {atom} " + " ".join(f"{v!r}" for v in values))
    return lines


def version():
    """The LAMMPS release of BOUNCE_LMP, as its first line names it ("LAMMPS (4 Feb 2025)")."""
    _, output = L.run_lammps("print done\n")
    return output.splitlines()[0].strip()


def run_all():
    lines = [version()]
    for cores in (1, 2):
        with tempfile.TemporaryDirectory() as work:
            output = ""
            if cores == 1:
                for name, script in list(collisions()) + [("wall", wall())]:
                    output += L.run_in(work, script, 1, f"in.{name}")
            output += restarts(work, cores)
            lines += numbers(work, output)
    return lines


def compare(lines, path):
    with open(path) as f:
        golden = [l.rstrip("\n") for l in f if l.strip()]
    if len(golden) != len(lines):
        print(f"goldens: {len(lines)} lines against {len(golden)} in {path}")
        return 1
    if golden[0] != lines[0]:
        print(f"goldens: recorded with {golden[0]}, this is {lines[0]}: not comparable bit for bit")
        return 1
    differ = 0
    for new, old in zip(lines, golden):
        if new != old:
            differ += 1
            print(f"- {old}\n+ {new}")
    print(f"goldens: {len(lines)} lines, {differ} differ")
    return 1 if differ else 0


def main():
    for name in ("BOUNCE_LMP", "BOUNCE_PLUGIN", "BOUNCE_CLI"):
        if not os.environ.get(name):
            sys.exit(f"goldens.py: {name} is not set (the lmp, bounceplugin.so and bin/bounce of a build)")
    lines = run_all()
    if len(sys.argv) == 3 and sys.argv[1] == "--compare":
        sys.exit(compare(lines, sys.argv[2]))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
