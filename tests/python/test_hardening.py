"""Hardening of the Python package: every bad input is refused by one rule (docs/python.md, Errors).

"NAME = VALUE is invalid: expected ...": a value out of its declared range, or one whose results
would be inf or NaN, raises ValueError; a value of the wrong type (a bool, a str, None or a complex
where a number is expected) raises TypeError naming the parameter; Ctrl-C interrupts the long
calls. One test (or one parametrized case) per row of the issue "Hardening", and the values a new
user tries (negative, zero, nan, inf, huge, wrong types, wrong keywords, empty arrays).
"""
import json
import math
import os
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import bounce

MESSAGE = re.compile(r"^\S+ = .+ is invalid: expected .+")
NAN, INF = float("nan"), float("inf")


def ice():
    return bounce.Pair(material="water-ice", radius=1e-6)


def krijt():
    return bounce.Model("krijt", tvis=1e-11)


def viscoelastic():
    return bounce.Model("viscoelastic", A=1e-10)


def refused(error, name, call):
    """The call raises `error` with the one-line message naming `name`; returns the message."""
    with pytest.raises(error) as info:
        call()
    text = str(info.value)
    assert MESSAGE.match(text), text
    assert "\n" not in text, text
    assert text.startswith(name + " = "), text
    return text


def all_finite(x):
    if isinstance(x, dict):
        return all(all_finite(v) for v in x.values())
    if isinstance(x, (list, tuple)):
        return all(all_finite(v) for v in x)
    if isinstance(x, np.ndarray):
        return x.dtype.kind != "f" or bool(np.isfinite(x).all())
    if isinstance(x, float):
        return math.isfinite(x)
    return True


# --- 1. relative_tolerance of the sticking velocity: its declared range ---------------------------

STICKING_TOLERANCES = [0.0, -1.0, 1e-300, NAN, 1.0, 5.0]


def test_sticking_relative_tolerance_out_of_range_is_a_value_error():
    """0, -1 and 1e-300 hung (the bisection never met its width), nan, 1 and 5 gave a wrong answer.

    In a child process with a timeout, so that a regression fails instead of hanging the suite.
    """
    code = (
        "import json, bounce\n"
        "pair, model = bounce.Pair(material='water-ice', radius=1e-6), bounce.Model('krijt', tvis=1e-11)\n"
        "out = []\n"
        f"for rtol in {[repr(x) for x in STICKING_TOLERANCES]}:\n"
        "    try:\n"
        "        out.append(['returned', bounce.sticking_velocity(pair, model, relative_tolerance=float(rtol))])\n"
        "    except Exception as e:\n"
        "        out.append([type(e).__name__, str(e)])\n"
        "print(json.dumps(out))\n")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, run.stderr
    for rtol, (kind, text) in zip(STICKING_TOLERANCES, json.loads(run.stdout)):
        assert kind == "ValueError", (rtol, kind, text)
        assert MESSAGE.match(text) and text.startswith("relative_tolerance = "), text
        assert "<" in text, text  # the allowed range is stated


def test_sticking_relative_tolerance_goes_through_its_declaration():
    """sticking_velocity and sticking(relative_tolerance=...) take the same declared parameter."""
    for call in (lambda: bounce.sticking_velocity(ice(), krijt(), 0.0),
                 lambda: bounce.sticking(ice(), krijt(), relative_tolerance=0.0)):
        text = refused(ValueError, "relative_tolerance", call)
        assert text.endswith("relative tolerance < 0.1"), text
    assert bounce.sticking_velocity(ice(), krijt(), 1e-3) == pytest.approx(4.2015, rel=1e-3)


# --- 2. strict types: a bool, a str, None or a complex is not a number ------------------------------

@pytest.mark.parametrize("velocity", ["5", True, False, None, 1 + 2j, np.bool_(True), np.array([1 + 2j]),
                                      np.array([True, False]), ["1", "2"], [1.0, True], np.array("5"), {1.0}])
