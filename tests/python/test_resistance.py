"""Issue 36, point 1 (docs/resistance.md): `bounce contact resistance` and
bounce.contact_resistance print the same contact, with W07's closed forms in the
literature's per-surface γ_s = γ/2, and refuse bad input by the project's rule."""
import json
import math
import os
import subprocess

import pytest

import bounce

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
# Wada et al. 2007's ice, given as they give it: γ_s = 0.1 J/m² per surface, monomers of 0.1 µm.
W07_ICE = ["--E", "7e9", "--nu", "0.25", "--density", "1000", "--surface-energy", "0.1", "--radius", "1e-7"]


def run(*args):
    return subprocess.run([CLI, "contact", "resistance", *args], capture_output=True, text=True)


def test_cli_and_python_print_the_same_contact():
    done = run(*W07_ICE, "--xi-crit", "3.2e-9", "--json")
    assert done.returncode == 0, done.stderr
    pair = bounce.Pair(E=7e9, nu=0.25, density=1000, surface_energy=0.1, radius=1e-7)
    assert json.loads(done.stdout) == bounce.contact_resistance(pair, xi_crit=3.2e-9)


def test_w07_ice_in_the_literatures_gamma():
    """F_c = 3π γ_s R, E_roll = 6π² γ_s R ξ_crit, F_roll = 6π γ_s ξ_crit with R = 0.05 µm: the
    per-surface γ_s = 0.1 enters, not bounce's γ = 0.2 (which would double each)."""
    out = json.loads(run(*W07_ICE, "--json").stdout)
    R, gs, xi = 0.5e-7, 0.1, 8e-10
    assert out["surface_energy_per_surface"] == pytest.approx(gs, rel=1e-15)
    assert out["pull_off_force"] == pytest.approx(3 * math.pi * gs * R, rel=1e-13)
    assert out["rolling"]["energy"] == pytest.approx(6 * math.pi**2 * gs * R * xi, rel=1e-13)
    assert out["rolling"]["force"] == pytest.approx(6 * math.pi * gs * xi, rel=1e-13)
    assert out["twisting"]["critical_angle"] == pytest.approx(1 / (16 * math.pi), rel=1e-13)


def test_text_names_every_quantity_with_its_unit():
    text = run("--materials", "water-ice", "--radius", "1e-7").stdout
    for shown in ("a0 =", "F_c =", "E_break =", "J", "k_r =", "N/m", "M_roll =", "N m", "E_roll =", "xi_s =",
                  "F_slide =", "k_t =", "N m/rad", "phi_crit =", "rad", "M_twist =", "gamma_s ="):
        assert shown in text, shown


@pytest.mark.parametrize("args, message", [
    (["--materials", "water-ice", "--radius", "1e-7", "--xi-crit", "1e-6"],
     "--xi-crit = 1e-6 is invalid: expected 0 < xi_crit < a0 = 1.5186"),
    (["--materials", "water-ice", "--radius", "1e-7", "--xi-crit", "0"], "--xi-crit = 0 is invalid"),
    (["--materials", "water-ice,ice-bshp96", "--radius", "1e-6"], "--gamma = (not given) is invalid"),
    (["--materials", "a,b,c", "--radius", "1e-6"], "--materials = a,b,c is invalid: expected A or A,B"),
    (["--materials", "water-ice", "--material", "steel", "--radius", "1e-6"], "--material = steel is invalid"),
    (["--materials", "water-ice", "--radius", "1e-7", "--velocity", "3"],
     "--velocity = 3 is invalid: expected no --velocity in `bounce contact resistance`"),
    (["--materials", "water-ice", "--radius", "-1e-7"], "--radius = -1e-7 is invalid"),
])
def test_bad_input_is_refused_naming_what_was_typed(args, message):
    done = run(*args)
    assert done.returncode == 2 and message in done.stderr, done.stderr
    assert done.stdout == ""


def test_python_refuses_by_the_same_rule():
    pair = bounce.Pair(material="water-ice", radius=1e-7)
    with pytest.raises(ValueError, match="xi_crit = 1 is invalid: expected 0 < xi_crit < a0"):
        bounce.contact_resistance(pair, xi_crit=1.0)
    with pytest.raises(TypeError, match="xi_crit = 'a' is invalid"):
        bounce.contact_resistance(pair, xi_crit="a")
    with pytest.raises(ValueError, match="gamma"):
        bounce.contact_resistance(bounce.Pair(material="ice-bshp96", radius=1e-6))
