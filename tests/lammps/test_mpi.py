"""pair_style bounce over MPI: a granular gas of 10 648 spheres in a periodic box on one and on
two ranks (docs/lammps.md, MPI). Two ranks sum the forces on the atoms at the domain boundary
in another order, so the runs differ by round-off, which a granular gas amplifies (its
collisions are chaotic): over a short run they agree to round-off, over a long one only
statistically. The contact history crosses ranks with the atoms (FixNeighHistory): a lost or
doubled history would show as a difference far above round-off in the short run."""
import math
import os
import tempfile

import lammps_runs as L

# Soft viscoelastic grains (E = 1e7 Pa, R = 1 mm, eps ~ 0.89 at 1 m/s, t_c = 1.4e-4 s) at volume
# fraction 0.1, so that each grain collides every ~300 steps of dt = t_c/48.
COEFF = "viscoelastic E 1e7 nu 0.3 A 3e-6 friction 0.3 asperity 1e-6"
GAS = dict(phi=0.1, dt=3e-6)


def run(cores, steps, thermo, dump=None):
    script = L.gas_script(COEFF, steps=steps, thermo=thermo, dump=dump, **GAS)
    _, output = L.run_lammps(script, cores=cores)
    return L.thermo_rows(output)


def test_short_run_agrees_to_round_off():
    """1500 steps (about 5 collisions per grain): the kinetic energy on 1 and 2 ranks agrees to
    1e-12 relative and every position to 1e-10 of the box (measured: 6e-15 and 4e-13 of the
    box, round-off already grown by the collisions), while the gas lost 27% of its energy."""
    with tempfile.TemporaryDirectory() as work:
        one, two = os.path.join(work, "one.dump"), os.path.join(work, "two.dump")
        rows1 = run(1, 1500, 500, one)
        rows2 = run(2, 1500, 500, two)
        a, b = L.read_dump(one), L.read_dump(two)
    ke1, ke2 = rows1[-1][1], rows2[-1][1]
    assert ke1 < 0.9 * rows1[0][1]  # collisions happened
    assert abs(ke1 - ke2) <= 1e-12 * ke1, (ke1, ke2)
    box = 22 * 1e-3 * (4 * math.pi / (3 * 0.1)) ** (1 / 3)
    assert a.keys() == b.keys() and len(a) == 22 ** 3
    worst = 0.0
    for atom, p in a.items():
        q = b[atom]
        for k in range(3):
            d = abs(p[k] - q[k])
            worst = max(worst, min(d, box - d))  # periodic images
    assert worst <= 1e-10 * box, worst / box


def test_long_run_agrees_statistically():
    """15 000 steps (about 50 collisions per grain; the gas keeps 14% of its energy): the
    kinetic energy's decay on 1 and 2 ranks agrees within 2% at every output. The round-off
    grows by collisions (4e-9 relative at step 9000, 1e-5 at 15 000, measured), so beyond the
    short run the two are samples of the same cooling gas, not the same trajectory."""
    rows1 = run(1, 15000, 3000)
    rows2 = run(2, 15000, 3000)
    assert len(rows1) == len(rows2)
    for r1, r2 in zip(rows1, rows2):
        assert abs(r1[1] - r2[1]) <= 0.02 * r1[1], (r1, r2)
    assert rows1[-1][1] < 0.5 * rows1[0][1]  # it cooled
