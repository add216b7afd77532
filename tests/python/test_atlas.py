"""The collision atlas from Python (docs/atlas.md): bounce.atlas.open, numpy broadcasting to
(Nr, Nm, Nm) grids, agreement with bounce.collide within the stored error, p_stick against its
closed form, the file read by h5py (self-describing), and the one rule for bad input.

Run by `make test` through CTest (PYTHONPATH=build/python, BOUNCE_CLI=build/bin/bounce).
"""
import math
import os
import shutil
import signal
import subprocess
import time

import numpy as np
import pytest

import bounce
import bounce.atlas

CLI = os.environ.get("BOUNCE_CLI", "build/bin/bounce")
RADII = (2e-6, 1e-5)  # grain radii whose R_eff lies in the atlas's 1-10 um for any pair


@pytest.fixture(scope="module")
def path(tmp_path_factory):
    out = str(tmp_path_factory.mktemp("atlas") / "ice.h5")
    subprocess.run([CLI, "atlas", "build", "--model", "krijt", "--tvis", "1e-11", "--materials", "water-ice",
                    "--radius", "1e-6:1e-5:4", "--velocity", "0.3:20:5", "--tol", "1e-3", "-o", out],
                   check=True, capture_output=True)
    return out


@pytest.fixture(scope="module")
def atlas(path):
    return bounce.atlas.open(path, model="krijt")


def test_lookups_broadcast_to_coagulation_grids(atlas):
    nr, nm = 3, 20
    a = np.geomspace(*RADII, nm)
    r1 = np.broadcast_to(a[None, :, None], (nr, nm, nm))
    r2 = np.broadcast_to(a[None, None, :], (nr, nm, nm))
    v = np.linspace(1.0, 15.0, nr)[:, None, None]
    cor = atlas.cor(r1, r2, v)
    assert cor.shape == (nr, nm, nm)
    assert np.all((cor >= 0) & (cor <= 1))
    np.testing.assert_array_equal(cor, cor.transpose(0, 2, 1))  # like materials: symmetric in R1, R2
    sticks = atlas.sticks(r1, r2, v)
    assert sticks.dtype == bool and np.array_equal(sticks, cor == 0)
    assert atlas.v_stick(a[:, None], a[None, :]).shape == (nm, nm)
    assert isinstance(atlas.cor(3e-6, 4e-6, 5.0), float)


def test_agrees_with_collide_within_the_stored_error(atlas):
    rng = np.random.default_rng(3)
    model = bounce.Model("krijt", tvis=1e-11)
    for _ in range(40):
        r1, r2 = np.exp(rng.uniform(*np.log(RADII), 2))
        v = math.exp(rng.uniform(math.log(0.3), math.log(20.0)))
        pair = bounce.Pair(material="water-ice", radius=r1, radius2=r2)
        direct = bounce.collide(pair, model, v)
        if (direct["outcome"] == "stick") != bool(atlas.sticks(r1, r2, v)):
            assert abs(v / atlas.v_stick(r1, r2) - 1) <= atlas.v_stick_error
            continue
        assert abs(atlas.cor(r1, r2, v) - direct["cor"]) <= atlas.cor_error


def test_p_stick_is_the_maxwellian_probability_below_v_stick(atlas):
    r1, r2, sigma = 3e-6, 5e-6, 3.0
    x = atlas.v_stick(r1, r2) / sigma
    closed = math.erf(x / math.sqrt(2)) - math.sqrt(2 / math.pi) * x * math.exp(-x * x / 2)
    assert atlas.p_stick(r1, r2, sigma) == pytest.approx(closed, rel=1e-12)
    # The same through a user pdf (Gauss-Legendre, 64 points: exact to round-off for this smooth pdf).
    def maxwell(v, s):
        return math.sqrt(2 / math.pi) * v * v / s**3 * np.exp(-v * v / (2 * s * s))
    assert atlas.p_stick(r1, r2, sigma, distribution=maxwell) == pytest.approx(closed, rel=1e-9)
    # A pdf concentrated far below the atlas's top speed (the quadrature follows sigma).
    assert atlas.p_stick(r1, r2, 0.5, distribution=maxwell) == pytest.approx(atlas.p_stick(r1, r2, 0.5), rel=1e-9)
    # Small speeds: no cancellation (P(3/2, x^2/2) ~ x^3 / (3 sqrt(pi/2)) ... = sqrt(2/pi) x^3 / 3).
    assert bounce.atlas.maxwell_cdf(1e-8, 1.0) == pytest.approx(math.sqrt(2 / math.pi) * 1e-24 / 3, rel=1e-6)
    grid = atlas.p_stick(np.full((2, 4, 1), r1), np.full((2, 1, 4), r2), np.array([2.5, 3.0])[:, None, None])
    assert grid.shape == (2, 4, 4) and np.all((grid >= 0) & (grid <= 1))


def test_the_file_describes_itself_to_h5py(path, atlas):
    h5py = pytest.importorskip("h5py")
    with h5py.File(path, "r") as f:
        assert f.attrs["format"] == b"bounce-atlas" and f.attrs["model"] == b"krijt"
        assert f["parameters/tvis"].attrs["value"] == b"1e-11" and f["parameters/tvis"].attrs["unit"] == b"s"
        assert f["materials/body1/density"].attrs["unit"] == b"kg/m^3"
        assert f["grid/values"].shape[0] == 4
        assert f["errors/cor"][0] == atlas.cor_error
    assert atlas.describe()["model"] == "krijt"


