"""Plots of a fit (docs/fitting.md), as K13 draws them: the data with the best fit (K13 Fig 6)
and the chi^2 landscape of two parameters. Both take the dict :func:`bounce.fit` returns and
draw on axes you give (or on a new figure's); :mod:`bounce.plot` exports them.
"""
from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.ticker import NullFormatter

from ._bounce import models


def _axes(ax: Axes | None) -> Axes:
    return ax if ax is not None else Figure(figsize=(6.4, 4.4), layout="constrained").add_subplot()


def _with_unit(x: float, unit: str) -> str:
    return f"{x:.3g} {_tex_unit(unit)}" if unit else f"{x:.3g}"


def _tex_unit(unit: str) -> str:
    """The registry's "J/m^2" as mathtext (J/m$^2$); "s" and "Pa" as they are."""
    return unit.replace("^2", "$^2$").replace("^3", "$^3$")


def best_text(result: dict) -> str:
    """``gamma = 0.0994 J/m², yield >= 1e9 Pa``: the best values with their units; a value on
    its grid's edge (``grid_edges``) is marked as the limit it is."""
    units, edges = result.get("units", {}), result.get("grid_edges", {})
    limits = result.get("lower_limits", {})  # a parameter the data do not determine: a lower limit
    parts = []
    for k, x in result["best"].items():
        u = units.get(k, "")
        text = f"{k} = {_with_unit(x, u)}" if x is not None else f"{k} >= {_with_unit(limits[k], u)}"
        parts.append(text + (f" (grid's {edges[k]} edge)" if k in edges else ""))
    return ", ".join(parts)


def _drawable(values) -> np.ndarray | None:
    """A column as floats, or None where no value is finite (None and NaN are missing): a
    legend lists only what is drawn."""
    a = np.array([np.nan if x is None else x for x in np.asarray(values, dtype=object)], float)
    return a if np.any(np.isfinite(a)) else None


def fit_curve(result: dict, ax: Axes | None = None, title: str | None = None) -> Axes:
    """K13 Fig 6: the measured COR (with error bars where the data have them; sticking
    collisions at 0), the best fit e of K13 (30), JKR theory (24) at the fitted gamma
    (dashed, adhesive models with a surface energy) and the plastic part e_P (29) (dotted,
    when Y is fitted). Each curve is drawn, and in the legend, only where it has values.
    """
    ax = _axes(ax)
    points, curve = result["points"], result["curve"]
    v, e = np.asarray(points["velocity"], float), np.asarray(points["cor"], float)
    errors = _drawable(points["cor_error"])
    if errors is not None and np.all(np.isfinite(errors)):
        ax.errorbar(v, e, yerr=errors, fmt="o", ms=4, color="k", label="data")
    else:
        ax.plot(v, e, "o", ms=4, color="k", label="data")
    ax.plot(curve["velocity"], curve["cor"], color="C3", label=f"{result['model']}: {best_text(result)}")
    jkr = _drawable(curve["cor_jkr"])
    if jkr is not None:
        ax.plot(curve["velocity"], jkr, "--", color="C0", label="JKR (24) at the fitted $\\gamma$")
    plastic = _drawable(curve["cor_plastic"])
    if result["best"].get("yield") is not None and plastic is not None:
        ax.plot(curve["velocity"], plastic, ":", color="C2", label="plastic $e_P$ (29)")
    ax.set_xscale("log")
    ax.set_ylim(0, 1.05)
    ax.set_xlabel(r"impact velocity $v_{in}$ [m s$^{-1}$]")
    ax.set_ylabel("coefficient of restitution")
    ax.set_title(title if title is not None else f"{result['data']}: $\\chi^2$ = {result['chi2']:.3g}", fontsize=9)
    ax.legend(fontsize=7)
    return ax


# The smallest factor-2 region drawn as a contour: 2 % of an axis's log span (about the best
# fit's 10-point marker on a 6.4 x 4.4 inch figure); a smaller one would be an invisible loop.
VISIBLE_FRACTION = 0.02


def _visible_contour(ax: Axes, xs: np.ndarray, ys: np.ndarray, plane: np.ndarray, level: float) -> bool:
    """The factor-2 contour of K13 §4.1 in white, drawn when the region holds two grid values
    or more and spans VISIBLE_FRACTION of an axis; False when it is not drawn."""
    inside = np.isfinite(plane) & (plane <= level)
    if inside.sum() < 2 or min(len(xs), len(ys)) < 2:
        return False
    rows, cols = np.nonzero(inside)
    span_x = np.log10(xs[cols.max()] / xs[cols.min()]) / np.log10(xs[-1] / xs[0])
    span_y = np.log10(ys[rows.max()] / ys[rows.min()]) / np.log10(ys[-1] / ys[0])
    if max(span_x, span_y) < VISIBLE_FRACTION:
        return False
    ax.contour(xs, ys, plane, levels=[level], colors="w", linewidths=1.2)
    return True


