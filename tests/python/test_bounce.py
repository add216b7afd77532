"""The Python package against the CLI, vectorised against scalar calls, and bad input.

Run by `make test` through CTest (PYTHONPATH=build/python, BOUNCE_CLI=build/bin/bounce).
"""
import json
import os
import re
import subprocess

import numpy as np
import pytest

import bounce

CLI = os.environ.get("BOUNCE_CLI", "build/bin/bounce")
# The foundation's message rule: the parameter, its value and the allowed range.
MESSAGE = re.compile(r"^\S+ = .+ is invalid: expected .+")


def cli(*args):
    out = subprocess.run([CLI, *args, "--json"], check=True, capture_output=True, text=True)
    return json.loads(out.stdout)


CASES = [
    (dict(material="ice-bshp96", radius=0.01), dict(name="viscoelastic", A=1e-6), 0.5,
     ["--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6"]),
    (dict(material="ice-bshp96", radius=0.01, wall="elastic"), dict(name="viscoelastic", A=1e-6, contact_end="force"),
     2.0, ["--material", "ice-bshp96", "--radius", "0.01", "--wall", "--A", "1e-6", "--contact-end", "force"]),
    (dict(material="water-ice", radius=1e-6), dict(name="krijt", tvis=1e-11), 8.0,
     ["--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis", "1e-11"]),
    (dict(material="water-ice", radius=1e-6), dict(name="adhesive-viscoelastic", tvis=1e-11), 1.0,
     ["--material", "water-ice", "--radius", "1e-6", "--model", "adhesive-viscoelastic", "--tvis", "1e-11"]),
]


@pytest.mark.parametrize("pair_args,model_args,velocity,cli_args", CASES)
def test_collide_equals_cli(pair_args, model_args, velocity, cli_args):
    model_args = dict(model_args)
    name = model_args.pop("name")
    r = bounce.collide(bounce.Pair(**pair_args), bounce.Model(name, **model_args), velocity)
    c = cli("collide", *cli_args, "--velocity", str(velocity))
    # The same library call: equal to the last printed digit (JSON keeps 17 digits).
    assert r["cor"] == c["cor"]
    assert r["outcome"] == c["outcome"]
    assert r["contact_time"] == c["contact_time"]
    assert r["energy"]["bulk_dissipated"] == c["energy"]["bulk_dissipated"]


def test_oblique_equals_cli():
    pair = bounce.Pair(material="ice-bshp96", radius=0.01)
    model = bounce.Model("viscoelastic", A=1e-6, friction=0.014142, asperity=1e-6, asperity_form="published")
    with pytest.warns(bounce.ValidityWarning, match="published asperity law"):
        r = bounce.collide(pair, model, 1.0, tangential_velocity=0.01)
    c = cli("collide", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--friction", "0.014142",
            "--asperity", "1e-6", "--asperity-form", "published", "--velocity", "1", "--tangential-velocity", "0.01")
    assert r["cor_tangential"] == c["cor_tangential"]
    assert r["cor_tangential"] == pytest.approx(-1.1331, abs=1e-4)  # docs/decisions.md D12's check


