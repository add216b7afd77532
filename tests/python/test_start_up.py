"""Issue 40, point 24: a command that reads no atlas and runs on one rank loads neither libhdf5
(with the ~35 libraries it brings) nor Open MPI. In a shared build they are bounce's modules,
opened on first use (docs/architecture.md, "Modules"); a missing module is an installation
error naming it. Skipped for a static build (the pip wheel), which links them in.
"""
import os
import re
import shutil
import subprocess
import sys

import pytest

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
HEAVY = re.compile(r"libhdf5|libmpi|libopen-pal|libcurl|libgnutls|libkrb5")
MPI = re.compile(r"libmpi|libopen-pal|libopen-rte")


def needs(library, pattern):
    """Whether a shared object names a library matching `pattern` among its own NEEDED entries."""
    out = subprocess.run(["readelf", "-d", library], capture_output=True, text=True).stdout
    return any(pattern.search(line) for line in out.splitlines() if "(NEEDED)" in line)


def libraries(program):
    """{soname: path} of what the loader maps for `program` (ldd, from libc-bin)."""
    out = subprocess.run(["ldd", program], capture_output=True, text=True, check=True).stdout
    found = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) >= 3 and parts[1] == "=>":
            found[parts[0]] = parts[2]
    return found


def module_folder():
    libbounce = next((p for name, p in libraries(CLI).items() if name.startswith("libbounce.so")), None)
    if libbounce is None:
        pytest.skip("a static libbounce (the modules are linked in)")
    return os.path.join(os.path.dirname(libbounce), "bounce")


def test_the_cli_starts_without_hdf5_and_mpi():
    """main's CLI mapped 52 libraries, libhdf5's and Open MPI's among them: 13 ms to start."""
    folder = module_folder()
    modules = sorted(os.listdir(folder))
    assert modules in (["atlas_hdf5.so", "mpi.so"], ["atlas_hdf5.so"]), modules  # mpi.so where MPI was found
    mapped = libraries(CLI)
    heavy = [name for name in mapped if HEAVY.search(name) and not MPI.search(name)]
    assert heavy == [], heavy
    # Debian 13's SUNDIALS 7 links Open MPI itself (libsundials_core): there it is SUNDIALS's, not bounce's.
    if any(MPI.search(name) for name in mapped):
        core = [path for name, path in mapped.items() if name.startswith("libsundials_core")]
        assert core and needs(core[0], MPI), sorted(mapped)
    for module in modules:
        assert any(HEAVY.search(name) for name in libraries(os.path.join(folder, module))), module


def test_python_loads_hdf5_on_the_first_atlas_only():
    module_folder()
    script = ("import bounce, bounce.atlas\n"
              "maps = lambda: open('/proc/self/maps').read()\n"
              "print('before', 'libhdf5' in maps())\n"
              "try:\n"
              "    bounce.atlas.open('/nonexistent/atlas.h5')\n"
              "except ValueError as e:\n"
              "    print('refused', 'no such file' in str(e))\n"
              "print('after', 'libhdf5' in maps())\n")
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["before", "False", "refused", "True", "after", "True"]


def test_a_missing_module_is_an_installation_error_naming_it(tmp_path):
    """A libbounce without its modules folder beside it (LD_LIBRARY_PATH is searched before RUNPATH)."""
    folder = module_folder()
    libbounce = next(p for name, p in libraries(CLI).items() if name.startswith("libbounce.so"))
    shutil.copy(libbounce, tmp_path / os.path.basename(libbounce))
    env = dict(os.environ, LD_LIBRARY_PATH=str(tmp_path))
    done = subprocess.run([CLI, "atlas", "query", str(tmp_path / "a.h5"), "--radius", "1e-6", "--velocity", "1"],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 3
    assert done.stderr.startswith(f"bounce: installation error: bounce could not load its module {tmp_path}/bounce/"
                                  "atlas_hdf5.so"), done.stderr
    assert folder not in done.stderr
    if os.path.exists(os.path.join(folder, "mpi.so")):  # a CLI built with MPI opens it under a launcher
        done = subprocess.run([CLI, "fit", "--batch", str(tmp_path / "none.toml")], capture_output=True, text=True,
                              env=dict(env, OMPI_COMM_WORLD_SIZE="1"))
        assert done.returncode == 3
        assert f"{tmp_path}/bounce/mpi.so" in done.stderr, done.stderr
    # The same CLI with its modules reads on: exit 2 for the missing atlas, naming it.
    done = subprocess.run([CLI, "atlas", "query", str(tmp_path / "a.h5"), "--radius", "1e-6", "--velocity", "1"],
                          capture_output=True, text=True)
    assert done.returncode == 2 and "no such file" in done.stderr
