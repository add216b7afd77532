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
    runner.progress("JKR force-overlap curve")
    (out / "jkr-force-overlap.csv").write_text(
        runner.run("contact", *PAIR, "--law", "jkr", "--csv", "--contact-radii", "0:1.5e-7:301"))
    (out / "report.md").write_text("\n".join(report))
    runner.progress(f"wrote {out / 'report.md'} and {out / 'jkr-force-overlap.csv'}")


if __name__ == "__main__":
    main()
