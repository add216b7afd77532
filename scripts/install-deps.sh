#!/usr/bin/env bash
# Install the Debian packages bounce needs, only those that are missing.
# Uses sudo when not root. Safe to run repeatedly (a no-op when all are present).
# Extra packages for one target come as arguments (`make lint`: clang-tidy; `make test`,
# `make test-sanitize`, `make fuzz`: clang, libclang-rt-dev and ccache, the sanitizer build).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libboost-dev libsundials-dev libcli11-dev libtomlplusplus-dev
  nlohmann-json3-dev libfmt-dev libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev librapidcheck-dev
  libnlopt-cxx-dev libopenmpi-dev openmpi-bin libhdf5-dev gfortran
  pybind11-dev python3 python3-dev python3-numpy python3-matplotlib
  python3-scipy python3-pytest python3-emcee python3-h5py
  help2man gzip
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "bounce: installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1; then
  SUDO=(sudo)
else
  echo "bounce: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq
"${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
