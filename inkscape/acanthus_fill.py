#!/usr/bin/env python3
"""Extensions > Render > Acanthus: fills each selected shape with the ornament a rule file grows.

Each shape becomes a region file (its path in the document's user units, every transform
applied); `acanthus run RULES` grows into it and writes its structured SVG; that SVG's layers
go into a new top-level layer, scaled back from the output page onto the shape. Ids and CSS
classes get the shape's id as a prefix, so several ornaments live in one drawing.
"""

import json
import os
import re
import shutil
import subprocess
import tempfile

import inkex
from lxml import etree

# Installed as PREFIX/share/inkscape/extensions/, next to PREFIX/bin/acanthus.
HERE = os.path.dirname(os.path.abspath(__file__))

# The output page's width in points: the structured SVG writes coordinates to a fixed share of
# the page, so the ornament's precision does not depend on the shape's size.
PAGE_WIDTH = 2000
# Must match the page layout of the runtime (docs/rendering.md, "Formats and the page").
MARGIN_FRACTION = 0.02

SVG_NS = "http://www.w3.org/2000/svg"
INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"


def find_acanthus():
    """$ACANTHUS_EXECUTABLE, else the acanthus installed with this extension, else PATH's."""
    candidates = [os.environ.get("ACANTHUS_EXECUTABLE", "")]
    if HERE.endswith(os.path.join("share", "inkscape", "extensions")):
        candidates.append(os.path.normpath(os.path.join(HERE, "..", "..", "..", "bin", "acanthus")))
    candidates.append(shutil.which("acanthus") or "")
    for path in candidates:
        if path and os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    raise inkex.AbortExtension(
        "Acanthus: the 'acanthus' program was not found (set ACANTHUS_EXECUTABLE, or put it on PATH)."
    )


def parse_params(text):
    """'a=1, b=2' or 'a=1 b=2' as a list of NAME=VALUE strings."""
    items = [p for p in re.split(r"[,\s]+", text.strip()) if p]
    for item in items:
        if "=" not in item or item.startswith("="):
            raise inkex.AbortExtension(
                f"Acanthus: parameter '{item}' is not NAME=VALUE (separate several with commas)."
            )
    return items


def page_transform(bounds, width):
    """The page layout of the runtime: (scale, offset_x, offset_y) from region to page units."""
    x0, y0, x1, y1 = bounds
    bw = x1 - x0 if x1 > x0 else 1.0
    bh = y1 - y0 if y1 > y0 else 1.0
    margin = MARGIN_FRACTION * max(bw, bh)
    span_x, span_y = bw + 2 * margin, bh + 2 * margin
    height = max(1.0, round(width * span_y / span_x))
    scale = min(width / span_x, height / span_y)
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    return scale, width / 2.0 - cx * scale, height / 2.0 - cy * scale


