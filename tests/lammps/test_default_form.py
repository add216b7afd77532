"""Issue 40, point 23: the asperity law's default form is passive in LAMMPS too (docs/decisions.md
D12): a pair_coeff or fix wall/bounce that names no form is `asperity_form passive`, which creates no
energy (main's default, published, gave D12's -1.13). A restart file names the form; one written
before the change names none, and keeps the published form its springs hold (docs/lammps.md,
Restarts)."""
import os
import re
import tempfile

import lammps_runs as L

ICE = dict(material="ice-bshp96", radius=0.01)
D12 = dict(model="viscoelastic", A=1e-6, friction=0.014142, asperity=1e-6)  # zeta0 = 2e-4 R_eff
GAS = "viscoelastic E 1e7 nu 0.3 A 3e-6 friction 0.3 asperity 1e-6"


def test_default_pair_coeff_is_the_passive_form():
    """D12's collision (g^N = 1 m/s, g^T = 0.01 m/s) naming no form equals `asperity_form passive`
    bit for bit, with |eps^T| <= 1 and bounce's default within the geometry's 1.5e-3 at this g^N
    (test_pair_bounce); the published form, named, gives eps^T < -1."""
    runs = {form: L.head_on(ICE, dict(D12, **({"asperity_form": form} if form else {})), 1.0,
                            steps_per_contact=1000, tangential_velocity=0.01)
            for form in ("", "passive", "published")}
    eps_t, ref = runs[""][1], runs[""][2]
    assert eps_t == runs["passive"][1]
    assert abs(eps_t) <= 1.0 and abs(eps_t - ref["cor_tangential"]) <= 2e-3, (eps_t, ref["cor_tangential"])
    assert runs["published"][1] < -1.0, runs["published"][1]


def test_default_wall_is_the_passive_form():
    """fix wall/bounce naming no form equals `asperity_form passive` bit for bit (a linear spring,
    g^T below the first break) and differs from the published form."""
    eps = {form: L.wall_collision(ICE, dict(D12, **({"asperity_form": form} if form else {})), 0.1, 1000,
                                  tangential_velocity=0.001)[1]
           for form in ("", "passive", "published")}
    assert eps[""] == eps["passive"]
    assert abs(eps[""] - eps["published"]) > 1e-3, eps


def without_form(path, out):
    """The restart file `path` as a plugin from before issue 40 wrote it: its coefficients' text
    less ` asperity_form=...`, the text's length (the int before it) shortened to match."""
    data = open(path, "rb").read()
    start = data.index(b"A=3e-6 ")  # the text of pair_coeff 1 1, in key order
    length = int.from_bytes(data[start - 4:start], "little")
    text = data[start:start + length]
    shorter = re.sub(rb" asperity_form=\w+", b"", text)
    assert len(shorter) < len(text)
    with open(out, "wb") as f:
        f.write(data[:start - 4] + len(shorter).to_bytes(4, "little") + shorter + data[start + length:])


def test_a_restart_naming_no_form_keeps_the_published_form():
    """A gas with `asperity_form published` written to a restart mid-run; its file made into an old
    one (no form named) continues as the file naming the form, position for position, with a
    WARNING; the same with its pair_coeff given again without a form. A new file names the form."""
    continued = """
plugin load {plugin}
read_restart {restart}
{again}
neighbor 2e-4 bin
neigh_modify delay 0 every 1 check yes
fix 1 all nve/sphere
run 300
write_dump all custom {dump} id x y z vx vy vz modify sort id format float %.17g
"""
    with tempfile.TemporaryDirectory() as work:
        first = L.gas_script(GAS + " asperity_form published", cells=6, phi=0.3, dt=3e-6, steps=300, thermo=300,
                             skin=2e-4)
        L.run_in(work, first + "write_restart named.restart\n", 1, "in.first")
        L.run_in(work, L.gas_script(GAS, cells=2, phi=0.3, steps=1) + "write_restart new.restart\n", 1, "in.new")
        assert b"asperity_form=passive" in open(os.path.join(work, "new.restart"), "rb").read()
        without_form(os.path.join(work, "named.restart"), os.path.join(work, "old.restart"))
        logs = {}
        for name, restart, again in [("named", "named.restart", ""), ("old", "old.restart", ""),
                                     ("again", "old.restart", f"pair_coeff * * {GAS}")]:
            logs[name] = L.run_in(work, continued.format(plugin=L.PLUGIN, restart=restart, again=again,
                                                         dump=f"{name}.dump"), 1, f"in.{name}")
        dumps = {name: L.read_dump(os.path.join(work, f"{name}.dump")) for name in logs}
    assert dumps["old"] == dumps["named"] and dumps["again"] == dumps["named"]
    assert "WARNING" not in logs["named"]
    assert "names no asperity_form" in logs["old"] and "keeps the published form" in logs["old"]
    assert "pair_coeff * * names no asperity_form" in logs["again"]
