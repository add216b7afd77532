#!/usr/bin/env bash
# Run every benchmark (C++ and the Python/scipy references where present).
set -euo pipefail
build_dir="${1:-build}"
cd "$(dirname "$0")/.."
for b in "$build_dir"/bin/bench_*; do
  echo "== $(basename "$b")"
  "$b" --benchmark_min_time=0.2
done
