"""Issue 40, round 3 (docs/hardening.md, "round 3"), the experimentalist's fit: the Python fit
plots' legends list only what they draw (point 15); fit output and legends carry units,
`--compare` lists each model's best values, `fit --plot FILE` writes the figure (point 17); a
best value on a grid edge is reported in text, JSON and Python, and a posterior's yield prior
stops at the theoretical 0.2 E_soft (point 18). The data are the issue's steel set (no adhesion).
"""
import json
import os
import subprocess

import numpy as np
import pytest

import bounce
import bounce.plot

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
STEEL = [(0.05, 0.975), (0.08, 0.972), (0.12, 0.970), (0.2, 0.966), (0.3, 0.962), (0.45, 0.955), (0.6, 0.951),
         (0.8, 0.944), (1.0, 0.938), (1.3, 0.927), (1.6, 0.918), (2.0, 0.905), (2.5, 0.889), (3.0, 0.874)]
PAIR = ["--material", "steel", "--radius", "0.5e-3", "--wall", "--material2", "ag-coated-glass"]
# Krijt on a small grid whose gamma starts at 0.1 gamma_L (0.0994 J/m^2), where this data's best
# gamma sits: a few seconds instead of the default grid's half minute.
KRIJT_GRID = ["--model", "krijt", "--grid", "gamma=0.0994:9.94:4,tvis=1e-9:5e-9:4"]


@pytest.fixture(scope="module")
def steel_csv(tmp_path_factory):
    path = tmp_path_factory.mktemp("steel") / "steel.csv"
    path.write_text("velocity [m/s],cor,cor_error\n" + "".join(f"{v},{e},0.01\n" for v, e in STEEL))
    return str(path)


@pytest.fixture(scope="module")
def viscoelastic_fit(steel_csv):
    pair = bounce.Pair(material="steel", radius=0.5e-3, wall=True, material2="ag-coated-glass")
    return bounce.fit(pair, bounce.Model("viscoelastic"), data=steel_csv, fit=["A", "yield"])


def fit(*args, check=True):
    done = subprocess.run([CLI, "fit", *args], capture_output=True, text=True, timeout=600)
    if check:
        assert done.returncode == 0, done.stderr
    return done


def drawn(artist) -> bool:
    """A legend entry's artist holds at least one finite point (an errorbar's: its line)."""
    line = artist[0] if isinstance(artist, tuple) else artist
    if hasattr(line, "get_ydata"):
        return bool(np.any(np.isfinite(np.asarray(line.get_ydata(), float))))
    return True


def test_fit_curve_legend_lists_only_what_is_drawn(viscoelastic_fit):
    """Point 15: main listed "JKR (24) at the fitted gamma" for the viscoelastic fit (no gamma)
    and drew nothing for it (its column is NaN)."""
    ax = bounce.plot.fit_curve(viscoelastic_fit)
    handles, labels = ax.get_legend_handles_labels()
    assert not any("JKR" in label for label in labels)
    assert all(drawn(h) for h in handles), labels
    # Point 17: the legend's best values carry their units.
    assert any("A = 5.14e-08 s" in label and "yield = 1.49e+09 Pa" in label for label in labels), labels


def test_chi2_map_promises_the_factor_2_contour_only_where_it_draws_one(viscoelastic_fit, steel_csv):
    """Point 15: on the default grid the factor-2 region is two grid values (1-2 % of the axes);
    main's legend promised a white contour there. On a fine grid around the minimum it is drawn."""
    ax = bounce.plot.chi2_map(viscoelastic_fit, "A", "yield")
    labels = ax.get_legend_handles_labels()[1]
    assert not any("white" in label for label in labels), labels
    assert not ax.collections[1:], "no contour drawn"  # the mesh alone
    pair = bounce.Pair(material="steel", radius=0.5e-3, wall=True, material2="ag-coated-glass")
    fine = bounce.fit(pair, bounce.Model("viscoelastic"), data=steel_csv, fit=["A", "yield"],
                      grid={"A": (2e-8, 1.2e-7, 25), "yield": (1e9, 2.2e9, 25)})
    ax = bounce.plot.chi2_map(fine, "A", "yield")
    assert any("white" in label for label in ax.get_legend_handles_labels()[1])
    assert any(len(p.vertices) > 4 for c in ax.collections[1:] for p in c.get_paths())


def test_fit_text_and_json_carry_units(steel_csv):
    """Point 17: main printed `A = 5.1444e-08` and `yield = 1.48976e+09` without units."""
    out = fit("--data", steel_csv, *PAIR, "--model", "viscoelastic", "--fit", "A,yield").stdout
    assert "  A        = 5.1444e-08 s " in out, out
    assert "  yield    = 1.48976e+09 Pa " in out, out
    assert "range 3.892e-08 .. 6.301e-08 s" in out, out
    j = json.loads(fit("--data", steel_csv, *PAIR, "--model", "viscoelastic", "--fit", "A,yield", "--json").stdout)
    assert j["units"] == {"A": "s", "yield": "Pa"}
    assert j["grid_edges"] == {}


def test_compare_lists_each_models_best_values(steel_csv):
    """Point 17: main's comparison listed chi2, AIC and BIC only."""
    out = fit("--data", steel_csv, *PAIR, "--compare", "--grid-only").stdout
    rows = out.split("comparison (lowest AIC first is best):\n")[1].splitlines()
    best = {rows[i].split("  chi2")[0].strip(): rows[i + 1].strip() for i in range(0, 10, 2)}
    assert best["viscoelastic + plastic, no adhesion"].startswith("A = "), best
    assert " s, yield = " in best["viscoelastic + plastic, no adhesion"] and best["viscoelastic + plastic, no adhesion"].endswith(" Pa")
    k13 = best["K13: adhesion, viscous crack, bulk damping, plastic"]
    assert k13.startswith("gamma = ") and "J/m^2 (on the grid's lower edge: a limit), tvis = " in k13, k13


