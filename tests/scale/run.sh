#!/usr/bin/env bash
# run.sh VERIFY WORK_DIR: tab:CPNC's derivation spread over machines, on the engines users have
# (docs/scale_out.md). One small block (theta 30 deg, F = 1, X from -0.1 to 0.1) is derived
#   1. whole, in one process;
#   2. as three shards under GNU parallel, merged;
#   3. as a Slurm job array of three tasks on a one-node cluster that this script starts itself
#      (munged, slurmctld and slurmd with a configuration of its own: simple process tracking,
#      no accounting), merged.
# The three tables must be byte-identical. A failing shard must fail its run: GNU parallel with
# one shard that cannot be written, and a Slurm array with one task that fails, must each exit
# non-zero. Every daemon is stopped on exit.
set -euo pipefail
verify=$(realpath "$1")
work=$(realpath -m "$2")
rm -rf "$work" && mkdir -p "$work"
block=(derive-table --theta 30 --F 1 --X -0.1:0.1:0.05 --threads 1)

echo "== whole =="
"$verify" "${block[@]}" > "$work/whole.json" 2> "$work/whole.log"

echo "== GNU parallel: 3 shards =="
parallel --halt now,fail=1 -j 2 "'$verify' ${block[*]} --shard {}/3 > '$work/parallel-{}.json' 2> '$work/parallel-{}.log'" ::: 1 2 3
"$verify" merge "$work"/parallel-{1,2,3}.json > "$work/parallel.json"
cmp "$work/whole.json" "$work/parallel.json"
echo "GNU parallel: merged table byte-identical to the whole one"
if parallel --halt now,fail=1 -j 2 "'$verify' ${block[*]} --shard {}/3 > '$work/{= \$_ = \$_ == 2 ? \"missing/x\" : \$_ =}.json'" ::: 1 2 3 2> /dev/null; then
  echo "run.sh: GNU parallel succeeded although shard 2 could not be written" >&2
  exit 1
fi
echo "GNU parallel: a failing shard fails the run"

echo "== Slurm: a job array of 3 tasks on a one-node cluster =="
cluster=$work/slurm
mkdir -p "$cluster"/{spool,state,log}
daemons=()
stop() { for pid in "${daemons[@]}"; do kill "$pid" 2> /dev/null || true; done; wait 2> /dev/null || true; }
trap stop EXIT
# munge: a key of its own and a socket in the work folder (munged runs as root only with --force).
dd if=/dev/urandom of="$cluster/munge.key" bs=1024 count=1 status=none
chmod 400 "$cluster/munge.key"
munged --force --foreground --key-file="$cluster/munge.key" --socket="$cluster/munge.socket" --pid-file="$cluster/munged.pid" \
  --log-file="$cluster/log/munged.log" --seed-file="$cluster/munge.seed" 2> "$cluster/log/munged.out" &
daemons+=($!)
node=$(hostname -s)
port=$((20000 + RANDOM % 20000))
cat > "$cluster/slurm.conf" <<CONF
ClusterName=trebuchet-test
SlurmctldHost=$node
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$cluster/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$cluster/state
SlurmdSpoolDir=$cluster/spool
SlurmctldPidFile=$cluster/slurmctld.pid
SlurmdPidFile=$cluster/slurmd.pid
SlurmctldLogFile=$cluster/log/slurmctld.log
SlurmdLogFile=$cluster/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/builtin
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SwitchType=switch/none
NodeName=$node CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$cluster/slurm.conf
for _ in $(seq 50); do [ -S "$cluster/munge.socket" ] && break; sleep 0.1; done
slurmctld -D -i -f "$SLURM_CONF" > "$cluster/log/slurmctld.out" 2>&1 &
daemons+=($!)
slurmd -D -f "$SLURM_CONF" > "$cluster/log/slurmd.out" 2>&1 &
daemons+=($!)
for _ in $(seq 100); do sinfo -h -o %T 2> /dev/null | grep -qE '^idle' && break; sleep 0.2; done
sinfo -h -o "%P %D %T" | grep -q idle || { echo "run.sh: the Slurm node did not come up" >&2; tail -20 "$cluster"/log/*; exit 1; }
timeout 300 sbatch --wait --quiet --array=1-3 --output="$work/slurm-%a.log" --chdir="$work" \
  --wrap "'$verify' ${block[*]} --shard \$SLURM_ARRAY_TASK_ID/3 > '$work/slurm-'\$SLURM_ARRAY_TASK_ID.json"
"$verify" merge "$work"/slurm-{1,2,3}.json > "$work/slurm.json"
cmp "$work/whole.json" "$work/slurm.json"
echo "Slurm: merged table byte-identical to the whole one"
if timeout 300 sbatch --wait --quiet --array=1-3 --output="$work/failing-%a.log" --chdir="$work" \
  --wrap "[ \$SLURM_ARRAY_TASK_ID != 2 ] && '$verify' ${block[*]} --shard \$SLURM_ARRAY_TASK_ID/3 > /dev/null"; then
  echo "run.sh: the Slurm array succeeded although task 2 failed" >&2
  exit 1
fi
echo "Slurm: a failing task fails the array"
