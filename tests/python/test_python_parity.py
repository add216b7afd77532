"""Issue 40, round 3, section D: Python as complete as the CLI (docs/hardening.md, "round 3").
Point 13: curve() returns the validity warnings the CLI's curve prints and raises them as
bounce.ValidityWarning; point 14: sticking(pair, model, radii=array) is `sticking --radii`, numpy
in and out; point 16: a misspelt keyword (Python) or --fit name (CLI) gets a suggestion."""
import json
import os
import re
import subprocess
import warnings

import numpy as np
import pytest

import bounce

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
ICE = bounce.Pair(material="water-ice", radius=1e-6)
SLOW_CRACK = bounce.Model("krijt", tvis=1e-8)  # T_vis not << t_c: the CLI warns (BSHP96 (B12), K13 (A.2), (A.4))


def cli_warnings(*args):
    done = subprocess.run([CLI, *args], capture_output=True, text=True, check=True)
    return [line[len("bounce: warning: "):] for line in done.stderr.splitlines() if line.startswith("bounce: warning: ")]


def test_curve_returns_and_raises_the_clis_warnings():
    """The same texts as `bounce curve --csv` prints, without its "(N rows in all)" (main returned none)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        d = bounce.curve(ICE, SLOW_CRACK, np.array([1.0, 5.5, 10.0]))
    cli = cli_warnings("curve", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis", "1e-8",
                       "--velocities", "1:10:3", "--csv")
    assert len(d["warnings"]) >= 3 and [re.sub(r" \(\d+ rows in all\)$", "", w) for w in cli] == d["warnings"]
    raised = [str(w.message) for w in caught if issubclass(w.category, bounce.ValidityWarning)]
    assert raised == d["warnings"]
    assert issubclass(bounce.ValidityWarning, UserWarning)


def test_a_valid_curve_warns_nothing():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        d = bounce.curve(ICE, bounce.Model("krijt", tvis=1e-14), [0.5, 1.0])
    assert d["warnings"] == []


def test_sticking_over_radii_is_the_clis_sweep():
    """numpy in, a dict of arrays of its shape out, the CLI's numbers (main: "expected a str")."""
    radii = np.geomspace(1e-7, 1e-5, 3)
    d = bounce.sticking(ICE, bounce.Model("krijt", tvis=1e-11), radii=radii)
    assert d["radius"].shape == (3,) and np.array_equal(d["radius"], radii)
    out = subprocess.run([CLI, "sticking", "--material", "water-ice", "--model", "krijt", "--tvis", "1e-11",
                          "--radii", "1e-7:1e-5:3", "--log"], capture_output=True, text=True, check=True).stdout
    rows = [line.split(",") for line in out.splitlines()[1:]]
    assert np.isnan(d["sticking_velocity"][0]) and rows[0][2] == "" and "sound speed" in d["note"][0]
    for row, v, note in zip(rows[1:], d["sticking_velocity"][1:], d["note"][1:]):
        assert float(row[2]) == pytest.approx(v, rel=1e-12) and note == ""
    grid = bounce.sticking(ICE, bounce.Model("krijt", tvis=1e-11), radii=[[1e-6, 2e-6]])
    assert grid["sticking_velocity"].shape == (1, 2)


@pytest.mark.parametrize("radii,error", [("1e-7:1e-5:3", TypeError), ([1e-6, -1.0], ValueError),
                                         ([1e-6, np.inf], ValueError)])
def test_bad_radii_are_refused_by_the_rule(radii, error):
    with pytest.raises(error, match=r"^radii = .* is invalid: expected"):
        bounce.sticking(ICE, bounce.Model("krijt", tvis=1e-11), radii=radii)


def test_misspelt_keywords_get_a_suggestion():
    with pytest.raises(ValueError, match=r"did you mean tvis\?$"):
        bounce.Model("krijt", t_vis=1e-11)
    with pytest.raises(ValueError, match=r"did you mean radius2\?$"):
        bounce.Pair(material="water-ice", radius=1e-6, radus2=1.0)
    with pytest.raises(ValueError, match=r"did you mean tangential_velocity\?$"):
        bounce.collide(ICE, bounce.Model("krijt", tvis=1e-11), 1.0, tangental_velocity=1.0)


def test_misspelt_fit_parameter_gets_a_suggestion(tmp_path):
    data = tmp_path / "d.csv"
    data.write_text("velocity,cor\n1,0.5\n2,0.6\n3,0.7\n")
    done = subprocess.run([CLI, "fit", "--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis",
                           "1e-11", "--fit", "A,yeild", "--data", str(data)], capture_output=True, text=True)
    assert done.returncode == 2 and done.stderr.strip().endswith("(yeild is none of them; did you mean yield?)")


def test_analytic_marks_a_divergent_series_and_keeps_small_values():
    """Point 2: at q = 4.35 (ice on a wall, A = 5.05e-5 s, 10 m/s) main printed the series' 8.3, 39.7,
    50.5 and 190 as coefficients of restitution, and 2.2e-14 as 0.0000000000 (A = 1e-2 s)."""
    base = ["analytic", "--material", "ice-bshp96", "--radius", "0.01", "--wall", "--velocity", "10"]
    done = subprocess.run([CLI, *base, "--A", "5.05e-5", "--json"], capture_output=True, text=True, check=True)
    series = json.loads(done.stdout)["series_8_89"]
    assert all(series[k] is None for k in ("bp04_simple", "bp04_rigorous", "bounce_overlap", "bounce_force"))
    assert len(series["warnings"]) == 4 and "radius of convergence" in series["warnings"][0]
    text = subprocess.run([CLI, *base, "--A", "5.05e-5"], capture_output=True, text=True, check=True).stdout
    assert text.count("diverges (below)") == 4 and "8.3001" not in text
    small = subprocess.run([CLI, *base, "--A", "1e-2"], capture_output=True, text=True, check=True).stdout
    assert "0.0000000000" not in small
    slow = json.loads(subprocess.run([CLI, *base[:-1], "0.001", "--A", "1e-6", "--json"], capture_output=True,
                                     text=True, check=True).stdout)["series_8_89"]
    assert "warnings" not in slow and 0.0 < slow["bounce_overlap"] <= 1.0  # small q: the series is a COR
