#!/usr/bin/python3
"""The bounce demo: the papers' figures (out/figures/) and a report of the key numbers
(out/report.md), with the data behind them as CSV.

The numbers come from the CLI (build/bin/bounce), the figures from the Python package
(build/python, bounce.figures). Default pair for static contact: two water-ice spheres of
radius 1 um (K13 table 2 properties).
"""
import argparse
import json
import pathlib
import subprocess
import sys
import time

PAIR = ["--material", "water-ice", "--radius", "1e-6"]


class Runner:
    def __init__(self, cli: pathlib.Path):
        self.cli = cli
        self.start = time.monotonic()
        self.step = 0

    def progress(self, what: str) -> None:
        self.step += 1
        print(f"[demo {time.monotonic() - self.start:6.1f}s] {what}", flush=True)

    def run(self, *args: str) -> str:
        result = subprocess.run([str(self.cli), *args], capture_output=True, text=True)
        if result.returncode != 0:
            sys.exit(f"bounce {' '.join(args)} failed: {result.stderr.strip()}")
        return result.stdout

    def json(self, *args: str) -> dict:
        return json.loads(self.run(*args, "--json"))


def fmt(x: float, unit: str = "") -> str:
    return f"{x:.4g} {unit}".strip()


def contact_section(runner: Runner) -> list[str]:
    runner.progress("static contact: Hertz, JKR, DMT, Maugis-Dugdale")
    lines = ["## Static contact (two 1 um water-ice spheres)", ""]
    hertz = runner.json("contact", *PAIR, "--law", "hertz", "--force", "1e-6")
    pair = hertz["pair"]
    lines += [
        f"Pair: R_eff = {fmt(pair['effective_radius'], 'm')}, m_eff = {fmt(pair['effective_mass'], 'kg')}, "
        f"E* = {fmt(pair['effective_modulus'], 'Pa')}, gamma = {fmt(pair['surface_energy'], 'J/m^2')}.",
        "",
        f"Hertz at F = 1 uN: contact radius {fmt(hertz['contact_radius'], 'm')}, "
        f"overlap {fmt(hertz['overlap'], 'm')}.",
        "",
        "| law | pull-off force [N] | a at pull-off [m] | a at zero load [m] | overlap at zero load [m] | "
        "separation overlap [m] |",
        "|---|---|---|---|---|---|",
    ]
    tabor = None
    for law in ("jkr", "dmt", "maugis"):
        r = runner.json("contact", *PAIR, "--law", law)
        tabor = r
        lines.append(
            f"| {law} | {fmt(r['pull_off_force'])} | {fmt(r['pull_off_contact_radius'])} | "
            f"{fmt(r['zero_load_contact_radius'])} | {fmt(r['zero_load_overlap'])} | "
            f"{fmt(r['separation_overlap'])} |")
    lines += [
        "",
        f"Tabor parameter (K13 (11), z0 = {tabor['z0']:g} m): mu = {tabor['tabor_parameter']:.3g} "
        f"({tabor['regime_k13']}); BP04 (8.55): {tabor['tabor_parameter_bp04']:.3g} "
        f"({tabor['regime_bp04']}); Maugis lambda = {tabor['maugis_lambda']:.3g}.",
        "",
        "JKR force-overlap curve (both branches): `jkr-force-overlap.csv`.",
        "",
    ]
    return lines


ICE_WALL = ["--material", "ice-bshp96", "--radius", "0.01", "--wall", "--A", "1e-6"]


