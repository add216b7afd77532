"""pair_style bounce in production runs (docs/lammps.md; issue 25's table, one test or more a row):
inserted grains, computes that ask for one pair's force, unlike types mixed by bounce's rule, the
explicit step's check, a zero skin, rigid bodies and frozen atoms, errors with stdout redirected.
(Row 1, the releases, is the whole suite passing on each; row 3, restarts, is test_restart.py.)"""
import math
import os
import subprocess
import tempfile

import pytest

import lammps_runs as L


def errors_of(output):
    return [line for line in output.splitlines() if line.startswith("ERROR")]


def warnings_of(output):
    return [line for line in output.splitlines() if line.startswith("WARNING") and "bounce" in line]


# Row 2: fix pour into an empty box.
POUR = f"""
units si
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 0.02 0 0.02 0 0.1
create_box 1 box
plugin load {{plugin}}
pair_style bounce
pair_coeff * * viscoelastic E 1e6 nu 0.3 A 1e-5 friction 0.5 asperity 1e-6
neighbor 2e-4 bin
neigh_modify delay 0
fix 1 all nve/sphere
fix 2 all gravity 9.81 vector 0 0 -1
fix floor all wall/bounce zplane 0 NULL viscoelastic E 1e6 nu 0.3 A 1e-5 friction 0.5 asperity 1e-6
region slab block 0 0.02 0 0.02 0.03 0.1
fix 3 all pour 300 1 4767548 vol 0.2 200 diam one 0.002 dens 1000 1000 region slab
compute touch all contact/atom
compute contacts all reduce sum c_touch
compute high all reduce max z
thermo_style custom step atoms ke c_contacts c_high
thermo_modify lost error
thermo 5000
timestep 1e-5
run 60000
print "END $(atoms) $(ke:%.17g) $(c_contacts) $(c_high:%.17g)"
"""


def test_pour_into_an_empty_box_settles():
    """300 grains poured into an empty box onto fix wall/bounce settle in contact: none lost, the
    kinetic energy below 1e-6 of their potential energy over the fall (~3e-4 J), about 3 contacts a
    grain, the heap under 1 cm. (The cutoff from fix pour's radius; it was 0, and the grains fell
    through each other: "Lost atoms".)"""
    _, output = L.run_lammps(POUR.format(plugin=L.PLUGIN))
    atoms, ke, contacts, high = [float(v) for v in output.split("\nEND ")[-1].split()[:4]]
    assert atoms == 300 and ke < 1e-9, (atoms, ke)
    assert contacts / 300 > 2.0 and high < 0.01, (contacts, high)


# Row 4: single(). Two hertz spheres pressed 10 um into each other, at rest.
PRESSED = L.preamble(0.1, 2) + """
create_atoms 1 single -0.009995 0 0
create_atoms 2 single 0.009995 0 0
set atom * diameter 0.02 density 1000
plugin load {plugin}
pair_style bounce
pair_coeff * * hertz E 1e9 nu 0.3 friction 0.3 asperity 1e-6
{computes}
run 0
"""


def test_pair_local_gives_the_contact_force():
    """compute pair/local dist force and compute property/local patom1 patom2 run (they were refused
    without single()): the force is Hertz's (4/3) E* sqrt(R) xi^{3/2} (E* = E/(2(1 - nu^2)), R = 5 mm,
    xi = 10 um) to 1e-12, its distance 2 cm - 10 um."""
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "pairs.dump")
        computes = f"""compute pl all pair/local dist force
compute pp all property/local patom1 patom2
dump out all local 1 {path} c_pl[1] c_pl[2] c_pp[1] c_pp[2]
dump_modify out format float %.17g
"""
        L.run_lammps(PRESSED.format(plugin=L.PLUGIN, computes=computes))
        rows = [line.split() for line in open(path).read().split("ITEM: ENTRIES")[-1].splitlines()[1:] if line.strip()]
    assert len(rows) == 1, rows
    d, f = float(rows[0][0]), float(rows[0][1])
    n = sorted(int(float(v)) for v in rows[0][2:4])
    e_star = 1e9 / (2 * (1 - 0.3 ** 2))
    hertz = 4 / 3 * e_star * math.sqrt(0.005) * 1e-5 ** 1.5
    assert abs(f - hertz) <= 1e-12 * hertz, (f, hertz)
    assert abs(d - (0.02 - 1e-5)) <= 1e-15 and n == [1, 2], (d, n)


# Row 5: unlike types mixed by bounce's rule.
ICE_QUARTZ = dict(material="ice-bshp96", material2="quartz", radius=0.01, radius2=0.004)


