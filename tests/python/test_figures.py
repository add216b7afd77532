"""Every figure function runs and writes a non-empty PNG and SVG (coarse grids: quick=True)."""
import pathlib
import subprocess
import sys

import pytest

from bounce import figures, plot


@pytest.mark.parametrize("name", list(plot.FIGURES))
def test_figure_writes_png_and_svg(name, tmp_path: pathlib.Path):
    written = figures.write_figures(tmp_path, [name], quick=True, progress=lambda s: None, dpi=60)
    assert [p.name for p in written] == [f"{name}.png", f"{name}.svg"]
    png, svg = written
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10_000
    text = svg.read_text()
    assert text.lstrip().startswith("<?xml") and "</svg>" in text
    # The caption names the paper's figure.
    paper = {"bshp96": "BSHP96 Fig.", "bp04": "BP04 Fig.", "k13": "K13 Fig."}[name.split("-")[0]]
    assert paper in text


def test_bridges_law_and_fitted_a():
    assert plot.bridges_law(0.01) == pytest.approx(0.32)  # 1 cm/s
    import bounce
    pair = bounce.Pair(material="ice-bshp96", radius=0.01)
    a = plot.dissipative_constant_for(pair, 0.32e-2)
    g_star = bounce.viscoelastic_scales(pair, bounce.Model(A=a), 1.0)["characteristic_velocity"]
    assert g_star == pytest.approx(0.32e-2, rel=1e-12)  # g* ~ A^-5 exactly (BP04 (8.88))
    with pytest.raises(ValueError):
        plot.dissipative_constant_for(pair, 0.0)


def test_command_rejects_unknown_figure(tmp_path: pathlib.Path):
    r = subprocess.run([sys.executable, "-m", "bounce.figures", "--out", str(tmp_path), "--only", "k13-fig9"],
                       capture_output=True, text=True)
    assert r.returncode == 2
    assert "figure = k13-fig9 is invalid: expected one of" in r.stderr


@pytest.mark.parametrize("page,images", [("python.md", ["cor.png", "k13-fig4.png"]),
                                         ("figures.md", ["k13-fig4.png", "silicon-energies.png"])])
def test_docs_examples_run(page, images, tmp_path: pathlib.Path, monkeypatch):
    """The Python examples of docs/python.md (the tour) and docs/figures.md, run as written."""
    import re
    docs = pathlib.Path(__file__).resolve().parents[2] / "docs" / page
    code = re.search(r"```python\n(.*?)```", docs.read_text(), re.S).group(1)
    monkeypatch.chdir(tmp_path)
    exec(compile(code, str(docs), "exec"), {})
    for image in images:
        assert (tmp_path / image).stat().st_size > 10_000


def test_building_blocks_draw_on_given_axes(tmp_path: pathlib.Path):
    from matplotlib.figure import Figure
    import numpy as np
    import bounce

    fig = Figure()
    ax = fig.add_subplot(2, 2, 1)
    ice = bounce.Pair(material="ice-bshp96", radius=0.01)  # no surface energy: Hertz only
    assert plot.cor_curve(ice, bounce.Model(A=1e-6), np.geomspace(1e-3, 1, 5), ax=ax) is ax
    assert len(ax.lines) == 1 and ax.get_xscale() == "log"
    axes = (fig.add_subplot(2, 2, 2), fig.add_subplot(2, 2, 3))
    assert plot.contact_history(ice, bounce.Model(A=1e-6), 0.1, axes=axes, points=50) == axes
    assert [line.get_label() for line in axes[0].lines] == ["bounce, 0.1 m/s", "Hertz (4)"]
    e = plot.energy_budget(bounce.Pair(material="water-ice", radius=1e-6), bounce.Model("krijt", tvis=1e-11), 8.0,
                           ax=fig.add_subplot(2, 2, 4), points=50)
    kinetic = e.lines[0].get_ydata()
    assert kinetic[0] == 1.0 and 0 < kinetic[-1] < 1  # normalised to U_K(0); a bounce keeps some
    fig.savefig(tmp_path / "blocks.png")
    assert (tmp_path / "blocks.png").stat().st_size > 10_000
