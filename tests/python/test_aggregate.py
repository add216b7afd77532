"""Aggregates from Python and the CLI (docs/aggregates.md): bounce.build_aggregate gives the
CLI's JSON keys with the same values, the centres as a numpy array that hold the geometry (no
overlap, n - 1 contacts), the same array for the same seed, and the one rule for bad input
(ValueError / TypeError in Python, exit 2 on the command line).

Run by `make test` through CTest (PYTHONPATH=build/python, BOUNCE_CLI=build/bin/bounce).
"""
import json
import os
import subprocess

import numpy as np
import pytest

import bounce

CLI = os.environ.get("BOUNCE_CLI", "build/bin/bounce")


def cli(*args):
    return subprocess.run([CLI, "aggregate", "build", *args], capture_output=True, text=True)


def test_python_and_cli_give_the_same_aggregate(tmp_path):
    out = tmp_path / "a.data"
    done = cli("--kind", "bcca", "--n", "128", "--radius", "1e-7", "--material", "water-ice", "--seed", "9",
               "-o", str(out), "--json")
    assert done.returncode == 0, done.stderr
    record = json.loads(done.stdout)
    got = bounce.build_aggregate("bcca", 128, 1e-7, material="water-ice", seed=9, output=tmp_path / "p.data")
    assert {k: v for k, v in got.items() if k not in ("positions", "history")} == record
    assert (tmp_path / "p.data").read_text() == out.read_text()  # the same file, byte for byte
    assert record["contacts"] == 127 and record["density"] == bounce.material("water-ice")["density"]


def test_positions_hold_the_geometry_and_the_seed_fixes_them():
    got = bounce.build_aggregate("bpca", 400, 2e-7, density=2650.0, seed=4)
    x = got["positions"]
    assert x.shape == (400, 3) and x.dtype == np.float64
    d = np.sqrt(((x[:, None, :] - x[None, :, :]) ** 2).sum(-1))[np.triu_indices(400, 1)]
    # 1e-12 of 2r: the round-off of centres a few tens of r from the origin (docs/aggregates.md)
    assert d.min() >= 4e-7 * (1 - 1e-12)
    assert ((d <= 4e-7 * (1 + 1e-12))).sum() == 399
    assert np.abs(x.mean(axis=0)).max() < 1e-12 * 2e-7 * 40  # centred to round-off
    assert np.array_equal(x, bounce.build_aggregate("bpca", 400, 2e-7, density=2650.0, seed=4)["positions"])
    assert not np.array_equal(x, bounce.build_aggregate("bpca", 400, 2e-7, density=2650.0, seed=5)["positions"])
    history = got["history"]
    assert history["n"][-1] == 400 and history["radius_of_gyration"][-1] == pytest.approx(got["radius_of_gyration"])


def test_ensemble_fit_is_reported_beside_the_aggregates_own():
    got = bounce.build_aggregate("bcca", 1024, 1e-7, material="water-ice", seed=1, ensemble=10)
    assert got["fractal_dimension"]["over"] == "growth history of this aggregate"
    assert got["ensemble"]["n_min"] == 16 and 1.7 < got["ensemble"]["dimension"] < 2.1  # measured 1.84-1.93


@pytest.mark.parametrize("kwargs,message", [
    (dict(kind="bcca", n=1000), "n = 1000 is invalid: expected a power of 2"),
    (dict(kind="bpca", n=0), "n = 0 is invalid: expected"),
    (dict(kind="bpca", n=2.5), "n = 2.5 is invalid: expected"),
    (dict(kind="bpca", n=131073), "n = 131073 is invalid: expected"),
    (dict(kind="ppca", n=10), "kind = ppca is invalid: expected"),
    (dict(kind="bpca", n=10, radius=-1.0), "radius = -1 is invalid: expected"),
    (dict(kind="bpca", n=10, material="unobtainium"), "material = unobtainium is invalid: expected"),
    (dict(kind="bpca", n=10, material=None), "material = (not given) is invalid: expected"),
    (dict(kind="bpca", n=10, seed=-1), "seed = -1 is invalid: expected"),
    (dict(kind="bcca", n=16, ensemble=5), "ensemble = 5 is invalid: expected 0 below 32 monomers for bcca"),
])
def test_bad_input_is_refused_by_the_one_rule(kwargs, message):
    args = dict(dict(radius=1e-7, material="water-ice"), **kwargs)
    with pytest.raises(ValueError) as e:
        bounce.build_aggregate(args.pop("kind"), args.pop("n"), args.pop("radius"), **args)
    assert str(e.value).startswith(message), str(e.value)


