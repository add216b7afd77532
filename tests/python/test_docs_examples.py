"""Issue 40, round 3: every example of the README's tour and of docs/ runs as written.

Each fenced block of README.md and docs/*.md is read the way a reader would copy it:
  * shell blocks (```sh and unlabelled ones): every line that runs bounce (`bounce ...`,
    `build/bin/bounce ...`, `PYTHONPATH=build/python ... -m bounce.figures ...`), continuation
    lines joined, run one after the other in one empty folder (so `atlas query ice.h5` finds the
    atlas the line before built), with `build` and `data` linked there and the build's bounce
    first on PATH; each must exit 0;
  * transcripts (```text and ```sh blocks whose lines start with `$ `): the command runs, and the
    lines shown under it appear in its output in that order ("…" and "..." stand for what the
    page leaves out); a "bounce: error:" line means exit 2 with that message;
  * Python blocks: run statement by statement in one namespace per page, from the same folder; a
    statement followed by a comment "# ValueError: MESSAGE" must raise it.
What is not run, and why, is listed in OPT_IN (root, MPI, a build tree of its own, the user's
files: each has its own target), PYTHON_OPT_IN (minutes of CPU) and NOT_RUNNABLE (fragments of a
larger file). The CLI's fits run (about 10 s each on 2 cores)."""
import ast
import os
import re
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CLI = os.path.abspath(os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce")))
BUILD = os.path.dirname(os.path.dirname(CLI))
PAGES = ["README.md"] + sorted("docs/" + f for f in os.listdir(os.path.join(ROOT, "docs")) if f.endswith(".md"))

# Lines left to their own targets: what each needs that a test run does not have.
OPT_IN = {
    "make": "builds and installs (`make demo`, `make test`, `make lammps`: the commands themselves)",
    "cmake": "configures another build tree (make test-sanitize, make lammps)",
    "mpirun": "MPI ranks and a manifest of the user's files (tests/python/test_fit_batch.py runs batches)",
    "bounce fit --batch": "a manifest of the user's files (tests/python/test_fit_batch.py runs batches)",
    "venv": "a virtual environment and pip (make check-pip)",
    "pip": "a virtual environment and pip (make check-pip)",
    "fuzz": "the sanitizer build (make fuzz)",
    "build-asan": "the sanitizer build (make test-sanitize)",
}
# Python statements left out: the fit's full grid and the posterior's chain cost minutes in Python
# (tests/python/test_fit.py and test_posterior.py run them on small grids); the statements that
# use their result go with them.
PYTHON_OPT_IN = ("bounce.fit(", "bounce.posterior(")
NOT_RUNNABLE = {"lammps", "toml", "cpp", "text"}  # input-file fragments; C++ in tests/cpp (FrontDoor.*)


def blocks(page):
    """(line number, language, text) of each fenced block of a page."""
    text = open(os.path.join(ROOT, page)).read()
    for m in re.finditer(r"^```(\w*)\n(.*?)^```", text, re.S | re.M):
        yield text.count("\n", 0, m.start()) + 1, m.group(1), m.group(2)


def commands(text):
    """The block's lines with continuations joined, comments and blank lines dropped."""
    out, pending = [], ""
    for raw in text.splitlines():
        line = pending + raw.strip()
        if line.endswith("\\"):
            pending = line[:-1] + " "
            continue
        pending = ""
        line = re.sub(r"\s+#\s.*$", "", line).strip()
        if line and not line.startswith("#"):
            out.append(line)
    return out


def opt_in(line):
    return next((why for key, why in OPT_IN.items() if re.search(r"(^|\s|/)" + re.escape(key), line)), None)


def runs_bounce(line):
    return re.match(r"^(build/bin/)?bounce\s", line) or "-m bounce." in line


def cases():
    for page in PAGES:
        for line, language, text in blocks(page):
            if language in ("sh", "") and not text.lstrip().startswith("$ "):
                lines = [c for c in commands(text) if runs_bounce(c) or opt_in(c)]
                if lines:
                    yield pytest.param("shell", lines, id=f"{page}:{line}")
            elif language in ("sh", "text") and "$ " in text:
                yield pytest.param("transcript", text, id=f"{page}:{line}")
            elif language == "python":
                yield pytest.param("python", text, id=f"{page}:{line}")


@pytest.fixture
def folder(tmp_path):
    os.symlink(BUILD, tmp_path / "build")
    os.symlink(os.path.join(ROOT, "data"), tmp_path / "data")
    return tmp_path


def shell(line, folder):
    env = dict(os.environ, PATH=os.path.dirname(CLI) + os.pathsep + os.environ["PATH"], MPLBACKEND="Agg")
    return subprocess.run(["bash", "-c", "set -o pipefail; " + line], cwd=folder, env=env, capture_output=True,
                          text=True, timeout=600)


def matches(shown, got):
    """A shown line against an output line: "…" and "..." stand for anything."""
    pattern = ".*".join(re.escape(part) for part in re.split(r"…|\.\.\.", shown.strip()))
    return re.fullmatch(pattern, got.strip()) is not None


def check_transcript(text, folder):
    parts = re.split(r"^\$ ", text, flags=re.M)[1:]
    for part in parts:
        command, *shown = part.rstrip("\n").split("\n")
        if not runs_bounce(command) or opt_in(command):
            continue
        done = shell(command, folder)
        output = (done.stdout + done.stderr).splitlines()
        if shown and shown[0].startswith("bounce: error:"):
            assert done.returncode == 2, (command, done.returncode, done.stderr)
        else:
            assert done.returncode == 0, (command, done.stderr)
        at = 0
        for want in shown:
            while at < len(output) and not matches(want, output[at]):
                at += 1
            assert at < len(output), f"{command}: the page shows\n  {want}\nwhich is not in its output:\n" + "\n".join(
                output)
            at += 1


def check_python(text, folder, namespace):
    tree = ast.parse(text)
    source = text.splitlines()
    left_out = set()  # names bound by statements left out
    for statement in tree.body:
        code = ast.get_source_segment(text, statement)
        names = {n.id for n in ast.walk(statement) if isinstance(n, ast.Name)}
        if any(key in code for key in PYTHON_OPT_IN) or names & left_out:
            left_out |= {n.id for n in ast.walk(statement) if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Store)}
            continue
        after = source[statement.end_lineno] if statement.end_lineno < len(source) else ""
        expected = re.match(r"\s*# ValueError: (.*)", after)
        previous = os.getcwd()
        os.chdir(folder)
        try:
            if expected:
                with pytest.raises(ValueError) as error:
                    exec(compile(ast.Module([statement], []), "<docs>", "exec"), namespace)
                assert matches(expected.group(1), str(error.value)), (code, str(error.value))
            else:
                exec(compile(ast.Module([statement], []), "<docs>", "exec"), namespace)
        finally:
            os.chdir(previous)


NAMESPACES = {}


@pytest.mark.parametrize("kind,content", list(cases()))
def test_example_runs_as_written(kind, content, folder, request):
    if kind == "shell":
        for line in content:
            if opt_in(line):
                continue
            done = shell(line, folder)
            assert done.returncode == 0, (line, done.stderr[-2000:])
    elif kind == "transcript":
        check_transcript(content, folder)
    else:
        import matplotlib
        matplotlib.use("Agg")
        page = request.node.callspec.id.split(":")[0]
        check_python(content, folder, NAMESPACES.setdefault(page, {}))


def test_what_is_left_out_is_said():
    """Every block is run, or its language says why not (NOT_RUNNABLE), or its lines are OPT_IN."""
    for page in PAGES:
        for line, language, text in blocks(page):
            if language in NOT_RUNNABLE or language in ("sh", "", "python"):
                continue
            pytest.fail(f"{page}:{line}: a ```{language} block that is neither run nor said to be left out")
