"""Restart files with pair_style bounce (docs/lammps.md, Restarts; issue row 3): the pair style
writes its setting and every pair_coeff, FixNeighHistory each contact's history (the tangential
spring, krijt's crack), fix wall/bounce each atom's touch flags and histories. A run continued from a
restart file in a second process equals the uninterrupted one."""
import os
import tempfile

import pytest

import lammps_runs as L

# A gas with the asperity law (every contact keeps a spring), small enough for seconds a run.
COEFF = "viscoelastic E 1e7 nu 0.3 A 3e-6 friction 0.3 asperity 1e-6"
STEPS = 3000


def continued(cores, work):
    """`run 3000, write_restart, run 3000` in one process; `read_restart, run 3000` in a second,
    given only the plugin, neighbor settings and the integrator (no pair_style, no pair_coeff)."""
    first = L.gas_script(COEFF, cells=12, phi=0.1, dt=3e-6, steps=STEPS, thermo=STEPS, skin=2e-4)
    one, two, _, log = L.restart_and_continue(first, STEPS, cores, work)
    return one, two, log


@pytest.mark.parametrize("cores", [1, 2])
def test_gas_continues_from_a_restart(cores):
    """Positions within 1e-12 m and velocities within 1e-9 m/s (the issue's bound) after 3000 steps
    from the restart, on 1 and 2 ranks: the laws, the integration setting and every contact's
    spring came back (a lost spring changes the grains' paths by ~1e-6 m in these steps)."""
    with tempfile.TemporaryDirectory() as work:
        one, two, log = continued(cores, work)
    assert "pair_style bounce" not in log.split("read_restart", 1)[1].split("run", 1)[0]  # not given again
    assert one.keys() == two.keys() and len(one) == 12 ** 3
    worst_x = max(abs(one[a][k] - two[a][k]) for a in one for k in range(3))
    worst_v = max(abs(one[a][k] - two[a][k]) for a in one for k in range(3, 6))
    assert worst_x <= 1e-12 and worst_v <= 1e-9, (worst_x, worst_v)


def krijt_script(velocity=3.0):
    """Two 1 um water-ice grains head-on with krijt (T_vis = 1e-12 s), dt = t_H/100."""
    pair, model = dict(material="water-ice", radius=1e-6), dict(model="krijt", tvis=1e-12)
    ref = L.bounce(*L.cli_args(dict(pair, **model)), "--velocity", str(velocity))
    b = ref["pair"]["body1"]
    r, m = b["radius"], b["mass"]
    dt = ref["closed_forms"]["hertz_time_k13_22"] / 100
    return L.preamble(8 * r, 2) + f"""
create_atoms 1 single {-r!r} 0 0
create_atoms 2 single {r!r} 0 0
set atom * diameter {2 * r!r} mass {m!r}
velocity all set 0 0 0
set atom 1 vx {velocity / 2!r}
set atom 2 vx {-velocity / 2!r}
plugin load {L.PLUGIN}
pair_style bounce
{L.pair_coeffs(dict(material="water-ice"), model)}
neighbor 6e-7 bin
timestep {dt!r}
fix 1 all nve/sphere
thermo_style custom step pe
"""


def test_krijt_crack_survives_a_restart():
    """Stopped a Hertz time into their contact (pe != 0: it holds) and continued from a restart
    file, the two grains leave with the velocities of the run that wrote it (to 1e-12 relative:
    the crack's radius, its two earlier values and the last forces came back)."""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "k.restart")
        _, first = L.run_lammps(krijt_script() + f"""run 100
print "PE $(pe:%.17g)"
write_restart {path}
run 700
print "STATE $(vx[1]:%.17g) $(vx[2]:%.17g)"
""")
        _, second = L.run_lammps(f"""
plugin load {L.PLUGIN}
read_restart {path}
neighbor 6e-7 bin
fix 1 all nve/sphere
run 700
print "STATE $(vx[1]:%.17g) $(vx[2]:%.17g)"
""")
    assert L.printed(first, "PE") != 0.0  # in contact at the restart
    a, b = L.final_state(first), L.final_state(second)
    assert a[1] - a[0] > 0.0  # they separated
    assert all(abs(x - y) <= 1e-12 * abs(x) for x, y in zip(a, b)), (a, b)


WALL = L.preamble(0.05, 1) + """
create_atoms 1 single 0 0 0.00999985
set type 1 diameter 0.02 density 1000
velocity all set 0.05 0 0
plugin load {plugin}
pair_style bounce
pair_coeff * * viscoelastic material ice-bshp96 A 1e-6
fix 1 all nve/sphere
fix 2 all gravity 9.81 vector 0 0 -1
fix floor all wall/bounce zplane 0 NULL viscoelastic material ice-bshp96 A 1e-6 friction 0.3 asperity 1e-5
timestep 1e-6
run 2000
"""


def test_wall_history_survives_a_restart():
    """A grain sliding on fix wall/bounce: after a restart (the fix given again, same ID) the wall's
    tangential force is the one before it (the spring came back; it was lost, fx 7.64e-7 N -> 0),
    and 2000 steps later the grain is where it is without the restart (to 1e-12 m)."""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "w.restart")
        head = WALL.format(plugin=L.PLUGIN)
        _, before = L.run_lammps(head + f'write_restart {path}\nrun 0\nprint "FX $(fx[1]:%.17g)"\nrun 2000\n'
                                 'print "X $(x[1]:%.17g) $(z[1]:%.17g)"\n')
        _, after = L.run_lammps(f"""
plugin load {L.PLUGIN}
read_restart {path}
fix 1 all nve/sphere
fix 2 all gravity 9.81 vector 0 0 -1
fix floor all wall/bounce zplane 0 NULL viscoelastic material ice-bshp96 A 1e-6 friction 0.3 asperity 1e-5
run 0
print "FX $(fx[1]:%.17g)"
run 2000
print "X $(x[1]:%.17g) $(z[1]:%.17g)"
""")
    fx = L.printed(before, "FX")
    assert fx != 0.0 and L.printed(after, "FX") == fx, (fx, L.printed(after, "FX"))
    x1 = [float(v) for v in before.split("\nX ")[-1].split()[:2]]
    x2 = [float(v) for v in after.split("\nX ")[-1].split()[:2]]
    assert max(abs(a - b) for a, b in zip(x1, x2)) <= 1e-12, (x1, x2)
