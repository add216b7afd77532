"""Reliability round 2 (docs/cli.md "Memory", docs/fitting.md "The data"): memory flat in the number
of output rows, Ctrl-C keeping the rows written (exit 130), Python's fit interrupted within a
collision, data files as spreadsheets write them, and plots with legends and units.
"""
import json
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import bounce
import bounce.plot

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
CURVE = [CLI, "curve", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--csv"]


def peak_rss_mb(args, stdout):
    """The peak resident memory [MB] of the CLI run with `args` (os.wait4's ru_maxrss, in KB on Linux)."""
    p = subprocess.Popen(args, stdout=stdout, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    assert p.returncode == 0, args
    return usage.ru_maxrss / 1024.0


def test_curve_memory_is_flat_in_the_number_of_rows(tmp_path):
    """docs/cli.md, "Memory": 2e5 rows cost what 1e3 rows cost, within 100 MB (it was ~4.4 KB a row)."""
    with open(tmp_path / "small.csv", "w") as small, open(tmp_path / "large.csv", "w") as large:
        small_mb = peak_rss_mb(CURVE + ["--velocities", "1:10:1000"], small)
        large_mb = peak_rss_mb(CURVE + ["--velocities", "1:10:200000"], large)
    assert sum(1 for _ in open(tmp_path / "large.csv")) == 200_001
    assert large_mb - small_mb < 100.0, (small_mb, large_mb)


def test_curve_json_memory_is_flat_too(tmp_path):
    with open(tmp_path / "small.json", "w") as small, open(tmp_path / "large.json", "w") as large:
        small_mb = peak_rss_mb(CURVE[:-1] + ["--json", "--velocities", "1:10:1000"], small)
        large_mb = peak_rss_mb(CURVE[:-1] + ["--json", "--velocities", "1:10:100000"], large)
    assert len(json.load(open(tmp_path / "large.json"))["points"]) == 100_000
    assert large_mb - small_mb < 100.0, (small_mb, large_mb)


def test_sigint_keeps_the_rows_written_and_exits_130(tmp_path):
    out = tmp_path / "rows.csv"
    with open(out, "w") as f:
        p = subprocess.Popen(CURVE + ["--velocities", "1:10:5000000"], stdout=f, stderr=subprocess.PIPE, text=True)
        deadline = time.monotonic() + 30.0
        while os.path.getsize(out) < 10_000 and time.monotonic() < deadline:
            time.sleep(0.05)
        p.send_signal(signal.SIGINT)
        _, err = p.communicate(timeout=30)
    assert p.returncode == 130, err
    assert "interrupted" in err
    lines = out.read_text().splitlines(keepends=True)
    assert lines[0].startswith("velocity,cor,outcome")
    assert len(lines) > 100 and all(line.endswith("\n") for line in lines)  # whole rows only
    assert float(lines[-1].split(",")[0]) > 1.0


def test_python_fit_stops_within_a_collision_on_ctrl_c():
    """Row 12: bounce.fit raised KeyboardInterrupt ~10 s after Ctrl-C; now within a collision."""
    pair = bounce.Pair(material="psl", radius=0.635e-6, wall=True, material2="quartz")
    data = os.path.join(ROOT, "data", "experiments", "synthetic-psl-quartz.csv")
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    sent = []
    timer = threading.Timer(0.5, lambda: (sent.append(time.monotonic()), os.kill(os.getpid(), signal.SIGINT)))
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            bounce.fit(pair, bounce.Model("krijt"), data=data, threads=1,
                       grid={"gamma": (0.01, 0.2, 30), "tvis": (1e-13, 1e-10, 30), "yield": (1e7, 1e10, 10)})
        assert time.monotonic() - sent[0] < 0.5
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)


def test_python_fit_reads_mapped_columns(tmp_path):
    path = tmp_path / "excel.csv"
    path.write_bytes("\ufeffSpeed [m/s];e\n0,01;0,9\n0,1;0,8\n1;0,6\n".encode("utf-8"))
    pair, model = bounce.Pair(material="ice-bshp96", radius=0.01), bounce.Model("viscoelastic")
    kw = dict(fit="A", grid={"A": (1e-8, 1e-4, 5)}, grid_only=True)
    mapped = bounce.fit(pair, model, data=str(path), columns={"velocity": "Speed", "cor": "e"}, **kw)
    arrays = bounce.fit(pair, model, [0.01, 0.1, 1.0], [0.9, 0.8, 0.6], **kw)
    assert mapped["chi2"] == arrays["chi2"]
    with pytest.raises(ValueError, match="columns = speed=v is invalid"):
        bounce.fit(pair, model, data=str(path), columns="speed=v", **kw)
    with pytest.raises(TypeError, match="columns"):
        bounce.fit(pair, model, data=str(path), columns=3, **kw)


def test_energy_budget_has_a_legend_and_chi2_map_units():
    """Row 14: five labelled curves without a legend; chi^2 axes without units."""
    ax = bounce.plot.energy_budget(bounce.Pair(material="water-ice", radius=1e-6), bounce.Model("krijt", tvis=1e-11),
                                   8.0, points=100)
    assert ax.get_legend() is not None and len(ax.get_legend().get_texts()) == 5
    v = np.geomspace(0.01, 3.0, 8)
    pair = bounce.Pair(material="ice-bshp96", radius=0.01)
    e = bounce.curve(pair, bounce.Model("viscoelastic", A=2e-6), v)["cor"]
    r = bounce.fit(pair, bounce.Model("viscoelastic"), v, e, fit=["A", "yield"],
                   grid={"A": (1e-8, 1e-4, 9), "yield": (1e7, 1e11, 9)})
    ax = bounce.plot.chi2_map(r, "A", "yield")
    assert ax.get_xlabel() == "A [s]" and ax.get_ylabel() == "yield [Pa]"


def test_readme_command_lines_run_as_written():
    """Row 20: `[--compare]` copied from the README was refused; its command lines hold no brackets."""
    lines = [line for line in open(os.path.join(ROOT, "README.md")) if "bin/bounce " in line or line.startswith("    --")]
    assert lines
    for line in lines:
        code = line.split("  #", 1)[0]
        assert "[--" not in code and "]" not in code, line
