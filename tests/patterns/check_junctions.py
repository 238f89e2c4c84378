#!/usr/bin/env python3
"""Tangential junctions (Wong et al. section 2.2) read from the element tree: where a vine,
stem or spiral branches off another, the angle between the parent's direction of travel at the
branch point and the branch's first tangent is under 35 degrees (no right-angle branches, no
cusps). Measured from the Bézier proxies themselves, not from the patterns' own fields.

usage: check_junctions.py TYPE WORK PANEL... -- PROGRAM
  TYPE  the curve element type (its first child of the same type starting off the parent's
        end is a branch; spirals mark their first segment with the field index == 0)"""
import math
import os

from pattern_tree import arguments, bezier_point, finish, grow_tree

LIMIT = 35.0

(kind, work, *panels), command = arguments()


def tangent(c, t):
    u = 1 - t
    d = [3 * u * u * (c[1][i] - c[0][i]) + 6 * u * t * (c[2][i] - c[1][i])
         + 3 * t * t * (c[3][i] - c[2][i]) for i in (0, 1)]
    if math.hypot(*d) < 1e-12:  # a handle of zero length: the chord
        d = [c[3][i] - c[0][i] for i in (0, 1)]
    return d


def degrees(a, b):
    cos = (a[0] * b[0] + a[1] * b[1]) / (math.hypot(*a) * math.hypot(*b))
    return math.degrees(math.acos(max(-1.0, min(1.0, cos))))


failures = []
total = 0
for panel in panels:
    name = os.path.splitext(os.path.basename(panel))[0]
    elements = grow_tree(command, panel, work)["elements"]
    by_id = {e["id"]: e for e in elements}
    angles = []
    for e in elements:
        parent = by_id.get(e["parent"])
        if e["type"] != kind or parent is None or parent["type"] != kind:
            continue
        if e["fields"].get("index", 0) != 0:
            continue  # a later segment of a spiral: it continues its own first segment
        c, pc = e["proxies"][0]["c"], parent["proxies"][0]["c"]
        if math.dist(c[0], pc[3]) < 1e-6:
            continue  # a continuation, not a branch
        # the branch point: the parent's point nearest the branch's start
        t = min(range(401), key=lambda k: math.dist(bezier_point(pc, k / 400), c[0])) / 400
        angles.append((degrees(tangent(pc, t), tangent(c, 0.0)), e["id"]))
    total += len(angles)
    if not angles:
        failures.append(f"{name}: no branch junctions at all")
        continue
    worst = max(angles)
    angles.sort()
    print(f"{name}: {len(angles)} junctions, median {angles[len(angles) // 2][0]:.1f} deg, "
          f"max {worst[0]:.1f} deg (element {worst[1]})")
    if worst[0] >= LIMIT:
        failures.append(f"{name}: element {worst[1]} branches {worst[0]:.1f} deg off its parent")

print(f"{total} junctions over {len(panels)} panels")
finish(failures)
