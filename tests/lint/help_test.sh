#!/usr/bin/env bash
# help.sh passes on the repository's ./sdlqr and built executables, and fails, for the reason it
# names, on a command whose --help starts work, an executable whose --help writes a file, prints no
# usage, or is slow.
#   help_test.sh SOURCE_DIR BIN_DIR WORK_DIR
set -u
root="$1" bin_dir="$2" work="$3"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
failed=0
if out="$(bash "$here/help.sh" "$root/sdlqr" "$bin_dir" "$work/repository")"; then
  echo "ok   the repository: $(grep -c '^ok' <<<"$out") commands and executables answer --help"
  echo "$out"
else
  echo "FAIL: a command or executable does not answer --help as it must:"
  echo "$out"
  failed=1
fi

# negatives SCRIPT BIN_DIR ONLY NAME=EXPECTED_LINE_REGEX...: help.sh, running the checks whose name
# matches ONLY, must exit 1 with each FAIL line.
negatives() {
  local script="$1" bin="$2" only="$3" out status case
  shift 3
  out="$(HELP_ONLY="$only" bash "$here/help.sh" "$script" "$bin" "$work/negative")"
  status=$?
  for case in "$@"; do
    if [ "$status" -eq 1 ] && grep -qE "${case#*=}" <<<"$out"; then
      echo "ok   (negative) ${case%%=*} caught: $(grep -E "${case#*=}" <<<"$out" | head -1)"
    else
      echo "FAIL (negative) ${case%%=*} not caught (exit $status; expected a line /${case#*=}/):"
      echo "$out"
      failed=1
    fi
  done
}
fake="$work/fake"
rm -rf "$fake" && mkdir -p "$fake/good" "$fake/bad"
tool() {  # FOLDER NAME BODY: an executable of that name in that folder
  printf '#!/bin/sh\n%s\n' "$3" >"$fake/$1/$2"
  chmod +x "$fake/$1/$2"
}
tool good tool 'echo "usage: tool [options]"'
tool bad writes 'echo "usage: writes [options]" > started.txt'
tool bad silent 'exit 0'
tool bad slow 'sleep 2.5; echo "usage: slow [options]"'

# ./sdlqr as it was before help was answered in main(): bench --help starts the set-up and build,
# soak --help fails on an unknown option.
sed '/help_requested "\$cmd" "\$@" &&/d' "$root/sdlqr" >"$fake/sdlqr_without_help"
if cmp -s "$root/sdlqr" "$fake/sdlqr_without_help"; then
  echo "FAIL the negative's edit no longer matches ./sdlqr's help line in main()"
  failed=1
fi
negatives "$fake/sdlqr_without_help" "$fake/good" '^\./sdlqr (bench|soak) --help$' \
  "bench --help starts the benchmarks=^FAIL \./sdlqr bench --help: started " \
  "soak --help refused=^FAIL \./sdlqr soak --help: exit 2 "
negatives "$root/sdlqr" "$fake/bad" '^(writes|silent|slow) --help$' \
  "an executable's --help writes a file=^FAIL writes --help: wrote \./cwd/started\.txt" \
  "an executable's --help prints no usage=^FAIL silent --help: no usage printed" \
  "an executable's --help takes over 2 s=^FAIL slow --help: took [0-9.]+ s"
[ "$failed" -eq 0 ] && echo PASS
exit "$failed"