@pytest.mark.parametrize("extension,magic", [("png", b"\x89PNG"), ("svg", b"<?xml"), ("pdf", b"%PDF")])
def test_fit_plot_writes_the_figure(steel_csv, tmp_path, extension, magic):
    """Point 17: `bounce fit --plot FILE` (main: "The following argument was not expected: --plot")."""
    path = tmp_path / f"fit.{extension}"
    done = fit("--data", steel_csv, *PAIR, "--model", "viscoelastic", "--fit", "A,yield", "--plot", str(path))
    assert "A        = 5.1444e-08 s" in done.stdout  # the text as without --plot
    assert path.read_bytes().startswith(magic)


def test_fit_plot_refuses_what_it_cannot_draw(steel_csv, tmp_path):
    """An unknown extension, and a python3 without matplotlib, are exit 2 before the fit."""
    done = fit("--data", steel_csv, *PAIR, "--plot", str(tmp_path / "fit.jpg"), check=False)
    assert done.returncode == 2
    assert done.stderr == (f"bounce: error: --plot = {tmp_path / 'fit.jpg'} is invalid: expected a file name ending "
                           "in .png, .svg or .pdf (the figure's format)\n")
    fake = tmp_path / "fake" / "matplotlib"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text('raise ImportError("no matplotlib here")\n')
    done = subprocess.run([CLI, "fit", "--data", steel_csv, *PAIR, "--plot", str(tmp_path / "fit.png")],
                          capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, PYTHONPATH=str(tmp_path / "fake")))
    assert done.returncode == 2, done.stderr
    assert done.stderr.startswith(f"bounce: error: --plot = {tmp_path / 'fit.png'} is invalid: expected a machine "
                                  "where /usr/bin/python3 draws it with matplotlib")
    assert "no matplotlib here" in done.stderr and done.stdout == ""
    assert not (tmp_path / "fit.png").exists()


def test_best_value_on_a_grid_edge_is_reported_everywhere(steel_csv):
    """Point 18: krijt's best gamma sits on the grid's floor (0.1 gamma_L, no adhesion to speak
    of): main said so in a warning only, not by the value in text, JSON or Python."""
    j = json.loads(fit("--data", steel_csv, *PAIR, *KRIJT_GRID, "--json").stdout)
    assert j["grid_edges"] == {"gamma": "lower"}
    assert j["units"] == {"gamma": "J/m^2", "tvis": "s", "yield": "Pa"}
    out = fit("--data", steel_csv, *PAIR, *KRIJT_GRID).stdout
    assert "J/m^2 (on the grid's lower edge: a limit) range" in out.splitlines()[2], out
    pair = bounce.Pair(material="steel", radius=0.5e-3, wall=True, material2="ag-coated-glass")
    r = bounce.fit(pair, bounce.Model("krijt"), data=steel_csv, grid={"gamma": (0.0994, 9.94, 4), "tvis": (1e-9, 5e-9, 4)})
    assert r["grid_edges"] == {"gamma": "lower"}
    assert "(grid's lower edge)" in bounce.plot.fit_curve(r).get_legend_handles_labels()[1][0]


def test_posterior_yield_prior_stops_at_the_theoretical_bound(steel_csv):
    """Point 18: main's prior reached 1 E_soft = 7.2e10 Pa (95 % intervals up to 6.4e10 Pa),
    above the theoretical 0.2 E_soft = 1.44e10 Pa of K13 Fig 7 (b)."""
    pair = bounce.Pair(material="steel", radius=0.5e-3, wall=True, material2="ag-coated-glass")
    model = bounce.Model("viscoelastic")
    e_soft = 72e9  # ag-coated glass (K13 Table 2): softer than steel
    p = bounce.posterior(pair, model, data=steel_csv, fit=["A", "yield"], walkers=16, steps=20, seed=1, threads=1)
    assert p["prior"]["yield"][1] == pytest.approx(0.2 * e_soft, rel=1e-12)  # the bound as computed, 1 ulp
    assert np.max(p["samples"][:, 1]) <= 0.2 * e_soft
    with pytest.raises(ValueError, match=r"priors\[yield\] = \(100000000.0, 50000000000.0\) is invalid: expected hi <= 0.2 "
                                         r"E_soft = 1.44e\+10 Pa"):
        bounce.posterior(pair, model, data=steel_csv, fit=["A", "yield"], priors={"yield": (1e8, 5e10)}, steps=10)


def test_default_viscous_grid_ends_where_the_models_do():
    """The default A grid reaches 1e-2 s, beyond the viscous models' bound for micrometre grains
    (1e6 t_H(c_t) = 1.9e-3 s for PSL on quartz): before the grid was clipped there, `bounce fit
    --model viscoelastic` and `fit --compare` (the README's tour) ended in exit 2 on "--A =
    0.0021 is invalid" from their own trial (docs/fitting.md)."""
    data = os.path.join(ROOT, "data", "experiments", "synthetic-psl-quartz.csv")
    done = subprocess.run([CLI, "fit", "--data", data, "--material", "psl", "--radius", "0.635e-6", "--wall",
                           "--material2", "quartz", "--model", "viscoelastic", "--json"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    r = json.loads(done.stdout)
    assert r["grid"]["A"]["hi"] <= 1.93e-3 < 1e-2, r["grid"]["A"]
