#!/usr/bin/env bash
# Checks an installed bounce the way a user meets it (docs/install.md).
#
#   scripts/check-package.sh [--lmp LMP] DIST_DIR     unpack every .deb of DIST_DIR (`make package`)
#                                                     into an empty folder, then check its usr/
#   scripts/check-package.sh [--lmp LMP] --prefix P   check the tree installed under P (/usr after
#                                                     `apt install ./dist/*.deb`, or `cmake --install`)
#
# The checks: bin/bounce --version prints the project's version; a collision runs; its HDF5 and
# MPI modules open (an atlas read, a batch under mpirun); the man page
# (when installed) names the commands; the bash completion completes a command, a model and a
# material; `import bounce` from another folder gives the same __version__, with its type stubs;
# examples/consumer configures against the installed CMake package, builds and runs; and with
# an lmp (LAMMPS with the PLUGIN package) the installed plugin loads by `plugin load` (and by
# LAMMPS_PLUGIN_PATH where that LAMMPS has it; 20220106 does not). Without --prefix every package must carry its part (man page, plugin).
# Bad input (a missing tool, a folder that holds no bounce) is one line on stderr, exit 2.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD

fail() { echo "bounce: error: $*" >&2; exit 2; }
step() { echo "bounce check: $*"; }

lmp=""
prefix=""
dist=""
while [ $# -gt 0 ]; do
  case $1 in
    --lmp) [ $# -ge 2 ] || fail "--lmp = (no value) is invalid: expected the path of an lmp"; lmp=$2; shift 2 ;;
    --prefix) [ $# -ge 2 ] || fail "--prefix = (no value) is invalid: expected an installation prefix"; prefix=$2; shift 2 ;;
    -*) fail "$1 = (given) is invalid: expected --lmp LMP, --prefix P or a folder of .deb files" ;;
    *) dist=$1; shift ;;
  esac
done
[ -n "$prefix" ] || [ -n "$dist" ] || fail "dist = (not given) is invalid: expected a folder of .deb files or --prefix P"
for tool in cmake /usr/bin/python3 bash; do
  command -v "$tool" >/dev/null || fail "$tool = (not found) is invalid: expected it installed (scripts/install-deps.sh)"
done