def test_collide_velocity_of_the_wrong_type_is_a_type_error(velocity):
    refused(TypeError, "velocity", lambda: bounce.collide(ice(), krijt(), velocity))


@pytest.mark.parametrize("name,call", [
    ("radius", lambda: bounce.Pair(material="water-ice", radius=True)),
    ("radius", lambda: bounce.Pair(material="water-ice", radius="1e-6")),
    ("radius", lambda: bounce.Pair(material="water-ice", radius=[1e-6])),
    ("gamma", lambda: bounce.Pair(material="water-ice", radius=1e-6, gamma=1j)),
    ("material", lambda: bounce.Pair(material=3, radius=1e-6)),
    ("wall", lambda: bounce.Pair(material="steel", radius=1e-3, wall=1)),
    ("A", lambda: bounce.Model("viscoelastic", A="1e-6")),
    ("A", lambda: bounce.Model("viscoelastic", A=True)),
    ("tvis", lambda: bounce.Model("krijt", tvis=np.array([1e-11, 2e-11]))),
    ("stiff_engine", lambda: bounce.Model("krijt", tvis=1e-11, stiff_engine=1)),
    ("curvature_radii", lambda: bounce.Model("hertz", curvature_radii=[True, 1e-3])),
    ("curvature_radii", lambda: bounce.Model("hertz", curvature_radii="1e-3,5e-3")),
    ("tangential_velocity", lambda: bounce.collide(ice(), krijt(), 8.0, tangential_velocity="1")),
    ("trajectory", lambda: bounce.collide(ice(), krijt(), 8.0, trajectory=1)),
    ("trajectory_points", lambda: bounce.collide(ice(), krijt(), 8.0, trajectory=True, trajectory_points=True)),
    ("follow_time", lambda: bounce.collide(ice(), krijt(), 2.0, follow_time=True)),
    ("velocities", lambda: bounce.curve(ice(), krijt(), [True, 2.0])),
    ("velocity", lambda: bounce.closed_forms(ice(), krijt(), "8")),
    ("velocity", lambda: bounce.viscoelastic_scales(ice(), viscoelastic(), True)),
    ("relative_tolerance", lambda: bounce.sticking_velocity(ice(), krijt(), "1e-3")),
    ("relative_tolerance", lambda: bounce.sticking_velocity(ice(), krijt(), True)),
    ("q", lambda: bounce.cor_series("0.5")),
    ("q", lambda: bounce.cor_pade(True)),
    ("kappa", lambda: bounce.master_cor(np.array([True]))),
    ("force", lambda: bounce.ContactLaw(ice(), "jkr").at_force("1e-7")),
    ("force", lambda: bounce.ContactLaw(ice(), "jkr").state(force=True)),
    ("z0", lambda: bounce.ContactLaw(ice(), "maugis", z0="3e-10")),
    ("g_min", lambda: bounce.NormalTable.build(ice(), krijt(), "0.5", 20.0)),
    ("bound", lambda: bounce.NormalTable.build(ice(), krijt(), 0.5, 20.0, bound=True)),
    ("cor", lambda: bounce.apply_restitution(ice(), [1, 0, 0], [-1, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0], cor=True)),
    ("velocity1", lambda: bounce.apply_restitution(ice(), [1, 0, 0], [True, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0],
                                                   cor=0.5)),
    ("normal", lambda: bounce.apply_restitution(ice(), [1, 0], [-1, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0], cor=0.5)),
])
def test_a_value_of_the_wrong_type_is_a_type_error_naming_it(name, call):
    refused(TypeError, name, call)


