#!/usr/bin/python3
"""Fails on any #include that runs up bounce's layer order (docs/architecture.md).

    core -> pair -> contact -> models -> dynamics -> dem -> analytic -> analysis -> aggregate -> api -> (apps | python | lammps | explorer)

A file belongs to the layer of its folder: include/bounce/<layer>/, src/<layer>/, apps/bounce
(the CLI), python/src (the bindings) or explorer/src (the browser's binding). Every `#include "..."` and `#include <bounce/...>` is
resolved: "bounce/<layer>/..." names its layer; any other quoted include is looked up next
to the including file, then anywhere in the layer folders (a private include directory such
as src/analytic makes a bare name compile from elsewhere); one found nowhere is a system or
generated header and no edge. An edge may go to the same layer or to one below it, never
up; the front ends (apps, python, lammps, explorer) may not include each other, nor the library's private
headers under src/ (only its public include/bounce/).

    check_layers.py [REPO]     exit 0 and "layers: N edges, all downward", or 1 and the offending edges
"""
import os
import re
import sys

ORDER = ["core", "pair", "contact", "models", "dynamics", "dem", "analytic", "analysis", "aggregate", "api"]
FRONT_ENDS = {"apps": "apps/bounce", "python": "python/src", "lammps": "lammps", "explorer": "explorer/src"}
INCLUDE = re.compile(r'^\s*#\s*include\s+(?:"([^"]+)"|<(bounce/[^>]+)>)', re.M)


def layer_of(repo, path):
    """The layer of a file (by its path relative to the repository), or None outside the layers."""
    rel = os.path.relpath(path, repo).replace(os.sep, "/")
    for name, folder in FRONT_ENDS.items():
        if rel.startswith(folder + "/"):
            return name
    if rel.startswith("include/bounce/") and "/" not in rel[len("include/bounce/"):]:
        return "api"  # the plain C headers beside the layers (bounce/atlas.h): the front door's
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


def find_anywhere(repo, included):
    """A quoted include that is not next to its file: the layer folder that holds it, if any."""
    for root in ["src"] + list(FRONT_ENDS.values()):
        for folder, _, files in os.walk(os.path.join(repo, root)):
            candidate = os.path.normpath(os.path.join(folder, included))
            if os.path.exists(candidate):
                return candidate
    return None


def edges(repo, path):
    """(included text, target layer, target path) for every include of `path` that lands in a layer."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    for quoted, angled in INCLUDE.findall(text):
        included = quoted or angled
        if included.startswith("bounce/"):
            target = os.path.join(repo, "include", included)
            layer = layer_of(repo, target) or included.split("/")[1]  # a missing header is still an edge
            yield included, layer, target
            continue
        target = os.path.normpath(os.path.join(os.path.dirname(path), included))
        if not os.path.exists(target):
            target = find_anywhere(repo, included)
        layer = layer_of(repo, target) if target else None
        if layer is not None:
            yield included, layer, target


def private(repo, target):
    return os.path.relpath(target, repo).replace(os.sep, "/").startswith("src/")


def main():
    repo = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    count, bad = 0, []
    for path in sorted(sources(repo)):
        source = layer_of(repo, path)
        if source is None:
            continue
        for included, target, target_path in edges(repo, path):
            count += 1
            where = os.path.relpath(path, repo)
            if target not in ORDER and target not in FRONT_ENDS:
                bad.append(f"{where}: \"{included}\" is in no layer ({target})")
            elif not allowed(source, target):
                bad.append(f"{where} ({source}) includes \"{included}\" ({target}): up the layers")
            elif source in FRONT_ENDS and private(repo, target_path):
                bad.append(f"{where} ({source}) includes \"{included}\", a private header of the library")
    if bad:
        print("\n".join(bad))
        print(f"layers: {len(bad)} of {count} edges break the order {' -> '.join(ORDER)} -> apps | python")
        return 1
    print(f"layers: {count} edges, all downward ({' -> '.join(ORDER)} -> apps | python | lammps | explorer)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
