"""The collision atlas (docs/atlas.md): eps, sticking and v_stick over radius and speed, read
from a file of `bounce atlas build`, looked up with numpy broadcasting::

    import numpy as np, bounce.atlas
    atlas = bounce.atlas.open("ice.h5", model="krijt")
    a = np.geomspace(1e-7, 1e-3, 100)                      # radii [m]
    atlas.cor(a[:, None], a[None, :], 3.0)                 # (100, 100) eps at 3 m/s
    atlas.p_stick(a[:, None], a[None, :], sigma_v=1.0)     # sticking probability, Maxwellian speeds

Radii in m (R2 = np.inf: a wall of the atlas's second material), speeds in m/s. A value
outside the atlas raises ValueError naming it and the atlas's range: never an extrapolation.
"""

from __future__ import annotations

import os
from typing import Callable, Optional, Union

import numpy as np

from . import _bounce

__all__ = ["open", "Atlas", "maxwell_cdf", "plot_map"]

Distribution = Union[str, Callable[[np.ndarray, np.ndarray], np.ndarray]]


def maxwell_cdf(v, sigma):
    """P(speed <= v) for a Maxwellian relative speed of scale sigma > 0: the pdf
    sqrt(2/pi) v^2 / sigma^3 exp(-v^2 / (2 sigma^2)), mean speed sigma sqrt(8/pi); the CDF is the
    regularised incomplete gamma function P(3/2, v^2 / (2 sigma^2)) (no cancellation at small v)."""
    from scipy.special import gammainc

    v, sigma = np.asarray(v, dtype=float), np.asarray(sigma, dtype=float)
    _require_positive("sigma_v", sigma)
    if np.any(np.isnan(v)) or np.any(v < 0):
        bad = v[np.isnan(v) | (v < 0)].flat[0]
        raise ValueError(f"velocity = {bad} is invalid: expected a speed >= 0 [m/s] (inf allowed)")
    x = v / sigma
    with np.errstate(over="ignore", invalid="ignore"):
        return np.where(np.isinf(x), 1.0, gammainc(1.5, 0.5 * x * x))


def _require_positive(name, values):
    values = np.asarray(values, dtype=float)
    bad = ~(np.isfinite(values) & (values > 0))
    if np.any(bad):
        raise ValueError(f"{name} = {values[bad].flat[0]} is invalid: expected a finite number > 0")