def test_sticking_equals_cli():
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    v = bounce.sticking_velocity(pair, bounce.Model("krijt", tvis=1e-11))
    c = cli("sticking", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis", "1e-11")
    assert v == c["sticking_velocity"]


def test_vectorised_equals_scalar():
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    model = bounce.Model("krijt", tvis=1e-11)
    speeds = np.geomspace(0.5, 50, 12).reshape(3, 4)
    many = bounce.collide(pair, model, speeds)
    assert many["cor"].shape == (3, 4)
    for v, e, s in zip(speeds.ravel(), many["cor"].ravel(), many["stick"].ravel()):
        one = bounce.collide(pair, model, float(v))
        assert e == one["cor"]
        assert s == (one["outcome"] == "stick")
    kappas = np.geomspace(1e-6, 1e3, 7)
    assert list(bounce.master_cor(kappas)) == [bounce.master_cor(float(k)) for k in kappas]


def test_table_against_direct_and_cli():
    pair = bounce.Pair(material="water-ice", radius=1e-6)
    model = bounce.Model("krijt", tvis=1e-11)
    table = bounce.NormalTable.build(pair, model, 0.5, 10.0)
    speeds = np.geomspace(0.5, 10.0, 40)
    direct = bounce.collide(pair, model, speeds)["cor"]
    assert np.max(np.abs(table.cor(speeds) - direct)) <= table.bound
    again = bounce.NormalTable.from_json(table.to_json())
    assert np.array_equal(again.cor(speeds), table.cor(speeds))
    c = cli("table", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis", "1e-11",
            "--velocities", "0.5:10")
    assert c["nodes"] == json.loads(table.to_json())["nodes"]


def test_tangential_table_against_direct_and_cli():
    pair = bounce.Pair(material="ice-bshp96", radius=0.01)
    model = bounce.Model(A=1e-6, friction=0.014142, asperity=1e-6, asperity_form="published")  # tabulated form
    table = bounce.TangentialTable.build(pair, model, 0.1, 3.0, 1e-3, 0.5)
    rng = np.random.default_rng(5)
    gn = 0.1 * 30.0 ** rng.random(30)
    gt = 1e-3 * 500.0 ** rng.random(30)
    direct = [bounce.collide(pair, model, float(n), tangential_velocity=float(t))["cor_tangential"] for n, t in zip(gn, gt)]
    assert np.max(np.abs(table.cor(gn, gt) - direct)) <= table.bound
    assert isinstance(table.cor(1.0, 0.01), float)
    assert table.cor(np.array([1.0, 2.0]), 0.01).shape == (2,)  # numpy broadcasting
    again = bounce.TangentialTable.from_json(table.to_json())
    assert np.array_equal(again.cor(gn, gt), table.cor(gn, gt))
    c = cli("table", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--friction", "0.014142",
            "--asperity", "1e-6", "--asperity-form", "published", "--velocities", "0.1:3",
            "--tangential-velocities", "0.001:0.5")
    assert c["nodes"] == json.loads(table.to_json())["nodes"]
    with pytest.raises(ValueError, match="tangential_velocity"):
        table.cor(1.0, 2.0)


def test_rules_conserve_momentum():
    pair = bounce.Pair(material="steel", radius=1e-3, radius2=2e-3)
    r = bounce.apply_restitution(pair, [1, 0, 0], [-1, 0.3, 0.1], [0, 5, 0], [0.2, 0, 0], [0, 0, 3], 0.7, -0.3)
    m1 = 4 / 3 * np.pi * 1e-3**3 * bounce.material("steel")["density"]
    m2 = 8 * m1
    before = m1 * np.array([-1, 0.3, 0.1]) + m2 * np.array([0.2, 0, 0])
    after = m1 * np.array(r["velocity1"]) + m2 * np.array(r["velocity2"])
    assert np.allclose(before, after, rtol=0, atol=1e-15 * np.abs(before).max())


@pytest.mark.parametrize("call", [
    lambda: bounce.Pair(material="water-ice", radius=-1.0),
    lambda: bounce.Pair(material="unobtainium", radius=1.0),
    lambda: bounce.Pair(E=1e9, nu=0.7, density=1000, radius=1.0),
    lambda: bounce.Pair(E=1e9, density=1000, radius=1.0),
    lambda: bounce.Pair(material="steel", radius=1e-3, wall="soft"),
    lambda: bounce.Model("nope"),
    lambda: bounce.Model("viscoelastic", contact_end="later"),
    lambda: bounce.collide(bounce.Pair(material="steel", radius=1e-3), bounce.Model(A=1e-7), -1.0),
    lambda: bounce.collide(bounce.Pair(material="steel", radius=1e-3), bounce.Model(A=1e-7), float("nan")),
    lambda: bounce.collide(bounce.Pair(material="steel", radius=1e-3), bounce.Model(A=-1.0), 1.0),
    lambda: bounce.sticking_velocity(bounce.Pair(material="steel", radius=1e-3), bounce.Model(A=1e-7)),
    lambda: bounce.NormalTable.build(bounce.Pair(material="steel", radius=1e-3), bounce.Model(A=1e-7), 2.0, 1.0),
])
def test_bad_arguments_raise_value_error(call):
    with pytest.raises(ValueError) as info:
        call()
    assert MESSAGE.match(str(info.value)), str(info.value)
    assert "\n" not in str(info.value)
