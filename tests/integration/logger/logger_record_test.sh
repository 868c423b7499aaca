#!/bin/bash
# Integration test of sdlqr-logger over real LCM multicast. Run inside a private network
# namespace (see CMakeLists.txt): record while a peer publishes, stop with SIGINT and find every
# message; kill -9 mid-recording and find everything published more than 1 s before the kill;
# refuse to overwrite; export the logs (and refuse missing or foreign files); lcm-logplayer plays
# what was recorded.
#
# usage: logger_record_test.sh SDLQR_LOGGER LOGGER_TEST_PEER WORK_DIR
set -u
LOGGER=$1
PEER=$2
WORK=$3
rm -rf "$WORK" && mkdir -p "$WORK"
FAILED=0
fail() { echo "FAIL: $*"; FAILED=1; }

# Waits until the logger has printed where it records (its subscription is live then).
wait_ready() {
  for _ in $(seq 100); do
    grep -q "recording" "$1" 2>/dev/null && return 0
    sleep 0.05
  done
  fail "logger did not start: $(cat "$1")"
  return 1
}

echo "== 1. SIGINT: every published message is recorded, file named by date and scenario"
"$LOGGER" --dir "$WORK/runs" --scenario it_sigint >"$WORK/sigint.out" 2>"$WORK/sigint.err" &
LOGGER_PID=$!
wait_ready "$WORK/sigint.out"
"$PEER" publish --count 1500 --rate 500 --published "$WORK/sigint.published" || fail "publisher failed"
sleep 0.5
kill -INT $LOGGER_PID
wait $LOGGER_PID
RC=$?
[ $RC -eq 0 ] || fail "logger exit code $RC after SIGINT: $(cat "$WORK/sigint.err")"
cat "$WORK/sigint.out"
LOG=$(ls "$WORK"/runs/*-it_sigint.lcmlog 2>/dev/null | head -1)
if [ -z "$LOG" ]; then
  fail "no log in $WORK/runs"
else
  basename "$LOG" | grep -Eq '^[0-9]{8}-[0-9]{6}-it_sigint\.lcmlog$' || fail "bad log name $(basename "$LOG")"
  "$PEER" check "$LOG" --published "$WORK/sigint.published" --logger-heartbeat || fail "recorded log incomplete"
  "$LOGGER" export "$LOG" --out "$WORK/export" >"$WORK/export.out" 2>"$WORK/export.err" || fail "export failed: $(cat "$WORK/export.err")"
  ROWS=$(($(wc -l <"$WORK/export/IMU.csv") - 1))
  [ "$ROWS" -eq 1500 ] || fail "IMU.csv has $ROWS rows, expected 1500"
  grep -q '"GAINS"' "$WORK/export/metrics.json" || fail "metrics.json lacks GAINS"
  grep -q "100% " "$WORK/export.err" || fail "no progress lines: $(cat "$WORK/export.err")"
fi

echo "== 2. kill -9: the log is readable up to the last second"
"$LOGGER" --out "$WORK/killed.lcmlog" >"$WORK/kill.out" 2>&1 &
LOGGER_PID=$!
wait_ready "$WORK/kill.out"
"$PEER" publish --rate 1000 --duration 6 --published "$WORK/kill.published" >/dev/null &
PEER_PID=$!
# Mid-recording: its file has grown at six of its flushes (every 200 ms), over a second of messages.
grown=0 last=0
for _ in $(seq 60); do
  size=$(stat -c %s "$WORK/killed.lcmlog" 2>/dev/null || echo 0)
  [ "$size" -gt "$last" ] && grown=$((grown + 1)) last=$size
  [ "$grown" -ge 6 ] && break
  sleep 0.1
done
[ "$grown" -ge 6 ] || fail "the recorder wrote nothing for 6 s"
KILL_UTIME=$(date +%s%6N)
kill -9 $LOGGER_PID
wait $LOGGER_PID 2>/dev/null
kill -INT $PEER_PID
wait $PEER_PID
SIZE=$(stat -c %s "$WORK/killed.lcmlog")
echo "killed at utime $KILL_UTIME; log holds $SIZE bytes"
"$PEER" check "$WORK/killed.lcmlog" --published "$WORK/kill.published" --before $((KILL_UTIME - 1000000)) \
  || fail "messages older than 1 s before the kill are missing"

echo "== 3. an existing file is never overwritten"
SUM=$(md5sum <"$WORK/killed.lcmlog")
"$LOGGER" --out "$WORK/killed.lcmlog" --duration 1 >"$WORK/over.out" 2>"$WORK/over.err"
RC=$?
[ $RC -eq 2 ] || fail "exit code $RC for an existing file, expected 2"
[ "$(wc -l <"$WORK/over.err")" -eq 1 ] || fail "expected a one-line error, got: $(cat "$WORK/over.err")"
grep -q "refusing to overwrite" "$WORK/over.err" || fail "unexpected error: $(cat "$WORK/over.err")"
[ "$(md5sum <"$WORK/killed.lcmlog")" = "$SUM" ] || fail "existing log was modified"
cat "$WORK/over.err"

echo "== 4. export: a truncated log is exported with a warning; missing and foreign files are errors"
# The SIGINT log ends on an event boundary; every event is longer than 10 bytes.
cp "$LOG" "$WORK/cut.lcmlog"
truncate -s -10 "$WORK/cut.lcmlog"
"$LOGGER" export "$WORK/cut.lcmlog" --out "$WORK/cut" >/dev/null 2>"$WORK/cut.err" || fail "truncated log not exported"
grep -q "truncated" "$WORK/cut.err" || fail "no truncation warning: $(cat "$WORK/cut.err")"
grep "warning" "$WORK/cut.err"
"$LOGGER" export "$WORK/missing.lcmlog" --out "$WORK/x" 2>"$WORK/missing.err"
[ $? -eq 2 ] || fail "missing log: exit code not 2"
echo "not a log" >"$WORK/foreign.lcmlog"
"$LOGGER" export "$WORK/foreign.lcmlog" --out "$WORK/x" 2>"$WORK/foreign.err"
[ $? -eq 2 ] || fail "foreign file: exit code not 2"
cat "$WORK/missing.err" "$WORK/foreign.err"

echo "== 5. lcm-logplayer replays a recorded log; recording the replay (stopped by SIGTERM) gives every message again"
if command -v lcm-logplayer >/dev/null && [ -n "$LOG" ]; then
  "$LOGGER" --out "$WORK/replayed.lcmlog" >"$WORK/replay.out" 2>&1 &
  LOGGER_PID=$!
  wait_ready "$WORK/replay.out"
  lcm-logplayer --speed 4 "$LOG" || fail "lcm-logplayer could not play $LOG"
  sleep 0.5
  kill -TERM $LOGGER_PID
  wait $LOGGER_PID || fail "logger did not end cleanly on SIGTERM"
  "$PEER" check "$WORK/replayed.lcmlog" --published "$WORK/sigint.published" || fail "replayed log incomplete"
elif [ -n "$LOG" ]; then
  MISSING_LOGPLAYER=1
fi

[ $FAILED -eq 0 ] && echo "PASS" || echo "FAILED"
[ $FAILED -eq 0 ] || exit 1
# Everything else passed; step 5 did not run: skipped (or, with CI=true, failed), not passed.
# shellcheck source=../../support/prerequisite.sh
[ -z "${MISSING_LOGPLAYER:-}" ] || . "$(dirname "${BASH_SOURCE[0]}")/../../support/prerequisite.sh"
[ -z "${MISSING_LOGPLAYER:-}" ] || missing_prerequisite "lcm-logplayer (step 5)" "Debian liblcm-bin, or ./sdlqr setup"
exit 0
