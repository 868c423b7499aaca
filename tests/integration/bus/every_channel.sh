#!/usr/bin/env bash
# Every tool hears every channel of a split bus (real udpm multicast; run in a private network
# namespace). The publisher is logger_test_peer (IMU, STATE_EST, RATE_CMD on ports of their own,
# GAINS on the base port), then a 2 s simulator run (IMU, VIO_POSE, SIM_TRUTH, SIM_CLOCK, HEARTBEAT).
#   1. sdlqr-logger record (split, the default) has every published message;
#   2. sdlqr-bridge merge puts every channel on the monitor URL, where lcm-spy listens: a
#      recorder there with --bus-layout single has every published message;
#   3. sdlqr-top (split) reports a rate on every channel;
#   4. negative: a recorder and a top on the base port alone (--bus-layout single) miss the
#      channels of the other ports, and the same checks fail on them;
#   5. a log replayed by lcm-logplayer (everything on the base URL) is seen whole by sdlqr-top,
#      and drives the scenario player on its clock through `sdlqr-bridge split`, or with
#      --bus-layout single; without either the player hears no clock (negative).
#   every_channel.sh BUILD_DIR WORK_DIR CLOCK_SCENARIO PEER
set -u
build="$1" work="$2" scenario="$3" peer="$4"
bin="$build/bin"
rm -rf "$work" && mkdir -p "$work"
failed=0
fail() { echo "FAIL: $*"; failed=1; }
pids=()
stop() { for p in "$@"; do kill -TERM "$p" 2>/dev/null; done; for p in "$@"; do wait "$p" 2>/dev/null; done; }

# Each report of sdlqr-top starts with "sdlqr-top  t=N s"; a channel line is "NAME RATE ...".
top_saw() {  # top_output channel... -> 0 when one report shows every channel at a rate > 0
  local out="$1"
  shift
  awk -v want="$*" '
    function check() { n = split(want, names, " "); ok = 1
      for (i = 1; i <= n; i++) if (!(names[i] in seen)) ok = 0
      if (ok) { found = 1; exit } }
    /^sdlqr-top  t=/ { check(); split("", seen) }
    $2 ~ /^[0-9.]+$/ && $2 > 0 { seen[$1] = 1 }
    END { if (!found) check(); exit found ? 0 : 1 }' "$out"
}

monitor="$("$bin/sdlqr-bridge" merge --print-url)" || { echo "FAIL: sdlqr-bridge --print-url"; exit 1; }
echo "== 1-4. peer on the split bus; monitor URL $monitor"
"$bin/sdlqr-logger" record --out "$work/split.lcmlog" >"$work/rec-split.out" 2>&1 & rec_split=$!
"$bin/sdlqr-logger" record --out "$work/single.lcmlog" --bus-layout single >"$work/rec-single.out" 2>&1 & rec_single=$!
"$bin/sdlqr-bridge" merge >"$work/bridge.out" 2>&1 & bridge=$!
"$bin/sdlqr-logger" record --out "$work/monitor.lcmlog" --lcm-url "$monitor" --bus-layout single \
  >"$work/rec-monitor.out" 2>&1 & rec_monitor=$!
"$bin/sdlqr-top" --plain --duration 5 >"$work/top-split.out" 2>&1 & top_split=$!
"$bin/sdlqr-top" --plain --duration 5 --bus-layout single >"$work/top-single.out" 2>&1 & top_single=$!
sleep 1.5
"$peer" publish --count 1000 --rate 500 --published "$work/published.txt" || fail "publisher"
sleep 0.5
stop "$rec_split" "$rec_single" "$bridge" "$rec_monitor"
wait "$top_split" "$top_single"

