#!/usr/bin/env bash
# Usage: check_golden.sh ACANTHUS golden/NAME.acr CXX RUNTIME_INCLUDE
# `acanthus compile` must produce golden/NAME.cpp byte for byte, and the C++ compiler must
# accept it without warnings. ACANTHUS_REGENERATE=1 rewrites golden/NAME.cpp instead.
set -u
acanthus="$1"; file="$2"; cxx="$3"; include="$4"
expected="${file%.acr}.cpp"
actual="$(mktemp --suffix=.cpp)"
trap 'rm -f "$actual"' EXIT
if ! "$acanthus" compile "$file" -I golden/lib -o - >"$actual"; then
  echo "FAIL: acanthus compile '$file' failed"
  exit 1
fi
if [ "${ACANTHUS_REGENERATE:-0}" = 1 ]; then
  cp "$actual" "$expected"
  echo "regenerated $expected"
elif ! cmp -s "$actual" "$expected"; then
  echo "FAIL: generated C++ for '$file' differs from '$expected' (ACANTHUS_REGENERATE=1 rewrites it):"
  diff "$expected" "$actual"
  exit 1
fi
if ! "$cxx" -std=c++20 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$include" -x c++ "$actual"; then
  echo "FAIL: the C++ generated from '$file' does not compile cleanly"
  exit 1
fi
echo "ok: $file"
