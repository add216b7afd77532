"""The corner plot of a posterior (docs/fitting.md, "Posteriors"): :func:`bounce.posterior`'s
samples as marginal histograms on the diagonal and pairwise densities below it, in log10 of each
parameter (the space the sampler moves in). :mod:`bounce.plot` exports it.
"""
from __future__ import annotations

from typing import Mapping

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

#: The units of the parameters a fit can fit (SI), for the axes' labels.
UNITS = {"gamma": "J m$^{-2}$", "tvis": "s", "yield": "Pa", "A": "s", "z0": "m", "k": "", "friction": ""}


def _label(name: str) -> str:
    unit = UNITS.get(name, "")
    return f"log$_{{10}}$ {name}" + (f" [{unit}]" if unit else "")


def _marginal(ax: Axes, x: np.ndarray, lo68: float, hi68: float, lo95: float, hi95: float, bins: int) -> None:
    ax.hist(x, bins=bins, density=True, histtype="stepfilled", color="C0", alpha=0.35)
    ax.hist(x, bins=bins, density=True, histtype="step", color="C0")
    for edge, style in ((lo68, "--"), (hi68, "--"), (lo95, ":"), (hi95, ":")):
        ax.axvline(np.log10(edge), color="k", ls=style, lw=0.8)
    ax.axvline(np.median(x), color="k", lw=1.0)
    ax.set_yticks([])


def _density(ax: Axes, x: np.ndarray, y: np.ndarray, bins: int) -> None:
    """Filled contours of the 2-d histogram at the levels enclosing 39 %, 86 % and 99 % of the
    samples (the 1, 2 and 3 sigma regions of a 2-d Gaussian), over the samples as dots."""
    ax.plot(x, y, ",", color="0.6", alpha=0.3, rasterized=True)
    h, xe, ye = np.histogram2d(x, y, bins=bins)
    order = np.sort(h.ravel())[::-1]
    cumulative = np.cumsum(order) / max(order.sum(), 1)
    levels = sorted({float(order[min(np.searchsorted(cumulative, q), order.size - 1)]) for q in (0.99, 0.86, 0.39)})
    if len(levels) < 2 or levels[-1] <= 0:
        return
    xc, yc = 0.5 * (xe[1:] + xe[:-1]), 0.5 * (ye[1:] + ye[:-1])
    ax.contourf(xc, yc, h.T, levels=levels + [h.max() + 1], cmap="Blues", alpha=0.8)
    ax.contour(xc, yc, h.T, levels=levels, colors="C0", linewidths=0.8)


def corner(result: Mapping, truths: Mapping | None = None, bins: int = 30, figure: Figure | None = None) -> Figure:
    """Marginals (diagonal: histogram, median solid, 68 % dashed, 95 % dotted) and pairwise
    densities (below: 39/86/99 % contours over the samples) of ``result = bounce.posterior(...)``,
    in log10 of each parameter. ``truths``: {name: value} drawn as red lines (synthetic data)."""
    names = list(result["names"])
    samples = np.log10(np.asarray(result["samples"], float))
    if samples.ndim != 2 or samples.shape[1] != len(names) or samples.shape[0] < 2:
        raise ValueError(f"result['samples'] has shape {samples.shape}: expected (n >= 2, {len(names)}) as "
                         "bounce.posterior returns")
    truths = dict(truths or {})
    unknown = sorted(set(truths) - set(names))
    if unknown:
        raise ValueError(f"truths = {unknown[0]} is invalid: expected one of the posterior's names {', '.join(names)}")
    p = len(names)
    fig = figure or Figure(figsize=(2.2 * p + 0.8, 2.2 * p + 0.6), layout="constrained")
    axes = fig.subplots(p, p, squeeze=False)
    for i, name in enumerate(names):
        for j in range(p):
            ax = axes[i, j]
            if j > i:
                ax.set_axis_off()
                continue
            if i == j:
                _marginal(ax, samples[:, i], *result["credible_68"][name], *result["credible_95"][name], bins)
            else:
                _density(ax, samples[:, j], samples[:, i], bins)
                if names[i] in truths:
                    ax.axhline(np.log10(truths[names[i]]), color="C3", lw=1.0)
            if names[j] in truths:
                ax.axvline(np.log10(truths[names[j]]), color="C3", lw=1.0)
            if i == p - 1:
                ax.set_xlabel(_label(names[j]))
            else:
                ax.set_xticklabels([])
            if j == 0 and i > 0:
                ax.set_ylabel(_label(name))
            elif j > 0:
                ax.set_yticklabels([])
        for j in range(i):  # a column's panels share the diagonal's range
            axes[i, j].set_xlim(axes[j, j].get_xlim())
    for i in range(1, p):
        for j in range(i):
            axes[i, j].set_ylim(axes[i, i].get_xlim())
    n = samples.shape[0]
    fig.suptitle(f"posterior: {n} samples, {result.get('walkers', '?')} walkers x {result.get('steps', '?')} steps",
                 fontsize="medium")
    return fig