def test_unlike_types_mix_as_two_materials():
    """Types 1 (ice) and 2 (quartz) with the same model and A, no pair_coeff 1 2: the collision is
    the one with pair_coeff 1 2 ... material ice-bshp96 material2 quartz, to round-off (1e-12), and
    bounce's within 2e-5 at t_c/1000 (test_head_on_force_laws's bound)."""
    model = dict(model="viscoelastic", A=1e-5)
    mixed = "pair_coeff 1 1 viscoelastic material ice-bshp96 A 1e-5\npair_coeff 2 2 viscoelastic material quartz A 1e-5"
    eps_mixed, _, ref = L.head_on(ICE_QUARTZ, model, 1.0, coeff_lines=mixed)
    eps_given, _, _ = L.head_on(ICE_QUARTZ, model, 1.0)
    assert abs(eps_mixed - eps_given) <= 1e-12, (eps_mixed, eps_given)
    assert abs(eps_mixed - ref["cor"]) <= 2e-5, (eps_mixed, ref["cor"])


COLLISION = L.preamble(1.0, 2) + """
create_atoms 1 single 0 0 0
create_atoms 2 single 0.5 0 0
set atom * diameter 0.02 density 1000
plugin load {plugin}
pair_style bounce
{coeffs}
run 0
"""


@pytest.mark.parametrize("coeffs,expected", [
    ("pair_coeff 1 1 viscoelastic material ice-bshp96 A 1e-5\npair_coeff 2 2 viscoelastic material quartz A 2e-5",
     "A = 1e-5 for 1 1 but 2e-5 for 2 2"),
    ("pair_coeff 1 1 viscoelastic material ice-bshp96 A 1e-5\npair_coeff 2 2 hertz material quartz",
     "model = viscoelastic for 1 1 but hertz for 2 2"),
    ("pair_coeff 1 1 krijt material water-ice tvis 1e-11\npair_coeff 2 2 krijt material water-ice tvis 1e-11 z0 1e-9",
     "z0 = (not given) for 1 1 but 1e-9 for 2 2"),
])
def test_types_that_cannot_mix_are_refused_with_the_reason(coeffs, expected):
    code, output = L.run_lammps(COLLISION.format(plugin=L.PLUGIN, coeffs=coeffs), check=False)
    errors = errors_of(output)
    assert code != 0 and errors and expected in errors[0] and "pair_coeff 1 2" in errors[0], output[-2000:]


def test_types_mix_by_value_not_by_text():
    """tvis 1e-11 for 1 1 and 1.0e-11 for 2 2 are the same number: the types mix (they were refused
    as differing while the keys were compared as text), and the mixed collision is the one of
    pair_coeff 1 2 given."""
    one = "pair_coeff 1 1 jkr-viscoelastic material water-ice tvis 1e-11"
    mixed = one + "\npair_coeff 2 2 jkr-viscoelastic material water-ice tvis 1.0e-11"
    pair, model = dict(material="water-ice", radius=1e-6), dict(model="jkr-viscoelastic", tvis=1e-11)
    eps_mixed, _, _ = L.head_on(pair, model, 5.0, coeff_lines=mixed)
    eps_given, _, _ = L.head_on(pair, model, 5.0)
    assert eps_mixed == eps_given, (eps_mixed, eps_given)


# Rows 6 and 7: the explicit step's check from the contact's stiffness and damping.
@pytest.mark.parametrize("steps", [200, 1000])
def test_resolved_collisions_print_no_warning(steps):
    """A viscoelastic ice/quartz collision at t_c/200 and t_c/1000 prints no WARNING (at t_c/200 the
    period of the total force's secant, all damping at tiny overlaps, was 0.6 steps), and at t_c/1000
    its COR is bounce's within 2e-5."""
    eps, _, ref = L.head_on(ICE_QUARTZ, dict(model="viscoelastic", A=1e-5), 1.0, steps_per_contact=steps)
    assert not warnings_of(L.last_output), warnings_of(L.last_output)
    if steps == 1000:
        assert abs(eps - ref["cor"]) <= 2e-5


def test_damped_gas_prints_no_warning():
    """A gas of damped grains with friction (test_mpi's, 1000 steps of t_c/48) prints no WARNING."""
    script = L.gas_script("viscoelastic E 1e7 nu 0.3 A 3e-6 friction 0.3 asperity 1e-6", cells=12, phi=0.1, dt=3e-6,
                          steps=1000)
    _, output = L.run_lammps(script)
    assert not warnings_of(output), warnings_of(output)


STEEL = dict(material="steel", radius=1e-6, radius2=1.0)


