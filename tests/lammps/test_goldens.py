"""The golden LAMMPS runs (goldens.py, docs/lammps.md, Goldens) give today's numbers bit for bit:
two spheres with friction, krijt bouncing and sticking, jkr-viscoelastic with integration plain,
maugis-viscoelastic forming before touching, a wall with friction, restarts mid-contact on 1 and 2
ranks. The numbers are those of LAMMPS's release they were recorded with (the file's first line);
another release sums forces in its own order, so there the test is skipped."""
import os

import pytest

import goldens
import lammps_runs as L

GOLDEN = os.path.join(os.path.dirname(__file__), "..", "golden", "lammps_goldens.txt")


def test_lammps_runs_equal_their_goldens_bit_for_bit():
    with open(GOLDEN) as f:
        recorded = f.readline().strip()
    if goldens.version() != recorded:
        pytest.skip(f"goldens recorded with {recorded}, this is {goldens.version()}")
    lines = goldens.run_all()
    with open(GOLDEN) as f:
        golden = [l.rstrip("\n") for l in f if l.strip()]
    differ = [(old, new) for old, new in zip(golden, lines) if old != new]
    assert len(lines) == len(golden) and not differ, differ[:5]
