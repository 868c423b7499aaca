#!/usr/bin/env bash
# A batch through a real Slurm (./sdlqr batch --slurm): a one-node cluster of our own in this
# network namespace (one_node_cluster.sh), the batch as a job array of 4 tasks, task 2 killed
# mid-run (kill -9 of its sdlqr-batch), which the waiter must requeue and which must continue its
# journal; the merged flights.csv, summary.txt and batch.yaml must equal a single local run's
# byte for byte; a job submitted with --no-wait and collected by batch-merge too. Negative: a merge
# missing a shard is refused for that reason.
#   slurm_batch.sh SDLQR_BATCH SPEC WORK_DIR
set -uo pipefail
batch="$1" spec="$2" work="$3"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=one_node_cluster.sh
. "$here/one_node_cluster.sh"

fail() { echo "slurm_batch: FAILED: $*" >&2; exit 1; }

missing=$(cluster_prerequisites | tr '\n' ' ')
if [ -n "${missing// /}" ]; then
  echo "slurm_batch: missing $missing(Debian packages slurm-wlm munge; ./sdlqr setup installs them)" >&2
  [ "${CI:-}" = true ] && exit 1
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
trap 'cluster_down "$work/cluster"' EXIT
cluster_up 2 || fail "the one-node cluster did not start (logs in $work/cluster)"

"$batch" "$spec" --out "$work/single" --jobs 2 --no-progress >/dev/null 2>"$work/single.err" ||
  fail "the local run failed: $(cat "$work/single.err")"
total=$(($(wc -l <"$work/single/flights.csv") - 1))

"$batch" "$spec" --slurm --tasks 4 --out "$work/slurm" >"$work/slurm.out" 2>"$work/slurm.err" &
waiter=$!

# Task 2, killed once it has journaled a flight and before it finished its shard. Found as soon as
# its sdlqr-batch starts and held stopped from then on, it flies in 20 ms steps (SIGCONT, a pause,
# SIGSTOP) until its journal holds a flight: a stalled watcher can no longer let the task fly on to
# the end of its 12 short flights between a look at the journal and the kill (it did beside the
# compilers of a clean clone). The watch starts no process (builtins, /proc read by the shell, the
# pause a timed-out read): beside compilers a fork can wait seconds (docs/verdicts.md).
shard2="$work/slurm/slurm/shard-2"
mkfifo "$work/nap.fifo"
exec {nap}<>"$work/nap.fifo"
nap() { read -r -t "$1" -u "$nap" _ || true; }
journaled_rows() {  # sets rows: the flights in task 2's journal
  local lines=()
  rows=0
  [ -f "$shard2/flights.partial.csv" ] && mapfile -t lines <"$shard2/flights.partial.csv" && rows=$((${#lines[@]} - 1))
}
find_task2_pid() {  # sets pid: the process whose command line holds "--out $shard2 "
  local proc arg line
  pid=""
  for proc in /proc/[0-9]*; do
    line=""
    { while IFS= read -r -d '' arg; do line+="$arg "; done <"$proc/cmdline"; } 2>/dev/null
    case "$line" in *"--out $shard2 "*) pid="${proc#/proc/}"; return 0 ;; esac
  done
}
pid=""
for _ in $(seq 3000); do
  kill -0 "$waiter" 2>/dev/null || break
  find_task2_pid
  [ -n "$pid" ] && kill -STOP "$pid" 2>/dev/null && break
  pid=""
  nap 0.01
done
[ -n "$pid" ] || fail "task 2's sdlqr-batch never started (waiter: $(cat "$work/slurm.err"))"
journaled_rows
for _ in $(seq 3000); do
  [ "$rows" -ge 1 ] && break
  kill -CONT "$pid" 2>/dev/null || fail "task 2 (pid $pid) ended before it journaled a flight"
  nap 0.02
  kill -STOP "$pid" 2>/dev/null || fail "task 2 (pid $pid) ended after $rows journaled flights, before it could be killed"
  journaled_rows
done
[ "$rows" -ge 1 ] || fail "task 2 (pid $pid) journaled no flight in 3000 steps"
[ -f "$shard2/flights.csv" ] && { kill -CONT "$pid"; fail "task 2 finished its shard before it could be killed mid-run"; }
kill -KILL "$pid"
killed="$rows"
echo "killed task 2 (pid $pid) with $killed of its 12 flights journaled"

wait "$waiter" || fail "the Slurm batch failed: $(cat "$work/slurm.err")"
grep -q '^slurm job [0-9]*: task 2 failed; requeued' "$work/slurm.err" ||
  fail "the waiter did not requeue the killed task: $(cat "$work/slurm.err")"
grep -q 'attempt 2' "$work/slurm/slurm/task-2.out" || fail "task 2 ran once: $(cat "$work/slurm/slurm/task-2.out")"
resumed=$(sed -n 's/.*flew \([0-9]*\), resumed \([0-9]*\) from the journal.*/\2/p' "$work/slurm/slurm/task-2.out" | tail -n 1)
[ "${resumed:-0}" -ge "$killed" ] || fail "task 2's second attempt resumed ${resumed:-no} flights of its journal, $killed were there"
for file in flights.csv summary.txt batch.yaml; do
  cmp "$work/single/$file" "$work/slurm/$file" || fail "the Slurm batch's $file differs from the single run's"
done
echo "4 Slurm array tasks (task 2 killed and requeued, $resumed flights resumed) merged into the single run's $total rows, byte for byte"

# --no-wait: the job id on stdout, the shards collected later by batch-merge.
id=$("$batch" "$spec" --slurm --tasks 2 --no-wait --out "$work/later" 2>"$work/later.err") ||
  fail "--no-wait submission failed: $(cat "$work/later.err")"
[[ "$id" =~ ^[0-9]+$ ]] || fail "--no-wait printed '$id', not a job id"
for _ in $(seq 1200); do
  [ -f "$work/later/slurm/shard-1/flights.csv" ] && [ -f "$work/later/slurm/shard-2/flights.csv" ] && break
  sleep 0.1
done
"$batch" merge "$spec" --out "$work/later" "$work"/later/slurm/shard-{1,2} >/dev/null 2>"$work/later-merge.err" ||
  fail "collecting job $id failed: $(cat "$work/later-merge.err")"
cmp "$work/single/flights.csv" "$work/later/flights.csv" || fail "job $id, collected later, differs from the single run"
echo "job $id submitted with --no-wait, collected by batch-merge: the single run's rows"

# Negative: a merge missing shard 4 is refused for that reason.
if "$batch" merge "$spec" --out "$work/incomplete" "$work"/slurm/slurm/shard-{1,2,3} 2>"$work/incomplete.err"; then
  fail "a merge of 3 of 4 shards was accepted"
fi
grep -q 'batch-merge: shard 4/4 missing' "$work/incomplete.err" ||
  fail "the incomplete merge failed for another reason: $(cat "$work/incomplete.err")"
echo "a merge without shard 4 refused: $(cat "$work/incomplete.err")"
