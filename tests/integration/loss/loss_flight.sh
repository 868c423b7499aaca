#!/usr/bin/env bash
# hover_jumps on a bus that loses PERCENT % of every datagram in the kernel: every functional
# criterion of the scenario must hold (none loosened; the timing ones measure the loss itself and
# are reported: at 0.5 % the STATE_EST -> RATE_CMD latency p99 and the wall jitter p99 reach 66x
# and 75x the lossless calibration's one-way p99), and the loss must be visible where it
# happened — the kernel dropped datagrams, and the subscribers counted lost messages per channel.
#   loss_flight.sh BUILD_DIR WORK_DIR SCENARIO PERCENT     (in a private network namespace)
set -uo pipefail
build="$1" work="$2" scenario="$3" percent="$4"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
flight_out=$(SDLQR_IN_NETNS=1 "$root/scripts/loss_flight" --build "$build" --out "$work" --percent "$percent" "$scenario")
flight_status=$?
echo "$flight_out"
grep -q "launcher exit 0$" <<<"$flight_out" || { echo "FAIL: the launcher did not end cleanly (a process died?)"; exit 1; }
lost=$(/usr/bin/python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))
print(sum(l["lost"] for l in r["message_loss"] if l["process"] != "log"))' "$work/report.json" 2>/dev/null || echo 0)
echo "loss_flight: subscribers counted $lost lost message(s)"
[ "$lost" -gt 0 ] || { echo "FAIL: no subscriber counted a lost message: the loss was not active"; exit 1; }
[ -f "$work/report.json" ] || exit "$flight_status"
"$root/scripts/functional_verdict" "$work/report.json" loss_flight
