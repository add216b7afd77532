"""The CLI's outputs for the fixed calls of tests/golden/calls.txt, as recorded.

The record was taken before the architecture change (docs/architecture.md) and is updated only with a
change that is listed and justified (docs/architecture.md, "Behaviour kept"). Text must
match exactly; numbers to a relative 1e-9: the same code on another x86-64 machine may take
another path through glibc's libm (FMA variants), and adaptive integration turns a last-bit
difference into ~1e-12 relative; 1e-9 leaves room and still catches a change of the physics,
of a default or of a tolerance (those move results by 1e-8 or more). The viscoelastic series
fitted at build time are the exception: their inputs' last bits follow the CPU's x87
instructions, and the fits amplify them to 3e-9 (coefficients) and 5e-5 (their spreads); they
are compared to 1e-6 and 1e-2 (tests/golden/golden.py, FITTED).
"""
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "golden"))
import golden  # noqa: E402

BUILD = os.path.dirname(os.path.dirname(os.environ.get("BOUNCE_CLI", "build/bin/bounce")))


@pytest.mark.parametrize("name,args,stdin", golden.calls(), ids=[c[0] for c in golden.calls()])
def test_call_as_recorded(name, args, stdin):
    with open(golden.expected_path(name)) as f:
        want = f.read()
    got = golden.run(BUILD, args, stdin)
    d = golden.difference(got, want, 1e-9)
    assert d is None, d
