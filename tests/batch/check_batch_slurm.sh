#!/usr/bin/env bash
# Usage: check_batch_slurm.sh ACANTHUS SOURCE_DIR WORK
# A real single-node Slurm cluster, started and stopped here: a munge key and munged, a
# slurm.conf for this machine (2 CPUs, unprivileged ports), slurmctld and slurmd, all in WORK;
# then the recipe of docs/batch.md: an array job of three tasks, each `acanthus batch
# MANIFEST --shard auto --check refs --report report-$SLURM_ARRAY_TASK_ID`, and `acanthus
# batch report` merging them. Every daemon started here is stopped on any exit. Exits 77
# (skipped) with the reason when Slurm cannot run here: not root, not installed, or the
# daemons do not come up.
set -u
acanthus="$1"; source="$2"; work="$3"
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*"; for f in log "$work"/*.log; do [ -s "$f" ] && { echo "--- $f"; tail -20 "$f"; }; done; exit 1; }
[ "$(id -u)" -eq 0 ] || skip "slurmd needs root to run jobs as their user (CI runs as root)"
for tool in munged mungekey slurmctld slurmd sbatch sinfo; do
  command -v "$tool" >/dev/null || PATH="$PATH:/usr/sbin" command -v "$tool" >/dev/null ||
    skip "$tool is not installed (scripts/install-deps: munge, slurmctld, slurmd, slurm-client)"
done
export PATH="$PATH:/usr/sbin"
rm -rf "$work"; mkdir -p "$work"/{state,spool}; cd "$work" || exit 1
chmod 755 "$work"  # munged wants its socket reachable

pids=()
stop_daemons() {
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
  done
}
trap stop_daemons EXIT

# Ports no one else is likely to use, different for each run.
base=$(( 20000 + RANDOM % 20000 ))
node=$(hostname -s)
mungekey -c -k "$work/munge.key" >/dev/null 2>&1 ||
  { dd if=/dev/urandom of="$work/munge.key" bs=1024 count=1 2>/dev/null; chmod 400 "$work/munge.key"; }
munged -F -f --key-file="$work/munge.key" --socket="$work/munge.socket" \
  --pid-file="$work/munged.pid" --log-file="$work/munged.log" --seed-file="$work/munge.seed" \
  >munged.out 2>&1 &
pids+=($!)
cat > slurm.conf <<CONF
ClusterName=acanthus-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$base
SlurmdPort=$((base + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$work/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=10 State=UP
CONF
export SLURM_CONF="$work/slurm.conf"
for _ in $(seq 50); do [ -S "$work/munge.socket" ] && break; sleep 0.1; done
[ -S "$work/munge.socket" ] || skip "munged did not start: $(tail -3 munged.log 2>/dev/null)"
slurmctld -D -c -i >slurmctld.out 2>&1 &
pids+=($!)
slurmd -D -N "$node" >slurmd.out 2>&1 &
pids+=($!)
up=""
for _ in $(seq 60); do
  state=$(timeout 5 sinfo -h -N -o %T 2>/dev/null | head -1)
  case "$state" in idle*|mix*|alloc*) up=1; break ;; esac
  sleep 1
done
[ -n "$up" ] || skip "the single-node cluster did not come up (node state '${state:-none}'): $(tail -3 slurmctld.log slurmd.log slurmctld.out slurmd.out 2>/dev/null | tr '\n' ' ')"

cat > batch.toml <<TOML
[[job]]
rules = "$source/rules/dots.acr"
panels = ["rect:60,40", "circle:25", "$source/examples/panels/heart.svg"]
seeds = [1, 2]
args = ["--resolution", "64", "--width", "100"]
formats = ["svg", "png"]
TOML
"$acanthus" batch batch.toml -q --output-dir whole --check refs --update-references 2>log ||
  fail "references"
cat > render.sh <<SCRIPT
#!/bin/sh
#SBATCH --job-name=acanthus-batch
#SBATCH --array=0-2
exec "$acanthus" batch batch.toml --shard auto --jobs 1 -q --check refs --output-dir sharded \\
  --report "report-\$SLURM_ARRAY_TASK_ID"
SCRIPT
timeout 240 sbatch --wait --chdir="$work" --output="$work/task-%a.log" render.sh >log 2>&1 ||
  fail "the array job failed or timed out"
for k in 0 1 2; do
  grep -q "^batch: 4 jobs (shard $k/3 of 12)" "task-$k.log" || fail "task $k did not run shard $k/3"
done
[ "$(find sharded/out -type f | wc -l)" -eq 12 ] || fail "expected 12 outputs from the array"
diff -r whole/out sharded/out >/dev/null || fail "the array's files differ from one run's"
"$acanthus" batch report report-0 report-1 report-2 -o merged 2>log || fail "batch report"
grep -q 'tests="12" failures="0" errors="0"' merged/junit.xml || fail "merged JUnit"
grep -q '<p id="summary">12 jobs: 12 passed' merged/index.html || fail "merged HTML summary"
echo ok
