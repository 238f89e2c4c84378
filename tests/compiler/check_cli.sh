#!/usr/bin/env bash
# Usage: check_cli.sh ACANTHUS
# Exit statuses, --version/--help, no partial output on error, output to stdout.
set -u
acanthus="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$acanthus" --version | grep -Eq '^acanthus [0-9]+\.[0-9]+' || fail "--version"
"$acanthus" --help | grep -q compile || fail "--help"
"$acanthus" >/dev/null 2>&1; [ $? -eq 2 ] || fail "no subcommand should exit 2"
"$acanthus" frobnicate >/dev/null 2>&1; [ $? -eq 2 ] || fail "unknown subcommand should exit 2"
"$acanthus" build golden/appendix_dots.acr -O 9 >/dev/null 2>&1; [ $? -eq 2 ] || fail "bad -O should exit 2"

"$acanthus" check golden/appendix_flowers.acr || fail "check of a good file"
"$acanthus" check "$work/missing.acr" 2>"$work/err"; [ $? -eq 1 ] || fail "missing file should exit 1"
grep -q "cannot read '$work/missing.acr'" "$work/err" || fail "missing file message"
"$acanthus" check "$work" 2>/dev/null; [ $? -eq 1 ] || fail "a directory should exit 1"

# A good compile writes the file; a failing one leaves it untouched and leaves no temporary.
"$acanthus" compile golden/appendix_dots.acr -o "$work/out.cpp" || fail "compile"
cp "$work/out.cpp" "$work/good.cpp"
"$acanthus" compile errors/unknown_type_rule.acr -o "$work/out.cpp" 2>/dev/null
[ $? -eq 1 ] || fail "compile of a bad file should exit 1"
cmp -s "$work/out.cpp" "$work/good.cpp" || fail "a failed compile changed the output"
"$acanthus" compile errors/unknown_type_rule.acr -o "$work/new.cpp" 2>/dev/null
[ -e "$work/new.cpp" ] && fail "a failed compile created its output"
[ "$(ls -A "$work" | grep -c tmp)" -eq 0 ] || fail "temporary files left behind"

# -o - writes to stdout; the default output is the rule file's stem in the current directory.
"$acanthus" compile golden/appendix_dots.acr -o - | grep -q 'acanthus::run_program' || fail "-o -"
(cd "$work" && "$acanthus" compile "$OLDPWD/golden/appendix_dots.acr") || fail "default output"
[ -s "$work/appendix_dots.cpp" ] || fail "default output name"

# Unwritable output directory.
"$acanthus" compile golden/appendix_dots.acr -o "$work/no/such/dir/x.cpp" 2>/dev/null
[ $? -eq 1 ] || fail "unwritable output should exit 1"
echo ok
