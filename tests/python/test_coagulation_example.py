"""The Smoluchowski example with the atlas as its kernel (examples/coagulation/smoluchowski.py):
mass conservation, the constant kernel against its closed form, the kernel's bounds, bad input.

Builds its own small atlas with the CLI (about 6 s; the whole file takes about 12 s). Run by
`make test` through CTest (PYTHONPATH=build/python, BOUNCE_CLI=build/bin/bounce); without
BOUNCE_CLI, the build/bin/bounce of this checkout.
"""
import importlib.util
import json
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
SCRIPT = os.path.join(ROOT, "examples", "coagulation", "smoluchowski.py")
# The project's message rule, after the program's name as the CLI prints it ("bounce: error: ").
MESSAGE = re.compile(r"^smoluchowski: error: (\S+) = .+ is invalid: expected .+$")


def load():
    spec = importlib.util.spec_from_file_location("smoluchowski", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # (dataclasses look their module up there)
    spec.loader.exec_module(module)
    return module


sm = load()


@pytest.fixture(scope="module")
def atlas_path(tmp_path_factory):
    """The atlas of docs/atlas.md's tests: krijt, water ice, R_eff 1 .. 10 um, 0.3 .. 20 m/s."""
    path = tmp_path_factory.mktemp("atlas") / "ice.h5"
    subprocess.run([CLI, "atlas", "build", "--model", "krijt", "--tvis", "1e-11", "--materials", "water-ice",
                    "--radius", "1e-6:1e-5:4", "--velocity", "0.3:20:5", "--tol", "1e-3", "-o", str(path)],
                   check=True, capture_output=True, text=True)
    return str(path)


@pytest.fixture(scope="module")
def atlas(atlas_path):
    import bounce.atlas

    return bounce.atlas.open(atlas_path, model="krijt")


def script(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)


def test_closed_form_solves_the_equation():
    """The constant kernel's closed form, independently of the integrator: its normalisation and
    its time derivative (central differences) against the example's right-hand side."""
    kmax = 400  # (7/8)^400 ~ 1e-23: the grid's end does not matter at T <= 3.5
    system = sm.Smoluchowski(np.full((kmax, kmax), 2.5e-12), 2.5e-12)
    k = np.arange(1, kmax + 1)
    for tau in (0.3, 2.0, 7.0):
        n = sm.closed_form(kmax, [tau])[0]
        T = tau / 2
        assert math.fsum(n) == pytest.approx(1 / (1 + T), rel=1e-13)  # N = N0 / (1 + T)
        assert math.fsum(k * n) == pytest.approx(1.0, rel=1e-13)       # the mass
        h = 1e-4 * tau
        dn = (sm.closed_form(kmax, [tau + h])[0] - sm.closed_form(kmax, [tau - h])[0]) / (2 * h)
        rhs = system(tau, np.append(n, 0.0))[:-1]
        # Central differences err by ~ h^2 n''' / 6 ~ 1e-8 relative here (plus 1e-16 / h round-off).
        assert np.max(np.abs(dn - rhs)) < 1e-7 * np.max(np.abs(rhs))
    assert list(sm.closed_form(5, [0.0])[0]) == [1.0, 0.0, 0.0, 0.0, 0.0]


def test_constant_kernel_matches_closed_form(tmp_path):
    r = sm.run(sm.Settings(out=tmp_path, constant_kernel=1e-12, steps=5, t_end=10.0, kmax=180))
    assert r["relative_mass_error"] < 1e-12
    assert r["mass_fraction_left_grid"] < 1e-12  # so the grid solution is the untruncated one
    # DOP853 holds each step's local error under atol + rtol |n_k|; the equation is dissipative
    # (errors are not amplified), so the global relative error, where n_k >= 1e-8 N0 >> atol / rtol
    # = 1e-10 N0, is at most the sum over its steps, < (right-hand sides) * rtol ~ 1e-7. Measured:
    # ~3e-11. A wrong closed form (a factor, T for 2T) would be off by O(1).
    tolerance = r["right_hand_sides"] * r["rtol"]
    assert r["closed_form_max_relative_deviation"] < tolerance
    assert r["closed_form_max_mass_fraction_deviation"] < tolerance
    assert r["mass_weighted_mean_k"][-1] == pytest.approx(1 + 10.0, rel=1e-9)  # (1 + p)/(1 - p) = 1 + 2T
    assert json.loads((tmp_path / "smoluchowski.json").read_text()) == r
    assert (tmp_path / "smoluchowski.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "</svg>" in (tmp_path / "smoluchowski.svg").read_text()


def test_atlas_run_conserves_mass(atlas_path, tmp_path):
    """As a user runs it: the atlas kernel, to tau = 30."""
    out = tmp_path / "out"
    r = script("--atlas", atlas_path, "--out", str(out), "--sigma-v", "3.0", "--steps", "3", "--t-end", "30")
    assert r.returncode == 0, r.stderr
    result = json.loads((out / "smoluchowski.json").read_text())
    assert result["mode"] == "atlas" and result["model"] == "krijt"
    assert result["relative_mass_error"] < 1e-12
    assert result["mass_fraction_left_grid"] < 1e-6
    assert len(result["tau"]) == 3 and result["tau"][-1] == 30.0
    mean = result["mass_weighted_mean_k"]
    assert mean[0] < mean[1] < mean[2]  # it grows
    assert (out / "smoluchowski.png").stat().st_size > 10_000
    assert "</svg>" in (out / "smoluchowski.svg").read_text()


def test_atlas_kernel_between_zero_and_geometric(atlas):
    kmax, a0, sigma_v = 180, 2e-6, 3.0
    kernel, p = sm.atlas_kernel(atlas, a0, kmax, sigma_v)
    geometric = sm.geometric_kernel(a0, kmax, sigma_v)
    assert kernel.shape == geometric.shape == (kmax, kmax)
    assert np.all(kernel >= 0) and np.all(kernel <= geometric)
    assert np.all(kernel > 0)  # every pair here sticks below some v_stick >= 0.3 m/s
    assert np.array_equal(kernel, kernel.T)
    # P_ij is the collision-weighted Maxwellian's closed form at the atlas's v_stick (the atlas
    # integrates the callable pdf by Gauss-Legendre, exact to round-off for this smooth integrand).
    a = sm.radii(a0, kmax)
    v_stick = atlas.v_stick(a[:, None], a[None, :])
    assert np.max(np.abs(p - sm.collision_cdf(v_stick, sigma_v))) < 1e-12
    # Slow pairs collide less often: fewer collisions than pairs stick (atlas.p_stick's default).
    _, pairs = sm.atlas_kernel(atlas, a0, kmax, sigma_v, distribution="maxwell")
    assert np.all(p <= pairs) and np.all(pairs <= 1)


def test_grid_outside_atlas_is_refused(atlas):
    with pytest.raises(sm.InputError, match=r"^--kmax = 400 is invalid: expected kmax <= \d+ for this atlas"):
        sm.atlas_kernel(atlas, 2e-6, 400, 3.0)  # large like pairs stick below 0.3 m/s only
    with pytest.raises(sm.InputError, match=r"^--a0 = 1e-06 is invalid: expected a monomer radius 2e-06 \.\. 2e-05"):
        sm.atlas_kernel(atlas, 1e-6, 10, 3.0)  # R_eff of two monomers below the atlas's 1 um


@pytest.mark.parametrize("args,name", [
    (["--sigma-v", "-1"], "--sigma-v"),
    (["--sigma-v", "nan"], "--sigma-v"),
    (["--steps", "0"], "--steps"),
    (["--steps", "2.5"], "--steps"),
    (["--kmax", "1"], "--kmax"),
    (["--bogus", "1"], "--bogus"),
])
def test_bad_argument_exits_2(args, name, tmp_path):
    r = script("--constant-kernel", "1e-12", "--out", str(tmp_path / "out"), *args)
    assert r.returncode == 2
    assert r.stdout == "" and r.stderr.count("\n") == 1, r.stderr
    assert MESSAGE.match(r.stderr.strip()).group(1) == name, r.stderr


def test_bad_atlas_exits_2(atlas_path, tmp_path):
    missing = script("--atlas", str(tmp_path / "missing.h5"), "--out", str(tmp_path / "out"))
    # sigma_v = 4 m/s puts 5e-5 of the collisions above the atlas's 20 m/s: refused by the atlas.
    too_fast = script("--atlas", atlas_path, "--out", str(tmp_path / "out"), "--sigma-v", "4")
    for r, name in ((missing, "--atlas"), (too_fast, "--sigma-v")):
        assert r.returncode == 2
        assert r.stderr.count("\n") == 1, r.stderr
        assert MESSAGE.match(r.stderr.strip()).group(1) == name, r.stderr
    assert not (tmp_path / "out").exists()
