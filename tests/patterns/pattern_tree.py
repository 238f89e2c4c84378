"""What the pattern checks share: their command line, growing a pattern over a panel into its
element tree, points on its cubic Bézier proxies, and the verdict."""
import json
import os
import subprocess
import sys


def arguments():
    """sys.argv as ARG... -- PROGRAM [PROGRAM ARG...]: the arguments before "--" and the
    program's command (a list)."""
    split = sys.argv.index("--")
    return sys.argv[1:split], sys.argv[split + 1:]


def grow_tree(command, panel, work, name=None):
    """Runs COMMAND over PANEL (--rng-seed 1), writing WORK/NAME.json and .svg; the tree."""
    name = name or os.path.splitext(os.path.basename(panel))[0]
    os.makedirs(work, exist_ok=True)
    tree_path = os.path.join(work, f"{name}.json")
    subprocess.run(command + ["--region", panel, "--rng-seed", "1", "--quiet", "--json", tree_path,
                              "-o", os.path.join(work, f"{name}.svg")], check=True, timeout=600)
    with open(tree_path) as f:
        return json.load(f)


def bezier_point(c, t):
    u = 1 - t
    return [u ** 3 * c[0][i] + 3 * u * u * t * c[1][i] + 3 * u * t * t * c[2][i] + t ** 3 * c[3][i]
            for i in (0, 1)]


def finish(failures):
    """Prints the failures and exits: 0 when there are none."""
    for f in failures:
        print("FAIL:", f)
    sys.exit(1 if failures else 0)