@pytest.mark.parametrize("call, name", [
    (lambda a: a.cor(3e-6, 4e-6, 50.0), "velocity"),
    (lambda a: a.cor(1e-7, 1e-7, 1.0), "radius"),
    (lambda a: a.v_stick(-1.0, 2e-6), "radius1"),
    (lambda a: a.p_stick(3e-6, 4e-6, 0.0), "sigma_v"),
    (lambda a: a.p_stick(3e-6, 4e-6, 30.0), "sigma_v"),   # much of it above 20 m/s
    (lambda a: a.p_stick(np.full((2, 3), 3e-6), np.full((2, 3), 4e-6), np.full((2, 3), 30.0)), "sigma_v"),
    (lambda a: a.p_stick(3e-6, 4e-6, 5.0, distribution="gauss"), "distribution"),
    (lambda a: a.p_stick(3e-6, 4e-6, 3.0, max_outside=float("nan")), "max_outside"),
    (lambda a: a.p_stick(3e-6, 4e-6, 3.0, nodes=2), "nodes"),
    (lambda a: a.p_stick(3e-6, 4e-6, 3.0, distribution=lambda v, s: 3 * np.exp(-v / s) / s), "distribution"),
    (lambda a: bounce.atlas.maxwell_cdf(-1.0, 1.0), "velocity"),
    (lambda a: bounce.atlas.maxwell_cdf(1.0, 0.0), "sigma_v"),
])
def test_bad_queries_name_the_value_and_the_range(atlas, call, name):
    with pytest.raises(ValueError, match=rf"^{name} = .+ is invalid: expected .+"):
        call(atlas)


def test_other_files_are_refused(path, tmp_path):
    with pytest.raises(ValueError, match="model = viscoelastic is invalid"):
        bounce.atlas.open(path, model="viscoelastic")
    text = tmp_path / "data.csv"
    text.write_text("velocity,cor\n1,0.5\n")
    with pytest.raises(ValueError, match="is invalid: expected an atlas"):
        bounce.atlas.open(str(text))
    with pytest.raises(TypeError, match="path = 3 is invalid"):
        bounce.atlas.open(3)
    import pathlib
    assert bounce.atlas.open(pathlib.Path(path)).model == "krijt"


def test_hostile_files_are_refused(path, tmp_path):
    """Files with valid HDF5 that would make a careless reader overrun a buffer or allocate
    gigabytes: an array where one value is expected, a huge dataset declared and never written."""
    h5py = pytest.importorskip("h5py")
    array = tmp_path / "array.h5"
    shutil.copy(path, array)
    with h5py.File(array, "r+") as f:
        del f.attrs["format_version"]
        f.attrs["format_version"] = np.ones(4000)
    with pytest.raises(ValueError, match="format_version holds one value"):
        bounce.atlas.open(str(array))
    huge = tmp_path / "huge.h5"
    shutil.copy(path, huge)
    with h5py.File(huge, "r+") as f:
        n = f["grid/values"].shape
        del f["grid/values"]
        f.create_dataset("grid/values", shape=(4, n[1], n[2], n[3] * 1000), dtype="f8", chunks=True)
        del f["grid/z_ln_velocity_above_v_stick"]
        z = f.create_dataset("grid/z_ln_velocity_above_v_stick", data=np.arange(n[3] * 1000, dtype=float))
        z.attrs["start"], z.attrs["step"], z.attrs["unit"] = 0.0, 1.0, np.bytes_("ln(m/s)")
    with pytest.raises(ValueError, match="stores its"):
        bounce.atlas.open(str(huge))


BUILD = ["atlas", "build", "--model", "krijt", "--tvis", "1e-11", "--materials", "water-ice",
         "--radius", "1e-6:1e-5:4", "--velocity", "0.3:20:5", "--tol", "1e-3"]
# As root, OpenMPI's documented switches (the CI runs as root).
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def _values(path):
    h5py = pytest.importorskip("h5py")
    with h5py.File(path, "r") as f:
        return f.attrs["checksum"], f["grid/values"][()]


@pytest.mark.skipif(shutil.which("mpirun") is None, reason="OpenMPI's mpirun is not installed")
def test_two_mpi_ranks_build_the_same_atlas(path, tmp_path):
    out = str(tmp_path / "ranks.h5")
    r = subprocess.run(["mpirun", "--oversubscribe", "-np", "2", CLI, *BUILD, "--threads", "1", "-o", out],
                       capture_output=True, text=True, env=MPI_ENV)
    assert r.returncode == 0, r.stderr
    assert r.stdout.count("written to") == 1  # rank 0 alone writes and reports
    (sum_ranks, ranks), (sum_alone, alone) = _values(out), _values(path)
    assert sum_ranks == sum_alone
    np.testing.assert_array_equal(ranks, alone)


def test_an_interrupted_build_leaves_no_atlas_and_resumes(path, tmp_path):
    out = tmp_path / "cut.h5"
    run = subprocess.Popen([CLI, *BUILD, "-o", str(out)], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    cache = tmp_path / "cut.h5.partial"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and run.poll() is None:
        if cache.exists() and cache.stat().st_size > 20000:
            break
        time.sleep(0.05)
    run.send_signal(signal.SIGINT)
    _, err = run.communicate(timeout=60)
    assert run.returncode == 130, err
    assert not out.exists() and not (tmp_path / "cut.h5.writing").exists()
    done = sum(1 for line in cache.read_text().splitlines() if line.startswith(("c ", "s ")))
    assert done > 10
    again = subprocess.run([CLI, *BUILD, "-o", str(out), "--progress"], capture_output=True, text=True)
    assert again.returncode == 0, again.stderr
    assert not cache.exists()  # gone once the atlas is written
    np.testing.assert_array_equal(_values(str(out))[1], _values(path)[1])
