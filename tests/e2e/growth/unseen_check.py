#!/usr/bin/env python3
"""Grows a set of references nobody tuned on through rules/arrangement.acr, as an author runs it,
and reports what issue 27 checks per run: the NN median against the reference's (all motifs
against the interior reference elements, and the motifs 1.5 NN inside the panel against the
inner reference elements), the symbol mix and the same-symbol neighbour share against the
reference's, the largest empty circle in NN distances, the defect share, and whether the same
seed gives the same bytes. Each run's line also shows the factor the spacing match scaled the
jitter by (x1.00: left as grown).

Usage: unseen_check.py PROGRAM SOURCE_DIR WORK_DIR [--set NAME] [--seeds N] [--only SUBSTRING]
       [--tsv FILE]

Sets (each reference made here from its own random seed, coordinates rounded to 3 decimals):
  s8  seeds 801-806: square grids jittered by 0.12 and 0.18 of their spacing (the second turned
      by 20 degrees), a triangular lattice jittered by 0.14 turned by 35 degrees, a honeycomb
      jittered by 0.12 of its edge, a square grid jittered by 0.15 with three symbols, and a
      two-symbol Poisson-disc set of spacing 9; in the shield, the star, the arch with a window,
      a bean (two cubic lobes) and a ring (a disc with a round hole, even-odd).
  s9  seeds 901-906, made after s8 with nothing tuned on it: a triangular lattice jittered by
      0.1 drawn in millimetres (spacing 2.8), an exact 3-colour triangular lattice scaled x100
      (spacing 1000), a honeycomb jittered by 0.09 of its edge turned by 15 degrees, an exact
      checkerboard turned by 30 degrees, a square grid jittered by 0.16 turned by 10 degrees,
      and a two-symbol Poisson-disc set of spacing 10; in a gourd and a wave band (each with a
      neck, every edge curved), the circle and the L (each panel scaled with the reference's
      units).
  s10 seeds 1001-1006 (set_s10): exact lattices of motifs turned at random, a jittered one and
      a Poisson-disc set, in the gourd, the wave band, the shield and the ring.
  s11 seeds 1101-1106 (set_s11): jittered lattices in three units, exact 3-colour and stripe
      lattices and a Poisson-disc set, in the gourd, the wave band, the heart and the narrow
      neck.
"""
import argparse
import json
import math
import pathlib
import random
import subprocess
import sys
import time

ap = argparse.ArgumentParser()
ap.add_argument("program")
ap.add_argument("source")
ap.add_argument("work")
ap.add_argument("--set", default="s8")
ap.add_argument("--seeds", type=int, default=3)
ap.add_argument("--only", default="")
ap.add_argument("--tsv", default="")
args = ap.parse_args()
SOURCE = pathlib.Path(args.source)
WORK = pathlib.Path(args.work)
WORK.mkdir(parents=True, exist_ok=True)
PANELS = SOURCE / "examples/panels"


def lattice_points(kind, gap, width, height, jitter, rng, turn):
    """Lattice points of spacing `gap` (a honeycomb: edge `gap`) over width x height, each moved
    by up to jitter x gap in x and y, then the whole turned by `turn` degrees."""
    pts = []
    tags = []  # (row, col) of each point
    if kind == "square":
        for row in range(int(height / gap) + 1):
            for col in range(int(width / gap) + 1):
                pts.append((col * gap, row * gap))
                tags.append((row, col))
    elif kind == "triangular":
        for row in range(int(height / (gap * math.sqrt(3) / 2)) + 1):
            for col in range(int(width / gap) + 1):
                pts.append((col * gap + (row % 2) * gap / 2, row * gap * math.sqrt(3) / 2))
                tags.append((row, col))
    elif kind == "honeycomb":
        for row in range(int(height / (1.5 * gap)) + 1):
            for col in range(int(width / (math.sqrt(3) * gap)) + 1):
                x = col * math.sqrt(3) * gap + (row % 2) * math.sqrt(3) * gap / 2
                for dy in (0, gap):
                    pts.append((x, row * 1.5 * gap + dy))
                    tags.append((row, col))
    out = []
    c, s = math.cos(math.radians(turn)), math.sin(math.radians(turn))
    for x, y in pts:
        x += rng.uniform(-jitter, jitter) * gap
        y += rng.uniform(-jitter, jitter) * gap
        out.append((c * x - s * y, s * x + c * y))
    return out, tags


