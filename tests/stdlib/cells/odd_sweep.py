#!/usr/bin/env python3
"""The mason's checker summed over the 420 brick walls (28 facades x 5 bonds x 3 trees, seed 1).

Runs the cells test binary's per-wall checks (CellsMason.ExampleFacades/UnseenFacades,
CellsUnseen.BrickWalls/NewFacadesForTheJambCheck, CellsFresh.BrickWalls), reads the report line each prints per wall and
sums odd pieces, the ones the geometry does not force, straight joints, narrow pieces, shaved bricks
(and those a run's room forces),
and small pieces at an arris, by bond; with --walls, one line per wall (to diff
two builds), ending in a hash of the wall's cells when MASON_HASH=1 is set (the same hash: the same
cells). MASON_SHAVED=1 lists each shaved brick in the binaries' output; with MASON_TAG=1 too,
each is followed by the other generators within a brick and a course of it (a sill row, a ring).

    MASON_HASH=1 tests/stdlib/cells/odd_sweep.py BUILD_DIR [--walls]
"""
import collections
import re
import subprocess
import sys

RUNS = (("test_cells_mason", "CellsMason.ExampleFacades:CellsMason.UnseenFacades"),
        ("test_cells_unseen_check",
         "CellsUnseen.BrickWalls:CellsUnseen.NewFacadesForTheJambCheck:CellsFresh.BrickWalls"))
LINE = re.compile(r"^([\w-]+) (running|english|flemish|header|stack) (\w+): (straight .*)$")


def field(text, pattern):
    m = re.search(pattern, text)
    return int(m.group(1)) if m else 0


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = "".join(
        subprocess.run([f"{sys.argv[1]}/tests/stdlib/{binary}", "--gtest_filter=" + tests],
                       capture_output=True, text=True, check=False).stdout
        for binary, tests in RUNS)
    walls = {}
    for line in out.splitlines():
        m = LINE.match(line)
        if not m:
            continue
        name, bond, tree, rest = m.groups()
        walls[(name, bond, tree)] = {
            "odd": field(rest, r"odd pieces (\d+)"),
            "unforced": field(rest, r"not forced (\d+)"),
            "straight": field(rest, r"^straight (\d+)/"),
            "narrow": field(rest, r" narrow (\d+)"),
            "shaved": field(rest, r" shaved (\d+)"),
            "shaved_forced": field(rest, r" shaved \d+ \(forced (\d+)\)"),
            "cut": field(rest, r" cut (\d+),"),
            "arris": field(rest, r"arris pieces \d+ small (\d+)") -
                     field(rest, r"arris pieces \d+ small \d+ \(forced (\d+)"),
            "hash": (re.search(r" hash (\d+)", rest) or re.search("()", "")).group(1),
        }
    by_bond = collections.defaultdict(lambda: collections.Counter())
    per_facade = collections.defaultdict(lambda: collections.Counter())
    for (name, bond, tree), w in sorted(walls.items()):
        h = w.pop("hash")
        by_bond[bond].update(w)
        w["hash"] = h
        for k, v in ((k, v) for k, v in w.items() if k != "hash"):
            per_facade[name][k] = max(per_facade[name][k], v)
        if "--walls" in sys.argv:
            print(f"{name} {bond} {tree}: odd {w['odd']} unforced {w['unforced']} shaved {w['shaved']} "
                  f"forced {w['shaved_forced']} "
                  f"straight {w['straight']} narrow {w['narrow']} cut {w['cut']} arris {w['arris']} "
                  f"{w['hash']}")
    total = collections.Counter()
    for c in by_bond.values():
        total.update(c)
    print(f"walls {len(walls)}: odd {total['odd']}, not forced {total['unforced']}, "
          f"straight (bonds but stack) "
          f"{sum(c['straight'] for b, c in by_bond.items() if b != 'stack')}, "
          f"narrow {total['narrow']}, shaved {total['shaved']} "
          f"(a room forces {total['shaved_forced']}), "
          f"small pieces at an arris not forced {total['arris']}")
    print("not forced by bond: " + ", ".join(f"{b} {c['unforced']}" for b, c in
                                             sorted(by_bond.items())))
    print("small at an arris by bond: " + ", ".join(f"{b} {c['arris']}" for b, c in
                                                    sorted(by_bond.items())))
    print("shaved by bond: " + ", ".join(f"{b} {c['shaved']}" for b, c in
                                         sorted(by_bond.items())))
    print("most per facade (odd / not forced / cut courses): " + ", ".join(
        f"{n} {c['odd']}/{c['unforced']}/{c['cut']}" for n, c in sorted(per_facade.items())))


if __name__ == "__main__":
    main()
