"""Plots of a fit (docs/fitting.md), as K13 draws them: the data with the best fit (K13 Fig 6)
and the chi^2 landscape of two parameters. Both take the dict :func:`bounce.fit` returns and
draw on axes you give (or on a new figure's); :mod:`bounce.plot` exports them.
"""
from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure


def _axes(ax: Axes | None) -> Axes:
    return ax if ax is not None else Figure(figsize=(6.4, 4.4), layout="constrained").add_subplot()


def fit_curve(result: dict, ax: Axes | None = None, title: str | None = None) -> Axes:
    """K13 Fig 6: the measured COR (with error bars where the data have them; sticking
    collisions at 0), the best fit e of K13 (30), JKR theory (24) at the fitted gamma
    (dashed, adhesive models) and the plastic part e_P (29) (dotted, when Y is fitted).
    """
    ax = _axes(ax)
    points, curve = result["points"], result["curve"]
    v, e = np.asarray(points["velocity"], float), np.asarray(points["cor"], float)
    errors = np.asarray(points["cor_error"], dtype=object)
    if all(x is not None and not (isinstance(x, float) and np.isnan(x)) for x in errors):
        ax.errorbar(v, e, yerr=errors.astype(float), fmt="o", ms=4, color="k", label="data")
    else:
        ax.plot(v, e, "o", ms=4, color="k", label="data")
    best = ", ".join(f"{k} = {x:.3g}" for k, x in result["best"].items())
    ax.plot(curve["velocity"], curve["cor"], color="C3", label=f"{result['model']}: {best}")
    jkr = np.asarray(curve["cor_jkr"], dtype=object)
    if all(x is not None for x in jkr):
        ax.plot(curve["velocity"], jkr.astype(float), "--", color="C0", label="JKR (24) at the fitted $\\gamma$")
    if "yield" in result["best"]:
        ax.plot(curve["velocity"], curve["cor_plastic"], ":", color="C2", label="plastic $e_P$ (29)")
    ax.set_xscale("log")
    ax.set_ylim(0, 1.05)
    ax.set_xlabel(r"impact velocity $v_{in}$ [m s$^{-1}$]")
    ax.set_ylabel("coefficient of restitution")
    ax.set_title(title if title is not None else f"{result['data']}: $\\chi^2$ = {result['chi2']:.3g}", fontsize=9)
    ax.legend(fontsize=7)
    return ax


def chi2_map(result: dict, x: str = "gamma", y: str = "tvis", ax: Axes | None = None) -> Axes:
    """The chi^2 (31) landscape over two fitted parameters (log axes), minimised over the
    others, with the factor-2 contour of K13 §4.1 and the best fit marked.
    """
    names = list(result["fitted"])
    for n in (x, y):
        if n not in names:
            raise ValueError(f"{n} = (not fitted) is invalid: expected one of the fitted parameters {', '.join(names)}")
    if x == y:
        raise ValueError(f"y = {y} is invalid: expected a parameter other than x")
    grid = np.asarray(result["chi2_grid"], float)
    others = tuple(i for i, n in enumerate(names) if n not in (x, y))
    plane = np.nanmin(grid, axis=others) if others else grid
    if names.index(x) < names.index(y):
        plane = plane.T  # rows: y, columns: x
    xs, ys = np.asarray(result["grid_values"][x]), np.asarray(result["grid_values"][y])
    ax = _axes(ax)
    mesh = ax.pcolormesh(xs, ys, np.log10(plane), shading="nearest", cmap="viridis")
    ax.figure.colorbar(mesh, ax=ax, label=r"$\log_{10}\chi^2$")
    level = 2.0 * result["chi2"]
    label = "best fit"
    if np.nanmin(plane) <= level:  # else the factor-2 region lies between grid values
        ax.contour(xs, ys, plane, levels=[level], colors="w", linewidths=1.2)
        label += r"; white: $\chi^2 = 2\chi^2_{min}$"
    ax.plot(result["best"][x], result["best"][y], "r*", ms=10, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(x)
    ax.set_ylabel(y)
    ax.legend(fontsize=7, loc="upper right")
    return ax
