#!/usr/bin/env bash
# SIGTERM to the launcher mid-hover: every process must exit within 1 s and the log be complete.
#   sigterm_launcher.sh BUILD_DIR WORK_DIR SCENARIO
set -uo pipefail
build="$1" work="$2" scenario="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
source "$root/tests/support/sim_time.sh"
# The signal comes mid-hover, at 5 s of simulation time (tests/support/sim_time.sh).
start_marked_flight "$build" "$work" 5 "$scenario"
wait_sim_time_or_stop "$work" 5
# Only this launcher's processes (other tests fly their own stacks at the same time).
mapfile -t pids < <(pgrep -P "$launcher" -f '/sdlqr-[a-z-]+ ')
[ "${#pids[@]}" -eq 7 ] || { echo "expected 7 processes, found ${#pids[@]}"; cat "$work/launch.out"; exit 1; }
declare -A name_of=() gone_ms=()
for pid in "${pids[@]}"; do name_of[$pid]=$(ps -o comm= -p "$pid"); done
start_ms=$(date +%s%3N)
kill -TERM "$launcher"
remaining=${#pids[@]}
while [ "$remaining" -gt 0 ] && [ $(( $(date +%s%3N) - start_ms )) -lt 5000 ]; do
  remaining=0
  for pid in "${pids[@]}"; do
    [ -n "${gone_ms[$pid]:-}" ] && continue
    if kill -0 "$pid" 2>/dev/null; then remaining=$((remaining + 1)); else gone_ms[$pid]=$(( $(date +%s%3N) - start_ms )); fi
  done
  sleep 0.01
done
wait "$launcher"
launch_status=$?
worst=0
for pid in "${pids[@]}"; do
  t="${gone_ms[$pid]:-99999}"
  echo "${name_of[$pid]} exited ${t} ms after SIGTERM to the launcher"
  [ "$t" -gt "$worst" ] && worst=$t
done
echo "sigterm_launcher: launcher exit $launch_status (143 expected), slowest process gone ${worst} ms after the signal (reported; a process that ignores SIGTERM fails below)"
grep -q "ignored SIGTERM" "$work/launch.out" && { echo "a process ignored SIGTERM"; exit 1; }
"$build/bin/sdlqr-faultcheck" "$log" --complete
check_status=$?
[ "$launch_status" -eq 143 ] && [ "$check_status" -eq 0 ]
