#!/usr/bin/env bash
# A hostile publisher on the bus mid-hover: sdlqr-fuzz-publisher floods every channel at 1 kHz for
# 10 s (random bytes, truncated, oversized, wrong fingerprint, NaN/Inf, huge values, replays).
# Pass: no process crashes or stalls (launcher exit 0; every process of config/stack.procs beats,
# its own heartbeats never silent > 2.5 s, to the end of the log: forged ones do not count), hover
# error below 0.1 m (SIM_TRUTH, which the fuzzer leaves alone), every rejection kind counted.
#   fuzz_flight.sh BUILD_DIR WORK_DIR SCENARIO
set -uo pipefail
build="$1" work="$2" scenario="$3"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
source "$root/tests/support/sim_time.sh"
# The attack starts at 5 s of simulation time, airborne and settled at 1 m (tests/support/sim_time.sh).
start_marked_flight "$build" "$work" 5 "$scenario"
fuzz_status=1
if wait_sim_time 5; then
  "$build/bin/sdlqr-fuzz-publisher" --duration 10 --rate 1000 --seed 5 > "$work/fuzz.out" 2>&1
  fuzz_status=$?
fi
wait "$launcher"
launch_status=$?
grep -E '^launch:.*(ended|crash|killed)' "$work/launch.out"
cat "$work/fuzz.out"
echo "fuzz_flight: fuzz publisher exit $fuzz_status, launcher exit $launch_status"
# The fuzzed channels are in the log too: hover error from SIM_TRUTH (not fuzzed) over the fuzz
# window (from 5 s of simulation time, 10 s) and 5 s after it.
# Every process of the stack table must beat to the end of the log (the fuzzer may stop early).
expected=$(sed -n 's/^\([a-z]\+\) .*/sdlqr-\1/p' "$root/config/stack.procs" | paste -sd, -)
"$build/bin/sdlqr-faultcheck" "$log" --expect "$expected" --hover 5,20,0,0,1 --max-hover-error 0.1 \
  --require reject.size,reject.decode,reject.nonfinite,reject.range,reject.time_backwards,fuzz.sent.replayed
check_status=$?
[ "$fuzz_status" -eq 0 ] && [ "$launch_status" -eq 0 ] && [ "$check_status" -eq 0 ]