echo "-- recorder, split layout"
"$peer" check "$work/split.lcmlog" --published "$work/published.txt" || fail "the split recorder missed messages"
echo "-- recorder on the monitor URL behind sdlqr-bridge merge (what lcm-spy hears)"
"$peer" check "$work/monitor.lcmlog" --published "$work/published.txt" || fail "the monitor URL missed messages"
echo "-- negative: a recorder on the base port alone"
"$peer" check "$work/single.lcmlog" --published "$work/published.txt" >"$work/check-single.out" 2>&1
single=$?
# exit 1 and a channel of another port with fewer messages present than required
if [ "$single" -eq 1 ] && awk -F'[ :/]+' '/required present/ { if ($3 < $4) short = 1 } END { exit !short }' "$work/check-single.out"; then
  grep -E "required present" "$work/check-single.out"
  echo "as expected, it misses the channels of the other ports (exit 1)"
else
  fail "a recorder on the base port alone: exit $single, expected 1 with channels short of their messages"
fi
top_saw "$work/top-split.out" IMU STATE_EST RATE_CMD GAINS || fail "sdlqr-top (split) did not report every channel"
if top_saw "$work/top-single.out" IMU STATE_EST RATE_CMD GAINS; then
  fail "sdlqr-top on the base port alone reported every channel"
else
  echo "as expected, sdlqr-top on the base port alone misses IMU, STATE_EST and RATE_CMD"
fi

echo "== 5. a 2 s simulator run, recorded, then replayed by lcm-logplayer on the base URL"
"$bin/sdlqr-logger" record --out "$work/sim.lcmlog" >"$work/rec-sim.out" 2>&1 & rec_sim=$!
sleep 1
"$bin/sdlqr-sim" --duration 2 >"$work/sim.out" 2>&1 || fail "sdlqr-sim --duration 2"
sleep 0.3
stop "$rec_sim"
sim_channels="IMU VIO_POSE SIM_TRUTH SIM_CLOCK HEARTBEAT"
"$bin/sdlqr-logger" export "$work/sim.lcmlog" --out "$work/sim-csv" >/dev/null 2>&1 || fail "export of the sim log"
for channel in $sim_channels; do
  [ -s "$work/sim-csv/$channel.csv" ] || fail "the split recorder has no $channel from the simulator"
done

play() { lcm-logplayer "$work/sim.lcmlog" >/dev/null 2>&1; }
# (a) sdlqr-top hears the replay whole
"$bin/sdlqr-top" --plain --duration 3 >"$work/top-replay.out" 2>&1 & top_replay=$!
sleep 0.5
play
wait "$top_replay"
top_saw "$work/top-replay.out" $sim_channels || fail "sdlqr-top missed channels of the lcm-logplayer replay"
# (b) the player on a split bus hears its clock only through the split bridge
run_mission() {  # label extra-args... -> mission exit code, its stderr in $work/mission-LABEL.err
  local label="$1"
  shift
  "$bin/sdlqr-mission" "$scenario" --no-clock-timeout 10 "$@" >/dev/null 2>"$work/mission-$label.err" & local m=$!
  # The replay starts once the player listens (its first HEARTBEAT), not after a guessed delay: on
  # a busy machine a process took seconds to start and the whole 2 s replay went by unheard.
  "$bin/sdlqr-top" --wait-for sdlqr-mission --timeout 20 "$@" >/dev/null 2>&1 || echo "sdlqr-mission not heard within 20 s"
  play
  wait "$m"
}
run_mission split-no-bridge
[ $? -eq 1 ] && grep -q "no SIM_CLOCK" "$work/mission-split-no-bridge.err" \
  && echo "as expected, without the bridge the player on a split bus hears no clock" \
  || { fail "the player heard a clock on a split bus without the bridge"; cat "$work/mission-split-no-bridge.err"; }
"$bin/sdlqr-bridge" split >"$work/bridge-split.out" 2>&1 & bridge=$!
sleep 0.5
run_mission split-bridge || fail "the player did not complete on the replay through sdlqr-bridge split"
stop "$bridge"
grep -q "scenario complete" "$work/mission-split-bridge.err" && grep -q "command arm" "$work/mission-split-bridge.err" \
  || fail "the player behind the split bridge did not play its event"
run_mission single --bus-layout single || fail "the player with --bus-layout single did not complete on the replay"
grep -q "scenario complete" "$work/mission-single.err" || fail "the player with --bus-layout single did not complete"

[ "$failed" = 0 ] && echo "PASS: every tool saw every channel" || exit 1