def test_numpy_numbers_and_lists_of_numbers_keep_working():
    pair, model = ice(), krijt()
    one = bounce.collide(pair, model, 8.0)["cor"]
    for x in (8, np.float64(8), np.float32(8), np.int64(8), np.int32(8)):
        r = bounce.collide(pair, model, x)
        assert isinstance(r["cor"], float) and r["cor"] == one
    for xs in ([2, 8], (2.0, 8.0), np.array([2, 8]), np.array([2.0, 8.0], dtype=np.float32), [[2.0], [8.0]]):
        many = bounce.collide(pair, model, xs)
        assert many["cor"].shape == np.shape(xs) and many["cor"].ravel()[-1] == one
    assert bounce.collide(pair, model, np.array(8.0))["cor"].shape == ()  # a 0-d array gives 0-d arrays
    assert bounce.Pair(material="water-ice", radius=np.float64(1e-6)).effective_radius == 5e-7
    assert bounce.Pair(material="water-ice", radius=np.array(1e-6)).effective_radius == 5e-7
    assert bounce.Model("viscoelastic", A=np.float32(1e-6)).parameters["A"] == pytest.approx(1e-6)
    assert bounce.Model("hertz", curvature_radii=np.array([1e-3, 5e-3])).parameters["curvature_radii"] == [1e-3, 5e-3]
    assert bounce.cor_series(np.int64(0)) == 1.0
    assert bounce.Pair(material="steel", radius=1e-3, wall=True).effective_radius == 1e-3  # wall=True: elastic


# --- 3. a Model checks its parameters when it is made ------------------------------------------------

@pytest.mark.parametrize("name,model,parameters", [
    ("A", "viscoelastic", {"A": -1.0}),
    ("A", "viscoelastic", {"A": INF}),
    ("tvis", "krijt", {"tvis": NAN}),
    ("tvis", "krijt", {"tvis": 0.0}),
    ("z0", "krijt", {"tvis": 1e-11, "z0": -1.0}),
    ("adhesive_tolerance", "krijt", {"tvis": 1e-11, "adhesive_tolerance": 0.0}),
    ("yield_strength", "krijt", {"tvis": 1e-11, "yield_strength": -1.0}),
    ("friction", "viscoelastic", {"A": 1e-6, "friction": -1.0}),
    ("contact_end", "viscoelastic", {"A": 1e-6, "contact_end": "later"}),
    ("tolerance", "hertz", {"tolerance": 0.0}),
    ("curvature_radii", "hertz", {"curvature_radii": [1e-3, -1.0]}),
])
def test_model_refuses_a_bad_parameter_when_made(name, model, parameters):
    refused(ValueError, name, lambda: bounce.Model(model, **parameters))


# --- 4. never an inf or a NaN: refused as the input's fault -----------------------------------------

@pytest.mark.parametrize("name,call", [
    ("velocity", lambda: bounce.collide(ice(), viscoelastic(), 1e308)),
    ("velocity", lambda: bounce.collide(ice(), viscoelastic(), [1.0, 1e308])),
    ("velocity", lambda: bounce.curve(ice(), bounce.Model("hertz"), [1.0, 1e300])),
    ("velocity", lambda: bounce.closed_forms(ice(), krijt(), NAN)),
    ("velocity", lambda: bounce.closed_forms(ice(), krijt(), -1.0)),
    ("velocity", lambda: bounce.closed_forms(ice(), krijt(), INF)),
    ("velocity", lambda: bounce.closed_forms(ice(), krijt(), 1e308)),
    ("velocity", lambda: bounce.closed_forms(ice(), krijt(), [8.0, NAN])),
    ("q", lambda: bounce.cor_series(INF)),
    ("q", lambda: bounce.cor_series(NAN)),
    ("q", lambda: bounce.cor_series(-1.0)),
    ("q", lambda: bounce.cor_series(1e100)),
    ("q", lambda: bounce.cor_pade(-1.0)),
    ("q", lambda: bounce.cor_pade(NAN)),
    ("q", lambda: bounce.cor_pade(np.array([0.5, -1.0]))),
    ("radius", lambda: bounce.Pair(material="water-ice", radius=1e308)),
    ("radius", lambda: bounce.Pair(material="water-ice", radius=1e100)),  # m_eff = m1 m2/(m1 + m2) overflowed
    ("radius", lambda: bounce.Pair(material="water-ice", radius=1e-300)),
    ("velocity", lambda: bounce.viscoelastic_scales(ice(), viscoelastic(), 1e308)),
    ("model", lambda: bounce.viscoelastic_scales(ice(), bounce.Model("hertz"), 1.0)),  # g* = inf
    ("A", lambda: bounce.viscoelastic_scales(ice(), bounce.Model("viscoelastic", A=0.0), 1.0)),
    ("overlap", lambda: bounce.ContactLaw(ice(), "hertz").at_overlap(1e308)),
    ("contact_radius", lambda: bounce.ContactLaw(ice(), "jkr").at_contact_radius(1e308)),
    ("force", lambda: bounce.ContactLaw(ice(), "maugis", z0=3e-10).at_force(1e308)),
    ("overlap", lambda: bounce.ContactLaw(ice(), "jkr").state(overlap=1e308)),
])
def test_a_result_beyond_double_precision_is_a_value_error(name, call):
    refused(ValueError, name, call)