def poisson_points(gap, width, height, rng):
    pts = []
    for _ in range(20000):
        x, y = rng.uniform(0, width), rng.uniform(0, height)
        if all((x - a) ** 2 + (y - b) ** 2 >= gap * gap for a, b in pts):
            pts.append((x, y))
    return pts


def pattern_symbol(pattern, row, col):
    """An exact lattice's symbol by its place: "checker" alternates on a square grid, "colour3"
    gives a triangular lattice three symbols with no two alike side by side."""
    if pattern == "checker":
        return "ab"[(row + col) % 2]
    if pattern == "stripes":
        return "b" if col % 3 == 2 else "a"
    if pattern == "plain":
        return "a"
    q = col - row // 2  # axial coordinates of the offset rows
    return "abc"[(q - row) % 3]


JITTERED = {}  # per jittered reference: what lattice_points made it from


def independent_copy(kind, gap, width, height, jitter, turn, seed):
    """The inner NN median a copy whose every jitter is drawn on its own would have, over the
    reference's: the reference's sites, each given the jitter of a random element of it, 30
    draws, the median; inner: sites 2 spacings in from the reference's edge."""
    pts, _ = lattice_points(kind, gap, width, height, jitter, random.Random(seed), turn)
    sites, _ = lattice_points(kind, gap, width, height, 0, random.Random(seed), turn)
    jit = [(p[0] - s[0], p[1] - s[1]) for p, s in zip(pts, sites)]
    c, s = math.cos(math.radians(-turn)), math.sin(math.radians(-turn))
    upright = [(c * x - s * y, s * x + c * y) for x, y in sites]
    xs, ys = [u[0] for u in upright], [u[1] for u in upright]
    inner = [i for i, (x, y) in enumerate(upright)
             if min(x - min(xs), max(xs) - x, y - min(ys), max(ys) - y) >= 2 * gap]

    def median_nn(points):
        nn = sorted(min(math.dist(points[i], q) for j, q in enumerate(points) if j != i)
                    for i in inner)
        return nn[len(nn) // 2]

    rng = random.Random(7)
    draws = sorted(median_nn([(x + jit[k][0], y + jit[k][1]) for (x, y), k in
                              zip(sites, [rng.randrange(len(jit)) for _ in sites])])
                   for _ in range(30))
    return draws[15] / median_nn(pts)


def make_reference(path, seed, kind, gap, width, height, jitter, turn, shares, sizes,
                   pattern="", unit=1.0, turned=False):
    """`unit` scales the whole reference (coordinates and sizes) before rounding to 3 decimals;
    `turned`: each motif turned at random also on a patterned lattice."""
    if kind != "poisson" and jitter > 0:
        JITTERED[path.stem] = (kind, gap, width, height, jitter, turn, seed)
    rng = random.Random(seed)
    tags = None
    if kind == "poisson":
        pts = poisson_points(gap, width, height, rng)
    else:
        pts, tags = lattice_points(kind, gap, width, height, jitter, rng, turn)
    elements = []
    for k, (x, y) in enumerate(pts):
        if pattern:
            symbol = pattern_symbol(pattern, *tags[k])
        else:
            r = rng.random()
            symbol = "abc"[len(shares) - 1]
            for s, w in zip("abc", shares):
                if r < w:
                    symbol = s
                    break
                r -= w
        elements.append({"symbol": symbol, "x": round(x * unit, 3), "y": round(y * unit, 3),
                         "size": round(sizes["abc".index(symbol)] * unit, 3),
                         # an exact lattice's elements all point one way (else no two alike)
                         "angle": 0.0 if pattern and not turned else
                         round(rng.uniform(0, 2 * math.pi), 3)})
    path.write_text(json.dumps({"elements": elements}))


def own_panels():
    bean = WORK / "bean.svg"
    bean.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="230" height="150">\n'
        '<path d="M 20,80 C 10,20 90,0 120,40 C 140,10 220,10 215,70 '
        'C 210,130 150,140 120,110 C 90,145 30,140 20,80 Z"/>\n</svg>\n')
    ring = WORK / "ring.svg"
    ring.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="180" height="180">\n'
        '<path fill-rule="evenodd" d="M 170,90 A 80,80 0 1 0 10,90 A 80,80 0 1 0 170,90 Z '
        'M 125,90 A 35,35 0 1 0 55,90 A 35,35 0 1 0 125,90 Z"/>\n</svg>\n')
    return [str(bean), str(ring)]