def viscoelastic_section(runner: Runner, out: pathlib.Path) -> list[str]:
    runner.progress("viscoelastic collisions: master curves and BP04's closed forms")
    lines = ["## Viscoelastic collisions (1 cm ice sphere on an ice wall, BSHP96 §III, A = 1 us)", "",
             "The dissipative constant A is an illustrative value here (BSHP96 fit it to experiment).", "",
             "| g [m/s] | kappa | e (overlap end) | e (force end) | contact time [s] |",
             "|---|---|---|---|---|"]
    for g in ("0.001", "0.01", "0.1", "1", "10"):
        o = runner.json("collide", *ICE_WALL, "--velocity", g)
        f = runner.json("collide", *ICE_WALL, "--velocity", g, "--contact-end", "force")
        lines.append(f"| {g} | {o['kappa']:.4g} | {o['cor']:.6f} | {f['cor']:.6f} | {o['contact_time']:.4g} |")
    a = runner.json("analytic", *ICE_WALL, "--velocity", "1")
    coefficients = a["coefficients"]
    lines += ["", f"Characteristic velocity g* = {a['characteristic_velocity']:.4g} m/s (BP04 (8.88)).", "",
              "Series coefficients of (8.89), e = 1 - a1 q + a2 q^2 - a3 q^3 + a4 q^4:", "",
              "| source | a3 | a4 |", "|---|---|---|"]
    for name, label in (("bp04_simple", "BP04 simple"), ("bp04_rigorous", "BP04 quoted"),
                        ("bounce_overlap", "bounce (master curve fit)")):
        c = coefficients[name]
        unc = [f" +- {u:.1g}" if u else "" for u in c["uncertainty"]]
        lines.append(f"| {label} | {c['a'][2]:.6g}{unc[2]} | {c['a'][3]:.6g}{unc[3]} |")
    runner.progress("viscoelastic COR curve")
    (out / "viscoelastic-curve.csv").write_text(
        runner.run("curve", *ICE_WALL, "--velocities", "1e-4:100:121", "--log"))
    lines += ["", "COR against velocity (overlap end rule): `viscoelastic-curve.csv`.", ""]
    return lines


# K13 §3: water ice, T_vis = 1e-11 s, the sphere radius for which K13 (22) gives t_H = 1.4e-8 s at
# 8 m/s. K13 does not state its z0; 0.088 nm reproduces its e_A = 0.66 (docs/adhesive.md).
K13 = ["--material", "water-ice", "--model", "krijt", "--tvis", "1e-11"]
K13_RADIUS = "2.0353e-6"
K13_Z0 = "0.088e-9"


def number(value, spec: str, none: str) -> str:
    """A record's number as the table prints it; `none` where the record holds null (a sticking
    collision has no contact time; a closed form beyond its validity is null)."""
    return none if value is None else format(value, spec)


