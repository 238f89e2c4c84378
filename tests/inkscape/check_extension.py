#!/usr/bin/env python3
"""The Inkscape extension run headless, as Inkscape runs it (the script, --id per selected
object, the drawing last, the result on stdout), on a drawing with two selected shapes under
transforms: an ornament layer per shape whose every element lies inside its shape, ids unique,
the drawing otherwise unchanged; a failing rule file, no selection and a bad parameter give an
inkex message on stderr and a non-zero exit, never a traceback.

Usage: check_extension.py [--inkscape] SCRIPT ACANTHUS|- SOURCE_DIR WORK [DRAWING]
SCRIPT is the extension's acanthus_fill.py; with ACANTHUS '-' it must find the acanthus installed
beside it. With --inkscape, Inkscape itself runs it (under Xvfb, the extension installed in a
fresh user folder, the dialog's values in its preferences, the menu item as an action), and
only the filled drawing is checked. Exits 77 (skipped) when inkex is not installed."""

import os
import shutil
import signal
import subprocess
import sys
import tempfile
from xml.sax.saxutils import quoteattr

EXTENSIONS = "/usr/share/inkscape/extensions"
sys.path.insert(0, EXTENSIONS)
try:
    import inkex  # noqa: E402
    from inkex.bezier import csplength  # noqa: F401,E402
    from lxml import etree  # noqa: E402
except ImportError as err:
    print(f"SKIP: inkex not importable ({err}); scripts/install-deps installs inkscape")
    sys.exit(77)

args = sys.argv[1:]
in_inkscape = args[:1] == ["--inkscape"]
if in_inkscape:
    args = args[1:]
    if not shutil.which("inkscape") or not shutil.which("xvfb-run"):
        print("SKIP: inkscape or xvfb-run not installed (scripts/install-deps)")
        sys.exit(77)
script, acanthus, source, work = args[:4]
drawing = args[4] if len(args) > 4 else os.path.join(source, "tests/inkscape/drawing.svg")
os.makedirs(work, exist_ok=True)
env = dict(os.environ, PYTHONPATH=EXTENSIONS)
env.pop("ACANTHUS_EXECUTABLE", None)
if acanthus != "-":
    env["ACANTHUS_EXECUTABLE"] = os.path.abspath(acanthus)  # Inkscape runs scripts elsewhere
failures = []


def fail(message):
    failures.append(message)
    print("FAIL:", message)


def run_extension(*args):
    command = [sys.executable, script, *args]
    return subprocess.run(command, capture_output=True, text=True, env=env, check=False)


def polygon_of(element):
    """The element's outline in the document's user units, as a list of points."""
    path = element.path.to_absolute().transform(element.composed_transform())
    points = []
    for sub in path.to_superpath():
        for k in range(1, len(sub)):
            p0, p1, p2, p3 = sub[k - 1][1], sub[k - 1][2], sub[k][0], sub[k][1]
            for i in range(16):
                t = i / 16
                mt = 1 - t
                points.append(
                    (
                        mt**3 * p0[0] + 3 * mt * mt * t * p1[0] + 3 * mt * t * t * p2[0] + t**3 * p3[0],
                        mt**3 * p0[1] + 3 * mt * mt * t * p1[1] + 3 * mt * t * t * p2[1] + t**3 * p3[1],
                    )
                )
    return points


def inside(poly, x, y):
    result = False
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
            result = not result
    return result


def distance_to_outline(poly, x, y):
    best = float("inf")
    n = len(poly)
    for i in range(n):
        (x0, y0), (x1, y1) = poly[i], poly[(i + 1) % n]
        dx, dy = x1 - x0, y1 - y0
        length2 = dx * dx + dy * dy
        t = 0 if length2 == 0 else max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy) / length2))
        best = min(best, ((x - x0 - t * dx) ** 2 + (y - y0 - t * dy) ** 2) ** 0.5)
    return best


source_doc = inkex.load_svg(drawing).getroot()
selected = [e.get("id") for e in source_doc.iter() if e.get("data-select") == "yes"] or ["heart", "oval"]
rules = os.path.join(source, "rules/dots.acr")

OPTIONS = {"rules": rules, "params": "max_radius=2.5, rim=0.2", "rng_seed": "3", "resolution": "160"}


