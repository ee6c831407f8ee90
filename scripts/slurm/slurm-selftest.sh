#!/usr/bin/env bash
# Proves the Slurm farm recipe (scripts/slurm/, docs/farm-rendering.md) on a real Slurm
# cluster of one node: this machine.
#
# Usage: slurm-selftest.sh [--prism PATH] OUTDIR     (as root; default PATH build/release/prism)
#
# 1. Installs the Debian packages slurm-wlm and munge if missing.
# 2. Starts munged, slurmctld and slurmd on localhost (free ports, configuration and state in
#    a temporary folder, no systemd, no cgroups: proctrack/linuxproc, task/none).
# 3. Submits the Cornell box (64x64, 2048 spp) with submit.sh as an array of 4 sample ranges
#    plus the dependent merge job. While they render, requeues task 1 (`scontrol requeue`:
#    Slurm sends SIGTERM, prism checkpoints, Slurm starts the task again) and sends task 2
#    the time-limit warning (`scancel --batch --signal=USR1`, as --signal=B:USR1 would: the
#    task checkpoints and requeues itself). Waits for every job; checks from the logs that
#    tasks 1 and 2 ran twice, the second time resuming from their checkpoints ("requeue 1 of
#    this task"), and that tasks 0 and 3 rendered once.
# 4. Renders the same 2048 spp in one process and checks OUTDIR/merged.exr against
#    OUTDIR/single.exr with compare-merge.py: equal within the merge's float rounding (the
#    parts store their means as float, so a merge is not bitwise; see compare-merge.py).
#    Checks that parts 1 and 2 equal their ranges rendered in one go bit for bit, and that
#    `prism merge` refuses overlapping parts and a part rendered with another seed.
# 5. Submits a second, tiny farm render whose task 1 fails (its output path is a folder):
#    task 0's part must stay and the merge job wait for ever (DependencyNeverSatisfied).
#    Then cancels that merge, fixes the cause and resubmits with the same OUTDIR: task 0 must
#    skip its finished part, task 1 render, and the new merge job run.
# Exits 0 only if everything held; prints where the logs are (OUTDIR/logs). Every wait is
# bounded, and the EXIT trap cancels the jobs and stops the daemons it started, whatever
# happened.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
usage="usage: slurm-selftest.sh [--prism PATH] OUTDIR"
prism="$repo/build/release/prism"
if [ "${1:-}" = --prism ]; then prism=${2:?$usage}; shift 2; fi
if [ $# -ne 1 ]; then echo "$usage" >&2; exit 2; fi
outdir=$1

size=64 spp=2048 tasks=4 requeued_task=1 time_limited_task=2
# 512 spp a task on one thread: 1 to 4 s, long enough for tasks 1 and 2 to be caught
# mid-render (after their first checkpoint, 0.2 s and one pass in), short enough for the
# whole test to take about a minute.
render_args=(--width "$size" --height "$size" --checkpoint-every 0.2)
started=$(date +%s)

say() { echo "slurm-selftest: $(date -u +%H:%M:%S) $*"; }
fail() { echo "slurm-selftest: FAIL: $*" >&2; exit 1; }
# Everything after the installation must end within this many seconds, so that the test
# fails and cleans up on its own well before CTest's timeout (300 s) would kill it (which
# would leave the jobs' slurmstepd processes, which are not its children, running).
budget_seconds=180
deadline=""
remaining() {
  local left=$((deadline - $(date +%s)))
  [ "$left" -gt 0 ] || fail "out of time: the test's budget of $budget_seconds s is spent"
  echo "$left"
}
bounded() { timeout "$(remaining)" "$@"; }  # COMMAND..., stopped at the deadline
# wait_for SECONDS WHAT COMMAND...: polls COMMAND every 0.2 s; fails after SECONDS or at
# the deadline.
wait_for() {
  local give_up_at=$(($(date +%s) + $1)) what=$2
  shift 2
  [ "$give_up_at" -le "$deadline" ] || give_up_at=$deadline
  until "$@"; do
    [ "$(date +%s)" -lt "$give_up_at" ] || fail "timed out waiting for $what"
    sleep 0.2
  done
}

[ "$(id -u)" = 0 ] || fail "run as root: slurmd must be root to start jobs (and apt-get installs Slurm)"
[ -x "$prism" ] || fail "prism binary '$prism' not found or not executable (build it, or pass --prism PATH)"
prism=$(realpath "$prism")

# --- 1. Packages --------------------------------------------------------------------------
missing=()
for p in slurm-wlm munge python3; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  timeout 300 apt-get update -qq || fail "apt-get update failed"
  timeout 600 apt-get install -y -qq --no-install-recommends "${missing[@]}" || fail "cannot install ${missing[*]}"
fi

# --- 2. A one-node cluster ----------------------------------------------------------------
deadline=$(($(date +%s) + budget_seconds))
mkdir -p "$outdir"
outdir=$(realpath "$outdir")
rm -rf "$outdir/parts" "$outdir/checkpoints" "$outdir/logs" "$outdir/failure" \
  "$outdir"/{merged,single,foreign,refused}.exr \
  "$outdir"/uninterrupted-*.exr
logs="$outdir/logs"
mkdir -p "$logs/cluster"
work=$(mktemp -d /tmp/prism-slurm-selftest.XXXXXX)
munged_pid="" slurmctld_pid="" slurmd_pid=""
user=$(id -un)

# stop PID NAME: SIGTERM, up to 15 s, then SIGKILL; only processes this script started.
stop() {
  [ -n "$1" ] || return 0
  kill -TERM "$1" 2>/dev/null || return 0
  for _ in $(seq 75); do kill -0 "$1" 2>/dev/null || break; sleep 0.2; done
  if kill -0 "$1" 2>/dev/null; then
    echo "slurm-selftest: $2 ignored SIGTERM for 15 s: SIGKILL" >&2
    kill -KILL "$1" 2>/dev/null || true
  fi
  wait "$1" 2>/dev/null || true
}
cleanup() {
  local status=$?
  set +e
  trap - INT TERM
  if [ -n "$slurmctld_pid" ] && kill -0 "$slurmctld_pid" 2>/dev/null; then
    timeout 20 scancel --quiet --user="$user" 2>/dev/null  # every job: the cluster is this script's
    # Cancelled jobs leave once slurmd has killed their processes (KillWait=5 below).
    for _ in $(seq 100); do
      [ -z "$(timeout 10 squeue -h -o %i 2>/dev/null)" ] && break
      sleep 0.2
    done
    # Anything still running belongs to this cluster's jobs: its pids, from slurmd.
    if [ -n "$(timeout 10 squeue -h -o %i 2>/dev/null)" ]; then
      echo "slurm-selftest: jobs still present after scancel; killing their processes" >&2
      for pid in $(timeout 10 scontrol listpids 2>/dev/null | awk 'NR > 1 && $1 ~ /^[0-9]+$/ {print $1}'); do
        kill -KILL "$pid" 2>/dev/null
      done
    fi
  fi
  stop "$slurmd_pid" slurmd
  stop "$slurmctld_pid" slurmctld
  stop "$munged_pid" munged
  rm -rf "$work"
  local seconds=$(($(date +%s) - started))
  if [ "$status" -eq 0 ]; then
    echo "slurm-selftest: PASS in ${seconds} s; logs in $logs"
  else
    echo "slurm-selftest: FAILED (status $status) after ${seconds} s; logs in $logs" \
      "(render-*.log and merge-*.log: the jobs; cluster/: munged, slurmctld, slurmd)" >&2
  fi
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# A TCP port nothing listens on (a connection to it is refused).
free_port() {
  local port
  for _ in $(seq 100); do
    port=$((20000 + RANDOM % 40000))
    [ "$port" != "${1:-}" ] || continue
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then echo "$port"; return 0; fi
  done
  fail "no free TCP port found"
}

say "starting munged"
# munged wants its key private and its socket's folders searchable by everyone.
mkdir -p "$work/munge" "$work/munge-key" "$work/state" "$work/spool"
chmod 0755 "$work" "$work/munge"
chmod 0700 "$work/munge-key"
head -c 1024 /dev/urandom >"$work/munge-key/munge.key"
chmod 0400 "$work/munge-key/munge.key"
socket="$work/munge/munge.socket"
munged --foreground --key-file="$work/munge-key/munge.key" --socket="$socket" \
  --pid-file="$work/munge/munged.pid" --seed-file="$work/munge/munged.seed" \
  --log-file="$logs/cluster/munged.log" >>"$logs/cluster/munged.log" 2>&1 &
munged_pid=$!
alive_and() {  # alive_and PID NAME COMMAND...: fails at once if the daemon died
  kill -0 "$1" 2>/dev/null || fail "$2 exited (see $logs/cluster/$2.log)"
  "${@:3}"
}
wait_for 20 "munged's socket" alive_and "$munged_pid" munged test -S "$socket"
munge --socket="$socket" --no-input | unmunge --socket="$socket" >/dev/null || fail "munge cannot encode and decode a credential"

node=$(hostname -s)
ctld_port=$(free_port)
slurmd_port=$(free_port "$ctld_port")
export SLURM_CONF="$work/slurm.conf"  # read by every Slurm command below
cat >"$SLURM_CONF" <<EOF
# One-node cluster of slurm-selftest.sh: no systemd, no cgroups, everything under $work.
ClusterName=prismselftest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
# cred_expire: how long a requeued job waits before it may start again (default 120 s).
AuthInfo=socket=$socket,cred_expire=10
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
# Look for startable jobs every second or two, not every 30 to 60 s (the defaults).
SchedulerParameters=sched_interval=2,bf_interval=1
ReturnToService=2
# Seconds between SIGTERM and SIGKILL when a job is cancelled or requeued: prism needs one
# pass (well under a second here) to stop and write its checkpoint.
KillWait=5
MinJobAge=600
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=selftest Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF

say "starting slurmctld (port $ctld_port) and slurmd (port $slurmd_port) on $node"
slurmctld -D -c >>"$logs/cluster/slurmctld.log" 2>&1 &
slurmctld_pid=$!
ctld_up() { timeout 5 scontrol ping 2>/dev/null | grep -q "is UP"; }
wait_for 30 "slurmctld to answer" alive_and "$slurmctld_pid" slurmctld ctld_up
slurmd -D -N "$node" >>"$logs/cluster/slurmd.log" 2>&1 &
slurmd_pid=$!
node_idle() { [ "$(timeout 10 sinfo -h -n "$node" -o %T 2>/dev/null)" = idle ]; }
wait_for 60 "node $node to be idle" alive_and "$slurmd_pid" slurmd node_idle

# --- 3. The farm render -------------------------------------------------------------------
say "submitting $tasks tasks of cornell-box ${size}x${size}, $spp spp, and the merge job"
# submit OUTDIR SPP TASKS RENDER_ARGS...: submit.sh; sets array_id and merge_id.
submit() {
  local ids
  ids=$(bounded "$here/submit.sh" --prism "$prism" cornell-box "$2" "$3" "$1" -- "${@:4}") || fail "submit.sh failed"
  array_id=$(awk '$1 == "array" {print $2}' <<<"$ids")
  merge_id=$(awk '$1 == "merge" {print $2}' <<<"$ids")
  [ -n "$array_id" ] && [ -n "$merge_id" ] || fail "submit.sh printed no job ids: $ids"
  say "array job $array_id, merge job $merge_id"
}
submit "$outdir" "$spp" "$tasks" "${render_args[@]}"

job_state() { timeout 10 scontrol show job -o "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -1 | cut -d= -f2; }
task_log() { echo "$logs/render-${array_id}_$1.log"; }
# interrupt_while_rendering TASK HOW COMMAND...: waits until TASK runs and has written its
# first checkpoint (so it is mid-render), then runs COMMAND, which stops it.
interrupt_while_rendering() {
  local task=$1 how=$2
  shift 2
  rendering_with_checkpoint() {
    local state
    state=$(job_state "${array_id}_$task")
    case "$state" in
      RUNNING) [ -e "$outdir/checkpoints/part-$task.ckp" ] ;;
      PENDING | CONFIGURING | "") return 1 ;;
      *) fail "task $task ended as $state before it could be stopped (see $(task_log "$task"))" ;;
    esac
  }
  wait_for 60 "task $task to render and write its first checkpoint" rendering_with_checkpoint
  say "$how task $task while it renders ($*)"
  timeout 20 "$@" || fail "$* failed"
  [ ! -e "$outdir/parts/part-$task.exr" ] ||
    fail "task $task had finished before it was stopped: the render is too short for this test"
}
# Task 1: the cluster requeues it (as on preemption or an operator's requeue): Slurm sends
# SIGTERM to all its processes and starts it again.
interrupt_while_rendering "$requeued_task" requeueing scontrol requeue "${array_id}_$requeued_task"
# Task 2: its time limit is near: Slurm sends --signal=B:USR1 to the batch shell only, as
# `scancel --batch --signal=USR1` does; the task stops prism and requeues itself.
interrupt_while_rendering "$time_limited_task" "signalling the time limit (USR1) to" \
  scancel --batch --signal=USR1 "${array_id}_$time_limited_task"