def chi2_map(result: dict, x: str = "gamma", y: str = "tvis", ax: Axes | None = None) -> Axes:
    """The chi^2 (31) landscape over two fitted parameters (log axes), minimised over the
    others, with the factor-2 contour of K13 §4.1 (where it is large enough to see) and the
    best fit marked.
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
    label = "best fit"
    if _visible_contour(ax, xs, ys, plane, 2.0 * result["chi2"]):
        label += r"; white: $\chi^2 = 2\chi^2_{min}$"
    else:
        label += r" ($\chi^2 \leq 2\chi^2_{min}$: too small to draw on this grid)"
    best = [result["best"][n] if result["best"][n] is not None else result["lower_limits"][n] for n in (x, y)]
    ax.plot(*best, "r*", ms=10, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(_axis_label(result["model"], x))
    ax.set_ylabel(_axis_label(result["model"], y))
    ax.legend(fontsize=7, loc="upper right")
    return ax


def _axis_label(model: str, name: str) -> str:
    """``name [unit]`` from the model's parameter table (gamma from the pair's: J/m^2)."""
    units = {"gamma": "J m$^{-2}$"}
    for row in models()["models"]:
        if row["name"] == model:
            units.update({p["name"]: p["unit"] for p in row["parameters"] if p.get("unit")})
    unit = units.get(name, "")
    return f"{name} [{unit}]" if unit else f"{name} [-]"


def _normalised_range(fit: dict, name: str, scale: float) -> tuple[float, float | None, float | None]:
    lo, hi = fit["ranges"][name]
    return fit["best"][name] / scale, (lo / scale if lo is not None else None), (hi / scale if hi is not None else None)


def _interval_plot(ax: Axes, rows: list[tuple[float, float | None, float | None]], labels: list[str], xlabel: str) -> None:
    """Best values with their ranges; an open end is an arrow (K13 Fig 7's grey arrows)."""
    for i, (best, lo, hi) in enumerate(rows):
        left = lo if lo is not None else best / 3.0
        right = hi if hi is not None else best * 3.0
        ax.plot([left, right], [i, i], color="k", lw=1.2)
        ax.plot(best, i, "o", color="C3", ms=5)
        for end, open_end, direction in ((left, lo is None, -1), (right, hi is None, 1)):
            if open_end:
                ax.annotate("", xy=(end * (1.8 if direction > 0 else 1 / 1.8), i), xytext=(end, i),
                            arrowprops=dict(arrowstyle="->", color="0.5", lw=1.5))
    ax.set_yticks(range(len(rows)), labels, fontsize=7)
    ax.set_ylim(len(rows) - 0.5, -0.5)
    ax.set_xscale("log")
    ends = [x for best, lo, hi in rows for x in (best, lo if lo is not None else best / 6, hi if hi is not None else best * 6)]
    ax.set_xlim(min(ends) / 1.5, max(ends) * 1.5)  # the arrows' tips inside
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel(xlabel)


def batch_summary(batch: dict) -> Figure:
    """K13 Figs 7 and 8 for a batch (the JSON of ``bounce fit --batch --json``): gamma / gamma_L
    and Y / E_soft per experiment with their ranges (arrows: one-sided limits), ordered from the
    smallest reduced radius (top) to the largest, and T_vis against the reduced radius.
    """
    fits = sorted(batch["experiments"], key=lambda f: f["scales"]["effective_radius"])
    fig = Figure(figsize=(10.5, 0.3 * len(fits) + 3.2), layout="constrained")
    axes = fig.subplots(1, 3)
    gamma = [f for f in fits if "gamma" in f["best"] and f["scales"]["gamma_L"] is not None]
    if gamma:
        _interval_plot(axes[0], [_normalised_range(f, "gamma", f["scales"]["gamma_L"]) for f in gamma],
                       [f["name"] for f in gamma], r"$\gamma / \gamma_L$ (K13 Fig 7a)")
        axes[0].axvline(1.0, color="0.7", lw=1)
    yields = [f for f in fits if "yield" in f["best"]]
    if yields:
        _interval_plot(axes[1], [_normalised_range(f, "yield", f["scales"]["E_soft"]) for f in yields],
                       [f["name"] for f in yields], r"$Y / E_{soft}$ (K13 Fig 7b)")
    tvis = [f for f in fits if "tvis" in f["best"]]
    values = []
    for f in tvis:
        r, (best, lo, hi) = f["scales"]["effective_radius"], _normalised_range(f, "tvis", 1.0)
        bottom, top = (lo if lo is not None else best / 3.0), (hi if hi is not None else best * 3.0)
        axes[2].plot([r, r], [bottom, top], color="C0", lw=1.2)
        axes[2].plot(r, best, "o", color="C0")
        for end, open_end, factor in ((bottom, lo is None, 1 / 1.8), (top, hi is None, 1.8)):
            if open_end:
                axes[2].annotate("", xy=(r, end * factor), xytext=(r, end),
                                 arrowprops=dict(arrowstyle="->", color="0.5", lw=1.5))
        values += [bottom / 2.0, top * 2.0, r]
    if tvis:
        radii = [f["scales"]["effective_radius"] for f in tvis]
        axes[2].set_xlim(min(radii) / 3.0, max(radii) * 3.0)
        axes[2].set_ylim(min(values[0::3]), max(values[1::3]))
    axes[2].set_xscale("log")
    axes[2].set_yscale("log")
    axes[2].set_xlabel("reduced radius $R$ [m]")
    axes[2].set_ylabel(r"$T_{vis}$ [s] (K13 Fig 8b)")
    for ax, shown in zip(axes, (gamma, yields, tvis)):
        if not shown:
            ax.set_axis_off()
    return fig