def set_s8():
    refs = []
    # seed, kind, spacing, width, height, jitter, turn, symbol shares, sizes
    for seed, kind, gap, w, h, jitter, turn, shares, sizes in (
            (801, "square", 10, 100, 90, 0.12, 0, (0.45, 0.55), (3.0, 3.2)),
            (802, "square", 9, 95, 85, 0.18, 20, (0.3, 0.7), (2.6, 2.8)),
            (803, "triangular", 10, 100, 90, 0.14, 35, (0.5, 0.5), (3.2, 3.0)),
            (804, "honeycomb", 8, 95, 85, 0.12, 0, (0.4, 0.6), (2.5, 2.6)),
            (805, "square", 11, 110, 100, 0.15, 0, (0.4, 0.35, 0.25), (3.5, 3.2, 3.0)),
            (806, "poisson", 9, 100, 85, 0, 0, (0.35, 0.65), (3.0, 2.8))):
        name = f"{kind}-{jitter:g}-t{turn}-{seed}" if kind != "poisson" else f"poisson-{gap}-{seed}"
        path = WORK / f"{name}.json"
        make_reference(path, seed, kind, gap, w, h, jitter, turn, shares, sizes)
        refs.append(path)
    panels = [str(PANELS / p) for p in ("shield.svg", "star.svg", "arch-window.svg")] + \
        own_panels()
    return refs, panels


def s9_panels():
    """A gourd (a big lobe and a small one, a neck 26 wide between them) and a wave band (wavy
    edges pinched to a neck 24 wide in the middle), every edge a cubic curve."""
    gourd = WORK / "gourd.svg"
    gourd.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="250" height="170">\n'
        '<path d="M 150,72 C 160,20 235,20 240,70 C 245,120 175,130 150,98 '
        'C 130,145 10,150 10,85 C 10,20 130,10 150,72 Z"/>\n</svg>\n')
    wave = WORK / "wave.svg"
    wave.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="260" height="150">\n'
        '<path d="M 5,30 C 50,0 90,40 130,63 C 170,40 210,0 255,30 C 270,80 250,130 225,140 '
        'C 190,150 160,110 130,87 C 100,110 70,150 35,140 C 10,130 -10,80 5,30 Z"/>\n'
        '</svg>\n')
    return [gourd, wave, PANELS / "circle.svg", PANELS / "l-shape.svg"]


def scaled_panel(panel, unit):
    """The panel in the reference's units: its drawing inside a scale(unit) group."""
    if unit == 1.0:
        return str(panel)
    text = pathlib.Path(panel).read_text()
    start = text.index(">", text.index("<svg")) + 1
    end = text.rindex("</svg>")
    out = WORK / f"{pathlib.Path(panel).stem}-x{unit:g}.svg"
    out.write_text('<svg xmlns="http://www.w3.org/2000/svg">\n'
                   f'<g transform="scale({unit:g})">{text[start:end]}</g>\n</svg>\n')
    return str(out)


def made_reference(row, panels, turned=False):
    """One reference of a set written from its row (seed, kind, spacing, width, height, jitter,
    turn, symbol shares, sizes, pattern, unit), with the panels scaled to its unit."""
    seed, kind, gap, w, h, jitter, turn, shares, sizes, pattern, unit = row
    if kind == "poisson":
        name = f"poisson-{gap}-{seed}"
    else:
        turned_tag = "-turned" if turned else ""
        name = f"{kind}-{pattern or f'{jitter:g}'}-t{turn}-u{unit:g}{turned_tag}-{seed}"
    path = WORK / f"{name}.json"
    make_reference(path, seed, kind, gap, w, h, jitter, turn, shares, sizes, pattern, unit,
                   turned=turned)
    return path, [scaled_panel(p, unit) for p in panels]


