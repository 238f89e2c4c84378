#!/usr/bin/env python3
"""The dots pattern (Appendix A) over built-in regions: no two dots overlap (touching within a
small tolerance allowed) and no dot leaves the region."""
import json
import math
import os
import subprocess
import sys

program, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
TOL = 1e-6

def inside(region, x, y, r):
    kind, size = region.split(":")
    v = [float(s) for s in size.split(",")]
    if kind == "rect":
        return x - r >= -TOL and y - r >= -TOL and x + r <= v[0] + TOL and y + r <= v[1] + TOL
    if kind == "circle":
        return math.hypot(x - v[0], y - v[0]) + r <= v[0] + TOL
    raise ValueError(region)

bad = []
for region, seeds in [("rect:120,80", []), ("circle:50", []), ("rect:200,60", ["10,30", "190,30"])]:
    tree = os.path.join(work, region.replace(":", "-").replace(",", "x") + ".json")
    cmd = [program, "--region", region, "--rng-seed", "1", "--quiet", "--json", tree, "-o",
           tree[:-5] + ".svg"]
    for s in seeds:
        cmd += ["--seed", s]
    subprocess.run(cmd, check=True, timeout=600)
    with open(tree) as f:
        dots = [p for e in json.load(f)["elements"] for p in e["proxies"] if p["kind"] == "circle"]
    print(f"{region}: {len(dots)} dots")
    if len(dots) < 100:
        bad.append(f"{region}: only {len(dots)} dots")
    # Grid buckets keep the pairwise check fast.
    cell, grid = 6.0, {}
    for i, d in enumerate(dots):
        (x, y), r = d["center"], d["radius"]
        if not inside(region, x, y, r):
            bad.append(f"{region}: dot {i} at ({x:.3f},{y:.3f}) r={r:.3f} leaves the region")
        grid.setdefault((int(x // cell), int(y // cell)), []).append(i)
    for i, d in enumerate(dots):
        (x, y), r = d["center"], d["radius"]
        gx, gy = int(x // cell), int(y // cell)
        for ox in (-1, 0, 1):
            for oy in (-1, 0, 1):
                for j in grid.get((gx + ox, gy + oy), []):
                    if j <= i:
                        continue
                    (u, v), s = dots[j]["center"], dots[j]["radius"]
                    if math.hypot(u - x, v - y) < r + s - 1e-4:
                        bad.append(f"{region}: dots {i} and {j} overlap")
if bad:
    print("\n".join(bad[:50]), file=sys.stderr)
    sys.exit(1)
print("no overlaps, nothing outside")