@pytest.mark.parametrize("steps", [500, 50000])
def test_overdamped_contact_stops_lammps(steps):
    """Steel, 1 um against 1 m, A = 1e-6 s at 1 m/s: bounce's COR is 4e-14 (the grain stops in the
    damping), and an explicit step of t_c/500 or t_c/50 000 cannot integrate it (D dt/m_eff ~ 1e4 and
    1e2; the run gave a COR of 11 443 and 9.6 with a warning about the period): LAMMPS stops, naming
    the atoms, the damping and the largest stable step."""
    with pytest.raises(RuntimeError) as failed:
        L.head_on(STEEL, dict(model="viscoelastic", A=1e-6), 1.0, steps_per_contact=steps)
    errors = errors_of(str(failed.value))
    assert errors and "time step is too long for the contact of atoms" in errors[0], str(failed.value)[-2000:]
    assert "damping D =" in errors[0] and "dt <" in errors[0]


# A linear spring-dashpot (power-law with alpha = beta = 1, gamma = 0): F = m_eff (D1 xi + D2 xi'),
# k = m_eff D1, D = m_eff D2 exactly; stability = D1 dt^2/4 + q D2 dt with q = 1 (corrected) or
# 1/2 (plain). D1 = 1e6 /s^2, D2 = 1e3 /s: t_c ~ 3 ms.
LINEAR = dict(model="power-law", power_d1=1e6, power_alpha=1, power_d2=1e3, power_beta=1, power_gamma=0)


@pytest.mark.parametrize("integration,q", [("corrected", 1.0), ("plain", 0.5)])
def test_the_stability_limit_is_the_explicit_steps(integration, q):
    """At 0.95 of the step the check calls the limit the run ends (with a COR that is no longer the
    law's: 1.37 plain, a few steps a contact); at 1.05 it stops: the check is the linearised rule,
    exact for this law (steps found by solving D1 dt^2/4 + q D2 dt = s)."""
    d1, d2 = LINEAR["power_d1"], LINEAR["power_d2"]
    def step(s):
        return (-q * d2 + math.sqrt((q * d2) ** 2 + d1 * s)) / (d1 / 2)
    coeffs = "pair_coeff * * " + " ".join(f"{k} {v}" for k, v in LINEAR.items() if k != "model")
    coeffs = coeffs.replace("pair_coeff * * ", "pair_coeff * * power-law material steel ")
    for s, stable in ((0.95, True), (1.05, False)):
        script = L.preamble(1.0, 1) + f"""
create_atoms 1 single -0.0101 0 0
create_atoms 1 single 0.0101 0 0
set atom * diameter 0.02 density 1000
set atom 1 vx 0.5
set atom 2 vx -0.5
plugin load {L.PLUGIN}
pair_style bounce integration {integration}
{coeffs}
neighbor 0.001 bin
fix 1 all nve/sphere
timestep {step(s)!r}
run 400
print "V $(vx[2]-vx[1]:%.17g)"
"""
        code, output = L.run_lammps(script, check=False)
        if stable:
            assert code == 0 and abs(L.printed(output, "V")) < 2.0, output[-2000:]
        else:
            assert code != 0 and errors_of(output) and "too long" in errors_of(output)[0], output[-2000:]


# Row 8: a zero skin.
def test_zero_skin_is_accepted_without_adhesion():
    """neighbor 0.0 bin with a law that holds no contact beyond touching runs (it was refused: "stay
    in contact up to -0 m beyond touching"), as pair granular; an adhesive neck still needs a skin."""
    script = COLLISION.format(plugin=L.PLUGIN, coeffs="pair_coeff * * hertz material steel") + "neighbor 0.0 bin\nrun 10\n"
    code, output = L.run_lammps(script.replace("run 0\n", ""), check=False)
    assert code == 0, output[-2000:]
    script = COLLISION.format(plugin=L.PLUGIN, coeffs="pair_coeff * * jkr-viscoelastic material water-ice tvis 1e-11")
    code, output = L.run_lammps(script.replace("run 0\n", "neighbor 0.0 bin\nrun 0\n"), check=False)
    assert code != 0 and "beyond touching" in errors_of(output)[0], output[-2000:]


# Row 9: rigid bodies, frozen atoms, keys a fix does not use.
def rigid_collision(rigid):
    """Two dumbbells (two touching 1 cm spheres each, along x) meet head-on at 1 m/s with the linear
    law; `rigid`: each dumbbell a fix rigid body (else the front atoms are free spheres)."""
    lines = [f"create_atoms 1 single {x!r} 0 0" for x in (-0.0301, -0.0101, 0.0101, 0.0301)]
    integrate = ("fix 1 all rigid group 2 left right\nneigh_modify exclude group left left exclude group right right"
                 if rigid else "fix 1 all nve/sphere")
    coeffs = "pair_coeff * * power-law material steel " + " ".join(f"{k} {v}" for k, v in LINEAR.items() if k != "model")
    return L.preamble(1.0, 1) + "\n".join(lines) + f"""
set atom * diameter 0.02 density 1000
group left id 1 2
group right id 3 4
velocity all set 0 0 0
set atom 1*2 vx 0.5
set atom 3*4 vx -0.5
plugin load {L.PLUGIN}
pair_style bounce
{coeffs}
neighbor 0.001 bin
{integrate}
timestep 1e-6
run 6000
print "V $(vx[3]-vx[2]:%.17g)"
"""


