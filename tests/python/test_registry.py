"""Every model of the registry from Python (docs/architecture.md): each parameter reachable, results equal
to the CLI's (the same JSON keys and values), and a keyword a model does not take refused.

The models and their parameters are read from the registry (bounce.models()), so a model
added as a row is tested here without editing this file.
"""
import ast
import json
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import bounce

CLI = os.environ.get("BOUNCE_CLI", "build/bin/bounce")
MESSAGE = re.compile(r"^\S+ = .+ is invalid: expected .+")
REGISTRY = bounce.models()
MODELS = {m["name"]: m for m in REGISTRY["models"]}

# One working set of parameters per model (SI units), for 1 um water-ice grains, and a
# speed at which it bounces. A model added to the registry needs a line here to join the
# equality test below (the other tests cover it from the registry alone).
CASES = {
    "hertz": ({}, 1.0),
    "viscoelastic": ({"A": 1e-10}, 1.0),
    "viscoelastic-shifted": ({"A": 1e-10}, 1.0),
    "power-law": ({"power_d1": 1e17, "power_d2": 1e7}, 1.0),
    "adhesive-viscoelastic": ({"tvis": 1e-11}, 2.0),
    "jkr-viscoelastic": ({"tvis": 1e-11}, 8.0),
    "krijt": ({"tvis": 1e-11}, 8.0),
    "maugis-viscoelastic": ({"tvis": 1e-11, "z0": 2e-9}, 4.0),
}
PAIR = {"material": "water-ice", "radius": 1e-6}


def option(name):
    return "--" + name.replace("_", "-")


def cli(*args):
    out = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return json.loads(out.stdout)


def cli_args(model, parameters, velocity, extra=()):
    args = ["collide", "--material", "water-ice", "--radius", "1e-6", "--model", model]
    for key, value in parameters.items():
        args += [option(key), ",".join(repr(float(x)) for x in value) if isinstance(value, tuple) else repr(value)]
    return [*args, "--velocity", repr(velocity), *extra, "--json"]


def test_every_model_has_a_case():
    assert set(CASES) == set(MODELS)


@pytest.mark.parametrize("name", sorted(CASES))
def test_python_equals_cli(name):
    """The same front door on both sides: every key and value of the CLI's JSON."""
    parameters, velocity = CASES[name]
    py = bounce.collide(bounce.Pair(**PAIR), bounce.Model(name, **parameters), velocity)
    assert py == cli(*cli_args(name, parameters, velocity))


@pytest.mark.parametrize("law", [law["name"] for law in bounce.contact_laws()])
def test_contact_state_equals_cli(law):
    """ContactLaw.state goes through the same front door as `bounce contact --json`."""
    extra = {"maugis": {"z0": 3e-10}}.get(law, {})
    args = ["contact", "--material", "water-ice", "--radius", "1e-6", "--law", law, "--force", "1e-7", "--json"]
    for key, value in extra.items():
        args += [option(key), repr(value)]
    assert bounce.ContactLaw(bounce.Pair(**PAIR), law, **extra).state(force=1e-7) == cli(*args)
    convex = bounce.ContactLaw(bounce.Pair(material="steel", radius=1e-3), "hertz", curvature_radii=[1e-3, 5e-3])
    assert convex.state(overlap=1e-7) == cli("contact", "--material", "steel", "--radius", "1e-3", "--curvature-radii",
                                             "1e-3,5e-3", "--overlap", "1e-7", "--json")


@pytest.mark.parametrize("name", ["viscoelastic", "krijt"])
def test_python_equals_cli_oblique_and_trajectory_keys(name):
    parameters, velocity = CASES[name]
    tangential = {"friction": 0.3, "asperity": 1e-10}
    py = bounce.collide(bounce.Pair(**PAIR), bounce.Model(name, **parameters, **tangential), velocity,
                        tangential_velocity=1.0)
    assert py == cli(*cli_args(name, {**parameters, **tangential}, velocity, ["--tangential-velocity", "1"]))
    run = bounce.collide(bounce.Pair(**PAIR), bounce.Model(name, **parameters), velocity, trajectory=True)
    rows = cli(*cli_args(name, parameters, velocity, ["--trajectory"]))["trajectory"]
    # A Table: the CLI's list of samples, Python's dict of arrays; the same columns and values.
    assert set(run["trajectory"]) == set(rows[0])
    for key, column in run["trajectory"].items():
        assert list(column) == [r[key] for r in rows]


def value_for(p):
    """A valid value of a parameter from its registry entry."""
    if p.get("choices"):
        return p["choices"][-1]
    if p["kind"] == "reals":
        return (2e-6, 3e-6)
    if p["default"] is not None:
        return float(p["default"])
    return {"power_d1": 1e17, "power_d2": 1e7, "k": 0.05}.get(p["name"], 1e-9)


