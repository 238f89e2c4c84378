#!/usr/bin/env python3
"""Writes the unseen regular references of test_growth_lattices.cpp: every lattice kind at
spacings, turns and origins the growth code was never tuned on, cut round, each coordinate
rounded to 3 decimals as an editor saving few digits would.

    python3 tests/stdlib/growth/references/make_references.py   # rewrites the *.json beside it
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# (kind, nearest-neighbour spacing, turn in degrees, origin)
CASES = [
    ("triangular", 3.7, 17.0, (-41.3, 12.9)),
    ("triangular", 0.83, 90.0, (5.0, 5.0)),
    ("square", 25.3, 0.0, (400.0, -300.0)),
    ("square", 1.9, 33.0, (0.0, 0.0)),
    ("honeycomb", 6.1, 0.0, (17.0, 3.0)),
    ("honeycomb", 0.47, 71.0, (-2.0, 1.0)),
    ("three_colour", 12.5, 45.0, (0.0, 0.0)),
    ("three_colour", 2.2, 8.0, (100.0, 100.0)),
    ("checker", 4.4, 0.0, (1.0, 2.0)),
    ("checker", 31.0, 22.5, (-500.0, 250.0)),
    ("stripes", 7.7, 0.0, (0.0, 0.0)),
    ("stripes", 1.3, 58.0, (9.0, -9.0)),
]


def sites(kind, a, extent):
    """Lattice points (x, y, symbol) of `kind` with spacing a, covering |x|, |y| <= extent."""
    n = int(extent / a) + 4
    h = a * math.sqrt(3) / 2
    out = []
    for r in range(-n, n + 1):
        for c in range(-n, n + 1):
            if kind in ("triangular", "three_colour"):
                x, y = c * a + (r % 2) * a / 2, r * h
                q = c - (r - r % 2) // 2
                out.append((x, y, "abc"[(q - r) % 3] if kind == "three_colour" else "a"))
            elif kind == "square":
                out.append((c * a, r * a, "a"))
            elif kind == "checker":
                out.append((c * a, r * a, "ab"[(r + c) % 2]))
            elif kind == "stripes":
                out.append((c * a, r * a, "b" if c % 4 == 3 else "a"))
            elif kind == "honeycomb":
                x, y = c * 2 * h + (r % 2) * h, r * 1.5 * a
                out.append((x, y, "a"))
                out.append((x, y + a, "a"))
    return out


def reference(kind, a, turn, origin):
    radius = 4.6 * a
    t = math.radians(turn)
    elements = []
    for x, y, symbol in sites(kind, a, radius + 2 * a):
        if math.hypot(x, y) > radius:
            continue
        rx = x * math.cos(t) - y * math.sin(t) + origin[0]
        ry = x * math.sin(t) + y * math.cos(t) + origin[1]
        elements.append({"symbol": symbol, "x": round(rx, 3), "y": round(ry, 3)})
    return {"elements": elements}


def main():
    for kind, a, turn, origin in CASES:
        name = f"{kind}-a{a:g}-turn{turn:g}.json"
        with open(os.path.join(HERE, name), "w") as f:
            elements = reference(kind, a, turn, origin)["elements"]
            f.write('{"elements": [\n' + ",\n".join(json.dumps(e) for e in elements) + "\n]}\n")


if __name__ == "__main__":
    main()
