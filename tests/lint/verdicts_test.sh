#!/usr/bin/env bash
# verdicts.sh passes on the repository and fails, naming the rule, on a script holding each banned
# pattern: `|| true` after a flight, `-ne 0` as a negative's verdict, a bare sleep before a fault.
#   verdicts_test.sh SOURCE_DIR WORK_DIR
set -u
root="$1" work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../support/checker_test.sh" bash "$here/verdicts.sh"
check() {  # RULE SCRIPT_TEXT: verdicts.sh on a tests/ folder holding only that script
  rm -rf "$work" && mkdir -p "$work/tests"
  printf '#!/usr/bin/env bash\n%s\n' "$2" >"$work/tests/sample.sh"
  expect_caught "$1" "^tests/sample.sh:[0-9]*: $1: " "$work"
}
expect_repository_passes "the repository's scripts hold a banned pattern" "$root"
check or-true '"$root/scripts/launch" --build "$build" --log "$log" "$scenario" || true'
check or-true 'cmd_run hover_jumps "${run_args[@]}" || true'
check or-true '"$build/bin/sdlqr-analyze" "$log" --scenario "$scenario" >/dev/null || true'
check ne-zero 'if [ "$hover_status" -ne 0 ]; then echo "ok (negative) the check fails"; fi'
check ne-zero '[ "$status" != 0 ] && echo ok'
check bare-sleep 'sleep 7  # airborne
"$build/bin/sdlqr-fuzz-publisher" --duration 10'
check bare-sleep 'sleep "$kill_after"
kill -KILL "$pid"'
check bare-sleep 'sleep 6
kill -TERM "$launcher"'
# A poll is no timing: sleep, then look again.
rm -rf "$work" && mkdir -p "$work/tests"
printf '#!/usr/bin/env bash\nuntil grep -q up out; do\n  sleep 0.1\ndone\nkill -9 "$pid"\n' >"$work/tests/poll.sh"
if bash "$here/verdicts.sh" "$work" >/dev/null; then echo "ok   a poll loop before a kill is no finding"; else echo "FAIL a poll loop was flagged"; failed=1; fi
[ "$failed" -eq 0 ] && echo PASS
exit "$failed"
