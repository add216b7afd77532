#!/usr/bin/python3
"""Fails on any #include that runs up bounce's layer order (docs/architecture.md).

    core -> pair -> contact -> models -> dynamics -> analytic -> analysis -> api -> (apps | python)

A file belongs to the layer of its folder: include/bounce/<layer>/, src/<layer>/, apps/bounce
(the CLI) or python/src (the bindings). Every `#include "..."` is resolved: "bounce/<layer>/..."
names its layer; any other quoted include is looked up next to the including file (a private
header of the same or another layer). An edge may go to the same layer or to one below it,
never up, and the two front ends (apps, python) may not include each other.

    check_layers.py [REPO]     exit 0 and "layers: N edges, all downward", or 1 and the offending edges
"""
import os
import re
import sys

ORDER = ["core", "pair", "contact", "models", "dynamics", "analytic", "analysis", "api"]
FRONT_ENDS = {"apps": "apps/bounce", "python": "python/src"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def layer_of(repo, path):
    """The layer of a file (by its path relative to the repository), or None outside the layers."""
    rel = os.path.relpath(path, repo).replace(os.sep, "/")
    for name, folder in FRONT_ENDS.items():
        if rel.startswith(folder + "/"):
            return name
    for prefix in ("include/bounce/", "src/"):
        if rel.startswith(prefix):
            first = rel[len(prefix):].split("/")[0]
            return first if first in ORDER else None
    return None


def rank(layer):
    return len(ORDER) if layer in FRONT_ENDS else ORDER.index(layer)


def allowed(source, target):
    if source in FRONT_ENDS and target in FRONT_ENDS:
        return source == target
    return rank(target) <= rank(source)


def sources(repo):
    roots = ["include/bounce", "src"] + list(FRONT_ENDS.values())
    for root in roots:
        for folder, _, files in os.walk(os.path.join(repo, root)):
            for f in files:
                if f.endswith((".hpp", ".cpp", ".h", ".c")):
                    yield os.path.join(folder, f)


def edges(repo, path):
    """(included text, target layer) for every include of `path` that lands in a layer."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    for included in INCLUDE.findall(text):
        if included.startswith("bounce/"):
            target = os.path.join(repo, "include", included)
        else:
            target = os.path.normpath(os.path.join(os.path.dirname(path), included))
        layer = layer_of(repo, target) if os.path.exists(target) or included.startswith("bounce/") else None
        if layer is None and included.startswith("bounce/"):
            layer = included.split("/")[1]  # a header that does not exist is still an edge
        if layer is not None:
            yield included, layer


def main():
    repo = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    count, bad = 0, []
    for path in sorted(sources(repo)):
        source = layer_of(repo, path)
        if source is None:
            continue
        for included, target in edges(repo, path):
            count += 1
            if target not in ORDER and target not in FRONT_ENDS:
                bad.append(f"{os.path.relpath(path, repo)}: \"{included}\" is in no layer ({target})")
            elif not allowed(source, target):
                bad.append(f"{os.path.relpath(path, repo)} ({source}) includes \"{included}\" ({target}): up the layers")
    if bad:
        print("\n".join(bad))
        print(f"layers: {len(bad)} of {count} edges run up the order {' -> '.join(ORDER)}")
        return 1
    print(f"layers: {count} edges, all downward ({' -> '.join(ORDER)} -> apps | python)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
