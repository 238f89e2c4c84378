#!/usr/bin/env python3
"""The Chinese vase pattern's balance, measured from the element tree (--json):
- flowers keep at least 0.9 grid apart, also across the parts of a panel in several pieces
  (each part lays its own grid from its own seed);
- the filler keeps clear of the flowers: no hook or drop comes within 1 unit of a flower's rim
  (but a hook growing out of a flower, in its first half, near that flower).

usage: check_vase.py WORK PANEL... -- PROGRAM"""
import math
import os

from pattern_tree import arguments, bezier_point, finish, grow_tree

GRID = 34.0  # rules/chinese_vase.acr's default
CLEAR = 1.0

(work, *panels), command = arguments()


failures = []
for panel in panels:
    name = os.path.splitext(os.path.basename(panel))[0]
    elements = grow_tree(command, panel, work)["elements"]
    flower_elements = [e for e in elements if e["type"] == "flower"]
    flowers = [e["proxies"][0] for e in flower_elements]
    closest = min((math.dist(a["center"], b["center"]), i, j)
                  for i, a in enumerate(flowers) for j, b in enumerate(flowers) if i < j)
    if closest[0] < 0.9 * GRID:
        failures.append(f"{name}: flowers {closest[1]} and {closest[2]} are "
                        f"{closest[0] / GRID:.2f} grid apart")
    parts = {e["fields"].get("part", 0) for e in elements if e["type"] == "flower"}
    nearest = math.inf
    for e in elements:
        if e["type"] == "hook":
            c = e["proxies"][0]["c"]
            points = [bezier_point(c, k / 16) for k in range(17)]
            reach = 0.0
        elif e["type"] == "drop":
            points = [e["proxies"][0]["center"]]
            reach = e["proxies"][0]["radius"]
        else:
            continue
        for fe, f in zip(flower_elements, flowers):
            grows_out = e["type"] == "hook" and e["parent"] == fe["id"]
            for p in points[8:] if grows_out else points:
                nearest = min(nearest, math.dist(p, f["center"]) - f["radius"] - reach)
    if nearest < CLEAR:
        failures.append(f"{name}: the filler comes {nearest:.2f} units from a flower's rim")
    print(f"{name}: {len(flowers)} flowers in {len(parts)} grids, closest "
          f"{closest[0] / GRID:.2f} grid apart; filler {nearest:.2f} units from the flowers")

finish(failures)
