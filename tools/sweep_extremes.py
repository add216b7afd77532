#!/usr/bin/python3
"""Extreme but accepted inputs of every model, through the CLI (issue 40 point 5).

Each case is a base collision (1 um water ice at 1 m/s, or a model's own base) with one
parameter set to an end of its declared range or a value far outside the physics (nu near 0,
T_vis of seconds). What the contract asks of each: exit 0, or exit 2 naming an input; exit 3
only where the integration genuinely fails, never a solver's own words for an input that
should have been refused; no nan/inf on stdout; no run over LIMIT seconds. The table it prints
(exit, seconds, the first line of stderr) is what docs/hardening.md records.

    tools/sweep_extremes.py BOUNCE [--limit S] [--only REGEX]   exit 1 if a case breaks the contract
"""
import argparse
import re
import subprocess
import sys
import time

ICE = ["--material", "water-ice", "--radius", "1e-6"]

# model -> its base options (beyond ICE and --velocity)
MODELS = {
    "hertz": [],
    "viscoelastic": ["--tvis", "1e-11"],
    "viscoelastic-shifted": ["--tvis", "1e-11"],
    "power-law": ["--power-d1", "1e10", "--power-d2", "1e3"],
    "adhesive-viscoelastic": ["--tvis", "1e-11"],
    "jkr-viscoelastic": ["--tvis", "1e-11"],
    "krijt": ["--tvis", "1e-11"],
    "maugis-viscoelastic": ["--tvis", "1e-11"],
}

# (option, values, models it applies to: None for every model)
VISCOUS = ["viscoelastic", "viscoelastic-shifted", "adhesive-viscoelastic", "jkr-viscoelastic", "krijt",
           "maugis-viscoelastic"]
EXTREMES = [
    ("--nu", ["0", "1e-300", "1e-6", "-1e-6", "0.4999999", "-0.9999999"], None),
    ("--tvis", ["1e-300", "1e-30", "1e-20", "1e-6", "1", "1e10", "1e300"], VISCOUS),
    ("--A", ["0", "1e-300", "1e-30", "1e-6", "1", "1e10", "1e300"], VISCOUS),
    ("--B", ["0", "1e-300", "1", "1e300"], ["adhesive-viscoelastic"]),
    ("--z0", ["1e-15", "1e-12", "1e-6"], ["adhesive-viscoelastic", "jkr-viscoelastic", "maugis-viscoelastic"]),
    ("--z0", ["1e-12", "1e-6"], ["krijt"]),
    ("--k", ["1e-10", "0.5"], ["krijt"]),
    ("--E", ["1e-300", "1", "1e30", "1e300"], None),
    ("--density", ["1e-300", "1e-3", "1e30", "1e300"], None),
    ("--gamma", ["0", "1e-300", "1e3"], None),
    ("--radius", ["1e-300", "1e-12", "1e3", "1e300"], None),
    ("--velocity", ["1e-300", "1e-12", "1e-6", "1000"], None),
    ("--yield", ["1e-300", "1", "1e300"], None),
    ("--power-alpha", ["1e-6", "0.01", "10", "1e3"], ["power-law"]),
    ("--power-beta", ["1e-6", "10"], ["power-law"]),
    ("--power-gamma", ["0", "10"], ["power-law"]),
    ("--power-d1", ["1e-300", "1e300"], ["power-law"]),
    ("--power-d2", ["0", "1e300"], ["power-law"]),
    ("--follow", ["1e-12", "1e-4", "1e3", "1e300"], ["adhesive-viscoelastic", "jkr-viscoelastic", "krijt",
                                                      "maugis-viscoelastic"]),
]
# A few combinations the single-parameter cases do not reach.
COMBINED = [
    ["--model", "krijt", "--tvis", "1e-6", "--nu", "1e-3"],
    ["--model", "jkr-viscoelastic", "--tvis", "1e-11", "--follow", "1e3", "--trajectory", "--csv"],
    ["--model", "jkr-viscoelastic", "--A", "0", "--follow", "1e3"],
    ["--model", "maugis-viscoelastic", "--A", "0", "--follow", "1e3"],
    ["--model", "krijt", "--tvis", "1e-11", "--follow", "1e3", "--trajectory", "--csv"],
    ["--model", "viscoelastic", "--tvis", "1e-11", "--nu", "0", "--A", "1e-9"],
    ["--model", "adhesive-viscoelastic", "--A", "0", "--velocity", "1e-5"],
]


def without(options, name):
    """`options` (name, value pairs) without `name` and its value."""
    pairs = zip(options[::2], options[1::2])
    return [x for n, v in pairs if n != name for x in (n, v)]


def cases(only):
    for model, base in MODELS.items():
        for option, values, models in EXTREMES:
            if models is not None and model not in models:
                continue
            for value in values:
                # A replaces T_vis, except for krijt, whose crack law needs T_vis too
                drop = option == "--A" and model != "krijt"
                args = ["--model", model] + ([] if drop else without(base, option))
                args += [option, value]
                if option != "--velocity":
                    args += ["--velocity", "1"]
                if re.search(only, " ".join(args)):
                    yield args
    for args in COMBINED:
        args = args + ([] if "--velocity" in args else ["--velocity", "1"])
        if re.search(only, " ".join(args)):
            yield args


NON_FINITE = re.compile(r"(?<![\w.])-?(nan|inf)(?![\w])")


def run(bounce, args, limit):
    command = [bounce, "collide"] + ICE + args
    if "--radius" in args:  # the case's radius replaces the base's
        command = [bounce, "collide", "--material", "water-ice"] + args
    start = time.monotonic()
    try:
        p = subprocess.run(command, capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        return None, limit, "", "(over the time limit)"
    seconds = time.monotonic() - start
    lines = [l for l in p.stderr.splitlines() if not l.startswith(("bounce: warning", "bounce: note"))]
    return p.returncode, seconds, p.stdout, lines[0] if lines else ""


def verdict(code, stdout, message):
    if code is None:
        return "HANGS"
    if code not in (0, 2, 3):
        return "CRASH"
    if code == 0 and NON_FINITE.search(stdout):
        return "NONFINITE"
    if code == 3 and re.search(r"RODAS|CVODE|state became non-finite|outside the range of double|kappa is", message):
        return "SOLVER"  # an input reached a solver that cannot take it
    return "ok"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bounce")
    parser.add_argument("--limit", type=float, default=20.0, help="seconds a case may take")
    parser.add_argument("--only", default="", help="run only the cases whose options match")
    a = parser.parse_args()
    bad = 0
    for args in cases(a.only):
        code, seconds, stdout, message = run(a.bounce, args, a.limit)
        v = verdict(code, stdout, message)
        bad += v != "ok"
        print(f"{v:9} exit {code!s:4} {seconds:6.2f} s  {' '.join(args)}  | {message[:160]}", flush=True)
    print(f"{bad} cases break the contract")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
