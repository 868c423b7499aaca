#!/usr/bin/env bash
# The launcher notices a crashed process: kill -9 the controller mid-flight, expect the whole
# stack stopped long before the scenario would have ended, and a non-zero exit naming the process.
#   launcher_crash.sh BUILD_DIR WORK_DIR SCENARIO
set -uo pipefail
build="$1" work="$2" scenario="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
source "$root/tests/support/sim_time.sh"
duration_s=$("$build/bin/sdlqr-mission" --describe "$scenario" | sed -n 's/^duration=//p')
start_marked_flight "$build" "$work" 2 "$scenario"
# Kill 2 s into the flight, by its simulation clock (tests/support/sim_time.sh).
wait_sim_time_or_stop "$work" 2
# Only this launcher's children: other tests may fly their own stacks at the same time.
children=$(pgrep -P "$launcher" | tr '\n' ' ')
victim=$(pgrep -n -P "$launcher" -f "bin/sdlqr-controller")
[ -n "$victim" ] || { echo "controller not running"; cat "$work/launch.out"; exit 1; }
kill -9 "$victim"
start_ms=$(date +%s%3N)
wait "$launcher"
status=$?
elapsed_ms=$(( $(date +%s%3N) - start_ms ))
grep '^launch:' "$work/launch.out"
echo "launcher exit code $status, stack stopped ${elapsed_ms} ms after the kill (the scenario had $duration_s s to go)"
leftover=0
for pid in $children; do kill -0 "$pid" 2>/dev/null && leftover=$((leftover + 1)); done
echo "processes left running: $leftover"
# Not at the scenario's end: stopped because of the crash (a slower machine only adds milliseconds).
[ "$status" -eq 1 ] && grep -q "controller ended early (killed by signal 9)" "$work/launch.out" && [ "$leftover" -eq 0 ] &&
  awk -v e="$elapsed_ms" -v d="$duration_s" 'BEGIN { exit !(e < (d - 2) * 1000 / 2) }'
