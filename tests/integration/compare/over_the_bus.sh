#!/usr/bin/env bash
# ./sdlqr compare --bus on the compare tests' benchmark (its short hover, two laws): each law flies
# over a private bus and bus.md sets its checks beside the in-process flight's. Checked: a row per
# law with every check passed both ways, and each log's RATE_CMD computed by that law (RATE_CMD.law,
# params_t LAW_*: sdlqr 0, geometric 2); negative: the law check on the other law's log fails.
#   over_the_bus.sh BUILD_DIR WORK_DIR
set -uo pipefail
build="$1" work="$2"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
SDLQR_BUILD_DIR="$build" "$root/sdlqr" compare "$root/tests/unit/tools/compare/small_benchmark.yaml" \
  --scenarios short_hover --out "$work" --no-plots --bus >"$work.out" 2>&1
status=$?
cat "$work/bus.md" 2>/dev/null
ok=0
[ "$status" -eq 0 ] || { echo "FAIL ./sdlqr compare --bus exits $status:"; tail -5 "$work.out"; ok=1; }
for law in sdlqr geometric; do
  if grep -qE "^\| \`$law\` \| short_hover \| ([0-9]+)/\1 \| ([0-9]+)/\2 \| — \|$" "$work/bus.md" 2>/dev/null; then
    echo "ok   $law: every check over the bus and in-process"
  else
    echo "FAIL $law: no row with every check passed both ways"; ok=1
  fi
done
laws_of() {  # LOG: the distinct RATE_CMD.law values
  rm -rf "$work/csv" && "$build/bin/sdlqr-logger" export "$1" --out "$work/csv" >/dev/null 2>&1 &&
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i ~ /^law /) c = i; next } { print $c }' "$work/csv/RATE_CMD.csv" |
    sort -u | paste -sd ' ' -
}
for pair in sdlqr:0 geometric:2; do
  law="${pair%:*}" code="${pair#*:}"
  seen="$(laws_of "$work/bus/$law/short_hover/flight.lcmlog")"
  if [ "$seen" = "$code" ]; then echo "ok   $law's log: every RATE_CMD by law $code"; else echo "FAIL $law's log: RATE_CMD laws '$seen', expected $code"; ok=1; fi
done
seen="$(laws_of "$work/bus/sdlqr/short_hover/flight.lcmlog")"
if [ "$seen" != 2 ]; then
  echo "ok   (negative) the sdlqr flight's log is not geometric's (laws '$seen')"
else
  echo "FAIL (negative) the sdlqr flight flew geometric"; ok=1
fi
exit "$ok"
