#!/usr/bin/env bash
# Help everywhere: `./sdlqr help`, `./sdlqr COMMAND --help` for every command main() dispatches
# (and every `bench` subcommand the usage lists), and `--help` on every executable in BIN_DIR
# (a test's own programs aside: tests/**/add_executable, *_tests). Each must exit 0, print a usage,
# start nothing, write nothing and answer in under 2 s.
#   help.sh SCRIPT BIN_DIR WORK_DIR     prints "ok ..." or "FAIL <what>: <reason>" per check;
#                                      exit 1 when one failed
# HELP_ONLY=<regex> runs only the checks whose name matches it (help_test.sh's negatives: each
# checks one or two names, not every command and executable again).
# Reasons: "exit N", "no usage printed", "started PROGRAM" (a shim on PATH for the programs a
# command runs to set up, build, test or fly), "wrote FILES" (beside the script, in the build
# folders or the working folder), "took S s".
set -uo pipefail

script="$(realpath "$1")" bin_dir="$(realpath "$2")" work="$3"
rm -rf "$work" && mkdir -p "$work/shims" "$work/started"
failures=0
run="$work/run"   # the folder of one check: root/ (the script alone), cwd/, the build folders

# Each shim records that it was started and fails, so nothing it stands for runs.
for program in cmake ctest ninja make npm apt-get dpkg-query sudo java stress-ng nft ip unshare chrt parallel node; do
  printf '#!/bin/sh\ntouch "%s/started/%s"\nexit 3\n' "$work" "$program" >"$work/shims/$program"
  chmod +x "$work/shims/$program"
done

# check NAME COMMAND...: run it in an empty folder beside a copy of the script alone.
check() {
  local name="$1" status=0 start end seconds files started
  shift
  [ -z "${HELP_ONLY:-}" ] || grep -qE -- "$HELP_ONLY" <<<"$name" || return 0
  rm -rf "$run" "$work/started"/* && mkdir -p "$run/root" "$run/cwd"
  install -m 755 "$script" "$run/root/sdlqr"
  start=$(date +%s.%N)
  (cd "$run/cwd" && PATH="$work/shims:$PATH" SDLQR_BUILD_DIR="$run/build" SDLQR_ASAN_BUILD_DIR="$run/build-asan" \
    timeout 10 "$@" >"$work/out" 2>"$work/err" </dev/null) || status=$?
  end=$(date +%s.%N)
  seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }')
  started=$(ls "$work/started")
  files=$(cd "$run" && find . -mindepth 1 ! -path ./root ! -path ./root/sdlqr ! -path ./cwd | sort | tr '\n' ' ')
  local reason=""
  if [ -n "$started" ]; then reason="started $(echo "$started" | tr '\n' ' ')"
  elif [ -n "$files" ]; then reason="wrote $files"
  elif [ "$status" != 0 ]; then reason="exit $status ($(head -c 200 "$work/err" | head -1))"
  elif ! grep -qiE 'usage|\[--' "$work/out"; then reason="no usage printed"
  elif awk -v s="$seconds" 'BEGIN { exit !(s >= 2) }'; then reason="took $seconds s"
  fi
  if [ -n "$reason" ]; then
    echo "FAIL $name: $reason"
    failures=$((failures + 1))
  else
    echo "ok   $name ($seconds s)"
  fi
}

# The commands main() dispatches: its case arms, but help itself and the catch-all.
commands=$(awk '/^main\(\) \{/ { on = 1 } on && /^    [a-z][a-z|-]*\)/ { sub(/\).*/, ""); gsub(/^ +/, ""); print }
                on && /^}/ { exit }' "$script" | tr '|' '\n' | grep -vxE 'help|-h|--help')
[ -n "$commands" ] || { echo "FAIL $script: no command found in main()"; exit 1; }
bench_subcommands=$(bash "$script" help 2>/dev/null | sed -n 's/^  bench \([a-z][a-z]*\).*/\1/p')

check "./sdlqr help" "$run/root/sdlqr" help
for command in $commands; do
  check "./sdlqr $command --help" "$run/root/sdlqr" "$command" --help
done
for sub in $bench_subcommands; do
  check "./sdlqr bench $sub --help" "$run/root/sdlqr" bench "$sub" --help
done

# A test's own programs are not the product's: peers, checkers and the gtest binaries.
test_programs=$(grep -rhoP '(add_executable|sdlqr_test_program)\(\K[A-Za-z0-9_-]+' "$(dirname "$script")/tests" 2>/dev/null | sort -u)
executables=0
for exe in "$bin_dir"/*; do
  [ -f "$exe" ] && [ -x "$exe" ] || continue
  name=$(basename "$exe")
  [[ "$name" == *_tests ]] && continue
  grep -qx -- "$name" <<<"$test_programs" && continue
  check "$name --help" "$exe" --help
  executables=$((executables + 1))
done
[ "$executables" -gt 0 ] || { echo "FAIL $bin_dir: no executable found"; exit 1; }

echo "$failures failed"
[ "$failures" = 0 ]