def test_pair_1e308_is_refused_before_its_properties_are_read():
    with pytest.raises(ValueError):
        bounce.Pair(material="water-ice", radius=1e308).effective_radius


@pytest.mark.parametrize("model", ["hertz", "viscoelastic", "krijt", "jkr-viscoelastic"])
def test_extreme_values_give_finite_results_or_an_error(model):
    """A sweep over the calls a user makes with extreme numbers: a result, all finite, or an error."""
    m = bounce.Model(model, **({"tvis": 1e-11} if model in ("krijt", "jkr-viscoelastic") else {}))
    calls = [lambda x: bounce.collide(ice(), m, x), lambda x: bounce.closed_forms(ice(), m, x),
             lambda x: bounce.cor_series(x), lambda x: bounce.cor_pade(x), lambda x: bounce.master_cor(x),
             lambda x: bounce.ContactLaw(ice(), "jkr").at_force(x),
             lambda x: bounce.ContactLaw(ice(), "dmt").at_overlap(x),
             lambda x: bounce.ContactLaw(ice(), "hertz").at_contact_radius(x)]
    for call in calls:
        for x in (1e-300, 1e-100, 1e10, 1e300, -1e-300, 0.0):
            try:
                assert all_finite(call(x)), (model, x)
            except (ValueError, RuntimeError) as e:
                assert "\n" not in str(e)


@pytest.mark.parametrize("model,parameters,velocity", [
    ("krijt", {"tvis": 1e-11}, 1e308),
    ("power-law", {"power_d1": 1e17, "power_d2": 1e7}, 1e-300),
    ("viscoelastic-shifted", {"A": 1e-10}, 1e300),
])
def test_an_impact_velocity_beyond_the_models_is_a_value_error(model, parameters, velocity):
    refused(ValueError, "velocity", lambda: bounce.collide(ice(), bounce.Model(model, **parameters), velocity))


def test_closed_forms_hold_the_documented_keys():
    """Only the closed forms that apply (the CLI's keys): docs/python.md lists what each needs."""
    always = {"hertz_time_k13_22"}
    adhesive = {"sticking_velocity_jkr", "sticking_velocity_k13_25", "e_jkr", "tabor_parameter"}
    viscous = {"dissipative_constant", "e_d"}
    rough = bounce.Pair(material="ice-bshp96", radius=0.01)  # no surface energy
    assert set(bounce.closed_forms(rough, bounce.Model("hertz"), 1.0)) == always
    assert set(bounce.closed_forms(rough, bounce.Model("viscoelastic", A=1e-6), 1.0)) == always | viscous
    assert set(bounce.closed_forms(ice(), bounce.Model("hertz"), 1.0)) == always | adhesive
    assert set(bounce.closed_forms(ice(), krijt(), 1.0)) == always | adhesive | viscous | {"e_i"}
    assert set(bounce.closed_forms(ice(), bounce.Model("adhesive-viscoelastic", tvis=1e-11), 1.0)) == \
        always | adhesive | viscous | {"e_i", "tensile_work_bp04_8_95", "e_ad_bp04_8_98"}
    plastic = bounce.closed_forms(rough, bounce.Model("viscoelastic", A=1e-6, yield_strength=1e8), 1.0)
    assert set(plastic) == always | viscous | {"yield_velocity", "e_plastic", "plastic_length_scale"}
    many = bounce.closed_forms(rough, bounce.Model("viscoelastic", A=1e-6), [0.5, 1.0])
    assert set(many) == always | viscous and many["e_d"].shape == (2,)


