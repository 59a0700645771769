#!/usr/bin/env python3
"""Evaluate a bicubic patch whose u = 0 edge is collapsed to one point (like the top of the Utah
teapot's lid): positions, unit normals and their kinds at a few points, scattered and on a grid.

The Python twin of examples/eval_demo.c. Run with the library on the search path, or with
BEZSURF_LIBRARY=build/lib/libbezsurf.so.1 PYTHONPATH=bindings/python python3 examples/python/eval_demo.py
"""

import sys

import bezsurf

KIND_NAMES = {bezsurf.NORMAL_REGULAR: "regular", bezsurf.NORMAL_LIMIT: "limit",
              bezsurf.NORMAL_UNDEFINED: "undefined"}


def dome() -> bezsurf.Patch:
    """Row i = 0 is the apex (0, 0, 1); the other rows spread out into a dome."""
    r = [0.0, 0.6, 1.0, 1.2]
    z = [1.0, 1.0, 0.6, 0.0]
    x = [1.0, 1.0, 0.55, 0.0]   # a quarter circle
    y = [0.0, 0.55, 1.0, 1.0]
    return bezsurf.Patch([[(r[i] * x[j], r[i] * y[j], z[i]) for j in range(4)] for i in range(4)])


def main() -> int:
    try:
        patch = dome()
        u = [0.0, 0.0, 0.5, 1.0, 0.25]
        v = [0.0, 0.5, 0.5, 1.0, 0.75]
        res = patch.eval_normal(u, v)
        print(f"libbezsurf {bezsurf.version()}: bicubic patch with its u = 0 edge collapsed to a point")
        print("    u     v   |  position                 |  unit normal                 kind")
        for uk, vk, p, n, k in zip(u, v, res.position, res.normal, res.kind):
            print(f"{uk:5.2f} {vk:5.2f} | {p[0]:7.4f} {p[1]:7.4f} {p[2]:7.4f} | "
                  f"{n[0]:8.5f} {n[1]:8.5f} {n[2]:8.5f}  {KIND_NAMES[k]}")

        # a 3 x 3 grid: only the points on u = 0 take the limit rule
        g = [0.0, 0.5, 1.0]
        kinds = patch.eval_grid(g, g, normals=True).kind
        print("grid normal kinds (rows u = 0, 0.5, 1):")
        for a in range(3):
            print("  " + " ".join(f"{KIND_NAMES[k]:<9}" for k in kinds[3 * a:3 * a + 3]))
    except bezsurf.BezsurfError as e:
        print(e, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
