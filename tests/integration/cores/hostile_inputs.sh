#!/usr/bin/env bash
# The same hostile inputs on the bus and in the replay: the real executables fly hostile_hover
# over real multicast while hostile_peer publishes the set (tests/support/hostile_inputs.hpp) at
# t = 5 s (again, for an input a busy receiver dropped on arrival) and reads every process's HEARTBEAT; then sdlqr-replay recomputes the recorded flight,
# hostile inputs included, and its cores must count the same rejections. The in-process loop's
# check of the same set is tests/unit/tools/offline/closedloop/hostile_inputs_test.cpp.
#   hostile_inputs.sh BUILD_DIR WORK_DIR PEER
set -uo pipefail
build="$1" work="$2" peer="$3"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$here/../../.."
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"
"$root/scripts/launch" --build "$build" --log "$log" "$here/hostile_hover.yaml" > "$work/launch.out" 2>&1 &
launcher=$!
"$peer" attack --at 5 --copies "$work/copies.txt" > "$work/bus.out" 2>&1
bus_status=$?
wait "$launcher"
launch_status=$?
cat "$work/bus.out"
grep -E '^launch:.*(ended|crash|killed)' "$work/launch.out"
"$build/bin/sdlqr-replay" "$log" --config "$root/config/quad255.yaml" --out "$work/replay.lcmlog" > "$work/replay.out" 2>&1
grep -E '^(rejections|foreign)' "$work/replay.out"
"$peer" check-replay "$work/replay.out" --copies "$work/copies.txt"
replay_status=$?
echo "hostile_inputs: bus check $bus_status, launcher $launch_status, replay check $replay_status"
[ "$bus_status" -eq 0 ] && [ "$launch_status" -eq 0 ] && [ "$replay_status" -eq 0 ]