def adhesive_section(runner: Runner, out: pathlib.Path) -> list[str]:
    runner.progress("adhesive collisions: K13 section 3")
    k13 = out / "k13"
    k13.mkdir(exist_ok=True)
    lines = ["## Adhesive collisions (K13 §3: water ice, T_vis = 1e-11 s, R = 2.035 um)", "",
             "| z0 [nm] | v [m/s] | outcome | e | t_c [s] | crack loss | bulk loss | e_I (27) |",
             "|---|---|---|---|---|---|---|---|"]
    for z0 in (K13_Z0, "0.2e-9"):
        for v in ("8", "2"):
            r = runner.json("collide", *K13, "--radius", K13_RADIUS, "--z0", z0, "--velocity", v)
            e = r["energy"]
            lines.append(f"| {float(z0) * 1e9:g} | {v} | {r['outcome']} | {r['cor']:.3f} | "
                         f"{number(r['contact_time'], '.3g', 'none (sticks)')} | "
                         f"{e['crack_dissipated'] / e['initial_kinetic']:.0%} | "
                         f"{e['bulk_dissipated'] / e['initial_kinetic']:.0%} | "
                         f"{number(r['closed_forms']['e_i'], '.3f', 'null (beyond its validity)')} |")
    lines += ["", "K13 reports e_A = 0.66, t_c = 1.7e-8 s, 37 % crack and 19 % bulk loss at 8 m/s, and "
              "sticking at 2 m/s (docs/adhesive.md compares and explains).", ""]
    stick = {m: runner.json("sticking", "--material", "water-ice", "--model", m, "--tvis", "1e-11",
                            "--radius", K13_RADIUS)["sticking_velocity"]
             for m in ("krijt", "jkr-viscoelastic", "adhesive-viscoelastic")}
    bp04 = runner.json("sticking", "--material", "water-ice", "--model", "adhesive-viscoelastic", "--tvis", "1e-11",
                       "--radius", K13_RADIUS)
    lines += ["Sticking velocities (z0 = 0.2 nm):", "",
              "| model | v_s [m/s] |", "|---|---|"]
    lines += [f"| {m} | {v:.4g} |" for m, v in stick.items()]
    lines += [f"| elastic JKR, exact (K13 (25): {bp04['sticking_velocity_k13_25']:.4g}) | "
              f"{bp04['sticking_velocity_jkr']:.4g} |",
              f"| BP04 (8.100) with the exact e(g) ((8.101): {bp04['sticking_velocity_bp04_8_101']:.4g}) | "
              f"{bp04['sticking_velocity_bp04_8_100']:.4g} |", ""]

    runner.progress("K13 fig. 2 and 3: a(delta), F_E(delta) with the Hertz and JKR curves")
    (k13 / "fig2-bounce-8ms.csv").write_text(
        runner.run("collide", *K13, "--radius", K13_RADIUS, "--z0", K13_Z0, "--velocity", "8", "--trajectory", "--csv"))
    (k13 / "fig3-stick-2ms.csv").write_text(
        runner.run("collide", *K13, "--radius", K13_RADIUS, "--z0", K13_Z0, "--velocity", "2", "--trajectory", "--csv",
                   "--follow", "2e-7"))
    (k13 / "jkr-curve.csv").write_text(
        runner.run("contact", "--material", "water-ice", "--radius", K13_RADIUS, "--law", "jkr", "--csv",
                   "--contact-radii", "0:2.5e-7:251"))
    (k13 / "hertz-curve.csv").write_text(
        runner.run("contact", "--material", "water-ice", "--radius", K13_RADIUS, "--law", "hertz", "--csv",
                   "--overlaps", "0:6e-8:121"))
    runner.progress("K13 fig. 4: COR against velocity with e_JKR, e_D, e_I")
    (k13 / "fig4-cor-velocity.csv").write_text(
        runner.run("curve", *K13, "--radius", K13_RADIUS, "--z0", K13_Z0, "--velocities", "0.1:100:100", "--log",
                   "--closed-forms"))
    runner.progress("K13 fig. 5 (left): COR against radius at 8 m/s")
    (k13 / "fig5-cor-radius-8ms.csv").write_text(
        runner.run("curve", *K13, "--z0", K13_Z0, "--radii", "2e-7:2e-4:61", "--log", "--velocity", "8",
                   "--closed-forms"))
    runner.progress("K13 fig. 5 (right): sticking velocity against radius for several T_vis")
    for tvis in ("1e-14", "1e-13", "1e-12", "1e-11", "1e-10"):
        (k13 / f"fig5-sticking-velocity-tvis{tvis}.csv").write_text(
            runner.run("sticking", "--material", "water-ice", "--model", "krijt", "--tvis", tvis, "--z0", K13_Z0,
                       "--radii", "2e-7:2e-4:25", "--log"))
    runner.progress("K13 fig. C1 and C2: energies against time")
    lines += ["Data for K13's figures under `k13/`: `fig2-bounce-8ms.csv` and `fig3-stick-2ms.csv` "
              "(trajectories: a, delta, F_E, beta and every energy against time; the second followed for "
              "0.2 us, which also gives fig. C2, and the first fig. C1), `hertz-curve.csv` and `jkr-curve.csv` "
              "(the static curves of figs 2 and 3), `fig4-cor-velocity.csv` (with K13 (24), (26), (27)), "
              "`fig5-cor-radius-8ms.csv` and `fig5-sticking-velocity-tvis*.csv` (all with z0 = 0.088 nm, as the figures).", ""]
    return lines


def figures_section(runner: Runner, build_dir: pathlib.Path, out: pathlib.Path) -> list[str]:
    sys.path.insert(0, str(build_dir / "python"))
    import bounce  # the package of this build
    from bounce import figures, plot

    written = figures.write_figures(out / "figures", progress=runner.progress)
    lines = ["## Figures (`figures/`, PNG and SVG)", "",
             "Regenerated from the library by `python3 -m bounce.figures`; docs/figures.md compares each with the "
             "paper.", "", "| file | figure |", "|---|---|"]
    for name, function in plot.FIGURES.items():
        lines.append(f"| `{name}.png`, `.svg` | {function.__doc__.strip().splitlines()[0]} |")
    ice = bounce.Pair(material=plot.BSHP96_MATERIAL, radius=plot.BSHP96_RADIUS)
    a = plot.dissipative_constant_for(ice, plot.BP04_ICE_CHARACTERISTIC_VELOCITY)
    lines += ["", f"BSHP96 Fig. 1 uses A = {a:.4g} s, the A for which BP04 (8.88) gives g* = 0.32 cm/s for two "
              "1 cm ice spheres (BSHP96 fit A to the same data but do not print it).", ""]
    assert len(written) == 2 * len(plot.FIGURES)
    return lines


