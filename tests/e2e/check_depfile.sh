#!/usr/bin/env bash
# Usage: check_depfile.sh ACANTHUS WORK
# `acanthus compile --depfile`: the rule file and its imports, recursively, each once, as one
# Make rule for the C++ file (paths with spaces, '#' and '$' escaped as Make and Ninja read
# them); no depfile without -o FILE; a rule file with errors or an unwritable depfile leaves
# neither file.
set -u
acanthus="$1"; work="$2"
rm -rf "$work"; mkdir -p "$work/lib dir" "$work/more"; cd "$work" || exit 1
fail() { echo "FAIL: $*"; cat log 2>/dev/null; exit 1; }
printf '%%import "shades"\n%%import "more/tint"\n%%element\nseed point\n%%endelement\n' > main.acr
printf '%%import "tint"\n// shades\n' > "lib dir/shades.acr"
printf '// tint\n' > "lib dir/tint.acr"
printf '%%import "cost$ #1"\n' > more/tint.acr
printf '// money\n' > 'more/cost$ #1.acr'

"$acanthus" compile main.acr -o main.cpp --depfile main.d -I "lib dir" 2>log || fail "compile --depfile"
[ -s main.cpp ] || fail "no C++ written"
expected="main.cpp: \\
  $work/main.acr \\
  $work/lib\\ dir/shades.acr \\
  $work/lib\\ dir/tint.acr \\
  $work/more/tint.acr \\
  $work/more/cost\$\$\\ \\#1.acr"
[ "$(cat main.d)" = "$expected" ] || { echo "expected:"; echo "$expected"; echo "got:"; cat main.d; fail "depfile"; }
# Make reads it back: only the newest import is newer than the target.
printf 'include main.d\nmain.cpp:\n\techo rebuilt > rebuilt\n' > Makefile
find . -name '*.acr' -exec touch -d 2000-01-01 {} + && touch -d 2000-01-02 main.cpp
touch 'more/cost$ #1.acr'
make -s 2>log >/dev/null || fail "make could not read the depfile"
[ -s rebuilt ] || fail "make did not rebuild after touching an import"

rm -f out.cpp
"$acanthus" compile main.acr -o - --depfile out.d -I "lib dir" >/dev/null 2>log; rc=$?
[ $rc -eq 2 ] || fail "--depfile with -o - should exit 2, got $rc"
grep -q -- "--depfile needs -o FILE" log || fail "message for -o -"
[ -e out.d ] && fail "a depfile was written for -o -"
printf '%%element\nseed point\n%%endelement\n%%rule\nseed --> nothing\n{ return SUCCESS; }\n%%endrule\n' > broken.acr
"$acanthus" compile broken.acr -o broken.cpp --depfile broken.d 2>log; rc=$?
[ $rc -eq 1 ] || fail "a broken rule file should exit 1, got $rc"
[ -e broken.cpp ] || [ -e broken.d ] && fail "a broken rule file left output"
"$acanthus" compile main.acr -o new.cpp --depfile nowhere/new.d -I "lib dir" 2>log; rc=$?
[ $rc -eq 1 ] || fail "an unwritable depfile should exit 1, got $rc"
grep -q "nowhere/new.d" log || fail "the unwritable depfile is not named"
[ -e new.cpp ] && fail "the C++ was left without its depfile"
"$acanthus" compile main.acr -o new.cpp --depfile "lib dir/tint.acr" -I "lib dir" 2>log; rc=$?
[ $rc -eq 2 ] || fail "a depfile over an import should exit 2, got $rc"
[ "$(cat "lib dir/tint.acr")" = "// tint" ] || fail "the import was overwritten"
echo ok
