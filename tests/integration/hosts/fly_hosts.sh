#!/usr/bin/env bash
# Flies a scenario over emulated hosts (scripts/deploy) and checks every criterion of the
# scenario with sdlqr-analyze; prints the bandwidth per channel the ground recorder heard.
# With MIN_US > 0 the STATE_EST -> RATE_CMD median at the recorder must be at least MIN_US (a
# delay the deployment adds shows); with MIN_US < 0 it must stay below -MIN_US (negative test:
# the check fails on a flight without the delay).
#   fly_hosts.sh BUILD_DIR WORK_DIR SCENARIO DEPLOYMENT MIN_US [deploy options...]
set -uo pipefail
build="$1" work="$2" scenario="$3" deployment="$4" min_us="$5"
shift 5
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"
"$root/scripts/deploy" --deploy "$deployment" --build "$build" --log "$log" "$@" "$scenario"
status=$?
echo "fly_hosts: deploy exit code $status"
[ "$status" -eq 0 ] || exit 1
"$build/bin/sdlqr-linkcheck" --bandwidth "$log" | tee "$work/bandwidth.txt"
ok=0
"$build/bin/sdlqr-linkcheck" --latency "$log,$log" --min-median-us "${min_us#-}" >"$work/latency.txt"
latency_status=$?
cat "$work/latency.txt"
if [ "$min_us" -ge 0 ]; then
  [ "$latency_status" -eq 0 ] || ok=1
elif [ "$latency_status" -eq 1 ] && grep -q '^FAIL STATE_EST -> RATE_CMD median' "$work/latency.txt"; then
  echo "ok   (negative) without an added delay the check of a ${min_us#-} us delay fails (exit 1, FAIL STATE_EST -> RATE_CMD median)"
else
  echo "FAIL (negative) without an added delay the check of a ${min_us#-} us delay exits $latency_status, expected 1"
  ok=1
fi
"$build/bin/sdlqr-analyze" "$log" --scenario "$scenario" --calibration "$work/calibration.yaml" --json "$work/report.json" || ok=1
exit "$ok"