def posterior_lines(runner: Runner, bounce, plot, pair, data: pathlib.Path, figures: pathlib.Path) -> list[str]:
    """The posterior of the PSL-on-quartz set with bounce.posterior's defaults and its corner plot."""
    runner.progress("fit: the posterior of the PSL-on-quartz set (emcee, 24 walkers x 1500 steps; minutes)")
    truths = {"gamma": 0.05, "tvis": 3e-12, "yield": 2e8}
    post = bounce.posterior(pair, bounce.Model("krijt"), data=str(data))
    fig = plot.corner(post, truths=truths)
    for suffix in ("png", "svg"):
        fig.savefig(figures / f"posterior-psl-quartz.{suffix}", dpi=150)
    held = [n for n in post["names"] if post["credible_95"][n][0] <= truths[n] <= post["credible_95"][n][1]]
    intervals = ", ".join(f"{n} = {post['median'][n]:.3g} (95 %: {lo:.3g} .. {hi:.3g})"
                          for n, (lo, hi) in post["credible_95"].items())
    return ["", f"* Its posterior (`bounce.posterior`, {post['walkers']} walkers x {post['steps']} steps, "
            f"log-uniform priors over the fit's default grid): {intervals}; the 95 % intervals hold "
            f"{len(held)} of the {len(truths)} true values; warnings: {'; '.join(post['warnings']) or 'none'} "
            "(`figures/posterior-psl-quartz.png`: the corner plot, true values in red)."]


def fit_section(runner: Runner, build_dir: pathlib.Path, out: pathlib.Path) -> list[str]:
    """K13 §4 on the synthetic data sets: one fit with its figures, the model comparison, the
    Bridges law's A and g*, and the batch of every set (K13 Figs 7 and 8)."""
    sys.path.insert(0, str(build_dir / "python"))
    import bounce
    from bounce import plot

    data = pathlib.Path("data/experiments")
    runner.progress("fit: K13's model to synthetic PSL-on-quartz data (60 x 60 x 100 grid) and the comparison")
    psl = ["--material", "psl", "--radius", "0.635e-6", "--wall", "--material2", "quartz"]
    fit = runner.json("fit", "--data", str(data / "synthetic-psl-quartz.csv"), *psl, "--compare")
    pair = bounce.Pair(material="psl", radius=0.635e-6, wall=True, material2="quartz")
    grid = bounce.fit(pair, bounce.Model("krijt"), data=str(data / "synthetic-psl-quartz.csv"))
    figures = out / "figures"
    figures.mkdir(parents=True, exist_ok=True)
    for name, ax in (("fit-psl-quartz", plot.fit_curve(grid)), ("fit-chi2-psl-quartz", plot.chi2_map(grid))):
        for suffix in ("png", "svg"):
            ax.figure.savefig(figures / f"{name}.{suffix}", dpi=150)

    def show(f: dict, key: str) -> str:
        parts = []
        for name in f["fitted"]:
            lo, hi = f[key][name]
            parts.append(f"{name} = {f['best'][name]:.3g} ({'?' if lo is None else f'{lo:.3g}'} .. "
                         f"{'?' if hi is None else f'{hi:.3g}'})")
        return ", ".join(parts)

    lines = ["## Fitting restitution curves (K13 §4; docs/fitting.md)", "",
             "Synthetic data (`data/experiments/`, made by `tools/make_synthetic_data.py` from bounce's own model with "
             "stated parameters and noise; not measurements).", "",
             f"* PSL on quartz (true gamma = 0.05 J/m^2, T_vis = 3e-12 s, Y = 2e8 Pa, sigma = 0.02): "
             f"{show(fit, 'ranges')}; chi^2 (31) = {fit['chi2']:.3g} "
             f"(`figures/fit-psl-quartz.png`, `figures/fit-chi2-psl-quartz.png`).", "",
             "| model | chi^2 (31) | AIC | BIC |", "|---|---|---|---|"]
    for row in fit["comparison"]:
        lines.append(f"| {row['label']} | {row['chi2']:.3g} | {row['aic']:.4g} | {row['bic']:.4g} |")
    lines += posterior_lines(runner, bounce, plot, pair, data / "synthetic-psl-quartz.csv", figures)
    runner.progress("fit: the viscoelastic A of Bridges et al.'s ice law (BSHP96 Fig 1, BP04 Fig 8.2)")
    ice = runner.json("fit", "--data", str(data / "bridges-ice.csv"), "--material", "ice-bshp96", "--radius", "1e-2",
                      "--model", "viscoelastic")
    lines += ["", f"* Bridges et al.'s ice law, 0.05-5 cm/s, two 1 cm ice spheres: {show(ice, 'ranges')} s, "
              f"g* = {ice['characteristic_velocity'] * 100:.3g} cm/s (BP04: 0.32 cm/s from the Pade form and the "
              "measurements; docs/fitting.md says why they differ).", ""]
    runner.progress("fit: the batch of every synthetic set (K13 Figs 7, 8)")
    batch = runner.json("fit", "--batch", str(data / "synthetic.toml"))
    fig = plot.batch_summary(batch)
    for suffix in ("png", "svg"):
        fig.savefig(figures / f"fit-batch.{suffix}", dpi=150)
    lines += ["| experiment | fitted (factor-2 ranges; ? = one-sided) |", "|---|---|"]
    for f in batch["experiments"]:
        lines.append(f"| {f['name']} | {show(f, 'ranges')} |")
    lines += ["", "`figures/fit-batch.png`: gamma/gamma_L, Y/E_soft and T_vis against the reduced radius, as K13 "
              "Figs 7 and 8.", ""]
    return lines


