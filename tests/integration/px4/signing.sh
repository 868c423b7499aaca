#!/usr/bin/env bash
# The signed MAVLink link (docs/px4.md): sdlqr-px4 and sdlqr-px4-emulator over UDP with key files of
# the bus key's rules (64 hex digits, mode 0600), each pair for 3 s of simulation time, a recorder
# keeping their HEARTBEATs:
#   same key      they talk: the bridge publishes PX4's ODOMETRY as STATE_EST, the emulator takes
#                 the bridge's setpoints, nothing is refused for its signature
#   wrong key     nothing passes: each side refuses the other's frames (bad_signature), no
#                 STATE_EST, no setpoint taken
#   unsigned      an emulator without a key: the bridge refuses its frames (unsigned)
# Each case's checks are the others' negatives (a counter required in one is forbidden in another).
#   signing.sh BUILD_DIR WORK_DIR CONFIG
set -uo pipefail
build="$1" work="$2" config="$3"
rm -rf "$work"
mkdir -p "$work"
unset SDLQR_MAVLINK_KEY SDLQR_BUS_KEY
new_key() { (umask 077 && head -c 32 /dev/urandom | od -An -v -tx1 | tr -d ' \n' >"$1" && echo >>"$1"); }
new_key "$work/a.key"
new_key "$work/b.key"

pair() {  # CASE BRIDGE_KEY EMULATOR_KEY (empty: unsigned)
  local case="$1" bridge_key=() emulator_key=()
  [ -n "$2" ] && bridge_key=(--mavlink-key "$2")
  [ -n "$3" ] && emulator_key=(--mavlink-key "$3")
  mkdir -p "$work/$case"
  "$build/bin/sdlqr-logger" record --out "$work/$case/flight.lcmlog" --channels HEARTBEAT >"$work/$case/logger.out" 2>&1 &
  local logger=$!
  "$build/bin/sdlqr-px4" --config "$config" --mavlink udp://127.0.0.1:14540 "${bridge_key[@]+"${bridge_key[@]}"}" \
    >"$work/$case/px4.out" 2>&1 &
  local bridge=$!
  "$build/bin/sdlqr-px4-emulator" --config "$config" --mavlink udpout://127.0.0.1:14540:14580 \
    "${emulator_key[@]+"${emulator_key[@]}"}" >"$work/$case/emulator.out" 2>&1 &
  local emulator=$!
  "$build/bin/sdlqr-top" --at-sim-time 3 --timeout 60 >/dev/null 2>"$work/$case/top.err" ||
    { echo "FAIL $case: the emulator's clock never reached 3 s"; cat "$work/$case/top.err"; }
  kill -TERM "$bridge" "$emulator"
  wait "$bridge" "$emulator"
  kill -TERM "$logger"
  wait "$logger"
}
check() {  # CASE faultcheck options...
  local case="$1"
  shift
  echo "-- $case"
  "$build/bin/sdlqr-faultcheck" "$work/$case/flight.lcmlog" --max-silence 1000 --expect sdlqr-px4,sdlqr-px4-emulator "$@" |
    grep -E '^(ok|FAIL) .* over all processes'
  return "${PIPESTATUS[0]}"
}

pair same "$work/a.key" "$work/a.key"
pair wrong "$work/a.key" "$work/b.key"
pair unsigned "$work/a.key" ""
ok=0
check same --require px4.estimates,px4emu.setpoints,mavlink.frames \
  --forbid mavlink.drop.bad_signature,mavlink.drop.unsigned,mavlink.drop.replayed || ok=1
check wrong --require mavlink.drop.bad_signature --forbid px4.estimates,px4emu.setpoints,mavlink.frames || ok=1
check unsigned --require mavlink.drop.unsigned --forbid px4.estimates || ok=1
grep -rqF "$(cat "$work/a.key")" "$work"/*/*.out && { echo "FAIL a key appears in the output"; ok=1; }
exit "$ok"
