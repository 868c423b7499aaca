#!/usr/bin/env bash
# Takes one host's link down for a while mid-hover (scripts/deploy --link-down: its bridge port
# stops forwarding, both ways) and checks from the ground recorder's log what the rest did.
#   link_down.sh BUILD_DIR WORK_DIR SCENARIO DEPLOYMENT HOST AT_S FOR_S CHECK...
# CHECK: `companion` (the lowlevel failsafe holds the vehicle, the controller takes over again
# and the mission goes on: sdlqr-faultcheck --controller-outage and every scenario criterion) or
# `ground` (the vehicle flies on, the recorder shows the silence and lost nothing else:
# sdlqr-linkcheck --gap, and every scenario criterion).
set -uo pipefail
build="$1" work="$2" scenario="$3" deployment="$4" host="$5" at="$6" for_s="$7" check="$8"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"
"$root/scripts/deploy" --deploy "$deployment" --build "$build" --log "$log" --link-down "$host:$at:$for_s" \
  --events "$work/events.txt" "$scenario"
status=$?
echo "link_down: deploy exit code $status"
cat "$work/events.txt" 2>/dev/null
down="$(awk -v h="$host" '$1 == "link_down" && $2 == h { print $3 }' "$work/events.txt" 2>/dev/null)"
up="$(awk -v h="$host" '$1 == "link_up" && $2 == h { print $3 }' "$work/events.txt" 2>/dev/null)"
[ -n "$down" ] && [ -n "$up" ] || { echo "link_down: the link of $host never went down and up"; exit 1; }
[ "$status" -eq 0 ] || exit 1
# The check of the outage, on the window it happened and (negative) on one 4 s later, when the
# link was up: there it must fail.
check_window() {  # DOWN_US UP_US
  case "$check" in
    # Held at the takeoff setpoint until the step at 16 s.
    companion) "$build/bin/sdlqr-faultcheck" "$log" --controller-outage "$1,$2" --setpoint 0,0,1 --settle-until 15.9 ;;
    ground) "$build/bin/sdlqr-linkcheck" --gap "$log" --down "$1,$2" ;;
  esac
}
case "$check" in companion|ground) ;; *) echo "link_down: unknown check '$check'"; exit 2 ;; esac
ok=0
check_window "$down" "$up" | tee "$work/check.out"
[ "${PIPESTATUS[0]}" -eq 0 ] || ok=1
check_window "$((down + 4000000))" "$((up + 4000000))" >"$work/check_link_up.out"
negative=$?
# Failing for the outage's own reason: the controller's gap, or the recorder's silence on IMU.
case "$check" in companion) named='^FAIL controller outage' ;; ground) named='^FAIL IMU: ' ;; esac
if [ "$negative" -eq 1 ] && grep -q "$named" "$work/check_link_up.out"; then
  echo "ok   the same check 4 s later, with the link up, fails (exit 1): $(grep -m1 "$named" "$work/check_link_up.out")"
else
  echo "FAIL the same check 4 s later, with the link up, exits $negative (expected 1 with '$named'):"
  cat "$work/check_link_up.out"
  ok=1
fi
"$build/bin/sdlqr-analyze" "$log" --scenario "$scenario" --calibration "$work/calibration.yaml" --json "$work/report.json" || ok=1
exit "$ok"
