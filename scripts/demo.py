#!/usr/bin/python3
"""The bounce demo: runs the CLI for a default pair and writes a report under out/.

Default pair: two water-ice spheres of radius 1 um (K13 table 2 properties).
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


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--out", default="out")
    args = parser.parse_args()
    runner = Runner(pathlib.Path(args.build_dir) / "bin" / "bounce")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    report = ["# bounce report", ""]
    report += contact_section(runner)
    report += viscoelastic_section(runner, out)
    runner.progress("JKR force-overlap curve")
    (out / "jkr-force-overlap.csv").write_text(
        runner.run("contact", *PAIR, "--law", "jkr", "--csv", "--contact-radii", "0:1.5e-7:301"))
    (out / "report.md").write_text("\n".join(report))
    runner.progress(f"wrote {out / 'report.md'} and the CSV files under {out}/")


if __name__ == "__main__":
    main()
