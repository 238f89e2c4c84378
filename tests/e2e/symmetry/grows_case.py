#!/usr/bin/env python3
"""One pattern grown under a group must grow something beyond its seed:
    grows_case.py PROGRAM WORKDIR ARGS...
runs PROGRAM ARGS --json WORKDIR/tree.json -o WORKDIR/out.svg and fails (exit 1) when the tree
holds no fundamental element other than the seeds (a pattern whose first elements are all
refused by their own images)."""
import json
import os
import shutil
import subprocess
import sys


def main():
    program, work, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    tree_path = os.path.join(work, "tree.json")
    run = subprocess.run([program, *args, "--quiet", "--json", tree_path, "-o",
                          os.path.join(work, "out.svg")], capture_output=True, text=True,
                         timeout=300)
    if run.returncode != 0:
        print(f"the program failed (exit {run.returncode}):\n{run.stderr}")
        return 1
    with open(tree_path) as f:
        elements = json.load(f)["elements"]
    grown = [e for e in elements if e["type"] != "seed" and "image_of" not in e]
    images = [e for e in elements if e["type"] != "seed" and "image_of" in e]
    print(f"{len(grown)} fundamental elements besides the seeds, {len(images)} images")
    if not grown:
        print("FAULT: nothing grew beyond the seed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
