#!/usr/bin/env bash
# Keeps three ways of passing by default out of the scripts that fly and judge (docs/verdicts.md):
#   or-true      `|| true` on a line that flies or judges a flight (the launcher, deploy, a loss or
#                soak flight, sdlqr-analyze and the other checkers): a crashed flight would pass;
#   ne-zero      `-ne 0` / `!= 0` as a verdict in a test script: a negative must require its exit
#                code (1) and the failing check's name, a positive exit 0 (`-eq 0`); "any non-zero"
#                also passes a crash, a missing file or a bad argument;
#   bare-sleep   a `sleep` of wall seconds within 8 lines before an injected fault (kill -9, a SIGTERM to the
#                launcher, the fuzz publisher, a link taken down, packet loss, the rogue publisher):
#                faults land on the flight's simulation clock (tests/support/sim_time.sh).
#   verdicts.sh ROOT     every shell script under tests/ (but tests/lint/, which holds the samples),
#                        scripts/, bench/, tools/ and ./sdlqr
# Prints file:line: rule: text for each finding; exit 1 when there is one.
set -u
root="$1"
flight='(scripts/(launch|deploy|isolated|loss_flight|soak)|cmd_run|bench_starved|fly_and_check|analyze_flight|functional_verdict|sdlqr-(analyze|faultcheck|linkcheck|soakcheck|replay|batch|compare))'
fault='(kill -(9|KILL|STOP)([^A-Za-z0-9]|$)|kill -TERM "?[$][{]?(launcher|deploy_pid)([^A-Za-z0-9_]|$)|sdlqr-fuzz-publisher|bridge link set|scripts/packet_loss [0-9]|[$]rogue([^A-Za-z0-9_]|$)|rogue_rate_cmd )'

shell_scripts() {
  {
    [ -f "$root/sdlqr" ] && echo "$root/sdlqr"
    find "$root/tests" "$root/scripts" "$root/bench" "$root/tools" -type f 2>/dev/null
  } | while read -r f; do
    case "$f" in "$root"/tests/lint/*) continue ;; *.sh | *.bash) echo "$f"; continue ;; *.*) continue ;; esac
    head -1 "$f" | grep -qE '^#!.*\b(ba)?sh\b' && echo "$f"
  done
}

findings=0
while read -r file; do
  out="$(awk -v flight="$flight" -v fault="$fault" -v in_tests="$([[ "$file" == "$root/tests/"* ]] && echo 1 || echo 0)" '
    { line[NR] = $0 }
    END {
      for (i = 1; i <= NR; i++) {
        text = line[i]
        if (text ~ /^[ \t]*#/) continue
        if (text ~ /\|\| *true/ && text ~ flight) print i ": or-true: " text
        if (in_tests && (text ~ /-ne 0([^0-9]|$)/ || text ~ /!= *"?0"? *\]/)) print i ": ne-zero: " text
        if (text ~ /^[ \t]*sleep[ \t]+[0-9"$]/) {
          next_line = ""
          for (j = i + 1; j <= NR && next_line == ""; j++) if (line[j] !~ /^[ \t]*(#|$)/) next_line = line[j]
          if (next_line ~ /^[ \t]*done([^A-Za-z0-9_]|$)/) continue  # a poll: sleep, look again
          for (j = i + 1; j <= i + 8 && j <= NR; j++) {
            if (line[j] ~ /^[ \t]*#/) continue
            if (line[j] ~ fault) { print i ": bare-sleep: " text " (then line " j ": " line[j] ")"; break }
          }
        }
      }
    }' "$file")"
  if [ -n "$out" ]; then
    sed "s|^|${file#"$root"/}:|" <<<"$out"
    findings=1
  fi
done < <(shell_scripts)
exit "$findings"
