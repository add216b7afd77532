#!/usr/bin/python3
"""Side-by-side comparison of the C++ benchmarks of two builds (a change against its base).

    tools/bench_compare.py BASE_BUILD NEW_BUILD [--rounds 3] [--min-time 0.2]

Runs every bench/ binary present in both builds, alternating base and new for --rounds
rounds (so drifts of the machine hit both alike), keeps each benchmark's fastest CPU
time per build, and prints a Markdown table of new/base ratios with their geometric
mean. The minimum over rounds is the estimate least disturbed by other load; a ratio
inside [0.85, 1.15] is within the noise of this 2-core machine (repeated runs of one
build spread that much; docs/benchmarks.md).
"""
import argparse
import json
import math
import pathlib
import subprocess
import sys


def run(binary: pathlib.Path, min_time: float) -> dict[str, float]:
    out = subprocess.run([str(binary), f"--benchmark_min_time={min_time}", "--benchmark_format=json"],
                         check=True, capture_output=True, text=True).stdout
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
    return {b["name"]: b["cpu_time"] * scale[b["time_unit"]]
            for b in json.loads(out)["benchmarks"] if b.get("run_type", "iteration") == "iteration"}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", type=pathlib.Path)
    parser.add_argument("new", type=pathlib.Path)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--min-time", type=float, default=0.2)
    parser.add_argument("--skip", default="bench_viscoelastic_exact", help="binaries left out (comma-separated)")
    parser.add_argument("--only", default="", help="only these binaries (comma-separated)")
    args = parser.parse_args()
    skip = set(args.skip.split(","))
    names = sorted(p.name for p in (args.new / "bin").glob("bench_*")
                   if (args.base / "bin" / p.name).exists() and p.name not in skip
                   and (not args.only or p.name in args.only.split(",")))
    best: dict[tuple[str, str, str], float] = {}
    for round_ in range(args.rounds):
        for name in names:
            for label, build in (("base", args.base), ("new", args.new)):
                print(f"round {round_ + 1}/{args.rounds}: {label} {name}", file=sys.stderr)
                for bench, t in run(build / "bin" / name, args.min_time).items():
                    key = (name, bench, label)
                    best[key] = min(best.get(key, math.inf), t)
    print("| binary | benchmark | base | new | new/base |\n|---|---|---|---|---|")
    ratios = []
    for (name, bench, label), base in sorted(best.items()):
        if label != "base" or (name, bench, "new") not in best:
            continue
        new = best[(name, bench, "new")]
        ratios.append(new / base)
        print(f"| {name} | {bench} | {base:.3g} s | {new:.3g} s | {new / base:.2f} |")
    geomean = math.exp(sum(map(math.log, ratios)) / len(ratios))
    print(f"\n{len(ratios)} benchmarks; new/base geometric mean {geomean:.3f}, "
          f"range {min(ratios):.2f} to {max(ratios):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
