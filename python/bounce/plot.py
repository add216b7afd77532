"""The papers' figures, regenerated from the library (matplotlib).

Three building blocks (and ``fit_curve``, ``chi2_map`` for :func:`bounce.fit`) draw on axes you give (or on a new figure's): ``cor_curve`` (e
against impact speed), ``contact_history`` (a and F_E against the approach, beside Hertz
and JKR) and ``energy_budget`` (the energies against time). Each figure function computes
its curves with :mod:`bounce` and returns a :class:`matplotlib.figure.Figure` with axes
in named units, a legend and a caption naming the paper's figure. ``quick=True`` uses coarser grids (for tests); the
figures in ``make demo`` use the full ones. ``python3 -m bounce.figures`` writes
them all as PNG and SVG (docs/figures.md says how each compares with the paper).

References: BSHP96 = Brilliantov, Spahn, Hertzsch, Poeschel, PRE 53 (1996);
BP04 = Brilliantov, Poeschel, Kinetic Theory of Granular Gases (2004), ch. 8;
K13 = Krijt, Guettler, Heisselmann, Dominik, Tielens, J. Phys. D 46 (2013).
"""

from __future__ import annotations

import textwrap
from typing import Callable

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from . import _bounce as b
from .fit_plots import batch_summary, chi2_map, fit_curve  # noqa: F401  (K13 Figs 6, 7, 8 and a fit's chi^2)
from .posterior_plots import corner  # noqa: F401  (a posterior's marginals and pairwise densities)

# --- the set-ups of the papers ---------------------------------------------------------

#: BSHP96 §III (the built-in ice-bshp96): ice at low temperature, Y = 10 GPa, nu = 0.3, rho = 1000 kg/m^3.
BSHP96_MATERIAL = "ice-bshp96"
#: BSHP96 §III: particle radius 1 cm.
BSHP96_RADIUS = 1e-2
#: BP04 §8.3.3: the characteristic velocity fitted to Bridges et al.'s ice data [m/s].
BP04_ICE_CHARACTERISTIC_VELOCITY = 0.32e-2
#: Bridges et al. (1984) as quoted by BSHP96 Fig 1 and BP04 Fig 8.2: eps = 0.32 (g / cm s^-1)^-0.234.
BRIDGES_PREFACTOR, BRIDGES_EXPONENT = 0.32, -0.234
#: BSHP96 Fig 2: the three asperity sizes zeta0 / R_eff, with mu = alpha sqrt(zeta0 / R_eff), alpha = 1.
BSHP96_ASPERITY_SIZES = (1e-7, 2e-4, 1e-3)
#: A for BSHP96 Fig 2 [s]: BSHP96 do not print the A of their tangential runs; the value of
#: docs/tangential.md's data tables (and of the test Figure2Regimes).
BSHP96_FIG2_DISSIPATIVE_CONSTANT = 1e-6

#: K13 §3: water ice (table 2), T_vis = 1e-11 s, and the sphere radius for which K13 (22)
#: gives t_H = 1.4e-8 s at 8 m/s (R_eff = 1.018 um). K13 do not state z0; 0.088 nm
#: reproduces their e_A = 0.66 (docs/adhesive.md).
K13_MATERIAL = "water-ice"
K13_RADIUS = 2.0353e-6
K13_TVIS = 1e-11
K13_Z0 = 0.088e-9
#: K13 fig. 5 (right): the relaxation times of the sticking-velocity curves [s].
K13_FIG5_TVIS = (1e-14, 1e-13, 1e-12, 1e-11, 1e-10)


def bridges_law(g: np.ndarray) -> np.ndarray:
    """Bridges et al.'s fit eps(g) = 0.32 (g / cm s^-1)^-0.234, g in m/s (BSHP96 Fig 1)."""
    return BRIDGES_PREFACTOR * (np.asarray(g) / 1e-2) ** BRIDGES_EXPONENT


def dissipative_constant_for(pair: b.Pair, characteristic_velocity: float) -> float:
    """The A [s] for which BP04 (8.88) gives this g* [m/s] for the pair (g* is proportional to A^-5)."""
    if not characteristic_velocity > 0:
        raise ValueError(f"characteristic_velocity = {characteristic_velocity} is invalid: expected g* > 0 m/s")
    reference = 1e-6
    g_ref = b.viscoelastic_scales(pair, b.Model("viscoelastic", A=reference), 1.0)["characteristic_velocity"]
    return reference * (g_ref / characteristic_velocity) ** 0.2


