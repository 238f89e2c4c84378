#!/usr/bin/env bash
# Usage: check_build_run.sh ACANTHUS RULES_DIR
# `acanthus build` turns the Appendix A patterns into programs that grow and render an SVG;
# `acanthus run` builds once into its cache and reuses the executable the second time.
set -u
acanthus="$1"; rules="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
for name in dots flowers; do
  src="$rules/$name.acr"
  [ -f "$src" ] || src="golden/appendix_$name.acr"
  "$acanthus" build "$src" -o "$work/$name" || fail "acanthus build $src"
  "$work/$name" --region rect:60,40 --rng-seed 1 -o "$work/$name.svg" || fail "$name exited with $?"
  grep -q '<svg' "$work/$name.svg" || fail "$name.svg is not SVG"
  echo "ok: build $src"
done
export ACANTHUS_CACHE_DIR="$work/cache"
"$acanthus" run "$rules/dots.acr" --region rect:60,40 -o "$work/run1.svg" || fail "acanthus run"
"$acanthus" run "$rules/dots.acr" --region rect:60,40 -o "$work/run2.svg" || fail "acanthus run (cached)"
[ "$(ls "$work/cache" | wc -l)" -eq 1 ] || fail "the cache should hold exactly one executable"
cmp -s "$work/run1.svg" "$work/run2.svg" || fail "two runs differ"
# A C++ error in a body fails the build with the compiler's message pointing into the .acr.
"$acanthus" build cxx_errors/body_errors.acr -o "$work/broken" 2>"$work/broken.err"
[ $? -eq 1 ] || fail "a build with C++ errors should exit 1"
grep -q '^cxx_errors/body_errors.acr:[0-9]*:[0-9]*: error' "$work/broken.err" || fail "errors not in the .acr"
[ -e "$work/broken" ] && fail "a failed build left an executable"
echo ok
