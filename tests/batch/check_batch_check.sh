#!/usr/bin/env bash
# Usage: check_batch_check.sh ACANTHUS SOURCE_DIR WORK
# --check REFDIR: --update-references writes the references, an unchanged run matches them, a
# changed reference gives exit 1, a diff picture, a JUnit failure and an HTML report (loaded
# in headless Chromium when one is installed).
set -u
acanthus="$1"; source="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
fail() { echo "FAIL: $*"; cat log 2>/dev/null; exit 1; }
cat > batch.toml <<TOML
[[job]]
rules = "$source/rules/dots.acr"
panels = ["rect:60,40", "circle:25"]
seeds = [3]
args = ["--resolution", "64", "--width", "100"]
formats = ["svg", "png"]
TOML
"$acanthus" batch batch.toml -q --check refs --update-references 2>log || fail "--update-references"
[ "$(find refs -type f | wc -l)" -eq 4 ] || fail "expected 4 references"
cmp -s refs/out/dots/rect-60x40-3.svg out/dots/rect-60x40-3.svg || fail "reference not written"
"$acanthus" batch batch.toml -q --check refs --report report 2>log || fail "an unchanged run should match"
grep -q "0 differ from the references" log || fail "summary of a matching run"
grep -q 'failures="0" errors="0"' report/junit.xml || fail "JUnit of a matching run"

# Another picture as the reference of one PNG; a changed byte in one SVG.
cp out/dots/circle-25-3.png refs/out/dots/rect-60x40-3.png
sed -i 's/<svg /<svg data-x="1" /' refs/out/dots/circle-25-3.svg
"$acanthus" batch batch.toml -q --check refs --report report 2>log; rc=$?
[ $rc -eq 1 ] || fail "a changed reference should give exit 1, got $rc"
grep -q "2 differ from the references" log || fail "summary with differences"
grep -q "^DIFFERS out/dots/rect-60x40-3.png" log || fail "the PNG difference is not named"
[ -s report/out/dots/rect-60x40-3.png.diff.png ] || fail "no diff picture"
[ -s report/out/dots/rect-60x40-3.png.new.png ] || fail "no copy of the new picture"
[ -s report/out/dots/rect-60x40-3.png.reference.png ] || fail "no copy of the reference"
grep -q 'tests="4" failures="2" errors="0"' report/junit.xml || fail "JUnit counts"
grep -q '<testcase classname="acanthus.batch.dots" name="out/dots/rect-60x40-3.png"' report/junit.xml || fail "JUnit test case"
python3 - report/junit.xml <<'PY' || fail "junit.xml is not well-formed XML"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert len(root.findall(".//failure")) == 2
PY
grep -q '<p id="summary">4 jobs: 2 passed, 2 differ, 0 failed' report/index.html || fail "HTML summary"
# Failures first: the first data row is a mismatch.
first=$(grep -o 'class="\(passed\|differs\|failed\)"' report/index.html | head -1)
[ "$first" = 'class="differs"' ] || fail "the report does not put failures first ($first)"
if command -v chromium >/dev/null 2>&1; then
  timeout 120 chromium --headless --no-sandbox --disable-gpu --dump-dom "file://$work/report/index.html" \
    > dom.html 2>/dev/null
  grep -q 'rect-60x40-3.png.diff.png' dom.html || fail "Chromium did not load the report"
  echo "ok: report loaded in headless Chromium"
fi
# --update-references puts things right.
"$acanthus" batch batch.toml -q --check refs --update-references 2>log || fail "second --update-references"
"$acanthus" batch batch.toml -q --check refs --report report 2>log || fail "after updating, the run should match"
echo ok