def _figure(width: float = 6.4, height: float = 4.4) -> Figure:
    return Figure(figsize=(width, height), layout="constrained")


def _caption(fig: Figure, text: str) -> None:
    """The caption under the axes, naming the paper's figure."""
    lines = textwrap.wrap(text, width=int(fig.get_figwidth() * 15))
    height = (len(lines) * 11 + 8) / (72 * fig.get_figheight())  # 8 pt text, 11 pt lines, as a figure fraction
    fig.get_layout_engine().set(rect=(0, height, 1, 1 - height))
    fig.text(0.5, 0.01, "\n".join(lines), ha="center", va="bottom", fontsize=8)


def _k13_pair() -> b.Pair:
    return b.Pair(material=K13_MATERIAL, radius=K13_RADIUS)


def _k13_model(tvis: float = K13_TVIS) -> b.Model:
    return b.Model("krijt", tvis=tvis, z0=K13_Z0)


# --- BSHP96 ------------------------------------------------------------------------------

def bshp96_fig1(quick: bool = False) -> Figure:
    """BSHP96 Fig 1: eps^N against g^N for ice, with Bridges et al.'s law (dashed)."""
    pair = b.Pair(material=BSHP96_MATERIAL, radius=BSHP96_RADIUS)
    a = dissipative_constant_for(pair, BP04_ICE_CHARACTERISTIC_VELOCITY)
    model = b.Model("viscoelastic", A=a)
    g = np.geomspace(1e-4, 0.1, 25 if quick else 121)  # m/s
    cor = b.collide(pair, model, g, method="integrate")["cor"]
    fig = _figure()
    ax = fig.add_subplot()
    ax.plot(g * 100, cor, "-", color="C0", label=f"bounce: viscoelastic spheres, (24)-(25), A = {a:.3g} s")
    ax.plot(g * 100, bridges_law(g), "--", color="k", label=r"Bridges et al.: $\epsilon = 0.32\,(g/\mathrm{cm\,s^{-1}})^{-0.234}$")
    ax.set_xscale("log")
    ax.set_ylim(0, 1.05)
    ax.set_xlabel(r"normal impact velocity $g^N$ [cm s$^{-1}$]")
    ax.set_ylabel(r"normal restitution coefficient $\epsilon^N$")
    ax.legend(loc="lower left", fontsize=8)
    _caption(fig, "BSHP96 Fig. 1: two ice spheres, R = 1 cm, Y = 10 GPa, nu = 0.3, rho = 1000 kg/m^3, by direct "
                  f"integration. A is set so that g* = {BP04_ICE_CHARACTERISTIC_VELOCITY * 100:g} cm/s (BP04's fit to the "
                  "same data); BSHP96 fit A but do not print it.")
    return fig


def bshp96_fig2_data(zeta0: float, n: int = 41) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """eps^T on an n x n log grid of g^N, g^T in [1e-3, 10] m/s for asperity size zeta0 R_eff."""
    pair = b.Pair(material=BSHP96_MATERIAL, radius=BSHP96_RADIUS)
    # The published form, as BSHP96 drew it (the default, passive, keeps |eps^T| <= 1: decisions.md D12).
    model = b.Model("viscoelastic", A=BSHP96_FIG2_DISSIPATIVE_CONSTANT, friction=float(np.sqrt(zeta0)),
                    asperity=zeta0 * pair.effective_radius, asperity_form="published")
    g_normal = np.geomspace(1e-3, 10.0, n)
    g_tangential = np.geomspace(1e-3, 10.0, n)
    cor_t = np.empty((n, n))
    for j, gt in enumerate(g_tangential):  # each row: an array of g^N, looped in C++
        cor_t[j] = b.collide(pair, model, g_normal, tangential_velocity=float(gt))["cor_tangential"]
    return g_normal, g_tangential, cor_t


