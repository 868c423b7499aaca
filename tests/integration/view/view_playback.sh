#!/usr/bin/env bash
# issue 24: `sdlqr-view --log` plays a recorded two-vehicle flight (stack_two_vehicles' ground log)
# to the page in headless Chromium (view_playback.mjs): seek, speed, pause; judged against the
# log's CSV export.
#   view_playback.sh BUILD_DIR WORK_DIR LOG VEHICLE...
set -uo pipefail
build="$1" work="$2" log="$3"
shift 3
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
source "$here/view_support.sh"
begin_view_test "$root" "$work" browser "$log"
"$build/bin/sdlqr-logger" export "$log" --out "$work/csv" > "$work/export.out" 2>&1 || { cat "$work/export.out"; exit 1; }
port=8080
"$build/bin/sdlqr-view" --log "$log" --paused --port "$port" > "$work/view.out" 2>&1 &
view=$!
trap 'kill -TERM "$view" 2>/dev/null' EXIT
wait_for_port "$port" || { echo "FAIL: sdlqr-view does not listen on $port"; cat "$work/view.out"; exit 1; }
node "$here/view_playback.mjs" "http://127.0.0.1:$port/" "$work" "$log" "$@"
status=$?
kill -TERM "$view"
wait "$view" || { echo "FAIL: sdlqr-view exited with $?"; cat "$work/view.out"; exit 1; }
trap - EXIT
exit "$status"
