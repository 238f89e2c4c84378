"""Runs a generated program with --json and returns its elements (shared by the e2e cases)."""
import json
import os
import shutil
import subprocess


def grown_elements(program, work, args):
    """PROGRAM ARGS --quiet --json WORK/tree.json -o WORK/out.svg in a fresh WORK; the tree's
    elements, or None (the failure printed) when the program fails."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    tree_path = os.path.join(work, "tree.json")
    run = subprocess.run([program, *args, "--quiet", "--json", tree_path, "-o",
                          os.path.join(work, "out.svg")], capture_output=True, text=True,
                         timeout=300)
    if run.returncode != 0:
        print(f"the program failed (exit {run.returncode}):\n{run.stderr}")
        return None
    with open(tree_path) as f:
        return json.load(f)["elements"]
