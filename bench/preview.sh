#!/usr/bin/env bash
# Usage: bench/preview.sh BUILD_DIR
# `acanthus preview` edit-to-picture: for every pattern in rules/, at its default size, the time
# from saving a changed rule body to the new revision in /status.json (compile, build with the
# precompiled prelude, grow, render), and to the new picture painted by the page in headless
# Chromium (tests/preview/paint_time.js, puppeteer-core from its package-lock.json): the median of
# 3 edits after a first render (and its units, compiled after its picture). Last line: one JSON object, {"seconds": {"dots": ..., ...},
# "max": ..., "build_cpu_seconds": {...}, "grow_cpu_seconds": {...}, "painted_seconds": {...},
# "painted_max": ...} (server times only without Chromium); the *_cpu_ times are processor
# seconds of the build's commands and of the program's run, which the load does not stretch.
# ACANTHUS_BENCH_TIMELINE=1 prints each save's steps (/status.json "timeline" and the page's), in
# ms from the file's write; ACANTHUS_BENCH_PATTERNS=flowers,dots benches only those patterns.
# needs: acanthus acanthus_runtime acanthus_stdlib
set -euo pipefail
BUILD="$1"
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
exec python3 "$ROOT/bench/preview_edit.py" "$BUILD/compiler/acanthus" "$ROOT"
