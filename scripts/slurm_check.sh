#!/bin/bash
# CTest CohortRunsOnSlurm: examples/slurm_cohort.sh (the README's Slurm
# snippet) on a real one-node Slurm.  Starts munged, slurmctld and slurmd
# directly (no systemd) with a minimal slurm.conf for this host in a temp
# folder, submits the array over 20 small phantom cases, waits, and checks
# that the merged summary.csv is byte for byte a local `pfdm batch` of the
# same manifest; then kills the array mid-run and checks that resubmitting
# it resumes: the finished cases are kept (the same fit.json), the rest
# fitted, the summary again the local one.
#   scripts/slurm_check.sh BUILD_DIR OUT_DIR
# Exits 77 (CTest: skipped), with the reason, when Slurm or munge is not
# installed (apt-get install slurm-wlm munge; with PFDM_SLURM_INSTALL=1 and
# root this script installs them) or its daemons cannot be started here.
set -euo pipefail
build=$(cd "$1" && pwd)
out=$2
here=$(cd "$(dirname "$0")" && pwd)
skip() { echo "skipped: $*"; exit 77; }

# The README shows this very file: the snippet after its mention, checked
# whether or not Slurm runs here.
snippet=$(awk '/`examples\/slurm_cohort.sh`, which/ { found = 1 }
  found && /^```$/ { exit } found && copy { print } found && /^```sh$/ { copy = 1 }' \
  "$here/../README.md")  # README, Cohorts
[ "$snippet" = "$(cat "$here/../examples/slurm_cohort.sh")" ] || {
  echo "README.md's Slurm snippet is not examples/slurm_cohort.sh" >&2
  exit 1
}

missing() {
  for tool in munged slurmctld slurmd sbatch squeue sinfo scontrol; do
    command -v "$tool" > /dev/null || { echo "$tool"; return; }
  done
}
if [ -n "$(missing)" ] && [ "${PFDM_SLURM_INSTALL:-0}" = 1 ] &&
   [ "$(id -u)" = 0 ] && command -v apt-get > /dev/null; then
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q slurm-wlm munge \
    > /dev/null 2>&1 || true
fi
[ -z "$(missing)" ] ||
  skip "$(missing) not installed (apt-get install slurm-wlm munge, or set" \
    "PFDM_SLURM_INSTALL=1 as root)"
[ "$(id -u)" = 0 ] || skip "not root: slurmd must run as root to start jobs"

rm -rf "$out" && mkdir -p "$out"
out=$(cd "$out" && pwd)
run="$out/slurm"
mkdir -p "$run/state" "$run/spool" "$run/munge"
pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill "$pid" 2> /dev/null || true; done
  wait 2> /dev/null || true
}
trap cleanup EXIT

# munge: its own key and socket here, not the system's.
dd if=/dev/urandom of="$run/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$run/munge/munge.key"
chmod 755 "$run/munge"
munged --force --key-file="$run/munge/munge.key" \
  --socket="$run/munge/munge.socket" --pid-file="$run/munge/munged.pid" \
  --log-file="$run/munge/munged.log" --seed-file="$run/munge/munged.seed" ||
  skip "munged did not start ($(tail -n 1 "$run/munge/munged.log" 2> /dev/null))"
pids+=("$(cat "$run/munge/munged.pid")")

host=$(hostname -s)
cpus=$(nproc)
# Ports off the defaults (6817/6818), in case a real Slurm runs here.
port=$((20000 + $$ % 20000))
export SLURM_CONF="$run/slurm.conf"
cat > "$SLURM_CONF" <<CONF
ClusterName=pfdmcheck
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$run/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$run/state
SlurmdSpoolDir=$run/spool/%n
SlurmctldPidFile=$run/slurmctld.pid
SlurmdPidFile=$run/slurmd.pid
SlurmctldLogFile=$run/slurmctld.log
SlurmdLogFile=$run/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
ReturnToService=2
MpiDefault=none
SlurmdTimeout=30
InactiveLimit=0
KillWait=2
NodeName=$host CPUs=$cpus State=UNKNOWN
PartitionName=check Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
slurmctld -D -i > /dev/null 2>&1 &
pids+=($!)
slurmd -D > /dev/null 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  state=$(sinfo -h -o %t 2> /dev/null || true)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] ||
  skip "Slurm did not come up (node '$state'): $(tail -n 2 "$run/slurmctld.log" "$run/slurmd.log" 2> /dev/null | tr '\n' ' ')"