def set_s9():
    refs = []
    panels = s9_panels()
    # rows: seed, kind, spacing, width, height, jitter, turn, symbol shares, sizes, pattern, unit
    for row in (
            (901, "triangular", 10, 100, 90, 0.1, 0, (0.4, 0.6), (3.0, 3.2), "", 0.28),
            (902, "triangular", 10, 100, 90, 0, 0, (), (3.0, 3.0, 3.0), "colour3", 100.0),
            (903, "honeycomb", 8, 95, 85, 0.09, 15, (0.55, 0.45), (2.4, 2.6), "", 1.0),
            (904, "square", 10, 100, 90, 0, 30, (), (3.2, 3.0), "checker", 1.0),
            (905, "square", 10, 100, 90, 0.16, 10, (0.6, 0.4), (3.0, 3.3), "", 1.0),
            (906, "poisson", 10, 110, 90, 0, 0, (0.3, 0.7), (3.3, 3.0), "", 1.0)):
        refs.append(made_reference(row, panels))
    return refs


def set_s10():
    """Seeds 1001-1006, nothing tuned on them: exact lattices whose motifs are each turned at
    random (a 3-colour triangular one turned 25 degrees, a checkerboard in units of 0.1, a one-
    symbol honeycomb turned 40 degrees, a square grid with every third column another symbol
    turned 12 degrees), a triangular lattice jittered by 0.12 and a two-symbol Poisson-disc set
    of spacing 8; in the gourd, the wave band, the shield and the ring."""
    refs = []
    panels = [str(p) for p in s9_panels()[:2]] + [str(PANELS / "shield.svg"), own_panels()[1]]
    for row in (
            (1001, "triangular", 10, 100, 90, 0, 25, (), (3.0, 3.1, 2.9), "colour3", 1.0),
            (1002, "square", 10, 100, 90, 0, 0, (), (3.1, 3.0), "checker", 0.1),
            (1003, "honeycomb", 8, 95, 85, 0, 40, (), (2.5,), "plain", 1.0),
            (1004, "square", 10, 100, 90, 0, 12, (), (3.0, 3.2), "stripes", 1.0),
            (1005, "triangular", 10, 100, 90, 0.12, 0, (0.45, 0.55), (3.0, 3.2), "", 1.0),
            (1006, "poisson", 8, 100, 85, 0, 0, (0.4, 0.6), (2.6, 2.8), "", 1.0)):
        refs.append(made_reference(row, panels, turned=True))
    return refs


def set_s11():
    """Seeds 1101-1106, made after the spacing match with nothing tuned on them: a triangular
    lattice jittered by 0.16 turned 50 degrees in units of 2.54, a square grid jittered by 0.13
    in units of 0.1, a honeycomb jittered by 0.1 turned 25 degrees, an exact 3-colour triangular
    lattice, exact stripes turned 45 degrees in units of 10 and a two-symbol Poisson-disc set of
    spacing 11; in the gourd, the wave band, the heart and the narrow neck."""
    refs = []
    panels = [str(p) for p in s9_panels()[:2]] + [str(PANELS / "heart.svg"),
                                                  str(PANELS / "narrow-neck.svg")]
    for row in (
            (1101, "triangular", 10, 110, 95, 0.16, 50, (0.5, 0.5), (3.0, 3.1), "", 2.54),
            (1102, "square", 10, 100, 90, 0.13, 0, (0.35, 0.65), (3.1, 3.0), "", 0.1),
            (1103, "honeycomb", 8, 95, 85, 0.1, 25, (0.5, 0.5), (2.4, 2.5), "", 1.0),
            (1104, "triangular", 10, 100, 90, 0, 0, (), (3.0, 3.0, 3.0), "colour3", 1.0),
            (1105, "square", 10, 100, 90, 0, 45, (), (3.1, 3.0), "stripes", 10.0),
            (1106, "poisson", 11, 110, 90, 0, 0, (0.45, 0.55), (3.4, 3.1), "", 1.0)):
        refs.append(made_reference(row, panels))
    return refs


