#!/usr/bin/python3
"""Writes the Python type stubs (_bounce.pyi) from their template and the registries.

    generate_stub.py BOUNCE_CLI TEMPLATE OUTPUT

The overloads of Model.__init__ (one per model: its keyword and its parameters) and
ContactLaw.__init__ (every law's parameters) come from `bounce models --json`, so a model
added to the registry needs no edit here. Python's keyword for the parameter `yield` is
`yield_strength` (yield is a Python keyword).
"""
import json
import subprocess
import sys

KINDS = {"real": "float", "reals": "Tuple[float, float]", "text": "str", "flag": "bool"}


def keyword(name):
    return "yield_strength" if name == "yield" else name


def annotation(p):
    if p["kind"] == "choice":
        return "Literal[" + ", ".join(repr(c) for c in p["choices"]) + "]"
    return KINDS[p["kind"]]


def model_overloads(models, default="viscoelastic"):
    out = []
    for m in models:
        args = "".join(f"\n        {keyword(p['name'])}: {annotation(p)} = ...," for p in m["parameters"])
        optional = " = ..." if m["name"] == default else ""  # Model(A=...) is the default model
        out.append(f"    @overload\n    def __init__(\n        self,\n        name: Literal[{m['name']!r}]{optional},\n"
                   f"        *,{args}\n    ) -> None: ...\n")
    return "".join(out)


def law_init(laws):
    seen, args = set(), ""
    for law in laws:
        for p in law["parameters"]:
            if p["name"] not in seen:
                seen.add(p["name"])
                args += f"\n        {p['name']}: {annotation(p)} = ...,"
    names = ", ".join(repr(law["name"]) for law in laws)
    return f"    def __init__(\n        self,\n        pair: Pair,\n        law: Literal[{names}] = ...,\n        *,{args}\n    ) -> None: ..."


def main():
    cli, template, output = sys.argv[1:4]
    registry = json.loads(subprocess.run([cli, "models", "--json"], check=True, capture_output=True, text=True).stdout)
    with open(template) as f:
        text = f.read()
    text = text.replace("# @MODEL_OVERLOADS@\n", model_overloads(registry["models"]))
    text = text.replace("# @LAW_INIT@", law_init(registry["laws"]))
    with open(output, "w") as f:
        f.write(text)


if __name__ == "__main__":
    main()
