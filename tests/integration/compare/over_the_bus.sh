#!/usr/bin/env bash
# ./sdlqr compare --bus on the compare tests' benchmark (its short hover, two laws): each law flies
# over a private bus and bus.md sets its checks beside the in-process flight's. Checked: a row per
# law with every check passed both ways, and each log's RATE_CMD computed by that law (RATE_CMD.law,
# params_t LAW_*: sdlqr 0, geometric 2); negative: the check of sdlqr's law on geometric's log fails
# (exit 1: another law in it). ./sdlqr compare --bus itself exits 1 when a flight fails a check
# (its negative: tests/support/sdlqr_script_test.sh).
#   over_the_bus.sh BUILD_DIR WORK_DIR
set -uo pipefail
build="$1" work="$2"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
SDLQR_BUILD_DIR="$build" "$root/sdlqr" compare "$root/tests/unit/tools/offline/compare/small_benchmark.yaml" \
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
# The law check: every RATE_CMD of LOG computed by law CODE (exit 0), another law in it (exit 1),
# no RATE_CMD to judge (exit 2).
law_check() {  # LOG CODE
  local seen
  rm -rf "$work/csv" && "$build/bin/sdlqr-logger" export "$1" --out "$work/csv" >/dev/null 2>&1 || return 2
  seen="$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i ~ /^law /) c = i; next } c { print $c }' \
            "$work/csv/RATE_CMD.csv" 2>/dev/null | sort -u | paste -sd ' ' -)"
  echo "RATE_CMD laws '$seen'"
  [ -n "$seen" ] || return 2
  [ "$seen" = "$2" ]
}
for pair in sdlqr:0 geometric:2; do
  law="${pair%:*}" code="${pair#*:}"
  out="$(law_check "$work/bus/$law/short_hover/flight.lcmlog" "$code")"
  if [ $? -eq 0 ]; then echo "ok   $law's log: every RATE_CMD by law $code"; else echo "FAIL $law's log: $out, expected $code"; ok=1; fi
done
# Negative: the sdlqr law's check on the other law's (geometric's) log.
out="$(law_check "$work/bus/geometric/short_hover/flight.lcmlog" 0)"
negative=$?
if [ "$negative" -eq 1 ]; then
  echo "ok   (negative) the check of law sdlqr (0) on geometric's log fails: $out"
else
  echo "FAIL (negative) the check of law sdlqr (0) on geometric's log exits $negative (expected 1): $out"; ok=1
fi
exit "$ok"
