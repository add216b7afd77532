"""Aggregates colliding head-on in LAMMPS (docs/aggregates.md, Collisions; tools/aggregate_collision.py)
at 20 monomers each, the example's 1000 being an opt-in run (`make aggregate-collisions`): the
set-up puts every contact where it should be, a collision far below 5 E_roll sticks without
breaking a contact, one far above 10 n_c E_break disrupts the pair, and every monomer is
counted once. By hand: BOUNCE_LMP=... BOUNCE_PLUGIN=... BOUNCE_CLI=... /usr/bin/python3 -m pytest
tests/lammps/test_aggregate_collision.py."""
import os
import sys
import tempfile

import numpy as np
import pytest
from scipy.spatial.distance import cdist

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import aggregate_collision as ac  # noqa: E402
import lammps_runs  # noqa: E402

pytestmark = pytest.mark.skipif(not (lammps_runs.LMP and lammps_runs.PLUGIN and lammps_runs.CLI),
                                reason="needs BOUNCE_LMP, BOUNCE_PLUGIN and BOUNCE_CLI")

N = 20


@pytest.fixture(scope="module")
def pair():
    contact = ac.monomer_contact(lammps_runs.CLI)
    with tempfile.TemporaryDirectory() as work:
        a, b = (ac.build_aggregate(lammps_runs.CLI, N, seed, work) for seed in (1, 2))
    return a, b, contact


def test_every_tree_contact_starts_at_rest_and_the_aggregates_one_gap_apart(pair):
    a, b, contact = pair
    positions, velocities = ac.head_on(a, b, 2.0, contact["rest_overlap"])
    rest = 2 * ac.RADIUS - contact["rest_overlap"]
    for part in (positions[:N], positions[N:]):
        d = cdist(part, part)[np.triu_indices(N, 1)]
        tree = d[d < 2 * ac.RADIUS]
        assert len(tree) == N - 1  # every contact of the tree, and no other pair, within touching
        # JKR's rest distance to round-off: centres ~1 um from the centre of mass times 1e-16.
        assert np.max(np.abs(tree / rest - 1)) < 1e-12
    across = cdist(positions[:N], positions[N:]).min()
    assert abs(across - (2 * ac.RADIUS + ac.GAP)) < 1e-12 * ac.RADIUS
    assert np.allclose(velocities[:N, 0], 1.0) and np.allclose(velocities[N:, 0], -1.0)
    assert abs(positions.mean(axis=0)).max() < 1e-18  # the centre of mass at the origin


def test_a_collision_far_below_five_rolling_energies_sticks_without_breaking(pair):
    a, b, contact = pair
    r = ac.collide(a, b, 0.3, contact, cores=1)
    assert r["impact_energy"] < 0.05 * contact["E_roll"]  # 0.3 m/s: E = 0.008 E_roll
    assert r["contacts_start"] == 2 * (N - 1)
    assert r["outcome"] == "sticking" and r["fragments"] == [2 * N]
    assert r["broken"] == 0 and r["made_across"] >= 1  # held together by contacts between the two


def test_a_collision_far_above_ten_breaking_energies_a_contact_disrupts_the_pair(pair):
    a, b, contact = pair
    r = ac.collide(a, b, 80.0, contact, cores=1)
    n_c = 2 * (N - 1)
    assert r["impact_energy"] > 5 * 10 * n_c * contact["E_break"]  # 80 m/s: E = 58 n_c E_break
    assert r["outcome"] == "disruption" and r["fragments"][0] < N
    assert sum(r["fragments"]) == 2 * N and r["broken"] > N  # every monomer counted once


def test_fragments_are_the_connected_components():
    sizes, labels = ac.fragments(6, {(0, 1), (1, 2), (4, 5)})
    assert sorted(sizes.tolist()) == [1, 2, 3]
    assert labels[0] == labels[1] == labels[2] != labels[3] and labels[4] == labels[5] != labels[3]
