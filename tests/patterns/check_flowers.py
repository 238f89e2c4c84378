#!/usr/bin/env python3
"""The flowers pattern as an artist reads it, measured from the element tree (--json):
- every stem shows between the two flowers' petals, at least 1 output pixel at the gallery's
  600 px width (petals reach 1.02 flower radii from the centre: rules/flowers.acr);
- along a line of stems, successive leaves lie on alternate sides of their stems;
- flowers are not all alike: their radii and petal turns vary.

usage: check_flowers.py WORK PANEL... -- PROGRAM"""
import math
import os

from pattern_tree import arguments, finish, grow_tree

WIDTH = 600
MARGIN = 0.02  # runtime/src/output/page_layout.cpp
PETAL_REACH = 1.02

(work, *panels), command = arguments()


def key(p):
    return (round(p[0], 6), round(p[1], 6))


failures = []
for panel in panels:
    name = os.path.splitext(os.path.basename(panel))[0]
    tree = grow_tree(command, panel, work)
    x0, y0, x1, y1 = tree["region"]["bounds"]
    margin = MARGIN * max(x1 - x0, y1 - y0)
    px = WIDTH / (x1 - x0 + 2 * margin)  # output pixels per unit at the gallery width
    elements = tree["elements"]
    by_id = {e["id"]: e for e in elements}
    flower_at = {key(e["proxies"][0]["center"]): e for e in elements if e["type"] == "flower"}
    stems = [e for e in elements if e["type"] == "stem"]
    leaves = [e for e in elements if e["type"] == "leaf"]

    # Stems shown between petals.
    shortest = (math.inf, None)
    for s in stems:
        p0, p1 = s["proxies"][0]["p0"], s["proxies"][0]["p1"]
        a, b = flower_at.get(key(p0)), flower_at.get(key(p1))
        if a is None or b is None:
            failures.append(f"{name}: stem {s['id']} does not join two flowers")
            continue
        shown = (math.dist(p0, p1)
                 - PETAL_REACH * (a["proxies"][0]["radius"] + b["proxies"][0]["radius"])) * px
        shortest = min(shortest, (shown, s["id"]))
    if shortest[1] is not None and shortest[0] < 1.0:
        failures.append(f"{name}: stem {shortest[1]} shows {shortest[0]:.2f} px between petals")

    # Each leaf's stem (same parent flower, the leaf's base on the stem) and side.
    side_of_stem = {}
    for leaf in leaves:
        base = leaf["proxies"][0]["c"][0]
        tip = leaf["proxies"][0]["c"][3]
        best = None
        for s in stems:
            if s["parent"] != leaf["parent"]:
                continue
            p0, p1 = s["proxies"][0]["p0"], s["proxies"][0]["p1"]
            d = [p1[0] - p0[0], p1[1] - p0[1]]
            length = math.hypot(*d)
            t = ((base[0] - p0[0]) * d[0] + (base[1] - p0[1]) * d[1]) / length ** 2
            off = abs((base[0] - p0[0]) * d[1] - (base[1] - p0[1]) * d[0]) / length
            if 0 < t < 1 and off < 1e-6 and (best is None or off < best[0]):
                cross = d[0] * (tip[1] - base[1]) - d[1] * (tip[0] - base[0])
                best = (off, s["id"], 1 if cross > 0 else -1)
        if best is None:
            failures.append(f"{name}: leaf {leaf['id']} sits on no stem of its flower")
            continue
        side_of_stem[best[1]] = best[2]

    # Successive leaves: walk up from each leafy stem to the nearest leafy stem before it.
    stem_into = {key(s["proxies"][0]["p1"]): s for s in stems}
    pairs = same = 0
    for s in stems:
        if s["id"] not in side_of_stem:
            continue
        before = stem_into.get(key(s["proxies"][0]["p0"]))
        while before is not None and before["id"] not in side_of_stem:
            before = stem_into.get(key(before["proxies"][0]["p0"]))
        if before is None:
            continue
        pairs += 1
        if side_of_stem[before["id"]] == side_of_stem[s["id"]]:
            same += 1
            if same <= 3:
                failures.append(f"{name}: leaves on stems {before['id']} and {s['id']} "
                                f"lie on the same side")
    if pairs == 0:
        failures.append(f"{name}: no two successive leaves to compare")

    # Variation.
    flowers = [e for e in elements if e["type"] == "flower"]
    radii = {round(f["proxies"][0]["radius"], 6) for f in flowers}
    turns = {round(f["fields"].get("turn", 0.0), 6) for f in flowers}
    if len(flowers) > 10 and (len(radii) < 3 or len(turns) < len(flowers) // 2):
        failures.append(f"{name}: flowers alike ({len(radii)} radii, {len(turns)} turns "
                        f"over {len(flowers)} flowers)")
    print(f"{name}: {len(flowers)} flowers, shortest stem shown {shortest[0]:.2f} px, "
          f"{len(leaves)} leaves, {pairs} successive pairs, {same} on the same side, "
          f"{len(radii)} radii")

finish(failures)
