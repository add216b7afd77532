"""`bounce fit --batch` over MPI (docs/fitting.md): the same output for 1, 2 and 4 ranks and
without mpirun; a batch killed with SIGKILL continues from its checkpoint without recomputing
finished blocks and ends byte-identical; a bad manifest is one error line, exit 2."""
import os
import shutil
import signal
import subprocess
import time

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
# OpenMPI refuses to run as root unless told (its documented switches); CI runs as root.
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

MANIFEST = """
[defaults]
threads = 1

[[experiment]]
name = "bridges ice"
data = "bridges-ice.csv"
material = "ice-bshp96"
radius = 1e-2
model = "viscoelastic"
grid = "A=1e-7:1e-3:150"

[[experiment]]
name = "psl on quartz"
data = "synthetic-psl-quartz.csv"
material = "psl"
radius = 0.635e-6
wall = true
material2 = "quartz"
grid = "gamma=0.02:0.1:{n},tvis=1e-12:1e-11:{n},yield=1e8:1e9:30"
"""

needs_mpirun = pytest.mark.skipif(shutil.which("mpirun") is None, reason="OpenMPI's mpirun is not installed")


def _manifest(tmp_path, n):
    for f in ("bridges-ice.csv", "synthetic-psl-quartz.csv"):
        shutil.copy(os.path.join(ROOT, "data", "experiments", f), tmp_path / f)
    path = tmp_path / "manifest.toml"
    path.write_text(MANIFEST.format(n=n))
    return path


def _mpirun(n, *args):
    return ["mpirun", "--oversubscribe", "-np", str(n), CLI, "fit", *args]


@needs_mpirun
def test_output_is_the_same_for_any_number_of_ranks(tmp_path):
    manifest = str(_manifest(tmp_path, 8))
    alone = subprocess.run([CLI, "fit", "--batch", manifest, "--json"], check=True, capture_output=True, text=True).stdout
    assert '"psl on quartz"' in alone
    for n in (1, 2, 4):
        out = subprocess.run(_mpirun(n, "--batch", manifest, "--json"), check=True, capture_output=True, text=True,
                             env=MPI_ENV).stdout
        assert out == alone, f"{n} ranks"


@needs_mpirun
def test_killed_batch_continues_from_its_checkpoint(tmp_path):
    manifest = str(_manifest(tmp_path, 20))  # 3 + 7 blocks of 60 points, a few seconds
    reference = subprocess.run([CLI, "fit", "--batch", manifest, "--json"], check=True, capture_output=True,
                               text=True).stdout
    checkpoint = tmp_path / "ck"
    run = subprocess.Popen(_mpirun(2, "--batch", manifest, "--checkpoint", str(checkpoint), "--json"),
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=MPI_ENV, start_new_session=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and run.poll() is None:
        if checkpoint.is_dir() and sum(f.suffix == ".block" for f in checkpoint.iterdir()) >= 3:
            break
        time.sleep(0.05)
    os.killpg(run.pid, signal.SIGKILL)
    run.wait()
    finished = sum(f.suffix == ".block" for f in checkpoint.iterdir())
    assert 3 <= finished < 10, "the batch should be killed part-way"
    again = subprocess.run(_mpirun(2, "--batch", manifest, "--checkpoint", str(checkpoint), "--json"), check=True,
                           capture_output=True, text=True, env=MPI_ENV)
    assert again.stdout == reference
    # The finished blocks were read, not recomputed (the restart says how many it read).
    read = int(again.stderr.split("bounce fit --batch: ")[1].split(" of ")[0])
    assert read >= finished


@needs_mpirun
def test_bad_manifest_is_one_error_line(tmp_path):
    manifest = _manifest(tmp_path, 8)
    manifest.write_text(manifest.read_text().replace("radius = 1e-2", "radius = -1"))
    r = subprocess.run(_mpirun(2, "--batch", str(manifest)), capture_output=True, text=True, env=MPI_ENV)
    assert r.returncode == 2
    assert r.stdout == ""
    lines = [l for l in r.stderr.splitlines() if l.startswith("bounce:")]
    assert lines == [f"bounce: error: {manifest}: bridges ice: radius = -1 is invalid: expected radius [m] > 0 and finite"]


@needs_mpirun
def test_error_on_another_rank_alone_is_printed_by_rank_0(tmp_path):
    # A damaged checkpoint block of unit 1 (the bridges' points 60-119), which rank 1 of 2 reads
    # and rank 0 never sees: rank 0 prints rank 1's error as its own, once, and exits with its code.
    manifest = _manifest(tmp_path, 8)
    checkpoint = tmp_path / "ck"
    checkpoint.mkdir()
    damaged = checkpoint / "experiment-1-points-60.block"
    damaged.write_text("not a block\n")
    r = subprocess.run(_mpirun(2, "--batch", str(manifest), "--checkpoint", str(checkpoint)), capture_output=True,
                       text=True, env=MPI_ENV)
    assert r.returncode == 2
    assert r.stdout == ""
    lines = [l for l in r.stderr.splitlines() if l.startswith("bounce:")]
    assert lines == [f"bounce: error: --checkpoint = {damaged} is invalid: expected a block of this manifest's fits "
                     "(the manifest or its data changed: use an empty directory)"]
