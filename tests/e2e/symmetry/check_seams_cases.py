"""check_seams on synthetic wallpaper trees: it accepts periodic tiles (a square and an oblique
one, with and without the translates across the edges in the tree) and refuses a tile whose
dots overlap their neighbours' across a seam and one with an empty strip along the seams.

usage: check_seams_cases.py CHECK_SEAMS WORKDIR
"""
import json
import math
import os
import subprocess
import sys


def tree(dots):
    return {"elements": [{"id": k, "type": "dot", "parent": None, "depth": 0,
                          "proxies": [{"kind": "circle", "center": [x, y], "radius": r}]}
                         for k, (x, y, r) in enumerate(dots)]}


def lattice(a, b, n, radius, jitter=0.0, inset=0.0, translates=False):
    """Dots at the points (i + 1/2) / n of the tile (u, v), optionally moved by `jitter` along a
    fixed pattern, only those at least `inset` (fractional) from the edges; with `translates`,
    also their copies one tile over that reach into the tile."""
    dots = []
    for j in range(n):
        for i in range(n):
            u, v = (i + 0.5) / n, (j + 0.5) / n
            if min(u, v, 1 - u, 1 - v) < inset:
                continue
            u += jitter * math.sin(7 * i + 3 * j) / n
            v += jitter * math.cos(5 * i + 11 * j) / n
            x, y = u * a[0] + v * b[0], u * a[1] + v * b[1]
            dots.append((x, y, radius))
            if translates:
                for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                    tx, ty = x + di * a[0] + dj * b[0], y + di * a[1] + dj * b[1]
                    tu, tv = u + di, v + dj
                    if -0.1 < tu < 1.1 and -0.1 < tv < 1.1:
                        dots.append((tx, ty, radius))
    return dots


def run(check, work, name, dots, tile):
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(tree(dots), f)
    r = subprocess.run([check, path, tile], capture_output=True, text=True)
    print(name, "->", r.returncode, r.stdout.strip().splitlines()[-1] if r.stdout else r.stderr)
    return r.returncode, r.stdout


def main():
    check, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    failures = []
    sq = ((100, 0), (0, 100))
    ob = ((100, 0), (100 * math.cos(math.radians(60)), 100 * math.sin(math.radians(60))))
    cases = [
        ("square", lattice(*sq, 8, 4.0), "100,100", 0, None),
        ("square-jittered", lattice(*sq, 8, 3.0, jitter=0.2), "100,100", 0, None),
        ("square-translates", lattice(*sq, 8, 4.0, translates=True), "100,100", 0, None),
        ("hexagonal", lattice(*ob, 8, 4.0, translates=True), "100,100,60", 0, None),
        # A dot at the right edge reaching into the next copy's first dot (and no other).
        ("overlap", [d for d in lattice(*sq, 8, 4.0) if d[:2] != (93.75, 43.75)]
         + [(99.5, 43.75, 3.0)], "100,100", 1, "across a seam"),
        # Nothing within a fifth of the tile of its edges: a wide empty strip on every seam.
        ("strip", lattice(*sq, 16, 1.5, inset=0.2), "100,100", 1, "gap across a seam"),
        ("strip-oblique", lattice(*ob, 16, 1.5, inset=0.2), "100,100,60", 1, "gap across a seam"),
    ]
    for name, dots, tile, expected, message in cases:
        code, out = run(check, work, name, dots, tile)
        if code != expected:
            failures.append(f"{name}: exit {code}, expected {expected}")
        elif message and message not in out:
            failures.append(f"{name}: no '{message}' in {out!r}")
    if failures:
        print("\n".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