def run_in_inkscape(out_path):
    """Extensions > Render > Acanthus on the selection, without its dialog, as Inkscape runs it."""
    home = tempfile.mkdtemp(dir=work, prefix="home-")
    extensions = os.path.join(home, ".config", "inkscape", "extensions")
    os.makedirs(extensions)
    for name in ("acanthus_fill.inx", "acanthus_fill.py"):
        shutil.copy(os.path.join(os.path.dirname(script), name), extensions)
    values = " ".join(f"org.acanthus.fill.{k}={quoteattr(v)}" for k, v in OPTIONS.items())
    with open(os.path.join(home, ".config", "inkscape", "preferences.xml"), "w", encoding="utf-8") as f:
        f.write('<?xml version="1.0" encoding="UTF-8" standalone="no"?>\n<inkscape '
                'xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd" '
                'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" version="1">\n'
                f'  <group id="extensions" {values}/>\n</inkscape>\n')
    actions = f"select-by-id:{','.join(selected)};org.acanthus.fill.noprefs;export-filename:{out_path};export-do"
    inkscape_env = dict(env, HOME=home)
    inkscape_env.pop("XDG_CONFIG_HOME", None)
    # An extension error is a modal dialog in Inkscape's window, which nobody closes here: a
    # time limit, then the whole session (xvfb-run, Xvfb, inkscape) is stopped.
    inkscape = subprocess.Popen(["xvfb-run", "-a", "inkscape", "--with-gui", "--batch-process",
                                 f"--actions={actions}", drawing], stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, text=True, env=inkscape_env, start_new_session=True)
    try:
        output, _ = inkscape.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        os.killpg(inkscape.pid, signal.SIGKILL)
        inkscape.communicate()
        fail("inkscape did not finish in 120 s (an error dialog?)")
        sys.exit(1)
    if inkscape.returncode != 0 or not os.path.isfile(out_path):
        fail(f"inkscape exited {inkscape.returncode}: {output}")
        sys.exit(1)


# 1. Two selected shapes filled.
out_path = os.path.join(work, "filled.svg")
if in_inkscape:
    if os.path.exists(out_path):
        os.remove(out_path)
    run_in_inkscape(out_path)
else:
    run = run_extension(*[f"--id={i}" for i in selected], *[f"--{k}={v}" for k, v in OPTIONS.items()], drawing)
    if run.returncode != 0:
        fail(f"the extension exited {run.returncode}: {run.stderr}")
        sys.exit(1)
    with open(out_path, "w", encoding="utf-8") as f:
        f.write(run.stdout)
doc = inkex.load_svg(out_path).getroot()
ids = [e.get("id") for e in doc.iter() if isinstance(e.tag, str) and e.get("id")]
if len(ids) != len(set(ids)):
    fail("ids are not unique: " + ", ".join(sorted({i for i in ids if ids.count(i) > 1})[:5]))
before = [e.get("id") for e in source_doc.iter() if isinstance(e.tag, str) and e.get("id")]
missing = [i for i in before if doc.getElementById(i) is None]
if missing:
    fail("the drawing lost elements: " + ", ".join(missing))

layers = [g for g in doc if isinstance(g, inkex.Layer) and g.get_id().startswith("acanthus-")]
if len(layers) != len(selected):
    fail(f"{len(layers)} ornament layers for {len(selected)} selected shapes")