def test_wrong_types_are_type_errors():
    with pytest.raises(TypeError, match="n = '10' is invalid"):
        bounce.build_aggregate("bpca", "10", 1e-7, material="water-ice")
    with pytest.raises(TypeError, match="seed = True is invalid"):
        bounce.build_aggregate("bpca", 10, 1e-7, material="water-ice", seed=True)


@pytest.mark.parametrize("args,message", [
    (["--kind", "bcca", "--n", "1000"], "--n = 1000 is invalid: expected a power of 2"),
    (["--kind", "bpca", "--n", "1e9"], "--n = 1e9 is invalid: expected"),
    (["--kind", "bpca", "--n", "10", "--radius", "0"], "--radius = 0 is invalid: expected"),
    (["--kind", "bpca", "--n", "10", "--seed", "1.5"], "--seed = 1.5 is invalid: expected"),
    (["--kind", "bpca", "--n", "10", "--radius", "1e-7"], "--output = (not given) is invalid: expected"),
    (["--kind", "bpca", "--n", "10", "--radius", "1e-7", "-o", "/nonexistent/a.data"],
     "--output = /nonexistent/a.data is invalid: expected a file in an existing folder"),
])
def test_cli_refuses_bad_input_with_exit_2(args, message, tmp_path):
    full = args + (["--material", "water-ice"] if "--radius" in args else ["--radius", "1e-7", "--material", "water-ice"])
    if "-o" not in full and "output" not in message:
        full += ["-o", str(tmp_path / "a.data")]
    done = cli(*full)
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.startswith("bounce: error: " + message), done.stderr
    assert not list(tmp_path.iterdir())  # nothing written


def test_text_output_names_the_file_and_the_dimension(tmp_path):
    done = cli("--kind", "bpca", "--n", "1000", "--radius", "1e-7", "--material", "water-ice", "--seed", "1",
               "-o", str(tmp_path / "a.data"))
    assert done.returncode == 0, done.stderr
    assert "bpca aggregate of 1000 monomers" in done.stdout and "999 contacts" in done.stdout
    assert "over n = 100 to 1000" in done.stdout and f"written to {tmp_path / 'a.data'}" in done.stdout


@pytest.mark.parametrize("kind", ["bpca", "bcca"])
def test_one_monomer_is_an_aggregate_with_no_pair(kind):
    got = bounce.build_aggregate(kind, 1, 1e-7, material="water-ice")
    assert got["contacts"] == 0 and got["min_distance"] is None and got["fractal_dimension"] is None
    assert got["positions"].tolist() == [[0.0, 0.0, 0.0]] and got["radius_of_gyration"] == 0.0


def test_ctrl_c_interrupts_a_long_build():
    """The largest BPCA takes seconds: a SIGINT after 0.5 s raises KeyboardInterrupt within the next
    1024 monomers (the build checks between them), well before the build would end."""
    script = ("import bounce, os, signal, threading, time\n"
              "threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()\n"
              "t = time.time()\n"
              "try:\n"
              "    bounce.build_aggregate('bpca', 131072, 1e-7, material='water-ice')\n"
              "    print('finished')\n"
              "except KeyboardInterrupt:\n"
              "    print('interrupted', time.time() - t)\n")
    done = subprocess.run(["/usr/bin/python3", "-c", script], capture_output=True, text=True, timeout=120,
                          env=dict(os.environ))
    word, *seconds = done.stdout.split()
    assert word == "interrupted" and float(seconds[0]) < 2.0, done.stdout + done.stderr  # the build alone: 4.6 s
