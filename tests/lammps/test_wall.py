"""fix wall/bounce: a sphere against a flat wall in LAMMPS against `bounce collide --wall` (an
elastic wall of material2, default the sphere's) and `--rigid-wall` (docs/lammps.md, Walls)."""
import math

import pytest

import lammps_runs as L

ICE = dict(material="ice-bshp96", radius=0.01)
ROUGH = dict(model="viscoelastic", A=1e-6, friction=math.sqrt(2e-4), asperity=2e-6)


@pytest.mark.parametrize("pair,model,velocity", [
    (ICE, dict(model="viscoelastic", A=1e-5), 1.0),
    (dict(ICE, material2="quartz"), dict(model="viscoelastic", A=1e-5), 1.0),
    (dict(ICE, rigid_wall="yes"), dict(model="viscoelastic", A=1e-5), 1.0),
    (ICE, dict(model="viscoelastic", A=1e-5, contact_end="force"), 1.0),
    (dict(material="water-ice", radius=1e-6), dict(model="jkr-viscoelastic", tvis=1e-11), 3.0),
    (dict(material="water-ice", radius=1e-6), dict(model="jkr-viscoelastic", tvis=1e-11, contact_end="pull-off"), 3.0),
], ids=["elastic-wall", "quartz-wall", "rigid-wall", "force-rule", "jkr-fold", "jkr-pull-off"])
def test_wall_head_on(pair, model, velocity):
    """Within 2e-5 of bounce at t_c/1000 (measured <= 8e-6), converging (t_c/4000: 4x smaller)."""
    errors = []
    for n in (1000, 4000):
        eps, _, ref = L.wall_collision(pair, model, velocity, n)
        errors.append(eps - ref["cor"])
    assert abs(errors[0]) <= 2e-5, errors
    assert abs(errors[1]) * 4 <= abs(errors[0]), errors


@pytest.mark.parametrize("form", ["published", "passive"])
@pytest.mark.parametrize("tangential", [0.001, 0.1], ids=["spring", "sliding"])
def test_wall_oblique(tangential, form):
    """eps^T within 1e-3 at t_c/2000. Published form: measured 4e-9 for the spring (a flat wall does
    not turn the contact's frame), 6e-5 sliding (the breaks' timing); passive, the default: 2e-5 and
    1.3e-5 (not second order in dt: docs/lammps.md, Walls)."""
    eps_n, eps_t, ref = L.wall_collision(ICE, dict(ROUGH, asperity_form=form), 0.1, 2000,
                                         tangential_velocity=tangential)
    assert abs(eps_t - ref["cor_tangential"]) <= 1e-3, (eps_t, ref["cor_tangential"])
    assert abs(eps_n - ref["cor"]) <= 2e-5, (eps_n, ref["cor"])


@pytest.mark.parametrize("wall,expected", [
    ("wplane 0 NULL viscoelastic material ice-bshp96 A 1e-5", "wall = wplane is invalid"),
    ("zplane NULL NULL viscoelastic material ice-bshp96 A 1e-5", "no wall"),
    ("zplane 1 0 viscoelastic material ice-bshp96 A 1e-5", "LO = 1 is invalid"),
    ("zplane 0 NULL viscoelastic material ice-bshp96 A 1e-5 rigid_wall maybe", "rigid_wall = maybe is invalid"),
    ("zplane 0 NULL viscoelastic material ice-bshp96 A -2", "A = -2 is invalid"),
    ("zplane 0 NULL viscoelastic material ice-bshp96 A 1e-5 wall yes", "wall = yes is invalid"),
    ("zplane 0 NULL viscoelastic material ice-bshp96 A 1e-5 rigid_wall yes E2 1e9", "E2 = 1e9 is invalid"),
    ("zplane 0 NULL krijt material water-ice tvis 1e-11", "krijt acts between atoms only"),
])
def test_bad_wall_stops_lammps_naming_it(wall, expected):
    script = f"""
units si
atom_style sphere
region box block -1 1 -1 1 -1 1
create_box 1 box
create_atoms 1 single 0 0 0.5
plugin load {L.PLUGIN}
fix 2 all wall/bounce {wall}
run 0
"""
    code, output = L.run_lammps(script, check=False)
    errors = [line for line in output.splitlines() if line.startswith("ERROR")]
    assert code != 0 and errors and expected in errors[0], output[-2000:]


def test_atom_behind_the_wall_feels_nothing():
    """An atom whose centre is behind the wall (here 5 cm below a floor at z = 0) keeps still."""
    script = L.preamble(0.2, 1) + f"""
create_atoms 1 single 0 0 -0.05
set type 1 diameter 0.02 density 1000
plugin load {L.PLUGIN}
pair_style bounce
pair_coeff * * viscoelastic material ice-bshp96 A 1e-5
fix 1 all nve/sphere
fix 2 all wall/bounce zplane 0.0 NULL viscoelastic material ice-bshp96 A 1e-5
timestep 1e-6
run 100
print "VZ $(vz[1]:%.17g)"
"""
    _, output = L.run_lammps(script)
    assert L.printed(output, "VZ") == 0.0
