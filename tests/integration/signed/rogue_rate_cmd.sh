#!/usr/bin/env bash
# A signed bus keeps out a process without the key (docs/hosts-and-signing.md, Signed bus): the real executables fly
# signed_hover over real multicast with --signed while rogue_rate_cmd, started without
# SDLQR_BUS_KEY, publishes well-formed, in-range, newer RATE_CMD (thrust 0) for 1.5 s mid-hover.
# The bodyrate loop must reject them (reject.rate_cmd.unsigned counted in its HEARTBEAT) and the
# hover must hold (sdlqr-faultcheck --hover). Negative: the same injection on an unsigned bus is
# taken (no such rejection, the hover breaks), so the check can fail. Also: the launcher's key
# file is mode 0600 and its key appears in no output; and the signed log (every message with its
# trailer, as on the wire) is read by sdlqr-replay (every output of the cores recomputed bit for
# bit; the only recorded-only messages are the rogue's), by LCM's Java decoder (as lcm-spy:
# tests/java/DecodeCheck.java) and played by lcm-logplayer to a recorder that exports every channel.
#   rogue_rate_cmd.sh BUILD_DIR WORK_DIR ROGUE
set -uo pipefail
build="$1" work="$2" rogue="$3"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$here/../../.."
rm -rf "$work"
mkdir -p "$work/signed" "$work/unsigned"
unset SDLQR_BUS_KEY
hover=(--hover 5,10,0,0,1 --max-hover-error 0.1 --also-may-stop rogue-rate-cmd)

fly() {  # CASE launch options...: the flight with the rogue; sets launch_status, rogue_status
  local case="$1"
  shift
  "$root/scripts/launch" --build "$build" --log "$work/$case/flight.lcmlog" "$@" "$here/signed_hover.yaml" \
    >"$work/$case/launch.out" 2>&1 &
  local launcher=$!
  "$rogue" --at 6 --for 1.5 >"$work/$case/rogue.out" 2>&1
  rogue_status=$?
  wait "$launcher"
  launch_status=$?
  cat "$work/$case/rogue.out"
  grep -E '^launch:.*(signed|ended|crash|killed)' "$work/$case/launch.out"
}

ok=0
fly signed --signed
key="$work/signed/bus-default.key"
if [ "$(stat -c %a "$key" 2>/dev/null)" = 600 ]; then
  echo "ok   the launcher's key file $key is mode 0600"
else
  echo "FAIL no key file of mode 0600 at $key"; ok=1
fi
if [ -s "$key" ] && grep -rqF "$(cat "$key")" "$work/signed"/*.out; then
  echo "FAIL the key appears in the output"; ok=1
fi
"$build/bin/sdlqr-faultcheck" "$work/signed/flight.lcmlog" --require reject.rate_cmd.unsigned "${hover[@]}" \
  >"$work/signed/check.out"
check_status=$?
grep -E 'rate_cmd|hover error|^(ok|FAIL)' "$work/signed/check.out"
if [ "$launch_status" -eq 0 ] && [ "$rogue_status" -eq 0 ] && [ "$check_status" -eq 0 ]; then
  echo "ok   signed: the rogue's RATE_CMD were rejected as unsigned and the hover held"
else
  echo "FAIL signed: launcher $launch_status, rogue $rogue_status, check $check_status"; ok=1
fi

# The signed log, read without the key.
log="$work/signed/flight.lcmlog"
sent="$(sed -n 's/^rogue: sent \([0-9]*\) .*/\1/p' "$work/signed/rogue.out")"
"$build/bin/sdlqr-replay" "$log" --config "$root/config/quad255.yaml" --out "$work/signed/replay.lcmlog" \
  >"$work/signed/replay.out" 2>&1
# Each channel row: NAME recorded replayed compared identical max|diff| result...
if awk 'NF >= 6 && $1 ~ /^(STATE_EST|RATE_CMD|REFERENCE|GAINS)$/ && $2 ~ /^[0-9]+$/ { rows++; if ($4 == 0 || $4 != $5) bad++ }
        END { exit !(rows == 4 && bad == 0) }' "$work/signed/replay.out" &&
   grep -q "^  RATE_CMD: $sent recorded only, 0 recomputed only" "$work/signed/replay.out"; then
  echo "ok   sdlqr-replay of the signed log: every recomputed output identical, recorded only: the rogue's $sent RATE_CMD"
