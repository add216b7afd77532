#!/usr/bin/python3
"""Serves the browser explorer (docs/explorer.md; `make explore`) on this machine and prints its
address. The page is static (out/explorer/, built by `make explorer`): any static host serves it as
well, and it also opens from file:// with no server at all.

    /usr/bin/python3 tools/explore.py [--dir out/explorer] [--port 8000] [--host 127.0.0.1]

Bad input is refused by bounce's one rule: `bounce: error: --port = 70000 is invalid: expected
...`, exit 2.
"""
import functools
import http.server
import os
import socket
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULTS = {"--dir": os.path.join(HERE, "..", "out", "explorer"), "--port": "8000", "--host": "127.0.0.1"}


def refuse(name, value, allowed):
    """bounce's message for bad input (docs/cli.md), and exit 2."""
    print(f"bounce: error: {name} = {value if value != '' else chr(34) * 2} is invalid: expected {allowed}", file=sys.stderr)
    sys.exit(2)


def parse(argv):
    """The options, each checked: --dir a built page, --port 1..65535 (0: any free port)."""
    given = dict(DEFAULTS)
    i = 0
    while i < len(argv):
        name = argv[i]
        if name not in DEFAULTS:
            refuse(name, "(given)", "one of --dir, --port, --host (`make explore`, docs/explorer.md)")
        if i + 1 >= len(argv):
            refuse(name, "(no value)", "a value after it")
        given[name] = argv[i + 1]
        i += 2
    port = given["--port"]
    if not port.isdigit() or int(port) > 65535:
        refuse("--port", port, "a TCP port, a whole number 0 <= port <= 65535 (0: any free port)")
    if not os.path.isfile(os.path.join(given["--dir"], "index.html")):
        refuse("--dir", given["--dir"], "a folder holding the built explorer (index.html): run `make explorer`")
    return given["--dir"], int(port), given["--host"]


def main():
    folder, port, host = parse(sys.argv[1:])
    handler = functools.partial(http.server.SimpleHTTPRequestHandler, directory=folder)
    try:
        server = http.server.ThreadingHTTPServer((host, port), handler)
    except socket.gaierror:
        refuse("--host", host, "a name or address of this machine (127.0.0.1: only this machine)")
    except OSError as e:
        refuse("--port", str(port), f"a port free on {host} ({e.strerror})")
    print(f"bounce explorer: http://{host}:{server.server_address[1]}/ (Ctrl-C stops it)", flush=True)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        pass


if __name__ == "__main__":
    main()
