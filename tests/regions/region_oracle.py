#!/usr/bin/env python3
"""Region area oracle: compares a region's area and bounds as Acanthus reads an SVG file with
what rsvg-convert draws when every shape of a copy of the file is filled solid.

    region_oracle.py --tool build/tests/regions/region_oracle FILE.svg [FILE.svg ...]

The copy keeps what docs/regions.md says a region reads and leaves out the rest: every shape
is filled opaque black with no stroke; text, images, foreignObject, clip paths, masks, filters
and markers are removed; of style sheets and style attributes only display and fill-rule stay
(rules with selectors Acanthus does not match go, as do at-rules); visibility is dropped;
nested viewports (svg, symbol) do not clip. The original root becomes a nested <svg> without
viewBox (so Acanthus's user units, the root's, are kept, with the root's viewport size for
percentages) inside a new root whose viewBox frames the drawing at a known pixel scale: a
first, coarse raster of the page and Acanthus's bounds finds where rsvg draws, and the fine
raster frames that and Acanthus's bounds plus a margin (measured again at twice the
resolution when the areas are more than half the tolerance apart). Anti-aliased edge pixels
count fractionally. A file passes when the areas agree to 0.1% (--tolerance) and each side of the
bounds lies within 2 pixels of the raster's (--bounds-px).

Prints one line per file; exits 1 when any file fails. Standard library only.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

SVG = "http://www.w3.org/2000/svg"
XLINK = "http://www.w3.org/1999/xlink"
PIXELS = 4.0e6  # raster budget: about 2000 x 2000 for a square region
MAX_SIDE = 16384  # longest raster side
MARGIN = 0.05  # of the larger side of the bounds, on each side

# Elements whose content a region leaves out (SVG namespace, or no namespace).
DROPPED = {"text", "image", "foreignObject", "script", "clipPath", "mask", "marker", "filter",
           "title", "desc", "metadata"}
# Presentation attributes and properties kept: everything else about paint goes.
KEPT_PROPERTIES = {"display", "fill-rule"}
PAINT = re.compile(r"^(fill|stroke|opacity|visibility|clip-path|clip-rule|mask|filter|marker|"
                   r"overflow|mix-blend-mode|isolation|paint-order|vector-effect|"
                   r"shape-rendering|color)")
UNITS = {"": 1, "px": 1, "pt": 96 / 72, "pc": 16, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96}

ET.register_namespace("", SVG)
ET.register_namespace("xlink", XLINK)


def split(tag):
    """(namespace, local name) of an ElementTree tag."""
    if tag.startswith("{"):
        uri, local = tag[1:].split("}", 1)
        return uri, local
    return "", tag


def is_svg(tag):
    return isinstance(tag, str) and split(tag)[0] in ("", SVG)


def absolute_length(text):
    m = re.fullmatch(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(px|pt|pc|mm|cm|in)?\s*",
                     text or "")
    return float(m.group(1)) * UNITS[m.group(2) or ""] if m else None


def root_viewport(root):
    """The root's viewport in its user units, as Acanthus takes it for percentages."""
    try:
        vb = [float(v) for v in re.split(r"[\s,]+", root.get("viewBox", "").strip()) if v]
        if len(vb) == 4 and vb[2] > 0 and vb[3] > 0:
            return vb[2], vb[3]
    except ValueError:
        pass
    w, h = absolute_length(root.get("width")), absolute_length(root.get("height"))
    return (w, h) if w is not None and h is not None else None


def declarations(body):
    """The display and fill-rule declarations of a declaration block."""
    kept = []
    for decl in body.split(";"):
        if ":" in decl and decl.split(":", 1)[0].strip() in KEPT_PROPERTIES:
            kept.append(decl.strip())
    return ";".join(kept)


