"""``bounce fit --plot FILE`` draws with this module (docs/fitting.md, "The figure"): the CLI
runs ``/usr/bin/python3 -m bounce.fit_figure FILE`` with its fit's JSON on standard input, and
this writes K13 Fig 6 (:func:`bounce.plot.fit_curve`) to FILE, its format from the extension.

``python3 -m bounce.fit_figure --check FILE`` only checks that matplotlib and this package
import and that FILE's extension is one it writes (the CLI asks before it fits).
"""
from __future__ import annotations

import json
import os
import sys

FORMATS = ("png", "svg", "pdf")


def _columns(rows: list) -> dict:
    """A table of the CLI's JSON (a list of row objects) as a dict of columns; null is None."""
    keys = rows[0].keys() if rows else ()
    return {k: [row.get(k) for row in rows] for k in keys}


def figure(result: dict):
    """The fit's figure from the dict of ``bounce fit --json`` (its tables as lists of rows)."""
    import numpy as np
    from .fit_plots import fit_curve

    result = dict(result)
    for key in ("points", "curve"):
        if isinstance(result[key], list):
            result[key] = {k: np.array([np.nan if x is None else x for x in v], dtype=object if k == "outcome" else float)
                           for k, v in _columns(result[key]).items()}
    return fit_curve(result).figure


def main(argv: list[str]) -> int:
    check = argv[:1] == ["--check"]
    args = argv[1:] if check else argv
    if len(args) != 1:
        print("usage: python3 -m bounce.fit_figure [--check] FILE.png|svg|pdf < fit.json", file=sys.stderr)
        return 2
    path = args[0]
    extension = os.path.splitext(path)[1].lstrip(".").lower()
    if extension not in FORMATS:
        print(f"plot = {path} is invalid: expected a file name ending in .png, .svg or .pdf", file=sys.stderr)
        return 2
    import matplotlib  # noqa: F401  (Debian's python3-matplotlib; the check's point)

    if check:
        return 0
    figure(json.load(sys.stdin)).savefig(path, format=extension, dpi=150)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
