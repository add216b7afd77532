"""The Python package built by CMake, for pip (pyproject.toml; README: Install).

    python3 -m pip install --no-build-isolation .          in a venv (--system-site-packages)
    python3 -m pip wheel --no-build-isolation --no-deps .  a wheel

The extension bounce._bounce and its type stubs (_bounce.pyi, generated from the registry)
come from the project's own CMake build, configured for the Python that runs pip, with the
library linked in statically (one extension module, nothing else to find at run time). The
version is project(bounce VERSION ...) of CMakeLists.txt, the one bounce.__version__ reports.
The CMake build is kept in build-pip/, so a second install only rebuilds what changed.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
BUILD_BASE = "build-pip"


def fail(name, value, expected):
    """The project's one-line rule for bad input, then exit (no traceback)."""
    sys.stderr.write(f"bounce: error: {name} = {value} is invalid: expected {expected}\n")
    raise SystemExit(2)


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text(encoding="utf-8")
    found = re.search(r"project\(\s*bounce\s+VERSION\s+([0-9]+\.[0-9]+\.[0-9]+)", text)
    if found is None:
        fail("CMakeLists.txt", "(no version)", "project(bounce VERSION X.Y.Z)")
    return found.group(1)


class CMakeBuild(build_ext):
    """Builds bounce._bounce with CMake instead of compiling sources itself."""

    def build_extension(self, ext):
        cmake = shutil.which("cmake")
        if cmake is None:
            fail("cmake", "(not found)", "CMake and bounce's build dependencies (scripts/install-deps.sh)")
        build = Path(self.build_temp).resolve() / "cmake"
        configure = [cmake, "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                     f"-DPython3_EXECUTABLE={sys.executable}", "-DBOUNCE_SHARED=OFF",
                     "-DBOUNCE_BUILD_TESTS=OFF", "-DBOUNCE_BUILD_BENCH=OFF"]
        if not (build / "CMakeCache.txt").exists() and shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        if shutil.which("ccache"):
            configure.append("-DCMAKE_CXX_COMPILER_LAUNCHER=ccache")
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 2))
        try:
            subprocess.run(configure, check=True)
            subprocess.run([cmake, "--build", str(build), "--target", "bounce_python", "bounce_python_stub",
                            "-j", jobs], check=True)
        except subprocess.CalledProcessError as e:
            fail("cmake", " ".join(e.cmd[:3]) + " ...", f"a successful build (exit {e.returncode}; its output is above)")
        built = build / "python" / "bounce"
        modules = sorted(built.glob("_bounce*.so"))
        if not modules:
            fail("build", str(built), "the extension _bounce*.so there")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(modules[0], target)
        shutil.copy2(built / "_bounce.pyi", target.parent / "_bounce.pyi")


os.makedirs(ROOT / BUILD_BASE, exist_ok=True)
setup(
    version=project_version(),
    packages=["bounce"],
    package_dir={"bounce": "python/bounce"},
    package_data={"bounce": ["py.typed"]},
    include_package_data=False,
    ext_modules=[Extension("bounce._bounce", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}},
)