def style_sheet(text):
    """A style sheet reduced to the rules Acanthus reads (see parse_style_sheet)."""
    text = re.sub(r"/\*.*?(\*/|$)", "", text, flags=re.S).replace("<!--", "").replace("-->", "")
    out, pos = [], 0
    while True:
        open_ = text.find("{", pos)
        if open_ < 0:
            break
        depth, close = 0, len(text)
        for i in range(open_, len(text)):
            depth += {"{": 1, "}": -1}.get(text[i], 0)
            if depth == 0:
                close = i
                break
        prelude = text[pos:open_].strip().lstrip(";").strip()
        while prelude.startswith("@") and ";" in prelude:  # @import ...; @charset ...;
            prelude = prelude.split(";", 1)[1].strip()
        selectors = [s for s in prelude.split(",") if s.strip() and not re.search(r"[\[:+~@]", s)]
        body = declarations(text[open_ + 1:close])
        if selectors and body and not prelude.startswith("@"):
            out.append(",".join(selectors) + "{" + body + "}")
        pos = close + 1
    return "\n".join(out)


def clean(element):
    """Strips paint from `element` and its subtree and removes left-out elements."""
    for child in list(element):
        if not isinstance(child.tag, str):  # comments, processing instructions
            continue
        if is_svg(child.tag) and split(child.tag)[1] in DROPPED:
            element.remove(child)
            continue
        clean(child)
    if is_svg(element.tag) and split(element.tag)[1] == "style":
        if element.get("type", "text/css") in ("", "text/css"):
            sheet = style_sheet((element.text or "") + "".join(c.tail or "" for c in element))
            element.clear()
            element.text = sheet
        return
    for name in list(element.attrib):
        if "}" not in name and name not in KEPT_PROPERTIES and PAINT.match(name):
            del element.attrib[name]
    style = element.get("style")
    if style is not None:
        kept = declarations(style)
        if kept:
            element.set("style", kept)
        else:
            del element.attrib["style"]
    if is_svg(element.tag) and split(element.tag)[1] in ("svg", "symbol"):
        element.set("overflow", "visible")


def solid_copy(source, window, pixels):
    """The solid copy of `source` framing `window` (x, y, w, h) in `pixels` (w, h)."""
    root = ET.parse(source).getroot()
    viewport = root_viewport(root)
    for name in ("x", "y", "width", "height", "viewBox", "preserveAspectRatio"):
        root.attrib.pop(name, None)
    clean(root)
    if viewport:
        root.set("width", repr(viewport[0]))
        root.set("height", repr(viewport[1]))
    outer = ET.Element(f"{{{SVG}}}svg", {
        "viewBox": " ".join(repr(v) for v in window),
        "width": str(pixels[0]), "height": str(pixels[1]),
        "preserveAspectRatio": "none", "fill": "#000", "stroke": "none"})
    outer.append(root)
    return ET.tostring(outer, encoding="unicode")


def run(cmd, timeout=120):
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)


def parse_lines(text):
    out = {}
    for line in text.splitlines():
        key, _, rest = line.partition(" ")
        out[key] = rest
    return out


def page(source):
    """The root's page in its user units: its viewBox, else (0, 0, width, height)."""
    try:
        root = ET.parse(source).getroot()
    except ET.ParseError:
        return None
    try:
        vb = [float(v) for v in re.split(r"[\s,]+", root.get("viewBox", "").strip()) if v]
        if len(vb) == 4 and vb[2] > 0 and vb[3] > 0:
            return tuple(vb)
    except ValueError:
        pass
    w, h = absolute_length(root.get("width")), absolute_length(root.get("height"))
    return (0.0, 0.0, w, h) if w and h and w > 0 and h > 0 else None


def union(a, b):
    """Union of boxes (x0, y0, x1, y1); either may be None."""
    if a is None or b is None:
        return a or b
    return (min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3]))


