#!/usr/bin/env bash
# Usage: check_body_errors.sh ACANTHUS CXX RUNTIME_INCLUDE
# C++ errors in a rule body, a %draw body, %source and an %element field are reported by the
# C++ compiler at their lines in the .acr file (through #line), and not when #line is off.
set -u
acanthus="$1"; cxx="$2"; include="$3"
src="cxx_errors/body_errors.acr"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$acanthus" compile "$src" -o "$work/out.cpp" || { echo "FAIL: acanthus compile"; exit 1; }
if "$cxx" -std=c++20 -fsyntax-only -I"$include" "$work/out.cpp" 2>"$work/errors.txt"; then
  echo "FAIL: the C++ compiler accepted code with errors"; exit 1
fi
status=0
# Lines marked "// ERROR" in the rule file are where the compiler must point.
for line in $(grep -n '// ERROR' "$src" | cut -d: -f1); do
  if ! grep -q "^$src:$line:[0-9]*: error" "$work/errors.txt"; then
    echo "FAIL: no error reported at $src:$line"; status=1
  fi
done
if grep -q "out.cpp:[0-9]*:[0-9]*: error" "$work/errors.txt"; then
  echo "FAIL: an error was blamed on the generated file"; status=1
fi
"$acanthus" compile "$src" --no-line-directives -o "$work/plain.cpp"
if grep -q '^#line' "$work/plain.cpp"; then echo "FAIL: --no-line-directives left #line"; status=1; fi
if [ $status -ne 0 ]; then cat "$work/errors.txt"; else echo "ok"; fi
exit $status
