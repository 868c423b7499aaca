#!/usr/bin/env bash
# sdlqr-top's reports during the fixture flight: at least one report lists each of the six
# flight processes (sim, estimator, gains, controller, lowlevel, mission) as alive, with the
# channels of the flight at their rates.
#   check_top.sh TOP_OUTPUT
set -u
out="$1"
processes="sdlqr-sim sdlqr-estimator sdlqr-gains sdlqr-controller sdlqr-lowlevel sdlqr-mission"
# Reports start with a "sdlqr-top  t=N s" line; print the first one with all six alive while
# RATE_CMD flows at >= 90 Hz (airborne).
report=$(awk -v want="$processes" '
  function check() {
    n = split(want, names, " "); ok = 1
    for (i = 1; i <= n; i++) if (!(names[i] in alive)) ok = 0
    if (ok && flying && block != "") { print block; found = 1; exit }
  }
  /^sdlqr-top  t=/ { check(); block = ""; flying = 0; split("", alive) }
  { block = block $0 "\n" }
  $2 == "alive" { alive[$1] = 1 }
  $1 == "RATE_CMD" && $2 >= 90 { flying = 1 }
  END { if (!found) check() }
' "$out")
if [ -z "$report" ]; then
  echo "FAIL: no report of sdlqr-top shows all six processes alive; last report:"
  awk '/^sdlqr-top  t=/ { block = "" } { block = block $0 "\n" } END { printf "%s", block }' "$out"
  exit 1
fi
printf '%s\n' "$report"
for channel in IMU STATE_EST RATE_CMD GAINS HEARTBEAT; do
  grep -Eq "^$channel +[0-9]" <<<"$report" || { echo "FAIL: channel $channel missing"; exit 1; }
done
echo "PASS: all six flight processes alive"