# 20 small cases: phantoms of 3 frames, each a fraction of a second.
cohort="$out/cohort"
mkdir -p "$cohort"
echo "case,points" > "$cohort/cases.csv"
for seed in $(seq 1 20); do
  "$build/pfdm" simulate --seed "$seed" --frames 3 --tags 800 \
    --out "$cohort/case$seed.csv" > /dev/null
  echo "case$seed,case$seed.csv" >> "$cohort/cases.csv"
done
export PATH="$build:$PATH"
script="$here/../examples/slurm_cohort.sh"

# Submits the README's script in folder $1, sbatch's further arguments
# after it (the array's size); prints the job id.
submit() {
  local dir=$1
  shift
  sbatch --parsable --chdir="$dir" --output="$dir/slurm-%A_%a.out" "$@" \
    "$script"
}
wait_for() {
  for _ in $(seq 600); do
    [ -z "$(squeue -h -j "$1" 2> /dev/null)" ] && return 0
    sleep 0.5
  done
  echo "job $1 did not finish in 5 minutes" >&2
  exit 1
}
# The README's final step: the whole manifest's summary, everything skipped.
merge() { (cd "$1" && pfdm batch --manifest cases.csv --out fits > /dev/null); }

(cd "$cohort" && pfdm batch --manifest cases.csv --out local --jobs 2 > /dev/null)
job=$(submit "$cohort" --array=0-4)
wait_for "$job"
merge "$cohort"
cmp "$cohort/local/summary.csv" "$cohort/fits/summary.csv" || {
  echo "the Slurm array's summary differs from the local batch's" >&2
  diff "$cohort/local/summary.csv" "$cohort/fits/summary.csv" >&2 || true
  exit 1
}
done_cases=$(grep -c ',done,' "$cohort/fits/summary.csv")
[ "$done_cases" = 20 ] || { echo "$done_cases of 20 cases done" >&2; exit 1; }
echo "array of 5 tasks over 20 cases: summary equals the local batch's"

# The array killed (SIGKILL) once its first case is done, then resubmitted
# whole: its finished cases are kept, the rest fitted.
resume="$out/resume"
mkdir -p "$resume"
cp "$cohort"/cases.csv "$cohort"/case[0-9]*.csv "$resume/"
job=$(submit "$resume" --array=0-4)
for _ in $(seq 2000); do
  [ -n "$(ls "$resume"/fits/case*/fit.json 2> /dev/null)" ] && break
  sleep 0.02
done
scancel --signal=KILL --full "$job"
wait_for "$job"
before=$(ls "$resume"/fits/case*/fit.json 2> /dev/null | wc -l)
[ "$before" -ge 1 ] && [ "$before" -lt 20 ] ||
  { echo "the killed array had finished $before of 20 cases" >&2; exit 1; }
stamps() { stat -c '%n %Y.%y' $kept; }
kept=$(ls "$resume"/fits/case*/fit.json)
stamped=$(stamps)
job=$(submit "$resume" --array=0-4)
wait_for "$job"
[ "$(stamps)" = "$stamped" ] ||
  { echo "the resubmission refitted finished cases" >&2; exit 1; }
merge "$resume"
cmp "$cohort/local/summary.csv" "$resume/fits/summary.csv" || {
  echo "after the kill and resubmission the summary differs" >&2
  diff "$cohort/local/summary.csv" "$resume/fits/summary.csv" >&2 || true
  exit 1
}
echo "array killed after $before of 20 cases resumed on resubmission," \
  "finished cases kept: summary equals the local batch's"
