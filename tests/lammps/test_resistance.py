"""Issue 36, point 2 (docs/resistance.md, In a DEM; docs/lammps.md): pair_style bounce with W07's
rolling, sliding and twisting springs (`rolling yes sliding yes twisting yes [xi_crit X]`). An
elastic dimer keeps its energy; the same dimer on 2 ranks, split between them, gives the 1-rank
run; a gas of adhesive grains continues from a restart as without one, on 1 and 2 ranks; bad
values are refused by the project's rule."""
import json
import os
import subprocess
import tempfile

import pytest

import lammps_runs as L

SPRINGS = "rolling yes sliding yes twisting yes"
# Wada et al. 2007's ice, as they give it (gamma_s = 0.1 J/m^2 per surface), elastic JKR.
W07_ICE = "jkr-viscoelastic E 7e9 nu 0.25 surface_energy 0.1 A 0"
RADIUS = 1e-7


def rest_overlap():
    """The JKR contact's overlap at zero load, from `bounce contact` (two 0.1 um grains)."""
    done = subprocess.run([L.CLI, "contact", "--E", "7e9", "--nu", "0.25", "--density", "1000", "--surface-energy", "0.1", "--radius",
                           str(RADIUS), "--law", "jkr", "--json"], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)["zero_load_overlap"]


def dimer_script(steps, dt=2e-13, thermo=10000, coeff=f"{W07_ICE} {SPRINGS}", dump="dimer.dump"):
    """Two 0.1 um grains at the JKR rest, spun against each other about z (rolling) and about the
    line of centres x (twisting): torques only, so the centres stay and the normal law's energy
    with them; pe is the springs' energy."""
    x = RADIUS - rest_overlap() / 2
    return L.preamble(1e-6, 1) + f"""
create_atoms 1 single {x!r} 0 0
create_atoms 1 single {-x!r} 0 0
set type 1 diameter {2 * RADIUS!r}
set type 1 density 1000
set atom 1 omega 3e3 0 1e3
set atom 2 omega -3e3 0 -1e3
plugin load {L.PLUGIN}
pair_style bounce
pair_coeff * * {coeff}
neighbor 1e-8 bin
neigh_modify delay 0 every 1 check yes
timestep {dt!r}
fix 1 all nve/sphere
compute rot all erotate/sphere
compute bp all pair bounce
thermo_style custom step ke c_rot pe c_bp[8] c_bp[5]
thermo_modify format float %.17g
thermo {thermo}
run {steps}
write_dump all custom {dump} id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""


def test_elastic_dimer_keeps_its_energy():
    """ke + erotate + pe within 1e-6 of the initial spin energy over 1e6 steps (dt = 2e-13 s, 3e4
    steps per rolling period: Verlet's error ~(omega dt)^2/8 ~ 1e-8); the springs take part of it
    (pe > 0) and none is dissipated (below every critical displacement)."""
    _, out = L.run_lammps(dimer_script(1000000))
    rows = L.thermo_rows(out)
    assert len(rows) == 101
    start = rows[0][1] + rows[0][2] + rows[0][3]
    worst = max(abs(r[1] + r[2] + r[3] - start) for r in rows) / start
    assert worst <= 1e-6, worst
    assert max(r[3] for r in rows) > 0.1 * start
    assert all(r[5] == 0.0 for r in rows)  # rolling dissipated: none
    assert all(abs(r[3] - r[4]) <= 1e-12 * start for r in rows)  # pe is the springs' energy


def test_dimer_split_between_ranks_is_the_one_rank_run():
    """The two atoms on two ranks (the box splits at x = 0): the contact's history (pointers, twist)
    crosses between them as the reverse view; the final state equals the 1-rank run's."""
    with tempfile.TemporaryDirectory() as work:
        for cores in (1, 2):
            L.run_in(work, dimer_script(20000, thermo=20000, dump=f"on{cores}.dump"), cores, f"in.{cores}")
        one, two = (L.read_dump(os.path.join(work, f"on{cores}.dump")) for cores in (1, 2))
    assert one == two, (one, two)
    assert one[1][5] != 3e3  # the twist spring turned the spin


GAS = f"jkr-viscoelastic E 1e7 nu 0.3 surface_energy 0.1 A 3e-6 {SPRINGS} xi_crit 1e-9"
STEPS = 3000


def restarted(cores, work):
    """A gas of adhesive 1 mm grains with the three springs: `run, write_restart, run` in one
    process, `read_restart, run` in a second; the springs' energy at the restart."""
    first = L.gas_script(GAS, cells=10, phi=0.2, dt=3e-6, steps=STEPS, thermo=STEPS, skin=2e-4,
                         extra="compute bp all pair bounce\nthermo_style custom step c_ke c_bp[8]")
    one, two, log, _ = L.restart_and_continue(first, STEPS, cores, work)
    return one, two, L.thermo_rows(log)[1][2]


@pytest.mark.parametrize("cores", [1, 2])
def test_rolling_gas_continues_from_a_restart(cores):
    """Positions within 1e-12 m and velocities within 1e-9 m/s after 3000 steps from the restart,
    as tests/lammps/test_restart.py asks of a gas with friction; contacts held spring energy when
    the file was written, so their pointers and twists came back with it."""
    with tempfile.TemporaryDirectory() as work:
        one, two, springs = restarted(cores, work)
    assert springs > 0.0
    worst_x = max(abs(one[a][k] - two[a][k]) for a in one for k in range(3))
    worst_v = max(abs(one[a][k] - two[a][k]) for a in one for k in range(3, 6))
    assert worst_x <= 1e-12 and worst_v <= 1e-9, (worst_x, worst_v)


@pytest.mark.parametrize("coeff, message", [
    (f"{W07_ICE} rolling maybe", "rolling = maybe is invalid: expected yes or no"),
    (f"{W07_ICE} rolling yes xi_crit -1", "xi_crit = -1 is invalid"),
    (f"{W07_ICE} xi_crit 1e-9", "xi_crit = 1e-9 is invalid: expected rolling yes beside it"),
    ("viscoelastic material ice-bshp96 A 1e-5 friction 0.3 asperity 1e-6 sliding yes",
     "sliding = yes is invalid: expected no beside friction"),
    ("viscoelastic material ice-bshp96 A 1e-5 rolling yes", "gamma = (not given) is invalid"),
])
def test_bad_pair_coeff_is_refused(coeff, message):
    code, out = L.run_lammps(dimer_script(10, coeff=coeff), check=False)
    assert code != 0 and message in out, out[-2000:]


def test_a_contact_narrower_than_xi_crit_stops_the_run():
    """xi_crit = 5e-8 m against a0 = 1.2e-8 m of these grains: stopped where the contact forms,
    naming xi_crit, a0 and the atoms."""
    code, out = L.run_lammps(dimer_script(10, coeff=f"{W07_ICE} rolling yes xi_crit 5e-8"), check=False)
    assert code != 0 and "xi_crit = 5e-08 is invalid: expected xi_crit < a0 = 1.23712e-08 m" in out, out[-2000:]


def test_fix_wall_refuses_the_springs():
    script = dimer_script(10).replace(f"pair_coeff * * {W07_ICE} {SPRINGS}", f"pair_coeff * * {W07_ICE}")
    script = script.replace("fix 1 all nve/sphere", f"fix 1 all nve/sphere\nfix w all wall/bounce zplane -1e-6 NULL "
                                                     f"{W07_ICE} rolling yes")
    code, out = L.run_lammps(script, check=False)
    assert code != 0 and "rolling = yes is invalid: expected no in fix wall/bounce" in out, out[-2000:]
