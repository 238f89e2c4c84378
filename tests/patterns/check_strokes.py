#!/usr/bin/env python3
"""No stroke thinner than 0.75 output pixels: the pattern rendered as SVG at --width 600 (the
gallery's width) over the panels given, every stroked shape's width times the scale of its
transform (Cairo writes one matrix per shape, in output pixels).

usage: check_strokes.py WORK PANEL... -- PROGRAM [PROGRAM ARGS...]"""
import math
import os
import re
import subprocess
import xml.etree.ElementTree as ET

from pattern_tree import arguments, finish

THINNEST = 0.75
WIDTH = 600

(work, *panels), program = arguments()
os.makedirs(work, exist_ok=True)


def matrix(text):
    """The transform attribute as (a, b, c, d, e, f); only what Cairo writes."""
    if not text:
        return (1, 0, 0, 1, 0, 0)
    m = re.fullmatch(r"\s*matrix\(([^)]*)\)\s*", text)
    if not m:
        raise ValueError(f"unexpected transform {text!r}")
    return tuple(float(v) for v in re.split(r"[\s,]+", m.group(1).strip()))


def compose(p, q):
    a, b, c, d, e, f = p
    A, B, C, D, E, F = q
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D, a * E + c * F + e,
            b * E + d * F + f)


def style_of(node):
    out = {}
    for part in node.get("style", "").split(";"):
        if ":" in part:
            k, v = part.split(":", 1)
            out[k.strip()] = v.strip()
    for k in ("stroke", "stroke-width"):
        if node.get(k) is not None:
            out[k] = node.get(k)
    return out


failures = []
for panel in panels:
    name = os.path.splitext(os.path.basename(panel))[0]
    out = os.path.join(work, f"{name}.svg")
    subprocess.run(program + ["--region", panel, "--rng-seed", "1", "--quiet", "--width",
                              str(WIDTH), "-o", out], check=True, timeout=600)
    thinnest, count = math.inf, 0

    def walk(node, m):
        global thinnest, count
        m = compose(m, matrix(node.get("transform")))
        tag = node.tag.split("}")[-1]
        if tag in ("path", "circle", "ellipse", "line", "polyline", "polygon", "rect"):
            s = style_of(node)
            if s.get("stroke", "none") != "none" and s.get("stroke-opacity", "1") != "0":
                w = float(s.get("stroke-width", "1")) * math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))
                thinnest = min(thinnest, w)
                count += 1
        if tag in ("defs", "clipPath", "mask", "symbol"):
            return  # glyph and clip definitions are not drawn where they stand
        for child in node:
            walk(child, m)

    walk(ET.parse(out).getroot(), (1, 0, 0, 1, 0, 0))
    print(f"{name}: {count} stroked shapes, thinnest {thinnest:.3f} px")
    if thinnest < THINNEST - 1e-3:
        failures.append(f"{name}: a stroke {thinnest:.3f} px wide at {WIDTH} px")

finish(failures)
