#!/usr/bin/env bash
# Runs each libFuzzer harness of a sanitizer build compiled by clang
# (tools/robustness/fuzz/CMakeLists.txt) for a bounded time on its corpus (kept in
# BUILD_DIR/fuzz/corpus_*, so coverage accumulates over runs), the two side by side. Prints
# executions and coverage; fails on any finding (the crashing input is left in
# BUILD_DIR/fuzz/artifacts/). Without the harnesses (no clang or libFuzzer when the build was
# configured): skipped (exit 77), failed with CI=true (tests/support/prerequisite.sh).
#   tools/robustness/fuzz/run_fuzz.sh BUILD_DIR [SECONDS_PER_HARNESS (default 20)]
set -uo pipefail
build="${1:?usage: tools/robustness/fuzz/run_fuzz.sh BUILD_DIR [SECONDS]}"
seconds="${2:-20}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
# shellcheck source=../../../tests/support/prerequisite.sh
. "$root/tests/support/prerequisite.sh"
for harness in fuzz_messages fuzz_config fuzz_mavlink fuzz_seeds; do
  [ -x "$build/bin/$harness" ] ||
    missing_prerequisite "run_fuzz: $build/bin/$harness" \
      "the sanitizer build compiled by clang++ with libclang-rt-14-dev builds it: ./sdlqr setup, then ./sdlqr test"
done
out="$build/fuzz"
mkdir -p "$out/corpus_messages" "$out/corpus_config" "$out/corpus_mavlink" "$out/seeds_messages" "$out/seeds_mavlink" \
  "$out/artifacts"
"$build/bin/fuzz_seeds" "$out/seeds_messages" "$out/seeds_mavlink" || exit 1
cp "$root/config/quad255.yaml" "$out/corpus_config/seed_quad255.yaml"

run() {  # name corpus seeds...
  local name="$1"
  shift
  "$build/bin/$name" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$out/artifacts/$name-" \
    -rss_limit_mb=2048 "$@" >"$out/$name.log" 2>&1
  local result=$?
  local execs cov
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$name.log")
  cov=$(grep -E '^#[0-9]+.*(DONE|pulse|NEW|REDUCE|INITED)' "$out/$name.log" | tail -1 | sed -n 's/.* cov: \([0-9]*\) ft: \([0-9]*\) corp: \([^ ]*\).*/\1 edges, \2 features, corpus \3/p')
  echo "run_fuzz: $name: ${execs:-?} executions in ${seconds} s, coverage ${cov:-?}, exit $result"
  if [ "$result" -ne 0 ]; then
    grep -E 'ERROR|SUMMARY|runtime error|artifact' "$out/$name.log" | head -20
  fi
  return "$result"
}
run fuzz_messages "$out/corpus_messages" "$out/seeds_messages" &
messages=$!
run fuzz_config "$out/corpus_config"
status=$?
# The MAVLink parser and the PX4 bridge (docs/px4.md), after the config harness: half the time.
seconds=$(((seconds + 1) / 2))
run fuzz_mavlink "$out/corpus_mavlink" "$out/seeds_mavlink" || status=1
wait "$messages" || status=1
exit "$status"