# --- 5. trajectory_points: refused at once beyond its declared limit ---------------------------------

def test_trajectory_points_beyond_the_limit_is_refused_at_once():
    start = time.monotonic()
    text = refused(ValueError, "trajectory_points",
                   lambda: bounce.collide(ice(), krijt(), 8.0, trajectory=True, trajectory_points=10**9))
    assert time.monotonic() - start < 1.0  # was 50 s, then MemoryError
    assert "<=" in text  # the limit is stated
    refused(ValueError, "trajectory_points", lambda: bounce.collide(ice(), krijt(), 8.0, trajectory=True,
                                                                     trajectory_points=1))
    refused(ValueError, "trajectory_points", lambda: bounce.collide(ice(), krijt(), 8.0, trajectory=True,
                                                                     trajectory_points=2.5))


# --- 6. tables: the declared bound, messages in Python's names ---------------------------------------

def test_table_bound_and_range_messages_read_well():
    text = refused(ValueError, "bound", lambda: bounce.NormalTable.build(ice(), krijt(), 0.5, 20.0, bound=0))
    assert text == "bound = 0 is invalid: expected 1e-10 < interpolation error bound < 0.1"
    refused(ValueError, "bound", lambda: bounce.NormalTable.build(ice(), krijt(), 0.5, 20.0, bound=1.0))
    text = refused(ValueError, "g_min", lambda: bounce.NormalTable.build(ice(), krijt(), -1.0, 20.0))
    assert "> 0 > 0" not in text and "> 0 m/s > 0" not in text, text
    assert refused(ValueError, "g_max", lambda: bounce.NormalTable.build(ice(), krijt(), 20.0, 0.5)) == \
        "g_max = 0.5 is invalid: expected g_max > g_min = 20 m/s"
    rough = bounce.Pair(material="ice-bshp96", radius=0.01)
    asperity = bounce.Model("viscoelastic", A=1e-6, friction=0.014142, asperity=1e-6, asperity_form="published")
    refused(ValueError, "bound", lambda: bounce.TangentialTable.build(rough, asperity, 0.01, 10.0, 1e-3, 1.0, bound=0))
    refused(ValueError, "gt_max", lambda: bounce.TangentialTable.build(rough, asperity, 0.01, 10.0, 1.0, 1e-3))
    text = refused(ValueError, "friction", lambda: bounce.NormalTable.build(rough, asperity, 0.5, 20.0))
    assert "TangentialTable.build" in text, text


# --- 7. Ctrl-C interrupts a long call -----------------------------------------------------------------

# A SIGINT sent DELAY s into a call that runs for 10 s to 80 s must raise KeyboardInterrupt
# within LATENCY s of it. Measured: 0.01-0.06 s (collide and curve: pieces of under ~20 ms
# between checks; a table: every 50 collisions; contact arrays: every 1024 points).
DELAY, LATENCY = 0.3, 1.0


