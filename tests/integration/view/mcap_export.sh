#!/usr/bin/env bash
# issue 24: `sdlqr-logger export LOG --mcap FILE`, read back by @mcap/core (mcap_check.mjs).
#   mcap_export.sh BUILD_DIR WORK_DIR LOG whole|torn
# whole: the log as recorded. torn: a copy cut 37 bytes into its last event (a recorder killed
# mid-write): the export writes every whole event and says how many bytes it dropped.
set -uo pipefail
build="$1" work="$2" log="$3" mode="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
source "$here/view_support.sh"
begin_view_test "$root" "$work" npm "$log"
input="$log"
if [ "$mode" = torn ]; then
  input="$work/torn.lcmlog"
  last=$(node --input-type=module -e "import { readLcmLog } from '$here/lib/lcmlog.mjs';
    const { events } = readLcmLog('$log'); console.log(events[events.length - 1].offset);")
  head -c $((last + 37)) "$log" > "$input"
fi
start=$(date +%s%3N)
"$build/bin/sdlqr-logger" export "$input" --mcap "$work/flight.mcap" > "$work/export.out" 2> "$work/export.err"
status=$?
echo "mcap_export: export exit code $status in $(($(date +%s%3N) - start)) ms; $(tail -1 "$work/export.out")"
[ "$status" -eq 0 ] || { cat "$work/export.err"; exit 1; }
if [ "$mode" = torn ]; then
  node "$here/mcap_check.mjs" "$input" "$work/flight.mcap" "$work/export.err"
else
  node "$here/mcap_check.mjs" "$input" "$work/flight.mcap"
fi
