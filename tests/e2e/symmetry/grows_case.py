#!/usr/bin/env python3
"""One pattern grown under a group must grow something beyond its seed:
    grows_case.py PROGRAM WORKDIR ARGS...
runs PROGRAM ARGS --json WORKDIR/tree.json -o WORKDIR/out.svg and fails (exit 1) when the tree
holds no fundamental element other than the seeds (a pattern whose first elements are all
refused by their own images)."""
import sys

from grown_tree import grown_elements


def main():
    program, work, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    elements = grown_elements(program, work, args)
    if elements is None:
        return 1
    grown = [e for e in elements if e["type"] != "seed" and "image_of" not in e]
    images = [e for e in elements if e["type"] != "seed" and "image_of" in e]
    print(f"{len(grown)} fundamental elements besides the seeds, {len(images)} images")
    if not grown:
        print("FAULT: nothing grew beyond the seed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