version=$(sed -n 's/^project(bounce VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
work=$(mktemp -d "${TMPDIR:-/tmp}/bounce-check.XXXXXX")
trap 'rm -rf "$work"' EXIT
strict=0

if [ -n "$dist" ]; then
  command -v dpkg-deb >/dev/null || fail "dpkg-deb = (not found) is invalid: expected Debian's dpkg"
  shopt -s nullglob
  debs=("$dist"/*.deb)
  [ ${#debs[@]} -gt 0 ] || fail "dist = $dist is invalid: expected a folder with the .deb files of make package"
  for deb in "${debs[@]}"; do
    dpkg-deb -x "$deb" "$work/root"
    step "$(dpkg-deb -f "$deb" Package) $(dpkg-deb -f "$deb" Version): Depends: $(dpkg-deb -f "$deb" Depends)"
  done
  prefix="$work/root/usr"
  strict=1
fi
[ -d "$prefix" ] || fail "--prefix = $prefix is invalid: expected an existing folder"
prefix=$(cd "$prefix" && pwd)
cli="$prefix/bin/bounce"
[ -x "$cli" ] || fail "--prefix = $prefix is invalid: expected an installed bounce there (bin/bounce)"

# The CLI: its version, and a collision.
got=$("$cli" --version)
[ "$got" = "bounce $version" ] || fail "bounce --version = $got is invalid: expected bounce $version"
step "$got"
"$cli" collide --material water-ice --radius 2e-6 --model krijt --tvis 1e-11 --velocity 8 --json > "$work/collide.json"
/usr/bin/python3 -c "import json, sys; r = json.load(open(sys.argv[1])); assert 0 < r['cor'] < 1 and r['outcome'] == 'bounce', r['cor']; \
print('bounce check: collide: cor', r['cor'], r['outcome'])" "$work/collide.json"

# The modules (docs/architecture.md, "Modules"): reading a missing atlas gets as far as the HDF5
# module's "no such file" (exit 2, where a module not installed is exit 3), and under mpirun a
# missing batch manifest is read after the MPI module started.
expect_refusal() {  # expect_refusal TEXT COMMAND...: exit 2 with TEXT on stderr
  local text=$1 code=0
  shift
  "$@" > /dev/null 2> "$work/refusal.txt" || code=$?
  [ "$code" = 2 ] && grep -q "$text" "$work/refusal.txt" ||
    fail "$* = exit $code ($(head -c 300 "$work/refusal.txt")) is invalid: expected exit 2 and $text"
}
expect_refusal "no such file" "$cli" atlas query "$work/missing.h5" --radius 1e-6 --velocity 1
step "atlas module: $(ls "$prefix"/lib/*/bounce/atlas_hdf5.so "$prefix"/lib/bounce/atlas_hdf5.so 2>/dev/null | head -1)"
modules=$(dirname "$(ls "$prefix"/lib/*/bounce/atlas_hdf5.so "$prefix"/lib/bounce/atlas_hdf5.so 2>/dev/null | head -1)")
if command -v mpirun > /dev/null && [ -e "$modules/mpi.so" ]; then
  expect_refusal "readable TOML manifest" env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
    mpirun --oversubscribe -np 2 "$cli" fit --batch "$work/missing.toml"
  step "mpi module: mpirun -np 2 bounce fit --batch"
fi

# The man page and the bash completion.
man="$prefix/share/man/man1/bounce.1.gz"
if [ -f "$man" ]; then
  # grep -c reads the whole page: grep -q would stop at the first match and, under pipefail, gzip's
  # SIGPIPE on its next write failed the check now and then (install_tree in .ci/run, 9b2e790).
  gzip -dc "$man" | grep -c "collide" > /dev/null || fail "man page = $man is invalid: expected the commands in it"
  step "man page $man"
elif [ $strict = 1 ]; then
  fail "man page = (missing) is invalid: expected share/man/man1/bounce.1.gz in the packages"
fi
completion="$prefix/share/bash-completion/completions/bounce"
[ -f "$completion" ] || fail "completion = (missing) is invalid: expected $completion"
complete_words() {  # what the completion offers for the words "$@" (the last being completed)
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _bounce; echo "${COMPREPLY[*]}"' \
    _ "$completion" "$@"
}
for probe in "col:collide" "collide --model kr:krijt" "collide --material water:water-ice" "collide --velo:--velocity"; do
  words=${probe%%:*}
  expected=${probe#*:}
  # shellcheck disable=SC2086
  offered=$(complete_words bounce $words)
  [[ " $offered " == *" $expected "* ]] || fail "completion of 'bounce $words' = '$offered' is invalid: expected $expected"
done
step "bash completion $completion"

# Python, imported from another folder.
pydir="$prefix/lib/python3/dist-packages"
[ -f "$pydir/bounce/__init__.py" ] || fail "--prefix = $prefix is invalid: expected the Python package in lib/python3/dist-packages/bounce"
for f in _bounce.pyi py.typed; do
  [ -f "$pydir/bounce/$f" ] || fail "python package = $pydir/bounce is invalid: expected $f in it"
done
(cd "$work" && PYTHONPATH="$pydir" /usr/bin/python3 - "$version" "$pydir" <<'EOF'
import sys
import bounce
version, pydir = sys.argv[1:]
assert bounce.__version__ == version, (bounce.__version__, version)
assert bounce.__file__.startswith(pydir), bounce.__file__
pair = bounce.Pair(material="water-ice", radius=2e-6)
print("bounce check: import bounce", bounce.__version__, "from", bounce.__file__, "cor",
      bounce.collide(pair, bounce.Model("krijt", tvis=1e-11), 8.0)["cor"])
EOF
)

# The C++ consumer, against the installed CMake package.
cmake -S "$source_dir/examples/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log" >&2; fail "consumer = examples/consumer is invalid: expected it to configure against $prefix"; }
cmake --build "$work/consumer" >> "$work/consumer.log" 2>&1 || { cat "$work/consumer.log" >&2; fail "consumer = examples/consumer is invalid: expected it to build"; }
step "consumer: $("$work/consumer/consumer")"

# The LAMMPS plugin.
plugin=$(find "$prefix/lib" -path '*/lammps/plugins/bounceplugin.so' 2>/dev/null | head -1)
if [ -z "$plugin" ]; then
  [ $strict = 0 ] || fail "plugin = (missing) is invalid: expected lib/<multiarch>/lammps/plugins/bounceplugin.so in the packages"
  step "no LAMMPS plugin installed"
elif [ -z "$lmp" ]; then
  [ $strict = 0 ] || fail "--lmp = (not given) is invalid: expected an lmp with the PLUGIN package to load $plugin"
  step "plugin $plugin (not loaded: no --lmp)"
else
  [ -x "$lmp" ] || fail "--lmp = $lmp is invalid: expected an lmp executable (make lammps builds one)"
  printf 'plugin load %s\nplugin list\n' "$plugin" > "$work/in.load"
  (cd "$work" && "$lmp" -log none -in in.load > load.out 2>&1) || { cat "$work/load.out" >&2; fail "plugin = $plugin is invalid: expected plugin load to work"; }
  grep -q "pair style plugin bounce" "$work/load.out" || { cat "$work/load.out" >&2; fail "plugin = $plugin is invalid: expected pair style bounce listed after plugin load"; }
  step "plugin $plugin loads in $lmp by plugin load"
  # LAMMPS_PLUGIN_PATH (loading every *plugin.so of its folders at start) is newer than 20220106:
  # checked where the LAMMPS has it (its library has the message of that loading; the
  # variable's name is built inline by the compiler, not kept as a string).
  liblammps=$(ldd "$lmp" | awk '/liblammps/ {print $3}')
  if grep -aq "plugins from" "$lmp" ${liblammps:+"$liblammps"}; then
    printf 'plugin list\n' > "$work/in.path"
    (cd "$work" && LAMMPS_PLUGIN_PATH=$(dirname "$plugin") "$lmp" -log none -in in.path > path.out 2>&1) ||
      { cat "$work/path.out" >&2; fail "LAMMPS_PLUGIN_PATH = $(dirname "$plugin") is invalid: expected lmp to start with it"; }
    grep -q "pair style plugin bounce" "$work/path.out" || { cat "$work/path.out" >&2; fail "LAMMPS_PLUGIN_PATH = $(dirname "$plugin") is invalid: expected LAMMPS to load bounceplugin.so from it"; }
    step "plugin loads by LAMMPS_PLUGIN_PATH=$(dirname "$plugin")"
  else
    step "this LAMMPS has no LAMMPS_PLUGIN_PATH (it predates it): plugin load only"
  fi
fi
step "all checks passed for $prefix"
