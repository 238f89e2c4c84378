#!/usr/bin/env python3
"""Fails when an include in runtime/src reaches a stage above the including file's own, when an
include of a private header does not name its folder, or when a folder is not a known stage."""
import pathlib
import re
import sys

# Lowest first; docs/architecture.md explains each.
STAGES = ["files", "geometry", "svg", "region", "proxy", "pattern", "field", "symmetry", "growth", "draw", "output", "program"]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def stage_of(relative):
    top = relative.parts[0]
    return STAGES.index(top) if top in STAGES else None


def main(src):
    src = pathlib.Path(src)
    problems = []
    files = sorted(p for p in src.rglob("*") if p.suffix in (".cpp", ".hpp"))
    for path in files:
        rel = path.relative_to(src)
        own = stage_of(rel)
        if own is None or len(rel.parts) < 2:
            problems.append(f"{rel}: not in a stage folder ({', '.join(STAGES)})")
            continue
        for line_no, target in ((m.string.count("\n", 0, m.start()) + 1, m.group(1))
                                for m in INCLUDE.finditer(path.read_text())):
            target_path = pathlib.PurePosixPath(target)
            if len(target_path.parts) < 2 or not (src / target_path).exists():
                problems.append(f"{rel}:{line_no}: include \"{target}\" does not name its folder")
                continue
            theirs = stage_of(target_path)
            if theirs is None or theirs > own:
                problems.append(f"{rel}:{line_no}: {rel.parts[0]}/ includes \"{target}\", a stage "
                                f"above it")
    for p in problems:
        print(p)
    print(f"check_includes: {len(files)} files, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
