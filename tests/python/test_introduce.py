"""The version everywhere (CMakeLists.txt, bounce --version, bounce.__version__) and the bash
completion that `bounce completion` generates (docs/cli.md, docs/install.md)."""
import json
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


def complete(script, *words):
    """What the completion offers for `bounce WORDS...` (the last word being completed)."""
    line = 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _bounce; printf "%s\\n" "${COMPREPLY[@]}"'
    out = subprocess.run(["bash", "-c", line, "_", script, "bounce", *words], check=True, capture_output=True,
                         text=True).stdout
    return set(out.split())


def test_completion_knows_the_registries(tmp_path):
    script = tmp_path / "bounce"
    script.write_text(run("completion"))
    subprocess.run(["bash", "-n", str(script)], check=True)
    commands = complete(script, "")
    assert {"collide", "curve", "fit", "completion", "--version"} <= commands
    models = [m["name"] for m in json.loads(run("models", "--json"))["models"]]
    assert complete(script, "collide", "--model", "") == set(models)
    assert complete(script, "collide", "--model", "kr") == {m for m in models if m.startswith("kr")}
    materials = set(bounce.material_names())
    assert complete(script, "collide", "--material", "") == materials
    assert complete(script, "curve", "--material2", "wat") == {m for m in materials if m.startswith("wat")}
    assert complete(script, "contact", "--law", "") >= {"hertz", "jkr", "dmt", "maugis"}
    assert complete(script, "collide", "--contact-end", "") >= {"overlap", "force"}


def test_completion_knows_each_commands_options(tmp_path):
    script = tmp_path / "bounce"
    script.write_text(run("completion"))
    help_text = run("collide", "--help")
    offered = complete(script, "collide", "--")
    assert offered == set(re.findall(r"(?<![\w-])(--[A-Za-z0-9][A-Za-z0-9-]*)", help_text))
    assert "--force" not in offered  # contact's, not collide's
    assert complete(script, "collide", "--velocity", "") == set()  # a number: nothing to offer
    assert complete(script, "collide", "--wall", "--velo") == {"--velocity"}  # a flag takes no value
    assert complete(script, "fit", "--data", str(tmp_path / "bou")) == {str(script)}  # a file
