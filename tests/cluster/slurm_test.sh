#!/usr/bin/env bash
# The cluster path on a real Slurm (issue 38; docs/reliability.md, "The cluster path"):
# a single-node Slurm (munged, slurmctld, slurmd from Debian's packages, installed by
# `./setup.sh --test`) configured and started in a private directory, the sharded sweep
# of docs/cluster/sweep.slurm run as an array job (sbatch --array --wait), joined by
# sweep-merge and compared byte for byte with the same sweep run locally; then a shard
# killed by Slurm (scontrol requeue) while it runs, which must resume its journal.
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
fail() { echo "slurm_test: $*" >&2; for l in "$dir"/*.log "$dir"/work*/logs/*; do [[ -f $l ]] && { echo "== $l"; tail -20 "$l"; }; done >&2; exit 1; }

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

# The docs' array job, three shards, resources lowered to this node's (the command line
# overrides the script's #SBATCH lines).
submit() {  # submit WORKDIR SPEC: sbatch --wait in the background (its pid in $waiter, the job id in WORKDIR/jobid)
  local work=$1 spec=$2
  mkdir -p "$work/logs"
  sbatch --wait --parsable --array=1-3 --cpus-per-task=1 --mem=200M --open-mode=append --chdir="$work" \
    --export="ALL,PATH=$(dirname "$mmvlab"):/usr/bin:/bin" "$root/docs/cluster/sweep.slurm" "$spec" > "$work/jobid" &
  waiter=$!
}

spec="$root/sweeps/link3-sizing.yaml"
submit "$dir/work" "$spec"
wait "$waiter" || fail "the array job failed"
(cd "$dir/work" && "$mmvlab" sweep-merge --out merged results/shard-*-of-3 >/dev/null 2>&1) || fail "sweep-merge failed"
"$mmvlab" sweep "$spec" --out "$dir/local" --jobs 2 >/dev/null 2>&1 || fail "the local sweep failed"
cmp "$dir/work/merged/sweep.csv" "$dir/local/sweep.csv" || fail "the merged array job differs from the local sweep"
echo "slurm_test: a 3-task array job merged equals the local sweep byte for byte ($(($(wc -l < "$dir/local/sweep.csv") - 1)) points)"

# A shard requeued by Slurm while it runs resumes its journal. Heavier points (96
# segments a link) so the shard is still running when it is requeued.
sed "s/^segments: 8/segments: 96/; s|\.\./scenes/mmv.yaml|$root/scenes/mmv.yaml|" "$spec" > "$dir/heavy.yaml"
submit "$dir/work2" "$dir/heavy.yaml"
journal="$dir/work2/results/shard-1-of-3/journal.csv"
for _ in $(seq 600); do
  [[ -f $journal && $(wc -l < "$journal") -ge 4 ]] && break  # the identity, the header and two points
  sleep 0.1
done
[[ -s "$dir/work2/jobid" ]] || sleep 1
job=$(head -1 "$dir/work2/jobid")
scontrol requeue "${job}_1" || fail "scontrol requeue ${job}_1 failed"
# A requeued job waits about two minutes before it may start again; start it now.
for _ in $(seq 100); do
  [[ $(squeue -h -j "${job}_1" -o %T 2>/dev/null) == PENDING ]] && break
  sleep 0.1
done
scontrol update JobId="${job}_1" StartTime=now >/dev/null 2>&1 || true
wait "$waiter" || fail "the requeued array job failed"
log=$(ls "$dir"/work2/logs/sweep-*_1.out)
grep -q "DUE TO JOB REQUEUE" "$log" || fail "shard 1 was not requeued while it ran"
resumed=$(sed -n 's/.*shard 1\/3: \([0-9]*\) computed, \([0-9]*\) already done.*/\2/p' "$log" | tail -1)
[[ -n $resumed && $resumed -ge 2 ]] || fail "the requeued shard did not resume its journal (already done: '${resumed}')"
(cd "$dir/work2" && "$mmvlab" sweep-merge --out merged results/shard-*-of-3 >/dev/null 2>&1) || fail "sweep-merge after the requeue failed"
rows=$(($(wc -l < "$dir/work2/merged/sweep.csv") - 1))
[[ $rows -eq 117 ]] || fail "the merged requeued sweep has $rows points, not 117"
dups=$(cut -d, -f1 "$dir/work2/merged/sweep.csv" | sort | uniq -d | wc -l)
[[ $dups -eq 0 ]] || fail "the merged requeued sweep repeats points"
echo "slurm_test: shard 1 requeued by Slurm while running resumed with $resumed points already done; merged: 117 points, none twice"
