#!/usr/bin/env python3
"""Runs a pattern program over every panel given; each run must exit 0 and grow at least a
few dozen elements (more than the seeds), writing a parseable tree."""
import json
import os
import subprocess
import sys

program, work, panels = sys.argv[1], sys.argv[2], sys.argv[3:]
os.makedirs(work, exist_ok=True)
failures = []
for panel in panels:
    name = os.path.splitext(os.path.basename(panel))[0]
    tree = os.path.join(work, name + ".json")
    run = subprocess.run([program, "--region", panel, "--rng-seed", "1", "--quiet",
                          "--json", tree, "-o", os.path.join(work, name + ".svg")],
                         capture_output=True, text=True, timeout=600)
    if run.returncode != 0:
        failures.append(f"{name}: exit {run.returncode}: {run.stderr.strip()}")
        continue
    with open(tree) as f:
        elements = json.load(f)["elements"]
    grown = [e for e in elements if e["parent"] is not None]
    print(f"{name}: {len(grown)} grown elements")
    if len(grown) < 36:
        failures.append(f"{name}: only {len(grown)} elements grew")
if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(1)
