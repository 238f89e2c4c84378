#!/usr/bin/env bash
# Usage: check_param_range.sh ACANTHUS
# A declared range `in [LO, HI]` at run time: --list-params shows it (a fifth column, only when
# some parameter has a range), --param refuses a value outside it (exit 1, the range named),
# accepts the bounds themselves.
set -u
acanthus="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$acanthus" build golden/param_range.acr -o "$work/param_range" || fail "build"
out="$("$work/param_range" --list-params)"
expected='name    type         default  current  range
leaf    double       3.0      3        [1, 6]
count   int          4        4        [-2, 100]
spread  float        0.25     0.25     [0, 1e1]
show    bool         false    false    -
name    std::string  "leafy"  leafy    -'
[ "$out" = "$expected" ] || fail "--list-params printed:
$out
expected:
$expected"
msg="$("$work/param_range" --param leaf=7 --list-params 2>&1)"; rc=$?
[ $rc -eq 1 ] || fail "leaf=7 exited $rc"
[ "$msg" = "param_range: error: bad value for parameter 'leaf' (double): '7' is outside the declared range [1, 6]" ] ||
  fail "leaf=7 said: $msg"
msg="$("$work/param_range" --param count=-3 --list-params 2>&1)"; rc=$?
[ $rc -eq 1 ] && [[ "$msg" == *"'-3' is outside the declared range [-2, 100]"* ]] || fail "count=-3: $rc $msg"
"$work/param_range" --param leaf=1 --param leaf=6 --param count=100 --param spread=10 --list-params >/dev/null ||
  fail "the bounds themselves are inside the range"
# Without any range the table keeps its four columns.
cat > "$work/plain.acr" <<'EOF'
%param double size = 3.0;
%element seed point
%endelement
%rule
seed -->
{
    return FAILURE;
}
%endrule
EOF
"$acanthus" build "$work/plain.acr" -o "$work/plain" || fail "build plain"
[ "$("$work/plain" --list-params | head -n 1)" = "name  type    default  current" ] ||
  fail "four columns without ranges: $("$work/plain" --list-params | head -n 1)"
echo "ok: parameter ranges at run time"
