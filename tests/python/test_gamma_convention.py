"""Issue 40, round 3, points 19 and 11 (docs/materials.md, "Which γ" and "User files"): a per-surface
surface energy is taken under its own name (--surface-energy, surface_energy=) as w = 2 γ_s, unlike
surfaces as 2 sqrt(γ_s1 γ_s2); `bounce materials` says which γ its column is; a materials file adds
to the built-in table; a density or γ far outside grain materials' is warned about as a unit slip."""
import json
import os
import subprocess

import pytest

import bounce

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
KRIJT = ["--model", "krijt", "--tvis", "1e-11", "--radius", "1e-6"]


def run(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


def v_stick(*args):
    done = run("sticking", *args, *KRIJT, "--json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)["sticking_velocity"]


def test_per_surface_energy_is_half_the_work_of_adhesion():
    """Dominik & Tielens' ice, γ_s = 0.37 J/m², is bounce's γ = 0.74 J/m² (main: no such option)."""
    assert v_stick("--material", "water-ice", "--surface-energy", "0.37") == v_stick("--material", "water-ice",
                                                                                    "--gamma", "0.74")


def test_unlike_surfaces_combine_as_k13s_rule():
    one = v_stick("--material", "water-ice", "--surface-energy", "0.185", "--material2", "quartz",
                  "--surface-energy2", "0.05")
    other = v_stick("--material", "water-ice", "--gamma", "0.37", "--material2", "quartz", "--gamma2", "0.1")
    assert one == other


def test_python_takes_the_per_surface_energy():
    model = bounce.Model("krijt", tvis=1e-11)
    a = bounce.collide(bounce.Pair(material="water-ice", radius=1e-6, surface_energy=0.185), model, 3.0)
    b = bounce.collide(bounce.Pair(material="water-ice", radius=1e-6), model, 3.0)
    assert a["cor"] == b["cor"] and a["pair"]["body1"]["surface_energy"] == 0.37


def test_both_for_one_body_are_refused():
    done = run("sticking", "--material", "water-ice", "--gamma", "0.37", "--surface-energy", "0.185", *KRIJT)
    assert done.returncode == 2 and "--gamma = 0.37 is invalid: expected gamma or surface_energy, not both" in done.stderr


def test_materials_listing_says_which_gamma():
    out = run("materials").stdout
    assert "gamma is the work of adhesion" in out and "--surface-energy" in out and "Dominik & Tielens 1997" in out


def test_a_materials_file_adds_to_the_builtin_table(tmp_path):
    """main: the file replaced the table, so --material2 water-ice was "not one of my-ice"."""
    path = tmp_path / "mine.toml"
    path.write_text('[[material]]\nname = "my-ice"\nyoungs_modulus = 7e9\npoisson_ratio = 0.25\ndensity = 1000.0\n'
                    'surface_energy = 0.2\nsource = "mine"\n'
                    '[[material]]\nname = "quartz"\nyoungs_modulus = 60e9\npoisson_ratio = 0.17\ndensity = 2600.0\n'
                    'surface_energy = 0.03\nsource = "mine"\n')
    done = run("collide", "--materials-file", str(path), "--material", "my-ice", "--material2", "water-ice",
               "--velocity", "1", *KRIJT, "--json")
    assert done.returncode == 0, done.stderr
    body2 = json.loads(done.stdout)["pair"]["body2"]
    assert body2["material"] == "water-ice" and body2["surface_energy"] == 0.37
    listed = json.loads(run("materials", "--materials-file", str(path), "--json").stdout)
    names = [m["name"] for m in listed]
    assert "my-ice" in names and "water-ice" in names and names.count("quartz") == 1
    assert next(m for m in listed if m["name"] == "quartz")["youngs_modulus"] == 60e9  # the file's replaces it


@pytest.mark.parametrize("option,value,said", [("--density", "2.5", "2.5 g/cm^3 would be 2500 kg/m^3"),
                                               ("--gamma", "370", "370 erg/cm^2 = mJ/m^2 would be 0.37 J/m^2")])
def test_implausible_values_ask_about_the_unit(option, value, said):
    """main: no warning for density 2.5 kg/m³ or γ = 370 J/m² (only E had one)."""
    done = run("collide", "--material", "water-ice", option, value, "--velocity", "1", *KRIJT, "--json")
    assert done.returncode == 0, done.stderr
    assert any(said in w for w in json.loads(done.stdout)["warnings"])
