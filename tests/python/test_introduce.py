"""The version everywhere: CMakeLists.txt, bounce --version, bounce.__version__ (docs/cli.md)."""
import os
import re
import subprocess

import bounce

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))


def run(*args):
    return subprocess.run([CLI, *args], check=True, capture_output=True, text=True).stdout


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(bounce VERSION ([0-9.]+)", f.read()).group(1)


def test_one_version():
    assert bounce.__version__ == project_version()
    assert run("--version") == f"bounce {project_version()}\n"
