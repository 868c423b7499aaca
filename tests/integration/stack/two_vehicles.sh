#!/usr/bin/env bash
# Two stacks under different --vehicle prefixes fly at once on one bus (the caller provides a
# private network namespace). Each must fly its own scenario — different setpoints, seeds and
# heights — to its own criteria; crosstalk would drag one towards the other's setpoints and show
# as rejected (out-of-order) messages in the heartbeats.
#   two_vehicles.sh BUILD_DIR WORK_DIR
set -uo pipefail
build="$1" work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"

"$root/scripts/launch" --build "$build" --vehicle QUAD1 --log "$work/quad1.lcmlog" "$here/two_vehicles_quad1.yaml" \
  > "$work/quad1.out" 2>&1 &
pid1=$!
"$root/scripts/launch" --build "$build" --vehicle QUAD2 --log "$work/quad2.lcmlog" "$here/two_vehicles_quad2.yaml" \
  > "$work/quad2.out" 2>&1 &
pid2=$!
wait "$pid1"; status1=$?
wait "$pid2"; status2=$?
echo "two_vehicles: launcher exit codes QUAD1 $status1, QUAD2 $status2"
if [ "$status1" -ne 0 ] || [ "$status2" -ne 0 ]; then
  tail -20 "$work/quad1.out" "$work/quad2.out"
  exit 1
fi

result=0
for v in 1 2; do
  echo "== QUAD$v"
  "$build/bin/sdlqr-analyze" "$work/quad$v.lcmlog" --vehicle "QUAD$v" \
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
exit "$result"
