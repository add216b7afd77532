"""`make demo`'s report sections that read CLI records (scripts/demo.py), run as the demo runs them:
`make demo` itself takes minutes and is not part of `make test`, so a record's change (issue 40
point 3 made a sticking collision's contact_time null) broke it unseen until `make check-debian13`.
The static-contact, viscoelastic and adhesive sections take a few seconds; the figures, fits and
atlas are the demo's own (their Python is tested by the tests of bounce.plot, fit and atlas).
"""
import importlib.util
import os
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("BOUNCE_CLI", str(ROOT / "build" / "bin" / "bounce"))


def load_demo():
    spec = importlib.util.spec_from_file_location("bounce_demo", ROOT / "scripts" / "demo.py")
    demo = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(demo)
    return demo


def test_the_report_sections_that_read_records_run(tmp_path):
    demo = load_demo()
    runner = demo.Runner(pathlib.Path(CLI))
    lines = demo.contact_section(runner) + demo.viscoelastic_section(runner, tmp_path)
    adhesive = demo.adhesive_section(runner, tmp_path)
    # K13's sticking row: no contact time, said in words; every other row has one.
    assert any("| 0.088 | 2 | stick |" in line and "none (sticks)" in line for line in adhesive), adhesive
    assert not any("None" in line or "nan" in line for line in lines + adhesive)