def bshp96_fig2(quick: bool = False) -> Figure:
    """BSHP96 Fig 2: eps^T over the g^N-g^T plane for zeta0 = 1e-7, 2e-4, 1e-3 R_eff."""
    fig = _figure(14.0, 5.4)
    for i, zeta0 in enumerate(BSHP96_ASPERITY_SIZES):
        g_n, g_t, cor_t = bshp96_fig2_data(zeta0, 13 if quick else 41)
        ax = fig.add_subplot(1, 3, i + 1, projection="3d")
        x, y = np.meshgrid(np.log10(g_n), np.log10(g_t))
        ax.plot_surface(x, y, cor_t, cmap="viridis", vmin=-1, vmax=1, rstride=1, cstride=1, linewidth=0.1,
                        edgecolor="k", antialiased=True)
        ax.set_xlabel(r"$\log_{10}\,g^N$ [m/s]")
        ax.set_ylabel(r"$\log_{10}\,g^T$ [m/s]")
        ax.set_zlabel(r"$\epsilon^T$")
        ax.set_zlim(-1.2, 1.1)
        ax.set_xticks([-3, -2, -1, 0, 1])
        ax.set_yticks([-3, -2, -1, 0, 1])
        ax.view_init(elev=28, azim=-55)
        ax.set_box_aspect(None, zoom=0.88)
        ax.set_title(f"({'abc'[i]}) " + rf"$\zeta_0 = {_latex_number(zeta0)}\,R^{{eff}}$, $\mu = {np.sqrt(zeta0):.3g}$",
                     fontsize=10)
    _caption(fig, "BSHP96 Fig. 2: tangential restitution coefficient over the plane of normal and tangential impact "
                  "velocities, ice spheres R = 1 cm, A = 1 us, asperity law (35)-(37) in the published form, "
                  "mu = sqrt(zeta0/R_eff) (alpha = 1). Sliding (eps^T near 1) at small g^N and large g^T; spin "
                  "reversal (eps^T < 0) at small g^T; the sharp edge is g^T_cr.")
    return fig


def _latex_number(x: float) -> str:
    mantissa, exponent = f"{x:.0e}".split("e")
    exponent = int(exponent)
    return rf"10^{{{exponent}}}" if mantissa == "1" else rf"{mantissa} \cdot 10^{{{exponent}}}"


# --- BP04 --------------------------------------------------------------------------------

def bp04_fig8_2(quick: bool = False) -> Figure:
    """BP04 Fig 8.2: the Pade approximation (8.92)-(8.93) against Bridges et al.'s law, g* = 0.32 cm/s."""
    g = np.geomspace(1e-4, 0.1, 40 if quick else 300)  # m/s
    q = (g / BP04_ICE_CHARACTERISTIC_VELOCITY) ** 0.2
    fig = _figure()
    ax = fig.add_subplot()
    ax.plot(g * 100, b.cor_pade(q, "bp04-printed"), "-", color="C3", label="Padé (8.92), $d_k$ of (8.93) as printed")
    # The exact curve for comparison: kappa = q / (2b) (BP04 (8.87)); 2b from any viscoelastic pair.
    scales = b.viscoelastic_scales(b.Pair(material=BSHP96_MATERIAL, radius=BSHP96_RADIUS),
                                   b.Model("viscoelastic", A=1e-6), 1.0)
    two_b = scales["q"] / scales["kappa"]
    ax.plot(g * 100, b.master_cor(q / two_b), ":", color="C0", lw=1.2, label="exact (bounce master curve)")
    ax.plot(g * 100, bridges_law(g), "--", color="k", label=r"experiment (Bridges et al.): $0.32\,g^{-0.234}$")
    ax.set_xscale("log")
    ax.set_ylim(0, 1.05)
    ax.set_xlabel(r"impact velocity $g$ [cm s$^{-1}$]")
    ax.set_ylabel(r"coefficient of normal restitution $\varepsilon$")
    ax.legend(loc="lower left", fontsize=8)
    _caption(fig, "BP04 Fig. 8.2: ice particles, Padé approximation (8.92) with the constants (8.93) and g* = 0.32 "
                  "cm/s (solid), the experimental fit (dashed); dotted: the exact viscoelastic curve.")
    return fig


# --- K13 -----------------------------------------------------------------------------------

