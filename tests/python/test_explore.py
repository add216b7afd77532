"""`make explore` (tools/explore.py, docs/explorer.md): serves a built explorer folder and prints its
address; bad options are refused by bounce's one rule with exit 2."""
import os
import subprocess
import sys
import urllib.request

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
EXPLORE = os.path.join(ROOT, "tools", "explore.py")


def run(*args):
    return subprocess.run([sys.executable, EXPLORE, *args], capture_output=True, text=True, timeout=30)


@pytest.mark.parametrize("args, message", [
    (["--port", "70000"], "bounce: error: --port = 70000 is invalid: expected a TCP port, a whole number 0 <= port <= 65535"),
    (["--port", "eighty"], "bounce: error: --port = eighty is invalid: expected a TCP port"),
    (["--dir", "/nonexistent"], "bounce: error: --dir = /nonexistent is invalid: expected a folder holding the built explorer"),
    (["--prot", "8000"], "bounce: error: --prot = (given) is invalid: expected one of --dir, --port, --host"),
    (["--port"], "bounce: error: --port = (no value) is invalid: expected a value after it"),
])
def test_bad_options_exit_2_with_the_message(args, message):
    out = run(*args)
    assert out.returncode == 2
    assert out.stderr.startswith(message)


def test_serves_the_folder_and_prints_the_address(tmp_path):
    (tmp_path / "index.html").write_text("<!doctype html><title>explorer</title>")
    server = subprocess.Popen([sys.executable, EXPLORE, "--dir", str(tmp_path), "--port", "0"],
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        line = server.stdout.readline()
        assert line.startswith("bounce explorer: http://127.0.0.1:")
        address = line.split()[2]
        with urllib.request.urlopen(address + "index.html", timeout=10) as reply:
            assert b"<title>explorer</title>" in reply.read()
    finally:
        server.terminate()
        server.wait(timeout=10)