@pytest.mark.parametrize("name", sorted(MODELS))
def test_every_parameter_is_reachable(name):
    """Each of the model's parameters as a keyword of bounce.Model (Python's spelling of
    yield is yield_strength), taken and kept."""
    for p in MODELS[name]["parameters"]:
        key = "yield_strength" if p["name"] == "yield" else p["name"]
        model = bounce.Model(name, **{key: value_for(p)})
        assert p["name"] in model.parameters, p["name"]


def test_numerics_curvatures_and_power_law_from_python():
    pair = bounce.Pair(**PAIR)
    # The power-law model, with its constants.
    power = bounce.collide(pair, bounce.Model("power-law", power_d1=1e17, power_d2=1e7, power_alpha=1.5), 1.0)
    assert 0.0 < power["cor"] < 1.0
    # Convex bodies: curvature radii change C0 (BP04 (8.21)).
    sphere = bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10), 1.0)
    ellipsoid = bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10, curvature_radii=(1e-6, 5e-6)), 1.0)
    assert ellipsoid["force_constant"] > sphere["force_constant"]
    # The tolerance and the stiff engine.
    tight = bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10, method="integrate", tolerance=1e-10), 1.0)
    assert tight["method"] == "integrate"
    assert tight["cor"] == pytest.approx(sphere["cor"], abs=1e-8)
    cvode = bounce.collide(pair, bounce.Model("krijt", tvis=1e-11, stiff_engine="cvode"), 8.0)
    rodas = bounce.collide(pair, bounce.Model("krijt", tvis=1e-11), 8.0)
    assert cvode["cor"] == pytest.approx(rodas["cor"], abs=1e-6)
    # Numerical settings also as keywords of the call.
    assert bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10), 1.0, method="integrate")["method"] == "integrate"


@pytest.mark.parametrize("name", sorted(MODELS))
def test_keywords_a_model_does_not_take_are_refused(name):
    own = {p["name"] for p in MODELS[name]["parameters"]}
    others = {p["name"]: p for m in MODELS.values() for p in m["parameters"] if p["name"] not in own}
    assert others
    for key, p in others.items():
        with pytest.raises(ValueError) as info:
            bounce.Model(name, **{key: value_for(p)})
        assert MESSAGE.match(str(info.value)), str(info.value)
        assert str(info.value).startswith(key + " = ")


def test_unused_call_keywords_are_refused():
    pair = bounce.Pair(**PAIR)
    with pytest.raises(ValueError, match="^friction = "):
        bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10, friction=0.3, asperity=1e-10), 1.0)
    with pytest.raises(ValueError, match="^follow_time = "):  # Python spells follow so
        bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10), 1.0, follow_time=1e-6)
    with pytest.raises(ValueError, match="^nonsense = "):
        bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10), 1.0, nonsense=1.0)
    with pytest.raises(ValueError, match="^nonsense = "):
        bounce.Pair(material="water-ice", radius=1e-6, nonsense=2)
    with pytest.raises(TypeError, match="^A = "):
        bounce.Model("viscoelastic", A=object())
    with pytest.raises(ValueError, match="^trajectory = "):
        bounce.collide(pair, bounce.Model("viscoelastic", A=1e-10), np.array([1.0, 2.0]), trajectory=True)


def test_type_stubs_follow_the_registry():
    """The stubs are generated at build time: one Model.__init__ overload per model, with
    its parameters as keywords (yield as yield_strength)."""
    with open(os.path.join(os.path.dirname(bounce.__file__), "_bounce.pyi")) as f:
        tree = ast.parse(f.read())
    model = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Model")
    overloads = {}
    for f in model.body:
        if isinstance(f, ast.FunctionDef) and f.name == "__init__":
            name = f.args.args[1].annotation.slice.value
            overloads[name] = {a.arg for a in f.args.kwonlyargs}
    assert set(overloads) == set(MODELS)
    for name, keywords in overloads.items():
        expected = {"yield_strength" if p["name"] == "yield" else p["name"] for p in MODELS[name]["parameters"]}
        assert keywords == expected, name


def test_docs_models_tables_follow_the_registry():
    """docs/models.md holds what `bounce models --markdown` prints (tools/update_model_docs.py)."""
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path.insert(0, os.path.join(here, "..", "..", "tools"))
    import update_model_docs

    with open(os.path.join(here, "..", "..", "docs", "models.md")) as f:
        page = f.read()
    assert update_model_docs.section(page) == update_model_docs.generated(CLI), \
        "docs/models.md differs from the registry: run tools/update_model_docs.py build/bin/bounce"