def run(ref, panel, seed, out):
    p = subprocess.run(["nice", args.program, "-o", str(out), "--param", f"reference={ref}",
                        "--region", panel, "--rng-seed", str(seed), "--metrics"],
                       capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        raise SystemExit(f"{ref.name} in {panel} seed {seed}: exit {p.returncode}: {p.stderr}")
    return json.loads(p.stdout)


if args.set == "s8":
    refs, panels = set_s8()
    refs = [(ref, panels) for ref in refs]
elif args.set == "s9":
    refs = set_s9()
elif args.set == "s10":
    refs = set_s10()
else:
    refs = set_s11()
rows = []
begin = time.time()
for ref, ref_panels in refs:
    for panel in ref_panels:
        pname = pathlib.Path(panel).stem
        if args.only and args.only not in f"{ref.stem} {pname}":
            continue
        for seed in range(1, args.seeds + 1):
            out = WORK / f"{ref.stem}-{pname}-{seed}.svg"
            t0 = time.time()
            m = run(ref, panel, seed, out)
            seconds = time.time() - t0
            same = ""
            if seed == 1:  # the same seed again: the same bytes
                again = WORK / "again.svg"
                run(ref, panel, seed, again)
                same = "same" if again.read_bytes() == out.read_bytes() else "DIFFERENT"
            g = m["growth"]
            mix = max(abs(v["result"] - v["reference"]) for v in g["symbols"].values())
            ss = g["same_symbol_neighbours"]
            row = dict(ref=ref.stem, panel=pname, seed=seed, motifs=g["motifs"],
                       all=g["nn_median"] / g["nn_median_reference"],
                       inner=g["nn_median_inner"] / g["nn_median_reference_inner"],
                       mix=mix, same=ss["result"] - ss["reference"], hole=g["largest_hole"],
                       defects=g["defects"]["share"], interior=g["defects"]["interior"],
                       fitted=g["near_regular"]["fitted"], lattice=g["lattice"]["sites"],
                       scale=g["near_regular"]["jitter_scale"],
                       bytes=same, seconds=seconds)
            rows.append(row)
            print(f"{row['ref']:28} {pname:12} {seed} motifs {row['motifs']:4} "
                  f"NN all {row['all']:.3f} inner {row['inner']:.3f} mix {100 * mix:4.1f} "
                  f"same {100 * row['same']:+5.1f} hole {row['hole']:.2f} "
                  f"defects {row['defects']:.2f}/{row['interior']} fitted {row['fitted']} "
                  f"x{row['scale']:.2f} "
                  f"{same} {seconds:.1f}s", flush=True)

print("\nper reference: NN median all / inner (runs over 5%), mix, same-symbol, hole")
for ref, _ in refs:
    rs = [r for r in rows if r["ref"] == ref.stem]
    if not rs:
        continue
    a = [r["all"] for r in rs]
    i = [r["inner"] for r in rs]
    print(f"{ref.stem:28} {min(a):.3f}-{max(a):.3f} ({sum(abs(v - 1) > 0.05 for v in a)}) / "
          f"{min(i):.3f}-{max(i):.3f} ({sum(abs(v - 1) > 0.05 for v in i)})  mix <= "
          f"{100 * max(r['mix'] for r in rs):.1f}  same {100 * min(r['same'] for r in rs):+.1f}.."
          f"{100 * max(r['same'] for r in rs):+.1f}  hole <= {max(r['hole'] for r in rs):.2f}  "
          f"defects {min(r['defects'] for r in rs):.2f}-{max(r['defects'] for r in rs):.2f}")
print("\njittered references: the inner NN median a copy with each jitter drawn on its own has")
for ref, _ in refs:
    if ref.stem in JITTERED and any(r["ref"] == ref.stem for r in rows):
        rs = [r["inner"] for r in rows if r["ref"] == ref.stem]
        print(f"{ref.stem:28} {independent_copy(*JITTERED[ref.stem]):.3f} (grown: mean "
              f"{sum(rs) / len(rs):.3f})")
a = [r["all"] for r in rows]
i = [r["inner"] for r in rows]
print(f"\n{len(rows)} runs: NN median over 5% all {sum(abs(v - 1) > 0.05 for v in a)}, inner "
      f"{sum(abs(v - 1) > 0.05 for v in i)}; mean all {sum(a) / len(a):.3f} inner "
      f"{sum(i) / len(i):.3f}; mix <= {100 * max(r['mix'] for r in rows):.1f} points; same-symbol "
      f"within {100 * max(abs(r['same']) for r in rows):.1f} points; hole <= "
      f"{max(r['hole'] for r in rows):.2f} NN; bytes: "
      f"{sum(r['bytes'] == 'same' for r in rows)} same, "
      f"{sum(r['bytes'] == 'DIFFERENT' for r in rows)} different; {time.time() - begin:.0f} s")
if args.tsv:
    keys = list(rows[0].keys())
    with open(args.tsv, "w") as f:
        f.write("\t".join(keys) + "\n")
        for r in rows:
            f.write("\t".join(f"{r[k]:.4f}" if isinstance(r[k], float) else str(r[k])
                              for k in keys) + "\n")
