#!/usr/bin/env bash
# The main job behind `make demo`: writes everything under out/.
set -euo pipefail
build_dir="${1:-build}"
cd "$(dirname "$0")/.."
exec /usr/bin/python3 scripts/demo.py --build-dir "$build_dir" --out out
