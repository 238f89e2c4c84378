#!/usr/bin/env bash
# Usage: check_appendix_a.sh ACANTHUS CXX RUNTIME_INCLUDE RULES_DIR
# The two rule files of Appendix A (rules/dots.acr, rules/flowers.acr; the copies in golden/
# when rules/ does not have them) compile to C++ that the C++ compiler accepts without warnings.
set -u
acanthus="$1"; cxx="$2"; include="$3"; rules="$4"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for name in dots flowers; do
  src="$rules/$name.acr"
  [ -f "$src" ] || src="golden/appendix_$name.acr"
  if ! "$acanthus" compile "$src" -o "$work/$name.cpp"; then
    echo "FAIL: acanthus compile $src"; status=1; continue
  fi
  for main in "" --no-main; do
    "$acanthus" compile "$src" $main -o "$work/$name$main.cpp" || { status=1; continue; }
    if ! "$cxx" -std=c++20 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$include" "$work/$name$main.cpp"; then
      echo "FAIL: g++ rejects the C++ generated from $src $main"; status=1
    fi
  done
  grep -q '^int main(int argc, char\*\* argv)' "$work/$name.cpp" || { echo "FAIL: no main() for $src"; status=1; }
  grep -q 'acanthus_pattern()' "$work/$name--no-main.cpp" || { echo "FAIL: --no-main exports nothing"; status=1; }
  [ $status -eq 0 ] && echo "ok: $src"
done
exit $status
