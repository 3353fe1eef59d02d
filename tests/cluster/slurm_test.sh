#!/usr/bin/env bash
# The cluster path on a real Slurm (issue 38; docs/reliability.md, "The cluster path"):
# a single-node Slurm (munged, slurmctld, slurmd from Debian's packages, installed by
# `./setup.sh --test`) configured and started in a private directory; the build installed
# to a prefix (`cmake --install`, the binary the recipe's PATH finds); the shipped
# docs/cluster/sweep.slurm submitted unmodified exactly as docs/planning.md shows it, from
# a folder laid out as the checkout (`sbatch docs/cluster/sweep.slurm
# sweeps/link3-sizing.yaml`: ten tasks of one CPU on a node of two), its tasks polled to
# their end, joined by `mmvlab sweep-merge --out results results/shard-*-of-10` and
# compared byte for byte with the same sweep run locally (sweep.csv; sweep.json's sweep);
# then a shard killed by Slurm (scontrol requeue) while it runs, which must resume its
# journal.
#
#   tests/cluster/slurm_test.sh build/mmvlab
#
# Exit 77 (ctest: skipped) with the reason where Slurm is not installed or the test is
# not root (slurmd runs jobs as their user and must start as root).
set -euo pipefail
mmvlab=$(readlink -f "${1:?usage: slurm_test.sh MMVLAB}")
root=$(cd "$(dirname "$0")/../.." && pwd)
for tool in munged munge slurmctld slurmd sbatch scontrol sinfo; do
  command -v "$tool" >/dev/null || { echo "SKIPPED: $tool is not installed (./setup.sh --test installs slurmctld, slurmd, slurm-client and munge)"; exit 77; }
done
[[ $(id -u) -eq 0 ]] || { echo "SKIPPED: slurmd must start as root to run jobs (run the suite as root)"; exit 77; }

dir=$(mktemp -d /tmp/mmvlab_slurm_XXXXXX)
host=$(hostname -s)
port=$((20000 + ($$ % 2000) * 2))
export SLURM_CONF=$dir/slurm.conf
cleanup() {
  scontrol shutdown >/dev/null 2>&1 || true
  for pid in "$dir/slurmctld.pid" "$dir/slurmd.pid" "$dir/munge/munged.pid"; do
    [[ -f $pid ]] && kill "$(cat "$pid")" 2>/dev/null || true
  done
  sleep 1
  rm -rf "$dir"
}
trap cleanup EXIT
fail() { echo "slurm_test: $*" >&2; for l in "$dir"/*.log "$dir"/work*/mmvlab-sweep-*.out; do [[ -f $l ]] && { echo "== $l"; tail -20 "$l"; }; done >&2; exit 1; }

mkdir -p "$dir"/{state,spool,munge}
chmod 700 "$dir/munge"
dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge/munge.key"
munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" --pid-file="$dir/munge/munged.pid" \
  --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/seed"
cat > "$SLURM_CONF" <<EOF
ClusterName=mmvtest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$dir/munge/munge.socket
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
SchedulerType=sched/builtin
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$host CPUs=2 RealMemory=2000 State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
slurmctld -c
slurmd
for _ in $(seq 60); do
  [[ $(sinfo -h -o %T 2>/dev/null) == idle ]] && break
  sleep 0.5
done
[[ $(sinfo -h -o %T 2>/dev/null) == idle ]] || fail "the node did not come up idle"

# The build installed where the recipe finds it: PREFIX/bin on the PATH sbatch exports.
cmake --install "$(dirname "$mmvlab")" --prefix "$dir/prefix" >/dev/null || fail "cmake --install failed"
export PATH="$dir/prefix/bin:$PATH"
installed=$dir/prefix/bin/mmvlab
# A folder laid out as the checkout, for the recipe's relative paths.
lay_out() {
  mkdir -p "$1/docs"
  cp -r "$root/docs/cluster" "$1/docs/"
  cp -r "$root/sweeps" "$root/scenes" "$1/"
}
# submit WORKDIR SPEC [sbatch options]: the heavier run's submission (the job id in $job).
submit() {
  local work=$1 spec=$2
  shift 2
  job=$(cd "$work" && sbatch --parsable "$@" docs/cluster/sweep.slurm "$spec") || fail "sbatch failed"
  job=${job%%;*}
}
# finished JOB: waits until every task of the array job has ended, true if each completed.
# Polled every 0.2 s: sbatch --wait polls at intervals that grow to 10 s, so it can see
# the end of a job of a few seconds that much late.
finished() {
  local states
  for _ in $(seq 3000); do
    states=$(scontrol -o show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | sort -u | tr '\n' ' ')
    if [[ -n $states ]] && ! grep -qE 'PENDING|RUNNING|CONFIGURING|COMPLETING|REQUEUE|SUSPENDED|RESIZING|SIGNALING|STAGE_OUT' <<<"$states"; then
      [[ $states == "JobState=COMPLETED " ]] || { echo "slurm_test: job $1 ended as: $states" >&2; return 1; }
      return 0
    fi
    sleep 0.2
  done
  echo "slurm_test: job $1 did not end in 10 minutes" >&2
  return 1
}

