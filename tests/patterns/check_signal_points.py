#!/usr/bin/env python3
"""Motifs at signal points (Wong et al. section 2.1.3), measured from the element tree (--json):
in the hierarchical pattern, at least three quarters of the sharp corners of a panel (the
frame's eight, the heart's tip and cleft) have a flower whose rim comes within 4 units of the
corner. Corners are written here from the panels' own path data.

usage: check_signal_points.py WORK PANEL... -- PROGRAM (panels among those of CORNERS)"""
import math
import os

from pattern_tree import arguments, finish, grow_tree

NEAR = 4.0
SHARE = 0.75
CORNERS = {
    "frame": [(0, 0), (160, 0), (160, 160), (0, 160), (30, 30), (130, 30), (130, 130), (30, 130)],
    "heart": [(80, 146), (80, 38)],
}

(work, *panels), command = arguments()

failures = []
for panel in panels:
    name = os.path.splitext(os.path.basename(panel))[0]
    corners = CORNERS[name]
    tree = grow_tree(command, panel, work)
    flowers = [e["proxies"][0] for e in tree["elements"] if e["type"] == "flower"]
    gaps = [min(math.dist(c, f["center"]) - f["radius"] for f in flowers) for c in corners]
    held = sum(1 for g in gaps if g <= NEAR)
    print(f"{name}: {held} of {len(corners)} corners hold a flower "
          f"(rim to corner: {', '.join(f'{g:.1f}' for g in gaps)})")
    if held < SHARE * len(corners):
        failures.append(f"{name}: only {held} of {len(corners)} corners hold a flower")

finish(failures)
