#!/usr/bin/python3
"""Smoluchowski coagulation of water-ice grains with the collision atlas as its sticking kernel.

    PYTHONPATH=build/python /usr/bin/python3 examples/coagulation/smoluchowski.py \\
        --atlas ice.h5 --out out/coagulation [--sigma-v 3.0] [--steps 5] [--t-end 100] [--kmax 180]
    ... --constant-kernel 1e-12 --out out/constant     # the check against the closed form

An atlas for it (R_eff 1 .. 10 um, 0.3 .. 20 m/s; about 6 s):

    build/bin/bounce atlas build --model krijt --tvis 1e-11 --materials water-ice \\
        --radius 1e-6:1e-5:4 --velocity 0.3:20:5 --tol 1e-3 -o ice.h5

The equations
-------------
Monomers of radius a0 (--a0, default 2 um) of the atlas's material (water ice, 1000 kg/m^3 in the
atlas above) start alone at number density N0. A k-mer is a compact sphere of k monomer masses,
radius a_k = a0 k^(1/3). Its number density n_k (k = 1 .. kmax) obeys the discrete Smoluchowski
equation

    dn_k/dt = 1/2 sum_{i+j=k} K_ij n_i n_j - n_k sum_{j=1}^{kmax} K_kj n_j,

with the kernel (the rate coefficient of collisions that stick)

    K_ij = pi (a_i + a_j)^2 <dv> P_ij,    <dv> = sigma_v sqrt(8/pi),

for relative speeds v with the Maxwell pdf f(v) = sqrt(2/pi) v^2/sigma_v^3 exp(-v^2/(2 sigma_v^2))
(--sigma-v, its mean <dv>). A pair sticks when v < v_stick(a_i, a_j) (the atlas's one threshold
per pair), so the rate of sticking collisions is pi (a_i + a_j)^2 int_0^v_stick v f(v) dv, i.e.

    P_ij = atlas.p_stick(a_i, a_j, sigma_v, distribution=g),  g(v) = v f(v) / <dv>
         = v^3 / (2 sigma_v^4) exp(-v^2 / (2 sigma_v^2)),   P_ij = 1 - (1 + x^2/2) exp(-x^2/2),

x = v_stick / sigma_v: the fraction of *collisions* that stick, slow pairs colliding less often.
`--distribution maxwell` uses the atlas's default instead, P_ij = P(v < v_stick) under f (the
fraction of *pairs* slower than v_stick): larger, by 2.1 sigma_v / v_stick when v_stick << sigma_v.
The (kmax, kmax) P_ij is one vectorised atlas call.

The atlas knows a pair's outcome only for R_eff = a_i a_j / (a_i + a_j) inside its radii and
v_stick at or above its lowest speed (below, p_stick would need speeds it has not seen): the
script refuses a kmax (or a0) with any pair outside, naming the largest kmax that fits. With the
atlas above and a0 = 2 um that is kmax = 189 (the default is 180: aggregates up to 11.3 um; the
largest like pair has R_eff = 5.6 um and v_stick = 0.31 m/s). sigma_v must keep all but 1e-6 of
the collisions below the atlas's top speed, 20 m/s: sigma_v < 3.46 m/s (3.61 with maxwell).

Beyond kmax (mass conservation)
-------------------------------
A collision of i + j > kmax makes a grain the grid does not hold: both partners leave the grid
(the loss term runs over all j <= kmax) and their mass goes to a tracked reservoir,

    dM_out/dt = 1/2 sum_{i, j <= kmax, i+j > kmax} (i + j) K_ij n_i n_j     [monomer masses],

which does not collide further (a sink). With K symmetric (the script symmetrises it: (K + K^T)/2,
a no-op for the atlas, which is symmetric by construction) the right-hand sides of
M = sum_k k n_k + M_out sum to zero term by term, so M is conserved in exact arithmetic; the
integrator below keeps it to round-off (relative 1e-15 .. 1e-14, checked: |M/M0 - 1| < 1e-12).
The grid solution equals the untruncated one while M_out is negligible (the reservoir's grains
would still sweep up small ones): the JSON reports M_out / M0, and the defaults keep it small.

Time and the integrator
-----------------------
n -> lambda n, t -> t / lambda leaves the equation unchanged, so the state is y_k = n_k / N0 as a
function of tau = K_ref N0 t, with K_ref = K_11 (the atlas kernel's monomer pair) or the constant
kernel: N0 is not a parameter, and t = tau / (K_ref N0) for any N0 (K_ref is in the JSON).
scipy's solve_ivp integrates to --t-end (tau; default 100, 10 with --constant-kernel) with DOP853,
rtol = 1e-10, atol = 1e-20 (units of N0). It is an explicit Runge-Kutta method: every step and
its dense output are y plus linear combinations of right-hand sides, each of which conserves M,
so M is conserved to round-off whatever the tolerance. --steps N is the number of output times
(log-spaced from t_end/1000 to t_end; the integrator chooses its own steps).

The constant-kernel check (--constant-kernel K, pure sticking: K_ij = K)
------------------------------------------------------------------------
From a monodisperse start n_k(0) = N0 delta_k1, the closed form (Smoluchowski 1916) is

    n_k(t) = N0 T^(k-1) / (1 + T)^(k+1) = N0 (T / (1 + T))^(k-1) / (1 + T)^2,  T = K N0 t / 2 = tau / 2.

Derivation check: summing the equation over k (i, j unbounded) gives dN/dt = -K N^2 / 2, so
N = N0 / (1 + T), and sum_k n_k = N0 / (1 + T) as it must; sum_k k n_k = N0 (mass). Inserting
n_k: d n_k / dT = N0 T^(k-2) (1+T)^(-k-2) [(k-1) - 2T], and (2 / (K N0)) times the right-hand
side, (1/N0) sum_{i+j=k} n_i n_j - 2 n_k N / N0, is the same, since sum_{i+j=k} T^(i-1) T^(j-1)
= (k-1) T^(k-2). The script reports the largest relative deviation of n_k from it over the output
times and the bins with n_k >= 1e-8 N0 (below, atol and round-off dominate), and the largest
deviation of the mass fraction k n_k / N0 over all bins.

What it shows
-------------
out/smoluchowski.png and .svg: the mass distribution k^2 n_k / N0 (the mass fraction per unit
ln k) at the output times, with the closed form dashed in the constant-kernel mode; beside it the
atlas's sticking probability P_ij over the grid (or the deviation from the closed form). With the
atlas above at sigma_v = 3 m/s two monomers (v_stick = 1.84 m/s) stick in 1.6 % of their
collisions, the largest like pair (180 + 180) in 1.3e-5, while a monomer on any aggregate keeps
1 - 2 % (R_eff stays near a0). Early on (tau ~ 1) the aggregates grow mainly by sweeping up
monomers; once those are used up, by collisions of comparable sizes, whose P_ij falls with size.
out/smoluchowski.json: the settings, the relative mass error, the mass that left the grid, the
mass-weighted mean size sum k^2 n_k / sum k n_k, and in the constant-kernel mode the deviations
from the closed form.

Bad input (a non-positive --sigma-v, a --steps that is not a positive integer, a missing atlas,
a kmax outside the atlas, ...) prints one line "smoluchowski: error: NAME = VALUE is invalid:
expected ..." to stderr and exits 2, as the bounce CLI does.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import math
import os
import pathlib
import sys
import time
from typing import Optional

import numpy as np

PROG = "smoluchowski"
RTOL, ATOL = 1e-10, 1e-20  # solve_ivp's tolerances (atol in units of N0)
DEVIATION_FLOOR = 1e-8     # the closed-form relative deviation is measured where n_k >= this * N0
MASS_TOLERANCE = 1e-12     # |M / M0 - 1| above it: the run is reported as failed (exit 1)


class InputError(ValueError):
    """A bad argument: its message is the one line "NAME = VALUE is invalid: expected ..."."""


# --------------------------------------------------------------------------------------------
# Kernels


def radii(a0: float, kmax: int) -> np.ndarray:
    """a_k = a0 k^(1/3), k = 1 .. kmax [m]: compact aggregates of one material."""
    return a0 * np.cbrt(np.arange(1, kmax + 1, dtype=float))


def mean_speed(sigma_v: float) -> float:
    """<dv> of the Maxwell speed pdf of scale sigma_v [m/s]."""
    return sigma_v * math.sqrt(8.0 / math.pi)


def collision_pdf(v, sigma_v):
    """g(v) = v f(v) / <dv>: the speeds of the pairs that collide (f: the Maxwell pdf)."""
    v = np.asarray(v, dtype=float)
    s = np.asarray(sigma_v, dtype=float)
    return v ** 3 / (2.0 * s ** 4) * np.exp(-0.5 * (v / s) ** 2)


def collision_cdf(v, sigma_v):
    """The closed form of int_0^v g: 1 - (1 + x^2/2) exp(-x^2/2), x = v / sigma_v."""
    x = np.asarray(v, dtype=float) / np.asarray(sigma_v, dtype=float)
    return -np.expm1(-0.5 * x * x) - 0.5 * x * x * np.exp(-0.5 * x * x)


def geometric_kernel(a0: float, kmax: int, sigma_v: float) -> np.ndarray:
    """pi (a_i + a_j)^2 <dv> [m^3/s]: every collision sticks."""
    a = radii(a0, kmax)
    return math.pi * (a[:, None] + a[None, :]) ** 2 * mean_speed(sigma_v)


def check_grid(atlas, a0: float, kmax: int) -> None:
    """Refuses a grid with a pair the atlas cannot answer for (InputError naming the kmax that fits)."""
    a = radii(a0, kmax)
    r_lo, r_hi = atlas.radius_range
    r_eff = a[:, None] * a[None, :] / (a[:, None] + a[None, :])
    if not r_lo <= r_eff[0, 0] <= r_hi:
        raise InputError(f"--a0 = {a0!r} is invalid: expected a monomer radius {2 * r_lo!r} .. {2 * r_hi!r} m, "
                         f"so that R_eff = a0/2 of a monomer pair is inside the atlas's {r_lo!r} .. {r_hi!r} m")
    bad = r_eff > r_hi
    what = f"R_eff inside the atlas's {r_lo!r} .. {r_hi!r} m"
    if not bad.any():
        vs = np.asarray(atlas.v_stick(a[:, None], a[None, :]), dtype=float)
        bad = vs < atlas.velocity_range[0]
        what = f"v_stick at or above the atlas's lowest speed {atlas.velocity_range[0]!r} m/s"
    if bad.any():
        i, j = np.nonzero(bad)
        fits = int(np.min(np.maximum(i, j)))  # the largest kmax without an offending pair
        worst = np.argmin(np.maximum(i, j))
        raise InputError(f"--kmax = {kmax} is invalid: expected kmax <= {fits} for this atlas and a0 = {a0!r} m "
                         f"(every pair needs {what}; pair {i[worst] + 1} + {j[worst] + 1} has not)")


def atlas_kernel(atlas, a0: float, kmax: int, sigma_v: float, distribution: str = "collision"):
    """(K [m^3/s], P): the sticking kernel pi (a_i + a_j)^2 <dv> P_ij and P_ij from the atlas,
    both (kmax, kmax). One p_stick call on the flattened pairs (a 1-d call: the atlas's message
    for a distribution outside it is built from a flat index)."""
    check_grid(atlas, a0, kmax)
    a = radii(a0, kmax)
    ai, aj = np.meshgrid(a, a, indexing="ij")
    pdf = collision_pdf if distribution == "collision" else "maxwell"
    p = np.asarray(atlas.p_stick(ai.ravel(), aj.ravel(), sigma_v, distribution=pdf), dtype=float).reshape(kmax, kmax)
    p = np.clip(0.5 * (p + p.T), 0.0, 1.0)  # symmetric (it is) and a probability (Gauss-Legendre round-off)
    return geometric_kernel(a0, kmax, sigma_v) * p, p


def closed_form(kmax: int, tau) -> np.ndarray:
    """n_k / N0 of the constant kernel from monomers, k = 1 .. kmax, at tau = K N0 t (shape (len(tau), kmax))."""
    T = 0.5 * np.atleast_1d(np.asarray(tau, dtype=float))[:, None]
    k = np.arange(1, kmax + 1, dtype=float)[None, :]
    # (T/(1+T))^(k-1) / (1+T)^2 through logs: no 0 * inf at T = 0 (then n_k = delta_k1).
    with np.errstate(divide="ignore", invalid="ignore"):
        log = (k - 1.0) * (np.log(T) - np.log1p(T)) - 2.0 * np.log1p(T)
    out = np.exp(np.where(k == 1.0, -2.0 * np.log1p(T), log))
    return out


# --------------------------------------------------------------------------------------------
# The equation


class Smoluchowski:
    """The right-hand side for y = (n_1 .. n_kmax, M_out) / N0 in tau = K_ref N0 t, with the
    dimensionless kernel k_ij = K_ij / K_ref."""

    def __init__(self, kernel: np.ndarray, k_ref: float):
        kernel = np.asarray(kernel, dtype=float)
        if kernel.ndim != 2 or kernel.shape[0] != kernel.shape[1]:
            raise ValueError(f"kernel = (shape {kernel.shape}) is invalid: expected a square matrix")
        self.kmax = kernel.shape[0]
        self.k = 0.5 * (kernel + kernel.T) / k_ref
        idx = np.arange(1, self.kmax + 1)
        self.sums = (idx[:, None] + idx[None, :]).ravel()        # i + j of each pair
        self.out_masses = np.arange(self.kmax + 1, 2 * self.kmax + 1, dtype=float)

    def __call__(self, tau, y):
        n = y[:-1]
        rates = self.k * np.outer(n, n)                              # k_ij n_i n_j
        made = 0.5 * np.bincount(self.sums, weights=rates.ravel(), minlength=2 * self.kmax + 1)
        dy = np.empty_like(y)
        dy[:-1] = made[1:self.kmax + 1] - n * (self.k @ n)
        dy[-1] = np.dot(self.out_masses, made[self.kmax + 1:])       # mass leaving the grid
        return dy

    def mass(self, y) -> float:
        """sum_k k n_k + M_out [N0 monomer masses], summed exactly (math.fsum)."""
        return math.fsum(np.arange(1, self.kmax + 1) * y[:-1]) + float(y[-1])


def integrate(system: Smoluchowski, times) -> dict:
    from scipy.integrate import solve_ivp

    y0 = np.zeros(system.kmax + 1)
    y0[0] = 1.0
    times = np.asarray(times, dtype=float)
    sol = solve_ivp(system, (0.0, float(times[-1])), y0, method="DOP853", rtol=RTOL, atol=ATOL, t_eval=times)
    if sol.status != 0:
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    y = sol.y.T                                               # (len(times), kmax + 1)
    masses = [system.mass(row) for row in y]
    return dict(tau=sol.t, n=y[:, :-1], out=y[:, -1], mass_error=max(abs(m - 1.0) for m in masses),
                nfev=int(sol.nfev))


def output_times(t_end: float, steps: int) -> np.ndarray:
    return np.array([t_end]) if steps == 1 else t_end * np.geomspace(1e-3, 1.0, steps)


# --------------------------------------------------------------------------------------------
# The run


@dataclasses.dataclass
class Settings:
    out: pathlib.Path
    atlas: Optional[str] = None
    constant_kernel: Optional[float] = None
    sigma_v: float = 3.0
    steps: int = 5
    t_end: Optional[float] = None
    kmax: int = 180
    a0: float = 2e-6
    distribution: str = "collision"

    @property
    def tau_end(self) -> float:
        if self.t_end is not None:
            return self.t_end
        return 10.0 if self.constant_kernel is not None else 100.0


def run(s: Settings, progress=lambda text: None) -> dict:
    """Solves, writes out/smoluchowski.{png,svg,json}; returns the JSON's contents."""
    start = time.monotonic()
    describe = None
    if s.constant_kernel is not None:
        kernel = np.full((s.kmax, s.kmax), s.constant_kernel)
        p = None
        k_ref = s.constant_kernel
    else:
        import bounce.atlas

        if not os.path.isfile(s.atlas):
            raise InputError(f"--atlas = {s.atlas} is invalid: expected an atlas file of `bounce atlas build` "
                             "(no such file)")
        atlas = bounce.atlas.open(s.atlas)
        describe = atlas.describe()
        b1, b2 = describe["body1"], describe["body2"]
        if b1 != b2:
            raise InputError(f"--atlas = {s.atlas} is invalid: expected an atlas of grains of one material "
                             f"(it has {b1.get('name')} and {b2.get('name')})")
        try:
            kernel, p = atlas_kernel(atlas, s.a0, s.kmax, s.sigma_v, s.distribution)
        except InputError:
            raise
        except ValueError as e:  # the atlas's p_stick names its parameter sigma_v: name the option
            text = str(e)
            if text.startswith("sigma_v = "):
                text = "--sigma-v = " + text[len("sigma_v = "):]
            raise InputError(text) from None
        k_ref = float(kernel[0, 0])
        if not k_ref > 0:
            raise InputError(f"--sigma-v = {s.sigma_v!r} is invalid: expected a speed scale at which monomers "
                             "can stick (the monomer kernel is 0)")
    progress(f"kernel {s.kmax} x {s.kmax} ({'constant' if p is None else 'atlas'}), "
             f"{time.monotonic() - start:.2f} s")
    system = Smoluchowski(kernel, k_ref)
    sol = integrate(system, output_times(s.tau_end, s.steps))
    progress(f"integrated to tau = {s.tau_end:g} ({sol['nfev']} right-hand sides), {time.monotonic() - start:.2f} s")

    sizes = np.arange(1, s.kmax + 1, dtype=float)
    result = dict(
        mode="constant" if p is None else "atlas",
        atlas=None if p is None else s.atlas,
        model=None if describe is None else describe["model"],
        material=None if describe is None else describe["body1"],
        sigma_v=None if p is None else s.sigma_v,
        distribution=None if p is None else s.distribution,
        a0=s.a0, kmax=s.kmax,
        k_ref=k_ref,
        time_unit="tau = K_ref N0 t (t = tau / (K_ref N0) [s] for N0 [m^-3])",
        tau=[float(t) for t in sol["tau"]],
        relative_mass_error=float(sol["mass_error"]),
        mass_fraction_left_grid=float(sol["out"][-1]),  # of M0, at t_end
        mass_weighted_mean_k=[float(np.dot(sizes * sizes, n) / np.dot(sizes, n)) for n in sol["n"]],
        rtol=RTOL, atol=ATOL, right_hand_sides=sol["nfev"],
    )
    exact = None
    if p is None:
        exact = closed_form(s.kmax, sol["tau"])
        held = exact >= DEVIATION_FLOOR
        rel = np.abs(sol["n"] - exact)[held] / exact[held]
        result["closed_form_max_relative_deviation"] = float(rel.max())
        result["closed_form_deviation_floor"] = DEVIATION_FLOOR
        result["closed_form_max_mass_fraction_deviation"] = float(
            np.max(sizes * np.abs(sol["n"] - exact)))
    else:
        result["p_stick_range"] = [float(p.min()), float(p.max())]
        result["p_stick_monomers"] = float(p[0, 0])

    s.out.mkdir(parents=True, exist_ok=True)
    fig = figure(s, sol, p, exact)
    fig.savefig(s.out / "smoluchowski.png", dpi=120)
    fig.savefig(s.out / "smoluchowski.svg")
    (s.out / "smoluchowski.json").write_text(json.dumps(result, indent=1) + "\n")
    progress(f"wrote {s.out}/smoluchowski.png, .svg, .json, {time.monotonic() - start:.2f} s")
    return result


