#!/usr/bin/env bash
# kill -9 one flight process mid-hover, restart it after a while, and measure from the log what the
# rest of the stack did meanwhile (sdlqr-faultcheck --NAME-outage). The launcher starts the stack
# without NAME (--without); this script runs NAME itself so it can kill and restart it.
#   process_outage.sh BUILD_DIR WORK_DIR SCENARIO NAME KILL_AFTER_S DOWN_FOR_S [faultcheck options...]
# NAME: gains, estimator or controller. KILL_AFTER_S: wall seconds after the simulator started (the
# launcher's "scenario" line), not after the launch: the bus calibration and the start-up before
# it took 2 s on one machine and over 5 s on another, where the kill landed before the take-off.
set -uo pipefail
build="$1" work="$2" scenario="$3" name="$4" kill_after="$5" down_for="$6"
shift 6
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
case "$name" in
  gains|controller) binary="$build/bin/sdlqr-$name" ;;
  estimator) binary="$build/bin/sdlqr-estimator" ;;
  *) echo "process_outage: unknown process '$name'"; exit 2 ;;
esac
config="$("$build/bin/sdlqr-mission" --describe "$scenario" | sed -n 's/^vehicle=//p')"
[ -n "$config" ] || { echo "process_outage: cannot read the scenario"; exit 2; }
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"

now_us() { date +%s%6N; }
"$root/scripts/launch" --build "$build" --log "$log" --without "$name" "$scenario" > "$work/launch.out" 2>&1 &
launcher=$!
"$binary" --config "$config" > "$work/$name.1.out" 2>&1 &
pid=$!
started=0
for _ in $(seq 600); do
  grep -q '^launch: scenario ' "$work/launch.out" && { started=1; break; }
  kill -0 "$launcher" 2>/dev/null || break
  sleep 0.1
done
[ "$started" = 1 ] || { echo "process_outage: the simulator never started"; cat "$work/launch.out"; kill -TERM "$launcher" "$pid"; wait; exit 1; }
sleep "$kill_after"
kill -0 "$pid" 2>/dev/null || { echo "process_outage: $name died on its own"; cat "$work/$name.1.out"; kill -TERM "$launcher"; wait; exit 1; }
kill_us=$(now_us)
kill -KILL "$pid"
wait "$pid" 2>/dev/null
sleep "$down_for"
restart_us=$(now_us)
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
