"""What the pattern checks share: grow a pattern over a panel into its element tree, and points
on its cubic Bézier proxies."""
import json
import os
import subprocess


def grow_tree(program, panel, work, name=None):
    """Runs PROGRAM over PANEL (--rng-seed 1), writing WORK/NAME.json and .svg; the tree."""
    name = name or os.path.splitext(os.path.basename(panel))[0]
    tree_path = os.path.join(work, f"{name}.json")
    subprocess.run([program, "--region", panel, "--rng-seed", "1", "--quiet", "--json", tree_path,
                    "-o", os.path.join(work, f"{name}.svg")], check=True, timeout=600)
    with open(tree_path) as f:
        return json.load(f)


def bezier_point(c, t):
    u = 1 - t
    return [u ** 3 * c[0][i] + 3 * u * u * t * c[1][i] + 3 * u * t * t * c[2][i] + t ** 3 * c[3][i]
            for i in (0, 1)]
