#!/usr/bin/env bash
# Flies a scenario over emulated hosts (scripts/deploy) and checks every criterion of the
# scenario with sdlqr-analyze; prints the bandwidth per channel the ground recorder heard.
#   fly_hosts.sh BUILD_DIR WORK_DIR SCENARIO DEPLOYMENT [deploy options...]
set -uo pipefail
build="$1" work="$2" scenario="$3" deployment="$4"
shift 4
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"
"$root/scripts/deploy" --deploy "$deployment" --build "$build" --log "$log" "$@" "$scenario"
status=$?
echo "fly_hosts: deploy exit code $status"
[ "$status" -eq 0 ] || exit 1
"$build/bin/sdlqr-linkcheck" --bandwidth "$log" | tee "$work/bandwidth.txt"
"$build/bin/sdlqr-analyze" "$log" --scenario "$scenario" --calibration "$work/calibration.yaml" --json "$work/report.json"
