#!/usr/bin/env python3
"""Every pattern under a sample of every group kind (c3 and d6 in a circle, the seven friezes,
the 17 wallpaper groups on tiles of 80), grown once each and checked by check_symmetry; a case
is BAD when it grows nothing beyond its seed or the checker finds a fault. Too long for ctest
(some 260 runs); run by hand after a change to growth under symmetry:
    sweep_groups.py BUILD_DIR PATTERN[,PATTERN...] [JOBS] [WORKDIR]"""
import json, os, subprocess, sys, concurrent.futures as cf
B = sys.argv[1]
patterns = sys.argv[2].split(",")
work = sys.argv[4] if len(sys.argv) > 4 else "/tmp/sweep_groups"
cases = []
for g in ["c3", "d6"]:
    cases.append((g, ["--symmetry", g, "--region", "circle:100"], "circle:100"))
for g in ["p1", "p11g", "p1m1", "p11m", "p2", "p2mg", "p2mm"]:
    cases.append((f"frieze:{g}:60", ["--frieze", g, "--period", "60", "--region", "rect:240,60"], "rect:240,60"))
for g, t in [("p1","80,60"),("p2","80,60"),("pm","80,60"),("pg","80,60"),("cm","80,60"),("pmm","80,60"),("pmg","80,60"),("pgg","80,60"),("cmm","80,60"),("p4","80,80"),("p4m","80,80"),("p4g","80,80"),("p3","80,80,60"),("p3m1","80,80,60"),("p31m","80,80,60"),("p6","80,80,60"),("p6m","80,80,60")]:
    cases.append((f"wallpaper:{g}:{t}", ["--wallpaper", g, "--tile", t], "-"))
def run(p, case):
    name, args, region = case
    w = f"{work}/{p}-{name.replace(':','_').replace(',','_')}"
    os.makedirs(w, exist_ok=True)
    r = subprocess.run([f"{B}/tests/regress/pattern_{p}" if os.path.exists(f"{B}/tests/regress/pattern_{p}") else f"{B}/tests/e2e/pattern_{p}", *args, "--rng-seed", "3", "--resolution", "256", "--quiet", "-o", f"{w}/a.svg", "--json", f"{w}/a.json"], capture_output=True, text=True, timeout=600)
    if r.returncode:
        return f"{p} {name}: EXIT {r.returncode} {r.stderr.strip()[:200]}"
    els = json.load(open(f"{w}/a.json"))["elements"]
    grown = sum(1 for e in els if e["type"] != "seed" and "image_of" not in e)
    c = subprocess.run([f"{B}/tests/e2e/symmetry/check_symmetry", f"{w}/a.json", name, region], capture_output=True, text=True)
    out = c.stdout.strip().splitlines()
    status = "ok" if c.returncode == 0 and grown > 0 else "BAD"
    return f"{status} {p} {name}: grown {grown}; check rc {c.returncode}: {out[-1] if out else ''}"
with cf.ThreadPoolExecutor(int(sys.argv[3]) if len(sys.argv) > 3 else 1) as ex:
    futs = [ex.submit(run, p, c) for p in patterns for c in cases]
    bad = 0
    for f in futs:
        line = f.result()
        bad += not line.startswith("ok")
        print(line, flush=True)
sys.exit(1 if bad else 0)
