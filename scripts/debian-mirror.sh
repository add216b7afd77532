#!/usr/bin/env bash
# Prints the Debian mirror the machine already uses (deb822 or one-line sources, the security
# archive skipped), else http://deb.debian.org/debian. Used by build-lammps.sh (the LAMMPS source
# package) and check-debian13.sh (debootstrap).
set -euo pipefail
uri=""
if compgen -G "/etc/apt/sources.list.d/*.sources" >/dev/null; then
  uri=$(awk '/^URIs:/ {print $2; exit}' /etc/apt/sources.list.d/*.sources 2>/dev/null | grep -v security || true)
fi
if [ -z "$uri" ] && [ -f /etc/apt/sources.list ]; then
  uri=$(awk '$1 == "deb" && $0 !~ /security/ {for (i = 2; i <= NF; i++) if ($i ~ /^https?:/) {print $i; exit}}' /etc/apt/sources.list || true)
fi
echo "${uri:-http://deb.debian.org/debian}"