def atlas_section(runner: Runner, build_dir: pathlib.Path, out: pathlib.Path) -> list[str]:
    """A collision atlas of ice grains (docs/atlas.md) and its map: eps over radius and speed."""
    sys.path.insert(0, str(build_dir / "python"))
    import bounce.atlas

    runner.progress("collision atlas of water ice (krijt, ~1 min)")
    path = out / "atlas" / "ice-krijt.h5"
    path.parent.mkdir(parents=True, exist_ok=True)
    runner.run("atlas", "build", "--model", "krijt", "--tvis", "1e-11", "--materials", "water-ice",
               "--radius", "1e-7:1e-3:9", "--velocity", "0.01:100:9", "--tol", "1e-3", "-o", str(path))
    atlas = bounce.atlas.open(str(path), model="krijt")
    figures = out / "figures"
    figures.mkdir(parents=True, exist_ok=True)
    ax = bounce.atlas.plot_map(atlas)
    for suffix in ("png", "svg"):
        ax.figure.savefig(figures / f"atlas-map.{suffix}", dpi=150)
    grid = atlas.describe()["grid"]
    return ["## Collision atlas (`atlas/ice-krijt.h5`, `figures/atlas-map.png`)", "",
            f"K13's model for water ice (T_vis = 1e-11 s) over R_eff 0.1 um - 1 mm and 0.01 - 100 m/s: a grid of "
            f"{grid[0]:.0f} x {grid[1]:.0f} x {grid[2]:.0f} nodes, eps within {atlas.cor_error:.2g} of direct "
            f"collisions and v_stick within {atlas.v_stick_error:.2g} (relative). Two 1 um grains stick below "
            f"{atlas.v_stick(1e-6, 1e-6):.4g} m/s; at 5 m/s eps = {atlas.cor(1e-6, 1e-6, 5.0):.4f}.", ""]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--out", default="out")
    args = parser.parse_args()
    build_dir = pathlib.Path(args.build_dir)
    runner = Runner(build_dir / "bin" / "bounce")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    report = ["# bounce report", ""]
    report += contact_section(runner)
    report += viscoelastic_section(runner, out)
    report += adhesive_section(runner, out)
    runner.progress("JKR force-overlap curve")
    (out / "jkr-force-overlap.csv").write_text(
        runner.run("contact", *PAIR, "--law", "jkr", "--csv", "--contact-radii", "0:1.5e-7:301"))
    report += figures_section(runner, build_dir, out)
    report += fit_section(runner, build_dir, out)
    report += atlas_section(runner, build_dir, out)
    (out / "report.md").write_text("\n".join(report))
    runner.progress(f"wrote {out / 'report.md'}, the figures under {out / 'figures'}/ and the CSV files under {out}/")


if __name__ == "__main__":
    main()
