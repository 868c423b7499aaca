#!/usr/bin/env bash
# Fixture of the record / replay / inspect tests (run in a private network namespace): flies the
# short hover scenario with the real processes and, meanwhile,
#   - sdlqr-top reports the bus once a second (top.out),
#   - a second sdlqr-logger records the same bus and is killed with kill -9 at 6 s of simulation
#     time (killed.lcmlog, the kill's wall time in killed.utime).
#   record_flight.sh BUILD_DIR WORK_DIR SCENARIO
set -uo pipefail
build="$1" work="$2" scenario="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
source "$root/tests/support/sim_time.sh"
rm -rf "$work" && mkdir -p "$work"

"$build/bin/sdlqr-top" --plain --duration 13 >"$work/top.out" 2>"$work/top.err" &
top_pid=$!
"$build/bin/sdlqr-logger" record --out "$work/killed.lcmlog" >"$work/killed.out" 2>&1 &
killed_pid=$!
echo "$killed_pid" >"$work/killed.pid"  # its heartbeats in the flight's log say what it lost
# The kill at 6 s of simulation time, hovering (tests/support/sim_time.sh).
sim_time_marks "$build" 6
(
  if wait_sim_time 6; then
    now_us killed_at
    kill -9 "$killed_pid"
    echo "$killed_at" >"$work/killed.utime"
  fi
  kill -9 "$killed_pid" 2>/dev/null
) &
killer_pid=$!

"$root/scripts/launch" --build "$build" --log "$work/flight.lcmlog" "$scenario" >"$work/launch.out" 2>&1
status=$?
wait "$killer_pid"
wait "$killed_pid" 2>/dev/null
wait "$top_pid"
top_status=$?
tail -5 "$work/launch.out"
echo "record_flight: launcher exit code $status, sdlqr-top exit code $top_status"
[ "$status" -eq 0 ] && [ "$top_status" -eq 0 ] && [ -s "$work/flight.lcmlog" ] && [ -s "$work/killed.utime" ]