class Atlas:
    """An atlas file's lookups. Its description (model, parameters with units, materials,
    ranges, grid, measured errors, bounce version) is `describe()`."""

    def __init__(self, core: _bounce.Atlas, path: str):
        self._core = core
        self.path = path

    @property
    def model(self) -> str:
        return self._core.model

    @property
    def cor_error(self) -> float:
        """The stated bound on |eps_atlas - eps_collide| (twice the largest measured)."""
        return self._core.cor_error

    @property
    def v_stick_error(self) -> float:
        """The stated bound on the relative error of v_stick (inside the atlas's speeds)."""
        return self._core.v_stick_error

    @property
    def velocity_range(self) -> tuple:
        return (self._core.velocity_min, self._core.velocity_max)

    @property
    def radius_range(self) -> tuple:
        """The range of the reduced radius R_eff = R1 R2 / (R1 + R2) [m]."""
        return (self._core.radius_min, self._core.radius_max)

    def describe(self) -> dict:
        return self._core.describe()

    def cor(self, radius1, radius2, velocity):
        """eps (0 where the grains stick), broadcasting like a ufunc."""
        r1, r2, v = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (radius1, radius2, velocity)))
        if r1.ndim == 0:
            return self._core.cor(float(r1), float(r2), float(v))
        out = self._core._cor_many(np.ascontiguousarray(r1).ravel(), np.ascontiguousarray(r2).ravel(),
                                   np.ascontiguousarray(v).ravel())
        # NaN: outside the atlas, where the checked lookup raises naming the value and the range;
        # or within round-off of its edge (the batch's vector logarithms are a few ulp off the
        # scalar ones, docs/atlas.md), where the checked lookup's value stands.
        for i in np.flatnonzero(np.isnan(out)):
            out[i] = self._core.cor(float(r1.flat[i]), float(r2.flat[i]), float(v.flat[i]))
        return out.reshape(r1.shape)

    def sticks(self, radius1, radius2, velocity):
        return self._core.sticks(radius1, radius2, velocity)

    def v_stick(self, radius1, radius2):
        """The sticking velocity [m/s]; inf where the grains stick at every speed of the atlas."""
        return self._core.v_stick(radius1, radius2)

    def contact_time(self, radius1, radius2, velocity):
        """[s]; NaN where the grains stick (they stay together)."""
        return self._core.contact_time(radius1, radius2, velocity)

    def bulk_fraction(self, radius1, radius2, velocity):
        """Bulk viscous loss / initial kinetic energy; NaN where the grains stick."""
        return self._core.bulk_fraction(radius1, radius2, velocity)

    def crack_fraction(self, radius1, radius2, velocity):
        """Loss at the crack tip / initial kinetic energy; NaN where the grains stick."""
        return self._core.crack_fraction(radius1, radius2, velocity)

    def p_stick(self, radius1, radius2, sigma_v, distribution: Distribution = "maxwell",
                max_outside: float = 1e-6, nodes: int = 64):
        """The probability that the pair sticks when its relative speed is drawn from
        `distribution` with scale sigma_v [m/s]: "maxwell" (maxwell_cdf), or a callable
        pdf(v, sigma_v), normalised, integrated over [0, v_stick] (Gauss-Legendre with `nodes`
        points on pieces growing geometrically from 1e-3 sigma_v).

        The atlas knows the outcome only inside its speeds (and below them where v_stick is
        above its lowest speed): where more than `max_outside` of the distribution lies
        elsewhere, ValueError names sigma_v and the range."""
        sigma = np.asarray(sigma_v, dtype=float)
        _require_positive("sigma_v", sigma)
        if not (isinstance(max_outside, (int, float)) and 0 <= max_outside < 1):
            raise ValueError(f"max_outside = {max_outside!r} is invalid: expected a fraction 0 <= max_outside < 1")
        if isinstance(nodes, bool) or not isinstance(nodes, int) or not 4 <= nodes <= 1024:
            raise ValueError(f"nodes = {nodes!r} is invalid: expected an integer 4 <= nodes <= 1024")
        vs = np.asarray(self.v_stick(radius1, radius2), dtype=float)
        lo, hi = self.velocity_range
        if isinstance(distribution, str) and distribution == "maxwell":
            cdf = maxwell_cdf
        elif callable(distribution):
            cdf = _cdf_of(distribution, nodes)
        else:
            raise ValueError(f"distribution = {distribution!r} is invalid: expected \"maxwell\" or a "
                             "callable pdf(v, sigma_v)")
        # Above its top speed the atlas has not seen the outcome; below its lowest speed it
        # knows it wherever v_stick is above it (they stick there: one threshold per pair).
        outside = (1.0 - cdf(hi, sigma)) + np.where(vs < lo, cdf(lo, sigma), 0.0)
        if np.any(outside > max_outside):
            worst = np.broadcast_to(sigma, np.shape(outside)).flat[int(np.argmax(outside))]
            raise ValueError(
                f"sigma_v = {float(worst)} is invalid: expected a speed distribution inside the atlas's "
                f"{lo} .. {hi} m/s (a fraction {float(np.max(outside)):.3g} > max_outside = {max_outside} lies "
                "outside; build an atlas over a wider range of speeds)")
        return np.where(np.isinf(vs), 1.0, cdf(np.where(np.isinf(vs), 0.0, vs), sigma))


