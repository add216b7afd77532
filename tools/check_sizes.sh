#!/usr/bin/env bash
# Opt-in (`make lint`): functions over 60 lines (clang-tidy readability-function-size, on the
# build's compile_commands.json) and files over 400 lines in src/, apps/ and python/src.
# Data tables and generated code are not in these folders' sources. Exit 1 when any is found.
set -euo pipefail
build_dir="${1:-build}"
cd "$(dirname "$0")/.."
config='{Checks: "-*,readability-function-size", CheckOptions: [{key: readability-function-size.LineThreshold, value: 60}]}'
status=0
long=$(for f in src/*/*.cpp apps/bounce/*.cpp python/src/*.cpp; do
  clang-tidy -p "$build_dir" --config="$config" --header-filter='/(src|apps|python/src)/' \
    --extra-arg=-Wno-unknown-warning-option --quiet "$f" 2>/dev/null | grep -E "warning: function .* exceeds" || true
done | sort -u)
if [ -n "$long" ]; then echo "$long"; status=1; fi
for f in $(ls src/*/*.{cpp,hpp,h} apps/bounce/*.{cpp,hpp} python/src/*.{cpp,hpp} 2>/dev/null); do
  lines=$(wc -l < "$f")
  if [ "$lines" -gt 400 ]; then echo "$f: $lines lines (over 400)"; status=1; fi
done
[ $status -eq 0 ] && echo "sizes: no function over 60 lines, no file over 400 lines"
exit $status
