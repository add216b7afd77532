#!/usr/bin/env bash
# Build the LAMMPS that bounce's plugin runs in (docs/lammps.md), cached outside the clone.
#
#   scripts/build-lammps.sh            prints the LAMMPS source directory (src/) on its last line
#   LAMMPS_SUITE=bookworm|trixie|sid   which Debian suite's lammps (default trixie, Debian 13)
#
# Debian's `lammps` binary has no PLUGIN package and liblammps-dev's headers do not compile
# as shipped (fmt 9, no neigh_request.h), so this fetches Debian's source package of a suite
# with apt's source download, through a private sources list in the cache (the machine's apt
# configuration is not touched), and builds it with GRANULAR + PLUGIN + MPI as a shared
# library. Each build is kept apart under $BOUNCE_CACHE (default ~/.cache/bounce), keyed by
# the Debian version: a second run finds it and only prints the path.
set -euo pipefail

suite="${LAMMPS_SUITE:-trixie}"
case "$suite" in
  bookworm) version="20220106.git7586adbb6a+ds1-2" ;;  # Debian 12: LAMMPS 29 Sep 2021, update 2
  trixie)   version="20250204+dfsg.1-2" ;;             # Debian 13: LAMMPS 4 Feb 2025
  sid)      version="20260704+dfsg-2" ;;               # unstable (moves: update this line)
  *) echo "bounce lammps: LAMMPS_SUITE = $suite is invalid: expected bookworm, trixie or sid" >&2; exit 2 ;;
esac
cache="${BOUNCE_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/bounce}/lammps-${version}"
jobs="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
log() { echo "bounce lammps: $*" >&2; }

if [ -f "$cache/ok" ] && [ -x "$cache/build/lmp" ]; then
  log "cached build in $cache"
  echo "$cache/src/src"
  exit 0
fi

mirror() { "$(dirname "$0")/debian-mirror.sh"; }  # the machine's Debian mirror

mkdir -p "$cache"
download="$cache/download"
orig() { compgen -G "$download/lammps_*.orig.tar.*" | head -1; }
if [ -z "$(orig || true)" ]; then
  rm -rf "$download" && mkdir -p "$download/lists/partial"
  echo "deb-src $(mirror) $suite main" > "$download/sources.list"
  apt_opts=(-o "Dir::Etc::sourcelist=$download/sources.list" -o "Dir::Etc::sourceparts=-"
            -o "Dir::State::Lists=$download/lists" -o "APT::Sandbox::User=root")
  log "fetching Debian's lammps $version ($suite) source ($(cat "$download/sources.list"))"
  apt-get "${apt_opts[@]}" update -qq >&2
  # apt checks each file against the suite's Sources index. Only the upstream tarball is
  # needed: a mirror that lacks the .dsc (trixie's answered 404 for it here) makes apt-get
  # fail after fetching the tarballs, which is not an error for this build.
  (cd "$download" && apt-get "${apt_opts[@]}" source --download-only -qq "lammps=$version" >&2) ||
    log "apt-get source did not fetch every file of lammps $version (only the .orig tarball is needed)"
  [ -n "$(orig || true)" ] || { log "no lammps_*.orig.tar.* of $version in $download"; exit 1; }
fi
if [ ! -d "$cache/src/src" ]; then
  log "unpacking"
  rm -rf "$cache/src.tmp" && mkdir -p "$cache/src.tmp"
  tar -xaf "$(orig)" -C "$cache/src.tmp"
  # bookworm's and trixie's tarballs hold one folder (lammps-.../), sid's the tree itself.
  entries=("$cache/src.tmp"/*)
  if [ "${#entries[@]}" -eq 1 ] && [ -d "${entries[0]}" ]; then
    mv "${entries[0]}" "$cache/src" && rmdir "$cache/src.tmp"
  else
    mv "$cache/src.tmp" "$cache/src"
  fi
fi

log "configuring and building (core + GRANULAR + PLUGIN + MPI, ~440 files; a few minutes on 2 cores)"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$cache/src/cmake" -B "$cache/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DBUILD_SHARED_LIBS=ON -DBUILD_MPI=ON -DBUILD_OMP=OFF -DLAMMPS_EXCEPTIONS=ON \
  -DPKG_GRANULAR=ON -DPKG_PLUGIN=ON \
  -DWITH_JPEG=OFF -DWITH_PNG=OFF -DWITH_FFMPEG=OFF -DWITH_GZIP=OFF "${launcher[@]}" >"$cache/configure.log" 2>&1 ||
  { tail -30 "$cache/configure.log" >&2; exit 1; }
cmake --build "$cache/build" -j "$jobs" >"$cache/build.log" 2>&1 || { tail -40 "$cache/build.log" >&2; exit 1; }
touch "$cache/ok"
log "built $cache/build/lmp"
echo "$cache/src/src"
