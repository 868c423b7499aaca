#!/usr/bin/env bash
# The kernel-loss check on a flight that lost nothing (the replay fixture's hover, no loss rule):
# its subscribers still count lost messages (their own queues drop: the criterion the loss flight
# used before, "some subscriber counted a loss", holds here), but the rule's counter is 0 and the
# check fails naming "kernel drops"; with a counter the log does not show (200 datagrams), it fails
# naming "kernel drops in the log".
#   kernel_negative.sh SDLQR_FAULTCHECK SDLQR_ANALYZE FLIGHT_DIR SCENARIO WORK_DIR
set -uo pipefail
faultcheck="$1" analyze="$2" dir="$3" scenario="$4" work="$5"
rm -rf "$work" && mkdir -p "$work"
ok=0
"$analyze" "$dir/flight.lcmlog" --scenario "$scenario" --json "$work/report.json" >/dev/null
queued=$(/usr/bin/python3 -c 'import json, sys
print(sum(l["lost"] for l in json.load(open(sys.argv[1]))["message_loss"] if l["process"] != "log"))' "$work/report.json")
echo "a lossless flight: its subscribers counted $queued lost message(s), all their own queues' drops"
expect() {  # COUNTER PATTERN
  local out status
  out="$("$faultcheck" "$dir/flight.lcmlog" --kernel-drops "$1")"
  status=$?
  if [ "$status" -eq 1 ] && grep -q "$2" <<<"$out"; then
    echo "ok   (negative) counter $1: exit 1, $(grep "$2" <<<"$out")"
  else
    echo "FAIL (negative) counter $1: exit $status, expected 1 with '$2'"; grep '^FAIL' <<<"$out"; ok=1
  fi
}
expect 0 '^FAIL kernel drops: the loss rule.s counter 0 '
expect 200 '^FAIL kernel drops in the log: 0 seq gaps'
exit "$ok"
