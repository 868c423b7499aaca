#!/usr/bin/env bash
# 10 % packet loss and 0-5 ms jitter on every channel of every flight process (the kernel has no
# netem: Node's seeded injection, SDLQR_FAULTS). Pass: hover error below 0.1 m, no process dies,
# the injection visibly active (fault.dropped, fault.delayed counted in HEARTBEAT).
#   loss_flight.sh BUILD_DIR WORK_DIR SCENARIO
set -uo pipefail
build="$1" work="$2" scenario="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"
SDLQR_FAULTS="drop=0.1,delay_ms=0:5,seed=3" "$root/scripts/launch" --build "$build" --log "$log" "$scenario" \
  > "$work/launch.out" 2>&1
launch_status=$?
grep -E '^launch:.*(ended|crash|killed)' "$work/launch.out"
echo "loss_flight: launcher exit $launch_status"
# Hover from 5 s (take-off settled) until the landing command at 28 s.
"$build/bin/sdlqr-faultcheck" "$log" --hover 5,27.5,0,0,1 --max-hover-error 0.1 --require fault.dropped,fault.delayed
check_status=$?
[ "$launch_status" -eq 0 ] && [ "$check_status" -eq 0 ]
