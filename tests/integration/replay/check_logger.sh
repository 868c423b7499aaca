#!/usr/bin/env bash
# The logger on the fixture's flight:
#   export  every channel's CSV has one row per message of the log and every row re-encodes to
#           the recorded bytes (decode -> CSV -> parse, exactly);
#   kill9   the recording killed with kill -9 mid-flight holds every message received more than
#           1 s before the kill (but what that recorder itself lost on the bus, by its heartbeats);
#           the same recording cut to its first half fails the check, and with its HEARTBEATs
#           (one channel, many senders) reordered passes it.
#   check_logger.sh export|kill9 SDLQR_LOGGER EXPORT_ROUNDTRIP_CHECK FLIGHT_DIR
set -u
mode="$1" logger="$2" check="$3" dir="$4"
case "$mode" in
  export)
    rm -rf "$dir/csv"
    "$logger" export "$dir/flight.lcmlog" --out "$dir/csv" >/dev/null 2>"$dir/export.err" || {
      echo "FAIL: export: $(cat "$dir/export.err")"; exit 1; }
    "$check" "$dir/flight.lcmlog" "$dir/csv" ;;
  kill9)
    killed=$(cat "$dir/killed.utime")
    size=$(stat -c %s "$dir/killed.lcmlog")
    echo "killed at $killed; log holds $size bytes"
    "$check" --prefix-of "$dir/flight.lcmlog" "$dir/killed.lcmlog" --before $((killed - 1000000)) \
      --killed-pid "$(cat "$dir/killed.pid")" || exit 1
    head -c $((size / 2)) "$dir/killed.lcmlog" >"$dir/killed_half.lcmlog"
    "$check" --prefix-of "$dir/flight.lcmlog" "$dir/killed_half.lcmlog" --before $((killed - 1000000)) \
      --killed-pid "$(cat "$dir/killed.pid")" >"$dir/killed_half.out"
    half=$?
    if [ "$half" -eq 1 ] && grep -q '^FAIL missing ' "$dir/killed_half.out"; then
      echo "ok: the recording cut to half its bytes fails (exit 1, FAIL missing ...): $(grep figures "$dir/killed_half.out")"
    else
      echo "FAIL: the recording cut to half its bytes exits $half, expected 1 naming the missing events"; exit 1
    fi
    rm -f "$dir/killed_reordered.lcmlog"
    "$check" --reorder-heartbeats "$dir/killed.lcmlog" "$dir/killed_reordered.lcmlog" || exit 1
    "$check" --prefix-of "$dir/flight.lcmlog" "$dir/killed_reordered.lcmlog" --before $((killed - 1000000)) \
      --killed-pid "$(cat "$dir/killed.pid")" >"$dir/killed_reordered.out" || {
      echo "FAIL: the recording with its HEARTBEATs reordered fails the check"; cat "$dir/killed_reordered.out"; exit 1; }
    echo "ok: the recording with its HEARTBEATs reordered passes: $(grep figures "$dir/killed_reordered.out")" ;;
  *) echo "unknown mode $mode"; exit 2 ;;
esac