def interrupt_latency(call):
    """Seconds from a SIGINT (sent by a timer thread DELAY s in) to the KeyboardInterrupt of `call`."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    sent = []
    timer = threading.Timer(DELAY, lambda: (sent.append(time.monotonic()), os.kill(os.getpid(), signal.SIGINT)))
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            call()
        return time.monotonic() - sent[0]
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)


@pytest.mark.parametrize("what,call", [
    ("collide over 1e5 speeds", lambda: bounce.collide(ice(), krijt(), np.full(100_000, 8.0))),
    ("curve over 1e5 speeds", lambda: bounce.curve(ice(), krijt(), np.geomspace(5.0, 50.0, 100_000))),
    ("a table to 1e-9", lambda: bounce.NormalTable.build(ice(), krijt(), 0.5, 200.0, bound=1e-9)),
    ("maugis over 1e6 forces", lambda: bounce.ContactLaw(ice(), "maugis", z0=3e-10).at_force(np.full(10**6, 1e-7))),
    ("a posterior of K13's model", lambda: bounce.posterior(ice(), bounce.Model("krijt"), np.geomspace(1.0, 10.0, 30),
                                                            np.full(30, 0.5), steps=100_000)),
])
def test_ctrl_c_interrupts_a_long_call(what, call):
    assert interrupt_latency(call) < LATENCY, what


# --- a new user's other mistakes -------------------------------------------------------------------

@pytest.mark.parametrize("name,call", [
    ("velocty", lambda: bounce.collide(ice(), krijt(), 8.0, velocty=3.0)),
    ("materal", lambda: bounce.Pair(materal="water-ice", radius=1e-6)),
    ("z", lambda: bounce.Model("krijt", tvis=1e-11, z=1.0)),
    ("foo", lambda: bounce.ContactLaw(ice(), "jkr", foo=1)),
    ("radius", lambda: bounce.collide(ice(), krijt(), 8.0, radius=1e-3)),  # would replace the Pair's silently
    ("material", lambda: bounce.sticking(ice(), krijt(), material="steel")),
    ("wall", lambda: bounce.collide(ice(), krijt(), 8.0, wall="rigid")),
    ("tvis", lambda: bounce.collide(ice(), krijt(), 8.0, tvis=1e-9)),  # the Model already sets it
    ("yield_strength", lambda: bounce.collide(ice(), bounce.Model("krijt", tvis=1e-11, yield_strength=1e8), 8.0,
                                              yield_strength=1e9)),
    ("velocity", lambda: bounce.collide(ice(), krijt(), 0)),
    ("velocity", lambda: bounce.collide(ice(), krijt(), -8.0)),
    ("velocity", lambda: bounce.collide(ice(), krijt(), [8.0, INF])),
    ("follow_time", lambda: bounce.collide(ice(), krijt(), 2.0, follow_time=-1.0)),
    ("kappa", lambda: bounce.master_cor(-1.0)),
    ("velocity", lambda: bounce.NormalTable.build(ice(), krijt(), 0.5, 20.0).cor(NAN)),
    ("cor", lambda: bounce.apply_restitution(ice(), [1, 0, 0], [-1, 0, 0], [0, 0, 0], [0, 0, 0], [0, 0, 0], cor=2.0)),
    ("velocity2", lambda: bounce.collide_grains(ice(), krijt(), [1, 0, 0], [-8, 0, 0], [0, 0, 0], [0, 0, NAN],
                                                [0, 0, 0])),
])
def test_other_bad_values_follow_the_rule(name, call):
    refused(ValueError, name, call)


def test_empty_arrays_give_empty_results():
    r = bounce.collide(ice(), krijt(), [])
    assert r["cor"].shape == (0,) and r["outcome"].dtype.kind == "U" and r["stick"].dtype == bool
    assert bounce.closed_forms(ice(), krijt(), np.array([]))["e_i"].shape == (0,)
    assert bounce.cor_series([]).shape == (0,)
    assert bounce.ContactLaw(ice(), "jkr").at_force([])["force"].shape == (0,)
    # the inputs are still checked
    refused(ValueError, "tangential_velocity", lambda: bounce.collide(ice(), krijt(), [], tangential_velocity=-1.0))


def test_sticking_velocity_is_none_without_a_threshold():
    """A grain that sticks at every speed up to the sound speed: None (the CLI's null and its note)."""
    tiny = bounce.Pair(material="water-ice", radius=1e-9)
    assert bounce.sticking_velocity(tiny, krijt()) is None
    assert "sound speed" in bounce.sticking(tiny, krijt())["note"]
