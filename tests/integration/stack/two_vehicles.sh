#!/usr/bin/env bash
# Two stacks under different --vehicle prefixes fly at once on one bus (the caller provides a
# private network namespace), recorded by one ground logger with no prefix (every channel of both).
# Each must fly its own scenario — different setpoints, seeds and heights — to its own criteria,
# judged from the ground log alone; crosstalk would drag one towards the other's setpoints and show
# as rejected (out-of-order) messages in the heartbeats. sdlqr-top, listening mid-flight, must show
# every process of both vehicles and the ground logger alive.
#   two_vehicles.sh BUILD_DIR WORK_DIR
set -uo pipefail
build="$1" work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"

# Every process of both vehicles and the ground logger alive in sdlqr-top's last report (TOP_FILE).
# The last report is read whole by one awk: a `tac | awk '... exit' | grep -q` pipeline failed under
# pipefail whenever a reader quit early and its writer died of SIGPIPE (exit 141), naming processes
# that the very report showed alive.
top_shows_everyone() {  # TOP_FILE
  local missing=0 name last_report
  last_report=$(awk '/^PROCESS/ {report = ""; next} {report = report $0 "\n"} END {printf "%s", report}' "$1")
  for name in sdlqr-logger QUAD{1,2}/sdlqr-{estimator,gains,controller,lowlevel,mission,sim}; do
    grep -qE "^$name +alive" <<< "$last_report" || { echo "sdlqr-top: $name not alive"; missing=1; }
  done
  return "$missing"
}
# The check fails on a report without one vehicle (its negative).
printf 'PROCESS HEALTH\nsdlqr-logger alive\nQUAD1/sdlqr-sim alive\n' > "$work/top_negative.txt"
if top_shows_everyone "$work/top_negative.txt" >/dev/null; then echo "FAIL: the sdlqr-top check passed a report without QUAD2"; exit 1; fi

"$build/bin/sdlqr-logger" record --out "$work/ground.lcmlog" > "$work/ground.out" 2>&1 &
logger=$!
"$build/bin/sdlqr-top" --wait-for sdlqr-logger --timeout 10 >/dev/null || { echo "ground logger never beat"; exit 1; }
"$root/scripts/launch" --build "$build" --vehicle QUAD1 --without logger --log "$work/quad1/flight.lcmlog" \
  "$here/two_vehicles_quad1.yaml" > "$work/quad1.out" 2>&1 &
pid1=$!
"$root/scripts/launch" --build "$build" --vehicle QUAD2 --without logger --log "$work/quad2/flight.lcmlog" \
  "$here/two_vehicles_quad2.yaml" > "$work/quad2.out" 2>&1 &
pid2=$!
# sdlqr-top listens once both vehicles fly (each launcher starts its simulator last): 3 s of their
# simulation clocks. One report is one sample of a live bus: a machine that stalls for seconds
# shows every process SILENT in it. So reports are taken until one shows everyone, for at most
# 12 s of wall time (top_shows_everyone judges the last report of each try).
for v in 1 2; do
  "$build/bin/sdlqr-top" --vehicle "QUAD$v" --at-sim-time 3 --timeout 60 >/dev/null ||
    echo "two_vehicles: QUAD$v's simulation clock not heard at 3 s"
done
top_ok=1
for try in 1 2 3 4; do
  "$build/bin/sdlqr-top" --plain --duration 3 > "$work/top.txt" 2>&1
  if top_shows_everyone "$work/top.txt" > "$work/top_check.txt"; then
    top_ok=0
    echo "sdlqr-top: every process of both vehicles and the ground logger alive (report of try $try)"
    break
  fi
  echo "sdlqr-top, try $try: $(paste -sd ' ' "$work/top_check.txt")"
done
wait "$pid1"; status1=$?
wait "$pid2"; status2=$?
kill -TERM "$logger"; wait "$logger"
echo "two_vehicles: launcher exit codes QUAD1 $status1, QUAD2 $status2"
if ! { [ "$status1" -eq 0 ] && [ "$status2" -eq 0 ]; }; then
  tail -20 "$work/quad1.out" "$work/quad2.out"
  exit 1
fi

result=0
for v in 1 2; do
  echo "== QUAD$v"
  "$build/bin/sdlqr-analyze" "$work/ground.lcmlog" --vehicle "QUAD$v" \
    --scenario "$here/two_vehicles_quad$v.yaml" --json "$work/quad$v.json" || result=1
  # No process of this vehicle may have rejected a message: another vehicle's messages on its
  # channels would be rejected as out of order or counted as sequence gaps.
  rejected=$(/usr/bin/python3 -c "
import json, sys
r = json.load(open('$work/quad$v.json'))
print(sum(p['rejected'] for p in r['processes']))")
  echo "QUAD$v: messages rejected by its processes: $rejected"
  [ "$rejected" -eq 0 ] || result=1
done
echo "== sdlqr-top mid-flight"
[ "$top_ok" -eq 0 ] || { tail -20 "$work/top.txt"; result=1; }
exit "$result"
