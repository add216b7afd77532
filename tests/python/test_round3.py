"""Issue 40, round 3 of what a new user trips over (docs/hardening.md, "round 3"): a closed pipe
where SIGPIPE is ignored is a normal end (point 8), Ctrl-C on a curve's JSON leaves a valid
document (point 8), closed forms beyond their validity are None (point A1).
"""
import json
import os
import signal
import subprocess
import time

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
CLI = os.environ.get("BOUNCE_CLI", os.path.join(ROOT, "build", "bin", "bounce"))
# Master-curve points take microseconds; 1e5 rows (~6 MB) are far more than a pipe holds (64 KB),
# so the writer is still writing when the reader goes away, however fast the machine.
CURVE = [CLI, "curve", "--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--velocities", "1:10:100000"]


def test_closed_pipe_is_a_normal_end_where_sigpipe_is_ignored_in_the_shell():
    """`trap '' PIPE; bounce curve ... --csv | head -2`: main ended in exit 3, "could not write the results"."""
    script = "trap '' PIPE; \"$@\" 2>\"$ERR\" | head -2 >/dev/null; exit ${PIPESTATUS[0]}"
    err = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"bounce-pipe-{os.getpid()}.err")
    try:
        done = subprocess.run(["bash", "-c", script, "bash"] + CURVE + ["--csv"], env=dict(os.environ, ERR=err),
                              timeout=120)
        with open(err) as f:
            message = f.read()
    finally:
        if os.path.exists(err):
            os.remove(err)
    assert done.returncode == 0, message
    assert message == ""


def test_closed_pipe_is_a_normal_end_for_a_parent_that_ignores_sigpipe():
    """Python ignores SIGPIPE; with restore_signals=False its child inherits that (runners do the same)."""
    for form in ("--csv", "--json"):
        p = subprocess.Popen(CURVE + [form], stdout=subprocess.PIPE, stderr=subprocess.PIPE, restore_signals=False)
        p.stdout.readline()
        p.stdout.readline()
        p.stdout.close()
        err = p.stderr.read()
        p.wait(timeout=120)
        assert p.returncode == 0, (form, err)
        assert err == b"", form


def test_sigint_on_curve_json_prints_a_valid_partial_document(tmp_path):
    """Main left nothing on stdout while its message said the output so far was kept."""
    out = tmp_path / "curve.json"
    with open(out, "w") as f:
        p = subprocess.Popen(CURVE[:-1] + ["1:10:5000000", "--json", "--progress"], stdout=f,
                             stderr=subprocess.PIPE, text=True)
        first = p.stderr.readline()  # a progress line: the first points are computed
        assert first.startswith("bounce curve:"), first
        time.sleep(0.2)
        p.send_signal(signal.SIGINT)
        _, err = p.communicate(timeout=60)
    assert p.returncode == 130, err
    assert "printed as a whole JSON document" in err
    doc = json.loads(out.read_text())
    assert doc["boundaries"] is None
    assert "SIGINT" in doc["interrupted"]
    assert 1 <= len(doc["points"]) < 5_000_000
    assert str(len(doc["points"])) in doc["interrupted"]
    velocities = [point["velocity"] for point in doc["points"]]
    assert velocities == sorted(velocities) and velocities[0] == 1.0


def test_closed_forms_beyond_their_validity_are_none_in_python():
    """A1: K13 (26)-(27) gave e_d = -1.71 and e_i = 1.39 for 0.1 um ice grains at 10 m/s (5.57 A/t_H = 2.7)."""
    import math

    import bounce
    pair, model = bounce.Pair(material="water-ice", radius=5e-8), bounce.Model("krijt", tvis=1e-11)
    one = bounce.closed_forms(pair, model, 10.0)
    assert one["e_d"] is None and one["e_i"] is None
    assert "5.57 A/t_H <= 1" in one["warnings"][0]
    assert bounce.collide(pair, model, 10.0)["closed_forms"]["e_d"] is None
    many = bounce.closed_forms(pair, model, [10.0, 1e-3])  # a column: NaN where null
    assert math.isnan(many["e_d"][0]) and math.isnan(many["e_i"][0])
    assert "warnings" not in many
    valid = bounce.closed_forms(bounce.Pair(material="water-ice", radius=1e-6), model, 8.0)
    assert 0.0 <= valid["e_d"] <= 1.0 and 0.0 <= valid["e_i"] <= 1.0 and "warnings" not in valid
    csv = subprocess.run([CLI, "curve", "--material", "quartz", "--radius", "1e-8", "--model", "krijt", "--tvis", "1e-8",
                          "--velocities", "0.001:2900:5", "--log", "--closed-forms", "--csv"],
                         capture_output=True, text=True, check=True)
    rows = [line.split(",") for line in csv.stdout.splitlines()]
    e_d, e_i = rows[0].index("e_d"), rows[0].index("e_i")
    assert all(row[e_d] == "" and row[e_i] == "" for row in rows[1:])  # main: -7.1e3 to -1.4e5, 7.1e3 to 1.4e5
    assert "5.57 A/t_H <= 1" in csv.stderr
