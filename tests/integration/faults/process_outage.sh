#!/usr/bin/env bash
# kill -9 one flight process mid-hover, restart it after a while, and measure from the log what the
# rest of the stack did meanwhile (sdlqr-faultcheck --NAME-outage). The launcher starts the stack
# without NAME (--without); this script runs NAME itself so it can kill and restart it.
#   process_outage.sh BUILD_DIR WORK_DIR SCENARIO NAME KILL_AT_S DOWN_FOR_S [faultcheck options...]
# NAME: gains, estimator or controller. KILL_AT_S: simulation time of the kill; the restart follows
# DOWN_FOR_S seconds of simulation time later (tests/support/sim_time.sh): wall seconds after the
# launch put the kill before the take-off on one machine (calibration and start-up took over 5 s),
# and a machine stalling for seconds stretches a wall-clock outage in the flight.
set -uo pipefail
build="$1" work="$2" scenario="$3" name="$4" kill_at="$5" down_for="$6"
shift 6
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
source "$root/tests/support/sim_time.sh"
case "$name" in
  gains|controller) binary="$build/bin/sdlqr-$name" ;;
  estimator) binary="$build/bin/sdlqr-estimator" ;;
  *) echo "process_outage: unknown process '$name'"; exit 2 ;;
esac
config="$("$build/bin/sdlqr-mission" --describe "$scenario" | sed -n 's/^vehicle=//p')"
[ -n "$config" ] || { echo "process_outage: cannot read the scenario"; exit 2; }
restart_at=$(awk -v a="$kill_at" -v d="$down_for" 'BEGIN { print a + d }')
start_marked_flight "$build" "$work" "$kill_at,$restart_at" --without "$name" "$scenario"
"$binary" --config "$config" > "$work/$name.1.out" 2>&1 &
pid=$!
abort() { echo "process_outage: $*"; cat "$work/launch.out"; kill -TERM "$launcher" "$pid" 2>/dev/null; stop_sim_time; wait; exit 1; }
wait_sim_time "$kill_at" || abort "no kill: the flight never reached $kill_at s"
kill -0 "$pid" 2>/dev/null || { cat "$work/$name.1.out"; abort "$name died on its own"; }
now_us kill_us
kill -KILL "$pid"
wait "$pid" 2>/dev/null
wait_sim_time "$restart_at" || abort "no restart: the flight never reached $restart_at s"
now_us restart_us
"$binary" --config "$config" > "$work/$name.2.out" 2>&1 &
pid=$!
wait "$launcher"
launch_status=$?
restarted_alive=0
kill -0 "$pid" 2>/dev/null && restarted_alive=1
kill -TERM "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
grep -E '^launch:.*(ended|crash|killed)' "$work/launch.out"
echo "process_outage: kill -9 $name at wall $kill_us us, restarted $(( (restart_us - kill_us) / 1000 )) ms later;" \
     "launcher exit $launch_status, restarted $name alive to the end: $restarted_alive"
# The figures stay in the work folder (check.out) after ctest, which shows output only on failure.
expected=$(sed -n 's/^\([a-z]\+\) .*/sdlqr-\1/p' "$root/config/stack.procs" | paste -sd, -)
"$build/bin/sdlqr-faultcheck" "$log" --expect "$expected" "--$name-outage" "$kill_us,$restart_us" "$@" |
  tee "$work/check.out"
check_status=${PIPESTATUS[0]}
[ "$launch_status" -eq 0 ] && [ "$restarted_alive" -eq 1 ] && [ "$check_status" -eq 0 ]