def contact_history(pair: b.Pair, model: b.Model, velocity: float, axes: tuple[Axes, Axes] | None = None,
                    follow_time: float = 0.0, points: int = 2000) -> tuple[Axes, Axes]:
    """a(delta) and F_E(delta) of one collision beside the static Hertz (and, with adhesion, JKR) curves.

    Draws on ``axes`` (left, right), or on a new figure's; returns them. With a surface
    energy: the JKR curve (both branches), its equilibrium (star) and the snap-on at
    delta = 0 (dotted), as in K13 Figs 2 and 3. Units: delta in nm, a in um, F_E in uN.
    """
    run = b.collide(pair, model, velocity, trajectory=True, trajectory_points=points, follow_time=follow_time)
    t = run["trajectory"]
    if axes is None:
        fig = _figure(11.0, 4.4)
        axes = (fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2))
    left, right = axes
    nm, um, uN = 1e9, 1e6, 1e6
    a_max = 1.15 * float(np.max(t["contact_radius"]))
    delta_max = 1.1 * float(np.max(t["overlap"]))
    hertz = b.ContactLaw(pair, "hertz").at_overlap(np.linspace(0.0, delta_max, 200))
    label = f"bounce, {velocity:g} m/s"
    left.plot(t["overlap"] * nm, t["contact_radius"] * um, "-", color="C3", lw=1.2, label=label)
    right.plot(t["overlap"] * nm, t["elastic_force"] * uN, "-", color="C3", lw=1.2, label=label)
    left.plot(hertz["overlap"] * nm, hertz["contact_radius"] * um, "--", color="C0", label="Hertz (4)")
    right.plot(hertz["overlap"] * nm, hertz["force"] * uN, "--", color="C0", label="Hertz (5)")
    if pair.surface_energy is not None:
        law = b.ContactLaw(pair, "jkr")
        jkr = law.at_contact_radius(np.linspace(0.0, a_max, 400))
        equilibrium = law.adhesion
        snap = law.at_overlap(0.0)  # where the stable JKR branch meets delta = 0 (snap-on)
        left.plot(jkr["overlap"] * nm, jkr["contact_radius"] * um, "-.", color="k", label="JKR (8)")
        right.plot(jkr["overlap"] * nm, jkr["force"] * uN, "-.", color="k", label="JKR (9)")
        left.plot([0, 0], [0, snap["contact_radius"] * um], ":", color="k", lw=1)
        right.plot([0, 0], [0, snap["force"] * uN], ":", color="k", lw=1)
        left.plot(equilibrium["zero_load_overlap"] * nm, equilibrium["zero_load_contact_radius"] * um, "*", ms=12,
                  color="C1", label="JKR equilibrium")
        right.plot(equilibrium["zero_load_overlap"] * nm, 0.0, "*", ms=12, color="C1", label="JKR equilibrium")
    right.axhline(0, color="0.6", lw=0.5)
    for ax in axes:
        ax.set_xlabel(r"mutual approach $\delta$ [nm]")
        ax.set_xlim(right=delta_max * nm)
    left.set_ylabel(r"contact radius $a$ [$\mu$m]")
    left.set_ylim(0, a_max * um)
    right.set_ylabel(r"elastic force $F_E$ [$\mu$N]")
    right.set_ylim(top=1.1 * float(np.max(t["elastic_force"])) * uN)
    left.legend(fontsize=8, loc="lower right")
    right.legend(fontsize=8, loc="upper left")
    return axes


def _k13_contact_figure(velocity: float, follow_time: float, quick: bool, caption: str) -> Figure:
    left, _ = contact_history(_k13_pair(), _k13_model(), velocity, follow_time=follow_time,
                              points=200 if quick else 2000)
    _caption(left.figure, caption)
    return left.figure


def k13_fig2(quick: bool = False) -> Figure:
    """K13 Fig 2: a(delta) and F_E(delta) for an 8 m/s bouncing collision of ice grains, T_vis = 1e-11 s."""
    return _k13_contact_figure(8.0, 0.0, quick,
                               "K13 Fig. 2: contact radius (left) and elastic force (right) against mutual approach, "
                               "8 m/s bouncing collision, water ice (table 2), R_eff = 1.02 um, T_vis = 1e-11 s, "
                               "z0 = 0.088 nm. Star: JKR equilibrium; dotted: JKR snap-on at delta = 0.")


def k13_fig3(quick: bool = False) -> Figure:
    """K13 Fig 3: as Fig 2 for a 2 m/s sticking collision, followed for 0.2 us."""
    return _k13_contact_figure(2.0, 2e-7, quick,
                               "K13 Fig. 3: as Fig. 2 for a 2 m/s sticking collision, followed for 0.2 us: the "
                               "grains spiral towards the JKR equilibrium (star).")