# job_done JOB: true once JOB completed, false while it may still run; fails otherwise.
job_done() {
  local state
  state=$(job_state "$1")
  case "$state" in
    COMPLETED) return 0 ;;
    PENDING)
      ! timeout 10 scontrol show job -o "$1" | grep -q "Reason=DependencyNeverSatisfied" ||
        fail "job $1 can never run: a job it depends on failed"
      return 1 ;;
    RUNNING | CONFIGURING | COMPLETING | REQUEUED) return 1 ;;
    *) fail "job $1 ended as ${state:-unknown} ($(timeout 10 scontrol show job -o "$1" | grep -o 'Reason=[^ ]*'))" ;;
  esac
}
wait_for 180 "the array and the merge job" job_done "$merge_id"
for ((i = 0; i < tasks; i++)); do
  state=$(job_state "${array_id}_$i")
  [ "$state" = COMPLETED ] || fail "task $i ended as $state"
done
[ -s "$outdir/merged.exr" ] || fail "the merge job left no $outdir/merged.exr"

# What the task logs must show: tasks 1 and 2 rendered twice, the second time as a requeue
# that resumed from the checkpoint; every other task rendered once.
expect_in_log() {  # expect_in_log TASK TEXT WHAT
  grep -q "$2" "$(task_log "$1")" || fail "task $1: $3 ($(task_log "$1") has no '$2')"
}
expect_in_log "$requeued_task" "SIGTERM from Slurm" "never saw Slurm's SIGTERM"
expect_in_log "$time_limited_task" "time limit near" "never saw the time-limit signal"
expect_in_log "$time_limited_task" "requeueing job" "did not requeue itself"
for task in "$requeued_task" "$time_limited_task"; do
  expect_in_log "$task" "requeue 1 of this task" "no requeue line"
  expect_in_log "$task" "resuming from checkpoint" "did not resume from its checkpoint"
