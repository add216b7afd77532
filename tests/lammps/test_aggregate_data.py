"""Aggregates (docs/aggregates.md): the LAMMPS data file of `bounce aggregate build` is read by
LAMMPS (read_data, atom_style sphere, units si) with every monomer where bounce put it, its
diameter and its mass (density x 4/3 pi r^3). Needs only BOUNCE_LMP and BOUNCE_CLI (not the
plugin): by hand, BOUNCE_LMP=~/.cache/bounce/lammps-20220106.git7586adbb6a+ds1-2/build/lmp
BOUNCE_CLI=$PWD/build/bin/bounce /usr/bin/python3 -m pytest tests/lammps/test_aggregate_data.py."""
import math
import os
import subprocess

import pytest

LMP = os.environ.get("BOUNCE_LMP", "")
CLI = os.environ.get("BOUNCE_CLI", "")

pytestmark = pytest.mark.skipif(not (LMP and CLI), reason="needs BOUNCE_LMP and BOUNCE_CLI")

SCRIPT = """units si
atom_style sphere
atom_modify map array
boundary f f f
read_data agg.data
write_dump all custom read.txt id x y z diameter mass modify sort id format float %.17g
"""


def read_data_atoms(path):
    """{id: (diameter, density, x, y, z)} of the Atoms section bounce wrote."""
    with open(path) as f:
        lines = f.read().split("Atoms # sphere\n\n", 1)[1].splitlines()
    return {int(line.split()[0]): [float(v) for v in line.split()[2:]] for line in lines if line.strip()}


def read_dump(path):
    with open(path) as f:
        lines = f.read().split("ITEM: ATOMS id x y z diameter mass\n", 1)[1].splitlines()
    return {int(line.split()[0]): [float(v) for v in line.split()[1:]] for line in lines}


@pytest.mark.parametrize("kind,n", [("bpca", 300), ("bcca", 256)])
def test_lammps_reads_every_monomer_where_bounce_put_it(kind, n, tmp_path):
    subprocess.run([CLI, "aggregate", "build", "--kind", kind, "--n", str(n), "--radius", "1e-7", "--material",
                    "water-ice", "--seed", "3", "-o", str(tmp_path / "agg.data")], check=True, capture_output=True)
    (tmp_path / "in.agg").write_text(SCRIPT)
    done = subprocess.run([LMP, "-in", "in.agg", "-log", "none"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    assert f"{n} atoms" in done.stdout
    written, read = read_data_atoms(tmp_path / "agg.data"), read_dump(tmp_path / "read.txt")
    assert sorted(read) == list(range(1, n + 1))
    for i, (diameter, density, *x) in written.items():
        got = read[i]
        assert got[:3] == x  # %.17g both ways: the same doubles
        assert got[3] == diameter
        mass = density * math.pi / 6 * diameter**3  # LAMMPS's mass of a sphere from its density
        assert abs(got[4] - mass) <= 4e-16 * mass, (got[4], mass)  # a few roundings
