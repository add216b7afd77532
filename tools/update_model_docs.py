#!/usr/bin/python3
"""Rewrites the generated part of docs/models.md from the registries.

    update_model_docs.py BOUNCE_CLI [DOCS_MODELS_MD]

Between the markers `<!-- begin: bounce models --markdown -->` and `<!-- end: ... -->` the
page holds exactly what `bounce models --markdown` prints; tests/python/test_registry.py
fails when it does not (after adding a model, run this).
"""
import os
import subprocess
import sys

BEGIN = "<!-- begin: bounce models --markdown -->\n"
END = "<!-- end: bounce models --markdown -->\n"


def generated(cli):
    return subprocess.run([cli, "models", "--markdown"], check=True, capture_output=True, text=True).stdout


def section(text):
    """The generated part of the page."""
    return text.split(BEGIN, 1)[1].split(END, 1)[0]


def main():
    cli = sys.argv[1]
    path = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..", "docs", "models.md")
    with open(path) as f:
        text = f.read()
    head, rest = text.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    with open(path, "w") as f:
        f.write(head + BEGIN + generated(cli) + END + tail)


if __name__ == "__main__":
    main()
