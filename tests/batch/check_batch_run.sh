#!/usr/bin/env bash
# Usage: check_batch_run.sh ACANTHUS SOURCE_DIR WORK
# acanthus batch over a small product: every job rendered, a second run skips them all, a changed
# input (a panel, a rule file's import) redoes only its jobs, --force redoes everything, a
# failing job does not stop the others (exit 1, its message in the summary), a bad manifest
# exits 2 with its line and column.
set -u
acanthus="$1"; source="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
fail() { echo "FAIL: $*"; cat log 2>/dev/null; exit 1; }
cp "$source/examples/panels/heart.svg" panel.svg
cat > batch.toml <<TOML
[[job]]
rules = "$source/rules/dots.acr"
panels = ["panel.svg", "rect:60,40"]
seeds = [1, 2]
params = { max_radius = [2.0, 3.5] }
args = ["--resolution", "64", "--width", "120"]
formats = ["svg", "png"]
output = "out/{rule}/{panel}-{seed}-{params}.{ext}"
TOML
"$acanthus" batch batch.toml --jobs 2 2>log; rc=$?
[ $rc -eq 0 ] || fail "first run exited $rc"
[ "$(find out -type f | wc -l)" -eq 16 ] || fail "expected 16 outputs"
[ -s out/dots/rect-60x40-2-max_radius-3.5.png ] || fail "a built-in panel's output name"
grep -q "16 rendered, 0 up to date, 0 failed" log || fail "summary of the first run"
grep -q "^batch: \[16/16\]" log || fail "no progress lines"

start=$(date +%s%N)
"$acanthus" batch batch.toml --jobs 2 2>log || fail "second run"
elapsed=$(( ($(date +%s%N) - start) / 1000000 ))
grep -q "0 rendered, 16 up to date" log || fail "the second run redid jobs"
[ $elapsed -lt 1000 ] || fail "the second run took $elapsed ms"

# A changed panel file redoes only the jobs over it.
sed -i 's/<svg /<svg data-changed="1" /' panel.svg
"$acanthus" batch batch.toml --jobs 2 2>log || fail "third run"
grep -q "8 rendered, 8 up to date" log || fail "a changed panel should redo its 8 jobs"
# A deleted output is rendered again.
rm out/dots/panel-1-max_radius-2.svg
"$acanthus" batch batch.toml -q 2>log || fail "fourth run"
grep -q "1 rendered, 15 up to date" log || fail "a deleted output should be redone"
"$acanthus" batch batch.toml --force -q 2>log || fail "--force"
grep -q "16 rendered, 0 up to date" log || fail "--force should redo everything"

# A rule file's import counts with its contents (the list `acanthus compile --depfile` writes),
# even where a change generates no different C++ (a comment).
mkdir -p lib
printf '%%import "lib/dots_body"\n' > imports.acr
cp "$source/rules/dots.acr" lib/dots_body.acr
printf '[[job]]\nrules = "imports.acr"\npanels = "rect:40,30"\nargs = ["--resolution", "64"]\n' > imports.toml
"$acanthus" batch imports.toml -q 2>log || fail "a rule file with an import"
"$acanthus" batch imports.toml -q 2>log || fail "a rule file with an import, again"
grep -q "0 rendered, 1 up to date" log || fail "an unchanged import redid its job"
echo "// a comment changes no C++" >> lib/dots_body.acr
"$acanthus" batch imports.toml -q 2>log || fail "after changing the import"
grep -q "1 rendered, 0 up to date" log || fail "a changed import did not redo its job"

# A parameter outside its declared range fails its jobs only.
cat >> batch.toml <<TOML

[[job]]
rules = "$source/rules/dots.acr"
panels = "rect:40,40"
params = { max_radius = [2.0, 50.0] }
args = ["--resolution", "64"]
output = "bad/{params}.svg"
TOML
"$acanthus" batch batch.toml -q 2>log; rc=$?
[ $rc -eq 1 ] || fail "a failing job should give exit 1, got $rc"
grep -q "1 rendered, 16 up to date, 1 failed" log || fail "summary with a failure"
grep -q "^FAILED bad/max_radius-50.svg" log || fail "the failure is not named"
grep -q "outside the declared range" log || fail "the program's message is not shown"
[ -s bad/max_radius-2.svg ] || fail "the other job of the failing table did not run"
[ -e bad/max_radius-50.svg ] && fail "a failed job left an output"

# A rule file with errors fails its jobs with the compiler's diagnostics.
printf '%%element\nseed point\n%%endelement\n%%rule\nseed --> nothing\n{ return SUCCESS; }\n%%endrule\n' > broken.acr
printf '[[job]]\nrules = "broken.acr"\npanels = "rect:20,20"\n' > broken.toml
"$acanthus" batch broken.toml -q 2>log; rc=$?
[ $rc -eq 1 ] || fail "a broken rule file should give exit 1, got $rc"
grep -q "broken.acr:5" log || fail "the rule file's diagnostic is not shown"

# Bad manifests: exit 2 with file:line:col, before any work.
printf '[[job]]\nrules = "%s/rules/dots.acr"\npanels = "rect:20,20"\nformat = "svg"\n' "$source" > typo.toml
"$acanthus" batch typo.toml 2>log; rc=$?
[ $rc -eq 2 ] || fail "an unknown key should give exit 2, got $rc"
grep -q "^typo.toml:4:1: error: unknown key 'format'" log || fail "unknown key message"
[ -e out-typo ] && fail "work started"
printf '[[job]]\nrules = "none.acr"\npanels = "rect:20,20"\n' > missing.toml
"$acanthus" batch missing.toml 2>log; [ $? -eq 2 ] || fail "a missing rule file should give exit 2"
grep -q "^missing.toml:2:9: error: missing rule file 'none.acr'" log || fail "missing file message"
"$acanthus" batch nowhere.toml 2>log; [ $? -eq 2 ] || fail "a missing manifest should give exit 2"
"$acanthus" batch batch.toml --shard 2/2 2>log; [ $? -eq 2 ] || fail "--shard 2/2 should give exit 2"
"$acanthus" batch batch.toml --update-references 2>log; [ $? -eq 2 ] || fail "--update-references alone"
echo ok
