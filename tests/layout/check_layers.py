#!/usr/bin/env python3
"""The layers of lib/ (docs/architecture.md), checked from the sources:

  core <- ops <- surface <- bspline, continuity, mesh, query <- model <- io

- every .c and .h of lib/ is in a layer's folder;
- a quoted include names a header of the file's own folder, a lower layer's header
  ("core/internal.h"), or the public "bezsurf.h"; never a layer above or beside its own;
- the headers of one folder do not include each other in a circle;
- no file of lib/ is over 500 lines.

    check_layers.py LIBDIR
"""
import os
import re
import sys

RANK = {"core": 0, "ops": 1, "surface": 2, "bspline": 3, "continuity": 3, "mesh": 3, "query": 3,
        "model": 4, "io": 5}
MAX_LINES = 500
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def main(libdir):
    problems = []
    headers = {}  # "layer/name.h" -> the quoted includes it resolves to
    for dirpath, _, files in os.walk(libdir):
        for name in sorted(files):
            if not name.endswith((".c", ".h")):
                continue
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, libdir)
            parts = rel.split(os.sep)
            if len(parts) != 2 or parts[0] not in RANK:
                problems.append(f"{rel}: not in a layer folder ({', '.join(sorted(RANK))})")
                continue
            layer = parts[0]
            with open(path, encoding="utf-8") as f:
                text = f.read()
            nlines = text.count("\n")
            if nlines > MAX_LINES:
                problems.append(f"{rel}: {nlines} lines (at most {MAX_LINES})")
            resolved = []
            for inc in INCLUDE.findall(text):
                if inc == "bezsurf.h":
                    continue
                if "/" not in inc:
                    target = f"{layer}/{inc}"
                else:
                    target = inc
                top = target.split("/")[0]
                if top not in RANK or not os.path.exists(os.path.join(libdir, target)):
                    problems.append(f'{rel}: includes "{inc}", which is not a header of lib/')
                    continue
                if top != layer and RANK[top] >= RANK[layer]:
                    problems.append(f'{rel}: includes "{inc}": layer {top} is not below {layer}')
                resolved.append(target)
            if name.endswith(".h"):
                headers[f"{layer}/{name}"] = resolved
    problems += circles(headers)
    for p in problems:
        print(p)
    print(f"layers: {len(problems)} problem(s)")
    return 1 if problems else 0


def circles(headers):
    """Include circles among the headers, each reported once by its path."""
    found, state = [], {}

    def visit(h, stack):
        state[h] = "open"
        for nxt in headers.get(h, []):
            if state.get(nxt) == "open":
                cycle = stack[stack.index(nxt):] + [nxt]
                found.append("include circle: " + " -> ".join(cycle))
            elif nxt not in state:
                visit(nxt, stack + [nxt])
        state[h] = "done"

    for h in sorted(headers):
        if h not in state:
            visit(h, [h])
    return found


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