done
for ((i = 0; i < tasks; i++)); do
  runs=$(grep -c "rendering on" "$(task_log "$i")" || true)
  expected=1
  [ "$i" = "$requeued_task" ] || [ "$i" = "$time_limited_task" ] && expected=2
  [ "$runs" = "$expected" ] || fail "task $i rendered $runs times, expected $expected"
done
say "tasks $requeued_task and $time_limited_task were requeued and resumed from their checkpoints;" \
  "the others rendered once"

# --- 4. One process, and the comparison ---------------------------------------------------
say "rendering the same $spp spp in one process"
bounded "$prism" render cornell-box "${render_args[@]:0:4}" --spp "$spp" -o "$outdir/single.exr" \
  >>"$logs/single.log" 2>&1 || fail "the single render failed (see $logs/single.log)"
parts=()
for ((i = 0; i < tasks; i++)); do parts+=("$outdir/parts/part-$i.exr"); done
bounded python3 "$here/compare-merge.py" "$outdir/single.exr" "$outdir/merged.exr" "${parts[@]}" ||
  fail "merged.exr differs from single.exr"

# The parts of the interrupted tasks, rendered over two runs with a checkpoint between
# them, equal the same ranges rendered in one go, bit for bit.
for task in "$requeued_task" "$time_limited_task"; do
  range="$((task * spp / tasks)):$(((task + 1) * spp / tasks))"
  bounded "$prism" render cornell-box "${render_args[@]:0:4}" --sample-range "$range" \
    -o "$outdir/uninterrupted-$task.exr" >>"$logs/single.log" 2>&1 || fail "the render of range $range failed"
  bounded python3 "$here/compare-merge.py" --bitwise "$outdir/uninterrupted-$task.exr" "${parts[$task]}" "${parts[$task]}" ||
    fail "part $task, resumed after Slurm stopped it, differs from the range rendered in one go"
  rm -f "$outdir/uninterrupted-$task.exr"
