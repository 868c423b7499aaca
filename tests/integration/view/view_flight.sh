#!/usr/bin/env bash
# issue 24: a flight watched live (run in a private network namespace). sdlqr-view serves the bus;
# view_live.mjs opens the page in headless Chromium, connects @foxglove/ws-protocol's client, a
# client that stops reading and, briefly, a page fed a wrong schema; the stack flies
# view_flight.yaml under the prefix QUAD1; then the log is exported (CSV, the independent path)
# and view_judge.mjs checks what each client saw against it. The view's CPU over the flight is
# measured here and reported with the flight's deadline misses (not judged).
#   view_flight.sh BUILD_DIR WORK_DIR
set -uo pipefail
build="$1" work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
source "$here/view_support.sh"
begin_view_test "$root" "$work" browser
port=8080 proxy_port=8090 unbounded_port=8081

# A per-client bound of 128 KiB (default 1 MiB): the stalled client reaches it within the flight.
"$build/bin/sdlqr-view" --port "$port" --max-client-buffer 128 > "$work/view.out" 2>&1 &
view=$!
# The negative: the same view with the bound lifted to a GiB.
"$build/bin/sdlqr-view" --port "$unbounded_port" --max-client-buffer 1048576 > "$work/unbounded_view.out" 2>&1 &
unbounded_view=$!
trap 'kill -TERM "$view" "$unbounded_view" "${watcher:-}" 2>/dev/null' EXIT
for p in "$port" "$unbounded_port"; do
  wait_for_port "$p" || { echo "FAIL: sdlqr-view does not listen on $p"; cat "$work/view.out"; exit 1; }
done
node "$here/view_live.mjs" "http://127.0.0.1:$port/" "$work" "$proxy_port" "$unbounded_port" > "$work/live.out" 2>&1 &
watcher=$!
for _ in $(seq 300); do [ -f "$work/browser.ready" ] || ! kill -0 "$watcher" 2>/dev/null && break; sleep 0.1; done
[ -f "$work/browser.ready" ] || { echo "FAIL: the browser never got ready"; cat "$work/live.out"; exit 1; }

cpu_before=$(cpu_ticks "$view") wall_before=$(date +%s%3N)
"$root/scripts/launch" --build "$build" --vehicle QUAD1 --log "$work/flight.lcmlog" "$here/view_flight.yaml" \
  > "$work/launch.out" 2>&1
launch_status=$?
date +%s%3N > "$work/flight.done"
cpu_after=$(cpu_ticks "$view") wall_after=$(date +%s%3N)
awk -v t=$((cpu_after - cpu_before)) -v w=$((wall_after - wall_before)) \
  'BEGIN { printf "%.2f CPU-s in %.1f s (%.1f %% of a core)\n", t / 100, w / 1000, 100 * (t / 100) / (w / 1000) }' > "$work/view_cpu.txt"
wait "$watcher"
watcher_status=$?
kill -TERM "$view" "$unbounded_view"
wait "$view"
view_status=$?
wait "$unbounded_view" || view_status=1
trap - EXIT
tail -3 "$work/launch.out"
echo "view_flight: launcher exit code $launch_status, page watcher $watcher_status, sdlqr-view $view_status"
if ! { [ "$launch_status" -eq 0 ] && [ "$watcher_status" -eq 0 ] && [ "$view_status" -eq 0 ]; }; then
  cat "$work/live.out" "$work/view.out"
  exit 1
fi
"$build/bin/sdlqr-logger" export "$work/flight.lcmlog" --out "$work/csv" > "$work/export.out" 2>&1 || { cat "$work/export.out"; exit 1; }
# The view listens only: nothing it could have published (a HEARTBEAT first of all) is in the log.
if grep -q '"sdlqr-view"' "$work/csv/QUAD1/HEARTBEAT.csv" "$work/csv/HEARTBEAT.csv" 2>/dev/null; then
  echo "FAIL view_live_flight.view_never_publishes: a HEARTBEAT of sdlqr-view is in the log"
  exit 1
fi
echo "PASS view_live_flight.view_never_publishes: no message of sdlqr-view in the log"
node "$here/view_judge.mjs" "$work" QUAD1
