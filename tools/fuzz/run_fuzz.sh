#!/usr/bin/env bash
# Builds the libFuzzer harnesses with clang (in BUILD_DIR/fuzz, from BUILD_DIR's generated headers)
# and runs each for a bounded time on its corpus (kept in BUILD_DIR/fuzz/corpus_*, so coverage
# accumulates over runs). Prints executions and coverage; fails on any finding (the crashing
# input is left in BUILD_DIR/fuzz/artifacts/). Without clang/libFuzzer: skipped (exit 77), failed
# with CI=true (tests/support/prerequisite.sh).
#   tools/fuzz/run_fuzz.sh BUILD_DIR [SECONDS_PER_HARNESS (default 20)]
set -uo pipefail
build="${1:?usage: tools/fuzz/run_fuzz.sh BUILD_DIR [SECONDS]}"
seconds="${2:-20}"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
# shellcheck source=../../tests/support/prerequisite.sh
. "$root/tests/support/prerequisite.sh"
clang="${SDLQR_FUZZ_CXX:-$(command -v clang++ || true)}"
[ -n "$clang" ] || missing_prerequisite "run_fuzz: clang++" "install clang libclang-rt-14-dev, or ./sdlqr setup"
if ! echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' |
     "$clang" -x c++ -fsanitize=fuzzer - -o /dev/null 2>/dev/null; then
  missing_prerequisite "run_fuzz: libFuzzer for $clang" "install libclang-rt-14-dev, or ./sdlqr setup"
fi
out="$build/fuzz"
# Idle priority (nice 19 where SCHED_IDLE is refused): beside real-time flights it takes only what
# they leave; its runs are bounded by time, so it costs executions, never the flights' timing.
chrt -i -p 0 $$ >/dev/null 2>&1 || renice -n 19 -p $$ >/dev/null
if [ ! -f "$out/CMakeCache.txt" ]; then
  cmake -S "$root/tools/fuzz" -B "$out" -DCMAKE_CXX_COMPILER="$clang" -DSDLQR_MAIN_BUILD="$build" >/dev/null || exit 1
fi
start=$(date +%s)
cmake --build "$out" -j "${SDLQR_JOBS:-2}" >"$out/build.log" 2>&1 || { tail -30 "$out/build.log"; exit 1; }
echo "run_fuzz: harnesses built in $(( $(date +%s) - start )) s with $clang"
mkdir -p "$out/corpus_messages" "$out/corpus_config" "$out/seeds_messages" "$out/artifacts"
"$out/fuzz_seeds" "$out/seeds_messages" || exit 1
cp "$root/config/quad255.yaml" "$out/corpus_config/seed_quad255.yaml"

status=0
run() {  # name corpus seeds...
  local name="$1"
  shift
  "$out/$name" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$out/artifacts/$name-" \
    -rss_limit_mb=2048 "$@" >"$out/$name.log" 2>&1
  local result=$?
  local execs cov
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$name.log")
  cov=$(grep -E '^#[0-9]+.*(DONE|pulse|NEW|REDUCE|INITED)' "$out/$name.log" | tail -1 | sed -n 's/.* cov: \([0-9]*\) ft: \([0-9]*\) corp: \([^ ]*\).*/\1 edges, \2 features, corpus \3/p')
  echo "run_fuzz: $name: ${execs:-?} executions in ${seconds} s, coverage ${cov:-?}, exit $result"
  if [ "$result" -ne 0 ]; then
    grep -E 'ERROR|SUMMARY|runtime error|artifact' "$out/$name.log" | head -20
    status=1
  fi
}
run fuzz_messages "$out/corpus_messages" "$out/seeds_messages"
run fuzz_config "$out/corpus_config"
exit "$status"
