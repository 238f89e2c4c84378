#!/usr/bin/env python3
"""The checker can fail: grows dots under d6, then breaks the tree three ways (an image moved,
an image dropped, every dot of one orbit grown into its neighbours) and expects check_symmetry
to refuse each, and to pass the tree as grown.
usage: checker_fails.py PROGRAM CHECK WORK"""
import copy
import json
import pathlib
import subprocess
import sys

program, check, work = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
work.mkdir(parents=True, exist_ok=True)
tree_path = work / "tree.json"
subprocess.run([program, "--region", "circle:60", "--symmetry", "d6", "--resolution", "160",
                "--quiet", "-o", str(work / "out.svg"), "--json", str(tree_path)], check=True)
tree = json.loads(tree_path.read_text())


def verdict(t, name):
    path = work / f"{name}.json"
    path.write_text(json.dumps(t))
    r = subprocess.run([check, str(path), "d6", "circle:60"], capture_output=True, text=True)
    print(name, r.returncode, r.stdout.strip().splitlines()[-1])
    return r.returncode


failures = []
if verdict(tree, "as-grown") != 0:
    failures.append("the grown tree was refused")
images = [e for e in tree["elements"] if "image_of" in e and e["type"] == "dot"]
moved = copy.deepcopy(tree)
e = next(x for x in moved["elements"] if x["id"] == images[5]["id"])
e["proxies"][0]["center"][0] += 0.5
if verdict(moved, "moved") == 0:
    failures.append("a moved image passed")
dropped = copy.deepcopy(tree)
dropped["elements"] = [x for x in dropped["elements"] if x["id"] != images[7]["id"]]
for k, x in enumerate(dropped["elements"]):  # ids stay indices
    x["id"] = k
    if "image_of" in x and x["image_of"] > images[7]["id"]:
        x["image_of"] -= 1
if verdict(dropped, "dropped") == 0:
    failures.append("a dropped image passed")
grown = copy.deepcopy(tree)
original = images[3]["image_of"]
for x in grown["elements"]:
    if x["id"] == original or x.get("image_of") == original:
        x["proxies"][0]["radius"] *= 3
if verdict(grown, "grown") == 0:
    failures.append("an orbit of overlapping dots passed")
if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
