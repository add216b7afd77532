"""bounce.fit (docs/fitting.md): the same answer as the CLI, arrays and files read by the same
rules, the chi^2 grid as a numpy array, and the plots of a fit."""
import json
import os
import subprocess

import numpy as np
import pytest

import bounce
import bounce.plot

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ICE = dict(material="ice-bshp96", radius=1e-2)
GRID = {"A": (1e-8, 1e-4, 13)}


def _curve(a=2e-6):
    v = np.geomspace(0.01, 3.0, 10)
    return v, bounce.collide(bounce.Pair(**ICE), bounce.Model("viscoelastic", A=a), v)["cor"]


def test_recovers_a_from_the_models_own_curve():
    v, e = _curve()
    r = bounce.fit(bounce.Pair(**ICE), bounce.Model("viscoelastic"), v, e, grid=GRID, precision=1e-5)
    # Nelder-Mead to 1e-5 in log A; the data are the model's own values.
    assert r["best"]["A"] == pytest.approx(2e-6, rel=1e-4)
    assert r["chi2"] < 1e-12
    assert set(r) >= {"best", "ranges", "chi2", "points", "profiles", "curve", "chi2_grid", "grid_values"}
    assert r["chi2_grid"].shape == (13,)
    assert np.all(np.isfinite(r["chi2_grid"]))
    # the grid's values: exp of evenly spaced logs (rounding of exp and log only)
    assert np.allclose(r["grid_values"]["A"], np.geomspace(1e-8, 1e-4, 13), rtol=1e-14, atol=0)


def test_equals_the_cli_on_a_file(tmp_path):
    v, e = _curve(5e-6)
    path = tmp_path / "d.csv"
    # float(): numpy 2 spells a float64 np.float64(...) in repr, numpy 1 as a plain number
    path.write_text("velocity,cor,cor_error\n" + "".join(f"{float(x)!r},{float(y)!r},0.01\n" for x, y in zip(v, e)))
    py = bounce.fit(bounce.Pair(**ICE), bounce.Model("viscoelastic"), data=str(path), grid=GRID, fit="A,yield_strength")
    cli = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
    out = subprocess.run([cli, "fit", "--data", str(path), "--material", "ice-bshp96", "--radius", "1e-2", "--model",
                          "viscoelastic", "--grid", "A=1e-8:1e-4:13", "--fit", "A,yield", "--json"],
                         check=True, capture_output=True, text=True).stdout
    j = json.loads(out)
    assert py["best"] == j["best"]
    assert py["chi2"] == j["chi2"]
    assert py["intervals"] == j["intervals"]
    assert py["chi2_grid"].shape == (13, 100)


def test_arrays_meet_the_files_rules():
    pair, model = bounce.Pair(**ICE), bounce.Model("viscoelastic")
    with pytest.raises(ValueError, match=r"cor\[1\] = 2 is invalid"):
        bounce.fit(pair, model, [0.1, 0.2], [0.5, 2.0], grid=GRID)
    with pytest.raises(ValueError, match=r"velocity\[0\] = -1 is invalid"):
        bounce.fit(pair, model, [-1.0], [0.5], grid=GRID)
    with pytest.raises(ValueError, match=r"cor_error\[0\] = 0 is invalid"):
        bounce.fit(pair, model, [0.1], [0.5], cor_error=[0.0], grid=GRID)
    with pytest.raises(ValueError, match="same length"):
        bounce.fit(pair, model, [0.1, 0.2], [0.5], grid=GRID)
    with pytest.raises(ValueError, match=r"velocity\[0\] = nan is invalid"):
        bounce.fit(pair, model, [float("nan")], [0.5], grid=GRID)
    with pytest.raises(ValueError, match="not both"):
        bounce.fit(pair, model, [0.1], [0.5], data="x.csv")
    with pytest.raises(ValueError, match="data = /nonexistent.csv is invalid"):
        bounce.fit(pair, model, data="/nonexistent.csv")
    with pytest.raises(ValueError, match="fit = A,gamma is invalid"):
        bounce.fit(pair, model, [0.1], [0.5], fit=("A", "gamma"))
    with pytest.raises(TypeError):
        bounce.fit(pair, model, [0.1], [0.5], fit=(1, 2))
    with pytest.raises(TypeError):
        bounce.fit(pair, model, ["a"], [0.5])


def test_plots_of_a_fit():
    v, e = _curve()
    r = bounce.fit(bounce.Pair(**ICE), bounce.Model("viscoelastic"), v, e, cor_error=np.full(v.size, 0.01),
                   grid={"A": (1e-8, 1e-4, 9), "yield_strength": (1e7, 1e11, 9)}, fit=["A", "yield"])
    ax = bounce.plot.fit_curve(r)
    assert len(ax.lines) >= 2
    ax = bounce.plot.chi2_map(r, "A", "yield")
    assert ax.get_xlabel() == "A [s]"  # with its unit (row 14 of reliability round 2)
    with pytest.raises(ValueError, match="gamma = \\(not fitted\\) is invalid"):
        bounce.plot.chi2_map(r, "gamma", "A")


def test_batch_summary_plots_k13_figs_7_and_8(tmp_path):
    for name in ("synthetic-psl-quartz.csv", "synthetic-agglass-steel.csv"):
        (tmp_path / name).write_text(open(os.path.join(ROOT, "data", "experiments", name)).read())
    (tmp_path / "m.toml").write_text(
        '[defaults]\nmodel = "krijt"\n'
        '[[experiment]]\nname = "psl"\ndata = "synthetic-psl-quartz.csv"\nmaterial = "psl"\nradius = 0.635e-6\n'
        'wall = true\nmaterial2 = "quartz"\ngrid = "gamma=0.01:0.2:6,tvis=1e-13:1e-10:6,yield=1e7:1e10:20"\n'
        '[[experiment]]\nname = "agglass"\ndata = "synthetic-agglass-steel.csv"\nmaterial = "ag-coated-glass"\n'
        'radius = 4.3e-6\nwall = true\nmaterial2 = "steel"\ngrid = "gamma=0.1:4:6,tvis=1e-12:1e-9:6,yield=1e8:1e11:20"\n')
    cli = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
    batch = json.loads(subprocess.run([cli, "fit", "--batch", str(tmp_path / "m.toml"), "--json"], check=True,
                                      capture_output=True, text=True).stdout)
    assert [f["name"] for f in batch["experiments"]] == ["psl", "agglass"]
    for f in batch["experiments"]:
        assert f["scales"]["effective_radius"] > 0 and f["scales"]["plastic_length_scale"] > 0
    fig = bounce.plot.batch_summary(batch)
    gamma_axes, yield_axes, tvis_axes = fig.axes[:3]
    assert len(gamma_axes.get_yticks()) == 2
    assert tvis_axes.get_xscale() == "log"