def has_fix(style):
    """Whether the lmp has this fix style (RIGID is not in the make lammps build)."""
    out = subprocess.run([L.LMP, "-h"], capture_output=True, text=True).stdout
    return f" {style} " in out.split("* Fix styles:")[-1].split("* Compute styles:")[0]


@pytest.mark.skipif(not L.LMP or not has_fix("rigid"), reason="this lmp has no RIGID package (make lammps builds none)")
def test_rigid_bodies_take_their_mass():
    """The linear law's force carries m_eff: with the body masses (fix rigid, as pair granular's
    mass_rigid) two dumbbells bounce with the law's own COR exp(-pi zeta/sqrt(1 - zeta^2)) (zeta =
    D2/(2 sqrt(D1)) = 0.5: 0.163) to 1e-3 (the step's error at t_c/3000); with each atom's own mass
    it was 0.9018 against 0.8728 (the issue's report)."""
    zeta = LINEAR["power_d2"] / (2 * math.sqrt(LINEAR["power_d1"]))
    cor = math.exp(-math.pi * zeta / math.sqrt(1 - zeta ** 2))
    _, output = L.run_lammps(rigid_collision(True))
    assert abs(L.printed(output, "V") - cor) <= 1e-3, (L.printed(output, "V"), cor)


def test_a_frozen_atom_is_immovable():
    """A sphere hitting a frozen one (fix freeze) with the linear law: m_eff is the moving atom's mass
    (as pair granular), so its COR is the law's 0.163 to 1e-3 (with m_eff = m/2 the force would be
    halved and the COR another)."""
    zeta = LINEAR["power_d2"] / (2 * math.sqrt(LINEAR["power_d1"]))
    cor = math.exp(-math.pi * zeta / math.sqrt(1 - zeta ** 2))
    coeffs = "pair_coeff * * power-law material steel " + " ".join(f"{k} {v}" for k, v in LINEAR.items() if k != "model")
    script = L.preamble(1.0, 1) + f"""
create_atoms 1 single -0.0101 0 0
create_atoms 1 single 0.0101 0 0
set atom * diameter 0.02 density 1000
group wall id 2
group ball id 1
set atom 1 vx 1.0
plugin load {L.PLUGIN}
pair_style bounce
{coeffs}
neighbor 0.001 bin
fix 1 ball nve/sphere
fix 2 wall freeze
timestep 1e-6
run 6000
print "V $(-vx[1]:%.17g)"
"""
    _, output = L.run_lammps(script)
    assert abs(L.printed(output, "V") - cor) <= 1e-3, (L.printed(output, "V"), cor)


@pytest.mark.parametrize("keys,expected", [
    ("rigid_wall yes material2 steel", "material2 = steel is invalid"),
    ("rigid_wall yes E2 1e9", "E2 = 1e9 is invalid"),
    ("velocity 3", "velocity"),
    ("integration plain integration corrected", "integration is given twice"),
])
def test_wall_keys_it_does_not_use_are_refused(keys, expected):
    """fix wall/bounce ... rigid_wall yes material2 steel: a rigid wall has no moduli, and material2
    was silently ignored: refused, as any key the fix does not use."""
    script = COLLISION.format(plugin=L.PLUGIN, coeffs="pair_coeff * * hertz material steel").replace(
        "run 0\n", f"fix 2 all wall/bounce zplane -0.5 NULL viscoelastic material ice-bshp96 A 1e-5 {keys}\nrun 0\n")
    code, output = L.run_lammps(script, check=False)
    assert code != 0 and errors_of(output) and expected in errors_of(output)[0], output[-2000:]


# Row 10: a stop on one rank, with stdout not a terminal.
def test_a_stop_on_one_rank_reaches_a_redirected_stdout():
    """Two atoms at the same place stop LAMMPS on one rank (error->one, then MPI_Abort); with stdout a
    pipe and no stdbuf the ERROR line is in it (LAMMPS 2021 lost it: only Open MPI's abort notice)."""
    script = COLLISION.format(plugin=L.PLUGIN, coeffs="pair_coeff * * hertz material steel").replace(
        "create_atoms 2 single 0.5 0 0", "create_atoms 2 single 0 0 0")
    with tempfile.TemporaryDirectory() as work:
        path = os.path.join(work, "in.stop")
        with open(path, "w") as f:
            f.write(script)
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        done = subprocess.run(["mpirun", "-np", "1", L.LMP, "-in", path, "-log", "none"], capture_output=True,
                              text=True, cwd=work, env=env, timeout=300)
    assert done.returncode != 0
    assert "ERROR on proc 0: pair_style bounce: atoms 1 and 2 are at the same place" in done.stdout, done.stdout[-2000:]
