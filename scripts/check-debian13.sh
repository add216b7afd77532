#!/usr/bin/env bash
# `make check-debian13` (opt-in): the two commands on a fresh Debian 13 (trixie) (docs/install.md).
#
#   scripts/check-debian13.sh [ROOT]     (default build-debian13/root)
#
# Makes a minimal trixie root with debootstrap from the Debian mirror the machine uses (about
# 20-60 s), copies the committed tree (git archive HEAD) into /src/bounce, and runs there, as
# root with its own apt-get: `apt-get install make` (what a user does first), `make test`,
# `make demo` (every figure checked) and `make check-pip`.
# The time of each step is printed and kept in ROOT/../times.txt, the output in
# ROOT/../<step>.log. Needs root (or sudo), debootstrap (installed when missing) and ~4 GB.
# The root is made afresh each run; /proc, /sys and /dev are mounted into it while it runs.
set -euo pipefail
cd "$(dirname "$0")/.."
fail() { echo "bounce: error: $*" >&2; exit 2; }

if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || fail "user = $(id -un) is invalid: expected root or sudo (debootstrap and chroot)"
  exec sudo "$0" "$@"
fi
git rev-parse --git-dir >/dev/null 2>&1 || fail "tree = $PWD is invalid: expected a git checkout (the tree is copied with git archive)"
command -v debootstrap >/dev/null || ./scripts/install-deps.sh debootstrap
command -v debootstrap >/dev/null || fail "debootstrap = (not found) is invalid: expected Debian's debootstrap package"

root="${1:-build-debian13/root}"
mkdir -p "$(dirname "$root")"
root="$(cd "$(dirname "$root")" && pwd)/$(basename "$root")"
logs=$(dirname "$root")

mirror() { scripts/debian-mirror.sh; }  # the machine's Debian mirror (the tree is the working directory)

unmount() {
  for m in dev sys proc; do
    if mountpoint -q "$root/$m"; then umount -R "$root/$m"; fi
  done
}
trap unmount EXIT
trap 'exit 130' INT TERM  # a stopped run unmounts too (bash runs no EXIT trap on a fatal signal)
unmount
if grep -q " $root/" /proc/mounts; then  # never remove through a mount into the machine
  fail "root = $root is invalid: expected nothing mounted inside it ($(grep -c " $root/" /proc/mounts) mounts)"
fi
rm -rf "$root"
: > "$logs/times.txt"
echo "bounce debian13: tree $(git rev-parse --short HEAD) (git archive HEAD), started $(date -u '+%Y-%m-%d %H:%M UTC')" | tee -a "$logs/times.txt"

timed() {  # timed NAME COMMAND...: runs it, its output in $logs/NAME.log, its time in times.txt
  local name=$1 start rc=0
  shift
  start=$(date +%s)
  echo "bounce debian13: $name ..."
  "$@" > "$logs/$name.log" 2>&1 || rc=$?
  local line
  line="$name: $( [ $rc = 0 ] && echo passed || echo "FAILED ($rc)" ) in $(( ($(date +%s) - start) / 60 )) min $(( ($(date +%s) - start) % 60 )) s"
  echo "bounce debian13: $line" | tee -a "$logs/times.txt"
  [ $rc = 0 ] || { tail -40 "$logs/$name.log" >&2; exit 1; }
}

inside() {  # a command in the root, as a fresh login would run it
  chroot "$root" /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root \
    LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive /bin/bash -c "cd /src/bounce && $1"
}

timed debootstrap debootstrap --variant=minbase trixie "$root" "$(mirror)"
mkdir -p "$root/src/bounce"
git archive HEAD | tar -x -C "$root/src/bounce"
cp /etc/resolv.conf "$root/etc/resolv.conf"
mount -t proc proc "$root/proc"
mount -t sysfs sysfs "$root/sys"
mount --rbind /dev "$root/dev"
mount --make-rslave "$root/dev"
inside 'grep PRETTY_NAME /etc/os-release' | tee -a "$logs/times.txt"

# minbase has no make, nor has a default Debian installation: the one package a user installs
# by hand before the two commands (they install the rest).
timed install-make inside 'apt-get update -qq && apt-get install -y -qq --no-install-recommends make'
timed make-test inside 'make test'
# Every figure of the registry (bounce.plot.FIGURES), as PNG and SVG, and the report.
timed make-demo inside 'make demo && /usr/bin/python3 -c "
import os, sys
sys.path.insert(0, \"build/python\")
from bounce import plot
missing = [f\"out/figures/{n}.{e}\" for n in plot.FIGURES for e in (\"png\", \"svg\")
           if not os.path.isfile(f\"out/figures/{n}.{e}\") or os.path.getsize(f\"out/figures/{n}.{e}\") == 0]
print(f\"figures: {len(plot.FIGURES)} written\" if not missing else f\"missing {missing}\")
sys.exit(1 if missing else 0)
" && test -s out/report.md'
timed make-check-pip inside 'make check-pip'
{ inside 'dpkg-query -W -f "\${Package} \${Version}\n" g++ clang cmake libsundials-dev libboost-dev libfmt-dev \
  libcli11-dev pybind11-dev python3 python3-numpy python3-setuptools' || true; } | tee -a "$logs/times.txt"
echo "bounce debian13: all passed (times in $logs/times.txt)"
