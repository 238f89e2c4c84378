#!/usr/bin/env bash
# Usage: check_error.sh ACANTHUS errors/NAME.acr
# The diagnostics for NAME.acr must equal NAME.expected byte for byte, with exit status 1.
# ACANTHUS_REGENERATE=1 rewrites NAME.expected instead.
set -u
acanthus="$1"
file="$2"
expected="${file%.acr}.expected"
actual="$(mktemp)"
trap 'rm -f "$actual"' EXIT
"$acanthus" check "$file" -I errors/lib 2>"$actual" >/dev/null
rc=$?
if [ "${ACANTHUS_REGENERATE:-0}" = 1 ]; then
  cp "$actual" "$expected"
  echo "regenerated $expected"
  exit 0
fi
if [ "$rc" -ne 1 ]; then
  echo "FAIL: '$file' exited with $rc, expected 1"
  cat "$actual"
  exit 1
fi
if ! cmp -s "$actual" "$expected"; then
  echo "FAIL: diagnostics for '$file' differ from '$expected' (ACANTHUS_REGENERATE=1 rewrites them):"
  diff -a "$expected" "$actual"
  exit 1
fi
echo "ok: $file"
