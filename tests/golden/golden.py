#!/usr/bin/python3
"""Recorded outputs of fixed CLI calls (tests/golden/calls.txt): the behaviour a change must keep.

    golden.py --record BUILD_DIR           rewrite expected/ from the CLI in BUILD_DIR
    golden.py --check BUILD_DIR            compare: text exactly, numbers to --tolerance (default 0: exact)
    golden.py --check BUILD_DIR --tolerance 1e-9

Each expected/NAME.out holds the exit code, stdout and stderr of one call. With a tolerance,
the outputs are split into numbers and the text between them: the text must match exactly,
floating-point numbers to that relative tolerance, and integers (counts of steps or breaks)
to 1 % or 2, whichever is larger.
"""
import argparse
import difflib
import os
import re
import shlex
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
NUMBER = re.compile(r"-?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


def calls():
    """(name, argv, stdin file or None) for every call of calls.txt."""
    out = []
    with open(os.path.join(HERE, "calls.txt")) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            parts = [p.strip() for p in line.split("|")]
            name, args = parts[0], shlex.split(parts[1])
            stdin = os.path.join(HERE, parts[2]) if len(parts) > 2 else None
            out.append((name, args, stdin))
    return out


def run(build_dir, args, stdin):
    cli = os.path.join(build_dir, "bin", "bounce")
    with open(stdin) if stdin else open(os.devnull) as inp:
        r = subprocess.run([cli, *args], stdin=inp, capture_output=True, text=True, cwd=HERE)
    return f"exit: {r.returncode}\n--- stdout\n{r.stdout}--- stderr\n{r.stderr}"


def expected_path(name):
    return os.path.join(HERE, "expected", name + ".out")


def numbers_agree(a, b, tolerance):
    if a == b:
        return True
    integers = re.fullmatch(r"-?\d+", a) and re.fullmatch(r"-?\d+", b)
    x, y = float(a), float(b)
    if integers:
        return abs(x - y) <= max(2.0, 0.01 * max(abs(x), abs(y)))
    return abs(x - y) <= tolerance * max(abs(x), abs(y))


def difference(got, want, tolerance):
    """None when `got` matches `want`, else a short description."""
    if tolerance == 0.0:
        if got == want:
            return None
        return "".join(difflib.unified_diff(want.splitlines(True), got.splitlines(True), "expected", "got", n=1))[:3000]
    got_text, want_text = NUMBER.split(got), NUMBER.split(want)
    if got_text != want_text:
        return "".join(difflib.unified_diff(want.splitlines(True), got.splitlines(True), "expected", "got", n=1))[:3000]
    for g, w in zip(NUMBER.findall(got), NUMBER.findall(want)):
        if not numbers_agree(g, w, tolerance):
            return f"number {g} differs from the recorded {w} beyond {tolerance:g}"
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--record", metavar="BUILD_DIR")
    mode.add_argument("--check", metavar="BUILD_DIR")
    parser.add_argument("--tolerance", type=float, default=0.0)
    parser.add_argument("--only", help="a regular expression on the call names")
    o = parser.parse_args()
    build_dir = os.path.abspath(o.record or o.check)
    os.makedirs(os.path.join(HERE, "expected"), exist_ok=True)
    failures = 0
    for name, args, stdin in calls():
        if o.only and not re.search(o.only, name):
            continue
        got = run(build_dir, args, stdin)
        if o.record:
            with open(expected_path(name), "w") as f:
                f.write(got)
            continue
        with open(expected_path(name)) as f:
            want = f.read()
        d = difference(got, want, o.tolerance)
        if d:
            failures += 1
            print(f"== {name}: {d}")
    if o.check:
        print(f"{failures} of the calls differ" if failures else "every call as recorded")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