class AcanthusFill(inkex.EffectExtension):
    """Grows an ornament into every selected shape."""

    def add_arguments(self, pars):
        pars.add_argument("--tab", default="options")
        pars.add_argument("--rules", default="", help="rule file (.acr)")
        pars.add_argument("--params", default="", help="NAME=VALUE, comma separated")
        pars.add_argument("--rng_seed", type=int, default=1)
        pars.add_argument("--resolution", type=int, default=512)
        pars.add_argument("--style", default="drawn")

    def effect(self):
        rules = self.options.rules
        if not rules:
            raise inkex.AbortExtension("Acanthus: choose a rule file (.acr) in the dialog.")
        if not os.path.isfile(rules):
            raise inkex.AbortExtension(f"Acanthus: rule file '{rules}' does not exist.")
        shapes = [
            e
            for e in self.svg.selection.values()
            if isinstance(e, inkex.ShapeElement) and not isinstance(e, (inkex.Group, inkex.TextElement))
        ]
        if not shapes:
            raise inkex.AbortExtension(
                "Acanthus: select one or more shapes (paths, rectangles, circles, ellipses, polygons) to fill."
            )
        acanthus = find_acanthus()
        params = parse_params(self.options.params)
        # inkex gives an element a random id when asked for it (the root, a shape's parents):
        # the drawing keeps its own, and the same run gives the same document.
        without_id = [e for e in self.svg.iter() if isinstance(e.tag, str) and "id" not in e.attrib]
        with tempfile.TemporaryDirectory(prefix="acanthus-inkscape-") as tmp:
            for shape in shapes:
                self.fill(shape, acanthus, rules, params, tmp)
        for element in without_id:
            element.attrib.pop("id", None)

    def fill(self, shape, acanthus, rules, params, tmp):
        """Grows into one shape and inserts the ornament layer above the drawing."""
        sid = shape.get_id()
        path = shape.path.to_absolute().transform(shape.composed_transform())
        fill_rule = shape.specified_style().get("fill-rule", "nonzero")
        region = os.path.join(tmp, f"{sid}-region.svg")
        with open(region, "w", encoding="utf-8") as f:
            f.write(
                f'<svg xmlns="{SVG_NS}"><path fill-rule="{fill_rule}" d="{path}"/></svg>\n'
            )
        out_svg = os.path.join(tmp, f"{sid}.svg")
        out_json = os.path.join(tmp, f"{sid}.json")
        command = [acanthus, "run", rules, "--region", region]
        command += ["--rng-seed", str(self.options.rng_seed)]
        command += ["--resolution", str(self.options.resolution)]
        command += ["--style", self.options.style, "--width", str(PAGE_WIDTH)]
        command += ["--no-region-outline", "--quiet", "-o", out_svg, "--json", out_json]
        for p in params:
            command += ["--param", p]
        try:
            run = subprocess.run(command, capture_output=True, text=True, check=False)
        except OSError as err:
            raise inkex.AbortExtension(f"Acanthus: cannot run {acanthus}: {err}") from err
        if run.returncode != 0:
            message = run.stderr.strip() or f"exit status {run.returncode}"
            raise inkex.AbortExtension(
                f"Acanthus failed on shape '{sid}' (exit {run.returncode}):\n{message}"
            )
        with open(out_json, encoding="utf-8") as f:
            bounds = json.load(f)["region"]["bounds"]
        ornament = etree.parse(out_svg, parser=etree.XMLParser(huge_tree=True)).getroot()
        self.insert(ornament, sid, bounds, os.path.basename(rules))

    def insert(self, ornament, sid, bounds, rules_name):
        """The ornament's layers as sublayers of a new layer over the shape."""
        scale, ox, oy = page_transform(bounds, PAGE_WIDTH)
        layer = self.svg.add(inkex.Layer.new(f"Acanthus {rules_name} in {sid}"))
        # acanthus-SHAPE, or -2, -3, ... after earlier runs: the same every time, unlike
        # get_unique_id's random digits.
        base, n = f"acanthus-{sid}", 1
        while self.svg.getElementById(base if n == 1 else f"{base}-{n}") is not None:
            n += 1
        layer.set_id(base if n == 1 else f"{base}-{n}")
        layer.transform = inkex.Transform(
            (1 / scale, 0, 0, 1 / scale, -ox / scale, -oy / scale)
        )
        prefix = layer.get_id()[len("acanthus-"):] + "-"
        for child in ornament:
            if not isinstance(child.tag, str):
                continue
            tag = etree.QName(child).localname
            if tag == "title":
                continue
            for node in child.iter():
                if not isinstance(node.tag, str):
                    continue
                if node.get("id"):
                    node.set("id", prefix + node.get("id"))
                if node.get("class"):
                    node.set("class", " ".join(prefix + c for c in node.get("class").split()))
                for attr in ("href", "{http://www.w3.org/1999/xlink}href"):
                    ref = node.get(attr)
                    if ref and ref.startswith("#"):
                        node.set(attr, "#" + prefix + ref[1:])
                for attr, value in node.attrib.items():
                    if "url(#" in value:
                        node.set(attr, value.replace("url(#", "url(#" + prefix))
            if tag == "style":
                child.text = re.sub(r"\.(s\d+)\{", lambda m: "." + prefix + m.group(1) + "{", child.text or "")
            layer.append(child)


if __name__ == "__main__":
    AcanthusFill().run()
