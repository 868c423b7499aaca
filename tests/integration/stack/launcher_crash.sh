#!/usr/bin/env bash
# The launcher notices a crashed process: kill -9 the controller mid-flight, expect the whole
# stack stopped promptly and a non-zero exit naming the process.
#   launcher_crash.sh BUILD_DIR WORK_DIR SCENARIO
set -uo pipefail
build="$1" work="$2" scenario="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
"$root/scripts/launch" --build "$build" --log "$work/flight.lcmlog" "$scenario" > "$work/launch.out" 2>&1 &
launcher=$!
sleep 4
# Only this launcher's children: other tests may fly their own stacks at the same time.
children=$(pgrep -P "$launcher" | tr '\n' ' ')
victim=$(pgrep -P "$launcher" -f "bin/sdlqr-controller" | head -1)
[ -n "$victim" ] || { echo "controller not running"; cat "$work/launch.out"; exit 1; }
kill -9 "$victim"
start_ms=$(date +%s%3N)
wait "$launcher"
status=$?
elapsed_ms=$(( $(date +%s%3N) - start_ms ))
grep '^launch:' "$work/launch.out"
echo "launcher exit code $status, stack stopped ${elapsed_ms} ms after the kill"
leftover=0
for pid in $children; do kill -0 "$pid" 2>/dev/null && leftover=$((leftover + 1)); done
echo "processes left running: $leftover"
[ "$status" -eq 1 ] && grep -q "controller ended early (killed by signal 9)" "$work/launch.out" && [ "$leftover" -eq 0 ] &&
  [ "$elapsed_ms" -lt 4000 ]
