#!/usr/bin/env bash
# `make lint`, and the test `lint_sizes` of `make test`: functions over 60 lines (clang-tidy
# readability-function-size, on the build's compile_commands.json) and files over 400 lines in
# src/, apps/, python/src and lammps/. LAMMPS's sources are checked for functions where the build
# compiled them (`make lammps`), for size always. Data tables and generated code are not in
# these folders' sources. Exit 1 when any is found, 2 when clang-tidy or the build is missing.
set -euo pipefail
build_dir="${1:-build}"
cd "$(dirname "$0")/.."
if ! command -v clang-tidy >/dev/null; then
  echo "check_sizes: clang-tidy not found (Debian package clang-tidy; make test and make lint install it)" >&2
  exit 2
fi
if [ ! -f "$build_dir/compile_commands.json" ]; then
  echo "check_sizes: $build_dir/compile_commands.json not found (configure the build first: make)" >&2
  exit 2
fi
config='{Checks: "-*,readability-function-size", CheckOptions: [{key: readability-function-size.LineThreshold, value: 60}]}'
sources=(src/*/*.cpp apps/bounce/*.cpp python/src/*.cpp)
for f in lammps/*.cpp; do
  if grep -q "\"file\": \"$PWD/$f\"" "$build_dir/compile_commands.json"; then sources+=("$f"); fi
done
status=0
# One clang-tidy per file, as many at once as there are cores (each parses Boost and friends).
long=$(printf '%s\n' "${sources[@]}" |
  xargs -P "$(nproc 2>/dev/null || echo 2)" -I{} sh -c 'clang-tidy -p "$0" --config="$1" \
      --header-filter="/(src|apps|python/src|lammps)/" --extra-arg=-Wno-unknown-warning-option --quiet "$2" 2>/dev/null |
    grep -E "warning: function .* exceeds" || true' "$build_dir" "$config" {} | sort -u)
if [ -n "$long" ]; then echo "$long"; status=1; fi
for f in $(ls src/*/*.{cpp,hpp,h} apps/bounce/*.{cpp,hpp} python/src/*.{cpp,hpp} lammps/*.{cpp,h} 2>/dev/null); do
  lines=$(wc -l < "$f")
  if [ "$lines" -gt 400 ]; then echo "$f: $lines lines (over 400)"; status=1; fi
done
[ $status -eq 0 ] && echo "sizes: no function over 60 lines, no file over 400 lines (${#sources[@]} sources)"
exit $status