def render(args, source, name, box, pixels):
    """Renders the solid copy framing `box` plus a margin in about `pixels` pixels: returns
    (area in user units, drawn box in user units or None, window, scale, png) or an error."""
    x0, y0, x1, y1 = box
    margin = MARGIN * max(x1 - x0, y1 - y0)
    wx, wy = x0 - margin, y0 - margin
    ww, wh = x1 - x0 + 2 * margin, y1 - y0 + 2 * margin
    scale = min(math.sqrt(pixels / (ww * wh)), MAX_SIDE / max(ww, wh))
    pw, ph = max(1, math.ceil(ww * scale)), max(1, math.ceil(wh * scale))
    window = (wx, wy, pw / scale, ph / scale)  # the exact scale both ways
    os.makedirs(args.work, exist_ok=True)
    copy = os.path.join(args.work, name + ".solid.svg")
    png = os.path.join(args.work, name + ".png")
    with open(copy, "w", encoding="utf-8") as f:
        f.write(solid_copy(source, window, (pw, ph)))
    rsvg = run([args.rsvg, "--format", "png", "-o", png, copy])
    if rsvg.returncode != 0:
        return f"rsvg-convert failed on {copy}: {rsvg.stderr.strip()}"
    cover = parse_lines(run([args.tool, "coverage", png]).stdout)
    drawn = None
    if "pixels" in cover:
        px = [int(v) for v in cover["pixels"].split()]
        drawn = (wx + px[0] / scale, wy + px[1] / scale, wx + px[2] / scale, wy + px[3] / scale)
    return float(cover["coverage"]) / (scale * scale), drawn, window, scale, png


def check(args, source):
    name = os.path.splitext(os.path.basename(source))[0]
    tool = run([args.tool, "region", source])
    acanthus = parse_lines(tool.stdout)
    mine = None
    if tool.returncode == 0:
        area = float(acanthus["area"])
        mine = tuple(float(v) for v in acanthus["bounds"].split())
    # Coarse: where does rsvg draw, on the page and around Acanthus's bounds?
    coarse = None
    first = union(mine, (lambda p: p and (p[0], p[1], p[0] + p[2], p[1] + p[3]))(page(source)))
    if first:
        coarse = render(args, source, name, first, args.pixels / 16)
        if isinstance(coarse, str):
            return False, f"FAIL {name}: {coarse}"
    if mine is None:
        why = acanthus.get("refused") or acanthus.get("exception") or tool.stderr.strip()
        drew = f"; rsvg draws area {coarse[0]:.8g}" if coarse and coarse[1] else ""
        return False, f"FAIL {name}: Acanthus refused it: {why}{drew}"
    # Fine: anti-aliased edges that coincide (identical shapes) darken, a bias that shrinks
    # with the pixel size; a result in the upper half of the tolerance is measured again at
    # twice the resolution.
    for pixels in (args.pixels, 4 * args.pixels):
        fine = render(args, source, name, union(mine, coarse and coarse[1]), pixels)
        if isinstance(fine, str):
            return False, f"FAIL {name}: {fine}"
        raster_area, drawn, window, scale, png = fine
        rel = abs(area - raster_area) / raster_area if raster_area > 0 else math.inf
        if rel <= args.tolerance / 2:
            break
    problems = []
    if not rel <= args.tolerance:
        problems.append(f"area off by {100 * rel:.3g}%")
    if drawn is None:
        problems.append("rsvg draws nothing")
    else:
        off = max(abs(a - b) for a, b in zip(mine, drawn)) * scale
        if off > args.bounds_px:
            problems.append(
                f"bounds off by {off:.1f} px: Acanthus ({mine[0]:.6g},{mine[1]:.6g})-"
                f"({mine[2]:.6g},{mine[3]:.6g}), rsvg about ({drawn[0]:.6g},{drawn[1]:.6g})-"
                f"({drawn[2]:.6g},{drawn[3]:.6g})")
    pw, ph = round(window[2] * scale), round(window[3] * scale)
    verdict = "FAIL" if problems else "PASS"
    line = (f"{verdict} {name}: Acanthus area {area:.8g}, rsvg {raster_area:.8g} "
            f"({100 * rel:.3g}% apart; {pw}x{ph} px, {scale:.4g} px/unit)")
    if problems:
        line += "; " + "; ".join(problems) + f"; raster {png}"
    return not problems, line


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tool", required=True, help="the region_oracle executable")
    parser.add_argument("--rsvg", default="rsvg-convert")
    parser.add_argument("--work", default="region-oracle", help="directory for copies, PNGs")
    parser.add_argument("--tolerance", type=float, default=1e-3, help="relative area")
    parser.add_argument("--bounds-px", type=float, default=2.0)
    parser.add_argument("--pixels", type=float, default=PIXELS, help="raster budget")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    ok = True
    for source in args.files:
        passed, line = check(args, source)
        print(line, flush=True)
        ok = ok and passed
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
