#!/usr/bin/env bash
# Replay of the fixture's recorded hover flight reproduces the recorded outputs: fast mode must
# report RATE_CMD, GAINS, STATE_EST and REFERENCE identical bit for bit; --speed 4 must pace the
# same replay at four times real time (wall time >= flight time / 4) with the same verdict; an
# existing output is never overwritten.
#   check_replay.sh SDLQR_REPLAY FLIGHT_DIR VEHICLE_FILE
set -u
replay="$1" dir="$2" vehicle="$3"
log="$dir/flight.lcmlog"
rm -f "$dir"/replay-*.lcmlog
failed=0
fail() { echo "FAIL: $*"; failed=1; }

echo "== fast"
"$replay" "$log" --config "$vehicle" --fast --out "$dir/replay-fast.lcmlog" | tee "$dir/replay-fast.txt"
status=${PIPESTATUS[0]}
[ "$status" -eq 0 ] || fail "sdlqr-replay exit code $status"
for channel in RATE_CMD GAINS STATE_EST REFERENCE; do
  grep -Eq "^$channel .*identical bit for bit" "$dir/replay-fast.txt" || fail "$channel not identical bit for bit"
done
grep -q "verdict: every output identical bit for bit" "$dir/replay-fast.txt" || fail "no bit-for-bit verdict"

echo "== --speed 4"
start=$(date +%s%N)
"$replay" "$log" --config "$vehicle" --speed 4 --out "$dir/replay-paced.lcmlog" >"$dir/replay-paced.txt"
status=$?
wall_ms=$(( ($(date +%s%N) - start) / 1000000 ))
flight_s=$(sed -n 's/^recomputed \([0-9.]*\) s of flight.*/\1/p' "$dir/replay-paced.txt")
echo "paced replay: ${flight_s} s of flight in ${wall_ms} ms"
[ "$status" -eq 0 ] || fail "paced replay exit code $status"
# Judged only on its figure: without a "recomputed N s of flight" line there is nothing to compare.
if [[ "$flight_s" =~ ^[0-9]+([.][0-9]+)?$ ]] && awk -v f="$flight_s" 'BEGIN { exit !(f > 1) }'; then
  awk -v f="$flight_s" -v w="$wall_ms" 'BEGIN { exit !(w >= f * 1000 / 4 - 50) }' || fail "--speed 4 ran faster than 4x"
else
  fail "the paced replay printed no 'recomputed N s of flight' figure (got '$flight_s')"
fi
grep -q "verdict: every output identical bit for bit" "$dir/replay-paced.txt" || fail "paced replay differs"

echo "== refuses to overwrite"
"$replay" "$log" --config "$vehicle" --out "$dir/replay-fast.lcmlog" 2>"$dir/overwrite.err" >/dev/null
status=$?
[ "$status" -eq 2 ] || fail "overwrite: exit code $status, expected 2"
cat "$dir/overwrite.err"
[ $failed -eq 0 ] && echo PASS || echo FAILED
exit $failed
