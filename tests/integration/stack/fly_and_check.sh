#!/usr/bin/env bash
# Flies one scenario with the real executables over real multicast (the caller runs this in its
# own network namespace) and checks every criterion of the scenario with sdlqr-analyze.
#   fly_and_check.sh BUILD_DIR WORK_DIR SCENARIO [--drop CHANNEL[:SEQ]=CHECK]... [launch options...]
# Each --drop is a negative test on the flight's own log: the log without that channel's messages
# (or without one seq of it, a COMMAND and its re-sends; tests/integration/stack/log_without.cpp)
# must fail sdlqr-analyze (exit 1) with the check CHECK among its failures, named "not in the log".
set -uo pipefail
build="$1" work="$2" scenario="$3"
shift 3
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
drops=()
while [ "${1:-}" = --drop ]; do
  drops+=("$2")
  shift 2
done
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"
vehicle_args=()
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  [ "${args[$i]}" = --vehicle ] && vehicle_args=(--vehicle "${args[$((i + 1))]}")
done
analyze() {  # LOG [sdlqr-analyze options...]
  local log="$1"
  shift
  "$build/bin/sdlqr-analyze" "$log" --scenario "$scenario" "${vehicle_args[@]+"${vehicle_args[@]}"}" \
    --calibration "$work/calibration.yaml" "$@"
}

"$root/scripts/launch" --build "$build" --log "$log" "$@" "$scenario"
launch_status=$?
echo "fly_and_check: launcher exit code $launch_status"
[ "$launch_status" -eq 0 ] || exit 1
analyze "$log" --json "$work/report.json"
status=$?
[ "$status" -eq 0 ] || exit "$status"

# One cut log per CHANNEL[:SEQ], judged once; each of its checks must be among the failures.
declare -A judged=()
for drop in "${drops[@]+"${drops[@]}"}"; do
  what="${drop%%=*}" check="${drop#*=}"
  cut="$work/without-${what//[:\/]/-}.lcmlog"
  if [ -z "${judged[$what]+set}" ]; then
    channel="${what%%:*}" seq=()
    [ "$what" != "$channel" ] && seq=("${what#*:}")
    "$build/bin/log_without" "$log" "$cut" "$channel" "${seq[@]+"${seq[@]}"}" || exit 1
    analyze "$cut" >"$cut.analyze.txt" 2>&1
    judged[$what]=$?
  fi
  failed="$(grep -F "  FAILED $check: " "$cut.analyze.txt")"
  if [ "${judged[$what]}" -eq 1 ] && grep -q "not in the log" <<<"$failed"; then
    echo "ok   (negative) without $what: exit 1,$failed"
  else
    echo "FAIL (negative) without $what: exit ${judged[$what]}, expected 1 with 'FAILED $check: ... not in the log'; its failures:"
    grep -E '^  FAILED' "$cut.analyze.txt"
    status=1
  fi
done
exit "$status"

for drop in "${drops[@]+"${drops[@]}"}"; do
  what="${drop%%=*}" check="${drop#*=}"
  channel="${what%%:*}" seq=()
  [ "$what" != "$channel" ] && seq=("${what#*:}")
  cut="$work/without-${what//[:\/]/-}.lcmlog"
  "$build/bin/log_without" "$log" "$cut" "$channel" "${seq[@]+"${seq[@]}"}" || exit 1
  out="$(analyze "$cut" 2>&1)"
  negative=$?
  failed="$(grep -F "  FAILED $check: " <<<"$out")"
  if [ "$negative" -eq 1 ] && grep -q "not in the log" <<<"$failed"; then
    echo "ok   (negative) without $what: exit 1, $failed"
  else
    echo "FAIL (negative) without $what: exit $negative, expected 1 with 'FAILED $check: ... not in the log'; its failures:"
    grep -E '^  FAILED' <<<"$out"
    status=1
  fi
done
exit "$status"