def figure(s: Settings, sol: dict, p, exact):
    from matplotlib.figure import Figure
    from matplotlib import colors

    k = np.arange(1, s.kmax + 1)
    fig = Figure(figsize=(11, 4.4), layout="constrained")
    left, right = fig.subplots(1, 2)
    shown = np.unique(np.linspace(0, len(sol["tau"]) - 1, min(len(sol["tau"]), 6)).round().astype(int))
    palette = [f"C{i}" for i in range(10)]
    for c, i in enumerate(shown):
        y = k * k * sol["n"][i]
        keep = y > 1e-12
        left.loglog(k[keep], y[keep], "-", color=palette[c], label=f"tau = {sol['tau'][i]:.3g}")
        if exact is not None:
            left.loglog(k, k * k * exact[i], "k--", lw=0.8, label="closed form" if c == 0 else None)
            held = exact[i] >= DEVIATION_FLOOR
            right.semilogy(k[held], np.maximum(np.abs(sol["n"][i] - exact[i])[held] / exact[i][held], 1e-18),
                           color=palette[c], label=f"tau = {sol['tau'][i]:.3g}")
    top = max(float(np.max(k * k * sol["n"][shown])), 0.0 if exact is None else float(np.max(k * k * exact[shown])))
    left.set_ylim(1e-8, 3.0 * top)  # (the closed form's far tail would stretch autoscale over 300 decades)
    left.set_xlabel("k (monomers per aggregate)")
    left.set_ylabel("k² n_k / N0 (mass fraction per ln k)")
    left.legend(fontsize=8)
    if exact is not None:
        left.set_title(f"constant kernel (T = tau/2), kmax = {s.kmax}")
        right.set_xlabel("k")
        right.set_ylabel(f"|n_k − closed form| / closed form (n_k ≥ {DEVIATION_FLOOR:g} N0)")
        right.set_title(f"DOP853, rtol = {RTOL:g}")
        right.legend(fontsize=8)
    else:
        a = radii(s.a0, s.kmax)
        left.set_title(f"atlas kernel, sigma_v = {s.sigma_v:g} m/s, a0 = {s.a0 * 1e6:g} µm")
        image = right.pcolormesh(k, k, p, norm=colors.LogNorm(vmin=max(p.min(), 1e-12), vmax=p.max()),
                                 shading="nearest")
        right.set_xscale("log")
        right.set_yscale("log")
        right.set_xlabel("j")
        right.set_ylabel("i")
        right.set_title(f"P_ij ({s.distribution}-weighted), a_kmax = {a[-1] * 1e6:.2g} µm")
        fig.colorbar(image, ax=right, label="sticking probability")
    return fig


