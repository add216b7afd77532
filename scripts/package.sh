#!/usr/bin/env bash
# `make package`: bounce's Debian packages (CPack DEB, cmake/BouncePackage.cmake) into DIST_DIR.
#
#   scripts/package.sh BUILD_DIR DIST_DIR [LAMMPS_SRC]
#
# Configures BUILD_DIR (default build-package) for /usr, without tests or benchmarks, with the
# LAMMPS plugin when LAMMPS_SRC (a LAMMPS src/ folder, `make lammps`'s) is given, builds it and
# writes one .deb per component: libbounce0, libbounce-dev, bounce, python3-bounce and
# bounce-lammps-plugin. A missing tool is one line on stderr, exit 2.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build-package}"
dist="${2:-dist}"
lammps_src="${3:-}"

for tool in cmake cpack help2man dpkg-shlibdeps dpkg-deb file; do
  if ! command -v "$tool" >/dev/null; then
    echo "bounce: error: $tool = (not found) is invalid: expected it installed (make package installs help2man, dpkg-dev and file)" >&2
    exit 2
  fi
done
if [ -n "$lammps_src" ] && [ ! -f "$lammps_src/lammpsplugin.h" ]; then
  echo "bounce: error: LAMMPS_SRC = $lammps_src is invalid: expected a LAMMPS src/ folder with the PLUGIN package" >&2
  exit 2
fi

mkdir -p "$dist"
dist=$(cd "$dist" && pwd)
args=(-G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DBOUNCE_PACKAGE=ON
      -DBOUNCE_BUILD_TESTS=OFF -DBOUNCE_BUILD_BENCH=OFF -DBOUNCE_WERROR="${WERROR:-ON}"
      -DPython3_EXECUTABLE=/usr/bin/python3 -DBOUNCE_PACKAGE_DIR="$dist")
[ -z "$lammps_src" ] || args+=(-DLAMMPS_SOURCE_DIR="$lammps_src")
! command -v ccache >/dev/null || args+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
[ -f "$build/CMakeCache.txt" ] && args=("${args[@]:2}")  # the generator only on the first run
cmake -S . -B "$build" "${args[@]}" > /dev/null
cmake --build "$build" -j "${JOBS:-2}"
rm -f "$dist"/*.deb
(cd "$build" && cpack -G DEB > cpack.log 2>&1) || { tail -30 "$build/cpack.log" >&2; exit 1; }
ls -1 "$dist"/*.deb