done

# The merge refuses parts that do not belong together.
refused() {  # refused WHAT PARTS...: prism merge must exit 2 and write nothing
  local status=0
  bounded "$prism" merge "${@:2}" -o "$outdir/refused.exr" >>"$logs/refusals.log" 2>&1 || status=$?
  [ "$status" = 2 ] && [ ! -e "$outdir/refused.exr" ] || fail "prism merge accepted $1 (status $status)"
}
refused "overlapping parts" "${parts[0]}" "${parts[0]}"
bounded "$prism" render cornell-box "${render_args[@]:0:4}" --seed 7 --sample-range "$spp:$((spp + 1))" \
  -o "$outdir/foreign.exr" >>"$logs/refusals.log" 2>&1 || fail "the foreign part's render failed"
refused "a part rendered with another seed" "${parts[@]}" "$outdir/foreign.exr"
rm -f "$outdir/foreign.exr"
say "prism merge refused overlapping parts and a part of other settings ($logs/refusals.log)"

# --- 5. A task that fails keeps the others' parts; a resubmission renders only the rest ----
failing="$outdir/failure"
say "a farm render whose task 1 fails (its output path is a folder), in $failing"
mkdir -p "$failing/parts"
mkdir "$failing/parts/.part-1.rendering.exr"  # prism cannot write task 1's image: exit 1
submit "$failing" 16 2 --width "$size" --height "$size"
task_failed() {
  local state
  state=$(job_state "${array_id}_1")
  case "$state" in
    FAILED) return 0 ;;
    PENDING | CONFIGURING | RUNNING | COMPLETING | "") return 1 ;;
    *) fail "task 1 was to fail but ended as $state" ;;
  esac
}
wait_for 60 "task 1 to fail" task_failed
wait_for 60 "task 0 to complete" job_done "${array_id}_0"
merge_stuck() { timeout 10 scontrol show job -o "$merge_id" | grep -q "JobState=PENDING.*Reason=DependencyNeverSatisfied"; }
wait_for 30 "the merge job to wait for ever" merge_stuck
[ -e "$failing/parts/part-0.exr" ] || fail "task 1's failure lost task 0's part"
[ ! -e "$failing/merged.exr" ] || fail "a merge ran although task 1 failed"
say "task 1 failed; task 0's part is kept and merge job $merge_id waits (DependencyNeverSatisfied)"

rmdir "$failing/parts/.part-1.rendering.exr"
timeout 20 scancel "$merge_id" || fail "scancel $merge_id failed"
submit "$failing" 16 2 --width "$size" --height "$size"
wait_for 120 "the resubmitted array and merge job" job_done "$merge_id"
grep -q "already rendered, nothing to do" "$failing/logs/render-${array_id}_0.log" ||
  fail "the resubmitted task 0 rendered again"
grep -q "done: " "$failing/logs/render-${array_id}_1.log" || fail "the resubmitted task 1 did not render its part"
[ -s "$failing/merged.exr" ] || fail "the resubmission left no $failing/merged.exr"
say "resubmitted: task 0 skipped its finished part, task 1 rendered, the merge ran"