else
  echo "FAIL sdlqr-replay of the signed log:"; grep -E '^(channel|STATE_EST|RATE_CMD|REFERENCE|GAINS|  RATE_CMD)' "$work/signed/replay.out"; ok=1
fi
if command -v javac >/dev/null && [ -f "$build/lcmtypes_sdlqr.jar" ]; then
  mkdir -p "$work/java"
  if javac -nowarn -cp "/usr/share/java/lcm.jar:$build/lcmtypes_sdlqr.jar" -d "$work/java" "$root/tests/java/DecodeCheck.java" &&
     java -cp "/usr/share/java/lcm.jar:$build/lcmtypes_sdlqr.jar:$work/java" DecodeCheck "$build/lcmtypes_sdlqr.jar" "$log" \
       >"$work/java/decode.out" 2>&1; then
    echo "ok   LCM's Java decoder (lcm-spy's) decodes every channel of the signed log: $(tail -1 "$work/java/decode.out")"
  else
    echo "FAIL LCM's Java decoder on the signed log:"; cat "$work/java/decode.out"; ok=1
  fi
elif [ "${CI:-}" = true ]; then
  echo "FAIL no javac or lcmtypes_sdlqr.jar (CI=true: no silent skip)"; ok=1
else
  echo "skip LCM's Java decoder: no javac or lcmtypes_sdlqr.jar"
fi
"$build/bin/sdlqr-logger" record --out "$work/signed/played.lcmlog" --bus-layout single >/dev/null 2>&1 &
recorder=$!
sleep 0.5
lcm-logplayer --speed 10 "$log" >/dev/null 2>&1
sleep 0.3
kill -TERM "$recorder"
wait "$recorder"
"$build/bin/sdlqr-logger" export "$work/signed/played.lcmlog" --out "$work/signed/played-csv" >/dev/null 2>&1
missing=""
for channel in IMU STATE_EST RATE_CMD GAINS REFERENCE MOTOR_CMD SIM_TRUTH HEARTBEAT; do
  [ -s "$work/signed/played-csv/$channel.csv" ] || missing="$missing $channel"
done
if [ -z "$missing" ]; then
  echo "ok   lcm-logplayer plays the signed log; an unsigned recorder's export has every channel"
else
  echo "FAIL lcm-logplayer of the signed log: the recorder's export lacks$missing"; ok=1
fi

fly unsigned --unsigned
# The negative judges a flight that happened: its log is there and the rogue sent its commands;
# then each check must fail for its own reason (exit 1 and the line naming it), not for any reason.
"$build/bin/sdlqr-faultcheck" "$work/unsigned/flight.lcmlog" "${hover[@]}" >"$work/unsigned/hover.out"
hover_status=$?
"$build/bin/sdlqr-faultcheck" "$work/unsigned/flight.lcmlog" --require reject.rate_cmd.unsigned \
  --also-may-stop rogue-rate-cmd >"$work/unsigned/require.out"
require_status=$?
grep -E 'hover error' "$work/unsigned/hover.out"
if [ "$rogue_status" -eq 0 ] && [ -s "$work/unsigned/flight.lcmlog" ] && [ "$hover_status" -eq 1 ] && grep -q '^FAIL hover error over' "$work/unsigned/hover.out" &&
   [ "$require_status" -eq 1 ] && grep -q '^FAIL reject.rate_cmd.unsigned = 0 ' "$work/unsigned/require.out"; then
  echo "ok   (negative) unsigned: the same RATE_CMD were taken: FAIL hover error, FAIL reject.rate_cmd.unsigned = 0"
else
  echo "FAIL (negative) unsigned: rogue $rogue_status, hover check $hover_status, rejection check $require_status" \
       "(expected 0, 1 naming 'hover error', 1 naming 'reject.rate_cmd.unsigned = 0'; log: $work/unsigned/flight.lcmlog)"
  grep -E '^FAIL' "$work/unsigned/hover.out" "$work/unsigned/require.out"
  ok=1
fi
exit "$ok"