def cor_curve(pair: b.Pair, model: b.Model, velocities: np.ndarray, ax: Axes | None = None,
              label: str | None = None, **style: object) -> Axes:
    """The coefficient of restitution against impact speed [m/s] (0 where the grains stick), log x axis.

    Draws on ``ax`` or a new figure's axes; returns it. ``style`` goes to ``Axes.plot``.
    """
    v = np.asarray(velocities, dtype=float)
    run = b.collide(pair, model, v)
    if ax is None:
        ax = _figure().add_subplot()
    ax.plot(v, run["cor"], label=label if label is not None else model.name, **style)
    ax.set_xscale("log")
    ax.set_ylim(0, 1.02)
    ax.set_xlabel(r"impact velocity $v_{in}$ [m s$^{-1}$]")
    ax.set_ylabel("coefficient of restitution")
    return ax


def k13_fig4(quick: bool = False) -> Figure:
    """K13 Fig 4: e_A against impact velocity with e_JKR (24), e_D (26), e_I (27)."""
    pair, model = _k13_pair(), _k13_model()
    v = np.geomspace(0.1, 100.0, 25 if quick else 120)
    ax = cor_curve(pair, model, v, label="bounce (K13 model)", color="C3", lw=1.6)
    closed = b.closed_forms(pair, model, v)
    v_s = b.sticking_velocity(pair, model)
    ax.plot(v, closed["e_jkr"], "--", color="k", label=r"$e_{JKR}$ (24)")
    ax.plot(v, closed["e_d"], ":", color="C0", label=r"$e_D$ (26)")
    ax.plot(v, closed["e_i"], "-.", color="C2", label=r"$e_I$ (27)")
    ax.axvline(v_s, color="0.5", lw=0.6)
    ax.annotate(f"$v_s$ = {v_s:.2f} m/s", (v_s, 0.05), xytext=(4, 0), textcoords="offset points", fontsize=8)
    ax.legend(loc="lower right", fontsize=8)
    _caption(ax.figure, "K13 Fig. 4: COR of head-on collisions against impact velocity (solid red), water ice, "
                        "T_vis = 1e-11 s, R_eff = 1.02 um, z0 = 0.088 nm, with the estimates (24), (26), (27).")
    return ax.figure


def k13_fig5(quick: bool = False) -> Figure:
    """K13 Fig 5: COR against reduced radius at 8 m/s (left); sticking velocity against radius (right)."""
    velocity = 8.0
    r_eff = np.geomspace(1e-7, 1e-4, 12 if quick else 50)
    cor, e_i = np.empty_like(r_eff), np.empty_like(r_eff)
    model = _k13_model()
    for i, r in enumerate(r_eff):  # one pair per radius (the loop over speeds would run in C++)
        pair = b.Pair(material=K13_MATERIAL, radius=2 * r)
        cor[i] = b.collide(pair, model, velocity)["cor"]
        closed = b.closed_forms(pair, model, velocity)["e_i"]
        e_i[i] = np.nan if closed is None else closed  # None beyond (26)'s validity
    fig = _figure(11.0, 4.4)
    left, right = fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2)
    left.plot(r_eff * 1e6, cor, "-", color="C3", lw=1.6, label="bounce (K13 model)")
    left.plot(r_eff * 1e6, e_i, "-.", color="C2", label=r"$e_I$ (27)")
    left.set_xscale("log")
    left.set_ylim(0, 1.02)
    left.set_xlabel(r"reduced radius $R$ [$\mu$m]")
    left.set_ylabel(f"coefficient of restitution at {velocity:g} m/s")
    left.legend(loc="lower right", fontsize=8)
    r_stick = np.geomspace(1e-7, 1e-4, 6 if quick else 25)
    for k, tvis in enumerate(K13_FIG5_TVIS):
        if quick and k % 2:
            continue
        v_s = [_sticking_or_nan(b.Pair(material=K13_MATERIAL, radius=2 * r), _k13_model(tvis)) for r in r_stick]
        right.plot(r_stick * 1e6, v_s, "-", color=f"C{k}", label=rf"$T_{{vis}} = 10^{{{int(np.log10(tvis))}}}$ s")
    v_c = [b.closed_forms(b.Pair(material=K13_MATERIAL, radius=2 * r), model, 1.0)["sticking_velocity_k13_25"]
           for r in r_stick]
    right.plot(r_stick * 1e6, v_c, "--", color="k", label="non-viscous (25)")
    right.set_xscale("log")
    right.set_yscale("log")
    right.set_xlabel(r"reduced radius $R$ [$\mu$m]")
    right.set_ylabel(r"sticking velocity $v_s$ [m s$^{-1}$]")
    right.legend(loc="upper right", fontsize=8)
    _caption(fig, "K13 Fig. 5: left, COR at 8 m/s against reduced radius (T_vis = 1e-11 s) with (27); right, "
                  "sticking velocity against reduced radius for five T_vis, with the non-viscous (25). Water ice, "
                  "z0 = 0.088 nm. Where a curve stops, the grains stick at every speed up to the transversal sound "
                  "speed (the quasi-static limit).")
    return fig


