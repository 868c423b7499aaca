#!/usr/bin/env bash
# The emulated PX4 refuses OFFBOARD without the setpoint stream and takes it with one, asked by
# node-mavlink over UDP (handshake_client.mjs). The emulator listens on udp://127.0.0.1:14580 and
# answers the client's port; its simulation, estimator and bodyrate loop run meanwhile on a
# private bus (the test's network namespace).
#   handshake_refused.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -uo pipefail
source="$1" build="$2" work="$3"
. "$source/tests/support/prerequisite.sh"
command -v node >/dev/null || missing_prerequisite "node" "Debian nodejs, ./sdlqr setup"
[ -f "$source/node_modules/node-mavlink/package.json" ] ||
  missing_prerequisite "node_modules/node-mavlink" "npm ci at the repository root, ./sdlqr setup"
rm -rf "$work"
mkdir -p "$work"
unset SDLQR_MAVLINK_KEY
"$build/bin/sdlqr-px4-emulator" --config "$source/config/quad255.yaml" --mavlink udp://127.0.0.1:14580 \
  >"$work/emulator.out" 2>&1 &
emulator=$!
node "$source/tests/integration/px4/handshake_client.mjs" 14580
status=$?
kill -TERM "$emulator" 2>/dev/null
wait "$emulator"
emulator_status=$?
cat "$work/emulator.out"
[ "$emulator_status" -eq 0 ] || { echo "FAIL the emulator exited $emulator_status"; exit 1; }
exit "$status"
