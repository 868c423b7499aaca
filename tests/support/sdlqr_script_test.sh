#!/usr/bin/env bash
# ./sdlqr's slowest-tests table survives a whole suite's transcript under `set -euo pipefail`
# (a `sort | head` there died of SIGPIPE on CI, exit 141, after the tests had passed) and
# lists the COUNT slowest, slowest first.
#   sdlqr_script_test.sh SOURCE_DIR
set -euo pipefail
source "$1/sdlqr"
CTEST_TRANSCRIPT=$(mktemp)
trap 'rm -f "$CTEST_TRANSCRIPT"' EXIT
for i in $(seq 1 20000); do
  echo "build: $i/20000 Test #$i: t$i ....   Passed    $((i % 997)).25 sec"
done > "$CTEST_TRANSCRIPT"
table=$(print_slowest_tests 12 2>&1 | tail -n +2)
[ "$(wc -l <<<"$table")" = 12 ] || { echo "FAIL: expected 12 rows, got:"; echo "$table"; exit 1; }
first=$(head -n 1 <<<"$table" | awk '{print $1}')
[ "$first" = 996.2 ] || [ "$first" = 996.3 ] || { echo "FAIL: slowest row is $first s, expected 996.25"; exit 1; }
echo PASS
