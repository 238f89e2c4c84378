#!/usr/bin/env bash
# Usage: check_batch_shards.sh ACANTHUS SOURCE_DIR WORK
# Two shards run side by side by GNU parallel give the same files, byte for byte, as one run;
# their reports merged by `acanthus batch report` hold every job; --shard auto reads Slurm's
# and Kubernetes' variables.
set -u
acanthus="$1"; source="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
fail() { echo "FAIL: $*"; cat log 2>/dev/null; exit 1; }
command -v parallel >/dev/null || fail "GNU parallel is not installed (scripts/install-deps)"
cat > batch.toml <<TOML
[[job]]
rules = "$source/rules/dots.acr"
panels = ["rect:60,40", "circle:25", "$source/examples/panels/heart.svg"]
seeds = [1, 2]
params = { rim = [0.1, 0.3] }
args = ["--resolution", "64", "--width", "100"]
formats = ["svg", "png"]
TOML
"$acanthus" batch batch.toml -q --output-dir whole --report whole-report 2>log || fail "one run"
parallel --halt now,fail=1 "$acanthus" batch batch.toml -q --shard {}/2 --output-dir sharded \
  --report report-{} ::: 0 1 2>log || fail "two shards through GNU parallel"
[ "$(find whole/out -type f | wc -l)" -eq 24 ] || fail "expected 24 outputs"
diff -r whole/out sharded/out >/dev/null || fail "the shards' files differ from one run's"
grep -q 'tests="12"' report-0/junit.xml || fail "shard 0 should hold 12 jobs"
"$acanthus" batch report report-0 report-1 -o merged 2>log || fail "batch report"
python3 - merged/report.json whole-report/report.json <<'PY' || fail "merged report differs from the whole run's"
import json, sys
def jobs(path):
    return [(r["index"], r["output"], r["status"], r["passed"]) for r in json.load(open(path))["results"]]
merged, whole = jobs(sys.argv[1]), jobs(sys.argv[2])
assert len(merged) == 24, len(merged)
assert [m[:2] for m in merged] == [w[:2] for w in whole]
PY
grep -q 'tests="24"' merged/junit.xml || fail "merged JUnit"
# --shard auto: a Slurm array task (IDs from 1) and a Kubernetes Indexed Job.
SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=3 \
  "$acanthus" batch batch.toml -q --shard auto --output-dir slurm 2>log || fail "Slurm shard"
grep -q "^batch: 8 jobs (shard 1/3 of 24)" log || fail "Slurm task 2 of 1-3 should be shard 1/3"
JOB_COMPLETION_INDEX=1 "$acanthus" batch batch.toml -q --shard auto --shards 4 --output-dir k8s 2>log \
  || fail "Indexed Job shard"
grep -q "^batch: 6 jobs (shard 1/4 of 24)" log || fail "JOB_COMPLETION_INDEX=1 should be shard 1/4"
JOB_COMPLETION_INDEX=1 "$acanthus" batch batch.toml --shard auto 2>log; [ $? -eq 2 ] || fail "auto without --shards"
echo ok
