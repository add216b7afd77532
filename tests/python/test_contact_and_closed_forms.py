"""Contact laws, closed forms, trajectories and the BP04 forms in Python, against the CLI."""
import csv
import io
import json
import os
import re
import subprocess

import numpy as np
import pytest

import bounce

CLI = os.environ.get("BOUNCE_CLI", "build/bin/bounce")
MESSAGE = re.compile(r"^\S+ = .+ is invalid: expected .+")
ICE = ["--material", "water-ice", "--radius", "1e-6"]


def run(*args):
    return subprocess.run([CLI, *args], check=True, capture_output=True, text=True).stdout


@pytest.mark.parametrize("law", ["hertz", "jkr", "dmt", "maugis"])
def test_contact_law_equals_cli(law):
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    c = bounce.ContactLaw(pair, law)
    # The same library call on both sides: equal to the last digit (JSON keeps 17 digits).
    py = c.at_force(1e-6)
    cli = json.loads(run("contact", *ICE, "--law", law, "--force", "1e-6", "--json"))
    assert py["contact_radius"] == cli["contact_radius"]
    assert py["overlap"] == cli["overlap"]
    if law != "hertz":
        assert c.adhesion["pull_off_force"] == cli["pull_off_force"]
        assert c.adhesion["zero_load_contact_radius"] == cli["zero_load_contact_radius"]
    else:
        assert c.adhesion is None


def test_contact_curve_vectorised_equals_scalar_and_cli():
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    jkr = bounce.ContactLaw(pair, "jkr")
    a = np.linspace(0.0, 1.5e-7, 7)
    curve = jkr.at_contact_radius(a)
    for i, x in enumerate(a):
        p = jkr.at_contact_radius(float(x))
        assert curve["overlap"][i] == p["overlap"] and curve["force"][i] == p["force"]
    rows = list(csv.DictReader(io.StringIO(run("contact", *ICE, "--law", "jkr", "--csv", "--contact-radii",
                                               "0:1.5e-7:7"))))
    # The CLI prints %.17g: a round trip to the same double.
    assert [float(r["force"]) for r in rows] == list(curve["force"])


def test_closed_forms_equal_cli_and_array():
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    model = bounce.Model("krijt", tvis=1e-11)
    c = json.loads(run("collide", *ICE, "--model", "krijt", "--tvis", "1e-11", "--velocity", "8",
                       "--json"))["closed_forms"]
    py = bounce.closed_forms(pair, model, 8.0)
    assert set(py) == set(c)
    for key, value in c.items():
        assert py[key] == value, key
    many = bounce.closed_forms(pair, model, np.array([2.0, 8.0]))
    assert many["e_i"][1] == py["e_i"]
    assert many["e_jkr"][0] == bounce.closed_forms(pair, model, 2.0)["e_jkr"]


def test_trajectory_equals_cli():
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    model = bounce.Model("krijt", tvis=1e-11)
    r = bounce.collide(pair, model, 8.0, trajectory=True)
    rows = list(csv.DictReader(io.StringIO(run("collide", *ICE, "--model", "krijt", "--tvis", "1e-11", "--velocity",
                                               "8", "--trajectory", "--csv"))))
    t = r["trajectory"]
    assert len(rows) == len(t["time"])
    assert [float(x["contact_radius"]) for x in rows] == list(t["contact_radius"])
    assert [float(x["crack_dissipated"]) for x in rows] == list(t["crack_dissipated"])
    # The last sample closes the energy budget of the outcome (the same numbers).
    assert t["bulk_dissipated"][-1] == pytest.approx(r["energy"]["bulk_dissipated"], rel=1e-12)


def test_pade_and_series_reproduce_bp04():
    # BP04 (8.92) with the printed d_k at q = 1: (1 + 2.583) / (1 + 3.583 + 2.983 + 1.148 + 0.326).
    assert bounce.cor_pade(1.0) == pytest.approx(3.583 / 9.04, rel=1e-15)
    # (8.89) with BP04's quoted a_k at q = 0.5, by hand.
    assert bounce.cor_series(0.5, "bp04") == pytest.approx(1 - 0.5 + 0.6 * 0.25 - 0.315 * 0.125 + 0.161 * 0.0625,
                                                           rel=1e-15)
    q = np.array([0.1, 0.5])
    assert list(bounce.cor_pade(q, "bounce")) == [bounce.cor_pade(0.1, "bounce"), bounce.cor_pade(0.5, "bounce")]
    # kappa = q / (2b) (BP04 (8.87)): the series meets the exact master curve at small q (O(q^5) apart).
    s = bounce.viscoelastic_scales(bounce.Pair(material="ice-bshp96", radius=0.01), bounce.Model(A=1e-6), 1.0)
    two_b = s["q"] / s["kappa"]
    assert bounce.cor_series(0.05) == pytest.approx(bounce.master_cor(0.05 / two_b), abs=1e-7)


@pytest.mark.parametrize("call", [
    lambda: bounce.ContactLaw(bounce.Pair(material="water-ice", radius=1e-6), "glue"),
    lambda: bounce.ContactLaw(bounce.Pair(material="water-ice", radius=1e-6), "maugis", z0=-1.0),
    lambda: bounce.ContactLaw(bounce.Pair(material="ice-bshp96", radius=1e-2), "jkr"),
    lambda: bounce.ContactLaw(bounce.Pair(material="water-ice", radius=1e-6), "hertz").at_force(-1.0),
    lambda: bounce.closed_forms(bounce.Pair(material="ice-bshp96", radius=1e-2), bounce.Model("krijt", tvis=1e-11), 1.0),
    lambda: bounce.collide(bounce.Pair(material="water-ice", radius=1e-6), bounce.Model("krijt", tvis=1e-11),
                           np.array([1.0, 2.0]), trajectory=True),
    lambda: bounce.collide(bounce.Pair(material="water-ice", radius=1e-6), bounce.Model("krijt", tvis=1e-11), 1.0,
                           follow_time=-1.0),
    lambda: bounce.cor_pade(0.5, "bp05"),
    lambda: bounce.cor_series(0.5, "nope"),
])
def test_bad_arguments_raise_value_error(call):
    with pytest.raises(ValueError) as info:
        call()
    assert MESSAGE.match(str(info.value)), str(info.value)
    assert "\n" not in str(info.value)


def test_curve_equals_cli_curve():
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    model = bounce.Model("krijt", tvis=1e-11)
    py = bounce.curve(pair, model, [1.0, 4.0, 8.0])
    rows = list(csv.DictReader(io.StringIO(run("curve", *ICE, "--model", "krijt", "--tvis", "1e-11",
                                               "--velocities", "1:8:3", "--csv"))))
    # 1:8:3 is 1, 4.5, 8 (linear); compare the end points, the same library call.
    assert float(rows[0]["cor"]) == py["cor"][0] and float(rows[-1]["cor"]) == py["cor"][-1]
    assert [r["outcome"] == "stick" for r in rows][0] == py["stick"][0]
