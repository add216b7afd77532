#!/usr/bin/env bash
# Run every benchmark: the C++ ones, then the side-by-side comparisons with Python references.
set -euo pipefail
build_dir="${1:-build}"
cd "$(dirname "$0")/.."
for b in "$build_dir"/bin/bench_*; do
  case "$(basename "$b")" in bench_viscoelastic_exact) continue ;; esac
  echo "== $(basename "$b")"
  "$b" --benchmark_min_time=0.2
done
echo "== viscoelastic collision against scipy"
/usr/bin/python3 bench/viscoelastic_vs_scipy.py "$build_dir"
echo "== K13 collisions against scipy, and the two stiff engines"
/usr/bin/python3 bench/adhesive_vs_scipy.py "$build_dir"
echo "== the collision atlas from Python against bounce.collide"
PYTHONPATH="$build_dir/python" /usr/bin/python3 bench/atlas_python.py "$build_dir"
echo "== bounce fit: K13's 60 x 60 x 100 grid, whole process, 1 and 2 threads"
/usr/bin/python3 bench/fit_speed.py "$build_dir"
if [ -x "$build_dir/lammps/lmp" ] && [ -f "$build_dir/lammps/bounceplugin.so" ]; then
  echo "== pair_style bounce against LAMMPS's pair granular, and 1 -> 2 ranks"
  /usr/bin/python3 bench/lammps_speed.py "$build_dir"
else
  echo "== (no LAMMPS build: make lammps for the LAMMPS benchmark)"
fi
if [ -f out/explorer/index.html ] && [ -x /usr/bin/chromium ]; then
  echo "== the browser explorer: first render and a 100-velocity curve, beside the native CLI"
  node tests/explorer/browser_test.js --page out/explorer --bounce "$build_dir/bin/bounce" | tail -1
else
  echo "== (no explorer or no chromium: make explorer and make deps-browser for the browser benchmark)"
fi
