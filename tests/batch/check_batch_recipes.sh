#!/usr/bin/env bash
# Usage: check_batch_recipes.sh ACANTHUS SOURCE_DIR WORK
# The recipes of docs/batch.md, run as written there:
# - the Kubernetes Indexed Job: its YAML (taken from the page) is a valid batch/v1 Indexed Job
#   whose --shards equals its completions; its container command runs once per index with
#   JOB_COMPLETION_INDEX set, as the Job's pods would (no cluster here), and the merged
#   reports hold every job, passed, with the same files as one run;
# - GNU parallel with --sshloginfile: the page's parallel line with a login file of ':' (the
#   local machine, as parallel spells it) renders the four shards; merged, they equal one run.
set -u
acanthus="$1"; source="$2"; work="$3"
doc="$source/docs/batch.md"
rm -rf "$work"; mkdir -p "$work/bin"; cd "$work" || exit 1
fail() { echo "FAIL: $*"; cat log 2>/dev/null; exit 1; }
command -v parallel >/dev/null || fail "GNU parallel is not installed (scripts/install-deps)"
# The recipes call `acanthus` by name, as on a render node.
ln -s "$acanthus" bin/acanthus
export PATH="$work/bin:$PATH"

# A manifest named as in the recipes: 12 jobs, tiny renders.
cat > renders.toml <<TOML
[[job]]
rules = "$source/rules/dots.acr"
panels = ["rect:60,40", "circle:25", "$source/examples/panels/heart.svg"]
seeds = [1, 2]
params = { rim = [0.1, 0.3] }
args = ["--resolution", "64", "--width", "100"]
formats = ["svg"]
TOML
acanthus batch renders.toml -q --output-dir whole --check refs --update-references 2>log ||
  fail "writing the references"
acanthus batch renders.toml -q --output-dir whole --check refs --report whole-report 2>log ||
  fail "one run against the references"

jobs_of() {  # the jobs of a report: index, output, passed (status says rendered or up to date)
  python3 - "$1" <<'PY'
import json, sys
for r in json.load(open(sys.argv[1]))["results"]:
    print(r["index"], r["output"], r["passed"])
PY
}
jobs_of whole-report/report.json > whole-jobs.txt
[ "$(wc -l < whole-jobs.txt)" -eq 12 ] || fail "the whole run should hold 12 jobs"

# --- Kubernetes Indexed Job -------------------------------------------------------------------
python3 - "$doc" job.sh <<'PY' || fail "the Indexed Job manifest of docs/batch.md"
import re, shlex, sys, yaml
text = open(sys.argv[1]).read()
blocks = re.findall(r"```yaml\n(.*?)```", text, re.S)
jobs = [yaml.safe_load(b) for b in blocks]
jobs = [j for j in jobs if isinstance(j, dict) and j.get("kind") == "Job"]
assert len(jobs) == 1, f"{len(jobs)} Job manifests on the page"
job = jobs[0]
assert job["apiVersion"] == "batch/v1", job["apiVersion"]
spec = job["spec"]
assert spec["completionMode"] == "Indexed"
completions = spec["completions"]
assert isinstance(completions, int) and completions > 0
assert 0 < spec.get("parallelism", completions) <= completions
pod = spec["template"]["spec"]
assert pod["restartPolicy"] in ("Never", "OnFailure"), "an Indexed Job's pods may not restart Always"
(container,) = pod["containers"]
assert container["image"] and container["name"]
command = container["command"] + container["args"]
assert command[:2] == ["sh", "-c"] and len(command) == 3, command
script = command[2]
assert "--shard auto" in script and f"--shards {completions}" in script, \
    f"--shards must equal completions ({completions}): {script}"
assert "$JOB_COMPLETION_INDEX" in script, "each index needs its own report directory"
mounts = {m["name"]: m["mountPath"] for m in container.get("volumeMounts", [])}
volumes = {v["name"] for v in pod.get("volumes", [])}
assert set(mounts) <= volumes, "a volumeMount without its volume"
assert container.get("workingDir") in mounts.values(), "the working directory is the shared volume"
with open(sys.argv[2], "w") as f:
    f.write(f"COMPLETIONS={completions}\nSCRIPT={shlex.quote(script)}\n")
PY
# shellcheck disable=SC1091
. ./job.sh
mkdir k8s && cp -r renders.toml refs k8s/ && cd k8s || exit 1
for ((i = 0; i < COMPLETIONS; i++)); do
  JOB_COMPLETION_INDEX=$i sh -c "$SCRIPT" 2>"../log-k8s-$i" || fail "index $i of the Indexed Job"
done
reports=()
for ((i = 0; i < COMPLETIONS; i++)); do reports+=("report-$i"); done
acanthus batch report "${reports[@]}" -o report 2>../log || fail "merging the Job's reports"
jobs_of report/report.json > ../k8s-jobs.txt
cd .. || exit 1
diff whole-jobs.txt k8s-jobs.txt || fail "the Job's merged report differs from one run's"
diff -r whole/out k8s/out >/dev/null || fail "the Job's files differ from one run's"
grep -q 'failures="0"' k8s/report/junit.xml || fail "the Job's JUnit report has failures"

# --- GNU parallel over an sshloginfile ----------------------------------------------------------
line=$(python3 - "$doc" <<'PY'
import re, sys
blocks = [b.replace("\\\n", " ") for b in re.findall(r"```sh\n(.*?)```", open(sys.argv[1]).read(), re.S)]
lines = [l for b in blocks for l in b.splitlines() if l.startswith("parallel --sshloginfile hosts.txt")]
assert len(lines) == 1, lines
print(" ".join(lines[0].split()))
PY
) || fail "no GNU parallel recipe with --sshloginfile in docs/batch.md"
mkdir ssh && cp -r renders.toml refs ssh/ && cd ssh || exit 1
echo ':' > hosts.txt  # ':' is the local machine, without ssh
echo "$line"
eval "$line" 2>../log || fail "the parallel recipe with --sshloginfile"
acanthus batch report report-0 report-1 report-2 report-3 -o report 2>../log || fail "merging"
jobs_of report/report.json > ../ssh-jobs.txt
cd .. || exit 1
diff whole-jobs.txt ssh-jobs.txt || fail "parallel's merged report differs from one run's"
diff -r whole/out ssh/out >/dev/null || fail "parallel's files differ from one run's"
echo ok
