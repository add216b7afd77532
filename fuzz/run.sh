#!/usr/bin/env bash
# Runs fuzz targets of the sanitizer build for a while each (docs/hardening.md).
#   fuzz/run.sh [--seconds N] [--keep-going] [--fresh] BUILD_DIR TARGET...
# Each target starts from its seeds (fuzz/corpus/TARGET, only read) and the inputs it found
# before (BUILD_DIR/fuzz/TARGET/corpus, where new ones go). With --fresh (the CTest runs) it
# starts from the seeds alone, so that a short run costs the same after long `make fuzz` runs
# (its new inputs go to BUILD_DIR/fuzz/TARGET/fresh, emptied each time). Without --keep-going the
# reproducers of fuzz/findings/TARGET run first, and the first finding stops the run with
# status 1. --keep-going (`make fuzz`) goes on after a finding (libFuzzer's -fork=1 and
# -ignore_crashes), to collect them all. Reproducers land in BUILD_DIR/fuzz/TARGET/artifacts,
# the log in BUILD_DIR/fuzz/TARGET/log (fresh-artifacts and fresh-log with --fresh).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
seconds=600
keep_going=0
fresh=0
while [ $# -gt 0 ]; do
  case $1 in
    --seconds) seconds=$2; shift 2 ;;
    --keep-going) keep_going=1; shift ;;
    --fresh) fresh=1; shift ;;
    *) break ;;
  esac
done
if [ $# -lt 2 ]; then
  echo "usage: $0 [--seconds N] [--keep-going] [--fresh] BUILD_DIR TARGET..." >&2
  exit 2
fi
build=$(cd "$1" && pwd)
shift

status=0
for target in "$@"; do
  work=$build/fuzz/$target
  artifacts=$work/artifacts
  log=$work/log
  if [ "$fresh" = 1 ]; then
    artifacts=$work/fresh-artifacts
    log=$work/fresh-log
  fi
  mkdir -p "$work/corpus" "$artifacts"
  # The sanitizers and the coverage slow bounce about tenfold: an input that runs longer than
  # 60 s here is a timeout, a hang if it also takes more than 10 s in the normal build. Slower
  # units below that are not findings, so libFuzzer's slow-unit reports (by default at 10 s,
  # written as artifacts) start at the timeout too: a collision that ends on the integrator's
  # step budget takes 0.4-0.8 s in the normal build and, sanitized on a loaded machine, over 10 s.
  options=(-max_total_time="$seconds" -timeout=60 -report_slow_units=60 -rss_limit_mb=2048 -print_final_stats=1
           -artifact_prefix="$artifacts/")
  [ -f "$here/$target.dict" ] && options+=(-dict="$here/$target.dict")
  corpora=("$work/corpus" "$here/corpus/$target")
  if [ "$fresh" = 1 ]; then
    rm -rf "$work/fresh"
    mkdir -p "$work/fresh"
    corpora[0]=$work/fresh
  fi
  if [ "$keep_going" = 1 ]; then
    options+=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  elif [ -d "$here/findings/$target" ]; then
    corpora+=("$here/findings/$target")
  fi
  touch "$work/started"
  echo "fuzz_$target: ${seconds} s, log in $log"
  if "$build/bin/fuzz_$target" "${options[@]}" "${corpora[@]}" >"$log" 2>&1; then
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ *DONE)' "$log" | sed 's/^/  /'
  else
    status=1
    echo "fuzz_$target: FAILED (a finding, or the fuzzer could not run); the end of its log:"
    grep -v NEW_FUNC "$log" | tail -n 60 | cut -c1-400
  fi
  found=$(find "$artifacts" -type f -newer "$work/started")
  if [ -n "$found" ]; then
    status=1
    echo "fuzz_$target: new findings (replay one with $build/bin/fuzz_$target FILE):"
    echo "$found" | sed 's/^/  /'
  fi
done
exit $status
