#!/usr/bin/env bash
# `make check-pip` (opt-in): the Python package installed as Python software (docs/install.md).
#
#   scripts/check-pip.sh [WORK_DIR]     (default build-pip/check)
#
# In a fresh venv made by Debian's /usr/bin/python3 with --system-site-packages (numpy,
# setuptools and wheel come from Debian's packages; nothing is downloaded: PIP_NO_INDEX):
# `pip install --no-build-isolation .` installs the extension, the package and its type stubs;
# `import bounce` from another folder gives the CMake project's version; `pip wheel` makes a
# wheel holding the same. The CMake build is setup.py's, kept in build-pip/ between runs.
set -euo pipefail
cd "$(dirname "$0")/.."
work="${1:-build-pip/check}"
fail() { echo "bounce: error: $*" >&2; exit 2; }

/usr/bin/python3 -c "import venv, ensurepip" 2>/dev/null ||
  fail "python3-venv = (not installed) is invalid: expected Debian's python3-venv (make check-pip installs it)"
/usr/bin/python3 -c "import setuptools" 2>/dev/null ||
  fail "python3-setuptools = (not installed) is invalid: expected Debian's python3-setuptools (make check-pip installs it)"
version=$(sed -n 's/^project(bounce VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)

rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
python="$work/venv/bin/python"
export PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
start=$(date +%s)
"$python" -m pip install --no-build-isolation .
echo "bounce check-pip: pip install took $(( $(date +%s) - start )) s"

mkdir -p "$work/elsewhere"
(cd "$work/elsewhere" && "$python" - "$version" "$work/venv" <<'EOF_PY'
import importlib.metadata
import pathlib
import sys

import bounce

version, venv = sys.argv[1:]
package = pathlib.Path(bounce.__file__).parent
assert bounce.__version__ == version, (bounce.__version__, version)
assert importlib.metadata.version("bounce") == version, importlib.metadata.version("bounce")
assert str(package).startswith(venv), package
for f in ("_bounce.pyi", "py.typed"):
    assert (package / f).is_file(), f
assert list(package.glob("_bounce*.so")), list(package.iterdir())
pair = bounce.Pair(material="water-ice", radius=2e-6)
cor = bounce.collide(pair, bounce.Model("krijt", tvis=1e-11), 8.0)["cor"]
assert 0 < cor < 1, cor
print(f"bounce check-pip: import bounce {bounce.__version__} from {package}: cor {cor:.6f}")
EOF_PY
)

"$python" -m pip wheel --no-build-isolation --no-deps -w "$work/wheel" .
"$python" - "$work/wheel" "$version" <<'EOF_PY'
import pathlib
import sys
import zipfile

wheels = list(pathlib.Path(sys.argv[1]).glob("bounce-*.whl"))
assert len(wheels) == 1, wheels
names = zipfile.ZipFile(wheels[0]).namelist()
for part in ("bounce/__init__.py", "bounce/_bounce.pyi", "bounce/py.typed"):
    assert part in names, (part, names)
assert any(n.startswith("bounce/_bounce") and n.endswith(".so") for n in names), names
assert wheels[0].name.startswith(f"bounce-{sys.argv[2]}-"), wheels[0].name
print(f"bounce check-pip: wheel {wheels[0].name}")
EOF_PY
echo "bounce check-pip: all checks passed"