for sid in selected:
    layer = next((g for g in layers if g.get_id() == f"acanthus-{sid}"), None)
    if layer is None:
        fail(f"no ornament layer for {sid}")
        continue
    shape = doc.getElementById(sid)
    poly = polygon_of(shape)
    sublayers = [g for g in layer if isinstance(g, inkex.Layer)]
    labels = [g.get("inkscape:label") for g in sublayers]
    if "dot" not in labels:
        fail(f"{sid}: no 'dot' sublayer (sublayers {labels})")
    circles = [c for c in layer.iter() if isinstance(c, inkex.Circle)]
    groups = [g for g in layer.iter() if isinstance(g, inkex.Group) and not isinstance(g, inkex.Layer)]
    if len(circles) < 30:
        fail(f"{sid}: only {len(circles)} dots")
    if any(not g.get_id().startswith(f"{sid}-") for g in groups):
        fail(f"{sid}: an element group's id lacks the shape's prefix")
    out, over = 0, 0.0
    xs, ys = [], []
    for c in circles:
        m = c.composed_transform()
        cx, cy = m.apply_to_point((float(c.get("cx")), float(c.get("cy"))))
        r = float(c.get("r")) * (abs(m.a * m.d - m.b * m.c) ** 0.5)
        xs.append(cx)
        ys.append(cy)
        if not inside(poly, cx, cy):
            out += 1
        else:
            over = max(over, r - distance_to_outline(poly, cx, cy))
    if out:
        fail(f"{sid}: {out} of {len(circles)} dot centres outside the shape")
    # A dot may touch the outline; the buffer is 160 px over the shape, so a dot may overlap it
    # by about a pixel of that buffer.
    bx = [p[0] for p in poly]
    by = [p[1] for p in poly]
    pixel = max(max(bx) - min(bx), max(by) - min(by)) / 160
    if over > 1.5 * pixel:
        fail(f"{sid}: a dot crosses the outline by {over:.3f} units (pixel {pixel:.3f})")
    # The ornament fills the shape: its dots reach near every side.
    spread = (min(xs) - min(bx), max(bx) - max(xs), min(ys) - min(by), max(by) - max(ys))
    if max(spread) > 0.15 * max(max(bx) - min(bx), max(by) - min(by)):
        fail(f"{sid}: the ornament does not reach the shape's sides (gaps {spread})")
    print(f"{sid}: {len(circles)} dots inside, largest overlap {over:.3f} (pixel {pixel:.3f})")


if in_inkscape:
    sys.exit(1 if failures else 0)


def expect_message(run, needles, what):
    if run.returncode == 0:
        fail(f"{what}: exit 0")
    if "Traceback" in run.stderr:
        fail(f"{what}: a traceback\n{run.stderr}")
    for needle in needles:
        if needle not in run.stderr:
            fail(f"{what}: '{needle}' not in the message:\n{run.stderr}")
    if run.stdout.strip():
        fail(f"{what}: a document was written")


# 2. A rule file with an error: the compiler's diagnostic, file:line, no traceback.
bad = os.path.join(work, "broken.acr")
with open(bad, "w", encoding="utf-8") as f:
    f.write("%element\nseed point\n%endelement\n\n%rule\nseed --> blob\n{\n    return SUCCESS;\n}\n%endrule\n")
expect_message(run_extension(f"--id={selected[0]}", f"--rules={bad}", drawing),
               ["Acanthus failed", "broken.acr:6"], "a broken rule file")
# 3. Nothing selected, a bad parameter, a missing rule file.
expect_message(run_extension(f"--rules={rules}", drawing), ["select one or more shapes"], "no selection")
expect_message(run_extension(f"--id={selected[0]}", f"--rules={rules}", "--params=max_radius=big", drawing),
               ["max_radius"], "a bad parameter value")
expect_message(run_extension(f"--id={selected[0]}", "--rules=/nonexistent.acr", drawing),
               ["does not exist"], "a missing rule file")

# 4. Run again on its own output: a second ornament layer per shape, ids still unique, and
# the same bytes as the first run gave (no random ids).
again = run_extension(*[f"--id={i}" for i in selected], f"--rules={rules}", "--params=max_radius=2.5, rim=0.2",
                      "--rng_seed=3", "--resolution=160", out_path)
if again.returncode != 0:
    fail(f"the second run exited {again.returncode}: {again.stderr}")
else:
    doc2 = etree.fromstring(again.stdout.encode())
    ids2 = [e.get("id") for e in doc2.iter() if isinstance(e.tag, str) and e.get("id")]
    if len(ids2) != len(set(ids2)):
        fail("a second run made duplicate ids")
    for sid in selected:
        if doc2.find(f".//*[@id='acanthus-{sid}-2']") is None:
            fail(f"the second run has no layer acanthus-{sid}-2")
same = run_extension(*[f"--id={i}" for i in selected], f"--rules={rules}", "--params=max_radius=2.5, rim=0.2",
                     "--rng_seed=3", "--resolution=160", drawing)
if same.stdout != run.stdout:
    fail("two runs with the same options gave different documents")

sys.exit(1 if failures else 0)
