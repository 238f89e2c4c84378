#!/usr/bin/env python3
"""A rosette with mirrors must have its centre filled, as an artist fills it first:
    centre_case.py PROGRAM WORKDIR CX,CY MAX ARGS...
runs PROGRAM ARGS --json WORKDIR/tree.json -o WORKDIR/out.svg and fails (exit 1) when no
element other than a seed comes within MAX of the centre (CX, CY) (curves sampled)."""
import math
import sys

from grown_tree import grown_elements


def bezier_at(c, t):
    u = 1 - t
    return [u * u * u * c[0][k] + 3 * u * u * t * c[1][k] + 3 * u * t * t * c[2][k] +
            t * t * t * c[3][k] for k in (0, 1)]


def segment_distance(p, a, b):
    ax, ay = b[0] - a[0], b[1] - a[1]
    length2 = ax * ax + ay * ay
    t = 0 if length2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) /
                                              length2))
    return math.dist(p, (a[0] + t * ax, a[1] + t * ay))


def distance(p, proxy):
    kind = proxy["kind"]
    if kind == "circle":
        return max(0.0, math.dist(p, proxy["center"]) - proxy["radius"])
    if kind == "linesegment":
        return segment_distance(p, proxy["p0"], proxy["p1"])
    if kind == "bezier":
        return min(math.dist(p, bezier_at(proxy["c"], i / 200)) for i in range(201))
    if kind == "point":
        return math.dist(p, proxy["point"])
    if kind == "arc":
        return max(0.0, abs(math.dist(p, proxy["center"]) - proxy["radius"]))
    if kind == "polygon":
        pts = proxy["points"]
        return min(segment_distance(p, pts[k], pts[(k + 1) % len(pts)]) for k in range(len(pts)))
    return math.inf


def main():
    program, work, centre, most, args = (sys.argv[1], sys.argv[2], sys.argv[3],
                                          float(sys.argv[4]), sys.argv[5:])
    c = tuple(float(v) for v in centre.split(","))
    elements = grown_elements(program, work, args)
    if elements is None:
        return 1
    nearest, what = math.inf, None
    for e in elements:
        if e["type"] == "seed":
            continue
        for proxy in e["proxies"]:
            d = distance(c, proxy)
            if d < nearest:
                nearest, what = d, e["type"]
    print(f"nearest element to the centre: {what} at {nearest:.3f} (at most {most})")
    if nearest > most:
        print("FAULT: the rosette's centre is left empty")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
