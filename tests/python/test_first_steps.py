"""Issue 40, round 3, point 9: first steps (docs/hardening.md, "round 3"). Every command's --help
starts with its usage and examples that run as written (each is run here, from an empty folder,
with the build's bounce first on PATH); `bounce help [COMMAND]` is its --help; a misspelt command
is refused with a suggestion even with --help; a command run with no option says what it needs;
sticking's help names no default model (it has none)."""
import gzip
import os
import subprocess

import pytest

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.path.abspath(os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce")))
COMMANDS = ["materials", "models", "contact", "collide", "curve", "analytic", "sticking", "rules", "table", "fit",
            "lammps", "atlas build", "atlas query", "atlas export", "aggregate build", "completion"]


def run(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


def examples(command):
    lines = run(*command.split(), "--help").stdout.splitlines()
    assert lines[1].startswith(f"Usage: bounce {command} "), lines[:3]
    assert lines[3] == "Examples:", lines[:5]
    out = []
    for line in lines[4:]:
        if not line.startswith("  "):
            break
        out.append(line.strip())
    return out


@pytest.mark.parametrize("command", COMMANDS)
def test_help_starts_with_usage_and_examples_that_run(command, tmp_path):
    found = examples(command)
    assert found and all("bounce " + command in e for e in found), found
    env = dict(os.environ, PATH=os.path.dirname(CLI) + os.pathsep + os.environ["PATH"])
    for example in found:
        done = subprocess.run(["bash", "-c", "set -o pipefail; " + example], cwd=tmp_path, env=env,
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, (example, done.stderr[-2000:])


def test_commands_listed_are_all_of_bounces():
    listed = [line.split()[0] for line in run("--help").stdout.split("Subcommands:")[-1].split("\n\n")[0].split("SUBCOMMANDS:")[-1].splitlines()
              if line.startswith("  ")]
    assert sorted(listed) == sorted({c.split()[0] for c in COMMANDS}), listed


@pytest.mark.parametrize("command", ["collide", "atlas query"])
def test_help_command_is_the_commands_help(command):
    given = run("help", *command.split())
    assert given.returncode == 0 and given.stdout == run(*command.split(), "--help").stdout
    whole = run("help")
    assert whole.returncode == 0 and whole.stdout == run().stdout


def test_misspelt_command_is_refused_even_with_help():
    """main printed bounce's own help with exit 0 for `bounce colide --help`."""
    for args in (["colide", "--help"], ["help", "colide"]):
        done = run(*args)
        assert done.returncode == 2 and done.stdout == "" and done.stderr.strip().endswith("did you mean collide?")


@pytest.mark.parametrize("command", ["collide", "curve", "sticking", "table", "fit", "atlas query", "aggregate build"])
def test_a_command_alone_says_what_it_needs(command, tmp_path):
    """main: `bounce collide` alone said `--E = (not given)`; now the needs and an example that runs."""
    done = run(*command.split())
    message = done.stderr.strip()
    assert done.returncode == 2 and message.startswith("bounce: error: options = (none given) is invalid: expected "
                                                       f"what `bounce {command}` needs: "), message
    example = message.split("; e.g. `", 1)[1].split("` (`bounce", 1)[0]
    env = dict(os.environ, PATH=os.path.dirname(CLI) + os.pathsep + os.environ["PATH"])
    assert subprocess.run(["bash", "-c", example], cwd=tmp_path, env=env, capture_output=True).returncode == 0


def test_sticking_help_names_no_default_model():
    """main: `(default viscoelastic)`, a model sticking refuses."""
    line = next(l for l in run("sticking", "--help").stdout.splitlines() if "--model NAME" in l)
    assert "(required: no default)" in line and "viscoelastic |" not in line.split("NAME", 1)[1].split("adhesive")[0]


def test_the_man_page_is_built_and_readable_from_the_build_tree():
    """Point 10: `man bounce` was advertised but existed only where help2man happened to be installed;
    help2man is a build dependency now (scripts/install-deps.sh), and the page is in the build tree."""
    page = os.path.join(os.path.dirname(os.path.dirname(CLI)), "share", "man", "man1", "bounce.1.gz")
    assert os.path.isfile(page), f"{page}: install help2man (scripts/install-deps.sh) and configure again"
    with gzip.open(page, "rt") as f:
        text = f.read()  # groff source: "\-\-velocity"
    assert ".TH BOUNCE" in text, text[:500]
    assert "velocity" in text and "sticking" in text, text[:500]