# docs/planning.md's commands, verbatim.
lay_out "$dir/work"
job=$(cd "$dir/work" && sbatch --parsable docs/cluster/sweep.slurm sweeps/link3-sizing.yaml) || fail "sbatch of the shipped recipe failed"
job=${job%%;*}
finished "$job" || fail "the shipped array job failed"
(cd "$dir/work" && mmvlab sweep-merge --out results results/shard-*-of-10 >/dev/null 2>&1) || fail "sweep-merge failed"
"$installed" sweep "$root/sweeps/link3-sizing.yaml" --out "$dir/local" --jobs 2 >/dev/null 2>&1 || fail "the local sweep failed"
cmp "$dir/work/results/sweep.csv" "$dir/local/sweep.csv" || fail "the merged array job differs from the local sweep"
for key in fingerprint points columns fields; do
  python3 -c "import json,sys; a,b=(json.load(open(p)) for p in sys.argv[1:3]); sys.exit(a[sys.argv[3]] != b[sys.argv[3]])" \
    "$dir/work/results/sweep.json" "$dir/local/sweep.json" "$key" || fail "the merged sweep.json's $key differs from the local one's"
done
ls "$dir/work"/mmvlab-sweep-"$job"_{1..10}.out >/dev/null || fail "the tasks' logs are not in the submit folder"
echo "slurm_test: the shipped 10-task array job, merged, equals the local sweep byte for byte ($(($(wc -l < "$dir/local/sweep.csv") - 1)) points)"

# A shard requeued by Slurm while it runs resumes its journal. Heavier points (96
# segments a link) so the shard is still running when it is requeued, and fewer of them
# (9 x 4 = 36, 12 a shard: about 7 s each; the whole 117 at 96 segments took 26 s of
# the test's 57).
lay_out "$dir/work2"
sed "s/^segments: 8/segments: 96/; s/samples: 13/samples: 4/" "$root/sweeps/link3-sizing.yaml" > "$dir/work2/sweeps/heavy.yaml"
submit "$dir/work2" sweeps/heavy.yaml --array=1-3 --open-mode=append
journal="$dir/work2/results/shard-1-of-3/journal.csv"
for _ in $(seq 600); do
  [[ -f $journal && $(wc -l < "$journal") -ge 4 ]] && break  # the identity, the header and two points
  sleep 0.1
done
scontrol requeue "${job}_1" || fail "scontrol requeue ${job}_1 failed"
# A requeued job waits about two minutes before it may start again; start it now.
for _ in $(seq 100); do
  [[ $(squeue -h -j "${job}_1" -o %T 2>/dev/null) == PENDING ]] && break
  sleep 0.1
done
scontrol update JobId="${job}_1" StartTime=now >/dev/null 2>&1 || true
finished "$job" || fail "the requeued array job failed"
log=$(ls "$dir"/work2/mmvlab-sweep-*_1.out)
grep -q "DUE TO JOB REQUEUE" "$log" || fail "shard 1 was not requeued while it ran"
resumed=$(sed -n 's/.*shard 1\/3: \([0-9]*\) computed, \([0-9]*\) already done.*/\2/p' "$log" | tail -1)
[[ -n $resumed && $resumed -ge 2 ]] || fail "the requeued shard did not resume its journal (already done: '${resumed}')"
(cd "$dir/work2" && mmvlab sweep-merge --out merged results/shard-*-of-3 >/dev/null 2>&1) || fail "sweep-merge after the requeue failed"
rows=$(($(wc -l < "$dir/work2/merged/sweep.csv") - 1))
[[ $rows -eq 36 ]] || fail "the merged requeued sweep has $rows points, not 36"
dups=$(cut -d, -f1 "$dir/work2/merged/sweep.csv" | sort | uniq -d | wc -l)
[[ $dups -eq 0 ]] || fail "the merged requeued sweep repeats points"
echo "slurm_test: shard 1 requeued by Slurm while running resumed with $resumed points already done; merged: 36 points, none twice"