def _cdf_of(pdf, nodes: int):
    """The CDF of a user pdf(v, sigma): Gauss-Legendre with `nodes` points on each of the pieces
    [0, 1e-3 sigma], then pieces growing by a factor 2 in units of sigma up to v, so that a pdf
    concentrated near sigma is resolved however far v lies beyond it."""
    x, w = np.polynomial.legendre.leggauss(nodes)

    def piece(lo, hi, sigma):
        half = 0.5 * (hi - lo)
        speeds = lo[..., None] + half[..., None] * (x + 1.0)
        values = np.asarray(pdf(speeds, sigma[..., None]), dtype=float)
        if values.shape != speeds.shape or np.any(~np.isfinite(values)) or np.any(values < 0):
            raise ValueError("distribution = (the callable) is invalid: expected a pdf(v, sigma_v) with finite "
                             "values >= 0 that broadcasts over arrays of speeds")
        return np.sum(values * w, axis=-1) * half

    def cdf(v, sigma):
        v, sigma = np.broadcast_arrays(np.asarray(v, dtype=float), np.asarray(sigma, dtype=float))
        total = np.zeros(v.shape)
        lo = np.zeros(v.shape)
        hi = np.minimum(v, 1e-3 * sigma)
        while np.any(hi > lo):
            total += np.where(hi > lo, piece(lo, hi, sigma), 0.0)
            lo, hi = hi, np.minimum(v, np.maximum(2.0 * hi, 1e-3 * sigma))
        if np.any(total > 1.0 + 1e-6):
            raise ValueError(f"distribution = (the callable) is invalid: expected a normalised pdf (its integral up "
                             f"to {float(v.flat[int(np.argmax(total))])} m/s is {float(np.max(total)):.6g} > 1)")
        return total

    return cdf


def open(path: str, model: Optional[str] = None) -> Atlas:  # noqa: A001  (bounce.atlas.open, as the issue names it)
    """Reads an atlas file. With `model`, a file of another model is refused (ValueError), as
    is a file that is not an atlas or was changed after bounce wrote it (its checksum)."""
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path = {path!r} is invalid: expected a file name (str or os.PathLike)")
    return Atlas(_bounce.open_atlas(os.fspath(path), model), os.fspath(path))


def plot_map(atlas: Atlas, wall: bool = False, points: int = 200, ax=None):
    """The atlas as a map: eps over the grain radius and the impact speed (equal grains of the
    atlas's first material, or grains on a wall), sticking collisions in grey, and the v_stick
    line. Returns the Axes (`.figure.savefig(...)` writes it)."""
    import matplotlib.pyplot as plt

    lo, hi = atlas.radius_range
    # R_eff = a / 2 for equal grains, a on a wall: grain radii whose R_eff spans the atlas.
    radii = np.geomspace(lo, hi, points) * (1.0 if wall else 2.0)
    speeds = np.geomspace(*atlas.velocity_range, points)
    r2 = np.inf if wall else radii[None, :]
    cor = atlas.cor(radii[None, :], r2, speeds[:, None])
    v_stick = atlas.v_stick(radii, np.inf if wall else radii)
    if ax is None:
        _, ax = plt.subplots(figsize=(6.4, 4.8))
    shown = np.ma.masked_where(cor <= 0.0, cor)
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad("0.8")
    mesh = ax.pcolormesh(radii, speeds, shown, cmap=cmap, vmin=0.0, vmax=1.0, shading="auto")
    inside = np.isfinite(v_stick) & (v_stick <= atlas.velocity_range[1])
    ax.plot(radii[inside], v_stick[inside], color="white", lw=1.5, label="sticking velocity")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(radii[0], radii[-1])
    ax.set_ylim(speeds[0], speeds[-1])
    ax.set_xlabel("grain radius [m]" + (" (on a wall)" if wall else " (two equal grains)"))
    ax.set_ylabel("impact speed [m/s]")
    ax.set_title(f"{atlas.model}: coefficient of restitution (grey: the grains stick)")
    ax.figure.colorbar(mesh, ax=ax, label="eps")
    ax.legend(loc="upper right")
    return ax

