#!/usr/bin/env bash
# The starved machine in the suite: scripts/starved_flight judges a short flight under stress-ng.
# Negative: the same check with a stand-in for stress-ng that starts and uses no CPU (first on the
# PATH) fails naming stress_cpu (exit 1), on a flight of a few seconds.
#   starved_flight.sh BUILD_DIR WORK_DIR SCENARIO NEGATIVE_SCENARIO     (in a private network namespace)
set -uo pipefail
build="$1" work="$2" scenario="$3" negative="$4"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
SDLQR_IN_NETNS=1 bash "$root/scripts/starved_flight" --build "$build" --out "$work/starved" "$scenario"
status=$?
mkdir -p "$work/idle-bin"
printf '#!/bin/sh\nexec sleep 600\n' >"$work/idle-bin/stress-ng"
chmod +x "$work/idle-bin/stress-ng"
out="$(PATH="$work/idle-bin:$PATH" SDLQR_IN_NETNS=1 bash "$root/scripts/starved_flight" --build "$build" \
  --out "$work/idle" "$negative")"
negative_status=$?
if [ "$negative_status" -eq 1 ] && grep -q '^FAIL stress_cpu: ' <<<"$out"; then
  echo "ok   (negative) a stress-ng that uses no CPU: exit 1, $(grep '^FAIL stress_cpu: ' <<<"$out")"
else
  echo "FAIL (negative) a stress-ng that uses no CPU: exit $negative_status, expected 1 with 'FAIL stress_cpu':"
  echo "$out"
  status=1
fi
exit "$status"
