"""Regenerate the papers' figures (docs/figures.md) as PNG and SVG.

    PYTHONPATH=build/python /usr/bin/python3 -m bounce.figures --out out/figures
    ... --only k13-fig4 bp04-fig8-2      # a subset
    ... --quick                          # coarse grids (seconds, for tests)

Each figure is computed from the library (bounce.plot); progress goes to stdout.
"""

from __future__ import annotations

import argparse
import pathlib
import sys
import time
from typing import Callable, Iterable

import matplotlib

matplotlib.use("Agg")

from . import plot  # noqa: E402  (after choosing the backend)


def write_figures(out: pathlib.Path, names: Iterable[str] | None = None, quick: bool = False,
                  progress: Callable[[str], None] = print, dpi: int = 150) -> list[pathlib.Path]:
    """Write each named figure (all of plot.FIGURES by default) as out/NAME.png and out/NAME.svg."""
    selected = list(plot.FIGURES) if names is None else list(names)
    unknown = [n for n in selected if n not in plot.FIGURES]
    if unknown:
        raise ValueError(f"figure = {unknown[0]} is invalid: expected one of {', '.join(plot.FIGURES)}")
    out.mkdir(parents=True, exist_ok=True)
    written = []
    start = time.monotonic()
    for i, name in enumerate(selected, 1):
        progress(f"[figures {time.monotonic() - start:6.1f}s] {i}/{len(selected)} {name}")
        fig = plot.FIGURES[name](quick=quick)
        for suffix in (".png", ".svg"):
            path = out / f"{name}{suffix}"
            fig.savefig(path, dpi=dpi)
            written.append(path)
    progress(f"[figures {time.monotonic() - start:6.1f}s] wrote {len(written)} files to {out}/")
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m bounce.figures", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="out/figures", help="output directory (default: out/figures)")
    parser.add_argument("--only", nargs="+", metavar="NAME", help=f"a subset of: {', '.join(plot.FIGURES)}")
    parser.add_argument("--quick", action="store_true", help="coarse grids (for tests)")
    args = parser.parse_args(argv)
    try:
        write_figures(pathlib.Path(args.out), args.only, args.quick, lambda s: print(s, flush=True))
    except ValueError as e:
        print(f"bounce.figures: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
