#!/usr/bin/env bash
# Usage: check_large_input.sh ACANTHUS
# 50 MB inputs (garbage outside sections, one huge body, NUL bytes, an unterminated comment)
# give a bounded report and exit 1, quickly, without crashing.
set -u
acanthus="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
size=$((50 * 1024 * 1024))

yes 'stray text $$ " /* %rule --> { } ' | head -c $size >"$work/stray.acr"
{ printf '%%source\n'; yes 'int x; // $$ $goal "%%endsource"' | head -c $size; } >"$work/body.acr"
{ printf '%%element\nseed point\n%%endelement\n/*'; head -c $size /dev/zero; } >"$work/comment.acr"
{ printf '%%rule\nseed -->\n{\n'; yes '$0 $$1 $x(3) $(9)' | head -c $size; } >"$work/dollars.acr"

for f in stray body comment dollars; do
  start=$(date +%s)
  "$acanthus" check "$work/$f.acr" >/dev/null 2>"$work/$f.err"
  rc=$?
  [ $rc -eq 1 ] || fail "$f.acr exited with $rc"
  lines=$(wc -l <"$work/$f.err")
  [ "$lines" -lt 400 ] || fail "$f.acr: $lines lines of diagnostics"
  echo "ok: $f.acr ($(( $(date +%s) - start )) s, $lines lines)"
done