# --------------------------------------------------------------------------------------------
# Arguments


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2 (argparse's own would print the usage too)
        if message.startswith("unrecognized arguments: "):
            word = message.split(": ", 1)[1].split()[0]
            raise InputError(f"{word} = (given) is invalid: expected an option of {PROG} (see --help)")
        if message.startswith("argument ") and "expected one argument" in message:
            flag = message.split()[1].rstrip(":").split("/")[0]
            raise InputError(f"{flag} = (missing) is invalid: expected a value after {flag}")
        raise InputError(f"arguments = ({message}) is invalid: expected the options of --help")


def _number(flag: str, text: Optional[str], default, convert, ok, expected: str):
    if text is None:
        return default
    try:
        value = convert(text)
    except ValueError:
        raise InputError(f"{flag} = {text} is invalid: expected {expected}") from None
    if not ok(value):
        raise InputError(f"{flag} = {text} is invalid: expected {expected}")
    return value


def parse(argv=None) -> Settings:
    parser = _Parser(prog=PROG, description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                     allow_abbrev=False)
    parser.add_argument("--atlas", help="an atlas file of `bounce atlas build` (one material)")
    parser.add_argument("--constant-kernel", metavar="K", help="a constant kernel K [m^3/s] instead of the atlas")
    parser.add_argument("--out", help="output directory")
    parser.add_argument("--sigma-v", metavar="V", help="Maxwell scale of the relative speeds [m/s] (default 3)")
    parser.add_argument("--steps", metavar="N",
                        help="number of output times, log-spaced to --t-end (default 5; the integrator's own "
                        "steps are adaptive)")
    parser.add_argument("--t-end", metavar="TAU",
                        help="end time tau = K_ref N0 t (default 100; 10 with --constant-kernel)")
    parser.add_argument("--kmax", metavar="K", help="largest aggregate on the grid [monomers] (default 180)")
    parser.add_argument("--a0", metavar="A", help="monomer radius [m] (default 2e-6)")
    parser.add_argument("--distribution", help="collision (default) or maxwell: see the docstring")
    a = parser.parse_args(argv)

    positive = lambda x: math.isfinite(x) and x > 0  # noqa: E731
    settings = Settings(
        out=pathlib.Path(a.out) if a.out is not None else pathlib.Path(),
        atlas=a.atlas,
        constant_kernel=_number("--constant-kernel", a.constant_kernel, None, float, positive,
                                "a kernel K > 0 [m^3/s]"),
        sigma_v=_number("--sigma-v", a.sigma_v, 3.0, float, positive, "a speed scale > 0 [m/s]"),
        steps=_number("--steps", a.steps, 5, int, lambda n: 1 <= n <= 1000,
                      "an integer number of output times, 1 .. 1000"),
        t_end=_number("--t-end", a.t_end, None, float, positive, "a time tau = K_ref N0 t > 0"),
        kmax=_number("--kmax", a.kmax, 180, int, lambda n: 2 <= n <= 2000, "an integer 2 .. 2000"),
        a0=_number("--a0", a.a0, 2e-6, float, positive, "a radius > 0 [m]"),
        distribution=a.distribution or "collision",
    )
    if settings.distribution not in ("collision", "maxwell"):
        raise InputError(f"--distribution = {a.distribution} is invalid: expected collision or maxwell")
    if a.out is None:
        raise InputError("--out = (missing) is invalid: expected an output directory (--out DIR)")
    if settings.out.exists() and not settings.out.is_dir():
        raise InputError(f"--out = {a.out} is invalid: expected a directory (it is a file)")
    if settings.constant_kernel is None and a.atlas is None:
        raise InputError("--atlas = (missing) is invalid: expected an atlas file (--atlas FILE.h5) or "
                         "--constant-kernel K")
    if settings.constant_kernel is not None and a.atlas is not None:
        raise InputError(f"--atlas = {a.atlas} is invalid: expected no --atlas with --constant-kernel")
    if a.atlas is not None and not os.path.isfile(a.atlas):
        raise InputError(f"--atlas = {a.atlas} is invalid: expected an atlas file of `bounce atlas build` "
                         "(no such file)")
    return settings


def main(argv=None) -> int:
    import matplotlib

    matplotlib.use("Agg")
    try:
        settings = parse(argv)
        result = run(settings, progress=lambda text: print(f"[{PROG}] {text}", flush=True))
    except ValueError as e:  # InputError, and the atlas's own (a sigma_v outside its speeds, a bad file)
        text = str(e).splitlines()[0] if str(e) else repr(e)
        print(f"{PROG}: error: {text}", file=sys.stderr)
        return 2
    print(f"[{PROG}] relative mass error {result['relative_mass_error']:.3g}, "
          f"mass left the grid {result['mass_fraction_left_grid']:.3g}"
          + (f", closed form: max relative deviation {result['closed_form_max_relative_deviation']:.3g}"
             if "closed_form_max_relative_deviation" in result else ""))
    if result["mass_fraction_left_grid"] > 1e-3:
        print(f"[{PROG}] note: {result['mass_fraction_left_grid']:.3g} of the mass left the grid: the grid solution "
              "is not the untruncated one there (a larger --kmax or a smaller --t-end)")
    if result["relative_mass_error"] > MASS_TOLERANCE:
        print(f"{PROG}: error: mass not conserved: {result['relative_mass_error']:.3g} > {MASS_TOLERANCE:g}",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