def _sticking_or_nan(pair: b.Pair, model: b.Model) -> float:
    """The sticking velocity, or NaN (not plotted) where the grains stick at every quasi-static speed."""
    try:
        v = b.sticking_velocity(pair, model, 1e-4)
    except RuntimeError:  # no threshold found (a numerical failure of the search)
        return float("nan")
    return float("nan") if v is None else v


def energy_budget(pair: b.Pair, model: b.Model, velocity: float, ax: Axes | None = None, follow_time: float = 0.0,
                  points: int = 2000) -> Axes:
    """U_K, U_E, U_S, U_CD, U_BD against time [ns], normalised to the initial kinetic energy (K13 appendix C).

    Draws on ``ax`` or a new figure's axes; returns it.
    """
    run = b.collide(pair, model, velocity, trajectory=True, trajectory_points=points, follow_time=follow_time)
    t = run["trajectory"]
    u0 = run["energy"]["initial_kinetic"]
    if ax is None:
        ax = _figure().add_subplot()
    ns = t["time"] * 1e9
    for key, label, style in (("kinetic", "$U_K$", "-"), ("elastic", "$U_E$", "--"), ("surface", "$U_S$", "-."),
                              ("crack_dissipated", "$U_{CD}$", ":"), ("bulk_dissipated", "$U_{BD}$", "-")):
        ax.plot(ns, t[key] / u0, style, lw=1.3 if key != "bulk_dissipated" else 0.9, label=label)
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("time [ns]")
    ax.set_ylabel("energy / initial kinetic energy [-]")
    ax.legend(fontsize=8)
    return ax


def _k13_energy_figure(velocity: float, follow_time: float, quick: bool, caption: str,
                       legend: dict[str, object]) -> Figure:
    ax = energy_budget(_k13_pair(), _k13_model(), velocity, follow_time=follow_time, points=200 if quick else 2000)
    ax.legend(fontsize=8, **legend)
    _caption(ax.figure, caption)
    return ax.figure


def k13_figC1(quick: bool = False) -> Figure:
    """K13 Fig C1: the energies against time for the 8 m/s bouncing collision."""
    return _k13_energy_figure(8.0, 0.0, quick,
                              "K13 Fig. C1: kinetic, elastic and surface energy and the energy dissipated at the "
                              "crack and in the bulk, normalised to the initial kinetic energy, 8 m/s bouncing "
                              "collision, water ice, T_vis = 1e-11 s, z0 = 0.088 nm.",
                              {"ncols": 5, "loc": "upper center"})


def k13_figC2(quick: bool = False) -> Figure:
    """K13 Fig C2: the energies against time for the 2 m/s sticking collision."""
    return _k13_energy_figure(2.0, 2e-7, quick,
                              "K13 Fig. C2: as Fig. C1 for the 2 m/s sticking collision (followed for 0.2 us): "
                              "most of the energy is dissipated at the crack, some stays elastic.",
                              {"loc": "center right", "bbox_to_anchor": (1.0, 0.68)})


#: The figure set of docs/figures.md, by file name.
FIGURES: dict[str, Callable[..., Figure]] = {
    "bshp96-fig1": bshp96_fig1,
    "bshp96-fig2": bshp96_fig2,
    "bp04-fig8-2": bp04_fig8_2,
    "k13-fig2": k13_fig2,
    "k13-fig3": k13_fig3,
    "k13-fig4": k13_fig4,
    "k13-fig5": k13_fig5,
    "k13-figC1": k13_figC1,
    "k13-figC2": k13_figC2,
}
